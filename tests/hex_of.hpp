// SPDX-License-Identifier: BSL-1.0
#pragma once
// Bytes as text for failure reports, shared by the tests and the fuzz targets.

#include <cstdint>
#include <span>
#include <string>

namespace support {

/// Bytes as upper-case hex, two digits each, nothing between.
inline std::string hex_of(std::span<const std::uint8_t> bytes) {
  std::string out;
  for (const std::uint8_t b : bytes) {
    out += "0123456789ABCDEF"[b >> 4U];
    out += "0123456789ABCDEF"[b & 15U];
  }
  return out;
}

}  // namespace support
