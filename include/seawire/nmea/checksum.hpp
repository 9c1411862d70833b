// SPDX-License-Identifier: BSL-1.0
#pragma once
// The NMEA 0183 checksum: XOR of every byte between the start character ('$' or '!') and '*',
// written as two hex digits.

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

#include "seawire/detail/byte_order.hpp"
#include "seawire/detail/simd.hpp"

namespace seawire::nmea {

namespace detail {

#if SEAWIRE_SIMD
// 16 bytes at a time, then 8, then the rest one by one.
inline std::uint8_t xor_bytes_simd(const char* p, std::size_t n) noexcept {
  namespace simd = seawire::detail::simd;
  simd::bytes16 acc = simd::zero();
  std::size_t i = 0;
  for (; n - i >= 16; i += 16) acc = acc ^ simd::load(p + i);
  std::uint64_t w = simd::xor_halves(acc);
  if (n - i >= 8) {
    w ^= seawire::detail::load_le64(p + i);
    i += 8;
  }
  auto x = simd::xor_fold(w);
  for (; i < n; ++i) x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(p[i]));
  return x;
}
#endif

}  // namespace detail

/// XOR of all bytes of `between` (pass the text between '$' or '!' and '*', both excluded).
[[nodiscard]] constexpr std::uint8_t checksum(std::string_view between) noexcept {
#if SEAWIRE_SIMD
  if (!std::is_constant_evaluated()) return detail::xor_bytes_simd(between.data(), between.size());
#endif
  std::uint8_t x = 0;
  for (char c : between) x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(c));
  return x;
}

/// Whether checksum digits as sent (the text after '*') are the XOR `computed` written in
/// decimal: "82" for 0x52. Digits only, one to three; and not a checksum that reads the same in
/// both (under 10: "06"), which is a right one.
[[nodiscard]] constexpr bool written_in_decimal(std::string_view digits,
                                                std::uint8_t computed) noexcept {
  if (digits.empty() || digits.size() > 3 || computed < 10) return false;
  unsigned d = 0;
  for (const char c : digits) {
    if (c < '0' || c > '9') return false;
    d = d * 10 + static_cast<unsigned>(c - '0');
  }
  return d == computed;
}

}  // namespace seawire::nmea
