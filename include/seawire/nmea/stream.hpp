// SPDX-License-Identifier: BSL-1.0
#pragma once
// nmea::stream_reader: a byte stream (TCP, serial, a log file) cut into NMEA 0183 sentences, and
// the binary frames of one recognizer F, in stream order, from chunks of any size, with every
// dropped byte accounted for. The rules (what starts, ends, interrupts and drops an item), the
// byte accounting and the memory used: docs/streams.md.

#include <array>
#include <cassert>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>

#include "seawire/detail/algorithm.hpp"
#include "seawire/detail/ascii.hpp"
#include "seawire/detail/enum_names.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/framer_scan.hpp"

namespace seawire::nmea {

/// What ended a framed line.
enum class line_ending : std::uint8_t {
  none,  ///< nothing: the stream ended (from finish()), or the next sentence or frame started
         ///< right after the sentence's "*hh" checksum
  lf,    ///< "\n"
  cr,    ///< "\r" not followed by "\n"
  crlf,  ///< "\r\n"
};

/// One candidate sentence, from its '$' or '!' up to (not including) its line ending.
struct framed_line {
  /// Valid until the next call of next(), feed() or finish() on the reader that made it.
  std::string_view text;
  line_ending ending = line_ending::none;
  /// 1-based: line endings seen before this line, plus one.
  std::uint64_t line = 0;

  friend constexpr bool operator==(const framed_line&, const framed_line&) noexcept = default;
};

/// A reader of sentences only: no binary frames on the link.
struct no_frames {};

namespace detail {
// A header's bytes after the sync must read as noise when a candidate is given up: none may
// start an item or break a line.
template <std::size_t N>
consteval bool header_is_noise_after_sync(const std::array<std::uint8_t, N>& h) {
  for (std::size_t k = 1; k < N; ++k)
    if (h[k] == '$' || h[k] == '!' || h[k] == '\r' || h[k] == '\n' || h[k] == h[0]) return false;
  return true;
}
}  // namespace detail

/// A binary frame recognizer plugged into stream_reader: a fixed-size frame that starts with a
/// fixed header and carries a check of its own (a CRC).
///   header  the bytes every frame starts with, at least two; header[0] is the sync byte that
///           starts a candidate, header[1] (the frame id) tells a candidate from a stray sync
///   size    the whole frame, header included
///   decode  checks and decodes the `size` bytes; an error rejects the candidate (bad_crc)
/// The sync byte is not printable ASCII (no sentence can hold it), and no later header byte
/// starts an item or breaks a line.
template <class F>
concept frame_recognizer = requires(const std::array<std::uint8_t, F::size>& bytes) {
  { F::header.size() } -> std::convertible_to<std::size_t>;
  { F::size } -> std::convertible_to<std::size_t>;
  typename F::value_type;
  { F::decode(bytes) } -> std::same_as<result<typename F::value_type>>;
}
&&(F::header.size() >= 2) && (F::size > F::header.size()) && (F::size <= 256) &&
    (F::header[0] != '$' && F::header[0] != '!' && F::header[0] != '\r' && F::header[0] != '\n' &&
     (F::header[0] < 0x20 || F::header[0] > 0x7E)) &&
    detail::header_is_noise_after_sync(F::header);

namespace detail {
// What a stream item holds of a frame: nothing for a reader without frames.
template <class F>
struct frame_parts {
  using bytes_type = std::array<std::uint8_t, F::size>;
  using value_type = typename F::value_type;
};
template <>
struct frame_parts<no_frames> {
  struct none {
    friend constexpr bool operator==(none, none) noexcept = default;
  };
  using bytes_type = none;
  using value_type = none;
};
}  // namespace detail

/// What a stream item is.
enum class stream_item_kind : std::uint8_t {
  sentence,  ///< an NMEA 0183 line: stream_item::sentence
  frame,     ///< a binary frame that passed its recognizer's check: stream_item::bytes, ::frame
  dropped,   ///< bytes the reader dropped, and why: stream_item::drop (only after
             ///< stream_reader::report_drops(true))
};

/// Why a stream_reader dropped bytes (the counters of stream_stats, one report per event).
enum class drop_reason : std::uint8_t {
  noise,            ///< bytes between items that start none (no '$' or '!' before them; a
                    ///< frame's sync byte not followed by its id is one of them)
  invalid_byte,     ///< a sentence holding a byte outside 0x20..0x7E: it and the rest of its line
  overlong,         ///< a sentence longer than the reader's capacity: it and the rest of its line
  interrupted,      ///< a sentence without a complete "*hh" checksum, ended by a '$' or a frame's
                    ///< sync byte before its line ending: cut short, or sent without either
  bad_crc,          ///< a whole frame candidate that failed its check (the CRC)
  bad_length,       ///< a frame's sync and id followed by other header bytes (the length)
  truncated_frame,  ///< a frame candidate (sync and id at least) cut short by finish()
};

/// "noise", "invalid_byte", ...: the enumerator's name.
// (A template of nothing, so that only a caller reads the enumerators' names.)
template <int = 0>
[[nodiscard]] constexpr std::string_view name(drop_reason r) noexcept {
  return seawire::detail::enumerator_name_of<7>(r);
}

/// One drop: which bytes of the stream the reader gave up on, and why. The stream_item's offset
/// and line are those of the first byte concerned.
struct stream_drop {
  /// Most bytes a report shows (a longer run of dropped bytes is shown by its start).
  static constexpr std::size_t max_shown = 256;

