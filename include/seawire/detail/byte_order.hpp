// SPDX-License-Identifier: BSL-1.0
#pragma once
// Integer loads and stores in a fixed byte order, by shifts: they run in constant expressions
// (so binary round trips can be static_asserted) and never depend on host order or alignment.
// Big-endian is the ANELLO frame's order; little-endian is NMEA 2000's.

#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>

namespace seawire::detail {

/// The integer types a wire field can have: any integral type but bool.
template <class T>
concept is_wire_integer = std::integral<T> && !std::same_as<std::remove_cv_t<T>, bool>;

/// The T stored big-endian at bytes[offset, offset + sizeof(T)).
/// Precondition: offset + sizeof(T) <= bytes.size() (checked by the caller, which knows the frame).
template <is_wire_integer T>
[[nodiscard]] constexpr T load_be(std::span<const std::uint8_t> bytes,
                                  std::size_t offset = 0) noexcept {
  using unsigned_type = std::make_unsigned_t<T>;
  unsigned_type v = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i) {
    // Two's complement for the signed types comes from the final conversion (modular in C++20).
    v = static_cast<unsigned_type>(static_cast<unsigned_type>(v << 8U) |
                                   static_cast<unsigned_type>(bytes[offset + i]));
  }
  return static_cast<T>(v);
}

/// The T stored little-endian at bytes[offset, offset + sizeof(T)). Same precondition.
template <is_wire_integer T>
[[nodiscard]] constexpr T load_le(std::span<const std::uint8_t> bytes,
                                  std::size_t offset = 0) noexcept {
  using unsigned_type = std::make_unsigned_t<T>;
  unsigned_type v = 0;
  for (std::size_t i = sizeof(T); i-- > 0;) {
    v = static_cast<unsigned_type>(static_cast<unsigned_type>(v << 8U) |
                                   static_cast<unsigned_type>(bytes[offset + i]));
  }
  return static_cast<T>(v);
}

/// The eight bytes at p as one little-endian word (p[0] in the low byte), on any host: one load
/// where the host is little-endian, by shifts in constant expressions and elsewhere. For the
/// word-at-a-time text scans. Precondition: p[0, 8) are readable.
[[nodiscard]] constexpr std::uint64_t load_le64(const char* p) noexcept {
  if (!std::is_constant_evaluated() && std::endian::native == std::endian::little) {
    std::uint64_t v = 0;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  std::uint64_t v = 0;
  for (unsigned i = 0; i < 8; ++i) v |= std::uint64_t{static_cast<unsigned char>(p[i])} << (8U * i);
  return v;
}

/// Writes `value` big-endian to bytes[offset, offset + sizeof(T)). Same precondition.
template <is_wire_integer T>
constexpr void store_be(std::span<std::uint8_t> bytes, std::size_t offset, T value) noexcept {
  using unsigned_type = std::make_unsigned_t<T>;
  auto v = static_cast<unsigned_type>(value);
  for (std::size_t i = sizeof(T); i-- > 0;) {
    bytes[offset + i] = static_cast<std::uint8_t>(v & 0xFFU);
    v = static_cast<unsigned_type>(v >> 8U);
  }
}

/// Writes `value` little-endian to bytes[offset, offset + sizeof(T)). Same precondition.
template <is_wire_integer T>
constexpr void store_le(std::span<std::uint8_t> bytes, std::size_t offset, T value) noexcept {
  using unsigned_type = std::make_unsigned_t<T>;
  auto v = static_cast<unsigned_type>(value);
  for (std::size_t i = 0; i < sizeof(T); ++i) {
    bytes[offset + i] = static_cast<std::uint8_t>(v & 0xFFU);
    v = static_cast<unsigned_type>(v >> 8U);
  }
}

}  // namespace seawire::detail
