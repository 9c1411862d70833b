// SPDX-License-Identifier: BSL-1.0
// anello::stream_reader, the mixed NMEA + 0xAB00 binary stream, fed the stream whole, byte by
// byte and in chunks whose sizes the fuzzer picks (empty ones included), at a small capacity and
// the default one.
// Properties:
//  - every chunking yields the same items (kind, offset, text, ending, line, bytes) and stats;
//  - items come in stream order without overlapping, and each is the stream's own bytes at its
//    offset: a sentence is '$' or '!' + printable ASCII without '$' within the capacity, a
//    frame is 56 bytes that
//    decode_frame accepts and decodes to the item's frame;
//  - every byte fed is accounted for (the rule in stream.hpp's comment);
//  - with report_drops(true): the same items with drop reports between them, in stream order,
//    the same for every chunking; each report shows the stream's own bytes at its offset, there
//    is one per counted event, and their sizes add up to noise_bytes + dropped_bytes;
//  - flush() after every chunk changes nothing but the ending of a sentence whose CR ended a
//    chunk (CR instead of CR LF), not even a line number;
//  - valid data after hostile data still comes out: a good sentence and a good frame appended
//    after a line break are the last two items, whatever came before (unless the fuzzer built a
//    frame with a right CRC over the appended bytes themselves).
// Input: byte 0 seeds the chunk sizes, the rest is the stream. Byte runs "AB 00 00 30" followed
// by 52 bytes get their CRC fixed up (when byte 0 is odd), so the fuzzer reaches good frames.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_common.hpp"
#include "seawire/anello/frame.hpp"
#include "seawire/anello/stream.hpp"

