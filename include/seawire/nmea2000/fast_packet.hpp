// SPDX-License-Identifier: BSL-1.0
#pragma once
// NMEA 2000 fast packets: a payload of up to 223 bytes carried by up to 32 CAN frames of one PGN
// from one source. Byte 0 of every frame holds a sequence counter (bits 7-5, the same in every
// frame of one packet, incremented per packet modulo 8 by the sender) and the frame's number
// (bits 4-0). Frame 0 carries the payload's length in byte 1 and payload bytes 0-5; frame k >= 1
// carries bytes 6 + 7(k-1) .. 6 + 7k - 1. A sender pads the last frame with 0xFF or shortens it.
// Whether a PGN travels as fast packet is a property of the PGN (pgn_info::transport), not of
// the bytes.
//
// Sending: split_fast_packet() cuts a payload into frames; fast_packet_sequencer keeps the
// sequence counter of each (PGN, source).
//
// Receiving: fast_packet_assembler<Slots> rebuilds packets from frames of any number of sources
// and PGNs interleaved, in `Slots` fixed buffers (Slots x 240 bytes; 16 slots, about 3.8 KiB, by
// default), keyed on (source, PGN, destination). Frames must come in order, as every sender
// sends them. What cannot be assembled is dropped and counted by reason:
//
//   missing_frame     a frame skipped (frame k+2 after frame k), or a new frame 0 before the
//                     packet was complete; the unfinished packet is dropped with the frame
//   repeated_frame    a frame number that already arrived (a retransmission)
//   sequence_changed  a frame whose sequence counter differs from its packet's frame 0
//   too_long          frame 0 announcing more bytes than 223 or than the PGN's length
//   short_frame       a frame, other than the last, with fewer than 8 bytes (or an empty one)
//   orphan_frame      a frame k >= 1 with no packet begun (its frame 0 was lost or dropped)
//   evicted           every slot busy with an unfinished packet when a new one began: the one
//                     touched longest ago is dropped to make room
//
// Every frame fed is accounted for: frames_in() == frames_assembled() + frames_dropped() +
// frames_pending(). A dropped packet never blocks the next one: the next frame 0 starts afresh.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "seawire/error.hpp"
#include "seawire/nmea2000/can_id.hpp"

namespace seawire::nmea2000 {

inline constexpr std::size_t max_fast_packet_length = 223;  ///< 6 + 31 x 7
inline constexpr std::size_t max_fast_packet_frames = 32;

/// Frames needed for a payload of `length` bytes.
[[nodiscard]] constexpr std::size_t fast_packet_frame_count(std::size_t length) noexcept {
  return length <= 6 ? 1 : 1 + (length - 6 + 6) / 7;
}

/// The data bytes of one CAN frame (up to 8).
struct frame_data {
  std::array<std::uint8_t, 8> bytes{};
  std::uint8_t size = 0;

  [[nodiscard]] constexpr std::span<const std::uint8_t> view() const noexcept {
    return {bytes.data(), size};
  }
  [[nodiscard]] constexpr bool operator==(const frame_data& o) const noexcept {
    if (size != o.size) return false;
    for (std::size_t i = 0; i < size; ++i)
      if (bytes[i] != o.bytes[i]) return false;
    return true;
  }
};

/// The frames of one fast packet, in sending order.
struct fast_packet_frames {
  std::array<frame_data, max_fast_packet_frames> frames{};
  std::size_t count = 0;

