// SPDX-License-Identifier: BSL-1.0
#pragma once
// nmea::framer: nmea::stream_reader without frames or drop reports: a byte stream cut into
// candidate sentences (framed_line), drops only counted (framer_stats). The same rules cut the
// same lines (docs/streams.md); read through stream_reader<Capacity> with report_drops(true) to
// hear about each drop. Use: feed(chunk), next() until nullopt; finish() at end of stream.
// Use: feed(chunk), then next() until nullopt, then the next chunk; finish() at end of stream.

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>

#include "seawire/detail/inline.hpp"
#include "seawire/nmea/stream.hpp"

namespace seawire::nmea {

/// What a framer has seen. Every byte fed lands in exactly one bucket: a yielded line's text,
/// noise_bytes, dropped_bytes, or a CR/LF.
struct framer_stats {
  std::uint64_t sentences = 0;      ///< lines yielded
  std::uint64_t noise_bytes = 0;    ///< bytes outside any sentence (not counting CR, LF)
  std::uint64_t interrupted = 0;    ///< sentences without a complete checksum abandoned for a
                                    ///< new '$' (not '!')
  std::uint64_t overlong = 0;       ///< lines dropped for exceeding the capacity
  std::uint64_t invalid_bytes = 0;  ///< lines dropped for a byte outside 0x20..0x7E
  std::uint64_t dropped_bytes = 0;  ///< bytes of all dropped lines, without their line endings

  friend constexpr bool operator==(const framer_stats&, const framer_stats&) noexcept = default;
};

/// Byte stream -> candidate sentences, in fixed memory: `Capacity` bytes of buffer plus a few
/// counters. Sans-I/O; never allocates; usable in constant expressions; noexcept throughout (the
/// callback feed() is as noexcept as its callback).
template <std::size_t Capacity = 1024>
class framer {
 public:
  static constexpr std::size_t capacity = Capacity;

  /// Hands over the next chunk. Precondition: next() has returned nullopt since the last feed(),
  /// i.e. the previous chunk is drained; the chunk must stay alive until it is.
  constexpr void feed(std::string_view chunk) noexcept { reader_.feed(chunk); }

  /// Feeds `chunk` and drains it, calling on_line(const framed_line&) for each line.
  template <class F>
  constexpr void feed(std::string_view chunk,
                      F&& on_line) noexcept(std::is_nothrow_invocable_v<F&, const framed_line&>) {
    feed(chunk);
    while (const std::optional<framed_line> l = next()) on_line(*l);
  }

  /// The next complete line of the current chunk, or nullopt once the chunk is used up.
  [[nodiscard]] SEAWIRE_FLATTEN constexpr std::optional<framed_line> next() noexcept {
    return line_of(reader_.next());
  }

  /// The link has gone quiet: yields a sentence whose CR was the last byte fed (held back to tell
  /// CR from CR LF) as ended by CR. Precondition: the current chunk is drained.
  [[nodiscard]] constexpr std::optional<framed_line> flush() noexcept {
    return line_of(reader_.flush());
  }

  /// End of stream: the sentence still waiting for its line ending, if any, once. Precondition:
  /// the current chunk is drained. Afterwards the framer sits at a line start; reset() before
  /// reusing it for an unrelated stream.
  [[nodiscard]] constexpr std::optional<framed_line> finish() noexcept {
    const std::optional<framed_line> last = line_of(reader_.finish());
    // Without frames or drop reports the end of stream holds at most that one line; the call
    // below returns nothing and closes the end of stream, so feed() may follow.
    [[maybe_unused]] const auto none = reader_.next();
    assert(!none && "framer::finish: a second item at the end of stream");
    return last;
  }

  /// The counters, in the framer's terms (CR and LF bytes are not counted: they are what is
  /// left once the other buckets are taken from the bytes fed).
  [[nodiscard]] constexpr framer_stats stats() const noexcept {
    const stream_stats& s = reader_.stats();
    return framer_stats{s.sentences, s.noise_bytes,   s.interrupted,
                        s.overlong,  s.invalid_bytes, s.dropped_bytes};
  }

  /// Back to the freshly constructed state: no chunk, no partial line, line 1, zero stats.
  constexpr void reset() noexcept { reader_.reset(); }

 private:
  using reader = stream_reader<Capacity>;

  // Drops are not reported (report_drops is never turned on), so every item is a sentence.
  SEAWIRE_ALWAYS_INLINE static constexpr std::optional<framed_line> line_of(
      const std::optional<typename reader::item>& item) noexcept {
    if (!item) return std::nullopt;
    return item->sentence;
  }

  reader reader_;
};

}  // namespace seawire::nmea
