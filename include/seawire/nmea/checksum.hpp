// SPDX-License-Identifier: BSL-1.0
#pragma once
// The NMEA 0183 checksum: XOR of every byte between '$' and '*', written as two hex digits.

#include <cstdint>
#include <string_view>

namespace seawire::nmea {

/// XOR of all bytes of `between` (pass the text between '$' and '*', both excluded).
[[nodiscard]] constexpr std::uint8_t checksum(std::string_view between) noexcept {
  std::uint8_t x = 0;
  for (char c : between) x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(c));
  return x;
}

}  // namespace seawire::nmea
