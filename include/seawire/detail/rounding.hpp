// SPDX-License-Identifier: BSL-1.0
#pragma once
// The one rule by which a double becomes a wire number.
//
// A double is taken as its shortest decimal: the fewest significant digits that read back as the
// same double (what std::to_chars(double) writes, and what a person typing 1.005 meant; the
// double's exact binary value is 1.00499999999999989...). That decimal is then rounded to the
// places or step the wire needs, exactly, halves away from zero: 1.005 -> 1.01, 2.675 -> 2.68,
// -1.005 -> -1.01, 0.125 -> 0.13 at two places. Every path from a double goes through
// round_double (nmea::decimal::from_double, the positions' and magnetic variation's
// from_degrees, nmea::builder, nmea2000::number::from and the ANELLO frame's to_wire), and every
// path from decimal text through round_scaled, the same exact halves-away-from-zero arithmetic.
//
// shortest() is hand-written to be constexpr (std::to_chars is not): Steele & White's
// free-format digits, as Burger & Dybvig state them, in big integers. round_double needs them only
// when a tie lies within the double's interval; otherwise 128-bit integers round its exact value.

#include <bit>
#include <cstdint>
#include <limits>

#include "seawire/detail/ascii.hpp"
#include "seawire/error.hpp"

namespace seawire::detail {

/// A finite double as its shortest decimal: magnitude = digits x 10^exponent.
struct shortest_decimal {
  std::uint64_t digits = 0;  ///< at most 17 digits, no trailing zero; 0 for zero
  int exponent = 0;          ///< 0 for zero
  bool negative = false;     ///< the double's sign bit (-0.0 too)

  [[nodiscard]] constexpr bool is_zero() const noexcept { return digits == 0; }
};

namespace rounding {

/// An unsigned integer of up to Capacity x 32 bits.
template <unsigned Capacity>
struct big {
  static constexpr unsigned capacity = Capacity;
  std::uint32_t limb[capacity]{};  // least significant first
  unsigned size = 0;               // limbs in use; limb[size - 1] != 0 unless size == 0