namespace {

namespace anello = seawire::anello;
using seawire::fuzz::number;

struct owned_item {
  anello::stream_item_kind kind{};
  std::uint64_t offset = 0;
  std::string text;
  seawire::nmea::line_ending ending{};
  std::uint64_t line = 0;
  anello::frame_bytes bytes{};
  anello::sensor_frame_raw frame{};
  anello::drop_reason reason{};  // drops: text is what the report shows
  std::uint64_t size = 0;
  friend bool operator==(const owned_item&, const owned_item&) = default;
};

struct outcome {
  std::vector<owned_item> items;
  anello::stream_stats stats;
  friend bool operator==(const outcome&, const outcome&) = default;
};

owned_item own(const anello::stream_item& i) {
  // An item holds only its own kind's members, whatever kind of item came before it.
  SEAWIRE_FUZZ_CHECK(i.is_drop() || i.drop == anello::stream_drop{}, "a drop's members set");
  SEAWIRE_FUZZ_CHECK(
      i.is_frame() || (i.bytes == anello::frame_bytes{} && i.frame == anello::sensor_frame_raw{}),
      "a frame's members set");
  SEAWIRE_FUZZ_CHECK(i.is_sentence() || i.sentence == seawire::nmea::framed_line{},
                     "a sentence's members set");
  if (i.is_drop()) {
    return {i.kind,        i.offset,   std::string(i.drop.bytes), {}, i.line, {}, {},
            i.drop.reason, i.drop.size};
  }
  SEAWIRE_FUZZ_CHECK(!i.is_sentence() || i.sentence.line == i.line, "two line numbers differ");
  return {i.kind,  i.offset, std::string(i.sentence.text), i.sentence.ending, i.line,
          i.bytes, i.frame};
}

// The line each byte of the stream is on, counted independently of the reader from the frames
// it yielded: CR, LF and CR LF outside those frames are line breaks (a '$', an AB, a frame or
// any other byte between a CR and an LF makes them two).
std::vector<std::uint64_t> lines_of(std::string_view stream, const std::vector<owned_item>& items) {
  std::vector<bool> in_frame(stream.size(), false);
  for (const owned_item& i : items) {
    if (i.kind != anello::stream_item_kind::frame) continue;
    for (std::size_t k = 0; k < anello::frame_size; ++k) in_frame[i.offset + k] = true;
  }
  std::vector<std::uint64_t> line(stream.size() + 1, 1);
  std::uint64_t n = 1;
  bool prev_cr = false;
  for (std::size_t k = 0; k < stream.size(); ++k) {
    line[k] = n;
    const char c = stream[k];
    if (!in_frame[k] && (c == '\r' || (c == '\n' && !prev_cr))) ++n;
    prev_cr = !in_frame[k] && c == '\r';
  }
  line[stream.size()] = n;
  return line;
}

// Read through the callbacks (the reader's own item), or with pull = true through next()
// (copies): the same items either way.
template <std::size_t Capacity, class NextSize>
outcome run(std::string_view stream, NextSize&& next_size, bool drops = false, bool flush = false,
            bool pull = false) {
  anello::stream_reader<Capacity> reader;
  reader.report_drops(drops);
  outcome out;
  const auto take = [&](const anello::stream_item& i) { out.items.push_back(own(i)); };
  std::size_t at = 0;
  while (at < stream.size()) {
    const std::size_t n = std::min(next_size(), stream.size() - at);
    if (pull) {
      reader.feed(stream.substr(at, n));
      while (const std::optional<anello::stream_item> i = reader.next()) take(*i);
    } else {
      reader.feed(stream.substr(at, n), take);
    }
    if (flush && pull) {
      reader.flush(take);
      SEAWIRE_FUZZ_CHECK(!reader.flush().has_value(), "flush() yielded twice");
    } else if (flush) {
      if (const std::optional<anello::stream_item> i = reader.flush()) take(*i);
      SEAWIRE_FUZZ_CHECK(!reader.flush().has_value(), "flush() yielded twice");
    }
    at += n;
  }
  reader.feed(std::string_view{}, take);
  reader.finish(take);
  SEAWIRE_FUZZ_CHECK(!reader.finish().has_value(), "finish() yielded after nullopt");
  out.stats = reader.stats();
  return out;
}

// Byte by byte is the slowest feed: it runs at the small capacity only, the chunked feed
// at both.
template <std::size_t Capacity>
void check_stream(std::string_view stream, std::uint8_t seed, bool bytewise_too) {
  const outcome whole = run<Capacity>(stream, [&] { return stream.size(); });
  if (bytewise_too) {
    const outcome bytewise = run<Capacity>(stream, [] { return std::size_t{1}; });
    SEAWIRE_FUZZ_CHECK(bytewise == whole, "byte-by-byte feed differs from the whole stream",
                       stream);
  }
  const outcome chunked =
      run<Capacity>(stream, seawire::fuzz::chunk_sizes(Capacity, seed), false, false, true);
  SEAWIRE_FUZZ_CHECK(chunked == whole, "chunked feed differs from the whole stream", stream);

  std::uint64_t next_free = 0;
  std::uint64_t text = 0;
  std::uint64_t frames = 0;
  const std::vector<std::uint64_t> lines = lines_of(stream, whole.items);
  for (const owned_item& i : whole.items) {
    SEAWIRE_FUZZ_CHECK(i.offset >= next_free, "items overlap or go backwards", stream,
                       number(i.offset));
    SEAWIRE_FUZZ_CHECK(i.line == lines[i.offset], "an item's line number is wrong", stream,
                       number(i.offset), number(i.line));
    if (i.kind == anello::stream_item_kind::frame) {
      SEAWIRE_FUZZ_CHECK(i.offset + anello::frame_size <= stream.size(), stream);
      const std::string_view here = stream.substr(i.offset, anello::frame_size);
      SEAWIRE_FUZZ_CHECK(
          std::equal(here.begin(), here.end(), i.bytes.begin(),
                     [](char c, std::uint8_t b) { return static_cast<std::uint8_t>(c) == b; }),
          "a frame's bytes are not the stream's", stream);
      const seawire::result<anello::sensor_frame_raw> d = anello::decode_frame(i.bytes);
      SEAWIRE_FUZZ_CHECK(d.ok() && d.value == i.frame, "a yielded frame does not decode", stream);
      SEAWIRE_FUZZ_CHECK(i.text.empty(), stream);
      next_free = i.offset + anello::frame_size;
      ++frames;
    } else {
      SEAWIRE_FUZZ_CHECK(!i.text.empty() && (i.text[0] == '$' || i.text[0] == '!') &&
                             i.text.size() <= Capacity && i.text.find('$', 1) == std::string::npos,
                         i.text);
      for (const char c : i.text) SEAWIRE_FUZZ_CHECK(c >= 0x20 && c <= 0x7E, i.text);
      SEAWIRE_FUZZ_CHECK(stream.substr(i.offset, i.text.size()) == i.text,
                         "a sentence is not the stream's bytes", stream, i.text);
      next_free = i.offset + i.text.size();
      text += i.text.size();
    }
  }
  const anello::stream_stats& s = whole.stats;
  SEAWIRE_FUZZ_CHECK(s.frames == frames && s.sentences == whole.items.size() - frames, stream);
  SEAWIRE_FUZZ_CHECK(
      text + anello::frame_size * frames + s.noise_bytes + s.dropped_bytes + s.line_break_bytes ==
          stream.size(),
      "bytes unaccounted for", stream, number(text), number(frames), number(s.noise_bytes),
      number(s.dropped_bytes), number(s.line_break_bytes));
}

// The same stream with drop reports.
template <std::size_t Capacity>
void check_drops(std::string_view stream, std::uint8_t seed) {
  using anello::drop_reason;
  const outcome plain = run<Capacity>(stream, [&] { return stream.size(); });
  const outcome whole = run<Capacity>(
      stream, [&] { return stream.size(); }, true);
  const outcome chunked =
      run<Capacity>(stream, seawire::fuzz::chunk_sizes(Capacity, seed ^ 0x5AU), true, false, true);
  SEAWIRE_FUZZ_CHECK(chunked == whole, "drop reports depend on the chunking", stream);
  outcome filtered = whole;
  std::erase_if(filtered.items,
                [](const owned_item& i) { return i.kind == anello::stream_item_kind::dropped; });
  SEAWIRE_FUZZ_CHECK(filtered == plain, "reporting drops changed the items", stream);

  std::array<std::uint64_t, 7> by_reason{};
  std::uint64_t sizes = 0;
  std::uint64_t last = 0;
  bool first = true;
  const std::vector<std::uint64_t> lines = lines_of(stream, whole.items);
  for (const owned_item& i : whole.items) {
    SEAWIRE_FUZZ_CHECK(first || i.offset > last, "items out of stream order", stream,
                       number(i.offset));
    SEAWIRE_FUZZ_CHECK(i.line == lines[i.offset], "a report's line number is wrong", stream,
                       number(i.offset), number(i.line));
    first = false;
    last = i.offset;
    if (i.kind != anello::stream_item_kind::dropped) continue;
    SEAWIRE_FUZZ_CHECK(i.size >= 1 && !i.text.empty() &&
                           i.text.size() <= anello::stream_drop::max_shown &&
                           stream.substr(i.offset, i.text.size()) == i.text,
                       "a drop report does not show the stream's bytes", stream, i.text);
    const bool candidate = anello::stream_drop{i.reason}.of_frame();
    SEAWIRE_FUZZ_CHECK(candidate ? static_cast<std::uint8_t>(i.text[0]) == 0xAB
                                 : i.text.size() == std::min<std::uint64_t>(
                                                        i.size, anello::stream_drop::max_shown),
                       "a drop report shows the wrong bytes", stream, i.text);
    ++by_reason.at(static_cast<std::size_t>(i.reason));
    sizes += i.size;
  }
  const anello::stream_stats& s = whole.stats;
  SEAWIRE_FUZZ_CHECK(sizes == s.noise_bytes + s.dropped_bytes, "drop sizes unaccounted for", stream,
                     number(sizes));
  const auto count = [&](drop_reason r) { return by_reason[static_cast<std::size_t>(r)]; };
  SEAWIRE_FUZZ_CHECK(count(drop_reason::invalid_byte) == s.invalid_bytes &&
                         count(drop_reason::overlong) == s.overlong &&
                         count(drop_reason::interrupted) == s.interrupted &&
                         count(drop_reason::bad_crc) == s.bad_crc_frames &&
                         count(drop_reason::bad_length) == s.bad_length_frames &&
                         count(drop_reason::truncated_frame) == s.truncated_frames,
                     "not one drop report per counted event", stream);
}

// The link going quiet after every chunk (flush()): the same items and stats, but that a
// sentence whose CR ended a chunk comes out as ended by CR even when an LF followed.
template <std::size_t Capacity>
void check_flush(std::string_view stream, std::uint8_t seed) {
  using seawire::nmea::line_ending;
  const outcome whole = run<Capacity>(
      stream, [&] { return stream.size(); }, true);
  const outcome flushed =
      run<Capacity>(stream, seawire::fuzz::chunk_sizes(Capacity, seed ^ 0x33U), true, true,
                    (seed & 1U) != 0);  // flush() and flush(on_item) both
  SEAWIRE_FUZZ_CHECK(flushed.stats == whole.stats, "flush() changed the stats", stream);
  SEAWIRE_FUZZ_CHECK(flushed.items.size() == whole.items.size(), "flush() changed the items",
                     stream);
  for (std::size_t k = 0; k < whole.items.size(); ++k) {
    owned_item f = flushed.items[k];
    if (f.ending == line_ending::cr && whole.items[k].ending == line_ending::crlf)
      f.ending = line_ending::crlf;
    SEAWIRE_FUZZ_CHECK(f == whole.items[k], "flush() changed an item", stream, number(k));
  }
}

// The spec's example frame (valid CRC).
constexpr std::array<std::uint8_t, 56> seed_frame = {
    0xAB, 0x00, 0x00, 0x30, 0x8E, 0xF7, 0xF1, 0x76, 0x00, 0x59, 0x01, 0xF4, 0xEC, 0xFF,
    0xF9, 0x03, 0x36, 0x9A, 0x00, 0x00, 0xFF, 0xFF, 0x00, 0x00, 0x01, 0x90, 0x79, 0x43,
    0x63, 0xD0, 0x00, 0x00, 0x01, 0xE0, 0x7F, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x02, 0x00, 0x6C, 0x00, 0x03, 0x00, 0x5A, 0xFF, 0xFF, 0xFF, 0xFF};

void check_recovery(std::string_view hostile) {
  constexpr std::string_view good = "$VMVBW,0.0,0.0,A,0.0,0.0,A*58";
  std::string stream(hostile);
  stream += "\r\n";
  const std::size_t suffix = stream.size();
  stream += good;
  stream += "\r\n";
  for (const std::uint8_t b : seed_frame) stream += static_cast<char>(b);
  const outcome out = run<80>(stream, [&] { return stream.size(); });
  for (const owned_item& i : out.items) {
    // A frame the fuzzer built over the appended bytes, CRC and all, is a frame: nothing to say.
    if (i.kind == anello::stream_item_kind::frame && i.offset + anello::frame_size > suffix &&
        i.offset < suffix + good.size() + 2)
      return;
  }
  const std::size_t n = out.items.size();
  SEAWIRE_FUZZ_CHECK(n >= 2 && out.items[n - 2].text == good && out.items[n - 2].offset == suffix &&
                         out.items[n - 1].kind == anello::stream_item_kind::frame &&
                         out.items[n - 1].bytes == seed_frame,
                     "good data after hostile bytes was lost", stream);
}

// Every "AB 00 00 30" with 52 bytes after it gets the CRC of those bytes' last 48.
std::string with_good_crcs(std::string_view s) {
  std::string out(s);
  for (std::size_t i = 0; i + anello::frame_size <= out.size(); ++i) {
    if (static_cast<std::uint8_t>(out[i]) == 0xAB && out[i + 1] == 0 && out[i + 2] == 0 &&
        out[i + 3] == 0x30) {
      std::array<std::uint8_t, anello::frame_size> f{};
      for (std::size_t k = 0; k < f.size(); ++k) f[k] = static_cast<std::uint8_t>(out[i + k]);
      seawire::fuzz::fix_frame_crc(f);
      for (std::size_t k = 4; k < 8; ++k) out[i + k] = static_cast<char>(f[k]);
    }
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view raw = seawire::fuzz::as_text(data + 1, size - 1);
  const std::string fixed = (data[0] & 1U) != 0 ? with_good_crcs(raw) : std::string(raw);
  check_stream<80>(fixed, data[0], true);
  check_stream<1024>(fixed, data[0], false);
  check_drops<80>(fixed, data[0]);
  check_flush<80>(fixed, data[0]);
  check_recovery(fixed);
  return 0;
}