  [[nodiscard]] constexpr std::span<const frame_data> view() const noexcept {
    return {frames.data(), count};
  }
};

/// The frames carrying `payload` with sequence counter `sequence` (0-7). Every frame has 8 bytes,
/// the last padded with 0xFF. bad_length for a payload above 223 bytes, out_of_range for a
/// sequence above 7.
[[nodiscard]] constexpr result<fast_packet_frames> split_fast_packet(
    std::span<const std::uint8_t> payload, std::uint8_t sequence) noexcept {
  result<fast_packet_frames> r;
  if (payload.size() > max_fast_packet_length) {
    r.ec = errc::bad_length;
    return r;
  }
  if (sequence > 7) {
    r.ec = errc::out_of_range;
    return r;
  }
  const std::size_t n = fast_packet_frame_count(payload.size());
  std::size_t at = 0;
  for (std::size_t k = 0; k < n; ++k) {
    frame_data& f = r.value.frames[k];
    f.bytes.fill(0xFF);
    f.size = 8;
    f.bytes[0] = static_cast<std::uint8_t>(std::size_t{sequence} << 5 | k);
    std::size_t i = 1;
    if (k == 0) f.bytes[i++] = static_cast<std::uint8_t>(payload.size());
    for (; i < 8 && at < payload.size(); ++i) f.bytes[i] = payload[at++];
  }
  r.value.count = n;
  return r;
}

/// The sequence counter of each (PGN, source) a sender sends fast packets for, in `Slots` fixed
/// entries (the least recently used is reused when full, and starts again at 0).
template <std::size_t Slots = 16>
class fast_packet_sequencer {
 public:
  /// The counter to use for the next packet of (pgn, source); advances it.
  constexpr std::uint8_t next(std::uint32_t pgn, std::uint8_t source) noexcept {
    ++clock_;
    entry* oldest = &entries_[0];
    for (entry& e : entries_) {
      if (e.used && e.pgn == pgn && e.source == source) {
        e.touched = clock_;
        const std::uint8_t s = e.sequence;
        e.sequence = static_cast<std::uint8_t>((s + 1) & 7);
        return s;
      }
      if (!e.used || (oldest->used && e.touched < oldest->touched)) oldest = &e;
    }
    *oldest = entry{pgn, source, 1, true, clock_};
    return 0;
  }

 private:
  struct entry {
    std::uint32_t pgn = 0;
    std::uint8_t source = 0;
    std::uint8_t sequence = 0;
    bool used = false;
    std::uint64_t touched = 0;
  };
  std::array<entry, Slots> entries_{};
  std::uint64_t clock_ = 0;
};

/// Why the assembler dropped frames (see the top of this file).
enum class fast_packet_drop : std::uint8_t {
  missing_frame,
  repeated_frame,
  sequence_changed,
  too_long,
  short_frame,
  orphan_frame,
  evicted,
};
inline constexpr std::size_t fast_packet_drop_count = 7;

[[nodiscard]] constexpr std::string_view name(fast_packet_drop d) noexcept {
  switch (d) {
    case fast_packet_drop::missing_frame: return "missing_frame";
    case fast_packet_drop::repeated_frame: return "repeated_frame";
    case fast_packet_drop::sequence_changed: return "sequence_changed";
    case fast_packet_drop::too_long: return "too_long";
    case fast_packet_drop::short_frame: return "short_frame";
    case fast_packet_drop::orphan_frame: return "orphan_frame";
    case fast_packet_drop::evicted: return "evicted";
  }
  return "unknown";
}

/// A packet the assembler completed. `payload` views the assembler's buffer: valid until the
/// next call to feed().
struct assembled_packet {
  can_id id;  ///< of the last frame (its priority)
  std::span<const std::uint8_t> payload;
};

template <std::size_t Slots = 16>
class fast_packet_assembler {
  static_assert(Slots >= 1);

 public:
  /// Takes one frame of a fast-packet PGN. `max_length` is the longest payload the PGN may have
  /// (its description's length for a PGN of this library). Returns the packet this frame
  /// completes, if any.
  constexpr std::optional<assembled_packet> feed(
      const can_id& id, std::span<const std::uint8_t> data,
      std::size_t max_length = max_fast_packet_length) noexcept {
    ++frames_in_;
    ++clock_;
    if (max_length > max_fast_packet_length) max_length = max_fast_packet_length;
    if (data.empty()) {
      drop_frame(fast_packet_drop::short_frame);
      return std::nullopt;
    }
    const auto sequence = static_cast<std::uint8_t>(data[0] >> 5);
    const auto number = static_cast<std::uint8_t>(data[0] & 0x1F);
    slot* s = find(id);
    if (number == 0) {
      if (s) {
        drop_packet(*s, s->sequence == sequence && s->frames == 1
                            ? fast_packet_drop::repeated_frame
                            : fast_packet_drop::missing_frame);
      }
      if (data.size() < 2) {
        drop_frame(fast_packet_drop::short_frame);
        return std::nullopt;
      }
      const std::size_t length = data[1];
      if (length > max_length) {
        drop_frame(fast_packet_drop::too_long);
        return std::nullopt;
      }
      const std::size_t here = std::min<std::size_t>(length, 6);
      if (data.size() < 2 + here) {
        drop_frame(fast_packet_drop::short_frame);
        return std::nullopt;
      }
      s = claim();
      s->id = id;
      s->sequence = sequence;
      s->length = static_cast<std::uint8_t>(length);
      s->received = 0;
      s->frames = 1;
      s->used = true;
      s->touched = clock_;
      for (std::size_t i = 0; i < here; ++i) s->buffer[s->received++] = data[2 + i];
      pending_ += 1;
      return complete_if_done(*s);
    }
    if (!s) {
      drop_frame(fast_packet_drop::orphan_frame);
      return std::nullopt;
    }
    if (sequence != s->sequence) {
      drop_packet(*s, fast_packet_drop::sequence_changed, 1);
      return std::nullopt;
    }
    if (number < s->frames) {
      drop_packet(*s, fast_packet_drop::repeated_frame, 1);
      return std::nullopt;
    }
    if (number > s->frames) {
      drop_packet(*s, fast_packet_drop::missing_frame, 1);
      return std::nullopt;
    }
    const std::size_t remaining = s->length - s->received;
    const std::size_t here = std::min<std::size_t>(remaining, 7);
    if (data.size() < 1 + here) {
      drop_packet(*s, fast_packet_drop::short_frame, 1);
      return std::nullopt;
    }
    for (std::size_t i = 0; i < here; ++i) s->buffer[s->received++] = data[1 + i];
    s->frames += 1;
    s->touched = clock_;
    s->id.priority = id.priority;
    pending_ += 1;
    return complete_if_done(*s);
  }

