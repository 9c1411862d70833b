// SPDX-License-Identifier: BSL-1.0
// anello::stream_reader: NMEA sentences and 0xAB00 binary frames from one byte stream.

#include "seawire/anello/stream.hpp"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "seawire/anello/frame.hpp"
#include "seawire/anello/inputs.hpp"
#include "seawire/detail/byte_order.hpp"
#include "seawire/detail/crc32.hpp"

#include "anello_seed.hpp"
#include "support.hpp"

namespace {

using namespace support;

using namespace seawire::anello;
using seawire::nmea::line_ending;
using namespace std::string_literals;
using namespace std::string_view_literals;

constexpr std::string_view vbw_line = "$VMVBW,0.0,0.0,A,0.0,0.0,A*58"sv;
constexpr std::string_view gpsctrl_line = "$PAPGPSCTRL,1*11"sv;
constexpr std::string_view ais_line = "!AIVDM,1,1,,B,15M67FC000G?ufbE`vJ8?wv4R0<4,0*10"sv;

std::string str(std::span<const std::uint8_t> bytes) {
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

// An item that owns its text, so it outlives the reader's next call.
struct rec {
  stream_item_kind kind = stream_item_kind::sentence;
  std::uint64_t offset = 0;
  std::string text;  // the sentence, the frame's 56 bytes, or the bytes a drop shows
  line_ending ending = line_ending::none;
  std::uint64_t line = 0;                   // a sentence's or a drop's (0 for frames)
  drop_reason reason = drop_reason::noise;  // drops only
  std::uint64_t size = 0;                   // drops only
  friend bool operator==(const rec&, const rec&) = default;
};

std::ostream& operator<<(std::ostream& os, const rec& r) {
  switch (r.kind) {
    case stream_item_kind::sentence: os << "{sentence"; break;
    case stream_item_kind::frame: os << "{frame"; break;
    case stream_item_kind::dropped: os << "{dropped " << name(r.reason) << ' ' << r.size; break;
  }
  os << " @" << r.offset;
  if (r.kind == stream_item_kind::sentence) {
    os << " line " << r.line << ' ' << ending_name(r.ending);
  }
  if (r.kind == stream_item_kind::dropped) os << " line " << r.line;
  os << ' ';
  return quote_text(os, r.text) << '}';
}

rec sentence(std::string_view text, std::uint64_t offset, line_ending e, std::uint64_t line) {
  return {stream_item_kind::sentence, offset, std::string(text), e, line};
}

rec frame(const frame_bytes& bytes, std::uint64_t offset) {
  return {stream_item_kind::frame, offset, str(bytes), line_ending::none, 0};
}

rec drop(drop_reason why, std::uint64_t offset, std::uint64_t size, std::string_view shown,
         std::uint64_t line) {
  return {
      stream_item_kind::dropped, offset, std::string(shown), line_ending::none, line, why, size};
}

// Frame items also check that the decoded frame is the decoding of the bytes it carries.
rec own(const stream_item& item) {
  if (item.is_drop()) {
    CHECK(item.sentence.text.empty());
    CHECK(item.drop.bytes.size() <= stream_drop::max_shown);
    CHECK(item.bytes == frame_bytes{});
    CHECK(item.frame == sensor_frame_raw{});
    return drop(item.drop.reason, item.offset, item.drop.size, item.drop.bytes, item.line);
  }
  CHECK(item.drop == stream_drop{});
  if (item.is_sentence()) {  // an item holds only its own kind's members
    CHECK(item.bytes == frame_bytes{});
    CHECK(item.frame == sensor_frame_raw{});
  }
  if (item.is_frame()) {
    const auto decoded = decode_frame(item.bytes);
    CHECK(decoded.ok());
    CHECK(decoded.value == item.frame);
    CHECK(item.sentence.text.empty());
    return frame(item.bytes, item.offset);
  }
  return sentence(item.sentence.text, item.offset, item.sentence.ending, item.sentence.line);
}

struct outcome {
  std::vector<rec> items;
  stream_stats stats;
  friend bool operator==(const outcome&, const outcome&) = default;
};

template <std::size_t N>
void drain(stream_reader<N>& r, std::vector<rec>& out) {
  while (const auto item = r.next()) out.push_back(own(*item));
}

template <std::size_t N>
void finish(stream_reader<N>& r, std::vector<rec>& out) {
  while (const auto item = r.finish()) out.push_back(own(*item));
  CHECK_FALSE(r.finish().has_value());  // nothing more
}

// Feeds `chunks` in order, then finishes.
template <std::size_t N = 1024>
outcome read(const std::vector<std::string_view>& chunks, bool drops = false) {
  stream_reader<N> r;
  r.report_drops(drops);
  outcome o;
  for (const auto c : chunks) {
    r.feed(c);
    drain(r, o.items);
  }
  finish(r, o.items);
  o.stats = r.stats();
  // The callbacks hand out the reader's own item, not a copy: the same items, and each holding
  // only its own kind's members after items of other kinds.
  stream_reader<N> by_callback;
  by_callback.report_drops(drops);
  outcome c;
  const auto take = [&c](const stream_item& item) { c.items.push_back(own(item)); };
  for (const auto chunk : chunks) by_callback.feed(chunk, take);
  by_callback.finish(take);
  c.stats = by_callback.stats();
  CHECK(c == o);
  return o;
}

template <std::size_t N = 1024>
outcome read(std::string_view stream, bool drops = false) {
  return read<N>(std::vector<std::string_view>{stream}, drops);
}

template <std::size_t N = 1024>
outcome read_bytewise(std::string_view stream, bool drops = false) {
  std::vector<std::string_view> chunks;
  for (std::size_t i = 0; i < stream.size(); ++i) chunks.push_back(stream.substr(i, 1));
  return read<N>(chunks, drops);
}

// The same stream read with drop reports: the items without them.
outcome without_drops(outcome o) {
  std::erase_if(o.items, [](const rec& r) { return r.kind == stream_item_kind::dropped; });
  return o;
}

// Bytes that matter to the reader come often, so random data exercises every rule.
char interesting_byte(prng& r) {
  static constexpr char specials[] = {'$', '!', '\r', '\n', '\xAB', '\x00', '\x30', '*', ','};
  if (r.chance(30)) return specials[r.below(sizeof specials)];
  return static_cast<char>(r.below(256));
}

frame_bytes random_frame(prng& r) {
  frame_bytes f{};
  const std::string_view header = "\xAB\x00\x00\x30"sv;
  std::copy(header.begin(), header.end(), f.begin());
  for (std::size_t i = header_size; i < frame_size; ++i) {
    f[i] = static_cast<std::uint8_t>(interesting_byte(r));
  }
  if (r.chance(20)) {  // a false sync inside a real payload
    const std::size_t at = header_size + r.below(payload_size - 3);
    std::copy(header.begin(), header.end(), f.begin() + static_cast<std::ptrdiff_t>(at));
  }
  return sealed(f);
}

const std::string_view sample_lines[] = {
    vbw_line,
    gpsctrl_line,
    "$PAPGPSCTRL,0*10"sv,
    "$VWVHW,87.3,T,,M,4.67,N,8.64,K*49"sv,
    "$IIRPM,S,1,1200.0,10.0,A*7B"sv,
    "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70"sv,
    "$"sv,
    ais_line,
    "!AIVDO,1*48"sv,
    "!"sv,
    "$BFMIS,1,Mission done!*2F"sv,
};

std::string_view pick_ending(prng& r) {
  switch (r.below(4)) {
    case 0: return "\n"sv;
    case 1: return "\r"sv;
    default: return "\r\n"sv;
  }
}

// A stream of everything a real link and a bad one can carry, in random order.
std::string random_stream(prng& r, std::size_t pieces) {
  std::string s;
  for (std::size_t p = 0; p < pieces; ++p) {
    switch (r.below(12)) {
      case 0:
      case 1:
        s += sample_lines[r.below(std::size(sample_lines))];
        s += pick_ending(r);
        break;
      case 2:
      case 3: s += str(random_frame(r)); break;
      case 4: {  // a frame with one bit flipped
        frame_bytes f = random_frame(r);
        f[r.below(frame_size)] ^= static_cast<std::uint8_t>(1U << r.below(8));
        s += str(f);
        break;
      }
      case 5: {  // a frame cut short, with whatever comes next inside its 56 bytes
        const frame_bytes f = random_frame(r);
        s += str(f).substr(0, 1 + r.below(frame_size - 1));
        break;
      }
      case 6: {  // a false sync: AB 00 00 30 and random bytes
        s += "\xAB\x00\x00\x30"sv;
        for (std::size_t n = r.below(60); n > 0; --n) s += interesting_byte(r);
        break;
      }
      case 7: {  // a length that lies
        static constexpr std::string_view lies[] = {"\xAB\x00\xFF\xFF"sv, "\xAB\x00\x00\x00"sv,
                                                    "\xAB\x00\x00\x31"sv, "\xAB\x00\x01\x30"sv,
                                                    "\xAB\x00"sv,         "\xAB"sv};
        s += lies[r.below(std::size(lies))];
        break;
      }
      case 8:  // garbage
        for (std::size_t n = r.below(40); n > 0; --n) s += interesting_byte(r);
        break;
      case 9: {  // a sentence cut by a byte it may not contain
        const std::string_view l = sample_lines[r.below(std::size(sample_lines))];
        s += l.substr(0, r.below(l.size() + 1));
        s += r.chance(50) ? '\xAB' : static_cast<char>(r.below(0x20));
        break;
      }
      case 10: {  // an overlong line (for the small-capacity readers)
        s += r.chance(30) ? '!' : '$';
        s.append(r.below(200), 'X');
        s += "\r\n";
        break;
      }
      default:  // a sentence with no line ending, then whatever comes
        s += sample_lines[r.below(std::size(sample_lines))];
        break;
    }
  }
  return s;
}

// The reader's contract written as the plainest loop over a whole stream, with random access:
// it looks ahead and backs up instead of holding bytes, so it shares no code and no states with
// the reader. Differential tests compare the two. With `drops`, it reports what it drops as
// the reader's report_drops(true) promises.
outcome reference_read(std::string_view s, std::size_t capacity, bool drops = false) {
  enum class st { idle, in, discard } state = st::idle;
  outcome o;
  stream_stats& k = o.stats;
  std::string cur;
  std::uint64_t cur_offset = 0;
  std::uint64_t line = 1;
  bool prev_cr = false;
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
  // The drop being collected (a noise run or a dropped line): reason, offset, size, line.
  std::optional<rec> open;
  const auto shown = [&](std::uint64_t at, std::uint64_t n) {
    return s.substr(at, std::min<std::uint64_t>(n, stream_drop::max_shown));
  };
  const auto close = [&] {
    if (open && drops) {
      open->text = std::string(shown(open->offset, open->size));
      o.items.push_back(*open);
    }
    open.reset();
  };
  const auto report = [&](drop_reason why, std::uint64_t at, std::uint64_t size,
                          std::string_view bytes) {
    if (drops) o.items.push_back(drop(why, at, size, bytes, line));
  };
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    const unsigned char u = byte(i);
    if (state == st::in) {
      if (c == '\r' || c == '\n') {
        line_ending e = c == '\n' ? line_ending::lf : line_ending::cr;
        if (c == '\r' && i + 1 < s.size() && s[i + 1] == '\n') e = line_ending::crlf;
        const std::size_t n = e == line_ending::crlf ? 2 : 1;
        k.line_break_bytes += n;
        i += n;
        o.items.push_back(sentence(cur, cur_offset, e, line));
        ++k.sentences;
        ++line;
        state = st::idle;
      } else if ((c == '$' || u == 0xAB) && cur.size() >= 5 && cur[cur.size() - 3] == '*' &&
                 std::isxdigit(static_cast<unsigned char>(cur[cur.size() - 2])) != 0 &&
                 std::isxdigit(static_cast<unsigned char>(cur.back())) != 0) {
        // A whole "*hh" sentence lacks only its line ending: it comes out; c is read again.
        o.items.push_back(sentence(cur, cur_offset, line_ending::none, line));
        ++k.sentences;
        state = st::idle;
      } else if (c == '$' || u == 0xAB) {  // not '!': that is text here
        ++k.interrupted;
        k.dropped_bytes += cur.size();
        report(drop_reason::interrupted, cur_offset, cur.size(), shown(cur_offset, cur.size()));
        state = st::idle;  // and read c again
      } else if (u < 0x20 || u > 0x7E) {
        ++k.invalid_bytes;
        k.dropped_bytes += cur.size() + 1;
        open = drop(drop_reason::invalid_byte, cur_offset, cur.size() + 1, "", line);
        state = st::discard;
        ++i;
      } else {
        cur += c;
        ++i;
        if (cur.size() > capacity) {
          ++k.overlong;
          k.dropped_bytes += cur.size();
          open = drop(drop_reason::overlong, cur_offset, cur.size(), "", line);
          state = st::discard;
        }
      }
      continue;
    }
    if (state == st::discard) {  // a '!' is dropped here: it starts nothing
      if (c == '$' || u == 0xAB || c == '\r' || c == '\n') {
        close();
        state = st::idle;
      } else {
        ++k.dropped_bytes;
        ++open->size;
        ++i;
      }
      continue;
    }
    // Between items: '$', '!' and line breaks end a noise run; an AB ends it only as AB 00.
    if (c == '$' || c == '!' || c == '\r' || c == '\n') close();
    if (u == 0xAB && i + 1 < s.size() && byte(i + 1) == 0x00) close();
    if (c == '$' || c == '!') {
      state = st::in;
      cur = std::string(1, c);
      cur_offset = i;
      prev_cr = false;
      ++i;
    } else if (u == 0xAB) {
      prev_cr = false;
      static constexpr unsigned char header[4] = {0xAB, 0x00, 0x00, 0x30};
      std::size_t m = 1;
      while (m < 4 && i + m < s.size() && byte(i + m) == header[m]) ++m;
      if (m < 4 && i + m < s.size()) {  // the header breaks at byte m: read it again
        if (m == 1) {
          ++k.noise_bytes;
          if (!open) open = drop(drop_reason::noise, i, 0, "", line);
          ++open->size;  // the AB is noise, in the run it follows
        } else {
          ++k.bad_length_frames;
          ++k.dropped_bytes;
          k.noise_bytes += m - 1;
          report(drop_reason::bad_length, i, m, s.substr(i, m + 1));  // and the byte that broke it
        }
        i += m;
      } else if (i + frame_size <= s.size()) {
        const auto* p = reinterpret_cast<const std::uint8_t*>(s.data() + i);
        const auto d = decode_frame(std::span(p, frame_size));
        if (d) {
          frame_bytes f{};
          std::copy_n(p, frame_size, f.begin());
          o.items.push_back(frame(f, i));
          ++k.frames;
          i += frame_size;
        } else {
          ++k.bad_crc_frames;
          ++k.dropped_bytes;
          report(drop_reason::bad_crc, i, 1, s.substr(i, frame_size));
          ++i;  // back up to the byte after the AB
        }
      } else if (s.size() - i == 1) {
        ++k.noise_bytes;
        if (!open) open = drop(drop_reason::noise, i, 0, "", line);
        ++open->size;
        ++i;
      } else {
        ++k.truncated_frames;
        ++k.dropped_bytes;
        report(drop_reason::truncated_frame, i, 1, s.substr(i));
        ++i;
      }
    } else if (c == '\r' || c == '\n') {
      ++k.line_break_bytes;
      if (c == '\r' || !prev_cr) ++line;
      prev_cr = c == '\r';
      ++i;
    } else {
      ++k.noise_bytes;
      prev_cr = false;
      if (!open) open = drop(drop_reason::noise, i, 0, "", line);
      ++open->size;
      ++i;
    }
  }
  if (state == st::in) {
    o.items.push_back(sentence(cur, cur_offset, line_ending::none, line));
    ++k.sentences;
  }
  close();
  return o;
}

// The accounting identity the header promises: every byte lands in exactly one bucket.
void check_accounting(std::string_view stream, const outcome& o) {
  std::uint64_t item_bytes = 0;
  std::uint64_t drop_bytes = 0;
  std::size_t reports = 0;
  for (const auto& it : o.items) {
    if (it.kind == stream_item_kind::dropped) {
      drop_bytes += it.size;
      ++reports;
    } else {
      item_bytes += it.text.size();
    }
  }
  const stream_stats& k = o.stats;
  CHECK(item_bytes + k.noise_bytes + k.dropped_bytes + k.line_break_bytes == stream.size());
  CHECK(k.sentences + k.frames + reports == o.items.size());
  if (reports > 0) CHECK(drop_bytes == k.noise_bytes + k.dropped_bytes);
}

// Whether `want` appears in `got` in order (other items may come between), comparing what was
// sent: kind, offset and bytes (a neighbour can turn a CR ending into CR LF).
bool in_order(const std::vector<rec>& want, const std::vector<rec>& got) {
  std::size_t j = 0;
  for (const auto& g : got) {
    if (j < want.size() && g.kind == want[j].kind && g.offset == want[j].offset &&
        g.text == want[j].text) {
      ++j;
    }
  }
  return j == want.size();
}

// Items and stats are compile-time values too.
constexpr bool reads_at_compile_time() {
  std::array<char, 18 + frame_size + 2> buf{};
  std::size_t n = 0;
  for (const char c : gpsctrl_line) buf[n++] = c;
  buf[n++] = '\r';
  buf[n++] = '\n';
  for (const std::uint8_t b : seed) buf[n++] = static_cast<char>(b);
  buf[n++] = '\xAB';
  buf[n++] = '\x00';
  stream_reader<32> r;
  r.feed(std::string_view(buf.data(), n));
  const auto a = r.next();
  const auto b = r.next();
  const bool drained = !r.next();
  const bool ended = !r.finish();
  return a && a->is_sentence() && a->sentence.text == gpsctrl_line &&
         a->sentence.ending == line_ending::crlf && b && b->is_frame() && b->offset == 18 &&
         b->frame.heading == 89 && b->bytes == seed && drained && ended &&
         r.stats().truncated_frames == 1 && r.stats().noise_bytes == 1 &&
         r.stats().dropped_bytes == 1;
}
static_assert(reads_at_compile_time());

// Drop reports too.
constexpr bool reports_drops_at_compile_time() {
  stream_reader<16> r;
  r.report_drops(true);
  // From an array, not the literal: a literal's address may not be compared in a constant
  // expression (clang), and the reader compares the source with its own buffer.
  constexpr std::string_view bytes = "##\r\n$A\x01z\n\xAB\x00"sv;
  std::array<char, bytes.size()> buf{};
  std::copy(bytes.begin(), bytes.end(), buf.begin());
  r.feed(std::string_view(buf.data(), buf.size()));
  const auto noise = r.next();  // its bytes are valid until the next call
  bool ok = noise && noise->is_drop() && noise->drop.reason == drop_reason::noise &&
            noise->drop.bytes == "##" && noise->line == 1;
  const auto line = r.next();
  ok = ok && line && line->is_drop() && line->drop.reason == drop_reason::invalid_byte &&
       line->drop.size == 4 && line->drop.bytes == "$A\x01z" && line->offset == 4 &&
       line->line == 2;
  ok = ok && !r.next();
  const auto truncated = r.finish();
  ok = ok && truncated && truncated->drop.reason == drop_reason::truncated_frame &&
       truncated->offset == 9 && truncated->drop.bytes == "\xAB\x00"sv;
  const auto zeros = r.finish();  // the 00 after the AB, read again
  return ok && zeros && zeros->drop.reason == drop_reason::noise && zeros->offset == 10 &&
         !r.finish();
}
static_assert(reports_drops_at_compile_time());

// Fixed memory: the line buffer, a frame, the bytes to read again, the item handed out, and a
// few counters.
static_assert(sizeof(stream_reader<82>) <= 82 + frame_size + (frame_size - 1) +
                                               stream_drop::max_shown + sizeof(stream_item) + 256);
static_assert(sizeof(stream_reader<1024>) <= sizeof(stream_reader<82>) + (1024 - 82) + 8);

}  // namespace

