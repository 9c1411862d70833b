// SPDX-License-Identifier: BSL-1.0
#pragma once
// Sixteen bytes at a time (internal): the few operations the byte searches, the checksum and the
// sentence scan are written against, SSE2 on x86-64 and NEON on 64-bit ARM (both always present,
// so no run-time check). SEAWIRE_SIMD is 1 where one is compiled; elsewhere, or with
// SEAWIRE_NO_SIMD, callers use their portable forms, which constant evaluation also runs.

#if !defined(SEAWIRE_NO_SIMD) && defined(__SSE2__) && (defined(__x86_64__) || defined(_M_X64))
#define SEAWIRE_SSE2 1
#else
#define SEAWIRE_SSE2 0
#endif

#if !defined(SEAWIRE_NO_SIMD) && defined(__ARM_NEON) && defined(__aarch64__) && \
    !defined(__ARM_BIG_ENDIAN)
#define SEAWIRE_NEON 1
#else
#define SEAWIRE_NEON 0
#endif

#define SEAWIRE_SIMD (SEAWIRE_SSE2 || SEAWIRE_NEON)

#if SEAWIRE_SIMD

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#if SEAWIRE_SSE2
#include <emmintrin.h>
#else
#include <arm_neon.h>
#endif

// GCC's -Warray-bounds (at -O2 and up) sees a 16-byte load in a loop guarded by a run-time
// length and a caller's short buffer, and warns about the path the guard rules out. The loads
// below only ever read bytes the caller's length covers.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#endif

namespace seawire::detail::simd {

/// Sixteen bytes in a vector register. A "mask" is the result of a comparison: each lane 0x00
/// or 0xFF.
struct bytes16 {
#if SEAWIRE_SSE2
  __m128i v;
#else
  uint8x16_t v;
#endif
};

#if SEAWIRE_SSE2

/// p[0, 16), any alignment.
[[nodiscard]] inline bytes16 load(const void* p) noexcept {
  return {_mm_loadu_si128(static_cast<const __m128i*>(p))};
}
[[nodiscard]] inline bytes16 splat(unsigned char c) noexcept {
  return {_mm_set1_epi8(static_cast<char>(c))};
}
[[nodiscard]] inline bytes16 zero() noexcept { return {_mm_setzero_si128()}; }
[[nodiscard]] inline bytes16 operator|(bytes16 a, bytes16 b) noexcept {
  return {_mm_or_si128(a.v, b.v)};
}
[[nodiscard]] inline bytes16 operator&(bytes16 a, bytes16 b) noexcept {
  return {_mm_and_si128(a.v, b.v)};
}
[[nodiscard]] inline bytes16 operator^(bytes16 a, bytes16 b) noexcept {
  return {_mm_xor_si128(a.v, b.v)};
}
/// Mask of the lanes of `a` that equal `c`.
[[nodiscard]] inline bytes16 equal(bytes16 a, unsigned char c) noexcept {
  return {_mm_cmpeq_epi8(a.v, _mm_set1_epi8(static_cast<char>(c)))};
}
/// Mask of the lanes outside printable ASCII (0x20..0x7E). Plus one (wrapping), 0x7F..0xFE turn
/// negative and 0xFF..0x1F become 0x00..0x20, so one signed compare below 0x21 finds them all.
[[nodiscard]] inline bytes16 not_printable(bytes16 a) noexcept {
  return {_mm_cmplt_epi8(_mm_add_epi8(a.v, _mm_set1_epi8(1)), _mm_set1_epi8(0x21))};
}
/// Bit i set where lane i of mask m is.
[[nodiscard]] inline unsigned bits(bytes16 m) noexcept {
  return static_cast<unsigned>(_mm_movemask_epi8(m.v));
}
/// Index of the first lane set in mask m; 16 when none is.
[[nodiscard]] inline std::size_t first(bytes16 m) noexcept {
  return static_cast<std::size_t>(std::countr_zero(bits(m) | 0x10000U));
}
[[nodiscard]] inline bool any(bytes16 m) noexcept { return bits(m) != 0; }
/// Each lane's counter plus one where mask m is set (a set lane is -1).
[[nodiscard]] inline bytes16 count(bytes16 counters, bytes16 m) noexcept {
  return {_mm_sub_epi8(counters.v, m.v)};
}
/// The sixteen byte counters added up.
[[nodiscard]] inline std::size_t sum(bytes16 counters) noexcept {
  const __m128i sums = _mm_sad_epu8(counters.v, _mm_setzero_si128());
  return static_cast<std::size_t>(_mm_cvtsi128_si32(sums)) +
         static_cast<std::size_t>(_mm_extract_epi16(sums, 4));
}
/// The XOR of the two halves, as a little-endian 64-bit word.
[[nodiscard]] inline std::uint64_t xor_halves(bytes16 a) noexcept {
  return static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_xor_si128(a.v, _mm_srli_si128(a.v, 8))));
}

