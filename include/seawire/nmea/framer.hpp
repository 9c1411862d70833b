// SPDX-License-Identifier: BSL-1.0
#pragma once
// nmea::framer: cuts a byte stream (TCP, serial, a log file) into complete candidate sentences.
//
// Contract, in the order a byte meets it:
// - A sentence starts at '$', or at '!' (NMEA 0183 encapsulation sentences: !AIVDM, !AIVDO).
//   Bytes outside a sentence are noise; CR and LF are line breaks, not noise. A line ends at LF,
//   CR, or CR LF (one ending, one line).
// - A '$' inside a sentence abandons the partial one (interrupted) and starts anew at that '$'.
//   A '!' inside a sentence is text: it starts a sentence only where a '$' would start one
//   without interrupting anything (between sentences, in noise), so a text field holding '!'
//   ("Mission done!") is never cut.
// - A sentence is dropped, and everything up to its line ending or the next '$' discarded, on the
//   first of: a byte outside 0x20..0x7E (invalid_bytes), or a byte past `Capacity` (overlong).
//   A '!' in the discarded rest is discarded with it: it does not end the discard.
// - Nothing else is checked: checksum and fields are sentence_view's business.
// - A line lying wholly inside the chunk being read is yielded as a view into that chunk. Only a
//   line cut by a chunk boundary -- or one whose CR is the chunk's last byte, since the next chunk
//   decides between CR and CR LF -- is copied into the fixed buffer. Memory never grows.
// - Stats account for every byte: fed = yielded text + noise_bytes + dropped_bytes + CR/LF bytes.
//
// Use: feed(chunk), then next() until nullopt, then the next chunk; finish() at end of stream.

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "seawire/detail/byte_order.hpp"

namespace seawire::nmea {

/// What ended a framed line.
enum class line_ending : std::uint8_t {
  none,  ///< nothing: the stream ended (only from finish())
  lf,    ///< "\n"
  cr,    ///< "\r" not followed by "\n"
  crlf,  ///< "\r\n"
};

/// One candidate sentence, from its '$' or '!' up to (not including) its line ending.
struct framed_line {
  /// Valid until the next call of next(), feed() or finish() on the framer that made it.
  std::string_view text;
  line_ending ending = line_ending::none;
  /// 1-based: line endings seen before this line, plus one.
  std::uint64_t line = 0;

  friend constexpr bool operator==(const framed_line&, const framed_line&) noexcept = default;
};

/// What a framer has seen. Every byte fed lands in exactly one bucket: a yielded line's text,
/// noise_bytes, dropped_bytes, or a CR/LF.
struct framer_stats {
  std::uint64_t sentences = 0;      ///< lines yielded
  std::uint64_t noise_bytes = 0;    ///< bytes outside any sentence (not counting CR, LF)
  std::uint64_t interrupted = 0;    ///< partial sentences abandoned for a new '$' (not '!')
  std::uint64_t overlong = 0;       ///< lines dropped for exceeding the capacity
  std::uint64_t invalid_bytes = 0;  ///< lines dropped for a byte outside 0x20..0x7E
  std::uint64_t dropped_bytes = 0;  ///< bytes of all dropped lines, without their line endings

  friend constexpr bool operator==(const framer_stats&, const framer_stats&) noexcept = default;
};

namespace detail {

// The scans behind the hot path. A sentence byte needs one decision (plain text or not), so it is
// made for 16 bytes at once with SSE2 where x86 guarantees it, else 8 at once in a 64-bit word
// (also the constexpr path). Both only narrow the search; a byte loop names the exact byte.
// Inside a sentence only '$' is special ('!' is text); between sentences both start one.
struct framer_scan {
  static constexpr std::uint64_t ones = 0x0101010101010101U;
  static constexpr std::uint64_t highs = 0x8080808080808080U;

  // Nonzero iff some byte of v is below n (n <= 0x80). Borrows may flag bytes above the first
  // hit, never below it, so "any" is exact; the byte loop then finds which one.
  [[nodiscard]] static constexpr std::uint64_t any_below(std::uint64_t v, unsigned n) noexcept {
    return (v - ones * n) & ~v & highs;
  }

  [[nodiscard]] static constexpr std::uint64_t any_equal(std::uint64_t v,
                                                         unsigned char c) noexcept {
    return any_below(v ^ (ones * c), 1);
  }

  [[nodiscard]] static constexpr bool is_plain(char c) noexcept {
    const auto u = static_cast<unsigned char>(c);
    return u >= 0x20 && u <= 0x7E && u != '$';
  }

  [[nodiscard]] static constexpr bool is_break(char c) noexcept {
    return c == '$' || c == '\r' || c == '\n';
  }

