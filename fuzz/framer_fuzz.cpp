// SPDX-License-Identifier: BSL-1.0
// nmea::framer against a byte-at-a-time model of its contract (the comment atop framer.hpp),
// fed the stream whole, byte by byte, and in chunks whose sizes the fuzzer picks (including
// empty ones), at a small capacity (so overlong lines are common) and the default one.
// Properties:
//  - every chunking yields exactly the model's lines (text, ending, line number) and stats;
//  - every yielded line starts with '$' or '!' and holds no other '$', is printable ASCII and
//    fits the capacity ('!' starts a sentence only between sentences: inside one it is text);
//  - every byte fed is accounted for: text + noise + dropped + CR/LF bytes = bytes fed;
//  - valid data after hostile data still comes out: a good sentence appended after a line
//    break is the last line yielded, whatever came before it.
// Input: byte 0 seeds the chunk sizes, the rest is the stream.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_common.hpp"
#include "seawire/nmea/framer.hpp"

namespace {

using seawire::nmea::framed_line;
using seawire::nmea::framer;
using seawire::nmea::framer_stats;
using seawire::nmea::line_ending;

struct owned_line {
  std::string text;
  line_ending ending = line_ending::none;
  std::uint64_t line = 0;
  friend bool operator==(const owned_line&, const owned_line&) = default;
};

struct outcome {
  std::vector<owned_line> lines;
  framer_stats stats;
  friend bool operator==(const outcome&, const outcome&) = default;
};

// The contract, one byte at a time, written for clarity rather than speed.
class model {
 public:
  explicit model(std::size_t capacity) : capacity_(capacity) {}

  void put(char c) {
    if (pending_cr_) {
      pending_cr_ = false;
      if (held_) {  // a sentence ended by CR: CR LF or CR alone?
        held_ = false;
        if (c == '\n') {
          emit(line_ending::crlf);
          return;
        }
        emit(line_ending::cr);
      } else if (c == '\n') {  // the LF of a CR LF that ended a non-sentence line
        return;
      }
    }
    const auto u = static_cast<unsigned char>(c);
    switch (state_) {
      case state::idle:
        if (c == '$' || c == '!') {
          start(c);
        } else if (c == '\r' || c == '\n') {
          line_break(c);
        } else {
          ++out_.stats.noise_bytes;
        }
        break;
      case state::sentence:
        if (c == '$' && ends_in_checksum()) {  // only the line ending is missing
          emit(line_ending::none);
          start(c);
        } else if (c == '$') {  // a '!' is text here, below
          ++out_.stats.interrupted;
          out_.stats.dropped_bytes += buf_.size();
          start(c);
        } else if (c == '\r') {
          held_ = true;
          pending_cr_ = true;
          state_ = state::idle;
        } else if (c == '\n') {
          state_ = state::idle;
          emit(line_ending::lf);
        } else if (u < 0x20 || u > 0x7E) {
          ++out_.stats.invalid_bytes;
          out_.stats.dropped_bytes += buf_.size() + 1;
          state_ = state::discard;
        } else if (buf_.size() == capacity_) {
          ++out_.stats.overlong;
          out_.stats.dropped_bytes += buf_.size() + 1;
          state_ = state::discard;
        } else {
          buf_ += c;
        }
        break;
      case state::discard:
        if (c == '$') {  // a '!' is dropped here, below
          start(c);
        } else if (c == '\r' || c == '\n') {
          state_ = state::idle;
          line_break(c);
        } else {
          ++out_.stats.dropped_bytes;
        }
        break;
    }
  }

  outcome finish() {
    if (held_) {
      held_ = false;
      pending_cr_ = false;
      emit(line_ending::cr);
    } else if (state_ == state::sentence) {
      emit(line_ending::none);
    }
    return out_;
  }

 private:
  enum class state { idle, sentence, discard };

  [[nodiscard]] bool ends_in_checksum() const {
    const auto hex = [](char c) {
      return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f');
    };
    const std::size_t n = buf_.size();
    return n >= 5 && buf_[n - 3] == '*' && hex(buf_[n - 2]) && hex(buf_[n - 1]);
  }
  void start(char c) {
    buf_ = std::string(1, c);
    state_ = state::sentence;
  }
  void line_break(char c) {
    ++line_;
    pending_cr_ = c == '\r';
  }
  void emit(line_ending e) {
    out_.lines.push_back({buf_, e, line_});
    ++out_.stats.sentences;
    if (e != line_ending::none) ++line_;
    state_ = state::idle;
  }

