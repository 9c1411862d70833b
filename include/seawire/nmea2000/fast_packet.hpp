// SPDX-License-Identifier: BSL-1.0
#pragma once
// NMEA 2000 fast packets: up to 223 bytes in up to 32 CAN frames of one PGN from one source.
// Byte 0 of each frame: sequence counter (bits 7-5, per packet, modulo 8) and frame number (bits
// 4-0); frame 0 has the length in byte 1 and payload bytes 0-5, frame k >= 1 bytes
// 6 + 7(k-1) .. 6 + 7k - 1; the last frame padded with 0xFF or shortened. The assembler takes
// interleaved sources and PGNs in fixed slots, frames in any order except frame 0 after all the
// others, and accounts for every frame: frames_in() == frames_assembled() + frames_dropped() +
// frames_pending(). Drop reasons and the ordering rule: docs/nmea2000.md.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "seawire/detail/algorithm.hpp"
#include "seawire/detail/enum_names.hpp"
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

// A template of nothing, so that only a caller reads the enumerators' names (at compile time).
template <int = 0>
[[nodiscard]] constexpr std::string_view name(fast_packet_drop d) noexcept {
  return seawire::detail::enumerator_name_of<fast_packet_drop_count>(d);
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
  /// Takes one frame of a fast-packet PGN (see the top of this file). Returns the packet this
  /// frame completes, if any.
  constexpr std::optional<assembled_packet> feed(const can_id& id,
                                                 std::span<const std::uint8_t> data) noexcept {
    ++frames_in_;
    ++clock_;
    if (data.empty() || ((data[0] & 0x1F) == 0 && data.size() < 2)) {
      drop_frame(fast_packet_drop::short_frame);
      return std::nullopt;
    }
    const auto sequence = static_cast<std::uint8_t>(data[0] >> 5);
    const auto number = static_cast<std::uint8_t>(data[0] & 0x1F);
    const std::uint32_t bit = std::uint32_t{1} << number;
    if (number == 0 && data[1] > max_fast_packet_length) {
      drop_frame(fast_packet_drop::too_long);
      return std::nullopt;
    }
    slot* s = find(id);
    if (s != nullptr && s->sequence != sequence) {
      drop_packet(*s, fast_packet_drop::sequence_changed);
      s = nullptr;
    }
    if (s != nullptr && (s->received & bit) != 0) {
      // Frame 0 again after frame 0 and more: that packet lacked frames; anything else repeats.
      drop_packet(*s, number == 0 && s->received != 1 ? fast_packet_drop::missing_frame
                                                      : fast_packet_drop::repeated_frame);
      s = nullptr;
    }
    if (s != nullptr && number == 0) {
      const std::uint32_t all = mask_of(data[1]);
      if ((s->received & ~all) != 0 || (all != 1 && ((s->received | 1) & all) == all)) {
        drop_packet(*s, fast_packet_drop::orphan_frame);
        s = nullptr;
      }
    } else if (s != nullptr && (s->received & 1) != 0 && (mask_of(s->length) & bit) == 0) {
      drop_frame(fast_packet_drop::orphan_frame);  // past the end frame 0 announced
      return std::nullopt;
    }
    if (s == nullptr) {
      s = claim();
      s->id = id;
      s->sequence = sequence;
      s->length = 0;
      s->received = 0;
      s->frames = 0;
      s->used = true;
    }
    const std::size_t skip = number == 0 ? 2 : 1;  // frame 0 also carries the length
    const std::size_t at = offset_of(number);
    const std::size_t here = std::min<std::size_t>(data.size() - skip, capacity_of(number));
    for (std::size_t i = 0; i < here; ++i) s->buffer[at + i] = data[skip + i];
    s->sizes[number] = static_cast<std::uint8_t>(here);
    if (number == 0) s->length = data[1];
    s->received |= bit;
    s->frames += 1;
    s->touched = clock_;
    s->id.priority = id.priority;
    pending_ += 1;
    return complete_if_done(*s);
  }

  /// Forgets every unfinished packet (missing_frame, or orphan_frame for frames without their
  /// frame 0), e.g. at the end of a log.
  constexpr void flush() noexcept {
    for (slot& s : slots_)
      if (s.used)
        drop_packet(s, (s.received & 1) != 0 ? fast_packet_drop::missing_frame
                                             : fast_packet_drop::orphan_frame);
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
    std::uint8_t length = 0;     ///< as frame 0 announced (when received has bit 0)
    std::uint32_t received = 0;  ///< bit k: frame k is held
    std::uint8_t frames = 0;     ///< frames held
    bool used = false;
    std::uint64_t touched = 0;
    std::array<std::uint8_t, max_fast_packet_frames> sizes{};  ///< payload bytes each frame gave
    std::array<std::uint8_t, max_fast_packet_length> buffer{};
  };

  /// Where frame k's bytes go in the payload, and how many it carries at most.
  [[nodiscard]] static constexpr std::size_t offset_of(std::size_t k) noexcept {
    return k == 0 ? 0 : 6 + 7 * (k - 1);
  }
  [[nodiscard]] static constexpr std::size_t capacity_of(std::size_t k) noexcept {
    return k == 0 ? 6 : 7;
  }
  /// The frames a payload of `length` bytes (at most 223) needs, as a bit mask.
  [[nodiscard]] static constexpr std::uint32_t mask_of(std::size_t length) noexcept {
    return static_cast<std::uint32_t>((std::uint64_t{1} << fast_packet_frame_count(length)) - 1);
  }

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
  /// Drops the slot's packet (the frames it holds).
  constexpr void drop_packet(slot& s, fast_packet_drop why) noexcept {
    ++drops_[static_cast<std::size_t>(why)];
    dropped_ += s.frames;
    pending_ -= s.frames;
    s.used = false;
  }
  constexpr std::optional<assembled_packet> complete_if_done(slot& s) noexcept {
    if ((s.received & 1) == 0 || s.received != mask_of(s.length)) return std::nullopt;
    for (std::size_t k = 0; k < s.frames; ++k) {
      const std::size_t at = offset_of(k);
      const std::size_t need = std::min<std::size_t>(capacity_of(k), s.length - at);
      if (s.sizes[k] < need) {
        drop_packet(s, fast_packet_drop::short_frame);
        return std::nullopt;
      }
    }
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
