// SPDX-License-Identifier: BSL-1.0
#pragma once
// Positions: DDMM.m with a hemisphere letter (nmea::latitude, nmea::longitude), split at the
// decimal point so unpadded degrees read right and are written back as they came, and decimal
// degrees with a letter (nmea::decimal_latitude, nmea::decimal_longitude); their codecs.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "seawire/detail/ascii.hpp"
#include "seawire/detail/byte_order.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/codec.hpp"
#include "seawire/nmea/decimal.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"

namespace seawire::nmea {

enum class hemisphere : char { north = 'N', south = 'S', east = 'E', west = 'W' };

namespace detail {
template <char Pos, char Neg, unsigned MaxDegrees, unsigned Width, errc Error>
struct axis {
  static constexpr char positive = Pos;
  static constexpr char negative = Neg;
  static constexpr unsigned max_degrees = MaxDegrees;
  static constexpr unsigned width = Width;  // degree digits in the canonical form
  static constexpr errc error = Error;
};
using lat_axis = axis<'N', 'S', 90, 2, errc::bad_latitude>;
using lon_axis = axis<'E', 'W', 180, 3, errc::bad_longitude>;

/// Why a position's hemisphere letter was refused, for error_text().
template <class Axis>
[[nodiscard]] constexpr std::string_view explain_hemisphere(std::string_view text) noexcept {
  if (text.empty()) return "hemisphere letter is missing (blank)";
  return Axis::positive == 'N' ? "hemisphere letter is not N or S"
                               : "hemisphere letter is not E or W";
}
/// A sign before a position whose letter says which side it is.
inline constexpr std::string_view signed_position =
    "a sign is not allowed: the hemisphere letter carries it";
template <class Axis>
[[nodiscard]] constexpr std::string_view beyond_degrees() noexcept {
  return Axis::max_degrees == 90 ? "beyond 90 degrees" : "beyond 180 degrees";
}
}  // namespace detail

/// A position in NMEA form: whole degrees, decimal minutes, hemisphere letter (two wire fields,
/// DDMM.mmm,N or DDDMM.mmm,E). The wire is split at the decimal point, so unpadded degrees
/// ("7105.44878") are read correctly and written back as they came (`degree_digits`).
template <class Axis>
struct nmea_coordinate {
  using axis_type = Axis;
  std::uint16_t whole_degrees = 0;
  decimal minutes;  ///< 0 <= minutes < 60, never negative
  hemisphere hemi = static_cast<hemisphere>(Axis::positive);
  std::uint8_t degree_digits = Axis::width;  ///< digits the degrees were written with
  /// The unpadded form under one degree ("5.5", "22.2": minutes only, docs/parse-policy.md), set
  /// by decode in a message that declares number_forms::unpadded_positions and written back
  /// there; encode refuses it in any other message, and with whole degrees.
  bool unpadded = false;

  constexpr nmea_coordinate() noexcept = default;
  /// `latitude{42, 21.71114_dec, hemisphere::north}`: the parts as written.
  constexpr nmea_coordinate(std::uint16_t whole, decimal mins,
                            hemisphere h = static_cast<hemisphere>(Axis::positive),
                            std::uint8_t digits = Axis::width) noexcept
      : whole_degrees(whole), minutes(mins), hemi(h), degree_digits(digits) {}
  /// Degrees as a double would be cut to whole degrees: use from_degrees(deg, minute_places).
  template <class... A>
  requires detail::any_floating<A...>
  explicit nmea_coordinate(A...) = delete;  // use latitude::from_degrees(deg, minute_places)

  /// Signed decimal degrees; the sign comes from the hemisphere letter only (so 0.0 S is -0.0).
  [[nodiscard]] constexpr double degrees() const noexcept {
    const double v = static_cast<double>(whole_degrees) + minutes.to_double() / 60.0;
    return static_cast<char>(hemi) == Axis::negative ? -v : v;
  }