  drop_reason reason = drop_reason::noise;
  /// Bytes taken out of the stream by this event. Over all reports of a finished stream they add
  /// up to stream_stats::noise_bytes + dropped_bytes. A rejected frame candidate (bad_crc,
  /// truncated_frame) drops only its sync byte: the bytes after it are read again and may still
  /// be items or drops of their own, reported after this one.
  std::uint64_t size = 0;
  /// The bytes concerned, from the report's offset, at most max_shown of them: the dropped
  /// bytes; for bad_crc and truncated_frame the whole candidate (up to a frame); for bad_length
  /// the header up to and including the byte that broke it (that byte is read again). Valid
  /// until the next call of next(), feed() or finish().
  std::string_view bytes{};

  /// Whether the report is about a frame candidate (bad_crc, bad_length, truncated_frame): its
  /// bytes are binary, and those after its sync byte are read again.
  [[nodiscard]] constexpr bool of_frame() const noexcept {
    return reason == drop_reason::bad_crc || reason == drop_reason::bad_length ||
           reason == drop_reason::truncated_frame;
  }

  friend constexpr bool operator==(const stream_drop&, const stream_drop&) noexcept = default;
};

/// One item of a stream: a sentence, a frame of the recognizer F, or a drop report.
template <class F = no_frames>
struct stream_item {
  /// The 0xAB00 frame's bytes, for instance; an empty type for a reader without frames.
  using frame_bytes = typename detail::frame_parts<F>::bytes_type;
  /// What F decodes a frame to; an empty type for a reader without frames.
  using frame_value = typename detail::frame_parts<F>::value_type;

  stream_item_kind kind = stream_item_kind::sentence;
  /// Of the item's first byte ('$', '!' or a frame's sync), counted from 0 at construction or
  /// reset().
  std::uint64_t offset = 0;
  /// Line number of the item's first byte: line breaks before it, plus one (CR LF is one break;
  /// CR and LF inside frames are none). For a sentence, the same as sentence.line.
  std::uint64_t line = 1;
  /// kind == sentence: the line up to its line ending, the ending and the line number. The text
  /// is valid until the next call of next(), feed() or finish().
  nmea::framed_line sentence{};
  /// kind == frame: the frame's bytes as received (owned, unlike the sentence text).
  [[no_unique_address]] frame_bytes bytes{};
  /// kind == frame: the bytes decoded; value-initialized otherwise.
  [[no_unique_address]] frame_value frame{};
  /// kind == dropped: what was dropped and why.
  stream_drop drop{};

  [[nodiscard]] constexpr bool is_sentence() const noexcept {
    return kind == stream_item_kind::sentence;
  }
  [[nodiscard]] constexpr bool is_frame() const noexcept { return kind == stream_item_kind::frame; }
  [[nodiscard]] constexpr bool is_drop() const noexcept {
    return kind == stream_item_kind::dropped;
  }