// ADL cannot see a printer for a seawire type from here, so tell Catch directly.
namespace Catch {
template <>
struct StringMaker<stream_stats> {
  static std::string convert(const stream_stats& s) {
    return "{sentences " + std::to_string(s.sentences) + ", frames " + std::to_string(s.frames) +
           ", noise " + std::to_string(s.noise_bytes) + ", bad_crc " +
           std::to_string(s.bad_crc_frames) + ", bad_length " +
           std::to_string(s.bad_length_frames) + ", truncated " +
           std::to_string(s.truncated_frames) + ", interrupted " + std::to_string(s.interrupted) +
           ", overlong " + std::to_string(s.overlong) + ", invalid " +
           std::to_string(s.invalid_bytes) + ", dropped " + std::to_string(s.dropped_bytes) +
           ", breaks " + std::to_string(s.line_break_bytes) + "}";
  }
};
template <>
struct StringMaker<outcome> {
  static std::string convert(const outcome& o) {
    return StringMaker<std::vector<rec>>::convert(o.items) + " " +
           StringMaker<stream_stats>::convert(o.stats);
  }
};
}  // namespace Catch

TEST_CASE("the spec's example frame", "[anello][stream]") {
  const std::string stream = str(seed);
  const outcome o = read(stream);
  REQUIRE(o.items.size() == 1);
  CHECK(o.items[0] == frame(seed, 0));
  CHECK(o.stats.frames == 1);
  CHECK(o.stats.noise_bytes == 0);
  CHECK(o.stats.dropped_bytes == 0);

  stream_reader<> r;
  r.feed(stream);
  const auto item = r.next();
  REQUIRE(item.has_value());
  REQUIRE(item->is_frame());
  CHECK(item->frame.heading_deg() == 89.0);
  CHECK(item->frame.latitude_deg() == 32.828671);
  CHECK(item->frame.longitude_deg() == -117.229926);
  CHECK(item->frame.wind_dir_abs_deg() == 108.0);
  CHECK_FALSE(item->frame.air_temp_c().has_value());
}