  /// From signed decimal degrees, minutes rounded to `minute_places` digits, 1 to 12 (0 is
  /// out_of_range: receivers such as gpsd drop a fix written "4221,N"), by the rule for every
  /// double (decimal::from_double), times 60 exactly; 59.99999' may carry into the next degree.
  /// A position that rounds to zero is N or E.
  [[nodiscard]] static constexpr result<nmea_coordinate> from_degrees(
      double deg, unsigned minute_places = 4) noexcept {
    result<nmea_coordinate> r;
    const bool places_ok = minute_places >= 1 && minute_places <= 12;
    // Minutes x 10^p in all (degrees x 60, rounded once), then split.
    seawire::detail::rounded_double m;
    r.ec = seawire::detail::round_double(deg, 60, places_ok ? static_cast<int>(minute_places) : 1,
                                         1, m);
    if (r.ec == errc::not_finite) return r;
    const std::uint64_t total = m.magnitude;
    const std::uint64_t per_degree =
        60 * seawire::detail::pow10_table[places_ok ? minute_places : 1];
    if (!r || !places_ok || total > Axis::max_degrees * per_degree) {
      r.ec = errc::out_of_range;
      return r;
    }
    r.value.whole_degrees = static_cast<std::uint16_t>(total / per_degree);
    r.value.minutes.mantissa = total % per_degree;
    r.value.minutes.places = static_cast<std::uint8_t>(minute_places);
    r.value.hemi =
        static_cast<hemisphere>(m.negative && total != 0 ? Axis::negative : Axis::positive);
    return r;
  }

  /// Degree digits of the written form: 0 when unpadded, else degree_digits, or the natural
  /// count when that is more.
  [[nodiscard]] constexpr unsigned written_degree_digits() const noexcept {
    if (unpadded) return 0;
    const unsigned natural = seawire::detail::digit_count(whole_degrees);
    return natural > degree_digits ? natural : degree_digits;
  }

  /// Integer digits of the written minutes: two, or when unpadded the minutes' int_width (1 or
  /// 2), or their natural count when that is more.
  [[nodiscard]] constexpr unsigned written_minute_digits() const noexcept {
    if (!unpadded) return 2;
    const std::uint64_t whole =
        minutes.places <= 19 ? minutes.mantissa / seawire::detail::pow10_table[minutes.places] : 0;
    const unsigned natural = whole >= 10 ? 2 : 1;
    return minutes.int_width > natural ? 2 : natural;
  }

  /// Minutes as written: at least one fraction digit ("21" is written "21.0").
  [[nodiscard]] constexpr decimal written_minutes() const noexcept {
    decimal m = minutes;
    if (m.places == 0) {
      m.mantissa *= 10;
      m.places = 1;
    }
    return m;
  }

  /// The same written form. The minutes' int_width counts only where it is written (unpadded).
  friend constexpr bool operator==(const nmea_coordinate& a, const nmea_coordinate& b) noexcept {
    const decimal am = a.written_minutes();
    const decimal bm = b.written_minutes();
    return a.whole_degrees == b.whole_degrees && a.hemi == b.hemi && am.mantissa == bm.mantissa &&
           am.places == bm.places && am.negative == bm.negative &&
           a.written_degree_digits() == b.written_degree_digits() &&
           a.written_minute_digits() == b.written_minute_digits();
  }
};
using latitude = nmea_coordinate<detail::lat_axis>;
using longitude = nmea_coordinate<detail::lon_axis>;

/// A position in decimal degrees with a hemisphere letter (RobotX: "21.31198,N"). The number
/// is unsigned on the wire; the sign comes from the letter.
template <class Axis>
struct decimal_coordinate {
  decimal value;  ///< unsigned decimal degrees
  hemisphere hemi = static_cast<hemisphere>(Axis::positive);

