// SPDX-License-Identifier: BSL-1.0
#pragma once
// CRC-32 exactly as zlib computes it: reflected polynomial 0xEDB88320, initial value 0xFFFFFFFF,
// final XOR 0xFFFFFFFF ("123456789" -> 0xCBF43926). It is the check of the ANELLO binary frame.
// The table is built by the compiler, so the CRC also works in constant expressions.

#include <array>
#include <cstddef>
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

// Slicing-by-8: slice[k][b] is the register contribution of byte b followed by k zero bytes, so
// eight bytes cost eight independent lookups instead of eight dependent steps (about 4x faster).
inline constexpr std::array<std::array<std::uint32_t, 256>, 8> crc32_slices = [] {
  std::array<std::array<std::uint32_t, 256>, 8> t{};
  t[0] = crc32_table;
  for (std::size_t k = 1; k < 8; ++k)
    for (std::size_t i = 0; i < 256; ++i) t[k][i] = crc32_step(t[k - 1][i], 0);
  return t;
}();

// The register after `n` bytes from `p` (bytes or chars, each taken as its byte value).
template <class Byte>
[[nodiscard]] constexpr std::uint32_t crc32_run(std::uint32_t reg, const Byte* p,
                                                std::size_t n) noexcept {
  const auto at = [&p](std::size_t i) {
    return static_cast<std::uint32_t>(static_cast<std::uint8_t>(p[i]));
  };
  const auto& t = crc32_slices;
  for (; n >= 8; n -= 8, p += 8) {
    const std::uint32_t lo = reg ^ (at(0) | at(1) << 8U | at(2) << 16U | at(3) << 24U);
    const std::uint32_t hi = at(4) | at(5) << 8U | at(6) << 16U | at(7) << 24U;
    reg = t[7][lo & 0xFFU] ^ t[6][(lo >> 8U) & 0xFFU] ^ t[5][(lo >> 16U) & 0xFFU] ^
          t[4][lo >> 24U] ^ t[3][hi & 0xFFU] ^ t[2][(hi >> 8U) & 0xFFU] ^
          t[1][(hi >> 16U) & 0xFFU] ^ t[0][hi >> 24U];
  }
  for (std::size_t i = 0; i < n; ++i) reg = crc32_step(reg, static_cast<std::uint8_t>(p[i]));
  return reg;
}

}  // namespace detail

/// Continues a CRC-32 over more bytes. Like zlib's crc32(crc, buf, len): `crc` is the finished
/// CRC of the bytes so far (0 before any), so crc32_update(crc32(a), b) == crc32(a followed by b).
[[nodiscard]] constexpr std::uint32_t crc32_update(std::uint32_t crc,
                                                   std::span<const std::uint8_t> bytes) noexcept {
  return ~detail::crc32_run(~crc, bytes.data(), bytes.size());
}

/// Same, over text (each char taken as its byte value).
[[nodiscard]] constexpr std::uint32_t crc32_update(std::uint32_t crc,
                                                   std::string_view text) noexcept {
  return ~detail::crc32_run(~crc, text.data(), text.size());
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