TEST_CASE("the spec's example frame from tests/data, between two sentences", "[anello][stream]") {
  const std::string hex = seed_hex_from_file();
  REQUIRE(hex.size() == 2 * frame_size);
  const frame_bytes from_file = frame_from_hex(hex);
  CHECK(from_file == seed);

  const std::string stream =
      std::string(vbw_line) + "\r\n" + str(from_file) + std::string(gpsctrl_line) + "\r\n";
  CHECK(read(stream).items == std::vector<rec>{sentence(vbw_line, 0, line_ending::crlf, 1),
                                               frame(seed, 31),
                                               sentence(gpsctrl_line, 87, line_ending::crlf, 2)});
}

TEST_CASE("interleaved sentences and frames: what was sent comes out, decodable",
          "[anello][stream]") {
  const frame_bytes other = [] {
    sensor_frame_raw raw;
    raw.heading = 270;
    raw.stw = 24;
    return encode_frame(raw);
  }();
  std::string stream;
  std::vector<rec> want;
  std::uint64_t line = 1;
  for (int round = 0; round < 3; ++round) {
    want.push_back(sentence(vbw_line, stream.size(), line_ending::crlf, line++));
    stream += std::string(vbw_line) + "\r\n";
    want.push_back(frame(seed, stream.size()));
    stream += str(seed);
    want.push_back(sentence(gpsctrl_line, stream.size(), line_ending::crlf, line++));
    stream += std::string(gpsctrl_line) + "\r\n";
    want.push_back(frame(other, stream.size()));
    stream += str(other);
    want.push_back(frame(seed, stream.size()));  // two frames back to back
    stream += str(seed);
  }
  const outcome o = read(stream);
  CHECK(o.items == want);
  CHECK(o.stats.sentences == 6);
  CHECK(o.stats.frames == 9);
  CHECK(o.stats.noise_bytes == 0);
  CHECK(o.stats.dropped_bytes == 0);
  check_accounting(stream, o);

  // What the INS does with the sentences.
  stream_reader<> r;
  int vbw = 0;
  int gpsctrl = 0;
  int frames = 0;
  r.feed(stream, [&](const stream_item& item) {
    if (item.is_frame()) {
      ++frames;
      return;
    }
    const auto in = decode_input(item.sentence.text);
    REQUIRE(in.ok());
    if (const auto* m = std::get_if<seawire::standard::vbw>(&in.value)) {
      ++vbw;
      CHECK(m->talker == "VM");
    }
    if (const auto* m = std::get_if<papgpsctrl>(&in.value)) {
      ++gpsctrl;
      CHECK(m->control == gps_control::use);
    }
  });
  r.finish([](const stream_item&) { FAIL("nothing is pending"); });
  CHECK(vbw == 3);
  CHECK(gpsctrl == 3);
  CHECK(frames == 9);
}