  friend constexpr bool operator==(const stream_item&, const stream_item&) noexcept = default;
};

/// What a stream_reader has seen. Items, rejected frames and dropped lines are counted once;
/// bytes as docs/streams.md's accounting rule says.
struct stream_stats {
  std::uint64_t sentences = 0;          ///< sentences yielded
  std::uint64_t frames = 0;             ///< frames yielded
  std::uint64_t noise_bytes = 0;        ///< bytes outside any item (not counting CR, LF)
  std::uint64_t bad_crc_frames = 0;     ///< whole candidates that failed their check (CRC)
  std::uint64_t bad_length_frames = 0;  ///< sync and id followed by other header bytes
  std::uint64_t truncated_frames = 0;   ///< candidates (sync and id at least) cut by finish()
  std::uint64_t interrupted = 0;        ///< sentences without a complete checksum ended by a '$'
                                        ///< or a sync byte before their line ending
  std::uint64_t overlong = 0;           ///< sentences dropped for exceeding the capacity
  std::uint64_t invalid_bytes = 0;      ///< sentences dropped for a byte outside 0x20..0x7E
  std::uint64_t dropped_bytes = 0;      ///< bytes of dropped sentences + the sync byte of each
                                        ///< rejected candidate
  std::uint64_t line_break_bytes = 0;   ///< CR and LF bytes read as line breaks

