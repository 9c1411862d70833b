// SPDX-License-Identifier: BSL-1.0
// NMEA 2000 fast packets. The input is cut into CAN frames, each one header byte (bits 0-1 the
// source, 2-3 which of four PGNs, 4-7 the data length, 9-15 meaning 8) and then up to 8 data
// bytes, all fed to one fast_packet_assembler<4> (fewer slots than the 4 x 4 keys, so eviction
// happens). Then the whole input as a payload: split_fast_packet, and its frames fed back.
// Properties:
//  - after every feed, frames_in == frames_assembled + frames_dropped + frames_pending; after
//    flush(), frames_pending == 0 and the sum still holds;
//  - a completed packet is of the frame's key (source, PGN, destination), carries the priority
//    of the frame that completed it, is no longer than 223 bytes, is as long as the last frame 0
//    of its key announced, holds at each place the bytes of the frame of that number its key
//    sent last (frames come in any order), all of one sequence counter, and moves
//    fast_packet_frame_count(length) frames to frames_assembled;
//  - split_fast_packet refuses payloads above 223 bytes and sequences above 7, and otherwise
//    gives fast_packet_frame_count(size) frames of 8 bytes whose first byte is the sequence and
//    frame number, which a fresh assembler turns back into the same payload, on the last frame
//    and not before, with nothing dropped or pending.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fuzz_common.hpp"
#include "seawire/nmea2000/can_id.hpp"
#include "seawire/nmea2000/fast_packet.hpp"

