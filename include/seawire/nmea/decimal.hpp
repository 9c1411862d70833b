// SPDX-License-Identifier: BSL-1.0
#pragma once
// Numbers as the wire has them: nmea::decimal keeps every digit as written ("4.50" stays "4.50",
// "045" keeps its padding), and the codecs of decimal, of integer fields (read as decimals with no
// fraction, range-checked for their type) and of 0/1 flags.

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>
#include <type_traits>

#include "seawire/detail/ascii.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/detail/rounding.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/codec.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"

namespace seawire::nmea {

/// The integer types that hold numbers: not bool, and none of the character types (`= '7'`
/// would be 55, `= u8'7'` too). What seawire's numbers (decimal, integer<T>) take implicitly.
template <class I>
concept whole_number = std::integral<I> && !std::is_same_v<I, bool> && !std::is_same_v<I, char> &&
                       !std::is_same_v<I, wchar_t> && !std::is_same_v<I, char8_t> &&
                       !std::is_same_v<I, char16_t> && !std::is_same_v<I, char32_t>;

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
  template <whole_number I>
  // NOLINTNEXTLINE(google-explicit-constructor): decimal{45} and in_range(-100, 100) read well.
  constexpr decimal(I integer) noexcept
      : mantissa(seawire::detail::magnitude(integer)), negative(integer < 0) {}
  /// A floating-point value is never taken silently (a speed cut to an integer is another
  /// command): say how many places, decimal::from_double(1.5, 1), parse("1.5") or 1.5_dec.
  template <std::floating_point F>
  decimal(F) = delete;  // use decimal::from_double(v, places), decimal::parse("1.5") or 1.5_dec