  /// Forgets every unfinished packet (counted as missing_frame), e.g. at the end of a log.
  constexpr void flush() noexcept {
    for (slot& s : slots_)
      if (s.used) drop_packet(s, fast_packet_drop::missing_frame);
  }

  [[nodiscard]] constexpr std::uint64_t frames_in() const noexcept { return frames_in_; }
  [[nodiscard]] constexpr std::uint64_t frames_assembled() const noexcept { return assembled_; }
  [[nodiscard]] constexpr std::uint64_t frames_dropped() const noexcept { return dropped_; }
  [[nodiscard]] constexpr std::uint64_t frames_pending() const noexcept { return pending_; }
  [[nodiscard]] constexpr std::uint64_t packets() const noexcept { return packets_; }
  /// How many times frames were dropped for `why` (one event may drop several frames).
  [[nodiscard]] constexpr std::uint64_t drops(fast_packet_drop why) const noexcept {
    return drops_[static_cast<std::size_t>(why)];
  }

 private:
  struct slot {
    can_id id;
    std::uint8_t sequence = 0;
    std::uint8_t length = 0;
    std::uint8_t received = 0;
    std::uint8_t frames = 0;  ///< frames taken so far = the next frame number expected
    bool used = false;
    std::uint64_t touched = 0;
    std::array<std::uint8_t, max_fast_packet_length> buffer{};
  };

  [[nodiscard]] static constexpr bool same_key(const can_id& a, const can_id& b) noexcept {
    return a.source == b.source && a.pgn == b.pgn && a.destination == b.destination;
  }
  constexpr slot* find(const can_id& id) noexcept {
    for (slot& s : slots_)
      if (s.used && same_key(s.id, id)) return &s;
    return nullptr;
  }
  constexpr slot* claim() noexcept {
    slot* oldest = nullptr;
    for (slot& s : slots_) {
      if (!s.used) return &s;
      if (!oldest || s.touched < oldest->touched) oldest = &s;
    }
    drop_packet(*oldest, fast_packet_drop::evicted);
    return oldest;
  }
  constexpr void drop_frame(fast_packet_drop why) noexcept {
    ++drops_[static_cast<std::size_t>(why)];
    ++dropped_;
  }
  /// Drops the slot's packet and `extra` frames just fed with it.
  constexpr void drop_packet(slot& s, fast_packet_drop why, std::uint64_t extra = 0) noexcept {
    ++drops_[static_cast<std::size_t>(why)];
    dropped_ += s.frames + extra;
    pending_ -= s.frames;
    s.used = false;
  }
  constexpr std::optional<assembled_packet> complete_if_done(slot& s) noexcept {
    if (s.received < s.length) return std::nullopt;
    s.used = false;
    pending_ -= s.frames;
    assembled_ += s.frames;
    ++packets_;
    return assembled_packet{s.id, std::span<const std::uint8_t>(s.buffer.data(), s.length)};
  }

  std::array<slot, Slots> slots_{};
  std::array<std::uint64_t, fast_packet_drop_count> drops_{};
  std::uint64_t frames_in_ = 0;
  std::uint64_t assembled_ = 0;
  std::uint64_t dropped_ = 0;
  std::uint64_t pending_ = 0;
  std::uint64_t packets_ = 0;
  std::uint64_t clock_ = 0;
};

}  // namespace seawire::nmea2000