  [[nodiscard]] constexpr double degrees() const noexcept {
    const double v = value.to_double();
    return static_cast<char>(hemi) == Axis::negative ? -v : v;
  }
  /// From signed decimal degrees rounded to `places` fraction digits by the rule for every
  /// double (decimal::from_double). A position that rounds to zero is N or E.
  [[nodiscard]] static constexpr result<decimal_coordinate> from_degrees(
      double deg, unsigned places = 5) noexcept {
    result<decimal_coordinate> r;
    const auto d = decimal::from_double(deg < 0 ? -deg : deg, places);
    if (!d) {
      r.ec = d.ec;
      return r;
    }
    if (d.value.compare(decimal(Axis::max_degrees)) > 0) {
      r.ec = errc::out_of_range;
      return r;
    }
    r.value.value = d.value;
    r.value.hemi =
        static_cast<hemisphere>(deg < 0 && !d.value.is_zero() ? Axis::negative : Axis::positive);
    return r;
  }
  friend constexpr bool operator==(const decimal_coordinate&,
                                   const decimal_coordinate&) noexcept = default;
};
using decimal_latitude = decimal_coordinate<detail::lat_axis>;
using decimal_longitude = decimal_coordinate<detail::lon_axis>;

/// Whether T is a DDMM.m position (latitude, longitude): its precision counts minute digits.
template <class T>
inline constexpr bool is_ddmm_position = false;
template <class A>
inline constexpr bool is_ddmm_position<nmea_coordinate<A>> = true;
/// Whether T is a decimal-degree position (decimal_latitude, decimal_longitude): its precision
/// counts degree digits.
template <class T>
inline constexpr bool is_degrees_position = false;
template <class A>
inline constexpr bool is_degrees_position<decimal_coordinate<A>> = true;

// ---------------------------------------------------------------------------------------------
// codecs

template <class Axis>
struct codec<nmea_coordinate<Axis>> {
  using value_type = nmea_coordinate<Axis>;
  static constexpr unsigned width = 2;
  /// DDDMM, point, 12 fraction digits (check's limit), comma, letter.
  static constexpr std::size_t max_chars = Axis::width + 2 + 1 + 12 + 2;
  static constexpr bool allows_blank = false;
  /// scan() refuses a blank field at its first byte (one_pass.hpp: scans_no_blank).
  static constexpr bool scan_refuses_blank = true;

  static constexpr errc read(field_reader& r, value_type& v) noexcept {
    return read_form<false>(r, v);
  }
  /// read(), and also the unpadded form of a sender that prints degrees * 100 + minutes as a
  /// number (number_forms::unpadded_positions): one or two digits before the point are minutes
  /// of zero degrees ("22.2" is 0 deg 22.2 min), kept as written (unpadded set, the minutes'
  /// int_width the digits they had).
  static constexpr errc read_unpadded(field_reader& r, value_type& v) noexcept {
    return read_form<true>(r, v);
  }

