// SPDX-License-Identifier: BSL-1.0
#pragma once
// The byte searches behind nmea::stream_reader's hot path (internal).

#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "seawire/detail/simd.hpp"  // SEAWIRE_SSE2
#if SEAWIRE_SSE2
#include <emmintrin.h>
#endif

#include "seawire/detail/byte_order.hpp"

namespace seawire::nmea {

namespace detail {

// The scan behind the hot path. A sentence byte needs one decision (plain text or not), so it is
// made for 16 bytes at once with SSE2 where x86 guarantees it, else 8 at once in a 64-bit word
// (also the constexpr path). Both only narrow the search; a byte loop names the exact byte.
// Inside a sentence only '$' is special ('!' is text).
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
  // sixteen SSE2 lanes.
  struct special_bytes {  // not printable ASCII, or '$'
    [[nodiscard]] static constexpr bool byte(char c) noexcept { return !is_plain(c); }
    [[nodiscard]] static constexpr std::uint64_t word(std::uint64_t v) noexcept {
      return any_below(v, 0x20) | (v & highs) | any_equal(v, 0x7F) | any_equal(v, '$');
    }
#if SEAWIRE_SSE2
    // Signed compare: "below 0x20" also catches 0x80..0xFF, which are negative.
    [[nodiscard]] static __m128i lanes(__m128i v) noexcept {
      return _mm_or_si128(_mm_cmplt_epi8(v, _mm_set1_epi8(0x20)),
                          _mm_or_si128(_mm_cmpeq_epi8(v, _mm_set1_epi8(0x7F)),
                                       _mm_cmpeq_epi8(v, _mm_set1_epi8('$'))));
    }
#endif
  };
  /// First index in [from, to) whose byte Bytes stops at; `to` if none.
  template <class Bytes>
  [[nodiscard]] static constexpr std::size_t find_first(const char* s, std::size_t from,
                                                        std::size_t to) noexcept {
    std::size_t i = from;
#if SEAWIRE_SSE2
    if (!std::is_constant_evaluated()) {
      for (; to - i >= 16; i += 16) {
        const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(s + i));
        const auto mask = static_cast<unsigned>(_mm_movemask_epi8(Bytes::lanes(v)));
        if (mask != 0) return i + static_cast<std::size_t>(std::countr_zero(mask));
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
