// SPDX-License-Identifier: BSL-1.0
#pragma once
// Bytes as hex text and back: for failure reports and for the payloads the tests spell in hex,
// shared by the tests and the fuzz targets. Written here rather than with the library's own hex
// helpers, so that a test's bytes do not depend on the code under test.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>
#include <vector>

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

/// A hex digit's value (either case), or -1 for any other character.
constexpr int hex_digit(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

/// The bytes `hex` spells: two digits a byte, either case, spaces or commas allowed between
/// bytes. Any other character, a separator inside a byte or a last lone digit is a mistake in the
/// test's own text: it is printed and the program stops.
inline std::vector<std::uint8_t> hex_bytes(std::string_view hex) {
  std::vector<std::uint8_t> out;
  int high = -1;  // the first digit of a byte, while its second is awaited
  for (const char c : hex) {
    const int d = hex_digit(c);
    if (d < 0 && high < 0 && (c == ' ' || c == ',')) continue;
    if (d < 0) {
      std::fprintf(stderr, "hex_bytes: not hex: \"%.*s\"\n", static_cast<int>(hex.size()),
                   hex.data());
      std::abort();
    }
    if (high < 0) {
      high = d;
    } else {
      out.push_back(static_cast<std::uint8_t>(high << 4 | d));
      high = -1;
    }
  }
  if (high >= 0) {
    std::fprintf(stderr, "hex_bytes: a lone last digit: \"%.*s\"\n", static_cast<int>(hex.size()),
                 hex.data());
    std::abort();
  }
  return out;
}

}  // namespace support
