// SPDX-License-Identifier: BSL-1.0
#pragma once
// A string usable as a template argument, so a message's address is part of its type.

#include <cstddef>
#include <string_view>

namespace seawire::detail {

template <std::size_t N>
struct fixed_string {
  char chars[N]{};  // includes the terminating NUL of the literal

  // NOLINTNEXTLINE(google-explicit-constructor): a literal must convert implicitly in <"...">.
  constexpr fixed_string(const char (&s)[N]) noexcept {
    for (std::size_t i = 0; i < N; ++i) chars[i] = s[i];
  }
  [[nodiscard]] constexpr std::string_view view() const noexcept { return {chars, N - 1}; }
  [[nodiscard]] static constexpr std::size_t size() noexcept { return N - 1; }
};

}  // namespace seawire::detail
