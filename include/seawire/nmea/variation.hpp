// SPDX-License-Identifier: BSL-1.0
#pragma once
// Magnetic variation: two wire fields, degrees and E/W (RMC fields 10-11).
//
//   ...,311214,15.3,W,A*hh     15.3 degrees west: true = magnetic - 15.3
//   ...,311214,,E,A*hh         a letter without a value: kept, and written back as it came
//   ...,311214,999.9,E,A*hh    no variation is 999.9 degrees: some receivers send it for
//                              "unknown"; read as a letter without a value, so the fix stays
//   ...,181207,0,A*hh          11 fields, the letter left out and the mode in its place (SiRF,
//                              Saab): no variation, mode A; written back ...,181207,,,A
//
// Easterly variation is positive (true bearing = magnetic bearing + variation). A value beyond
// 180 degrees, or one without its letter, costs nothing on receive: it reads as not available.
// A malformed number is bad_variation, a letter other than E/W bad_variation_direction. Only 0..180
// with E or W is ever written (variation_out_of_range otherwise).

#include <cstddef>
#include <optional>
#include <string_view>

#include "seawire/error.hpp"
#include "seawire/nmea/fields.hpp"

namespace seawire::nmea {

struct magnetic_variation {
  /// Unsigned degrees, 0..180; empty when the sender gave the letter but no usable value.
  std::optional<decimal> value;
  hemisphere direction = hemisphere::east;  ///< east or west

  /// Signed degrees, west negative; empty when the value is not available.
  [[nodiscard]] constexpr std::optional<double> degrees() const noexcept {
    if (!value) return std::nullopt;
    const double v = value->to_double();
    return direction == hemisphere::west ? -v : v;
  }

  /// From signed degrees (west negative), rounded to `places` fraction digits (0 to 15) by
  /// the rule for every double (decimal::from_double); a variation that rounds to zero is east.
  /// variation_out_of_range beyond 180 degrees, not_finite for NaN and infinities.
  [[nodiscard]] static constexpr result<magnetic_variation> from_degrees(
      double deg, unsigned places = 1) noexcept {
    result<magnetic_variation> r;
    if (places > 15) {
      r.ec = errc::value_too_large;
      return r;
    }
    const result<decimal> d = decimal::from_double(deg < 0 ? -deg : deg, places);
    if (!d) {
      r.ec = d.ec;
      return r;
    }
    if (d.value.compare(decimal{180}) > 0) {
      r.ec = errc::variation_out_of_range;
      return r;
    }
    r.value.value = d.value;
    r.value.direction = deg < 0 && !d.value.is_zero() ? hemisphere::west : hemisphere::east;
    return r;
  }

  friend constexpr bool operator==(const magnetic_variation&,
                                   const magnetic_variation&) noexcept = default;
};

template <>
struct codec<magnetic_variation> {
  static constexpr unsigned width = 2;
  static constexpr std::size_t max_chars = codec<decimal>::max_chars + 2;
  /// The codec sees a blank value field, to keep a letter that came without one.
  static constexpr bool allows_blank = true;

  static constexpr errc read(field_reader& r, magnetic_variation& v) noexcept {
    const std::string_view number = r.take().text;
    v.value.reset();
    if (!number.empty()) {
      decimal d;
      if (!read_number(number, r.policy(), d)) [[unlikely]]
        return errc::bad_variation;
      if (d.compare(decimal{180}) <= 0) v.value = d;  // beyond: no variation; not available
    }
    const field_token letter = r.take();
    if (!is_direction(letter.text)) return errc::bad_variation_direction;
    v.direction = static_cast<hemisphere>(letter.text[0]);
    return errc::ok;
  }