  template <bool Unpadded>
  static constexpr errc read_form(field_reader& r, value_type& v) noexcept {
    const std::string_view s = r.take().text;
    // One pass. The digits before the point are DDMM: one to Axis::width degree digits and
    // exactly two minute digits. Those after it are the fraction of the minute.
    const std::size_t n = s.size();
    std::size_t i = 0;
    std::uint64_t ddmm = 0;
    // The hemisphere field follows: the ',' before it ends the digit runs.
    const field_end end = r.end_of_field();
    detail::read_digits(s, i, ddmm, end);
    const std::size_t point = i;
    // Unpadded, one or two digits are the minutes of zero degrees; none is no number.
    const bool minutes_only = Unpadded && point >= 1 && point <= 2;
    if (point < 3 ? !minutes_only : point - 2 > Axis::width) [[unlikely]]
      return Axis::error;
    std::uint64_t fraction = 0;
    std::size_t places = 0;
    if (i < n) {
      if (s[i] != '.') [[unlikely]]
        return Axis::error;
      const std::size_t fraction_begin = ++i;
      detail::read_digits(s, i, fraction, end);
      places = i - fraction_begin;
      // 12 fraction digits of a minute is 2 micrometres: more is noise, and would overflow the
      // range arithmetic below.
      if (i != n || places > 12) [[unlikely]]
        return Axis::error;
    }
    // Senders write at least one fraction digit (every spec's DDMM.m); accepted without one,
    // as a zero fraction digit, unless the policy holds input to the sending rules.
    if (places == 0) [[unlikely]] {
      if (r.policy().strict_values) return Axis::error;
      places = 1;
    }
    const auto deg = static_cast<unsigned>(ddmm / 100);
    const std::uint64_t whole_minutes = ddmm % 100;
    if (whole_minutes >= 60) [[unlikely]]
      return errc::minute_out_of_range;
    decimal minutes;  // int_width 0: written with two digits, unless unpadded (below)
    minutes.mantissa = whole_minutes * seawire::detail::pow10_table[places] + fraction;
    minutes.places = static_cast<std::uint8_t>(places);
    if (deg > Axis::max_degrees || (deg == Axis::max_degrees && minutes.mantissa != 0))
      return Axis::error;
    v.whole_degrees = static_cast<std::uint16_t>(deg);
    if (minutes_only) {
      minutes.int_width = static_cast<std::uint8_t>(point);
      v.degree_digits = 0;
    } else {
      v.degree_digits = static_cast<std::uint8_t>(point - 2);
    }
    v.unpadded = minutes_only;
    v.minutes = minutes;
    return read_hemisphere<Axis>(r, v.hemi);
  }
  /// The one-pass reader (one_pass.hpp): DDMM.m,H at `p`, up to the byte after the letter;
  /// nullptr for what read() refuses, and for no fraction digit (read only by a liberal policy).
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan(const char* p, const char* end,
                                                          value_type& v) noexcept {
    return scan_form<false>(p, end, v);
  }
  /// scan(), as read_unpadded() reads.
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan_unpadded(const char* p, const char* end,
                                                                   value_type& v) noexcept {
    return scan_form<true>(p, end, v);
  }
  template <bool Unpadded>
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan_form(const char* p, const char* end,
                                                               value_type& v) noexcept {
    const auto digit = [](char c) {
      return static_cast<unsigned>(static_cast<unsigned char>(c)) - unsigned{'0'};
    };
    const auto refused = [](std::size_t point) {
      const bool minutes_only = Unpadded && point >= 1 && point <= 2;
      return point < 3 ? !minutes_only : point - 2 > Axis::width;
    };
    std::uint64_t ddmm = 0;
    std::uint64_t fraction = 0;
    std::size_t point = 0;
    std::size_t places = 0;
    if (end - p >= 11) {  // both words below within the body and its "*hh"
      // Eight bytes hold DDDMM and the point; eight more from the point's next the fraction,
      // unless it has eight digits or more.
      using seawire::detail::digits_value;
      using seawire::detail::non_digit_bytes;
      const std::uint64_t w = seawire::detail::load_le64(p);
      point = static_cast<std::size_t>(std::countr_zero(non_digit_bytes(w) | (1ULL << 63U))) / 8;
      if (refused(point) || p[point] != '.') [[unlikely]]
        return nullptr;
      ddmm = digits_value(w, static_cast<unsigned>(point));
      p += point + 1;
      const std::uint64_t other = non_digit_bytes(seawire::detail::load_le64(p));
      if (other != 0) [[likely]] {
        places = static_cast<std::size_t>(std::countr_zero(other)) / 8;
        if (places == 0) [[unlikely]]
          return nullptr;
        fraction = digits_value(seawire::detail::load_le64(p), static_cast<unsigned>(places));
        p += places;
      }
    }
    if (places == 0) {  // near the end of the body, or eight fraction digits or more
      const char* const begin = p - (point == 0 ? 0 : point + 1);
      p = begin;
      ddmm = 0;
      for (unsigned d = 0; (d = digit(*p)) < 10; ++p) ddmm = ddmm * 10 + d;
      point = static_cast<std::size_t>(p - begin);
      if (refused(point) || *p != '.') [[unlikely]]
        return nullptr;
      const char* const fraction_begin = ++p;
      fraction = 0;
      for (unsigned d = 0; (d = digit(*p)) < 10; ++p) fraction = fraction * 10 + d;
      places = static_cast<std::size_t>(p - fraction_begin);
      if (places - 1 >= 12) [[unlikely]]  // none, or more than 12
        return nullptr;
    }
    const bool minutes_only = Unpadded && point >= 1 && point <= 2;
    const auto deg = static_cast<unsigned>(ddmm / 100);
    const std::uint64_t whole_minutes = ddmm % 100;
    const std::uint64_t minutes = whole_minutes * seawire::detail::pow10_table[places] + fraction;
    if (whole_minutes >= 60 || deg > Axis::max_degrees ||
        (deg == Axis::max_degrees && minutes != 0)) [[unlikely]]
      return nullptr;
    v.whole_degrees = static_cast<std::uint16_t>(deg);
    v.degree_digits = static_cast<std::uint8_t>(minutes_only ? 0 : point - 2);
    v.unpadded = minutes_only;
    v.minutes = decimal{};
    v.minutes.mantissa = minutes;
    v.minutes.places = static_cast<std::uint8_t>(places);
    if (minutes_only) v.minutes.int_width = static_cast<std::uint8_t>(point);
    return scan_hemisphere<Axis>(p, end, v.hemi);
  }
  /// The one-pass reader of ",H" at `p` (the number's end): the comma, then A's letter.
  template <class A>
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan_hemisphere(const char* p, const char* end,
                                                                     hemisphere& h) noexcept {
    if (p == end || *p != ',' || (p[1] != A::positive && p[1] != A::negative)) [[unlikely]]
      return nullptr;
    h = static_cast<hemisphere>(p[1]);
    return p + 2;
  }
  static constexpr errc check(const value_type& v) noexcept {
    if (v.minutes.negative || v.minutes.places > 12 ||
        v.minutes.mantissa >= 60 * seawire::detail::pow10_table[v.minutes.places])
      return errc::minute_out_of_range;
    if (v.whole_degrees > Axis::max_degrees ||
        (v.whole_degrees == Axis::max_degrees && v.minutes.mantissa != 0) ||
        v.degree_digits > Axis::width || (v.unpadded && v.whole_degrees != 0))
      return Axis::error;
    return check_hemisphere<Axis>(v.hemi);
  }
  template <sentence_writer W>
  static constexpr void write(W& w, const value_type& v) noexcept {
    const decimal m = v.written_minutes();
    if (v.unpadded) {
      w.put_fixed(m.mantissa, m.places, v.written_minute_digits());
    } else {
      // Degrees and minutes as one number (dddmm.mmmm), the degrees' digits (at least one) and
      // the minutes' two: one conversion instead of two. check() keeps it below 10^17 (and the
      // places within pow10_table): write() is only given values check() accepts.
      const unsigned degree_digits = v.degree_digits > 0 ? v.degree_digits : 1U;
      w.put_fixed(std::uint64_t{v.whole_degrees} * 100 * seawire::detail::pow10_table[m.places] +
                      m.mantissa,
                  m.places, degree_digits + 2);
    }
    w.next_field();
    w.put(static_cast<char>(v.hemi));
  }

