// SPDX-License-Identifier: BSL-1.0
#pragma once
// Copying the short pieces text output is made of (a JSON key, a number) without a call.

#include <cstddef>
#include <cstring>
#include <type_traits>

#include "seawire/detail/inline.hpp"

namespace seawire::detail {

// GCC -O2 and up follows a short source (the writers' 24- and 26-byte buffers) into the
// branches for longer pieces, which the length the caller passes rules out, and warns of reads
// past it (-Warray-bounds, and GCC 11's -Wstringop-overread). Only those, only in this header:
// the callers are the library's own writers, whose lengths the sanitizer builds check.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#if __GNUC__ >= 11
#pragma GCC diagnostic ignored "-Wstringop-overread"
#endif
#endif

/// Copies in[0, n) to out (the two must not overlap). Up to 32 bytes it is two fixed-size copies
/// that meet or overlap in the middle (the first and the last 16, 8 or 4 bytes; for 1 to 3, the
/// first, middle and last byte), which compile to a load and a store each: no loop and no call
/// to memcpy, which costs more than such a piece. Longer pieces go to memcpy.
SEAWIRE_ALWAYS_INLINE constexpr void copy_bytes(char* out, const char* in, std::size_t n) noexcept {
  if (std::is_constant_evaluated()) {
    for (std::size_t i = 0; i < n; ++i) out[i] = in[i];
    return;
  }
  const auto two = [&]<std::size_t K>(std::integral_constant<std::size_t, K>) {
    char a[K];
    char b[K];
    std::memcpy(a, in, K);
    std::memcpy(b, in + n - K, K);
    std::memcpy(out, a, K);
    std::memcpy(out + n - K, b, K);
  };
  if (n > 32) {
    std::memcpy(out, in, n);
  } else if (n >= 16) {
    two(std::integral_constant<std::size_t, 16>{});
  } else if (n >= 8) {
    two(std::integral_constant<std::size_t, 8>{});
  } else if (n >= 4) {
    two(std::integral_constant<std::size_t, 4>{});
  } else if (n > 0) {
    const char first = in[0];
    const char middle = in[n / 2];
    const char last = in[n - 1];
    out[0] = first;
    out[n / 2] = middle;
    out[n - 1] = last;
  }
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

}  // namespace seawire::detail