  /// How many wire fields at the reader hold no variation at all, for the message layer to
  /// pass over (the optional stays empty; it is written back as two blank fields): 0 when they
  /// hold one, or something read() refuses. 2 for both blank, or a number without its letter (a
  /// direction cannot be guessed). 1 when the letter's field is the sentence's last and holds no
  /// direction: some receivers (SiRF, Saab) leave the letter out of an RMC that has a mode,
  /// "...,181207,0,A" in 11 fields, and that field is the next one's.
  [[nodiscard]] static constexpr unsigned nothing_span(field_reader r) noexcept {
    const field_token number = r.take();
    const field_token letter = r.take();
    const bool left_out =
        !letter.blank() && r.index() == r.field_count() && !is_direction(letter.text);
    if (!letter.blank() && !left_out) return 0;
    decimal d;
    if (!number.blank() && !read_number(number.text, r.policy(), d)) return 0;
    return left_out ? 1 : 2;
  }

  /// The one-pass reader (one_pass.hpp): "[number],E|W" at `p`, up to the byte after the
  /// letter; nullptr for what read() refuses. The number may be blank (a letter without one).
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan(const char* p, const char* end,
                                                          magnetic_variation& v) noexcept {
    v.value.reset();
    if (p != end && *p != ',') {
      decimal d;
      if (*p == '-' || (p = detail::scan_decimal(p, d)) == nullptr) [[unlikely]]
        return nullptr;
      if (d.compare(decimal{180}) <= 0) v.value = d;  // beyond: no variation, as read()
    }
    if (p == end || *p != ',' || (p[1] != 'E' && p[1] != 'W')) [[unlikely]]
      return nullptr;
    v.direction = static_cast<hemisphere>(p[1]);
    return p + 2;
  }
  /// The one-pass form of nothing_span for its commonest cases: the end of the two wire fields
  /// at `p` when they hold no variation (both blank, or a number without its letter); nullptr
  /// when they hold one, or need the general path to tell.
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan_nothing(const char* p,
                                                                  const char* end) noexcept {
    if (p == end) return nullptr;
    if (*p != ',') {
      decimal d;
      if (*p == '-' || (p = detail::scan_decimal(p, d)) == nullptr || p == end || *p != ',')
        return nullptr;
    }
    return p + 1 == end || p[1] == ',' ? p + 1 : nullptr;
  }

  /// Unsigned on the wire: a sign would contradict (or duplicate) the letter.
  [[nodiscard]] static constexpr bool read_number(std::string_view s, const parse_policy& p,
                                                  decimal& d) noexcept {
    return s[0] != '-' && s[0] != '+' && detail::parse_decimal(s, p, d) == errc::ok;
  }
  [[nodiscard]] static constexpr bool is_direction(std::string_view letter) noexcept {
    return letter == "E" || letter == "W";
  }

  static constexpr errc check(const magnetic_variation& v) noexcept {
    if (v.direction != hemisphere::east && v.direction != hemisphere::west)
      return errc::bad_variation_direction;
    if (!v.value) return errc::ok;
    if (const errc e = detail::check_decimal(*v.value); e != errc::ok) return e;
    if (v.value->negative || v.value->compare(decimal{180}) > 0)
      return errc::variation_out_of_range;
    return errc::ok;
  }
  /// Errors about the letter are in the second wire field.
  static constexpr unsigned error_offset(errc e) noexcept {
    return e == errc::bad_variation_direction ? 1 : 0;
  }
  /// The wire fields after the first, as about_field names them.
  [[nodiscard]] static constexpr std::string_view part_name(unsigned k) noexcept {
    return k == 1 ? "direction letter" : "";
  }
  /// Why read() refused `text` (wire field `k` of the two): a sign, a blank letter.
  [[nodiscard]] static constexpr std::string_view explain(unsigned k, errc e,
                                                          std::string_view text) noexcept {
    if (k == 1 && e == errc::bad_variation_direction && text.empty())
      return "magnetic variation letter is missing (blank)";
    if (k == 0 && e == errc::bad_variation && !text.empty() && (text[0] == '-' || text[0] == '+'))
      return "a sign is not allowed: the E/W letter carries it";
    return "";
  }
  template <sentence_writer W>
  static constexpr void write(W& w, const magnetic_variation& v) noexcept {
    if (v.value) detail::write_decimal(w, *v.value);
    w.next_field();
    w.put(static_cast<char>(v.direction));
  }
};

}  // namespace seawire::nmea
