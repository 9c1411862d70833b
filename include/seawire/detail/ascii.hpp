// SPDX-License-Identifier: BSL-1.0
#pragma once
// Character classes and small integer helpers. Locale-free and constexpr, unlike <cctype>.

#include <array>
#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <type_traits>

#include "seawire/detail/inline.hpp"

namespace seawire::detail {

/// |v| as a 64-bit unsigned number, exact for the most negative value too.
template <class I>
[[nodiscard]] constexpr std::uint64_t magnitude(I v) noexcept {
  static_assert(std::is_integral_v<I> && sizeof(I) <= sizeof(std::uint64_t));
  if constexpr (std::is_signed_v<I>) {
    // Conversion to unsigned is modular: a negative v becomes 2^64 + v, and 0 minus that is -v.
    return v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
  } else {
    return static_cast<std::uint64_t>(v);
  }
}

[[nodiscard]] constexpr bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }
[[nodiscard]] constexpr bool is_upper(char c) noexcept { return c >= 'A' && c <= 'Z'; }
[[nodiscard]] constexpr bool is_printable(char c) noexcept { return c >= 0x20 && c <= 0x7E; }

/// hex_values[c]: the value of hex digit c, or -1.
inline constexpr std::array<std::int8_t, 256> hex_values = [] {
  std::array<std::int8_t, 256> t{};
  for (int c = 0; c < 256; ++c) {
    t[static_cast<std::size_t>(c)] = static_cast<std::int8_t>(c >= '0' && c <= '9'   ? c - '0'
                                                              : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                                              : c >= 'a' && c <= 'f' ? c - 'a' + 10
                                                                                     : -1);
  }
  return t;
}();

/// Value of a hex digit, or -1. Accepts both cases; callers decide whether lower case is allowed.
[[nodiscard]] constexpr int hex_value(char c) noexcept {
  return hex_values[static_cast<unsigned char>(c)];
}

[[nodiscard]] constexpr char hex_digit_upper(unsigned nibble) noexcept {
  return "0123456789ABCDEF"[nibble & 0xFu];
}

/// "00" "01" ... "99": two digits written at once.
inline constexpr char digit_pairs[201] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/// Characters NMEA 0183 reserves for framing; never data in a sentence seawire writes.
[[nodiscard]] constexpr bool is_reserved(char c) noexcept {
  switch (c) {
    case '$':
    case ',':
    case '*':
    case '!':
    case '\\':
    case '^':
    case '~': return true;
    default: return false;
  }
}

inline constexpr std::uint64_t pow10_table[20] = {1ull,
                                                  10ull,
                                                  100ull,
                                                  1000ull,
                                                  10000ull,
                                                  100000ull,
                                                  1000000ull,
                                                  10000000ull,
                                                  100000000ull,
                                                  1000000000ull,
                                                  10000000000ull,
                                                  100000000000ull,
                                                  1000000000000ull,
                                                  10000000000000ull,
                                                  100000000000000ull,
                                                  1000000000000000ull,
                                                  10000000000000000ull,
                                                  100000000000000000ull,
                                                  1000000000000000000ull,
                                                  10000000000000000000ull};

/// The largest v for which v * 10^k fits 64 bits: scale_limit[k] == UINT64_MAX / 10^k.
inline constexpr std::uint64_t scale_limit[20] = {
    ~0ull / pow10_table[0],  ~0ull / pow10_table[1],  ~0ull / pow10_table[2],
    ~0ull / pow10_table[3],  ~0ull / pow10_table[4],  ~0ull / pow10_table[5],
    ~0ull / pow10_table[6],  ~0ull / pow10_table[7],  ~0ull / pow10_table[8],
    ~0ull / pow10_table[9],  ~0ull / pow10_table[10], ~0ull / pow10_table[11],
    ~0ull / pow10_table[12], ~0ull / pow10_table[13], ~0ull / pow10_table[14],
    ~0ull / pow10_table[15], ~0ull / pow10_table[16], ~0ull / pow10_table[17],
    ~0ull / pow10_table[18], ~0ull / pow10_table[19]};