  friend constexpr bool operator==(const stream_stats&, const stream_stats&) noexcept = default;
};

/// Byte stream -> NMEA sentences, and the binary frames of F unless F is no_frames, in fixed
/// memory: Capacity bytes for a sentence cut by a chunk boundary. Sans-I/O; never allocates;
/// noexcept throughout (the callback overloads are as noexcept as their callback).
template <std::size_t Capacity = 1024, class F = no_frames>
requires(std::same_as<F, no_frames> || frame_recognizer<F>) class stream_reader {
  static_assert(Capacity > 0, "a reader must hold at least the '$' or '!'");
  static_assert(Capacity < (std::size_t{1} << 48), "capacity + 1 must not overflow");

 public:
  static constexpr std::size_t capacity = Capacity;
  using item = stream_item<F>;
  using frame_bytes = typename item::frame_bytes;

  /// Hands over the next chunk. Precondition: next() has returned nullopt since the last feed()
  /// (the previous chunk is drained); the chunk must stay alive until it is.
  constexpr void feed(std::string_view chunk) noexcept {
    assert(drained() && "stream_reader::feed: previous chunk not drained by next()");
    assert(!ending_ && "stream_reader::feed: finish() not called until it returned nullopt");
    base_ += chunk_.size();
    chunk_ = chunk;
    pos_ = 0;
  }

  /// The same for raw bytes.
  void feed(std::span<const std::uint8_t> chunk) noexcept {
    feed(std::string_view(reinterpret_cast<const char*>(chunk.data()), chunk.size()));
  }

  /// Feeds `chunk` and drains it, calling on_item(const item&) for each item. The item is the
  /// reader's own, not a copy: valid during the call only. The cheapest way to read a stream.
  template <class Fn>
  constexpr void feed(std::string_view chunk,
                      Fn&& on_item) noexcept(std::is_nothrow_invocable_v<Fn&, const item&>) {
    feed(chunk);
    while (advance()) on_item(std::as_const(cur_));
  }

  template <class Fn>
  void feed(std::span<const std::uint8_t> chunk,
            Fn&& on_item) noexcept(std::is_nothrow_invocable_v<Fn&, const item&>) {
    feed(chunk);
    while (advance()) on_item(std::as_const(cur_));
  }

  /// The next item of the current chunk, or nullopt once the chunk is used up (or, after
  /// finish(), once the end of the stream is fully resolved). A copy of the reader's item: the
  /// callback overloads of feed() and finish() hand out the item itself, without the copy.
  [[nodiscard]] constexpr std::optional<item> next() noexcept {
    if (advance()) return cur_;
    return std::nullopt;
  }

  /// End of stream: call until it returns nullopt. Yields the sentence still waiting for its
  /// line ending (ending none, or cr), and whatever the bytes of a truncated candidate hold.
  /// Precondition: the current chunk is drained. Afterwards the reader sits between items with
  /// its counters and line number kept; reset() before reusing it for an unrelated stream.
  [[nodiscard]] constexpr std::optional<item> finish() noexcept {
    assert(pos_ == chunk_.size() && "stream_reader::finish: current chunk not drained by next()");
    ending_ = true;
    return next();
  }

  /// The link has gone quiet: yields a sentence whose CR was the last byte fed (held back to tell
  /// CR from CR LF) as ended by CR; an LF arriving next completes that line break. Nothing else
  /// is released. Precondition: the current chunk is drained.
  [[nodiscard]] constexpr std::optional<item> flush() noexcept {
    if (flush_held()) return cur_;
    return std::nullopt;
  }

  /// The same, calling on_item(const item&) with the sentence if there is one (the reader's own
  /// item, valid during the call only).
  template <class Fn>
  constexpr void flush(Fn&& on_item) noexcept(std::is_nothrow_invocable_v<Fn&, const item&>) {
    if (flush_held()) on_item(std::as_const(cur_));
  }

  /// Finishes, calling on_item(const item&) for each item the end of stream releases (the
  /// reader's own item, valid during the call only).
  template <class Fn>
  constexpr void finish(Fn&& on_item) noexcept(std::is_nothrow_invocable_v<Fn&, const item&>) {
    assert(pos_ == chunk_.size() && "stream_reader::finish: current chunk not drained by next()");
    ending_ = true;
    while (advance()) on_item(std::as_const(cur_));
  }

  [[nodiscard]] constexpr const stream_stats& stats() const noexcept { return stats_; }

  /// With `on`, next() and finish() also yield a dropped item for each run of bytes given up on,
  /// in stream order, once the run has ended (off by default). Keep it the same for a whole
  /// stream: a run open when it is turned off is not reported.
  constexpr void report_drops(bool on) noexcept { report_drops_ = on; }
  [[nodiscard]] constexpr bool reports_drops() const noexcept { return report_drops_; }

  /// Back to the freshly constructed state: no chunk, nothing pending, offset 0, line 1, zero
  /// stats. Keeps the report_drops() setting.
  constexpr void reset() noexcept {
    // Field by field: a whole new reader would put Capacity bytes on the stack.
    chunk_ = {};
    pos_ = 0;
    base_ = 0;
    line_ = 1;
    sentence_start_ = 0;
    frame_start_ = 0;
    llen_ = 0;
    stats_ = {};
    flen_ = 0;
    rpos_ = 0;
    rlen_ = 0;
    state_ = state::idle;
    prev_cr_ = false;
    ending_ = false;
    drop_open_ = false;
    dlen_ = 0;
    dsize_ = 0;
  }

 private:
  static constexpr bool has_frames = !std::same_as<F, no_frames>;
  enum class state : std::uint8_t {
    idle,      // between items
    sentence,  // lbuf_[0, llen_) is the start of a sentence cut by the end of its source
    held,      // lbuf_[0, llen_) is a complete line whose CR ended its source: CR or CR LF?
    discard,   // dropping the rest of an overlong or invalid line
    frame,     // fbuf_[0, flen_) is a frame candidate; its header so far is right
  };

  // The byte that starts a frame candidate; a sentence byte can never be it.
  static constexpr char sync = [] {
    if constexpr (has_frames)
      return static_cast<char>(F::header[0]);
    else
      return '$';
  }();
  static constexpr std::size_t frame_size = [] {
    if constexpr (has_frames)
      return F::size;
    else
      return std::size_t{1};
  }();
  static constexpr std::size_t replay_capacity = frame_size - 1;

  [[nodiscard]] constexpr bool drained() const noexcept {
    return pos_ == chunk_.size() && rpos_ == rlen_;
  }
  // Reads on until an item is in cur_ (true), or the chunk is used up (or, after finish(), the
  // end of the stream is resolved: false).
  [[nodiscard]] constexpr bool advance() noexcept {
    for (;;) {
      if (rpos_ < rlen_) {
        if (step(replay_.data(), rpos_, rlen_)) return true;
      } else if (pos_ < chunk_.size()) {
        if (step(chunk_.data(), pos_, chunk_.size())) return true;
      } else if (ending_) {
        if (end_of_stream()) return true;
        // A truncated candidate's bytes to read again, or a drop report to close.
        if (rpos_ < rlen_ || drop_open_) continue;
        ending_ = false;
        prev_cr_ = false;
        return false;
      } else {
        return false;
      }
    }
  }

  // flush(): the held sentence, if there is one, into cur_.
  [[nodiscard]] constexpr bool flush_held() noexcept {
    assert(drained() && "stream_reader::flush: current chunk not drained by next()");
    if (state_ != state::held) return false;
    state_ = state::idle;
    prev_cr_ = true;
    return yield_sentence(std::string_view(lbuf_, llen_), line_ending::cr);
  }

  // Stream offset of byte i of source s. Re-read bytes are always the ones just before the
  // unread part of the chunk, since they come from the candidate that ended there.
  [[nodiscard]] constexpr std::uint64_t offset_of(const char* s, std::size_t i) const noexcept {
    if (s == replay_.data()) return base_ + pos_ - (rlen_ - i);
    return base_ + i;
  }

  // Reads source s from i (a reference to rpos_ or pos_) until an item, a change of state or
  // the end of s.
  constexpr bool step(const char* s, std::size_t& i, std::size_t end) noexcept {
    switch (state_) {
      case state::held: {
        line_ending e = line_ending::cr;
        if (s[i] == '\n') {
          e = line_ending::crlf;
          ++stats_.line_break_bytes;
          ++i;
        }
        state_ = state::idle;
        return yield_sentence(std::string_view(lbuf_, llen_), e);
      }
      case state::idle: return idle(s, i, end);
      case state::sentence: return scan_sentence(s, i, end, llen_);
      case state::discard:
        // Cold (only after an error), so byte by byte. A '!' here is dropped: it starts nothing.
        for (; i < end; ++i) {
          const char c = s[i];
          if (c == '$' || c == sync || c == '\r' || c == '\n') {
            state_ = state::idle;  // idle starts the item or counts the line break
            return close_drop();
          }
          ++stats_.dropped_bytes;
          add_drop(s + i, 1);
        }
        return false;
      case state::frame:
        if constexpr (has_frames) return scan_frame(s, i, end);
        break;
    }
    return false;
  }

  // Between items. Real links send items back to back, so this loop mostly sees one byte.
  constexpr bool idle(const char* s, std::size_t& i, std::size_t end) noexcept {
    for (; i < end; ++i) {
      const char c = s[i];
      if (c == '$' || c == '!') {
        if (drop_open_) return close_drop();  // the noise before it; the start is read again
        prev_cr_ = false;
        return scan_sentence(s, i, end, 0);
      }
      if constexpr (has_frames) {
        if (c == sync) {  // an open noise run stays open: a lone sync is noise too (scan_frame)
          prev_cr_ = false;
          frame_start_ = offset_of(s, i);
          fbuf_[0] = F::header[0];
          flen_ = 1;
          state_ = state::frame;
          ++i;
          return scan_frame(s, i, end);
        }
      }
      if (c == '\r' || c == '\n') {
        if (drop_open_) return close_drop();
        ++stats_.line_break_bytes;
        if (c == '\r' || !prev_cr_) ++line_;
        prev_cr_ = c == '\r';
      } else {
        ++stats_.noise_bytes;
        prev_cr_ = false;
        if (!drop_open_) open_drop(drop_reason::noise, offset_of(s, i));
        add_drop(s + i, 1);
      }
    }
    return false;
  }

  // The sentence going on at i; `have` of its bytes are already in lbuf_ (0: it starts with the
  // '$' or '!' at i). Yields the line if it ends in this source, else stashes or drops it.
  constexpr bool scan_sentence(const char* s, std::size_t& i, std::size_t end,
                               std::size_t have) noexcept {
    using scan = detail::framer_scan;
    const std::size_t start = i;
    if (have == 0) sentence_start_ = offset_of(s, start);
    // Look no further than one byte past the capacity: that byte decides "overlong".
    const std::size_t room = Capacity + 1 - have;
    const std::size_t limit = end - start > room ? start + room : end;
    // find_special stops at a frame's sync byte too: it is outside 0x20..0x7E.
    const std::size_t q = scan::find_special(s, have == 0 ? start + 1 : start, limit);
    const std::size_t n = have + (q - start);  // sentence bytes before q
    if (q == limit) {
      if (n > Capacity) {
        ++stats_.overlong;
        stats_.dropped_bytes += n;
        sentence_drop(drop_reason::overlong, s, start, q, have);
        i = q;
        state_ = state::discard;
      } else {  // q == end: the sentence goes on in the next source
        stash(s, start, q, have);
        i = end;
        state_ = state::sentence;
      }
      return false;
    }
    const char c = s[q];
    if (c == '\r') {
      ++stats_.line_break_bytes;
      if (q + 1 == end) {
        stash(s, start, q, have);
        i = end;
        state_ = state::held;
        return false;
      }
      state_ = state::idle;
      if (s[q + 1] == '\n') {
        ++stats_.line_break_bytes;
        i = q + 2;
        return yield_sentence(text(s, start, q, have), line_ending::crlf);
      }
      i = q + 1;
      return yield_sentence(text(s, start, q, have), line_ending::cr);
    }
    if (c == '\n') {
      ++stats_.line_break_bytes;
      state_ = state::idle;
      i = q + 1;
      return yield_sentence(text(s, start, q, have), line_ending::lf);
    }
    if (c == '$' || c == sync) {  // a new item starts at q (a '!' is text: find_special passed it)
      state_ = state::idle;
      i = q;
      // A sentence whose "*hh" checksum is complete lacks only its line ending: nothing is
      // missing, so it is yielded (ending none) and the new item read from q. Any other sentence
      // may have lost its tail: it is dropped.
      if (ends_in_checksum(s, start, q, have))
        return yield_sentence(text(s, start, q, have), line_ending::none);
      ++stats_.interrupted;
      stats_.dropped_bytes += n;
      sentence_drop(drop_reason::interrupted, s, start, q, have);
      return close_drop();
    }
    ++stats_.invalid_bytes;
    stats_.dropped_bytes += n + 1;
    sentence_drop(drop_reason::invalid_byte, s, start, q + 1, have);
    i = q + 1;
    state_ = state::discard;
    return false;
  }

  // The candidate in fbuf_[0, flen_) takes bytes from i.
  constexpr bool scan_frame(const char* s, std::size_t& i, std::size_t end) noexcept {
    // The header is checked byte by byte, so a false sync is given up at the first byte that
    // betrays it, without waiting for what a length field promises.
    constexpr auto header = F::header;
    for (; flen_ < header.size() && i < end; ++i) {
      const auto b = static_cast<std::uint8_t>(s[i]);
      if (b != header[flen_]) return reject_header(b);  // s[i] is read again from the idle state
      fbuf_[flen_++] = b;
      if (flen_ == 2 && drop_open_) {  // sync and id: a candidate, so the noise before it ends
        ++i;
        return close_drop();
      }
    }
    const std::size_t n = std::min(frame_size - flen_, end - i);
    if (std::is_constant_evaluated()) {
      for (std::size_t k = 0; k < n; ++k) fbuf_[flen_ + k] = static_cast<std::uint8_t>(s[i + k]);
    } else if (n != 0) {
      std::memcpy(fbuf_.data() + flen_, s + i, n);  // the frame's body, most of it in one go
    }
    i += n;
    flen_ += n;
    if (flen_ < frame_size) return false;

    state_ = state::idle;
    const result<typename F::value_type> r = F::decode(fbuf_);
    if (r) {
      ++stats_.frames;
      item& out = make_item(stream_item_kind::frame, frame_start_, line_);
      out.bytes = fbuf_;
      out.frame = r.value;
      return true;
    }
    ++stats_.bad_crc_frames;
    const bool drop = candidate_drop(drop_reason::bad_crc, 1, flen_);
    read_again();
    return drop;
  }

  // The sync then not the id is a lone noise byte. Sync and id then a wrong header byte is a bad
  // length: the sync is dropped and the other header bytes so far are noise (read again, they
  // would be nothing else: frame_recognizer allows no byte in a header that starts an item or
  // breaks a line). A lone sync joins the noise run before it (or starts one); a bad length is a
  // report of its own, showing the header so far and the byte that broke it (`broke`, which is
  // read again).
  constexpr bool reject_header(std::uint8_t broke) noexcept {
    bool drop = false;
    if (flen_ == 1) {
      lone_sync();
    } else {
      ++stats_.bad_length_frames;
      ++stats_.dropped_bytes;
      stats_.noise_bytes += flen_ - 1;
      fbuf_[flen_] = broke;  // shown only: flen_ stays the header's length
      drop = candidate_drop(drop_reason::bad_length, flen_, flen_ + 1);
    }
    flen_ = 0;
    state_ = state::idle;
    return drop;
  }

  // A sync byte that turned out to start no frame: one noise byte, in the noise run it follows.
  constexpr void lone_sync() noexcept {
    ++stats_.noise_bytes;
    if (!drop_open_) open_drop(drop_reason::noise, frame_start_);
    add_drop(&sync, 1);
    flen_ = 0;
  }

  // ---- drop reports (cold) ----

  // Starts a report, when reports are wanted.
  constexpr void open_drop(drop_reason why, std::uint64_t offset) noexcept {
    if (!report_drops_) return;
    drop_open_ = true;
    dreason_ = why;
    doffset_ = offset;
    dline_ = line_;
    dsize_ = 0;
    dlen_ = 0;
  }

  // n more bytes of the open report (nothing when none is open): counted, and kept while the
  // report shows fewer than max_shown.
  constexpr void add_drop(const char* p, std::size_t n) noexcept {
    if (!drop_open_) return;
    dsize_ += n;
    const std::size_t keep = std::min(n, stream_drop::max_shown - dlen_);
    std::copy_n(p, keep, dbuf_ + dlen_);
    dlen_ += keep;
  }

  // A report on the sentence being collected: lbuf_[0, have) then s[from, to).
  constexpr void sentence_drop(drop_reason why, const char* s, std::size_t from, std::size_t to,
                               std::size_t have) noexcept {
    open_drop(why, sentence_start_);
    add_drop(lbuf_, have);
    add_drop(s + from, to - from);
  }

  // The open report as the item (false when none is open).
  constexpr bool close_drop() noexcept {
    if (!drop_open_) return false;
    drop_open_ = false;
    if (!report_drops_) return false;  // turned off while the report was open
    item& out = make_item(stream_item_kind::dropped, doffset_, dline_);
    out.drop = stream_drop{dreason_, dsize_, std::string_view(dbuf_, dlen_)};
    return true;
  }

  // The candidate fbuf_[0, shown) as a report of `size` dropped bytes.
  constexpr bool candidate_drop(drop_reason why, std::size_t size, std::size_t shown) noexcept {
    open_drop(why, frame_start_);
    if (!drop_open_) return false;
    for (std::size_t k = 0; k < shown; ++k) dbuf_[k] = static_cast<char>(fbuf_[k]);
    dlen_ = shown;
    dsize_ = size;
    return close_drop();
  }

  // A rejected candidate: drop its sync byte and read fbuf_[1, flen_) again. They are followed in
  // the stream by the unread bytes of the chunk: a candidate only completes or is truncated once
  // every re-read byte before it is used up, which the assert checks.
  constexpr void read_again() noexcept {
    assert(rpos_ == rlen_ && flen_ >= 1 && flen_ - 1 <= replay_capacity);
    ++stats_.dropped_bytes;
    for (std::size_t k = 1; k < flen_; ++k) replay_[k - 1] = static_cast<char>(fbuf_[k]);
    rpos_ = 0;
    rlen_ = flen_ - 1;
    flen_ = 0;
    state_ = state::idle;
  }

  // Both sources are used up and finish() was called: resolve what is pending.
  constexpr bool end_of_stream() noexcept {
    const state was = state_;
    state_ = state::idle;
    switch (was) {
      case state::held: return yield_sentence(std::string_view(lbuf_, llen_), line_ending::cr);
      case state::sentence:
        return yield_sentence(std::string_view(lbuf_, llen_), line_ending::none);
      case state::frame:
        if constexpr (!has_frames) {
          break;
        } else if (flen_ == 1) {  // a lone sync: not even a frame id
          lone_sync();
          return false;  // the noise report closes on the next call
        } else {
          ++stats_.truncated_frames;
          const bool drop = candidate_drop(drop_reason::truncated_frame, 1, flen_);
          read_again();
          return drop;
        }
      case state::idle:
      case state::discard: return close_drop();
    }
    return false;
  }

  // The item cur_ as one of `kind`: its members of the other kinds back to their defaults (only
  // where an item of another kind has set them, so a run of sentences rewrites just what a
  // sentence holds); the caller sets those of `kind`.
  constexpr item& make_item(stream_item_kind kind, std::uint64_t offset,
                            std::uint64_t line) noexcept {
    if (kind != stream_item_kind::sentence && cur_holds_sentence_) cur_.sentence = {};
    if (kind != stream_item_kind::frame && cur_holds_frame_) {
      cur_.bytes = {};
      cur_.frame = {};
    }
    if (kind != stream_item_kind::dropped && cur_holds_drop_) cur_.drop = {};
    cur_holds_sentence_ = kind == stream_item_kind::sentence;
    cur_holds_frame_ = kind == stream_item_kind::frame;
    cur_holds_drop_ = kind == stream_item_kind::dropped;
    cur_.kind = kind;
    cur_.offset = offset;
    cur_.line = line;
    return cur_;
  }

  constexpr bool yield_sentence(std::string_view line_text, line_ending e) noexcept {
    ++stats_.sentences;
    make_item(stream_item_kind::sentence, sentence_start_, line_).sentence =
        framed_line{line_text, e, line_};
    if (e != line_ending::none) ++line_;
    return true;
  }

  constexpr void stash(const char* s, std::size_t from, std::size_t to, std::size_t have) noexcept {
    std::copy_n(s + from, to - from, lbuf_ + have);
    llen_ = have + (to - from);
  }

  // Whether the sentence lbuf_[0, have) + s[from, to) ends in '*' and two hex digits.
  [[nodiscard]] constexpr bool ends_in_checksum(const char* s, std::size_t from, std::size_t to,
                                                std::size_t have) const noexcept {
    const std::size_t in_s = to - from;
    if (have + in_s < 5) return false;      // at least the start character, an address byte, "*hh"
    const auto back = [&](std::size_t k) {  // the k-th byte from the end, k = 1 the last
      return k <= in_s ? s[to - k] : lbuf_[have - (k - in_s)];
    };
    return back(3) == '*' && seawire::detail::hex_value(back(2)) >= 0 &&
           seawire::detail::hex_value(back(1)) >= 0;
  }

  // The finished sentence: a view into the source when it lies wholly there, else the buffer.
  constexpr std::string_view text(const char* s, std::size_t from, std::size_t to,
                                  std::size_t have) noexcept {
    if (have == 0) return std::string_view(s + from, to - from);
    stash(s, from, to, have);
    return std::string_view(lbuf_, llen_);
  }

  std::string_view chunk_{};
  std::size_t pos_ = 0;               // next unread byte of chunk_
  std::uint64_t base_ = 0;            // stream offset of chunk_[0]
  std::uint64_t line_ = 1;            // number of the line being read
  std::uint64_t sentence_start_ = 0;  // stream offset of the sentence being collected
  std::uint64_t frame_start_ = 0;     // stream offset of the candidate being collected
  std::size_t llen_ = 0;              // bytes in lbuf_ (state sentence or held)
  stream_stats stats_{};
  std::size_t flen_ = 0;  // bytes in fbuf_ (state frame)
  std::size_t rpos_ = 0;  // next byte of replay_ to read
  std::size_t rlen_ = 0;  // bytes in replay_
  state state_ = state::idle;
  bool prev_cr_ = false;  // the last byte read between items was a CR: an LF now ends no line
  bool ending_ = false;   // finish() was called: resolve what is pending at the end of input
  bool report_drops_ = false;
  bool drop_open_ = false;  // a drop report is collecting bytes: the d* members
  drop_reason dreason_ = drop_reason::noise;
  std::uint64_t doffset_ = 0;  // stream offset of its first byte
  std::uint64_t dline_ = 1;    // line of its first byte
  std::uint64_t dsize_ = 0;    // bytes dropped so far
  std::size_t dlen_ = 0;       // bytes of it kept in dbuf_
  char dbuf_[stream_drop::max_shown]{};
  std::array<std::uint8_t, frame_size> fbuf_{};  // the candidate (state frame)
  std::array<char, replay_capacity> replay_{};   // its bytes after the sync, to read again
  char lbuf_[Capacity]{};
  // The item handed out last: the callbacks get it, next() a copy of it.
  item cur_{};
  bool cur_holds_sentence_ = false;  // cur_.sentence is not the default
  bool cur_holds_frame_ = false;     // cur_.bytes and cur_.frame are not the defaults
  bool cur_holds_drop_ = false;      // cur_.drop is not the default
};

}  // namespace seawire::nmea