TEST_CASE("a payload holding '$', CR LF and AB 00 00 30 is still one frame", "[anello][stream]") {
  sensor_frame_raw raw;
  raw.heading = 0x240D;                                  // '$' CR
  raw.lat = 0x0A2450;                                    // 00 LF '$' 'P'
  raw.lon = static_cast<std::int32_t>(0xAB000030);       // a false sync
  raw.gps_time_ms = 0x2456'4D56'4257'0D0AU;              // "$VMVBW" CR LF
  raw.alt_msl = static_cast<std::int32_t>(0xAB00FFFFU);  // a lying length
  const frame_bytes f = encode_frame(raw);
  const std::string bytes = str(f);
  REQUIRE(bytes.find("\xAB\x00\x00\x30"sv, 4) != std::string::npos);
  REQUIRE(bytes.find("\r\n"sv) != std::string::npos);

  const std::string stream =
      std::string(gpsctrl_line) + "\r\n" + bytes + bytes + std::string(vbw_line) + "\r\n";
  const std::vector<rec> want{sentence(gpsctrl_line, 0, line_ending::crlf, 1), frame(f, 18),
                              frame(f, 74), sentence(vbw_line, 130, line_ending::crlf, 2)};
  const outcome o = read(stream);
  CHECK(o.items == want);
  CHECK(o.stats == stream_stats{2, 2, 0, 0, 0, 0, 0, 0, 0, 0, 4});
  CHECK(read_bytewise(stream) == o);
  CHECK(decode_frame(f).value == raw);
}

TEST_CASE("every single-bit flip of a frame drops it and the items after it come out",
          "[anello][stream]") {
  const std::string head = std::string(vbw_line) + "\r\n";
  const std::string tail = std::string(gpsctrl_line) + "\r\n" + str(seed) + std::string(vbw_line);
  const std::uint64_t after = head.size() + frame_size;
  const std::vector<rec> want{
      sentence(vbw_line, 0, line_ending::crlf, 1),
      sentence(gpsctrl_line, after, line_ending::crlf, 2),
      frame(seed, after + gpsctrl_line.size() + 2),
      sentence(vbw_line, after + gpsctrl_line.size() + 2 + frame_size, line_ending::none, 3),
  };
  for (std::size_t bit = 0; bit < 8 * frame_size; ++bit) {
    frame_bytes bad = seed;
    bad[bit / 8] ^= static_cast<std::uint8_t>(1U << (bit % 8));
    const std::string stream = head + str(bad) + tail;
    INFO("bit " << bit << " of byte " << bit / 8);
    const outcome o = read(stream);
    // A flip can make a payload byte an LF: compare what was sent, then line numbers apart.
    CHECK(o.items.size() == want.size());
    CHECK(in_order(want, o.items));
    CHECK(o.stats.frames == 1);
    CHECK(o.stats.sentences == 3);
    const std::size_t byte = bit / 8;
    CHECK(o.stats.bad_length_frames == (byte == 2 || byte == 3 ? 1U : 0U));
    CHECK(o.stats.bad_crc_frames == (byte >= 4 ? 1U : 0U));  // CRC-32 sees every single-bit error
    // A flip that makes a payload byte a '!' (0x01 -> 0x21) starts a sentence where the bytes
    // after the dropped AB are read again; the binary bytes after it drop that line too.
    if (bad[byte] != '!') CHECK(o.stats.dropped_bytes == (byte >= 2 ? 1U : 0U));
    CHECK(o == reference_read(stream, 1024));
    check_accounting(stream, o);
    prng r{bit};
    CHECK(read(chop(stream, r, 1 + r.below(64))) == o);
  }
}

