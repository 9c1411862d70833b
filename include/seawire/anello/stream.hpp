// SPDX-License-Identifier: BSL-1.0
#pragma once
// anello::stream_reader: one input link carrying both NMEA 0183 sentences and 0xAB00 binary
// frames (spec 002, sections 2.1 and 2.2), cut into items in the order they were sent, from
// chunks of any size. It is nmea::stream_reader with the 0xAB00 frame plugged in; the rules,
// the byte accounting and the drop reports are nmea::stream_reader's (seawire/nmea/stream.hpp).
//
//   anello::stream_reader<> reader;
//   reader.feed(chunk);                        // bytes as they arrive: std::span<const uint8_t>
//   while (auto item = reader.next()) {        //   or std::string_view
//     if (item->is_frame()) use(item->frame);  // sensor_frame_raw, CRC checked; item->bytes
//     else if (item->is_sentence()) use(item->sentence.text);  // decode_input() it
//   }
//   ...
//   while (auto item = reader.finish()) ...;   // end of stream: what is left, then nullopt
//
// The binary protocol has no byte stuffing, so which bytes are a frame is decided by the bytes
// alone. For this frame the reader's rules read:
// - Between items 0xAB starts a frame candidate. It must go on 00 (the frame id AB 00), then
//   00 30 (the length: 48 is the only length the frame has). 0xAB followed by anything but 00 is
//   one noise byte; AB 00 followed by any other length is a bad_length drop.
// - A candidate with a good header takes the next 52 bytes whatever they are, then its CRC-32
//   is checked. A bad CRC, or a candidate cut short by finish(), drops the AB and reads the
//   bytes after it again, so a sentence or a real frame that a false AB 00 00 30 swallowed
//   still comes out; a byte is read again at most 14 times (candidates start 4 bytes apart at
//   the closest: AB 00 00 30 AB ...).
// - A 0xAB inside a sentence ends it as a '$' does, and starts a candidate: a sentence whose
//   "*hh" checksum is complete is yielded (it lacks only its line ending), any other is dropped
//   as interrupted.
// What a false sync costs: the items inside its 56 bytes come out once the 56th byte has arrived
// (or at finish()), not before; nothing is lost and the order is kept.

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
  [[nodiscard]] static constexpr result<sensor_frame_raw> decode(const frame_bytes& b) noexcept {
    return decode_frame(b);
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