  [[nodiscard]] static constexpr bool is_start(char c) noexcept { return c == '$' || c == '!'; }

  // The three searches below: for each, which bytes it stops at, told for one byte, for eight
  // in a word (nonzero when one of them is such a byte; borrows may flag bytes above the
  // first hit, never below), and for sixteen SSE2 lanes.
  struct special_bytes {  // not printable ASCII, or '$'
    [[nodiscard]] static constexpr bool byte(char c) noexcept { return !is_plain(c); }
    [[nodiscard]] static constexpr std::uint64_t word(std::uint64_t v) noexcept {
      return any_below(v, 0x20) | (v & highs) | any_equal(v, 0x7F) | any_equal(v, '$');
    }
#if defined(__SSE2__)
    // Signed compare: "below 0x20" also catches 0x80..0xFF, which are negative.
    [[nodiscard]] static __m128i lanes(__m128i v) noexcept {
      return _mm_or_si128(_mm_cmplt_epi8(v, _mm_set1_epi8(0x20)),
                          _mm_or_si128(_mm_cmpeq_epi8(v, _mm_set1_epi8(0x7F)),
                                       _mm_cmpeq_epi8(v, _mm_set1_epi8('$'))));
    }
#endif
  };
  struct break_bytes {  // '$', CR, LF
    [[nodiscard]] static constexpr bool byte(char c) noexcept { return is_break(c); }
    [[nodiscard]] static constexpr std::uint64_t word(std::uint64_t v) noexcept {
      return any_equal(v, '$') | any_equal(v, '\r') | any_equal(v, '\n');
    }
#if defined(__SSE2__)
    [[nodiscard]] static __m128i lanes(__m128i v) noexcept {
      return _mm_or_si128(_mm_cmpeq_epi8(v, _mm_set1_epi8('$')),
                          _mm_or_si128(_mm_cmpeq_epi8(v, _mm_set1_epi8('\r')),
                                       _mm_cmpeq_epi8(v, _mm_set1_epi8('\n'))));
    }
#endif
  };
  struct start_bytes {  // '$', '!'
    [[nodiscard]] static constexpr bool byte(char c) noexcept { return is_start(c); }
    [[nodiscard]] static constexpr std::uint64_t word(std::uint64_t v) noexcept {
      return any_equal(v, '$') | any_equal(v, '!');
    }
#if defined(__SSE2__)
    [[nodiscard]] static __m128i lanes(__m128i v) noexcept {
      return _mm_or_si128(_mm_cmpeq_epi8(v, _mm_set1_epi8('$')),
                          _mm_cmpeq_epi8(v, _mm_set1_epi8('!')));
    }
#endif
  };

  /// First index in [from, to) whose byte Bytes stops at; `to` if none.
  template <class Bytes>
  [[nodiscard]] static constexpr std::size_t find_first(const char* s, std::size_t from,
                                                        std::size_t to) noexcept {
    std::size_t i = from;
#if defined(__SSE2__)
    if (!std::is_constant_evaluated()) {
      for (; to - i >= 16; i += 16) {
        const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(s + i));
        const auto mask = static_cast<unsigned>(_mm_movemask_epi8(Bytes::lanes(v)));
        if (mask != 0) return i + static_cast<std::size_t>(std::countr_zero(mask));
      }
    }
#endif
    for (; to - i >= 8; i += 8)
      if (Bytes::word(seawire::detail::load_le64(s + i)) != 0) break;
    while (i < to && !Bytes::byte(s[i])) ++i;
    return i;
  }

  /// First index in [from, to) whose byte is not printable ASCII or is '$'; `to` if none.
  [[nodiscard]] static constexpr std::size_t find_special(const char* s, std::size_t from,
                                                          std::size_t to) noexcept {
    return find_first<special_bytes>(s, from, to);
  }
  /// First index in [from, to) holding '$', CR or LF; `to` if none.
  [[nodiscard]] static constexpr std::size_t find_break(const char* s, std::size_t from,
                                                        std::size_t to) noexcept {
    return find_first<break_bytes>(s, from, to);
  }
  /// First index in [from, to) holding '$' or '!' (a sentence's start); `to` if none.
  [[nodiscard]] static constexpr std::size_t find_start(const char* s, std::size_t from,
                                                        std::size_t to) noexcept {
    return find_first<start_bytes>(s, from, to);
  }
};

}  // namespace detail

/// Byte stream -> candidate sentences, in fixed memory: `Capacity` bytes of buffer plus a few
/// counters. Sans-I/O; never allocates; usable in constant expressions; noexcept throughout (the
/// callback feed() is as noexcept as its callback).
template <std::size_t Capacity = 1024>
class framer {
  static_assert(Capacity > 0, "a framer must hold at least the '$' or '!'");
  static_assert(Capacity < (std::size_t{1} << 48), "capacity + 1 must not overflow");