TEST_CASE("a length field that lies is refused at once", "[anello][stream]") {
  const std::string after = std::string(gpsctrl_line) + "\r\n";
  SECTION("0xFFFF: the sentence right after it comes out without waiting for 65535 bytes") {
    const std::string stream = "\xAB\x00\xFF\xFF"s + after;
    stream_reader<> r;
    r.feed(stream);
    const auto item = r.next();  // no finish(): nothing is held back
    REQUIRE(item.has_value());
    CHECK(own(*item) == sentence(gpsctrl_line, 4, line_ending::crlf, 1));
    CHECK_FALSE(r.next().has_value());
    CHECK(r.stats() == stream_stats{1, 0, 3, 0, 1, 0, 0, 0, 0, 1, 2});
  }
  SECTION("0x0000: a frame right after it") {
    const std::string stream = "\xAB\x00\x00\x00"s + str(seed);
    stream_reader<> r;
    r.feed(stream);
    const auto item = r.next();
    REQUIRE(item.has_value());
    CHECK(own(*item) == frame(seed, 4));
    CHECK(r.stats() == stream_stats{0, 1, 3, 0, 1, 0, 0, 0, 0, 1, 0});
  }
  SECTION("the length is the next frame's sync") {
    const std::string stream = "\xAB\x00"s + str(seed);
    CHECK(read(stream).items == std::vector<rec>{frame(seed, 2)});
    CHECK(read(stream).stats == stream_stats{0, 1, 1, 0, 1, 0, 0, 0, 0, 1, 0});
  }
  SECTION("every other length, in every chunking") {
    for (unsigned length = 0; length <= 0xFFFF; length += 0x0101) {
      if (length == payload_size) continue;
      std::string stream = "\xAB\x00"s;
      stream += static_cast<char>(length >> 8);
      stream += static_cast<char>(length & 0xFF);
      stream += after + str(seed);
      INFO("length " << length);
      const outcome o = read(stream);
      CHECK(o.stats.bad_length_frames == 1);
      CHECK(in_order({sentence(gpsctrl_line, 4, line_ending::crlf, 1), frame(seed, 22)}, o.items));
      CHECK(read_bytewise(stream) == o);
    }
  }
}

TEST_CASE("a frame truncated by the end of the stream is counted", "[anello][stream]") {
  SECTION("a sentence, then 30 bytes of a frame") {
    const std::string stream = std::string(vbw_line) + "\r\n" + str(seed).substr(0, 30);
    stream_reader<> r;
    r.feed(stream);
    const auto item = r.next();
    REQUIRE(item.has_value());
    CHECK(own(*item) == sentence(vbw_line, 0, line_ending::crlf, 1));
    CHECK_FALSE(r.next().has_value());
    CHECK_FALSE(r.finish().has_value());
    CHECK(r.stats() == stream_stats{1, 0, 29, 0, 0, 1, 0, 0, 0, 1, 2});
  }
  SECTION("55 bytes") {
    const outcome o = read(str(seed).substr(0, 55));
    CHECK(o.items.empty());
    CHECK(o.stats.truncated_frames == 1);
  }
  SECTION("just AB 00 is a truncated frame; a lone AB is noise") {
    CHECK(read("\xAB\x00"sv).stats == stream_stats{0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0});
    CHECK(read("\xAB"sv).stats == stream_stats{0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0});
  }
  SECTION("a false sync at the end hides nothing: finish() reads its bytes again") {
    const std::string stream = "\xAB\x00\x00\x30"s + std::string(gpsctrl_line) + "\r\n";
    stream_reader<> r;
    r.feed(stream);
    CHECK_FALSE(r.next().has_value());  // could still be a frame
    const auto item = r.finish();
    REQUIRE(item.has_value());
    CHECK(own(*item) == sentence(gpsctrl_line, 4, line_ending::crlf, 1));
    CHECK_FALSE(r.finish().has_value());
    CHECK(r.stats() == stream_stats{1, 0, 3, 0, 0, 1, 0, 0, 0, 1, 2});
  }
  SECTION("truncated inside a truncated candidate") {
    const std::string stream = "\xAB\x00\x00\x30$A\r\n\xAB\x00\x00\x30$B"s;
    const outcome o = read(stream);
    CHECK(o.items == std::vector<rec>{sentence("$A", 4, line_ending::crlf, 1),
                                      sentence("$B", 12, line_ending::none, 2)});
    CHECK(o.stats.truncated_frames == 2);
    CHECK(read_bytewise(stream) == o);
  }
}

TEST_CASE("garbage that holds AB 00 by chance", "[anello][stream]") {
  SECTION("AB 00 00 30 and random bytes, then a sentence and a frame inside its 56 bytes") {
    prng r{42};
    for (int trial = 0; trial < 200; ++trial) {
      std::string stream = "xx\xAB\x00\x00\x30"s;
      for (std::size_t n = r.below(30); n > 0; --n) {
        char c = static_cast<char>(r.below(256));
        if (c == '$' || c == '\r' || c == '\n' || c == '\xAB') c = 'g';
        stream += c;
      }
      const std::size_t at_line = stream.size();
      stream += std::string(vbw_line) + "\r\n";
      const std::size_t at_frame = stream.size();
      stream += str(seed) + std::string(gpsctrl_line) + "\r\n";
      INFO("trial " << trial);
      const outcome o = read(stream);
      CHECK(o.items == std::vector<rec>{
                           sentence(vbw_line, at_line, line_ending::crlf, 1), frame(seed, at_frame),
                           sentence(gpsctrl_line, at_frame + frame_size, line_ending::crlf, 2)});
      CHECK(o.stats.bad_crc_frames == 1);
      check_accounting(stream, o);
      CHECK(read_bytewise(stream) == o);
    }
  }
  SECTION("a false sync that swallows the start of a real frame") {
    const std::string stream = "\xAB\x00\x00\x30zz"s + str(seed);
    const outcome o = read(stream);
    CHECK(o.items == std::vector<rec>{frame(seed, 6)});
    CHECK(o.stats == stream_stats{0, 1, 5, 1, 0, 0, 0, 0, 0, 1, 0});
  }
  SECTION("false syncs nested in false syncs") {
    std::string stream;
    for (int i = 0; i < 20; ++i) stream += "\xAB\x00\x00\x30"sv;
    stream += std::string(vbw_line) + "\n" + str(seed);
    const outcome o = read(stream);
    CHECK(o.items == std::vector<rec>{sentence(vbw_line, 80, line_ending::lf, 1),
                                      frame(seed, 80 + vbw_line.size() + 1)});
    CHECK(o.stats.bad_crc_frames == 20);
    CHECK(read_bytewise(stream) == o);
  }
  SECTION("AB 00 in noise, in a dropped line and between sentences") {
    const std::string stream = "noise\xAB\x00 more\r\n$BAD\x01\xAB\x00\x12tail\r\n$A\xAB\x01$B\n"s;
    const outcome o = read(stream);
    CHECK(o.items == std::vector<rec>{sentence("$B", 32, line_ending::lf, 3)});
    CHECK(o.stats.bad_length_frames == 2);
    CHECK(o.stats.invalid_bytes == 1);
    CHECK(o.stats.interrupted == 1);
    check_accounting(stream, o);
    CHECK(read_bytewise(stream) == o);
  }
}

