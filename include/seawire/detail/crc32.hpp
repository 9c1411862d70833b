// SPDX-License-Identifier: BSL-1.0
#pragma once
// CRC-32 exactly as zlib computes it: reflected polynomial 0xEDB88320, initial value 0xFFFFFFFF,
// final XOR 0xFFFFFFFF ("123456789" -> 0xCBF43926). It is the check of the ANELLO binary frame.
// The table is built by the compiler, so the CRC also works in constant expressions.

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace seawire {

namespace detail {

inline constexpr std::array<std::uint32_t, 256> crc32_table = [] {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int bit = 0; bit < 8; ++bit) c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1U) : c >> 1U;
    table[i] = c;
  }
  return table;
}();

// Works on the inverted register; crc32_update hides the inversion.
[[nodiscard]] constexpr std::uint32_t crc32_step(std::uint32_t reg, std::uint8_t byte) noexcept {
  return crc32_table[(reg ^ byte) & 0xFFU] ^ (reg >> 8U);
}

}  // namespace detail

/// Continues a CRC-32 over more bytes. Like zlib's crc32(crc, buf, len): `crc` is the finished
/// CRC of the bytes so far (0 before any), so crc32_update(crc32(a), b) == crc32(a followed by b).
[[nodiscard]] constexpr std::uint32_t crc32_update(std::uint32_t crc,
                                                   std::span<const std::uint8_t> bytes) noexcept {
  std::uint32_t reg = ~crc;
  for (std::uint8_t b : bytes) reg = detail::crc32_step(reg, b);
  return ~reg;
}

/// Same, over text (each char taken as its byte value).
[[nodiscard]] constexpr std::uint32_t crc32_update(std::uint32_t crc,
                                                   std::string_view text) noexcept {
  std::uint32_t reg = ~crc;
  for (char c : text) reg = detail::crc32_step(reg, static_cast<std::uint8_t>(c));
  return ~reg;
}

/// The CRC-32 of `bytes`.
[[nodiscard]] constexpr std::uint32_t crc32(std::span<const std::uint8_t> bytes) noexcept {
  return crc32_update(0, bytes);
}

/// The CRC-32 of `text` (each char taken as its byte value).
[[nodiscard]] constexpr std::uint32_t crc32(std::string_view text) noexcept {
  return crc32_update(0, text);
}

static_assert(crc32("123456789") == 0xCBF43926U, "zlib's CRC-32 check value");
static_assert(crc32(std::string_view{}) == 0U);

}  // namespace seawire
