// SPDX-License-Identifier: BSL-1.0
#pragma once
// Binary payloads described by tables. A table is a row_list of rows, one per field (or run of
// reserved bits) in wire order; each row type states its width in bits (`static constexpr
// unsigned bits`) and nothing says where it is: the rows follow each other with no gaps, so a
// field's bit offset is the sum of the widths before it. The two binary formats seawire reads
// are tables of this kind, and are walked, read and written by the functions below:
//
//   NMEA 2000 PGNs (nmea2000/field.hpp)   bit_order::lsb_first, fields of any width at any bit
//   ANELLO's 0xAB00 frame (anello/frame.hpp)  bit_order::msb_first, fields of whole bytes

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>

#include "seawire/detail/algorithm.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/detail/row_list.hpp"

namespace seawire::detail {

/// How a format lays the bits of a field into bytes.
enum class bit_order : std::uint8_t {
  /// Bit o of the payload is bit o % 8 of byte o / 8, counting from the least significant bit,
  /// and a field's least significant bit comes first: a field of whole bytes is little-endian.
  /// NMEA 2000.
  lsb_first,
  /// Bit o of the payload is bit 7 - o % 8 of byte o / 8, and a field's most significant bit
  /// comes first: a field of whole bytes is big-endian (network order). ANELLO's 0xAB00 frame.
  msb_first,
};

/// The `width`-bit field at bit `offset` of `p`, as an unsigned integer (a signed field's caller
/// extends the sign). Precondition: width <= 64 and offset + width <= 8 * p.size().
template <bit_order Order>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr std::uint64_t get_bits(
    std::span<const std::uint8_t> p, unsigned offset, unsigned width) noexcept {
  std::uint64_t v = 0;
  if (offset % 8 == 0 && width % 8 == 0) {  // whole bytes (most fields): no masks, no shifts
    const std::size_t at = offset / 8;
    for (unsigned k = 0; k < width / 8; ++k) {
      const std::uint64_t byte = p[at + k];
      if constexpr (Order == bit_order::lsb_first) {
        v |= byte << (8 * k);
      } else {
        v = (v << 8) | byte;
      }
    }
    return v;
  }
  for (unsigned i = 0; i < width;) {
    const unsigned bit = offset + i;
    const unsigned in_byte = bit % 8;
    const unsigned take = std::min(8 - in_byte, width - i);
    const std::uint64_t mask = (std::uint64_t{1} << take) - 1;
    const std::uint64_t byte = p[bit / 8];
    if constexpr (Order == bit_order::lsb_first) {
      v |= ((byte >> in_byte) & mask) << i;
    } else {
      v = (v << take) | ((byte >> (8 - in_byte - take)) & mask);
    }
    i += take;
  }
  return v;
}

/// Writes the low `width` bits of `v` as the field at bit `offset` of `p`, leaving the bits
/// around it as they are. Same precondition as get_bits.
template <bit_order Order>
constexpr void put_bits(std::span<std::uint8_t> p, unsigned offset, unsigned width,
                        std::uint64_t v) noexcept {
  for (unsigned i = 0; i < width;) {
    const unsigned bit = offset + i;
    const unsigned in_byte = bit % 8;
    const unsigned take = std::min(8 - in_byte, width - i);
    const unsigned shift = Order == bit_order::lsb_first ? in_byte : 8 - in_byte - take;
    const std::uint64_t part = Order == bit_order::lsb_first ? v >> i : v >> (width - i - take);
    const auto mask = static_cast<std::uint8_t>(((1U << take) - 1) << shift);
    const auto chunk = static_cast<std::uint8_t>((part << shift) & mask);
    p[bit / 8] = static_cast<std::uint8_t>((p[bit / 8] & ~mask) | chunk);
    i += take;
  }
}

/// A row of a table: anything that states its width in bits.
template <class R>
concept layout_row = requires {
  { std::remove_cvref_t<R>::bits } -> std::convertible_to<unsigned>;
};

template <class Rows>
struct layout_width;
template <class... R>
struct layout_width<row_list<R...>> {
  static_assert((layout_row<R> && ...), "every row of a table states its width (bits)");
  static constexpr unsigned value = (0U + ... + static_cast<unsigned>(R::bits));
};

/// The bits the rows of a table (a row_list) take together.
template <class Rows>
inline constexpr unsigned layout_bits = layout_width<std::remove_cvref_t<Rows>>::value;

/// Calls fn(row, bit_offset, number) for each row of the table `rows` in order: number counts
/// from 1, the first row is at bit `first_bit` and each next row where the one before ends. When
/// fn returns bool, false stops the walk. Returns whether the walk went to the end.
template <class Rows, class Fn>
constexpr bool for_each_row(Rows&& rows, unsigned first_bit, Fn&& fn) {
  return rows.apply([&](auto&&... row) {
    unsigned offset = first_bit;
    std::uint16_t number = 0;
    const auto visit = [&](auto&& r) {
      using R = std::remove_cvref_t<decltype(r)>;
      const unsigned at = offset;
      offset += R::bits;
      ++number;
      if constexpr (std::is_same_v<decltype(fn(r, at, number)), bool>) {
        return fn(r, at, number);
      } else {
        fn(r, at, number);
        return true;
      }
    };
    return (visit(row) && ...);
  });
}

}  // namespace seawire::detail