TEST_CASE("0xAB inside a sentence ends it: interrupted, unless its checksum is whole",
          "[anello][stream]") {
  SECTION("a stray AB") {
    const std::string stream =
        "$VMVBW,0.0\xAB"s + "0.0*58\r\n" + std::string(gpsctrl_line) + "\r\n";
    const outcome o = read(stream);
    CHECK(o.items == std::vector<rec>{sentence(gpsctrl_line, 19, line_ending::crlf, 2)});
    CHECK(o.stats == stream_stats{1, 0, 7, 0, 0, 0, 1, 0, 0, 10, 4});
  }
  SECTION("a frame right after a whole sentence with no line ending") {
    // "*hh" is complete: only the line ending is missing, and nothing is lost.
    const std::string stream = std::string(gpsctrl_line) + str(seed);
    const outcome o = read(stream);
    CHECK(o.items ==
          std::vector<rec>{sentence(gpsctrl_line, 0, line_ending::none, 1), frame(seed, 16)});
    CHECK(o.stats.interrupted == 0);
    CHECK(o.stats.dropped_bytes == 0);
  }
  SECTION("a frame right after a sentence cut inside its checksum") {
    const std::string cut(gpsctrl_line.substr(0, gpsctrl_line.size() - 1));
    const std::string stream = cut + str(seed);
    const outcome o = read(stream);
    CHECK(o.items == std::vector<rec>{frame(seed, cut.size())});
    CHECK(o.stats.interrupted == 1);
    CHECK(o.stats.dropped_bytes == cut.size());
  }
}

TEST_CASE("'!' starts a sentence between items, and is text inside one", "[anello][stream]") {
  SECTION("alone") {
    const std::string stream = std::string(ais_line) + "\r\n";
    const outcome o = read(stream, true);
    CHECK(o.items == std::vector<rec>{sentence(ais_line, 0, line_ending::crlf, 1)});
    CHECK(o.stats == stream_stats{1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2});
  }
  SECTION("mixed with '$' sentences and frames") {
    const std::string stream = std::string(vbw_line) + "\r\n" + std::string(ais_line) + "\r\n" +
                               str(seed) + "!AIVDO,1*48\n" + std::string(gpsctrl_line) + "\r\n";
    const std::uint64_t at_ais = vbw_line.size() + 2;
    const std::uint64_t at_frame = at_ais + ais_line.size() + 2;
    const std::uint64_t at_vdo = at_frame + frame_size;
    const outcome o = read(stream, true);
    CHECK(o.items == std::vector<rec>{sentence(vbw_line, 0, line_ending::crlf, 1),
                                      sentence(ais_line, at_ais, line_ending::crlf, 2),
                                      frame(seed, at_frame),
                                      sentence("!AIVDO,1*48", at_vdo, line_ending::lf, 3),
                                      sentence(gpsctrl_line, at_vdo + 12, line_ending::crlf, 4)});
    CHECK(o.stats.noise_bytes + o.stats.dropped_bytes == 0);
    check_accounting(stream, o);
    CHECK(o == reference_read(stream, 1024, true));
    CHECK(read_bytewise(stream, true) == o);
  }
  SECTION("in a '$' sentence's text: no interruption") {
    const std::string_view mis = "$BFMIS,1,Mission done!*2F"sv;
    const outcome o = read(std::string(mis) + "\r\n", true);
    CHECK(o.items == std::vector<rec>{sentence(mis, 0, line_ending::crlf, 1)});
    CHECK(o.stats.interrupted == 0);
  }
  SECTION("after noise: it ends the noise run") {
    const outcome o = read("junk!AIVDM,1\r\n"sv, true);
    CHECK(o.items == std::vector<rec>{drop(drop_reason::noise, 0, 4, "junk", 1),
                                      sentence("!AIVDM,1", 4, line_ending::crlf, 1)});
  }
  SECTION("in the rest of a dropped line: dropped with it") {
    const std::string_view stream = "$A\x01x!B\n!C\n"sv;
    const outcome o = read(stream, true);
    CHECK(o.items == std::vector<rec>{drop(drop_reason::invalid_byte, 0, 6, "$A\x01x!B", 1),
                                      sentence("!C", 7, line_ending::lf, 2)});
    CHECK(o.stats == stream_stats{1, 0, 0, 0, 0, 0, 0, 0, 1, 6, 2});
    CHECK(o == reference_read(stream, 1024, true));
    CHECK(read_bytewise(stream, true) == o);
  }
  SECTION("a '$' or an AB interrupts a '!' sentence") {
    const std::string stream = "!AIVDM,1$A\n!B"s + str(seed);
    const outcome o = read(stream, true);
    CHECK(o.items == std::vector<rec>{drop(drop_reason::interrupted, 0, 8, "!AIVDM,1", 1),
                                      sentence("$A", 8, line_ending::lf, 1),
                                      drop(drop_reason::interrupted, 11, 2, "!B", 2),
                                      frame(seed, 13)});
    CHECK(o.stats.interrupted == 2);
    check_accounting(stream, o);
    CHECK(read_bytewise(stream, true) == o);
  }
  SECTION("split across chunks") {
    const outcome o = read(
        {"ju"sv, "nk!"sv, "AIV"sv, "DM\r"sv, "\n"sv, "$BF,hi"sv, "!"sv, " there\n"sv, "!"sv}, true);
    CHECK(o.items == std::vector<rec>{drop(drop_reason::noise, 0, 4, "junk", 1),
                                      sentence("!AIVDM", 4, line_ending::crlf, 1),
                                      sentence("$BF,hi! there", 12, line_ending::lf, 2),
                                      sentence("!", 26, line_ending::none, 3)});
    CHECK(o == reference_read("junk!AIVDM\r\n$BF,hi! there\n!"sv, 1024, true));
  }
  SECTION("bytes of a rejected frame candidate, read again") {
    // AB 00 00 30, then a '!' sentence inside the 56 bytes: it comes out once the CRC fails.
    const std::string stream =
        "\xAB\x00\x00\x30"s + std::string(ais_line) + "\r\n" + std::string(frame_size, 'z') + "\n";
    const outcome o = read(stream);
    REQUIRE(o.items.size() == 1);
    CHECK(o.items[0] == sentence(ais_line, 4, line_ending::crlf, 1));
    CHECK(o.stats.bad_crc_frames == 1);
    CHECK(o == reference_read(stream, 1024));
    CHECK(read_bytewise(stream) == o);
  }
}

TEST_CASE("line numbers, offsets and endings across frames", "[anello][stream]") {
  // The CR LF inside the frame is payload; the CR before it and the LF after it are two breaks.
  sensor_frame_raw raw;
  raw.heading = 0x0D0A;
  const frame_bytes f = encode_frame(raw);
  const std::string stream = "$A\r"s + str(f) + "\n$B\r\n\r\n$C"s;
  const outcome o = read(stream);
  CHECK(o.items == std::vector<rec>{sentence("$A", 0, line_ending::cr, 1), frame(f, 3),
                                    sentence("$B", 60, line_ending::crlf, 3),
                                    sentence("$C", 66, line_ending::none, 5)});
  CHECK(read_bytewise(stream) == o);
  check_accounting(stream, o);

  SECTION("a CR held at a chunk's end, then a frame") {
    stream_reader<> r;
    r.feed("$A\r");
    CHECK_FALSE(r.next().has_value());
    const std::string rest = str(seed);
    r.feed(rest);
    auto item = r.next();
    REQUIRE(item.has_value());
    CHECK(own(*item) == sentence("$A", 0, line_ending::cr, 1));
    item = r.next();
    REQUIRE(item.has_value());
    CHECK(own(*item) == frame(seed, 3));
  }
}