#else  // NEON

// Through memcpy rather than vld1q_u8: the same one load, and GCC does not then warn that a
// buffer shorter than 16 bytes might be read on a path the caller's length check rules out.
[[nodiscard]] inline bytes16 load(const void* p) noexcept {
  uint8x16_t v;
  std::memcpy(&v, p, sizeof v);
  return {v};
}
[[nodiscard]] inline bytes16 splat(unsigned char c) noexcept { return {vdupq_n_u8(c)}; }
[[nodiscard]] inline bytes16 zero() noexcept { return {vdupq_n_u8(0)}; }
[[nodiscard]] inline bytes16 operator|(bytes16 a, bytes16 b) noexcept {
  return {vorrq_u8(a.v, b.v)};
}
[[nodiscard]] inline bytes16 operator&(bytes16 a, bytes16 b) noexcept {
  return {vandq_u8(a.v, b.v)};
}
[[nodiscard]] inline bytes16 operator^(bytes16 a, bytes16 b) noexcept {
  return {veorq_u8(a.v, b.v)};
}
[[nodiscard]] inline bytes16 equal(bytes16 a, unsigned char c) noexcept {
  return {vceqq_u8(a.v, vdupq_n_u8(c))};
}
/// Unsigned compares: below 0x20 or above 0x7E.
[[nodiscard]] inline bytes16 not_printable(bytes16 a) noexcept {
  return {vorrq_u8(vcltq_u8(a.v, vdupq_n_u8(0x20)), vcgtq_u8(a.v, vdupq_n_u8(0x7E)))};
}
/// NEON has no byte movemask: keep one weight bit per lane and add each half's eight lanes.
[[nodiscard]] inline unsigned bits(bytes16 m) noexcept {
  static constexpr std::uint8_t weights[16] = {1, 2, 4, 8, 16, 32, 64, 128,
                                               1, 2, 4, 8, 16, 32, 64, 128};
  const uint8x16_t t = vandq_u8(m.v, vld1q_u8(weights));
  return static_cast<unsigned>(vaddv_u8(vget_low_u8(t))) |
         (static_cast<unsigned>(vaddv_u8(vget_high_u8(t))) << 8U);
}
/// Narrowing each 16-bit pair by 4 leaves four bits per lane in one 64-bit word.
[[nodiscard]] inline std::size_t first(bytes16 m) noexcept {
  const std::uint64_t nibbles =
      vget_lane_u64(vreinterpret_u64_u8(vshrn_n_u16(vreinterpretq_u16_u8(m.v), 4)), 0);
  return nibbles == 0 ? 16 : static_cast<std::size_t>(std::countr_zero(nibbles)) / 4;
}
[[nodiscard]] inline bool any(bytes16 m) noexcept { return vmaxvq_u8(m.v) != 0; }
[[nodiscard]] inline bytes16 count(bytes16 counters, bytes16 m) noexcept {
  return {vsubq_u8(counters.v, m.v)};
}
[[nodiscard]] inline std::size_t sum(bytes16 counters) noexcept {
  return static_cast<std::size_t>(vaddlvq_u8(counters.v));
}
[[nodiscard]] inline std::uint64_t xor_halves(bytes16 a) noexcept {
  return vget_lane_u64(vreinterpret_u64_u8(veor_u8(vget_low_u8(a.v), vget_high_u8(a.v))), 0);
}

#endif

/// The XOR of the eight bytes of a word.
[[nodiscard]] constexpr std::uint8_t xor_fold(std::uint64_t w) noexcept {
  w ^= w >> 32U;
  w ^= w >> 16U;
  w ^= w >> 8U;
  return static_cast<std::uint8_t>(w);
}

/// The XOR of all sixteen bytes.
[[nodiscard]] inline std::uint8_t xor_all(bytes16 a) noexcept { return xor_fold(xor_halves(a)); }

/// Sixteen zero bytes then sixteen 0xFF: the 16 bytes at keep_from_table + 16 - k keep lanes
/// k..15.
alignas(16) inline constexpr unsigned char keep_from_table[32] = {
    0,    0,    0,    0,    0,    0,    0,    0,    0,    0,    0,    0,    0,    0,    0,    0,
    0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};

/// Mask of lanes k..15 (k <= 16).
[[nodiscard]] inline bytes16 lanes_from(std::size_t k) noexcept {
  return load(keep_from_table + 16 - k);
}

}  // namespace seawire::detail::simd

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#endif  // SEAWIRE_SIMD