  /// An error check() gives is about the hemisphere letter (the second wire field) or the number.
  static constexpr unsigned error_offset(errc e) noexcept {
    return e == errc::bad_hemisphere ? 1 : 0;
  }

  /// The wire fields after the first, as about_field names them.
  [[nodiscard]] static constexpr std::string_view part_name(unsigned k) noexcept {
    return k == 1 ? "hemisphere letter" : "";
  }
  /// Why read() refused `text` (wire field `k` of the two), from the text itself: a sign, the
  /// digits before the point that are not DDMM (two minute digits after one to Axis::width
  /// degree digits: decimal degrees "37.352387" are not), a character that is no digit or
  /// point, too many fraction digits, none (refused under a strict policy), degrees beyond the
  /// axis; "" when the text shows nothing more than `e` says.
  [[nodiscard]] static constexpr std::string_view explain(unsigned k, errc e,
                                                          std::string_view text) noexcept {
    if (k == 1) return e == errc::bad_hemisphere ? detail::explain_hemisphere<Axis>(text) : "";
    if (e != Axis::error || text.empty()) return "";
    if (text[0] == '-' || text[0] == '+') return detail::signed_position;
    std::size_t i = 0;
    std::uint64_t ddmm = 0;
    for (; i < text.size() && seawire::detail::is_digit(text[i]); ++i)
      if (i < 19) ddmm = ddmm * 10 + static_cast<unsigned>(text[i] - '0');  // more: too many
    const std::size_t point = i;
    std::size_t places = 0;
    bool has_point = false;
    bool fraction = false;  // a digit after the point other than 0
    if (i < text.size() && text[i] == '.') {
      has_point = true;
      for (++i; i < text.size() && seawire::detail::is_digit(text[i]); ++i) {
        fraction = fraction || text[i] != '0';
        ++places;
      }
    }
    if (i != text.size()) return "DDMM.m holds only digits and one decimal point";
    if (point < 3)
      return "DDMM.m needs two minute digits and at least one degree digit before the point";
    if (point - 2 > Axis::width)
      return Axis::width == 2 ? "DDMM.m has at most 2 degree digits before the minutes"
                              : "DDDMM.m has at most 3 degree digits before the minutes";
    if (places > 12) return "more than 12 fraction digits of a minute";
    if (places == 0)
      return has_point ? "no digit after the point: DDMM.m is sent with at least one"
                       : "no fraction: DDMM.m is sent with at least one digit after the point";
    if (ddmm / 100 > Axis::max_degrees ||
        (ddmm / 100 == Axis::max_degrees && (ddmm % 100 != 0 || fraction)))
      return detail::beyond_degrees<Axis>();
    return "";
  }