 public:
  static constexpr std::size_t capacity = Capacity;

  /// Hands over the next chunk. Precondition: next() has returned nullopt since the last feed(),
  /// i.e. the previous chunk is drained; the chunk must stay alive until it is.
  constexpr void feed(std::string_view chunk) noexcept {
    assert(pos_ == chunk_.size() && "framer::feed: previous chunk not drained by next()");
    chunk_ = chunk;
    pos_ = 0;
  }

  /// Feeds `chunk` and drains it, calling on_line(const framed_line&) for each line.
  template <class F>
  constexpr void feed(std::string_view chunk,
                      F&& on_line) noexcept(std::is_nothrow_invocable_v<F&, const framed_line&>) {
    feed(chunk);
    while (const std::optional<framed_line> l = next()) on_line(*l);
  }

  /// The next complete line of the current chunk, or nullopt once the chunk is used up.
  [[nodiscard]] constexpr std::optional<framed_line> next() noexcept {
    using scan = detail::framer_scan;
    const char* const s = chunk_.data();
    const std::size_t end = chunk_.size();
    while (pos_ < end) {
      switch (state_) {
        case state::held: {
          // The CR that ended the last chunk: only now can CR be told from CR LF.
          line_ending e = line_ending::cr;
          if (s[pos_] == '\n') {
            e = line_ending::crlf;
            ++pos_;
          }
          state_ = state::idle;
          return yield(std::string_view(buf_, len_), e);
        }
        case state::idle: {
          if (after_cr_) {
            after_cr_ = false;
            if (s[pos_] == '\n') {  // second half of a CR LF split by the chunk boundary
              ++pos_;
              continue;
            }
          }
          // Back-to-back sentences are the common case: skip the search when the start ('$' or
          // '!') is right here.
          const std::size_t stop =
              scan::is_start(s[pos_]) ? pos_ : scan::find_start(s, pos_ + 1, end);
          if (stop != pos_) count_noise(s, stop, end);
          if (stop == end) return std::nullopt;
          if (auto l = scan_sentence(s, end, 0)) return l;
          break;
        }
        case state::sentence:
          if (auto l = scan_sentence(s, end, len_)) return l;
          break;
        case state::discard: {
          const std::size_t q = scan::find_break(s, pos_, end);
          stats_.dropped_bytes += q - pos_;
          pos_ = q;
          if (q == end) return std::nullopt;
          state_ = state::idle;
          if (s[q] != '$') consume_ending(s, end);
          break;
        }
      }
    }
    return std::nullopt;
  }

  /// The link has gone quiet (a read timed out, a live stream paused): a sentence whose CR was
  /// the last byte fed, held back to tell CR from CR LF, is yielded now, as ended by CR; an LF
  /// that arrives next completes that line break (it counts no new line). A sentence without
  /// its line ending keeps waiting (finish() ends it). So a sender that ends lines with CR alone
  /// is not one sentence late. Precondition: the current chunk is drained.
  [[nodiscard]] constexpr std::optional<framed_line> flush() noexcept {
    assert(pos_ == chunk_.size() && "framer::flush: current chunk not drained by next()");
    if (state_ != state::held) return std::nullopt;
    state_ = state::idle;
    after_cr_ = true;
    return yield(std::string_view(buf_, len_), line_ending::cr);
  }

  /// End of stream: the sentence still waiting for its line ending, if any, once. Precondition:
  /// the current chunk is drained. Afterwards the framer sits at a line start; reset() before
  /// reusing it for an unrelated stream.
  [[nodiscard]] constexpr std::optional<framed_line> finish() noexcept {
    assert(pos_ == chunk_.size() && "framer::finish: current chunk not drained by next()");
    const state was = state_;
    state_ = state::idle;
    after_cr_ = false;
    switch (was) {
      case state::held: return yield(std::string_view(buf_, len_), line_ending::cr);
      case state::sentence: return yield(std::string_view(buf_, len_), line_ending::none);
      case state::idle:
      case state::discard: break;
    }
    return std::nullopt;
  }

  [[nodiscard]] constexpr const framer_stats& stats() const noexcept { return stats_; }

  /// Back to the freshly constructed state: no chunk, no partial line, line 1, zero stats.
  constexpr void reset() noexcept {
    chunk_ = {};
    pos_ = 0;
    len_ = 0;
    line_ = 1;
    stats_ = {};
    state_ = state::idle;
    after_cr_ = false;
  }

