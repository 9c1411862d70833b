// SPDX-License-Identifier: BSL-1.0
#pragma once
// Field values as the wire has them, and the codec that reads and writes each one.
//
// Every value type here keeps enough of the text to write it back exactly ("4.50" stays
// "4.50", an unpadded longitude stays unpadded) and rejects values outside its domain.
// A codec reads `width` wire fields from a field_reader and writes them to a writer; the
// message layer (message.hpp) handles blanks, optionals, units and ranges around it.

#include <array>
#include <chrono>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>

#include "seawire/detail/ascii.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"

namespace seawire::nmea {

// ---------------------------------------------------------------------------------------------
// decimal

namespace detail {
/// The integer nearest x >= 0 (halves up), for x below 2^64. Not static_cast(x + 0.5): that sum
/// is itself rounded, so 0.49999999999999994 gave 1 and 2^52 + 1 gave 2^52 + 2. The fraction
/// taken by subtraction is exact.
[[nodiscard]] constexpr std::uint64_t round_nonnegative(double x) noexcept {
  auto whole = static_cast<std::uint64_t>(x);
  if (x - static_cast<double>(whole) >= 0.5) ++whole;
  return whole;
}
}  // namespace detail

namespace detail {
/// Whether any of the arguments is floating-point: the value types below refuse such a call
/// rather than cut 42.5 degrees or 12.5 hours to an integer.
template <class... A>
concept any_floating = (std::floating_point<std::remove_cvref_t<A>> || ...);
}  // namespace detail

/// A decimal number exactly as written: digits, number of fraction digits, sign.
/// "-0.0" keeps its sign and "4.50" its trailing zero. Equality compares the written form;
/// `compare()` compares values. At most 19 significant digits and 19 fraction digits.
struct decimal {
  std::uint64_t mantissa = 0;  ///< all digits as one integer: "4.50" -> 450
  std::uint8_t places = 0;     ///< digits after the point: "4.50" -> 2
  bool negative = false;
  /// Integer digits as written when the sender zero-padded them ("000.0" -> 3, "011.3" -> 3);
  /// 0 when written naturally. Only the text form depends on it.
  std::uint8_t int_width = 0;

  constexpr decimal() noexcept = default;
  /// An integer value: `decimal{45}` is "45", and `msg.thrust = 45;` reads as it should.
  template <std::integral I>
  requires(!std::same_as<I, bool>)
      // NOLINTNEXTLINE(google-explicit-constructor): decimal{45} and in_range(-100, 100) read well.
      constexpr decimal(I integer) noexcept
      : mantissa(integer < 0 ? 0 - static_cast<std::uint64_t>(integer)
                             : static_cast<std::uint64_t>(integer)),
        negative(integer < 0) {}
  /// A floating-point value is never taken silently: 1.5 would have to be cut to some number of
  /// places, and a speed or depth command cut to an integer is a different command. Say how many
  /// places: decimal::from_double(1.5, 1), decimal::parse("1.5"), or the literal 1.5_dec.
  template <std::floating_point F>
  decimal(F) = delete;  // use decimal::from_double(v, places), decimal::parse("1.5") or 1.5_dec

  /// `mantissa` / 10^places: decimal::scaled(450, 2) is "4.50". Both are integers (a double
  /// does not compile); places above 19 is refused when the value is written (value_too_large).
  template <std::integral I, std::integral P>
  requires(!std::same_as<I, bool> && !std::same_as<P, bool>) [[nodiscard]] static constexpr decimal
      scaled(I mantissa, P places) noexcept {
    decimal d(mantissa);
    d.places = places < 0 || places > 255 ? std::uint8_t{255} : static_cast<std::uint8_t>(places);
    return d;
  }
  template <class I, class P>
  requires(std::floating_point<I> || std::floating_point<P>) static decimal
      scaled(I, P) = delete;  // integers only: use decimal::from_double(v, places)

  /// The number written in `text`: [-] digits [. digits], as a sender writes it (no '+', no
  /// spaces, no exponent), at most 19 digits. bad_number or number_too_long otherwise.
  [[nodiscard]] static constexpr result<decimal> parse(std::string_view text) noexcept;

  /// The same number with the other sign ("-1.5" from 1.5_dec).
  [[nodiscard]] constexpr decimal operator-() const noexcept {
    decimal d = *this;
    d.negative = !negative;
    return d;
  }

  /// The value rounded to `places` fraction digits; refuses NaN/inf and what 19 digits cannot
  /// hold.
  [[nodiscard]] static constexpr result<decimal> from_double(double v, unsigned places) noexcept {
    result<decimal> r;
    if (!(v == v) || v > std::numeric_limits<double>::max() ||
        v < -std::numeric_limits<double>::max()) {
      r.ec = errc::not_finite;
      return r;
    }
    if (places > 18) {
      r.ec = errc::value_too_large;
      return r;
    }
    const double mag = (v < 0 ? -v : v) * static_cast<double>(seawire::detail::pow10_table[places]);
    if (mag >= 1e19) {
      r.ec = errc::value_too_large;
      return r;
    }
    r.value.mantissa = detail::round_nonnegative(mag);
    r.value.places = static_cast<std::uint8_t>(places);
    r.value.negative = v < 0 && r.value.mantissa != 0;
    return r;
  }

