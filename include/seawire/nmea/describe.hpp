// SPDX-License-Identifier: BSL-1.0
#pragma once
// The former name of nmea/error_text.hpp and of nmea::error_text(), kept for one release.

#include <span>
#include <string_view>

#include "seawire/nmea/error_text.hpp"

namespace seawire::nmea {

template <message_like T, class R>
[[deprecated("use nmea::error_text (seawire/nmea/error_text.hpp)")]] constexpr std::string_view
describe(std::span<char> out, const result<R>& r, std::string_view line,
         const parse_policy& policy = {}) noexcept {
  return error_text<T>(out, r, line, policy);
}

template <class Set, class R>
requires requires { Set::size; }
[[deprecated("use nmea::error_text (seawire/nmea/error_text.hpp)")]] constexpr std::string_view
describe(std::span<char> out, const result<R>& r, std::string_view line,
         const parse_policy& policy = {}) noexcept {
  return error_text<Set>(out, r, line, policy);
}

}  // namespace seawire::nmea