TEST_CASE("flush(): a sentence held on its CR comes out when the link goes quiet",
          "[anello][stream]") {
  SECTION("CR-only sender, then a late LF and a frame") {
    stream_reader<> r;
    r.report_drops(true);
    r.feed("$A\r");
    CHECK_FALSE(r.next().has_value());
    auto item = r.flush();
    REQUIRE(item.has_value());
    CHECK(own(*item) == sentence("$A", 0, line_ending::cr, 1));
    CHECK_FALSE(r.flush().has_value());
    // The LF completes the CR's break (no line, no noise), the frame is on line 2.
    const std::string rest = "\n" + str(seed) + "$B\r\n";
    r.feed(rest);
    item = r.next();
    REQUIRE(item.has_value());
    CHECK(own(*item) == frame(seed, 4));
    CHECK(item->line == 2);
    item = r.next();
    REQUIRE(item.has_value());
    CHECK(own(*item) == sentence("$B", 4 + frame_size, line_ending::crlf, 2));
    CHECK_FALSE(r.next().has_value());
    CHECK_FALSE(r.finish().has_value());
    CHECK(r.stats().noise_bytes == 0);
    CHECK(r.stats().line_break_bytes == 4);
  }
  SECTION("nothing is released but the held sentence") {
    stream_reader<> r;
    r.report_drops(true);
    r.feed("junk$A,1");  // noise, then a sentence without its ending
    auto item = r.next();
    REQUIRE(item.has_value());
    CHECK(item->kind == stream_item_kind::dropped);
    CHECK_FALSE(r.next().has_value());
    CHECK_FALSE(r.flush().has_value());
    r.feed("\xAB\x00");  // ends the sentence as interrupted; a frame candidate waits
    item = r.next();
    REQUIRE(item.has_value());
    CHECK(item->drop.reason == drop_reason::interrupted);
    CHECK_FALSE(r.next().has_value());
    CHECK_FALSE(r.flush().has_value());
    CHECK(r.stats().truncated_frames == 0);
  }
}

TEST_CASE("flush(on_item): the held sentence handed over once, as flush() gives it",
          "[anello][stream]") {
  stream_reader<> r;
  r.report_drops(true);
  std::vector<rec> got;
  const auto take = [&got](const stream_item& item) { got.push_back(own(item)); };
  r.feed(str(seed) + "$A\r", take);  // a frame, then a sentence held on its CR
  REQUIRE(got.size() == 1);
  CHECK(got[0] == frame(seed, 0));
  r.flush(take);
  r.flush(take);  // nothing held any more
  REQUIRE(got.size() == 2);
  CHECK(got[1] == sentence("$A", frame_size, line_ending::cr, 1));
  r.feed("x\n", take);  // the LF completes the CR's break; the x is noise, reported at the LF
  r.finish(take);
  REQUIRE(got.size() == 3);
  CHECK(got[2] == drop(drop_reason::noise, frame_size + 3, 1, "x", 2));
  CHECK(r.stats().noise_bytes == 1);
}

TEST_CASE("small capacity: overlong lines, also inside bytes read again", "[anello][stream]") {
  const std::string fits = "$" + std::string(15, 'a');  // 16 bytes
  const std::string over = "$" + std::string(16, 'b');  // 17 bytes
  const std::string stream = fits + "\r\n" + over + "\r\n\xAB\x00\x00\x30"s + over + "\n" + fits +
                             "\n" + std::string(40, 'x') + str(seed);
  const outcome o = read<16>(stream);
  CHECK(o.items == std::vector<rec>{sentence(fits, 0, line_ending::crlf, 1),
                                    sentence(fits, 59, line_ending::lf, 4), frame(seed, 116)});
  CHECK(o.stats.overlong == 2);
  CHECK(o.stats.bad_crc_frames == 1);
  check_accounting(stream, o);
  CHECK(read_bytewise<16>(stream) == o);
  CHECK(reference_read(stream, 16) == o);
}

TEST_CASE("the same items and stats for every chunking, and as the reference reads them",
          "[anello][stream]") {
  for (std::uint64_t seed_value = 1; seed_value <= 150; ++seed_value) {
    prng r{seed_value};
    const std::string stream = random_stream(r, 20 + r.below(150));
    INFO("seed " << seed_value << ", " << stream.size() << " bytes");
    const outcome whole = read(stream);
    CHECK(whole == reference_read(stream, 1024));
    check_accounting(stream, whole);
    for (int cut = 0; cut < 6; ++cut) {
      const std::size_t max_chunk = pick_max_chunk(r);
      INFO("chunks up to " << max_chunk);
      CHECK(read(chop(stream, r, max_chunk)) == whole);
    }
    if (seed_value % 5 == 0) CHECK(read_bytewise(stream) == whole);
    // A capacity smaller than some lines.
    const outcome small = read<24>(stream);
    CHECK(small == reference_read(stream, 24));
    CHECK(read<24>(chop(stream, r, pick_max_chunk(r))) == small);
  }
}

TEST_CASE("what was sent comes out in order whatever garbage is between", "[anello][stream]") {
  for (std::uint64_t seed_value = 1000; seed_value < 1100; ++seed_value) {
    prng r{seed_value};
    std::string stream;
    std::vector<rec> sent;
    for (int piece = 0; piece < 40; ++piece) {
      if (r.chance(50)) {
        const std::string_view l = sample_lines[r.below(std::size(sample_lines))];
        // A '!' starts a sentence only between items: a line break first ends whatever the
        // garbage before left open (a '$' would interrupt it).
        if (l[0] == '!') stream += '\n';
        sent.push_back(sentence(l, stream.size(), line_ending::crlf, 0));
        stream += l;
        stream += r.chance(50) ? "\r\n" : "\n";
      } else {
        const frame_bytes f = random_frame(r);
        sent.push_back(frame(f, stream.size()));
        stream += str(f);
      }
      // False syncs, cut frames, partial sentences, bytes that end lines; the items it holds
      // may come out too, between the ones sent.
      stream += random_stream(r, r.below(4));
    }
    INFO("seed " << seed_value);
    const outcome o = read(chop(stream, r, pick_max_chunk(r)));
    CHECK(in_order(sent, o.items));
  }
}

