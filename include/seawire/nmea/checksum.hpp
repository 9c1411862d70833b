// SPDX-License-Identifier: BSL-1.0
#pragma once
// The NMEA 0183 checksum: XOR of every byte between the start character ('$' or '!') and '*',
// written as two hex digits.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <type_traits>

#include "seawire/detail/simd.hpp"  // SEAWIRE_SSE2
#if SEAWIRE_SSE2
#include <emmintrin.h>
#endif

namespace seawire::nmea {

namespace detail {

#if SEAWIRE_SSE2
// 16 bytes at a time, then 8, then the rest one by one.
inline std::uint8_t xor_bytes_sse2(const char* p, std::size_t n) noexcept {
  __m128i acc = _mm_setzero_si128();
  std::size_t i = 0;
  for (; n - i >= 16; i += 16)
    acc = _mm_xor_si128(acc, _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + i)));
  acc = _mm_xor_si128(acc, _mm_srli_si128(acc, 8));
  std::uint64_t w = static_cast<std::uint64_t>(_mm_cvtsi128_si64(acc));
  if (n - i >= 8) {
    std::uint64_t v = 0;
    std::memcpy(&v, p + i, sizeof v);
    w ^= v;
    i += 8;
  }
  w ^= w >> 32U;
  w ^= w >> 16U;
  w ^= w >> 8U;
  auto x = static_cast<std::uint8_t>(w);
  for (; i < n; ++i) x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(p[i]));
  return x;
}
#endif

}  // namespace detail

/// XOR of all bytes of `between` (pass the text between '$' or '!' and '*', both excluded).
[[nodiscard]] constexpr std::uint8_t checksum(std::string_view between) noexcept {
#if SEAWIRE_SSE2
  if (!std::is_constant_evaluated()) return detail::xor_bytes_sse2(between.data(), between.size());
#endif
  std::uint8_t x = 0;
  for (char c : between) x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(c));
  return x;
}

}  // namespace seawire::nmea