  std::size_t capacity_;
  state state_ = state::idle;
  std::string buf_;
  bool pending_cr_ = false;  // the last byte was a CR that ended a line
  bool held_ = false;        // ... and that line was a sentence not yet emitted
  std::uint64_t line_ = 1;
  outcome out_;
};

template <std::size_t Capacity>
void drain(framer<Capacity>& f, outcome& out) {
  while (const std::optional<framed_line> l = f.next())
    out.lines.push_back({std::string(l->text), l->ending, l->line});
}

// Feeds `stream` cut at the sizes `next_size` gives, then finishes.
// With `flush`, the link goes quiet after every chunk (framer::flush()).
template <std::size_t Capacity, class NextSize>
outcome run(std::string_view stream, NextSize&& next_size, bool flush = false) {
  framer<Capacity> f;
  outcome out;
  std::size_t at = 0;
  while (at < stream.size()) {
    const std::size_t n = std::min(next_size(), stream.size() - at);
    f.feed(stream.substr(at, n));
    drain(f, out);
    if (flush) {
      if (const std::optional<framed_line> l = f.flush())
        out.lines.push_back({std::string(l->text), l->ending, l->line});
      SEAWIRE_FUZZ_CHECK(!f.flush().has_value(), "flush() yielded twice");
    }
    at += n;
  }
  f.feed(std::string_view{});  // an empty chunk is a chunk too
  drain(f, out);
  if (const std::optional<framed_line> l = f.finish())
    out.lines.push_back({std::string(l->text), l->ending, l->line});
  SEAWIRE_FUZZ_CHECK(!f.finish().has_value(), "finish() yielded twice");
  out.stats = f.stats();
  return out;
}

// Byte by byte is the slowest feed: it runs at the small capacity only, the chunked feed
// at both.
template <std::size_t Capacity>
void check_stream(std::string_view stream, std::uint8_t seed, bool bytewise_too) {
  model m(Capacity);
  for (const char c : stream) m.put(c);
  const outcome expected = m.finish();

  const outcome whole = run<Capacity>(stream, [&] { return stream.size(); });
  SEAWIRE_FUZZ_CHECK(whole == expected, "whole stream differs from the model", stream);
  if (bytewise_too) {
    const outcome bytewise = run<Capacity>(stream, [] { return std::size_t{1}; });
    SEAWIRE_FUZZ_CHECK(bytewise == expected, "byte-by-byte feed differs from the model", stream);
  }
  const outcome chunked = run<Capacity>(stream, seawire::fuzz::chunk_sizes(Capacity, seed));
  SEAWIRE_FUZZ_CHECK(chunked == expected, "chunked feed differs from the model", stream);
  // Quiet after every chunk: the same lines and stats, but that a sentence whose CR ended a
  // chunk is ended by CR even when an LF followed (and no line number moves).
  outcome flushed = run<Capacity>(stream, seawire::fuzz::chunk_sizes(Capacity, seed ^ 0x33U), true);
  for (std::size_t k = 0; k < flushed.lines.size() && k < expected.lines.size(); ++k) {
    if (flushed.lines[k].ending == line_ending::cr && expected.lines[k].ending == line_ending::crlf)
      flushed.lines[k].ending = line_ending::crlf;
  }
  SEAWIRE_FUZZ_CHECK(flushed == expected, "flush() changed more than a CR LF ending", stream);

  std::uint64_t text = 0;
  for (const owned_line& l : expected.lines) {
    SEAWIRE_FUZZ_CHECK(
        !l.text.empty() && (l.text[0] == '$' || l.text[0] == '!') && l.text.size() <= Capacity,
        l.text);
    SEAWIRE_FUZZ_CHECK(l.text.find('$', 1) == std::string::npos, l.text);
    for (const char c : l.text) SEAWIRE_FUZZ_CHECK(c >= 0x20 && c <= 0x7E, l.text);
    text += l.text.size();
  }
  std::uint64_t breaks = 0;
  for (const char c : stream) breaks += c == '\r' || c == '\n' ? 1 : 0;
  const framer_stats& s = expected.stats;
  SEAWIRE_FUZZ_CHECK(text + s.noise_bytes + s.dropped_bytes + breaks == stream.size(),
                     "bytes unaccounted for", stream);
  SEAWIRE_FUZZ_CHECK(s.sentences == expected.lines.size(), stream);
}

// A good sentence after whatever the fuzzer sent comes out, last, as it was sent.
template <std::size_t Capacity>
void check_recovery(std::string_view hostile) {
  constexpr std::string_view good =
      "$GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,M,"
      "-33.2,M,,*5C";
  static_assert(good.size() <= Capacity);
  std::string stream(hostile);
  stream += "\n";
  stream += good;
  stream += "\r\n";
  const outcome out = run<Capacity>(stream, [&] { return stream.size(); });
  SEAWIRE_FUZZ_CHECK(!out.lines.empty() && out.lines.back().text == good &&
                         out.lines.back().ending == line_ending::crlf,
                     "a good sentence after hostile bytes was lost", stream);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view stream = seawire::fuzz::as_text(data + 1, size - 1);
  check_stream<80>(stream, data[0], true);
  check_stream<1024>(stream, data[0], false);
  check_recovery<80>(stream);
  return 0;
}