  /// `mantissa` / 10^places: decimal::scaled(450, 2) is "4.50". Both are integers (a double
  /// does not compile); places above 19 is refused when the value is written (value_too_large).
  template <whole_number I, whole_number P>
  [[nodiscard]] static constexpr decimal scaled(I mantissa, P places) noexcept {
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

  /// `v` at `places` fraction digits (0 to 19) by seawire's one rule for doubles
  /// (detail/rounding.hpp): 1.005 -> 1.01 at two places; a value that rounds to zero is "0.00",
  /// never "-0.00". not_finite for NaN and infinities; value_too_large past 19 places or digits.
  [[nodiscard]] static constexpr result<decimal> from_double(double v, unsigned places) noexcept {
    result<decimal> r;
    seawire::detail::rounded_double m;
    r.ec = seawire::detail::round_double(v, 1, static_cast<int>(places > 99 ? 99 : places), 1, m);
    if (r && (places > seawire::detail::max_fraction_digits ||
              m.magnitude > 9'999'999'999'999'999'999ULL))
      r.ec = errc::value_too_large;
    if (!r) return r;
    r.value.mantissa = m.magnitude;
    r.value.places = static_cast<std::uint8_t>(places);
    r.value.negative = m.negative && m.magnitude != 0;
    return r;
  }

  /// `v` as its shortest decimal, with the fraction digits that takes ("0.30000000000000004"
  /// for 0.1 + 0.2, "203.1" for 203.1, "0" for -0.0). not_finite for NaN and infinities;
  /// value_too_large when that decimal has more than 19 digits or 19 places (1e-20, 1e19).
  [[nodiscard]] static constexpr result<decimal> shortest(double v) noexcept {
    seawire::detail::shortest_decimal s;
    const errc e = seawire::detail::shortest(v, s);
    if (e != errc::ok) return {decimal{}, e};
    const unsigned places = s.exponent < 0 ? static_cast<unsigned>(-s.exponent) : 0U;
    return from_double(v, places);  // at its own places, the rounding changes nothing
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
  /// int_width of 1 on "45" pads nothing); the writer pads to max_integer_digits (20) at most.
  [[nodiscard]] constexpr unsigned written_int_digits() const noexcept {
    using seawire::detail::max_integer_digits;
    const unsigned natural =
        places > seawire::detail::max_fraction_digits
            ? 0
            : seawire::detail::digit_count(mantissa / seawire::detail::pow10_table[places]);
    const unsigned padded = int_width < max_integer_digits ? int_width : max_integer_digits;
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
  out.int_width = static_cast<std::uint8_t>(
      int_written > natural && int_written <= seawire::detail::max_integer_digits ? int_written
                                                                                  : 0);
  return errc::ok;
}

/// Reads the run of digits at s[i] onto m (m * 10 + digit each; past 19 digits m wraps, and the
/// caller, which sees the count, does not use it) and moves i past it. With field_end::comma the
/// byte just past s may be read and is no digit (the ',' after a field in its sentence): that
/// byte then ends the run, and no digit needs a length test.
constexpr void read_digits(std::string_view s, std::size_t& i, std::uint64_t& m,
                           field_end end = field_end::unknown) noexcept {
  const auto digit = [](char c) {
    return static_cast<unsigned>(static_cast<unsigned char>(c)) - unsigned{'0'};
  };
  if (end == field_end::comma) {
    const char* const p = s.data();
    for (unsigned d = 0; (d = digit(p[i])) < 10; ++i) m = m * 10 + d;
    return;
  }
  for (unsigned d = 0; i < s.size() && (d = digit(s[i])) < 10; ++i) m = m * 10 + d;
}

/// The integer width of `written` digits at `digits` when they are zero-padded ("007.5", "00"):
/// kept so the number is written back as it came; 0 when they are not.
[[nodiscard]] constexpr std::uint8_t padded_width(const char* digits,
                                                  std::size_t written) noexcept {
  if (written <= 1 || digits[0] != '0') return 0;
  std::size_t zeros = 1;
  while (zeros < written && digits[zeros] == '0') ++zeros;
  const std::size_t natural = written - zeros == 0 ? 1 : written - zeros;
  return static_cast<std::uint8_t>(written > natural ? written : 0);
}

/// The one-pass form of parse_decimal (one_pass.hpp): [-] digits [. digits] at `p`, read up to
/// the first byte that is no part of it, which the caller guarantees exists (the '*' of a
/// framed sentence). nullptr where parse_decimal would refuse the text or needs a policy to
/// accept it: a '+' sign, spaces, no digit, more than 19 digits. What it accepts, parse_decimal
/// reads to the same value.
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr const char* scan_decimal(const char* p,
                                                                       decimal& out) noexcept {
  const auto digit = [](char c) {
    return static_cast<unsigned>(static_cast<unsigned char>(c)) - unsigned{'0'};
  };
  const bool neg = *p == '-';
  if (neg) ++p;
  const char* const int_begin = p;
  std::uint64_t m = 0;
  for (unsigned d = 0; (d = digit(*p)) < 10; ++p) m = m * 10 + d;
  const auto int_written = static_cast<std::size_t>(p - int_begin);
  std::size_t places = 0;
  if (*p == '.') {
    const char* const frac_begin = ++p;
    for (unsigned d = 0; (d = digit(*p)) < 10; ++p) m = m * 10 + d;
    places = static_cast<std::size_t>(p - frac_begin);
  }
  if (int_written + places - 1 >= 19) [[unlikely]]  // none, or more than 19
    return nullptr;
  out.mantissa = m;
  out.places = static_cast<std::uint8_t>(places);
  out.negative = neg;
  out.int_width = padded_width(int_begin, int_written);
  return p;
}

[[nodiscard]] constexpr errc parse_decimal_spaced(std::string_view s, decimal& out) noexcept;

/// Parse [sign] digits [. digits] with a receive policy's leniencies: '+' unless strict_values,
/// spaces around the number with spaced_numbers. No exponent. The policy is consulted only for a
/// sign or a bad byte. `end`: as for read_digits.
[[nodiscard]] constexpr errc parse_decimal(std::string_view s, const parse_policy& p, decimal& out,
                                           field_end end = field_end::unknown) noexcept {
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
  read_digits(s, i, m, end);
  const std::size_t int_written = i - int_begin;
  std::size_t places = 0;
  if (i < n && s[i] == '.') {
    const std::size_t frac_begin = ++i;
    read_digits(s, i, m, end);
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
  out.int_width = padded_width(s.data() + int_begin, int_written);
  return errc::ok;
}

/// The same with the two leniencies as flags: a '+' only when `liberal`, spaces around the
/// number only when `spaced` too.
[[nodiscard]] constexpr errc parse_decimal(std::string_view s, bool liberal, decimal& out,
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
  return d.places > seawire::detail::max_fraction_digits || d.mantissa > max_mantissa ||
                 d.int_width > seawire::detail::max_integer_digits
             ? errc::value_too_large
             : errc::ok;
}

template <sentence_writer W>
constexpr void write_decimal(W& w, const decimal& d) noexcept {
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

// ---------------------------------------------------------------------------------------------
// codecs

template <>
struct codec<decimal> {
  static constexpr unsigned width = 1;
  /// Longest text written: sign, 20 integer digits (padding), point, 19 fraction digits.
  static constexpr std::size_t max_chars = seawire::detail::max_fixed_chars;
  static constexpr bool allows_blank = false;
  /// scan() refuses a blank field at its first byte (one_pass.hpp: scans_no_blank).
  static constexpr bool scan_refuses_blank = true;
  static constexpr errc read(field_reader& r, decimal& v) noexcept {
    const std::string_view s = r.take().text;
    return detail::parse_decimal(s, r.policy(), v, r.end_of_field());
  }
  /// The one-pass reader: the number at `p` (not a blank field), up to the byte after it;
  /// nullptr for what read() refuses or reads only under a liberal policy.
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan(const char* p, const char*,
                                                          decimal& v) noexcept {
    return detail::scan_decimal(p, v);
  }
  static constexpr errc check(const decimal& v) noexcept { return detail::check_decimal(v); }
  template <sentence_writer W>
  static constexpr void write(W& w, const decimal& v) noexcept {
    detail::write_decimal(w, v);
  }
};

template <whole_number I>
struct codec<I> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars =
      std::numeric_limits<I>::digits10 + 1 + (std::is_signed_v<I> ? 1 : 0);
  static constexpr bool allows_blank = false;
  /// scan() refuses a blank field at its first byte (one_pass.hpp: scans_no_blank).
  static constexpr bool scan_refuses_blank = true;
  static constexpr errc read(field_reader& r, I& v) noexcept {
    decimal d;
    const std::string_view s = r.take().text;
    const errc e = detail::parse_decimal(s, r.policy(), d, r.end_of_field());
    if (e != errc::ok) return e;
    return from_decimal(d, v);
  }
  /// The one-pass reader (as codec<decimal>::scan); nullptr for what read() refuses.
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan(const char* p, const char*,
                                                          I& v) noexcept {
    decimal d;
    p = detail::scan_decimal(p, d);
    return p != nullptr && from_decimal(d, v) == errc::ok ? p : nullptr;
  }
  /// A whole number of I's range, as read() takes it from its decimal.
  SEAWIRE_ALWAYS_INLINE static constexpr errc from_decimal(const decimal& d, I& v) noexcept {
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
  template <sentence_writer W>
  static constexpr void write(W& w, const I& v) noexcept {
    if constexpr (std::is_signed_v<I>) {
      if (v < 0) {
        w.put('-');
        w.put_uint(seawire::detail::magnitude(v));
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
  /// scan() refuses a blank field at its first byte (one_pass.hpp: scans_no_blank).
  static constexpr bool scan_refuses_blank = true;
  static constexpr errc read(field_reader& r, bool& v) noexcept {
    const std::string_view t = r.take().text;
    if (t.size() != 1 || (t[0] != '0' && t[0] != '1')) [[unlikely]]
      return errc::bad_flag;
    v = t[0] == '1';
    return errc::ok;
  }
  /// The one-pass reader: one '0' or '1'.
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan(const char* p, const char*,
                                                          bool& v) noexcept {
    if (*p != '0' && *p != '1') [[unlikely]]
      return nullptr;
    v = *p == '1';
    return p + 1;
  }
  static constexpr errc check(const bool&) noexcept { return errc::ok; }
  template <sentence_writer W>
  static constexpr void write(W& w, const bool& v) noexcept {
    w.put(v ? '1' : '0');
  }
};

}  // namespace seawire::nmea