/// Number of decimal digits of v (1 for 0). From the bit length, which fixes it to one of two
/// neighbours, and one comparison: no loop.
[[nodiscard]] constexpr unsigned digit_count(std::uint64_t v) noexcept {
  // 1233 / 4096 is log10(2) rounded up: t is the digit count or one less. v | 1 has the digits
  // of v, and makes 0 count as one digit.
  const std::uint64_t w = v | 1U;
  const auto t = static_cast<unsigned>(std::bit_width(w)) * 1233U >> 12U;
  return t + (w >= pow10_table[t] ? 1U : 0U);
}

/// The two characters of digit_pairs at `pair` (twice a number below 100) to out[0] and out[1].
constexpr void copy_pair(char* out, std::size_t pair) noexcept {
  if (std::is_constant_evaluated()) {
    out[0] = digit_pairs[pair];
    out[1] = digit_pairs[pair + 1];
  } else {
    std::memcpy(out, digit_pairs + pair, 2);  // one 16-bit load and store
  }
}

/// Writes the last `count` decimal digits of `v` (zero-padded) ending just before `end`, two at a
/// time, dividing only by constants; returns what is left of v (v / 10^count). One or two digits
/// (most fractions and integer parts written) without the loop, whose set-up costs more than
/// they do.
SEAWIRE_ALWAYS_INLINE constexpr std::uint64_t write_digits_inline(char* end, std::uint64_t v,
                                                                  unsigned count) noexcept {
  if (count <= 2) {
    if (count == 2) {
      copy_pair(end - 2, static_cast<std::size_t>(v % 100) * 2);
      return v / 100;
    }
    if (count == 1) {
      end[-1] = static_cast<char>('0' + v % 10);
      return v / 10;
    }
    return v;
  }
  if (v <= 0xFFFFFFFFU) {
    // In 32 bits (nearly every number a sentence carries): a division by 100 is then one
    // multiplication and a shift, where a 64-bit one takes a 128-bit product and five more.
    auto w = static_cast<std::uint32_t>(v);
    for (; count >= 2; count -= 2) {
      const std::uint32_t q = w / 100;
      end -= 2;
      copy_pair(end, std::size_t{w - q * 100} * 2);
      w = q;
    }
    if (count == 1) {
      *--end = static_cast<char>('0' + w % 10);
      w /= 10;
    }
    return w;
  }
  for (; count >= 2; count -= 2) {
    const auto pair = static_cast<std::size_t>(v % 100) * 2;
    v /= 100;
    end -= 2;
    copy_pair(end, pair);
  }
  if (count == 1) {
    *--end = static_cast<char>('0' + v % 10);
    v /= 10;
  }
  return v;
}

/// write_digits_inline, where the compiler decides: append_fixed's numbers have widths known only
/// when it runs, and its two calls forced inline made the writer's put_fixed 5% costlier.
constexpr std::uint64_t write_digits(char* end, std::uint64_t v, unsigned count) noexcept {
  return write_digits_inline(end, v, count);
}

/// The integer digits scaled / 10^places is written with: its own (at least one), or
/// `min_int_digits` when that is more, but at most `most` (zero padding has a limit).
constexpr unsigned integer_digits(std::uint64_t scaled, unsigned places, unsigned min_int_digits,
                                  unsigned most) noexcept {
  const unsigned n = digit_count(scaled);
  const unsigned own = n > places ? n - places : 1;
  if (own >= min_int_digits) return own;
  return min_int_digits < most ? min_int_digits : most;
}

/// The characters append_fixed writes: the integer digits, and a point and the fraction digits
/// when there are any.
constexpr std::size_t fixed_size(unsigned places, unsigned int_digits) noexcept {
  return std::size_t{int_digits} + (places == 0 ? 0 : 1 + std::size_t{places});
}

/// scaled / 10^places at out + at, right to left and dividing only by constants: `int_digits`
/// integer digits (zero-padded), then, when places is not 0, a point and all `places` fraction
/// digits ("4.50" from 450 and 2). Returns where it ends.
constexpr std::size_t append_fixed(char* out, std::size_t at, std::uint64_t scaled, unsigned places,
                                   unsigned int_digits) noexcept {
  char* const int_end = out + at + int_digits;
  if (places != 0) {
    scaled = write_digits(int_end + 1 + places, scaled, places);
    *int_end = '.';
  }
  (void)write_digits(int_end, scaled, int_digits);
  return at + fixed_size(places, int_digits);
}

