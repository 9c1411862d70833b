// SPDX-License-Identifier: BSL-1.0
#pragma once
// The ANELLO 0xAB00 frame the frame and stream tests start from, and the CRC made right again
// after a test changed a frame's payload.

#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <string_view>

#include "hex_of.hpp"
#include "seawire/anello/frame.hpp"
#include "seawire/detail/byte_order.hpp"
#include "seawire/detail/crc32.hpp"

namespace support {

/// The example frame of the ANELLO binary spec (section 2.2.1, "mix of valid and invalid
/// data"); its CRC is right. Also tests/data/anello_seed_frame.hex.
inline constexpr std::string_view seed_hex =
    "AB0000308EF7F176005901F4ECFFF903369A0000FFFF00000190794363D0000001E07FFFFFFFFFFF00000000000200"
    "6C0003005AFFFFFFFF";

/// The frame whose bytes `hex` spells (two digits a byte, no separators).
constexpr seawire::anello::frame_bytes frame_from_hex(std::string_view hex) {
  seawire::anello::frame_bytes out{};
  for (std::size_t i = 0; i < out.size() && 2 * i + 1 < hex.size(); ++i) {
    out[i] = static_cast<std::uint8_t>(hex_digit(hex[2 * i]) * 16 + hex_digit(hex[2 * i + 1]));
  }
  return out;
}

inline constexpr seawire::anello::frame_bytes seed = frame_from_hex(seed_hex);

/// The hex digits of tests/data/anello_seed_frame.hex (what else the file holds left out); the
/// test stops if it cannot be read.
inline std::string seed_hex_from_file() {
#ifdef SEAWIRE_TEST_DATA_DIR
  const std::string path = std::string(SEAWIRE_TEST_DATA_DIR) + "/anello_seed_frame.hex";
#else
  std::string path = __FILE__;
  path = path.substr(0, path.find_last_of('/') + 1) + "data/anello_seed_frame.hex";
#endif
  std::FILE* file = std::fopen(path.c_str(), "rb");
  INFO(path);
  REQUIRE(file != nullptr);
  std::string hex;
  for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file)) {
    if (hex_digit(static_cast<char>(c)) >= 0) hex.push_back(static_cast<char>(c));
  }
  std::fclose(file);
  return hex;
}

/// Gives a test frame a correct CRC after its payload was changed.
inline void seal(std::span<std::uint8_t> frame) {
  using seawire::anello::header_size;
  using seawire::anello::payload_size;
  seawire::detail::store_be(frame, 4, seawire::crc32(frame.subspan(header_size, payload_size)));
}

/// A copy of `f` with a correct CRC.
inline seawire::anello::frame_bytes sealed(seawire::anello::frame_bytes f) {
  seal(f);
  return f;
}

}  // namespace support