  [[nodiscard]] constexpr double to_double() const noexcept {
    // Both operands are exact doubles for mantissa < 2^53 and places <= 19, so the one
    // division is correctly rounded.
    double d =
        static_cast<double>(mantissa) / static_cast<double>(seawire::detail::pow10_table[places]);
    return negative ? -d : d;
  }

  [[nodiscard]] constexpr bool is_zero() const noexcept { return mantissa == 0; }

  /// Numeric comparison: -1, 0 or 1. "-0" equals "0"; "4.5" equals "4.50".
  [[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr int compare(const decimal& o) const noexcept {
    const bool n1 = negative && mantissa != 0;
    const bool n2 = o.negative && o.mantissa != 0;
    if (n1 != n2) return n1 ? -1 : 1;
    const int mag = compare_magnitude(o);
    return n1 ? -mag : mag;
  }

  /// Integer digits of the written form: int_width, or the natural count when that is more (an
  /// int_width of 1 on "45" pads nothing); the writer pads to 20 digits at most.
  [[nodiscard]] constexpr unsigned written_int_digits() const noexcept {
    const unsigned natural =
        places > 19 ? 0
                    : seawire::detail::digit_count(mantissa / seawire::detail::pow10_table[places]);
    const unsigned padded = int_width < 20 ? int_width : 20;
    return natural > padded ? natural : padded;
  }

  /// The same written form: digits, places, sign and integer padding.
  friend constexpr bool operator==(const decimal& a, const decimal& b) noexcept {
    return a.mantissa == b.mantissa && a.places == b.places && a.negative == b.negative &&
           a.written_int_digits() == b.written_int_digits();
  }

 private:
  [[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr int compare_magnitude(
      const decimal& o) const noexcept {
    // Scale the mantissa with fewer places up to the other's: no division, and a product that
    // would pass 2^64 is certainly the larger (the other mantissa is below 2^64).
    if (places == o.places) return three_way(mantissa, o.mantissa);
    if (places < o.places) return scaled_compare(mantissa, o.places - places, o.mantissa);
    return -scaled_compare(o.mantissa, places - o.places, mantissa);
  }
  // a * 10^k against b, for k < 20.
  [[nodiscard]] static constexpr int scaled_compare(std::uint64_t a, unsigned k,
                                                    std::uint64_t b) noexcept {
    if (a > seawire::detail::scale_limit[k]) return 1;
    return three_way(a * seawire::detail::pow10_table[k], b);
  }
  [[nodiscard]] static constexpr int three_way(std::uint64_t a, std::uint64_t b) noexcept {
    return a == b ? 0 : (a < b ? -1 : 1);
  }
};

namespace detail {

/// Parse [sign] digits [. digits] the slow, general way: any number of leading zeros.
[[nodiscard]] constexpr errc parse_decimal_long(std::string_view s, std::size_t i, bool neg,
                                                decimal& out) noexcept {
  const std::size_t n = s.size();
  std::uint64_t m = 0;
  unsigned significant = 0;
  unsigned places = 0;
  unsigned int_written = 0;
  bool point = false;
  bool any = false;
  for (; i < n; ++i) {
    const char c = s[i];
    if (seawire::detail::is_digit(c)) {
      any = true;
      if (point) {
        ++places;
      } else {
        ++int_written;
      }
      if (m != 0 || c != '0') {
        if (++significant > 19) [[unlikely]]
          return errc::number_too_long;
        m = m * 10 + static_cast<std::uint64_t>(c - '0');
      }
    } else if (c == '.' && !point) {
      point = true;
    } else {
      return errc::bad_number;
    }
  }
  if (!any) [[unlikely]]
    return errc::bad_number;
  if (places > 19) [[unlikely]]
    return errc::number_too_long;
  out.mantissa = m;
  out.places = static_cast<std::uint8_t>(places);
  out.negative = neg;
  const unsigned natural = seawire::detail::digit_count(m / seawire::detail::pow10_table[places]);
  out.int_width =
      static_cast<std::uint8_t>(int_written > natural && int_written <= 20 ? int_written : 0);
  return errc::ok;
}

/// Reads the run of digits at s[i] onto m (m * 10 + digit each; past 19 digits m wraps, and the
/// caller, which sees the count, does not use it) and moves i past it.
SEAWIRE_ALWAYS_INLINE constexpr void read_digits(std::string_view s, std::size_t& i,
                                                 std::uint64_t& m) noexcept {
  for (unsigned d = 0; i < s.size() && (d = static_cast<unsigned char>(s[i]) - unsigned{'0'}) < 10;
       ++i)
    m = m * 10 + d;
}

[[nodiscard]] constexpr errc parse_decimal_spaced(std::string_view s, decimal& out) noexcept;

/// Parse [sign] digits [. digits] with the leniencies of a receive policy: a '+' unless
/// strict_values, spaces before and after the number when spaced_numbers too (receivers accept
/// them, senders never write them). No exponent, no spaces inside. The policy is consulted
/// only for a sign or a bad byte, so the common number does not work its rules out.
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr errc parse_decimal(std::string_view s,
                                                                 const parse_policy& p,
                                                                 decimal& out) noexcept {
  std::size_t i = 0;
  const std::size_t n = s.size();
  bool neg = false;
  if (i < n && (s[i] == '-' || s[i] == '+')) {
    if (s[i] == '+' && p.strict_values) [[unlikely]]
      return errc::bad_number;
    neg = s[i] == '-';
    ++i;
  }
  // Up to 19 digits in all fit the mantissa whatever they are, and no division is needed to
  // find the integer digits as written; anything longer takes the general path.
  const std::size_t int_begin = i;
  std::uint64_t m = 0;
  read_digits(s, i, m);
  const std::size_t int_written = i - int_begin;
  std::size_t places = 0;
  if (i < n && s[i] == '.') {
    const std::size_t frac_begin = ++i;
    read_digits(s, i, m);
    places = i - frac_begin;
  }
  // Past 19 digits the general path decides, down to which error comes first.
  if (int_written + places > 19) [[unlikely]]
    return parse_decimal_long(s, int_begin, neg, out);
  if (i != n || int_written + places == 0) [[unlikely]] {
    // SPI 4.2: "if negative, the first non-whitespace character will be the minus sign", so a
    // receiver takes " -5.0" (and "12 "); senders never write spaces.
    if (n != 0 && (s.front() == ' ' || s.back() == ' ') && p.spaced_numbers && !p.strict_values)
      return parse_decimal_spaced(s, out);
    return errc::bad_number;
  }
  out.mantissa = m;
  out.places = static_cast<std::uint8_t>(places);
  out.negative = neg;
  out.int_width = 0;
  if (int_written > 1 && s[int_begin] == '0') {  // zero-padded ("007.5", "00"): keep the width
    std::size_t zeros = 1;
    while (zeros < int_written && s[int_begin + zeros] == '0') ++zeros;
    const std::size_t natural = int_written - zeros == 0 ? 1 : int_written - zeros;
    out.int_width = static_cast<std::uint8_t>(int_written > natural ? int_written : 0);
  }
  return errc::ok;
}

/// The same with the two leniencies as flags: a '+' only when `liberal`, spaces around the
/// number only when `spaced` too.
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr errc parse_decimal(std::string_view s, bool liberal,
                                                                 decimal& out,
                                                                 bool spaced = false) noexcept {
  parse_policy p;
  p.strict_values = !liberal;
  p.spaced_numbers = spaced;
  return parse_decimal(s, p, out);
}

/// parse_decimal of a number with spaces around it (parse_policy::spaced_numbers).
[[nodiscard]] constexpr errc parse_decimal_spaced(std::string_view s, decimal& out) noexcept {
  std::size_t b = 0;
  std::size_t e = s.size();
  while (b < e && s[b] == ' ') ++b;
  while (e > b && s[e - 1] == ' ') --e;
  if (b == e) [[unlikely]]
    return errc::bad_number;  // nothing but spaces
  return parse_decimal(s.substr(b, e - b), true, out, false);
}

/// Whether write_decimal writes `d` as text parse_decimal reads back to `d`: at most 19 digits
/// (the mantissa below 10^19, at most 19 of them after the point) and an integer padding the
/// writer can produce (20 digits at most).
[[nodiscard]] constexpr errc check_decimal(const decimal& d) noexcept {
  constexpr std::uint64_t max_mantissa = 9'999'999'999'999'999'999ULL;
  return d.places > 19 || d.mantissa > max_mantissa || d.int_width > 20 ? errc::value_too_large
                                                                        : errc::ok;
}

constexpr void write_decimal(writer& w, const decimal& d) noexcept {
  if (d.negative) w.put('-');
  w.put_fixed(d.mantissa, d.places, d.int_width);
}

}  // namespace detail

constexpr result<decimal> decimal::parse(std::string_view text) noexcept {
  result<decimal> r;
  r.ec = detail::parse_decimal(text, false, r.value);
  if (!r) r.value = decimal{};
  return r;
}

namespace detail {
// Not constexpr: a literal that reaches it does not compile, and the error names it.
inline void literal_is_not_a_decimal_with_at_most_19_digits() noexcept {}
}  // namespace detail

namespace literals {
/// `1.5_dec` is decimal::parse("1.5"): the digits as written, checked when compiled. Only plain
/// decimal literals ("1.50", "45"); an exponent, hex or digit separators do not compile.
template <char... Chars>
consteval decimal operator""_dec() {
  constexpr char text[] = {Chars...};
  const result<decimal> r = decimal::parse(std::string_view(text, sizeof...(Chars)));
  if (!r) detail::literal_is_not_a_decimal_with_at_most_19_digits();
  return r.value;
}
}  // namespace literals

namespace detail {

/// Parse an unsigned run of digits of exactly `len` characters at s[pos].
[[nodiscard]] constexpr bool parse_fixed_digits(std::string_view s, std::size_t pos,
                                                std::size_t len, unsigned& out) noexcept {
  if (pos + len > s.size()) return false;
  unsigned v = 0;
  for (std::size_t k = pos; k < pos + len; ++k) {
    if (!seawire::detail::is_digit(s[k])) return false;
    v = v * 10 + static_cast<unsigned>(s[k] - '0');
  }
  out = v;
  return true;
}

/// The first six characters of s (at least six) as three two-digit numbers ("hhmmss",
/// "ddmmyy"), with no branch per digit; false if any is not a digit.
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr bool parse_digit_pairs(std::string_view s,
                                                                     unsigned (&two)[3]) noexcept {
  const auto digit = [&s](std::size_t k) {  // a byte below '0' wraps to a large value
    return static_cast<unsigned>(static_cast<unsigned char>(s[k])) - unsigned{'0'};
  };
  const unsigned d0 = digit(0), d1 = digit(1), d2 = digit(2), d3 = digit(3), d4 = digit(4),
                 d5 = digit(5);
  two[0] = d0 * 10 + d1;
  two[1] = d2 * 10 + d3;
  two[2] = d4 * 10 + d5;
  return static_cast<bool>(static_cast<unsigned>(d0 < 10) & static_cast<unsigned>(d1 < 10) &
                           static_cast<unsigned>(d2 < 10) & static_cast<unsigned>(d3 < 10) &
                           static_cast<unsigned>(d4 < 10) & static_cast<unsigned>(d5 < 10));
}

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// positions

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
}  // namespace detail

/// A position in NMEA form: whole degrees, decimal minutes, hemisphere letter (two wire fields,
/// DDMM.mmm,N or DDDMM.mmm,E). The wire is split at the decimal point, so unpadded degrees
/// ("7105.44878") are read correctly and written back as they came (`degree_digits`).
template <class Axis>
struct nmea_coordinate {
  std::uint16_t whole_degrees = 0;
  decimal minutes;  ///< 0 <= minutes < 60, never negative
  hemisphere hemi = static_cast<hemisphere>(Axis::positive);
  std::uint8_t degree_digits = Axis::width;  ///< digits the degrees were written with

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

  /// From signed decimal degrees, minutes rounded to `minute_places` digits, 1 to 12: every
  /// spec writes DDMM.m with at least one digit after the point, and receivers rely on it (gpsd
  /// drops a fix whose position reads "4221,N"), so 0 places is out_of_range. A position
  /// received without a fraction is still decoded (as "4221.0": one fraction digit, zero),
  /// except under a strict policy (parse_policy::strict(), seawire-decode --strict), which
  /// refuses it; minutes given with no fraction digits are written with one ("4221.0").
  [[nodiscard]] static constexpr result<nmea_coordinate> from_degrees(
      double deg, unsigned minute_places = 4) noexcept {
    result<nmea_coordinate> r;
    if (!(deg == deg) || deg > 1e300 || deg < -1e300) {
      r.ec = errc::not_finite;
      return r;
    }
    const double mag = deg < 0 ? -deg : deg;
    if (mag > Axis::max_degrees || minute_places < 1 || minute_places > 12) {
      r.ec = errc::out_of_range;
      return r;
    }
    auto whole = static_cast<std::uint64_t>(mag);
    const std::uint64_t scale = seawire::detail::pow10_table[minute_places];
    auto m = detail::round_nonnegative((mag - static_cast<double>(whole)) * 60.0 *
                                       static_cast<double>(scale));
    if (m >= 60 * scale) {  // 59.99999 rounded up to 60: carry into the degrees
      m -= 60 * scale;
      ++whole;
    }
    if (whole > Axis::max_degrees || (whole == Axis::max_degrees && m != 0)) {
      r.ec = errc::out_of_range;
      return r;
    }
    r.value.whole_degrees = static_cast<std::uint16_t>(whole);
    r.value.minutes.mantissa = m;
    r.value.minutes.places = static_cast<std::uint8_t>(minute_places);
    r.value.hemi = static_cast<hemisphere>(deg < 0 ? Axis::negative : Axis::positive);
    return r;
  }

  /// Degree digits of the written form: degree_digits, or the natural count when that is more.
  [[nodiscard]] constexpr unsigned written_degree_digits() const noexcept {
    const unsigned natural = seawire::detail::digit_count(whole_degrees);
    return natural > degree_digits ? natural : degree_digits;
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

  /// The same written form. The minutes are always written with two integer digits, so their
  /// int_width is no part of it.
  friend constexpr bool operator==(const nmea_coordinate& a, const nmea_coordinate& b) noexcept {
    const decimal am = a.written_minutes();
    const decimal bm = b.written_minutes();
    return a.whole_degrees == b.whole_degrees && a.hemi == b.hemi && am.mantissa == bm.mantissa &&
           am.places == bm.places && am.negative == bm.negative &&
           a.written_degree_digits() == b.written_degree_digits();
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
    r.value.hemi = static_cast<hemisphere>(deg < 0 ? Axis::negative : Axis::positive);
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
// time and date

/// Time of day hhmmss[.f], 0 to 9 fraction digits kept as written. Second 60 is accepted only
/// as 23:59:60, the one place a UTC leap second can stand.
struct time_of_day {
  std::uint8_t hour = 0;
  std::uint8_t minute = 0;
  std::uint8_t second = 0;
  std::uint32_t fraction = 0;  ///< the fraction digits as an integer: ".980" -> 980
  std::uint8_t places = 0;     ///< number of fraction digits: ".980" -> 3

  constexpr time_of_day() noexcept = default;
  /// `time_of_day{16, 49, 59, 980, 3}` is 16:49:59.980.
  constexpr time_of_day(std::uint8_t h, std::uint8_t m, std::uint8_t s, std::uint32_t frac = 0,
                        std::uint8_t frac_places = 0) noexcept
      : hour(h), minute(m), second(s), fraction(frac), places(frac_places) {}
  /// Seconds as a double would lose their fraction: use from_since_midnight() or the parts.
  template <class... A>
  requires detail::any_floating<A...>
  explicit time_of_day(A...) = delete;  // use time_of_day::from_since_midnight(duration, places)

  [[nodiscard]] constexpr std::chrono::nanoseconds since_midnight() const noexcept {
    using namespace std::chrono;
    return hours(hour) + minutes(minute) + seconds(second) +
           nanoseconds(static_cast<std::int64_t>(fraction) *
                       static_cast<std::int64_t>(seawire::detail::pow10_table[9 - places]));
  }
  /// The fraction of the second in nanoseconds.
  [[nodiscard]] constexpr std::uint32_t fraction_ns() const noexcept {
    return static_cast<std::uint32_t>(fraction * seawire::detail::pow10_table[9 - places]);
  }
  /// From a duration since midnight (0 <= d < 24 h), truncated to `places` fraction digits
  /// (truncated, not rounded, so 23:59:59.9999 never becomes 24:00).
  [[nodiscard]] static constexpr result<time_of_day> from_since_midnight(
      std::chrono::nanoseconds d, unsigned places = 3) noexcept {
    result<time_of_day> r;
    const std::int64_t ns = d.count();
    if (ns < 0 || ns >= 86'400'000'000'000 || places > 9) {
      r.ec = errc::out_of_range;
      return r;
    }
    const std::int64_t s = ns / 1'000'000'000;
    r.value.hour = static_cast<std::uint8_t>(s / 3600);
    r.value.minute = static_cast<std::uint8_t>(s / 60 % 60);
    r.value.second = static_cast<std::uint8_t>(s % 60);
    r.value.fraction = static_cast<std::uint32_t>(static_cast<std::uint64_t>(ns % 1'000'000'000) /
                                                  seawire::detail::pow10_table[9 - places]);
    r.value.places = static_cast<std::uint8_t>(places);
    return r;
  }
  /// The UTC time of day of a system_clock time point (system_clock counts UTC without leap
  /// seconds), truncated to `places` fraction digits (0 to 9; out_of_range beyond). Any
  /// time point, before 1970 too.
  template <class Duration>
  [[nodiscard]] static constexpr result<time_of_day> from(std::chrono::sys_time<Duration> t,
                                                          unsigned places = 3) noexcept {
    using namespace std::chrono;
    const auto ns = time_point_cast<nanoseconds>(t);
    return from_since_midnight(ns - floor<days>(ns), places);
  }
  friend constexpr bool operator==(const time_of_day&, const time_of_day&) noexcept = default;
};

/// A ddmmyy date. Two-digit years are read as 1980..2079 (GPS time began in 1980).
struct date {
  std::uint16_t year = 2000;
  std::uint8_t month = 1;
  std::uint8_t day = 1;

  constexpr date() noexcept = default;
  /// `date{2014, 12, 31}`.
  constexpr date(std::uint16_t y, std::uint8_t m, std::uint8_t d) noexcept
      : year(y), month(m), day(d) {}
  template <class... A>
  requires detail::any_floating<A...>
  explicit date(A...) = delete;  // a date is whole numbers: date{year, month, day} or date::from()

  [[nodiscard]] constexpr std::chrono::year_month_day ymd() const noexcept {
    return std::chrono::year_month_day{std::chrono::year{year}, std::chrono::month{month},
                                       std::chrono::day{day}};
  }
  /// The day as a system_clock time point (its midnight, UTC).
  [[nodiscard]] constexpr std::chrono::sys_days sys_days() const noexcept {
    return std::chrono::sys_days{ymd()};
  }
  /// The UTC date of a system_clock time point. A ddmmyy field holds 1980..2079: a date
  /// outside is refused when written (out_of_range).
  template <class Duration>
  [[nodiscard]] static constexpr date from(std::chrono::sys_time<Duration> t) noexcept {
    return from(std::chrono::year_month_day{std::chrono::floor<std::chrono::days>(t)});
  }
  [[nodiscard]] static constexpr date from(std::chrono::year_month_day d) noexcept {
    return {static_cast<std::uint16_t>(static_cast<int>(d.year())),
            static_cast<std::uint8_t>(static_cast<unsigned>(d.month())),
            static_cast<std::uint8_t>(static_cast<unsigned>(d.day()))};
  }
  friend constexpr bool operator==(const date&, const date&) noexcept = default;
};

namespace detail {
[[nodiscard]] constexpr unsigned days_in_month(unsigned month, unsigned year) noexcept {
  constexpr unsigned days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return month == 2 && leap ? 29 : days[month - 1];
}
}  // namespace detail

/// The system_clock time point of a UTC date and time of day (RMC's fields 9 and 1, RobotX's
/// date and time), to the nanosecond. system_clock has no leap seconds: 23:59:60 is the next
/// day's 00:00:00.
[[nodiscard]] constexpr std::chrono::sys_time<std::chrono::nanoseconds> to_sys_time(
    const date& d, const time_of_day& t) noexcept {
  return d.sys_days() + t.since_midnight();
}

// ---------------------------------------------------------------------------------------------
// text

/// Text held inline, at most N bytes: no allocation, no view into the input that could dangle.
template <std::size_t N>
class text {
 public:
  static_assert(N > 0 && N <= 0xFFFF);
  static constexpr std::size_t capacity = N;

  constexpr text() noexcept = default;
  /// From a literal that fits (checked at compile time).
  template <std::size_t M>
  // NOLINTNEXTLINE(google-explicit-constructor): text<5> team = "AUVSI";
  constexpr text(const char (&s)[M]) noexcept {
    static_assert(M - 1 <= N, "literal longer than the text's capacity");
    for (std::size_t i = 0; i + 1 < M; ++i) data_[i] = s[i];
    size_ = static_cast<std::uint16_t>(M - 1);
  }
  /// Replace the content; false (and unchanged) when `s` does not fit.
  constexpr bool assign(std::string_view s) noexcept {
    if (s.size() > N) return false;
    for (std::size_t i = 0; i < s.size(); ++i) data_[i] = s[i];
    size_ = static_cast<std::uint16_t>(s.size());
    return true;
  }
  [[nodiscard]] constexpr std::string_view view() const noexcept { return {data_, size_}; }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0; }

  friend constexpr bool operator==(const text& a, const text& b) noexcept {
    return a.view() == b.view();
  }
  friend constexpr bool operator==(const text& a, std::string_view b) noexcept {
    return a.view() == b;
  }
  template <std::size_t M>
  friend constexpr bool operator==(const text& a, const char (&b)[M]) noexcept {
    return a.view() == std::string_view(b, M - 1);
  }

 private:
  char data_[N]{};
  std::uint16_t size_ = 0;
};

/// Two-character talker of a standard sentence ("GP", "GN", "II").
using talker_id = text<2>;

// ---------------------------------------------------------------------------------------------
// enums
//
// A single-letter field is an `enum class E : char` whose enumerators are the letters, with a
// function found by ADL listing them:   constexpr std::string_view enum_chars(E) { return "AV"; }
// (C++20 cannot list an enum's enumerators without parsing compiler-specific text, which costs
// every translation unit about 7 ms an enum with GCC and 18 ms with Clang; seawire's tests check
// that each enum_chars lists exactly its enum's enumerators instead.)
// A word field is an enum whose values index an array of its spellings, with
//   constexpr std::array<std::string_view, K> enum_words(E) { return {"ON", "OFF"}; }
// and optionally other spellings accepted on receive:
//   constexpr std::array<std::pair<std::string_view, E>, K> enum_aliases(E) { ... }

template <class E>
concept char_enum_like = std::is_enum_v<E> && requires(E e) {
  { enum_chars(e) } -> std::convertible_to<std::string_view>;
};
template <class E>
concept word_enum_like = std::is_enum_v<E> && requires(E e) {
  enum_words(e);
};
template <class E>
concept has_enum_aliases = requires(E e) {
  enum_aliases(e);
};

/// The wire spelling of an enum value ("A", "ON"); empty if the value is not one of its own.
template <class E>
requires char_enum_like<E> || word_enum_like<E>
[[nodiscard]] constexpr std::string_view to_string(const E& e) noexcept {
  if constexpr (char_enum_like<E>) {
    constexpr std::string_view chars = enum_chars(E{});
    const std::size_t pos = chars.find(static_cast<char>(e));
    return pos == std::string_view::npos ? std::string_view{} : chars.substr(pos, 1);
  } else {
    constexpr auto words = enum_words(E{});
    const auto i = static_cast<std::size_t>(e);
    return i < words.size() ? words[i] : std::string_view{};
  }
}

// ---------------------------------------------------------------------------------------------
// codecs

/// codec<T>: `width` wire fields; read() takes them from the reader (the first is known to be
/// present and non-blank unless `allows_blank`), check() applies the value's own domain before
/// writing, write() writes them (the message layer writes the comma before the first).
/// `max_chars` is the longest text write() produces for a value check() accepts (the commas
/// between its own wire fields included): encode() sizes its buffer from it.
template <class T>
struct codec;

template <>
struct codec<decimal> {
  static constexpr unsigned width = 1;
  /// Longest text written: sign, 20 integer digits (padding), point, 19 fraction digits.
  static constexpr std::size_t max_chars = 41;
  static constexpr bool allows_blank = false;
  SEAWIRE_ALWAYS_INLINE static constexpr errc read(field_reader& r, decimal& v) noexcept {
    return detail::parse_decimal(r.take().text, r.policy(), v);
  }
  static constexpr errc check(const decimal& v) noexcept { return detail::check_decimal(v); }
  static constexpr void write(writer& w, const decimal& v) noexcept { detail::write_decimal(w, v); }
};

template <std::integral I>
requires(!std::same_as<I, bool> && !std::same_as<I, char>) struct codec<I> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars =
      std::numeric_limits<I>::digits10 + 1 + (std::is_signed_v<I> ? 1 : 0);
  static constexpr bool allows_blank = false;
  SEAWIRE_ALWAYS_INLINE static constexpr errc read(field_reader& r, I& v) noexcept {
    decimal d;
    const errc e = detail::parse_decimal(r.take().text, r.policy(), d);
    if (e != errc::ok) return e;
    if (d.places != 0) [[unlikely]]
      return errc::bad_number;
    if (d.negative && d.mantissa != 0) {
      if constexpr (std::is_unsigned_v<I>) {
        return errc::out_of_range;
      } else {
        if (d.mantissa > static_cast<std::uint64_t>(std::numeric_limits<I>::max()) + 1)
          return errc::out_of_range;
        v = static_cast<I>(0 - d.mantissa);
        return errc::ok;
      }
    }
    if (d.mantissa > static_cast<std::uint64_t>(std::numeric_limits<I>::max()))
      return errc::out_of_range;
    v = static_cast<I>(d.mantissa);
    return errc::ok;
  }
  static constexpr errc check(const I&) noexcept { return errc::ok; }
  static constexpr void write(writer& w, const I& v) noexcept {
    if constexpr (std::is_signed_v<I>) {
      if (v < 0) {
        w.put('-');
        w.put_uint(0 - static_cast<std::uint64_t>(static_cast<std::int64_t>(v)));
        return;
      }
    }
    w.put_uint(static_cast<std::uint64_t>(v));
  }
};

/// A 0/1 flag.
template <>
struct codec<bool> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = 1;
  static constexpr bool allows_blank = false;
  SEAWIRE_ALWAYS_INLINE static constexpr errc read(field_reader& r, bool& v) noexcept {
    const std::string_view t = r.take().text;
    if (t.size() != 1 || (t[0] != '0' && t[0] != '1')) [[unlikely]]
      return errc::bad_flag;
    v = t[0] == '1';
    return errc::ok;
  }
  static constexpr errc check(const bool&) noexcept { return errc::ok; }
  static constexpr void write(writer& w, const bool& v) noexcept { w.put(v ? '1' : '0'); }
};

template <class Axis>
struct codec<nmea_coordinate<Axis>> {
  using value_type = nmea_coordinate<Axis>;
  static constexpr unsigned width = 2;
  /// DDDMM, point, 12 fraction digits (check's limit), comma, letter.
  static constexpr std::size_t max_chars = Axis::width + 2 + 1 + 12 + 2;
  static constexpr bool allows_blank = false;

  SEAWIRE_ALWAYS_INLINE static constexpr errc read(field_reader& r, value_type& v) noexcept {
    const std::string_view s = r.take().text;
    // One pass. The digits before the point are DDMM: one to Axis::width degree digits and
    // exactly two minute digits. Those after it are the fraction of the minute.
    const std::size_t n = s.size();
    std::size_t i = 0;
    std::uint64_t ddmm = 0;
    detail::read_digits(s, i, ddmm);
    const std::size_t point = i;
    if (point < 3 || point - 2 > Axis::width) [[unlikely]]
      return Axis::error;
    std::uint64_t fraction = 0;
    std::size_t places = 0;
    if (i < n) {
      if (s[i] != '.') [[unlikely]]
        return Axis::error;
      const std::size_t fraction_begin = ++i;
      detail::read_digits(s, i, fraction);
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
    decimal minutes;  // int_width stays 0: minutes are always written with two digits
    minutes.mantissa = whole_minutes * seawire::detail::pow10_table[places] + fraction;
    minutes.places = static_cast<std::uint8_t>(places);
    if (deg > Axis::max_degrees || (deg == Axis::max_degrees && minutes.mantissa != 0))
      return Axis::error;
    v.whole_degrees = static_cast<std::uint16_t>(deg);
    v.minutes = minutes;
    v.degree_digits = static_cast<std::uint8_t>(point - 2);
    return read_hemisphere<Axis>(r, v.hemi);
  }
  static constexpr errc check(const value_type& v) noexcept {
    if (v.minutes.negative || v.minutes.places > 12 ||
        v.minutes.mantissa >= 60 * seawire::detail::pow10_table[v.minutes.places])
      return errc::minute_out_of_range;
    if (v.whole_degrees > Axis::max_degrees ||
        (v.whole_degrees == Axis::max_degrees && v.minutes.mantissa != 0) ||
        v.degree_digits > Axis::width)
      return Axis::error;
    return check_hemisphere<Axis>(v.hemi);
  }
  static constexpr void write(writer& w, const value_type& v) noexcept {
    w.put_uint(v.whole_degrees, v.degree_digits);
    const decimal m = v.written_minutes();
    w.put_fixed(m.mantissa, m.places, 2);
    w.next_field();
    w.put(static_cast<char>(v.hemi));
  }

  /// An error check() gives is about the hemisphere letter (the second wire field) or the number.
  static constexpr unsigned error_offset(errc e) noexcept {
    return e == errc::bad_hemisphere ? 1 : 0;
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

  SEAWIRE_ALWAYS_INLINE static constexpr errc read(field_reader& r, value_type& v) noexcept {
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
  static constexpr errc check(const value_type& v) noexcept {
    if (const errc e = detail::check_decimal(v.value); e != errc::ok) return e;
    if (v.value.negative || v.value.compare(decimal(Axis::max_degrees)) > 0) [[unlikely]]
      return Axis::error;
    return nmea::template check_hemisphere<Axis>(v.hemi);
  }
  static constexpr unsigned error_offset(errc e) noexcept { return nmea::error_offset(e); }
  static constexpr void write(writer& w, const value_type& v) noexcept {
    detail::write_decimal(w, v.value);
    w.next_field();
    w.put(static_cast<char>(v.hemi));
  }
};

template <>
struct codec<time_of_day> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = 16;  // hhmmss.fffffffff
  static constexpr bool allows_blank = false;
  SEAWIRE_ALWAYS_INLINE static constexpr errc read(field_reader& r, time_of_day& v) noexcept {
    const std::string_view s = r.take().text;
    if (s.size() < 6) [[unlikely]]
      return errc::bad_time;
    unsigned two[3];  // hh, mm, ss
    if (!detail::parse_digit_pairs(s, two)) [[unlikely]]
      return errc::bad_time;
    unsigned frac = 0;
    std::size_t places = 0;
    if (s.size() > 6) {
      places = s.size() - 7;
      // "hhmmss." with nothing after the point is malformed, not zero places.
      if (s[6] != '.' || places == 0 || places > 9 ||
          !detail::parse_fixed_digits(s, 7, places, frac))
        return errc::bad_time;
    }
    v = {static_cast<std::uint8_t>(two[0]), static_cast<std::uint8_t>(two[1]),
         static_cast<std::uint8_t>(two[2]), frac, static_cast<std::uint8_t>(places)};
    return check(v);
  }
  SEAWIRE_ALWAYS_INLINE static constexpr errc check(const time_of_day& v) noexcept {
    if (v.hour > 23) [[unlikely]]
      return errc::hour_out_of_range;
    if (v.minute > 59) [[unlikely]]
      return errc::minute_out_of_range;
    if (v.second > 60 || (v.second == 60 && !(v.hour == 23 && v.minute == 59)))
      return errc::second_out_of_range;
    if (v.places > 9 || v.fraction >= seawire::detail::pow10_table[v.places]) [[unlikely]]
      return errc::bad_time;
    return errc::ok;
  }
  static constexpr void write(writer& w, const time_of_day& v) noexcept {
    w.put_uint(v.hour, 2);
    w.put_uint(v.minute, 2);
    w.put_uint(v.second, 2);
    if (v.places > 0) {
      w.put('.');
      w.put_uint(v.fraction, v.places);
    }
  }
};

template <>
struct codec<date> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = 6;
  static constexpr bool allows_blank = false;
  SEAWIRE_ALWAYS_INLINE static constexpr errc read(field_reader& r, date& v) noexcept {
    const std::string_view s = r.take().text;
    if (s.size() != 6) [[unlikely]]
      return errc::bad_date;
    unsigned two[3];  // dd, mm, yy
    if (!detail::parse_digit_pairs(s, two)) [[unlikely]]
      return errc::bad_date;
    v = {static_cast<std::uint16_t>(two[2] < 80 ? 2000 + two[2] : 1900 + two[2]),
         static_cast<std::uint8_t>(two[1]), static_cast<std::uint8_t>(two[0])};
    return check(v);
  }
  SEAWIRE_ALWAYS_INLINE static constexpr errc check(const date& v) noexcept {
    if (v.year < 1980 || v.year > 2079) [[unlikely]]
      return errc::out_of_range;
    if (v.month < 1 || v.month > 12) [[unlikely]]
      return errc::month_out_of_range;
    if (v.day < 1 || v.day > detail::days_in_month(v.month, v.year)) [[unlikely]]
      return errc::day_out_of_range;
    return errc::ok;
  }
  static constexpr void write(writer& w, const date& v) noexcept {
    w.put_uint(v.day, 2);
    w.put_uint(v.month, 2);
    w.put_uint(v.year % 100u, 2);
  }
};

template <std::size_t N>
struct codec<text<N>> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = N;
  static constexpr bool allows_blank = true;  // blank text is empty text
  SEAWIRE_ALWAYS_INLINE static constexpr errc read(field_reader& r, text<N>& v) noexcept {
    const std::string_view s = r.take().text;
    if (r.policy().strict_values) {
      const errc e = check_chars(s);
      if (e != errc::ok) return e;
    }
    return v.assign(s) ? errc::ok : errc::text_too_long;
  }
  static constexpr errc check(const text<N>& v) noexcept { return check_chars(v.view()); }
  static constexpr errc check_chars(std::string_view s) noexcept {
    for (char c : s)
      if (!seawire::detail::is_printable(c) || seawire::detail::is_reserved(c))
        return errc::bad_text;
    return errc::ok;
  }
  static constexpr void write(writer& w, const text<N>& v) noexcept { w.put(v.view()); }
};

template <char_enum_like E>
struct codec<E> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = 1;
  static constexpr bool allows_blank = false;
  // Which bytes are letters of E: one lookup instead of a search through enum_chars.
  static constexpr std::array<bool, 256> letters = [] {
    std::array<bool, 256> t{};
    for (const char c : std::string_view(enum_chars(E{}))) t[static_cast<unsigned char>(c)] = true;
    return t;
  }();
  SEAWIRE_ALWAYS_INLINE static constexpr errc read(field_reader& r, E& v) noexcept {
    const std::string_view s = r.take().text;
    if (s.size() != 1 || !letters[static_cast<unsigned char>(s[0])]) [[unlikely]]
      return errc::bad_enum;
    v = static_cast<E>(s[0]);
    return errc::ok;
  }
  static constexpr errc check(const E& v) noexcept {
    return letters[static_cast<unsigned char>(static_cast<char>(v))] ? errc::ok : errc::bad_enum;
  }
  static constexpr void write(writer& w, const E& v) noexcept { w.put(static_cast<char>(v)); }
};

template <word_enum_like E>
struct codec<E> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = [] {
    std::size_t n = 0;
    for (const std::string_view w : enum_words(E{})) n = w.size() > n ? w.size() : n;
    return n;
  }();
  static constexpr bool allows_blank = false;
  SEAWIRE_ALWAYS_INLINE static constexpr errc read(field_reader& r, E& v) noexcept {
    const std::string_view s = r.take().text;
    constexpr auto words = enum_words(E{});
    for (std::size_t i = 0; i < words.size(); ++i) {
      if (words[i] == s) {
        v = static_cast<E>(i);
        return errc::ok;
      }
    }
    if constexpr (has_enum_aliases<E>) {
      for (const auto& [word, value] : enum_aliases(E{})) {
        if (word == s) {
          v = value;
          return errc::ok;
        }
      }
    }
    return errc::bad_enum;
  }
  static constexpr errc check(const E& v) noexcept {
    return to_string(v).empty() ? errc::bad_enum : errc::ok;
  }
  static constexpr void write(writer& w, const E& v) noexcept { w.put(to_string(v)); }
};

template <class T>
concept has_codec = requires {
  codec<T>::width;
};

}  // namespace seawire::nmea