/// The eight decimal digits of v (below 10^8; zero-padded) as the eight bytes of a word whose
/// lowest byte is the first digit: the two halves, their digit pairs and then their digits split
/// off in every lane at once by a multiplication and a shift, no division and no loop.
[[nodiscard]] constexpr std::uint64_t eight_digits(std::uint64_t v) noexcept {
  const std::uint64_t high = v / 10000;
  std::uint64_t x = high | ((v - high * 10000) << 32U);                // 4 digits a 32-bit lane
  const std::uint64_t h = ((x * 10486) >> 20U) & 0x0000007F0000007FU;  // / 100 (exact below 10^4)
  x = h | ((x - h * 100) << 16U);                                      // 2 digits a 16-bit lane
  const std::uint64_t t = ((x * 103) >> 10U) & 0x000F000F000F000FU;    // / 10 (exact below 100)
  x = t | ((x - t * 10) << 8U);                                        // 1 digit a byte
  return x | 0x3030303030303030U;
}

/// The bytes append_fixed_wide may write from where the number starts: it writes 16-byte words,
/// past the number's end.
inline constexpr std::size_t fixed_word_room = 33;

/// append_fixed, for a number of at most 16 digits on a little-endian host, a word at a time:
/// all its digits made at once (eight_digits), then the integer digits and the fraction digits
/// put in place by two 16-byte copies. Precondition: out[at, at + fixed_word_room) may be
/// written (what follows the number there is left undefined). Other numbers, and constant
/// evaluation, go digit pair by digit pair (append_fixed).
constexpr std::size_t append_fixed_wide(char* out, std::size_t at, std::uint64_t scaled,
                                        unsigned places, unsigned int_digits) noexcept {
  const unsigned digits = int_digits + places;
  if (std::is_constant_evaluated() || std::endian::native != std::endian::little || digits > 16)
    return append_fixed(out, at, scaled, places, int_digits);
  // scaled < 10^digits: its 16 digits, zero-padded, in text[0, 16); zeros after them, which the
  // 16-byte copies read past the last digit.
  char text[32] = {};
  std::uint64_t low = scaled;
  if (digits > 8) {
    const std::uint64_t high = scaled / 100000000;
    low = scaled - high * 100000000;
    const std::uint64_t word = eight_digits(high);
    std::memcpy(text, &word, 8);
  }
  const std::uint64_t word = eight_digits(low);
  std::memcpy(text + 8, &word, 8);
  const char* const first = text + (16 - digits);
  std::memcpy(out + at, first, 16);
  if (places != 0) {
    std::memcpy(out + at + int_digits + 1, first + int_digits, 16);
    out[at + int_digits] = '.';
  }
  return at + fixed_size(places, int_digits);
}

/// Most digits append_uint and put_uint write for a zero-padded number (a 64-bit one has 20).
inline constexpr unsigned max_padded_digits = 24;

/// The decimal digits of `v` at out + at, at least `min_digits` of them (zero-padded on the
/// left; at most max_padded_digits); returns where they end.
///
/// A number that fits its width (a month in 2 digits, a year in 4, a fraction in its places) is
/// written at that width with no digit count, as digit pairs: where `min_digits` is a constant
/// the pairs are unrolled (an hour is one 16-bit store). Forced inline, so that the compiler
/// sees the width where it is a constant.
SEAWIRE_ALWAYS_INLINE constexpr std::size_t append_uint(char* out, std::size_t at, std::uint64_t v,
                                                        unsigned min_digits = 1) noexcept {
  if (min_digits != 0 && min_digits < std::size(pow10_table) && v < pow10_table[min_digits]) {
    (void)write_digits_inline(out + at + min_digits, v, min_digits);
    return at + min_digits;
  }
  return append_fixed(out, at, v, 0, integer_digits(v, 0, min_digits, max_padded_digits));
}

