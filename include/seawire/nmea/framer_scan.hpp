// SPDX-License-Identifier: BSL-1.0
#pragma once
// The byte searches behind nmea::stream_reader's hot path (internal).

#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "seawire/detail/byte_order.hpp"
#include "seawire/detail/simd.hpp"

namespace seawire::nmea {

namespace detail {

// The scan behind the hot path. A sentence byte needs one decision (plain text or not), so it is
// made for 16 bytes at once where the target has vector registers (SSE2, NEON), else 8 at once
// in a 64-bit word (also the constexpr path). Both only narrow the search; a byte loop names the
// exact byte. Inside a sentence only '$' is special ('!' is text).
struct framer_scan {
  static constexpr std::uint64_t ones = 0x0101010101010101U;
  static constexpr std::uint64_t highs = 0x8080808080808080U;

  // Nonzero iff some byte of v is below n (n <= 0x80). Borrows may flag bytes above the first
  // hit, never below it, so "any" is exact; the byte loop then finds which one.
  [[nodiscard]] static constexpr std::uint64_t any_below(std::uint64_t v, unsigned n) noexcept {
    return (v - ones * n) & ~v & highs;
  }

  [[nodiscard]] static constexpr std::uint64_t any_equal(std::uint64_t v,
                                                         unsigned char c) noexcept {
    return any_below(v ^ (ones * c), 1);
  }

  [[nodiscard]] static constexpr bool is_plain(char c) noexcept {
    const auto u = static_cast<unsigned char>(c);
    return u >= 0x20 && u <= 0x7E && u != '$';
  }

  // The bytes a search stops at, told for one byte, for eight in a word (nonzero when one of
  // them is such a byte; borrows may flag bytes above the first hit, never below), and for
  // sixteen vector lanes.
  struct special_bytes {  // not printable ASCII, or '$'
    [[nodiscard]] static constexpr bool byte(char c) noexcept { return !is_plain(c); }
    [[nodiscard]] static constexpr std::uint64_t word(std::uint64_t v) noexcept {
      return any_below(v, 0x20) | (v & highs) | any_equal(v, 0x7F) | any_equal(v, '$');
    }
#if SEAWIRE_SIMD
    [[nodiscard]] static seawire::detail::simd::bytes16 lanes(
        seawire::detail::simd::bytes16 v) noexcept {
      namespace simd = seawire::detail::simd;
      return simd::not_printable(v) | simd::equal(v, '$');
    }
#endif
  };
  /// First index in [from, to) whose byte Bytes stops at; `to` if none.
  template <class Bytes>
  [[nodiscard]] static constexpr std::size_t find_first(const char* s, std::size_t from,
                                                        std::size_t to) noexcept {
    std::size_t i = from;
#if SEAWIRE_SIMD
    if (!std::is_constant_evaluated()) {
      for (; to - i >= 16; i += 16) {
        const std::size_t k =
            seawire::detail::simd::first(Bytes::lanes(seawire::detail::simd::load(s + i)));
        if (k < 16) return i + k;
      }
    }
#endif
    for (; to - i >= 8; i += 8)
      if (Bytes::word(seawire::detail::load_le64(s + i)) != 0) break;
    while (i < to && !Bytes::byte(s[i])) ++i;
    return i;
  }

  /// First index in [from, to) whose byte is not printable ASCII or is '$'; `to` if none.
  [[nodiscard]] static constexpr std::size_t find_special(const char* s, std::size_t from,
                                                          std::size_t to) noexcept {
    return find_first<special_bytes>(s, from, to);
  }
};

}  // namespace detail

}  // namespace seawire::nmea
