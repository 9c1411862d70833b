// SPDX-License-Identifier: BSL-1.0
#pragma once
// CRC-32 exactly as zlib computes it: reflected polynomial 0xEDB88320, initial value 0xFFFFFFFF,
// final XOR 0xFFFFFFFF ("123456789" -> 0xCBF43926). It is the check of the ANELLO binary frame.
// The table is built by the compiler, so the CRC also works in constant expressions.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>

namespace seawire {

namespace detail {

// The slicing tables (below): slice[k][b] is the register contribution of byte b followed by k
// zero bytes; slice[0] is the byte-at-a-time table.
struct crc32_tables {
  std::uint32_t slice[8][256];
};

// Built by the compiler where a translation unit first uses the CRC: a variable template, so a
// header that merely includes this one evaluates nothing. (Plain arrays: GCC evaluates the 2,048
// entries several times faster than through std::array's operator[], which it calls for each.)
template <class = void>
inline constexpr crc32_tables crc32_slices = [] {
  crc32_tables t{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int bit = 0; bit < 8; ++bit) c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1U) : c >> 1U;
    t.slice[0][i] = c;
  }
  for (std::size_t k = 1; k < 8; ++k) {
    for (std::size_t i = 0; i < 256; ++i) {
      const std::uint32_t r = t.slice[k - 1][i];
      t.slice[k][i] = t.slice[0][r & 0xFFU] ^ (r >> 8U);
    }
  }
  return t;
}();

// Works on the inverted register; crc32_update hides the inversion. (The functions that read the
// tables are templates, each naming the tables through its parameter, so that GCC builds nothing
// before a call; Clang builds the tables where this header is read.)
template <class V = void>
[[nodiscard]] constexpr std::uint32_t crc32_step(std::uint32_t reg, std::uint8_t byte) noexcept {
  return crc32_slices<V>.slice[0][(reg ^ byte) & 0xFFU] ^ (reg >> 8U);
}

// The register after `n` bytes from `p` (bytes or chars, each taken as its byte value). Slicing-
// by-8: eight bytes cost eight independent lookups instead of eight dependent steps (about 4x
// faster).
template <class Byte>
[[nodiscard]] constexpr std::uint32_t crc32_run(std::uint32_t reg, const Byte* p,
                                                std::size_t n) noexcept {
  const auto at = [&p](std::size_t i) {
    return static_cast<std::uint32_t>(static_cast<std::uint8_t>(p[i]));
  };
  const auto& t = crc32_slices<std::void_t<Byte>>.slice;
  for (; n >= 8; n -= 8, p += 8) {
    const std::uint32_t lo = reg ^ (at(0) | at(1) << 8U | at(2) << 16U | at(3) << 24U);
    const std::uint32_t hi = at(4) | at(5) << 8U | at(6) << 16U | at(7) << 24U;
    reg = t[7][lo & 0xFFU] ^ t[6][(lo >> 8U) & 0xFFU] ^ t[5][(lo >> 16U) & 0xFFU] ^
          t[4][lo >> 24U] ^ t[3][hi & 0xFFU] ^ t[2][(hi >> 8U) & 0xFFU] ^
          t[1][(hi >> 16U) & 0xFFU] ^ t[0][hi >> 24U];
  }
  for (std::size_t i = 0; i < n; ++i)
    reg = crc32_step<std::void_t<Byte>>(reg, static_cast<std::uint8_t>(p[i]));
  return reg;
}

}  // namespace detail

// The four functions below are templates of nothing, called as any function (crc32(bytes)): a
// translation unit that does not call one builds no table (with GCC: above).

/// Continues a CRC-32 over more bytes. Like zlib's crc32(crc, buf, len): `crc` is the finished
/// CRC of the bytes so far (0 before any), so crc32_update(crc32(a), b) == crc32(a followed by b).
template <int = 0>
[[nodiscard]] constexpr std::uint32_t crc32_update(std::uint32_t crc,
                                                   std::span<const std::uint8_t> bytes) noexcept {
  return ~detail::crc32_run(~crc, bytes.data(), bytes.size());
}

/// Same, over text (each char taken as its byte value).
template <int = 0>
[[nodiscard]] constexpr std::uint32_t crc32_update(std::uint32_t crc,
                                                   std::string_view text) noexcept {
  return ~detail::crc32_run(~crc, text.data(), text.size());
}

/// The CRC-32 of `bytes`.
template <int = 0>
[[nodiscard]] constexpr std::uint32_t crc32(std::span<const std::uint8_t> bytes) noexcept {
  return crc32_update(0, bytes);
}

/// The CRC-32 of `text` (each char taken as its byte value).
template <int = 0>
[[nodiscard]] constexpr std::uint32_t crc32(std::string_view text) noexcept {
  return crc32_update(0, text);
}

}  // namespace seawire
