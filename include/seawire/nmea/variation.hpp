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

  /// From signed degrees (west negative), rounded to `places` fraction digits (0 to 15).
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
    r.value.direction = deg < 0 ? hemisphere::west : hemisphere::east;
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
      // Unsigned on the wire: a sign would contradict (or duplicate) the letter.
      decimal d;
      if (number[0] == '-' || number[0] == '+' ||
          detail::parse_decimal(number, r.policy(), d) != errc::ok) [[unlikely]]
        return errc::bad_variation;
      if (d.compare(decimal{180}) <= 0) v.value = d;  // beyond: no variation; not available
    }
    const field_token letter = r.take();
    if (letter.text.size() != 1 || (letter.text[0] != 'E' && letter.text[0] != 'W'))
      return errc::bad_variation_direction;
    v.direction = static_cast<hemisphere>(letter.text[0]);
    return errc::ok;
  }

  /// Whether the two fields at the reader hold no variation at all: both blank, or a number
  /// without its letter (a direction cannot be guessed). The message layer then leaves the
  /// optional empty, and it is written back as two blank fields.
  [[nodiscard]] static constexpr bool is_nothing(field_reader r) noexcept {
    const field_token number = r.take();
    const field_token letter = r.take();
    if (!letter.blank() && !mode_in_letter(r, letter.text)) return false;
    if (number.blank()) return true;
    decimal d;
    return number.text[0] != '-' && number.text[0] != '+' &&
           detail::parse_decimal(number.text, r.policy(), d) == errc::ok;
  }
  /// The wire fields a variation that reads as nothing spans: one when a receiver left its
  /// letter out and the next field (RMC's mode) took that place, else both.
  [[nodiscard]] static constexpr unsigned nothing_width(field_reader r) noexcept {
    (void)r.take();
    const field_token letter = r.take();
    return !letter.blank() && mode_in_letter(r, letter.text) ? 1 : 2;
  }

  /// Some receivers (SiRF, Saab) leave the variation's letter out of an RMC that has a mode:
  /// "...,181207,0,A" in 11 fields, the mode where the letter would be. A mode letter that is
  /// no direction (not E), as the sentence's last field, is read that way. `after` is past it.
  [[nodiscard]] static constexpr bool mode_in_letter(const field_reader& after,
                                                     std::string_view letter) noexcept {
    return after.index() == after.field_count() && letter.size() == 1 &&
           std::string_view("ADFMNPRS").find(letter[0]) != std::string_view::npos;
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
  static constexpr void write(writer& w, const magnetic_variation& v) noexcept {
    if (v.value) detail::write_decimal(w, *v.value);
    w.next_field();
    w.put(static_cast<char>(v.direction));
  }
};

}  // namespace seawire::nmea