namespace seawire::fuzz {
namespace {

namespace n2k = nmea2000;

/// The PGNs a header byte can pick: three of the library's fast-packet PGNs, and an addressed
/// (PDU1) proprietary one.
constexpr std::array<std::uint32_t, 4> choices = {127489, 128275, 130578, 126720};

template <std::size_t Slots>
void check_balance(const n2k::fast_packet_assembler<Slots>& a, const std::string& where) {
  SEAWIRE_FUZZ_CHECK(
      a.frames_in() == a.frames_assembled() + a.frames_dropped() + a.frames_pending(),
      "frames_in != assembled + dropped + pending", where, number(a.frames_in()),
      number(a.frames_assembled()), number(a.frames_dropped()), number(a.frames_pending()));
}

void check_stream(std::span<const std::uint8_t> input) {
  n2k::fast_packet_assembler<4> a;
  // The last frame of each number each key (4 sources x 4 PGNs) sent, that the assembler could
  // take (not an empty frame, nor a frame 0 without a length or announcing more than 223).
  using frame_bytes = std::vector<std::uint8_t>;
  std::array<std::array<std::optional<frame_bytes>, 32>, 16> keys{};
  std::uint64_t packets = 0;

  std::size_t at = 0;
  for (std::size_t frame = 0; at < input.size(); ++frame) {
    const std::uint8_t h = input[at++];
    const std::size_t want = std::min<std::size_t>(h >> 4U, 8);
    const std::size_t len = std::min(want, input.size() - at);
    const std::span<const std::uint8_t> data = input.subspan(at, len);
    at += len;

    const auto source = static_cast<std::uint8_t>(h & 3U);
    const std::size_t pick = (h >> 2U) & 3U;
    const std::uint32_t pgn = choices[pick];
    n2k::can_id id;
    id.priority = static_cast<std::uint8_t>(frame % 8);
    id.pgn = pgn;
    id.source = source;
    // The PDU1 PGN is sent to the next source's address, so the destination is part of the key.
    id.destination =
        n2k::is_addressed(pgn) ? static_cast<std::uint8_t>(source ^ 1U) : n2k::broadcast_address;
    auto& k = keys[pick * 4 + source];
    const bool takeable =
        !data.empty() && ((data[0] & 0x1FU) != 0 || (data.size() >= 2 && data[1] <= 223));
    if (takeable) k[data[0] & 0x1FU] = frame_bytes(data.begin(), data.end());

    const std::uint64_t assembled_before = a.frames_assembled();
    const std::optional<n2k::assembled_packet> done = a.feed(id, data);
    const std::string where = "frame " + number(frame) + ": " + hex_of(data);
    check_balance(a, where);
    if (!done) {
      SEAWIRE_FUZZ_CHECK(a.frames_assembled() == assembled_before, "frames assembled, no packet",
                         where);
      continue;
    }
    ++packets;
    const std::span<const std::uint8_t> p = done->payload;
    SEAWIRE_FUZZ_CHECK(done->id.source == id.source && done->id.pgn == id.pgn &&
                           done->id.destination == id.destination &&
                           done->id.priority == id.priority,
                       "a packet of another key, or not the last frame's priority", where);
    SEAWIRE_FUZZ_CHECK(p.size() <= n2k::max_fast_packet_length, "a packet longer than 223 bytes",
                       where, number(p.size()));
    SEAWIRE_FUZZ_CHECK(k[0] && (*k[0])[1] == p.size(),
                       "a packet not as long as its key's last frame 0 announced", where,
                       number(p.size()));
    // Every byte is the byte of the frame of its number last sent, whatever the frames' order.
    const std::size_t n = n2k::fast_packet_frame_count(p.size());
    for (std::size_t f = 0; f < n; ++f) {
      SEAWIRE_FUZZ_CHECK(k[f].has_value(), "a packet of a frame never sent", where, number(f));
      const frame_bytes& b = *k[f];
      const std::size_t skip = f == 0 ? 2 : 1;
      const std::size_t off = f == 0 ? 0 : 6 + 7 * (f - 1);
      for (std::size_t i = 0; off + i < p.size() && i < (f == 0 ? 6U : 7U); ++i) {
        SEAWIRE_FUZZ_CHECK(skip + i < b.size() && b[skip + i] == p[off + i],
                           "a packet's byte is not its frame's", where, number(f), number(i),
                           hex_of(p), hex_of(b));
      }
      SEAWIRE_FUZZ_CHECK((b[0] >> 5U) == (*k[0])[0] >> 5U,
                         "a packet of frames of different sequence counters", where, number(f));
    }
    SEAWIRE_FUZZ_CHECK(a.frames_assembled() - assembled_before == n,
                       "a packet of n bytes did not take fast_packet_frame_count(n) frames", where,
                       number(a.frames_assembled() - assembled_before));
    SEAWIRE_FUZZ_CHECK(a.packets() == packets, where);
  }
  a.flush();
  check_balance(a, "after flush");
  SEAWIRE_FUZZ_CHECK(a.frames_pending() == 0, "frames pending after flush",
                     number(a.frames_pending()));
}

void check_split(std::span<const std::uint8_t> payload, std::uint8_t sequence) {
  const seawire::result<n2k::fast_packet_frames> r = n2k::split_fast_packet(payload, sequence);
  if (payload.size() > n2k::max_fast_packet_length || sequence > 7) {
    SEAWIRE_FUZZ_CHECK(
        !r && r.ec == (payload.size() > n2k::max_fast_packet_length ? errc::bad_length
                                                                    : errc::out_of_range),
        "split_fast_packet took a payload or sequence it cannot send", number(payload.size()),
        number(sequence), name(r.ec));
    return;
  }
  SEAWIRE_FUZZ_CHECK(r.ok(), name(r.ec));
  const std::size_t n = r.value.count;
  SEAWIRE_FUZZ_CHECK(
      n == n2k::fast_packet_frame_count(payload.size()) && n <= n2k::max_fast_packet_frames,
      "split_fast_packet made the wrong number of frames", number(payload.size()), number(n));
  n2k::fast_packet_assembler<4> a;
  const n2k::can_id id{2, 130578, 0x23, n2k::broadcast_address};
  for (std::size_t k = 0; k < n; ++k) {
    const n2k::frame_data& f = r.value.frames[k];
    SEAWIRE_FUZZ_CHECK(f.size == 8 && f.bytes[0] == (std::size_t{sequence} << 5U | k),
                       "a frame not of 8 bytes, or its first byte wrong", number(k),
                       hex_of(f.view()));
    const std::optional<n2k::assembled_packet> done = a.feed(id, f.view());
    if (k + 1 < n) {
      SEAWIRE_FUZZ_CHECK(!done, "a packet before its last frame", number(k));
      continue;
    }
    SEAWIRE_FUZZ_CHECK(done && std::equal(done->payload.begin(), done->payload.end(),
                                          payload.begin(), payload.end()),
                       "split -> assemble changed the payload", hex_of(payload),
                       done ? hex_of(done->payload) : "(nothing)");
  }
  SEAWIRE_FUZZ_CHECK(a.frames_in() == n && a.frames_assembled() == n && a.frames_dropped() == 0 &&
                         a.frames_pending() == 0 && a.packets() == 1,
                     "split frames did not assemble cleanly", number(a.frames_dropped()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> input(data, size);
  check_stream(input);
  // The input as a payload, with a sequence from its first byte (8-15 must be refused, so only
  // one input in 32 tries it).
  const std::uint8_t first = size == 0 ? 0 : data[0];
  check_split(input, static_cast<std::uint8_t>(first % 32 == 31 ? 8 + (first >> 5U) : first & 7U));
  return 0;
}

}  // namespace seawire::fuzz