  constexpr explicit big(std::uint64_t v = 0) noexcept {
    limb[0] = static_cast<std::uint32_t>(v);
    limb[1] = static_cast<std::uint32_t>(v >> 32U);
    size = limb[1] != 0 ? 2 : (limb[0] != 0 ? 1 : 0);
  }
  constexpr void mul_small(std::uint32_t k) noexcept {
    std::uint64_t carry = 0;
    for (unsigned i = 0; i < size; ++i) {
      const std::uint64_t t = std::uint64_t{limb[i]} * k + carry;
      limb[i] = static_cast<std::uint32_t>(t);
      carry = t >> 32U;
    }
    if (carry != 0 && size < capacity) limb[size++] = static_cast<std::uint32_t>(carry);
  }
  constexpr void mul_pow10(unsigned n) noexcept {
    for (; n >= 9; n -= 9) mul_small(1'000'000'000U);
    if (n > 0) mul_small(static_cast<std::uint32_t>(pow10_table[n]));
  }
  constexpr void shift_left(unsigned bits) noexcept {
    if (size == 0) return;
    const unsigned whole = bits / 32;
    const unsigned part = bits % 32;
    unsigned n = size + whole + 1;
    if (n > capacity) n = capacity;
    for (unsigned i = n; i-- > 0;) {
      const std::uint64_t hi = i >= whole && i - whole < size ? limb[i - whole] : 0U;
      const std::uint64_t lo = i >= whole + 1 && i - whole - 1 < size ? limb[i - whole - 1] : 0U;
      limb[i] = static_cast<std::uint32_t>(((hi << 32U) | lo) >> (32U - part));
    }
    size = n;
    while (size > 0 && limb[size - 1] == 0) --size;
  }
  constexpr void add(const big& b) noexcept {
    const unsigned n = size > b.size ? size : b.size;
    std::uint64_t carry = 0;
    for (unsigned i = 0; i < n; ++i) {
      const std::uint64_t t = std::uint64_t{limb[i]} + b.limb[i] + carry;
      limb[i] = static_cast<std::uint32_t>(t);
      carry = t >> 32U;
    }
    size = n;
    if (carry != 0 && size < capacity) limb[size++] = 1;
  }
  /// *this -= b; b <= *this.
  constexpr void sub(const big& b) noexcept {
    std::uint64_t borrow = 0;
    for (unsigned i = 0; i < size; ++i) {
      const std::uint64_t t = std::uint64_t{limb[i]} - b.limb[i] - borrow;
      limb[i] = static_cast<std::uint32_t>(t);
      borrow = (t >> 32U) != 0 ? 1 : 0;
    }
    while (size > 0 && limb[size - 1] == 0) --size;
  }
  [[nodiscard]] friend constexpr int compare(const big& a, const big& b) noexcept {
    if (a.size != b.size) return a.size < b.size ? -1 : 1;
    for (unsigned i = a.size; i-- > 0;)
      if (a.limb[i] != b.limb[i]) return a.limb[i] < b.limb[i] ? -1 : 1;
    return 0;
  }
};

template <unsigned C>
[[nodiscard]] constexpr big<C> sum(big<C> a, const big<C>& b) noexcept {
  a.add(b);
  return a;
}

/// The digits of f x 2^e (f < 2^53, from a finite nonzero double of biased exponent
/// `biased`) in big integers of C x 32 bits, which must hold every value below: see shortest().
template <unsigned C>
constexpr void shortest_digits(std::uint64_t f, int e, int biased, shortest_decimal& out) noexcept {
  using big = big<C>;
  // v = r / s; the decimals that read back as v lie between (r - minus) / s and (r + plus) / s,
  // both ends included when f is even (a reader rounds a tie to the even mantissa). Below a
  // power of two the next smaller double is half as far.
  const bool ends_included = (f & 1U) == 0;
  const bool closer_below = f == std::uint64_t{1} << 52U && biased > 1;
  big r(f);
  big s(1);
  big plus(1);
  big minus(1);
  if (e >= 0) {
    r.shift_left(static_cast<unsigned>(e) + (closer_below ? 2U : 1U));
    s = big(closer_below ? 4U : 2U);
    plus.shift_left(static_cast<unsigned>(e) + (closer_below ? 1U : 0U));
    minus.shift_left(static_cast<unsigned>(e));
  } else {
    r.shift_left(closer_below ? 2U : 1U);
    s.shift_left(static_cast<unsigned>(-e) + (closer_below ? 2U : 1U));
    if (closer_below) plus = big(2);
  }
  // k: the decimal exponent with 10^(k-1) <= v's upper end < 10^k, so that v = 0.d1d2... x 10^k.
  // 1233 / 4096 is about log10(2): an estimate, put right below.
  const int e2 = e + static_cast<int>(std::bit_width(f)) - 1;  // 2^e2 <= v < 2^(e2 + 1)
  int k = ((e2 * 1233) >> 12) + 1;
  if (k >= 0) {
    s.mul_pow10(static_cast<unsigned>(k));
  } else {
    r.mul_pow10(static_cast<unsigned>(-k));
    plus.mul_pow10(static_cast<unsigned>(-k));
    minus.mul_pow10(static_cast<unsigned>(-k));
  }
  const auto reaches = [&](const big& x) {  // whether x / s, an upper end, reaches 1
    const int c = compare(x, s);
    return ends_included ? c >= 0 : c > 0;
  };
  while (reaches(sum(r, plus))) {
    s.mul_small(10);
    ++k;
  }
  for (;;) {
    big up = sum(r, plus);
    up.mul_small(10);
    if (reaches(up)) break;
    r.mul_small(10);
    plus.mul_small(10);
    minus.mul_small(10);
    --k;
  }
  // Digits of v, until the digits so far (low) or one more in the last place (high) lie in the
  // interval; at most 17 for a double.
  std::uint64_t digits = 0;
  int n = 0;
  for (;;) {
    r.mul_small(10);
    plus.mul_small(10);
    minus.mul_small(10);
    unsigned d = 0;
    while (compare(r, s) >= 0 && d < 10) {
      r.sub(s);
      ++d;
    }
    ++n;
    const int c_low = compare(r, minus);
    const bool low = ends_included ? c_low <= 0 : c_low < 0;
    const bool high = reaches(sum(r, plus));
    if (!low && !high && n < 18) {
      digits = digits * 10 + d;
      continue;
    }
    bool round_up = high && !low;
    if (low && high) {  // both are in the interval: the nearer to v
      const int c = compare(sum(r, r), s);
      round_up = c > 0 || (c == 0 && (d & 1U) != 0);
    }
    digits = digits * 10 + d + (round_up ? 1U : 0U);  // 9 + 1 carries into the digits before
    break;
  }
  int exponent = k - n;
  while (digits % 10 == 0) {
    digits /= 10;
    ++exponent;
  }
  out.digits = digits;
  out.exponent = exponent;
}

}  // namespace rounding

/// The shortest decimal of `v` (see the top of this file); among decimals of that length that
/// read back as v, the nearest to v (an exact tie: the even last digit). not_finite for NaN and
/// infinities.
[[nodiscard]] constexpr errc shortest(double v, shortest_decimal& out) noexcept {
  if (!(v == v) || v > std::numeric_limits<double>::max() ||
      v < -std::numeric_limits<double>::max())
    return errc::not_finite;
  const auto bits = std::bit_cast<std::uint64_t>(v);
  out = shortest_decimal{};
  out.negative = (bits >> 63U) != 0;
  const auto biased = static_cast<int>((bits >> 52U) & 0x7FFU);
  std::uint64_t f = bits & ((std::uint64_t{1} << 52U) - 1);
  int e = -1074;
  if (biased != 0) {
    f |= std::uint64_t{1} << 52U;
    e = biased - 1075;
  } else if (f == 0) {
    return errc::ok;  // zero
  }
  // The common magnitudes, 2^-8 <= v < 2^63, need at most 125 bits (s <= 2^62 x 10^17 when
  // e < 0; r <= 2^65, s <= 4 x 10^20 otherwise); five limbs leave a margin. The rest of the
  // range needs up to 2^1140 (a subnormal scaled by 10^324): forty.
  if (biased >= 1023 - 8 && e <= 10) {
    rounding::shortest_digits<5>(f, e, biased, out);
  } else {
    rounding::shortest_digits<40>(f, e, biased, out);
  }
  return errc::ok;
}

/// m x 10^t / den (den >= 1), rounded to an integer, halves away from zero, exactly; false when
/// m x 10^t or the result does not fit 64 bits.
[[nodiscard]] constexpr bool round_scaled(std::uint64_t m, int t, std::uint64_t den,
                                          std::uint64_t& out) noexcept {
  if (m == 0) {
    out = 0;
    return true;
  }
  std::uint64_t p = 1;  // the divisor's power of ten
  if (t > 0) {
    if (t > 19 || m > scale_limit[t]) return false;
    m *= pow10_table[t];
  } else if (t < -19) {
    out = 0;  // m < 2^64 < 10^20 / 5: the quotient is below 0.2
    return true;
  } else {
    p = pow10_table[-t];
  }
  // m = (q x den + r1) x p + r0: twice the remainder (r1 x p + r0) reaches den x p exactly when
  // 2 r1 + [2 r0 >= p] reaches den (2 r0 - p < p), with nothing that overflows.
  const std::uint64_t q1 = m / p;
  const std::uint64_t r0 = m % p;
  std::uint64_t q = q1 / den;
  const std::uint64_t r1 = q1 % den;
  const bool half = r1 >= den - r1 || (r1 + 1 == den - r1 && r0 >= p - r0);
  if (half) {
    if (q == std::numeric_limits<std::uint64_t>::max()) return false;
    ++q;
  }
  out = q;
  return true;
}

/// A shortest decimal x 10^t / den, rounded as round_scaled: the magnitude of a double at a
/// wire's step. false when it does not fit 64 bits.
[[nodiscard]] constexpr bool round_scaled(const shortest_decimal& d, int t, std::uint64_t den,
                                          std::uint64_t& out) noexcept {
  if (d.digits == 0) {
    out = 0;
    return true;
  }
  // |exponent| stays within 330, so the sum cannot overflow.
  return round_scaled(d.digits, d.exponent + t, den, out);
}

/// A double as a wire integer: the rounded magnitude and the double's sign.
struct rounded_double {
  std::uint64_t magnitude = 0;
  bool negative = false;  ///< the sign bit; a caller writes a zero magnitude as the plain zero
};

namespace rounding {
#if defined(__SIZEOF_INT128__)
__extension__ using u128 = unsigned __int128;

/// The rule's result for f x 2^e (-64 <= e < 0) without the shortest digits, when it is decided
/// by the double alone: the exact value a = f x 2^e, and the interval of decimals that read back
/// as it (within a +- 2^(e-1)), scaled by mul x 10^t / den, contain no half of an integer step,
/// so the shortest decimal (in that interval) rounds as a itself does. False when it is not
/// decided (a tie near; then the caller takes the shortest digits) or the operands do not fit.
[[nodiscard]] constexpr bool round_decided(std::uint64_t f, int e, std::uint64_t mul, int t,
                                           std::uint64_t den, std::uint64_t& out,
                                           bool& too_large) noexcept {
  const auto up = static_cast<unsigned>(t > 0 ? t : 0);
  const auto down = static_cast<unsigned>(t < 0 ? -t : 0);
  if (up > 19 || down > 19 || mul > 100 || den > scale_limit[down]) return false;
  const std::uint64_t divisor = pow10_table[down] * den;
  if ((divisor >> 63U) != 0) return false;
  const auto sh = static_cast<unsigned>(-e);
  // The value is n / d; the interval n +- scale / 2 (over d); steps of d; all below 2^127.
  // First in 64 bits, where most wire fields are (n = f x scale below 2^64: f < 2^53 and
  // scale < 2^11; d = divisor x 2^sh below 2^63).
  if (mul * pow10_table[up] < 2048 && sh < 63 && divisor < (std::uint64_t{1} << (63U - sh))) {
    const std::uint64_t scale64 = mul * pow10_table[up];
    const std::uint64_t n64 = f * scale64;
    const std::uint64_t d64 = divisor << sh;
    if (scale64 >= d64) return false;
    std::uint64_t q64 = n64 >> sh;  // then divided by the divisor, when it is not 1
    std::uint64_t r64 = n64 & ((std::uint64_t{1} << sh) - 1);
    if (divisor != 1) {
      r64 |= (q64 % divisor) << sh;
      q64 /= divisor;
    }
    const std::uint64_t twice_r64 = r64 * 2;
    const std::uint64_t distance64 = twice_r64 > d64 ? twice_r64 - d64 : d64 - twice_r64;
    if (distance64 <= scale64) return false;
    too_large = false;
    out = q64 + (twice_r64 > d64 ? 1U : 0U);
    return true;
  }
  const u128 scale = u128{mul} * pow10_table[up];             // < 2^70
  const u128 n = u128{f} * scale;                             // < 2^123
  const u128 d = u128{divisor} << static_cast<unsigned>(-e);  // < 2^127
  if (scale >= d) return false;  // the interval could hold more than one half step
  // n / d and its remainder, d = divisor x 2^sh: a shift, then a division only by the divisor
  // (in 64 bits when the quotient allows: no 128-bit division on the common path).
  const u128 high = n >> sh;
  const u128 low = n & ((u128{1} << sh) - 1);
  u128 q = high;
  u128 high_r = 0;
  if (divisor != 1) {
    if ((high >> 64U) == 0) {
      const auto h = static_cast<std::uint64_t>(high);
      q = h / divisor;
      high_r = h % divisor;
    } else {
      q = high / divisor;
      high_r = high % divisor;
    }
  }
  const u128 twice_r = ((high_r << sh) | low) * 2;  // below 2d; the half step is at d
  const u128 distance = twice_r > d ? twice_r - d : d - twice_r;
  if (distance <= scale) return false;  // a half step lies in the interval: not decided here
  const u128 rounded = q + (twice_r > d ? 1U : 0U);
  too_large = rounded > std::numeric_limits<std::uint64_t>::max();
  out = static_cast<std::uint64_t>(rounded);
  return true;
}
#endif
}  // namespace rounding

/// |v| x mul x 10^t / den (mul <= 100, den >= 1) by the rule: v's shortest decimal, rounded half
/// away from zero, exactly. not_finite for NaN and infinities, value_too_large when the result
/// does not fit 64 bits. Where the double alone decides the result (no tie within the interval
/// of decimals that read back as v, nearly always), it is found without the shortest digits.
[[nodiscard]] constexpr errc round_double(double v, std::uint64_t mul, int t, std::uint64_t den,
                                          rounded_double& out) noexcept {
  if (!(v == v) || v > std::numeric_limits<double>::max() ||
      v < -std::numeric_limits<double>::max())
    return errc::not_finite;
  const auto bits = std::bit_cast<std::uint64_t>(v);
  out.negative = (bits >> 63U) != 0;
#if defined(__SIZEOF_INT128__)
  const auto biased = static_cast<int>((bits >> 52U) & 0x7FFU);
  const int e = biased - 1075;
  if (biased != 0 && e >= -64 && e < 0) {
    const std::uint64_t f = (bits & ((std::uint64_t{1} << 52U) - 1)) | (std::uint64_t{1} << 52U);
    bool too_large = false;
    if (rounding::round_decided(f, e, mul, t, den, out.magnitude, too_large))
      return too_large ? errc::value_too_large : errc::ok;
  }
#endif
  shortest_decimal s;
  (void)shortest(v, s);
  if (mul > 100) return errc::value_too_large;  // outside the contract
  return round_scaled(s.digits * mul, s.exponent + t, den, out.magnitude) ? errc::ok
                                                                          : errc::value_too_large;
}

}  // namespace seawire::detail