TEST_CASE("drop reports: one per event, where it happened, in order", "[anello][stream]") {
  const std::string bad_crc = "\xAB\x00\x00\x30"s + std::string(52, 'x');
  const std::string stream = "junk\r\n$A*00\r\n$B\x01zz\rxx$C,1$D*00\n\xAB\x01hi\n"s +
                             "\xAB\x00\x00\x31\r\n"s + bad_crc + "\n$" + std::string(30, 'E') +
                             "tail\r\n\xAB\x00\x00"s;
  const outcome o = read<24>(stream, true);
  const std::vector<rec> want{
      drop(drop_reason::noise, 0, 4, "junk", 1),
      sentence("$A*00", 6, line_ending::crlf, 2),
      drop(drop_reason::invalid_byte, 13, 5, "$B\x01zz", 3),
      drop(drop_reason::noise, 19, 2, "xx", 4),
      drop(drop_reason::interrupted, 21, 4, "$C,1", 4),
      sentence("$D*00", 25, line_ending::lf, 4),
      drop(drop_reason::noise, 31, 4, "\xAB\x01hi", 5),
      drop(drop_reason::bad_length, 36, 3, "\xAB\x00\x00\x31"s, 6),
      drop(drop_reason::noise, 39, 1, "\x31", 6),
      drop(drop_reason::bad_crc, 42, 1, bad_crc, 7),
      drop(drop_reason::noise, 43, 55, bad_crc.substr(1), 7),
      drop(drop_reason::overlong, 99, 35, "$" + std::string(30, 'E') + "tail", 8),
      drop(drop_reason::truncated_frame, 136, 1, "\xAB\x00\x00"s, 9),
      drop(drop_reason::noise, 137, 2, "\x00\x00"s, 9),
  };
  CHECK(o.items == want);
  check_accounting(stream, o);
  CHECK(o == reference_read(stream, 24, true));
  CHECK(read_bytewise<24>(stream, true) == o);
  CHECK(without_drops(o) == read<24>(stream));

  SECTION("which reports are about a frame candidate") {
    for (const rec& r : want) {
      const bool frame = r.reason == drop_reason::bad_crc || r.reason == drop_reason::bad_length ||
                         r.reason == drop_reason::truncated_frame;
      CHECK(stream_drop{r.reason}.of_frame() == (r.kind == stream_item_kind::dropped && frame));
    }
  }
  SECTION("off by default, and reset keeps the setting") {
    stream_reader<> r;
    CHECK_FALSE(r.reports_drops());
    r.feed("junk\r\n$A\r\n"sv);
    auto item = r.next();
    REQUIRE(item.has_value());
    CHECK(item->is_sentence());
    r.report_drops(true);
    r.reset();
    CHECK(r.reports_drops());
    r.feed("junk\r\n"sv);
    item = r.next();  // the run ends at the CR
    REQUIRE(item.has_value());
    CHECK(own(*item) == drop(drop_reason::noise, 0, 4, "junk", 1));
    CHECK_FALSE(r.next().has_value());
    CHECK_FALSE(r.finish().has_value());
  }
  SECTION("a noise run is reported when it ends, whatever the chunks") {
    stream_reader<> r;
    r.report_drops(true);
    r.feed("ab"sv);
    CHECK_FALSE(r.next().has_value());
    r.feed("cd"sv);
    CHECK_FALSE(r.next().has_value());
    r.feed("e$A\n"sv);
    auto item = r.next();
    REQUIRE(item.has_value());
    CHECK(own(*item) == drop(drop_reason::noise, 0, 5, "abcde", 1));
    item = r.next();
    REQUIRE(item.has_value());
    CHECK(own(*item) == sentence("$A", 5, line_ending::lf, 1));
  }
  SECTION("an AB that starts no frame is noise in the run around it; AB 00 ends the run") {
    const outcome n = read(
        "ab\xAB"
        "cd\r\nxy\xAB\x00\x00\x30zz\r\n"s,
        true);
    CHECK(n.items ==
          std::vector<rec>{drop(drop_reason::noise, 0, 5,
                                "ab\xAB"
                                "cd",
                                1),
                           drop(drop_reason::noise, 7, 2, "xy", 2),
                           drop(drop_reason::truncated_frame, 9, 1, "\xAB\x00\x00\x30zz\r\n"s, 2),
                           drop(drop_reason::noise, 10, 5, "\x00\x00\x30zz"s, 2)});
    CHECK(read_bytewise("ab\xAB"
                        "cd\r\nxy\xAB\x00\x00\x30zz\r\n"s,
                        true) == n);
  }
  SECTION("turned off while a run is open: no report") {
    stream_reader<> r;
    r.report_drops(true);
    r.feed("abc"sv);
    CHECK_FALSE(r.next().has_value());
    r.report_drops(false);
    r.feed("de$A\n"sv);
    const auto item = r.next();
    REQUIRE(item.has_value());
    CHECK(item->is_sentence());
  }
  SECTION("a long run shows its first 256 bytes and counts them all") {
    const std::string noise(1000, '#');
    const outcome n = read(noise + "\n", true);
    CHECK(n.items == std::vector<rec>{drop(drop_reason::noise, 0, 1000, noise.substr(0, 256), 1)});
  }
}

TEST_CASE("drop reports match the reference for every chunking", "[anello][stream]") {
  for (std::uint64_t seed_value = 2000; seed_value < 2120; ++seed_value) {
    prng r{seed_value};
    const std::string stream = random_stream(r, 20 + r.below(150));
    INFO("seed " << seed_value << ", " << stream.size() << " bytes");
    const outcome whole = read(stream, true);
    CHECK(whole == reference_read(stream, 1024, true));
    CHECK(without_drops(whole) == read(stream));
    check_accounting(stream, whole);
    std::uint64_t last = 0;
    bool first = true;
    for (const rec& it : whole.items) {
      // In stream order, and a drop shows the stream's own bytes at its offset.
      CHECK((first || it.offset > last));
      first = false;
      last = it.offset;
      if (it.kind == stream_item_kind::dropped)
        CHECK(stream.substr(it.offset, it.text.size()) == it.text);
    }
    for (int cut = 0; cut < 4; ++cut) {
      CHECK(read(chop(stream, r, pick_max_chunk(r)), true) == whole);
    }
    const outcome small = read<24>(stream, true);
    CHECK(small == reference_read(stream, 24, true));
    CHECK(read<24>(chop(stream, r, pick_max_chunk(r)), true) == small);
  }
}

TEST_CASE("frames carry the line they start on", "[anello][stream]") {
  sensor_frame_raw raw;
  raw.heading = 0x0D0A;  // CR LF inside the frame are no line breaks
  const frame_bytes f = encode_frame(raw);
  const std::string stream = "$A\r\n"s + str(f) + str(f) + "\n\n"s + str(seed);
  stream_reader<> r;
  std::vector<std::uint64_t> lines;
  r.feed(stream, [&](const stream_item& item) {
    CHECK(item.is_frame() == (item.offset != 0));
    lines.push_back(item.line);
  });
  r.finish([](const stream_item&) { FAIL("nothing is pending"); });
  CHECK(lines == std::vector<std::uint64_t>{1, 2, 2, 4});
}

TEST_CASE("bytes, callbacks, reset", "[anello][stream]") {
  std::vector<std::uint8_t> bytes(seed.begin(), seed.end());
  for (const char c : "$PAPGPSCTRL,1*11\r\n"sv) bytes.push_back(static_cast<std::uint8_t>(c));

  SECTION("std::span feed, one call per chunk") {
    stream_reader<> r;
    std::vector<rec> got;
    const std::span<const std::uint8_t> all(bytes);
    r.feed(all.first(30), [&](const stream_item& item) { got.push_back(own(item)); });
    r.feed(all.subspan(30), [&](const stream_item& item) { got.push_back(own(item)); });
    r.finish([&](const stream_item& item) { got.push_back(own(item)); });
    CHECK(got ==
          std::vector<rec>{frame(seed, 0), sentence(gpsctrl_line, 56, line_ending::crlf, 1)});
  }
  SECTION("reset forgets a partial frame, the offsets, lines and stats") {
    stream_reader<> r;
    r.feed("$X\r\n\xAB\x00\x00\x30\x01\x02"sv);
    while (r.next()) {
    }
    r.reset();
    CHECK(r.stats() == stream_stats{});
    r.feed(std::span<const std::uint8_t>(bytes));
    const auto a = r.next();
    REQUIRE(a.has_value());
    CHECK(own(*a) == frame(seed, 0));
    const auto b = r.next();
    REQUIRE(b.has_value());
    CHECK(own(*b) == sentence(gpsctrl_line, 56, line_ending::crlf, 1));
  }
  SECTION("the hex of a frame item is the spec's") {
    stream_reader<> r;
    r.feed(std::span<const std::uint8_t>(bytes));
    const auto a = r.next();
    REQUIRE(a.has_value());
    CHECK(hex_of(a->bytes) == seed_hex);
  }
}
