// SPDX-License-Identifier: BSL-1.0
#pragma once
// anello::stream_reader: one input link carrying NMEA 0183 sentences and 0xAB00 frames, cut into
// items in stream order: nmea::stream_reader with the frame plugged in (sync AB 00 00 30, 56
// bytes, CRC-32; no byte stuffing, so the bytes alone decide). How a false sync is given up and
// re-read: docs/streams.md.

#include <array>
#include <cstddef>
#include <cstdint>

#include "seawire/anello/frame.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/stream.hpp"

namespace seawire::anello {

/// The 0xAB00 sensor frame as nmea::stream_reader recognizes it: AB 00 00 30, 56 bytes in all,
/// checked and decoded by decode_frame (CRC-32 over the payload).
struct frame_recognizer {
  using value_type = sensor_frame_raw;
  static_assert(payload_size <= 0xFF, "the length field's high byte is 0");
  static constexpr std::array<std::uint8_t, 4> header{0xAB, 0x00, 0x00,
                                                      static_cast<std::uint8_t>(payload_size)};
  static constexpr std::size_t size = frame_size;
  // A template of nothing, as decode_frame: the frame's decoder and the CRC tables are compiled
  // where a frame is decoded, not wherever this header is read.
  template <int N = 0>
  [[nodiscard]] static constexpr result<sensor_frame_raw> decode(const frame_bytes& b) noexcept {
    return decode_frame<N>(b);
  }
};
static_assert(nmea::frame_recognizer<frame_recognizer>);

using nmea::drop_reason;
using nmea::stream_drop;
using nmea::stream_item_kind;
using nmea::stream_stats;
/// One item of the INS link: a sentence, a 0xAB00 frame, or a drop report.
using stream_item = nmea::stream_item<frame_recognizer>;
/// NMEA 0183 sentences and 0xAB00 frames from one byte stream, in fixed memory.
template <std::size_t Capacity = 1024>
using stream_reader = nmea::stream_reader<Capacity, frame_recognizer>;

}  // namespace seawire::anello