  template <class A>
  static constexpr errc read_hemisphere(field_reader& r, hemisphere& h) noexcept {
    const field_token t = r.take();
    if (!t.present) [[unlikely]]
      return errc::too_few_fields;
    if (t.text.size() != 1 || (t.text[0] != A::positive && t.text[0] != A::negative))
      return errc::bad_hemisphere;
    h = static_cast<hemisphere>(t.text[0]);
    return errc::ok;
  }
  template <class A>
  static constexpr errc check_hemisphere(hemisphere h) noexcept {
    const char c = static_cast<char>(h);
    return c == A::positive || c == A::negative ? errc::ok : errc::bad_hemisphere;
  }
};

template <class Axis>
struct codec<decimal_coordinate<Axis>> {
  using value_type = decimal_coordinate<Axis>;
  using nmea = codec<nmea_coordinate<Axis>>;
  static constexpr unsigned width = 2;
  static constexpr std::size_t max_chars = codec<decimal>::max_chars + 2;
  static constexpr bool allows_blank = false;
  /// scan() refuses a blank field at its first byte (one_pass.hpp: scans_no_blank).
  static constexpr bool scan_refuses_blank = true;

  static constexpr errc read(field_reader& r, value_type& v) noexcept {
    const std::string_view s = r.take().text;
    // Unsigned on the wire: a sign would contradict (or duplicate) the hemisphere letter.
    if (s.empty() || s[0] == '-' || s[0] == '+') [[unlikely]]
      return Axis::error;
    if (detail::parse_decimal(s, false, v.value) != errc::ok) [[unlikely]]
      return Axis::error;
    if (v.value.compare(decimal(Axis::max_degrees)) > 0) [[unlikely]]
      return Axis::error;
    return nmea::template read_hemisphere<Axis>(r, v.hemi);
  }
  /// The one-pass reader: unsigned decimal degrees, then ",H".
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan(const char* p, const char* end,
                                                          value_type& v) noexcept {
    if (*p == '-') [[unlikely]]
      return nullptr;
    p = detail::scan_decimal(p, v.value);
    if (p == nullptr || v.value.compare(decimal(Axis::max_degrees)) > 0) [[unlikely]]
      return nullptr;
    return nmea::template scan_hemisphere<Axis>(p, end, v.hemi);
  }
  static constexpr errc check(const value_type& v) noexcept {
    if (const errc e = detail::check_decimal(v.value); e != errc::ok) return e;
    if (v.value.negative || v.value.compare(decimal(Axis::max_degrees)) > 0) [[unlikely]]
      return Axis::error;
    return nmea::template check_hemisphere<Axis>(v.hemi);
  }
  static constexpr unsigned error_offset(errc e) noexcept { return nmea::error_offset(e); }
  [[nodiscard]] static constexpr std::string_view part_name(unsigned k) noexcept {
    return nmea::part_name(k);
  }
  /// Why read() refused `text`: a sign, no decimal number, degrees beyond the axis (see the
  /// DDMM.m codec's explain).
  [[nodiscard]] static constexpr std::string_view explain(unsigned k, errc e,
                                                          std::string_view text) noexcept {
    if (k == 1) return e == errc::bad_hemisphere ? detail::explain_hemisphere<Axis>(text) : "";
    if (e != Axis::error || text.empty()) return "";
    if (text[0] == '-' || text[0] == '+') return detail::signed_position;
    decimal d;
    if (detail::parse_decimal(text, false, d) != errc::ok) return "not a number of decimal degrees";
    if (d.compare(decimal(Axis::max_degrees)) > 0) return detail::beyond_degrees<Axis>();
    return "";
  }
  template <sentence_writer W>
  static constexpr void write(W& w, const value_type& v) noexcept {
    detail::write_decimal(w, v.value);
    w.next_field();
    w.put(static_cast<char>(v.hemi));
  }
};

// ---------------------------------------------------------------------------------------------
// signed decimal degrees, both ways (JSON and fmt write positions this way)

namespace detail {

template <class T>
struct coordinate_traits;
template <class A>
struct coordinate_traits<nmea_coordinate<A>> {
  using axis = A;
  static constexpr bool nmea_form = true;
};
template <class A>
struct coordinate_traits<decimal_coordinate<A>> {
  using axis = A;
  static constexpr bool nmea_form = false;
};

/// Rounds a decimal to at most `places` fraction digits (halves away from zero).
[[nodiscard]] constexpr decimal round_places(decimal d, unsigned places) noexcept {
  if (d.places <= places) return d;
  std::uint64_t m = 0;  // fewer places: always fits
  (void)seawire::detail::round_scaled(d.mantissa,
                                      static_cast<int>(places) - static_cast<int>(d.places), 1, m);
  d.mantissa = m;
  d.places = static_cast<std::uint8_t>(places);
  return d;
}

}  // namespace detail

/// The fraction digits a position may be written with (a "precision"): minutes of a DDMM.mmm
/// field (at least one), degrees of a decimal-degree field.
inline constexpr unsigned min_minute_places = 1;
inline constexpr unsigned max_minute_places = 12;
inline constexpr unsigned max_degree_places = 18;

namespace detail {
/// Fraction digits to_decimal_degrees writes for minutes of `p` digits whose mantissa is
/// `mantissa`. minutes / 60 ends after p + 2 digits when the mantissa is a multiple of 3 (60 =
/// 2^2 * 3 * 5): then exactly those. Otherwise it repeats for ever: p + 8 digits, rounded, so
/// within 5e-10 degrees of the wire (at most 19 digits in all: 17 fraction digits for
/// latitudes, 16 for longitudes). Each count belongs to one p of each kind, and a rounded
/// quotient never equals an exact one at the same count, so the minutes' digits can be told
/// back from the degrees.
template <class Axis>
[[nodiscard]] constexpr unsigned degree_places_for(unsigned p, std::uint64_t mantissa) noexcept {
  if (mantissa % 3 == 0) return p + 2;
  constexpr unsigned cap = Axis::max_degrees >= 100 ? 16 : 17;
  return p + 8 < cap ? p + 8 : cap;
}
}  // namespace detail

/// Signed decimal degrees of an NMEA position, exact where the decimal expansion terminates
/// and within 5e-10 degrees of the wire's value where it does not (see degree_places_for):
/// "4221.71114,N" -> 42.3618523333333, "07105.44878,W" -> -71.0908130 (exact),
/// "01200.76,E" -> 12.0126666667, "0000.00,W" -> -0.0000 (the sign comes from the hemisphere
/// letter). from_decimal_degrees() gives the same minutes back, digit for digit.
template <class Axis>
[[nodiscard]] constexpr decimal to_decimal_degrees(const nmea_coordinate<Axis>& c) noexcept {
  decimal m = c.written_minutes();
  if (m.places > max_minute_places) m = detail::round_places(m, max_minute_places);
  const unsigned p = m.places;
  const unsigned k = detail::degree_places_for<Axis>(p, m.mantissa);
  // minutes / 60 at k places: mantissa * 10^(k - p) / 60, rounded. k >= p + 2, where a
  // terminating quotient ends, so there is never a tie; the product stays below
  // 60 * 10^k <= 6e18.
  const std::uint64_t scaled = m.mantissa * seawire::detail::pow10_table[k - p];
  const std::uint64_t frac = scaled / 60 + (scaled % 60 >= 30 ? 1 : 0);
  decimal d;
  d.places = static_cast<std::uint8_t>(k);
  d.mantissa = c.whole_degrees * seawire::detail::pow10_table[k] + frac;
  d.negative = static_cast<char>(c.hemi) == Axis::negative;
  return d;
}

/// Signed decimal degrees of a decimal-degrees position ("21.31198,S" -> -21.31198), the wire's
/// digits (zero padding of the degrees is dropped).
template <class Axis>
[[nodiscard]] constexpr decimal to_decimal_degrees(const decimal_coordinate<Axis>& c) noexcept {
  decimal d = c.value;
  d.int_width = 0;
  d.negative = static_cast<char>(c.hemi) == Axis::negative;
  return d;
}

template <class Coordinate>
[[nodiscard]] constexpr result<Coordinate> from_decimal_degrees(decimal deg,
                                                                int minute_places = -1) noexcept;

namespace detail {
/// The fewest minute digits whose minutes, written by to_decimal_degrees, give exactly `deg`
/// (its digits and their count); 0 when none does (degrees that seawire did not write).
template <class Coordinate>
[[nodiscard]] constexpr unsigned reproducing_minute_places(const decimal& deg) noexcept {
  for (unsigned p = min_minute_places; p <= max_minute_places; ++p) {
    const result<Coordinate> c = from_decimal_degrees<Coordinate>(deg, static_cast<int>(p));
    if (!c) return 0;
    const decimal back = to_decimal_degrees(c.value);
    if (back.mantissa == deg.mantissa && back.places == deg.places) return p;
  }
  return 0;
}
}  // namespace detail

/// The NMEA position of signed decimal degrees given as written, exactly (no double): minutes
/// rounded half away from zero to `minute_places` digits (1..12, else out_of_range), hemisphere
/// from the sign (-0.0 is S or W); bad_latitude/bad_longitude beyond 90/180. minute_places < 0:
/// the fewest digits from which to_decimal_degrees() gives these degrees back, so what seawire
/// wrote returns digit for digit (up to 8 minute digits for longitudes, 9 for latitudes); other
/// degrees get their fraction digits - 2, at least 4 (0.0001' = 0.19 m).
template <class Coordinate>
[[nodiscard]] constexpr result<Coordinate> from_decimal_degrees(decimal deg,
                                                                int minute_places) noexcept {
  result<Coordinate> r;
  using Axis = typename detail::coordinate_traits<Coordinate>::axis;
  if constexpr (detail::coordinate_traits<Coordinate>::nmea_form) {
    unsigned p = 0;
    if (minute_places >= 0) {
      p = static_cast<unsigned>(minute_places);
    } else {
      p = detail::reproducing_minute_places<Coordinate>(deg);
      if (p == 0) p = deg.places >= 3 ? deg.places - 2u : 4u;
    }
    if (p < min_minute_places || p > max_minute_places) {
      r.ec = errc::out_of_range;
      return r;
    }
    unsigned qd = deg.places;
    std::uint64_t whole = deg.mantissa / seawire::detail::pow10_table[qd];
    std::uint64_t frac = deg.mantissa % seawire::detail::pow10_table[qd];
    if (qd > 18) {  // keep frac * 6 inside 64 bits
      frac = (frac + 5) / 10;
      qd = 18;
      if (frac == seawire::detail::pow10_table[18]) {
        frac = 0;
        ++whole;
      }
    }
    // minutes * 10^p = frac * 60 * 10^p / 10^qd = frac * 6 * 10^(p + 1 - qd)
    std::uint64_t m = 0;
    if (p + 1 >= qd) {
      m = frac * 6 * seawire::detail::pow10_table[p + 1 - qd];
    } else {
      const std::uint64_t div = seawire::detail::pow10_table[qd - p - 1];
      m = (frac * 6 + div / 2) / div;
    }
    const std::uint64_t sixty = 60 * seawire::detail::pow10_table[p];
    if (m >= sixty) {
      m -= sixty;
      ++whole;
    }
    if (whole > Axis::max_degrees || (whole == Axis::max_degrees && m != 0)) {
      r.ec = Axis::error;
      return r;
    }
    r.value.whole_degrees = static_cast<std::uint16_t>(whole);
    r.value.minutes = decimal{};
    r.value.minutes.mantissa = m;
    r.value.minutes.places = static_cast<std::uint8_t>(p);
    r.value.degree_digits = Axis::width;
    r.value.hemi = static_cast<hemisphere>(deg.negative ? Axis::negative : Axis::positive);
  } else {
    decimal v = deg;
    if (minute_places >= 0) {
      if (static_cast<unsigned>(minute_places) > max_degree_places) {
        r.ec = errc::out_of_range;
        return r;
      }
      v = detail::round_places(v, static_cast<unsigned>(minute_places));
      while (v.places < static_cast<unsigned>(minute_places)) {  // pad: 21.3 at 5 places
        if (v.mantissa > 1'000'000'000'000'000'000ULL) {
          r.ec = errc::number_too_long;
          return r;
        }
        v.mantissa *= 10;
        ++v.places;
      }
    }
    v.negative = false;
    v.int_width = 0;
    if (v.compare(decimal(Axis::max_degrees)) > 0) {
      r.ec = Axis::error;
      return r;
    }
    r.value.value = v;
    r.value.hemi = static_cast<hemisphere>(deg.negative ? Axis::negative : Axis::positive);
  }
  return r;
}

}  // namespace seawire::nmea