 private:
  enum class state : std::uint8_t {
    idle,      // between sentences: bytes are noise until a '$' or '!'
    sentence,  // buf_[0, len_) is the start of a sentence cut by the chunk boundary
    discard,   // dropping the rest of an overlong or invalid line
    held,      // buf_[0, len_) is a complete line whose CR ended the previous chunk
  };

  constexpr framed_line yield(std::string_view text, line_ending e) noexcept {
    ++stats_.sentences;
    const framed_line l{text, e, line_};
    if (e != line_ending::none) ++line_;
    return l;
  }

  // Noise in [pos_, stop): cold path (real streams have none between sentences), byte by byte.
  constexpr void count_noise(const char* s, std::size_t stop, std::size_t end) noexcept {
    bool prev_cr = false;
    for (std::size_t i = pos_; i < stop; ++i) {
      const char c = s[i];
      if (c == '\n') {
        if (!prev_cr) ++line_;
        prev_cr = false;
      } else if (c == '\r') {
        ++line_;
        prev_cr = true;
      } else {
        ++stats_.noise_bytes;
        prev_cr = false;
      }
    }
    after_cr_ = prev_cr && stop == end;
    pos_ = stop;
  }

  // The CR or LF at pos_ ends a line that yields nothing.
  constexpr void consume_ending(const char* s, std::size_t end) noexcept {
    ++line_;
    if (s[pos_++] != '\r') return;
    if (pos_ == end) {
      after_cr_ = true;
    } else if (s[pos_] == '\n') {
      ++pos_;
    }
  }

  // Scans the sentence going on at pos_; `have` of its bytes are already in buf_ (0: it starts
  // with the '$' or '!' at pos_). Yields the line if it ends in this chunk, else stashes or drops
  // it.
  constexpr std::optional<framed_line> scan_sentence(const char* s, std::size_t end,
                                                     std::size_t have) noexcept {
    using scan = detail::framer_scan;
    const std::size_t start = pos_;
    // Look no further than one byte past the capacity: that byte decides "overlong".
    const std::size_t room = Capacity + 1 - have;
    const std::size_t limit = end - start > room ? start + room : end;
    const std::size_t q = scan::find_special(s, have == 0 ? start + 1 : start, limit);
    const std::size_t n = have + (q - start);  // sentence bytes before q
    if (q == limit) {
      if (n > Capacity) {
        ++stats_.overlong;
        stats_.dropped_bytes += n;
        pos_ = q;
        state_ = state::discard;
      } else {  // q == end: the sentence goes on in the next chunk
        stash(s, start, q, have);
        pos_ = end;
        state_ = state::sentence;
      }
      return std::nullopt;
    }
    switch (s[q]) {
      case '\r':
        if (q + 1 == end) {
          stash(s, start, q, have);
          pos_ = end;
          state_ = state::held;
          return std::nullopt;
        }
        state_ = state::idle;
        if (s[q + 1] == '\n') {
          pos_ = q + 2;
          return yield(text(s, start, q, have), line_ending::crlf);
        }
        pos_ = q + 1;
        return yield(text(s, start, q, have), line_ending::cr);
      case '\n':
        state_ = state::idle;
        pos_ = q + 1;
        return yield(text(s, start, q, have), line_ending::lf);
      case '$':  // not '!': that is text here (find_special passes it)
        ++stats_.interrupted;
        stats_.dropped_bytes += n;
        pos_ = q;
        state_ = state::idle;
        return std::nullopt;
      default:
        ++stats_.invalid_bytes;
        stats_.dropped_bytes += n + 1;
        pos_ = q + 1;
        state_ = state::discard;
        return std::nullopt;
    }
  }

  constexpr void stash(const char* s, std::size_t from, std::size_t to, std::size_t have) noexcept {
    std::copy_n(s + from, to - from, buf_ + have);
    len_ = have + (to - from);
  }

  // The finished sentence: a view into the chunk when it lies wholly there, else the buffer.
  constexpr std::string_view text(const char* s, std::size_t from, std::size_t to,
                                  std::size_t have) noexcept {
    if (have == 0) return std::string_view(s + from, to - from);
    stash(s, from, to, have);
    return std::string_view(buf_, len_);
  }

  std::string_view chunk_{};
  std::size_t pos_ = 0;     // next unread byte of chunk_
  std::size_t len_ = 0;     // bytes in buf_ (state sentence or held)
  std::uint64_t line_ = 1;  // number of the line being read
  framer_stats stats_{};
  state state_ = state::idle;
  bool after_cr_ = false;  // the previous chunk ended in a CR that ended a line (no sentence)
  char buf_[Capacity]{};
};

}  // namespace seawire::nmea