/// A sink that lends its own storage: `room(n)` is where n bytes may be written (nullptr when it
/// has not that much), `commit(k)` keeps the first k of them. Numbers are then written where
/// they go, not built on the stack and copied.
template <class Sink>
concept sink_with_room = requires(Sink& s, std::size_t n) {
  { s.room(n) } -> std::same_as<char*>;
  s.commit(n);
};

/// The text `make(out)` writes at `out` (at most Most bytes; it returns how many) into `s`: in
/// the sink's own storage when it lends it, through a buffer on the stack otherwise.
template <std::size_t Most, class Sink, class Make>
SEAWIRE_ALWAYS_INLINE constexpr void put_made(Sink& s, Make&& make) noexcept {
  char tmp[Most];
  char* out = tmp;
  if constexpr (sink_with_room<Sink>) {
    if (char* const room = s.room(Most)) out = room;
  }
  const std::size_t n = make(out);  // one call, so that `make` is inlined
  if (out != tmp) {
    if constexpr (sink_with_room<Sink>) s.commit(n);
  } else {
    s.put(std::string_view(tmp, n));
  }
}

/// The same into any sink with put(std::string_view).
template <class Sink>
constexpr void put_uint(Sink& s, std::uint64_t v, unsigned min_digits = 1) noexcept {
  put_made<max_padded_digits>(
      s, [&](char* out) SEAWIRE_INLINE_LAMBDA { return append_uint(out, 0, v, min_digits); });
}

/// Most integer digits a fixed-point number is written with: a 64-bit value's 20, which is also
/// where zero padding stops.
inline constexpr unsigned max_integer_digits = 20;
/// Most fraction digits (10^19 is the largest power of ten a 64-bit integer holds).
inline constexpr unsigned max_fraction_digits = 19;
/// The longest text put_fixed writes: sign, integer digits, point, fraction digits.
inline constexpr std::size_t max_fixed_chars = 1 + max_integer_digits + 1 + max_fraction_digits;

/// scaled / 10^places (places at most max_fraction_digits) into any sink with
/// put(std::string_view), as append_fixed writes it with no padding, `-` first when `negative`.
template <class Sink>
constexpr void put_fixed(Sink& s, std::uint64_t scaled, unsigned places, bool negative) noexcept {
  // 1 + fixed_word_room bytes (the sign, then append_fixed_wide's) fit in max_fixed_chars.
  static_assert(1 + fixed_word_room <= max_fixed_chars);
  put_made<max_fixed_chars>(s, [&](char* out) SEAWIRE_INLINE_LAMBDA {
    std::size_t n = 0;
    if (negative) out[n++] = '-';
    return append_fixed_wide(out, n, scaled, places,
                             integer_digits(scaled, places, 1, max_integer_digits));
  });
}

// ---------------------------------------------------------------------------------------------
// eight digits at a time: a little-endian word of 8 bytes, its first byte the lowest

/// 0x80 in each byte of `w` that is no ASCII digit. XOR with '0' turns a digit into 0..9 and
/// every other byte into something else; adding 0x76 to the low 7 bits sets bit 7 from 10 up,
/// with no carry into the next byte.
[[nodiscard]] constexpr std::uint64_t non_digit_bytes(std::uint64_t w) noexcept {
  const std::uint64_t x = w ^ 0x3030303030303030U;
  return (((x & 0x7F7F7F7F7F7F7F7FU) + 0x7676767676767676U) | x) & 0x8080808080808080U;
}

/// The number the first `k` (1 to 8) bytes of `w` spell, each a digit: moved to the top with
/// zeros below, then pairs, fours and all eight combined by multiplications.
[[nodiscard]] constexpr std::uint64_t digits_value(std::uint64_t w, unsigned k) noexcept {
  std::uint64_t x = (w ^ 0x3030303030303030U) << (8U * (8U - k));
  x = (x * 10 + (x >> 8U)) & 0x00FF00FF00FF00FFU;
  x = (x * 100 + (x >> 16U)) & 0x0000FFFF0000FFFFU;
  return (x * 10000 + (x >> 32U)) & 0xFFFFFFFFU;
}

}  // namespace seawire::detail
