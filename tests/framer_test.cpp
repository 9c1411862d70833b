// SPDX-License-Identifier: BSL-1.0
#include "seawire/nmea/framer.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "support.hpp"

namespace {

using namespace support;

using seawire::nmea::framed_line;
using seawire::nmea::framer;
using seawire::nmea::framer_stats;
using seawire::nmea::line_ending;
using namespace std::string_view_literals;

// A framed_line that owns its text, so it outlives the framer's next call.
struct rec {
  std::string text;
  line_ending ending = line_ending::none;
  std::uint64_t line = 0;
  friend bool operator==(const rec&, const rec&) = default;
};

std::ostream& operator<<(std::ostream& os, const rec& r) {
  os << '{' << r.line << ' ' << ending_name(r.ending) << ' ';
  return quote_text(os, r.text) << '}';
}

rec own(const framed_line& l) { return {std::string(l.text), l.ending, l.line}; }

template <std::size_t N>
void drain(framer<N>& f, std::vector<rec>& out) {
  while (const auto l = f.next()) out.push_back(own(*l));
}

template <std::size_t N>
void finish(framer<N>& f, std::vector<rec>& out) {
  if (const auto l = f.finish()) out.push_back(own(*l));
  CHECK_FALSE(f.finish().has_value());  // once only
}

// Feeds `chunks` in order, then finishes.
template <std::size_t N = 1024>
std::vector<rec> frame(framer<N>& f, const std::vector<std::string_view>& chunks) {
  std::vector<rec> out;
  for (const auto c : chunks) {
    f.feed(c);
    drain(f, out);
  }
  finish(f, out);
  return out;
}

template <std::size_t N = 1024>
std::vector<rec> frame_bytewise(framer<N>& f, std::string_view stream) {
  std::vector<rec> out;
  for (std::size_t i = 0; i < stream.size(); ++i) {
    f.feed(stream.substr(i, 1));
    drain(f, out);
  }
  finish(f, out);
  return out;
}

std::uint64_t count_line_breaks(std::string_view s) {
  return static_cast<std::uint64_t>(std::count(s.begin(), s.end(), '\r') +
                                    std::count(s.begin(), s.end(), '\n'));
}

// The accounting identity the header promises: every byte lands in exactly one bucket.
void check_accounting(std::string_view stream, const std::vector<rec>& lines,
                      const framer_stats& st) {
  std::uint64_t text = 0;
  for (const auto& l : lines) text += l.text.size();
  CHECK(text + st.noise_bytes + st.dropped_bytes + count_line_breaks(stream) == stream.size());
  CHECK(st.sentences == lines.size());
}

// The framer's contract written as the plainest byte-at-a-time loop over a whole stream, for
// differential tests. It may peek ahead, so it never needs the framer's chunk-boundary states.
struct reference_result {
  std::vector<rec> lines;
  framer_stats stats;
};

reference_result reference_frame(std::string_view s, std::size_t capacity) {
  enum class st { idle, in, discard } state = st::idle;
  reference_result r;
  std::string cur;
  std::uint64_t line = 1;
  bool prev_cr = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n' && prev_cr) {
      prev_cr = false;
      continue;
    }
    prev_cr = false;
    if (c == '\r' || c == '\n') {
      if (state == st::in) {
        line_ending e = line_ending::lf;
        if (c == '\r')
          e = i + 1 < s.size() && s[i + 1] == '\n' ? line_ending::crlf : line_ending::cr;
        r.lines.push_back({cur, e, line});
        ++r.stats.sentences;
      }
      state = st::idle;
      ++line;
      prev_cr = c == '\r';
      continue;
    }
    // '$' starts a sentence anywhere (interrupting one); '!' only between sentences: inside
    // one it is text, and in a discarded rest it is discarded.
    if (c == '$' || (c == '!' && state == st::idle)) {
      // The sentence before a '$' comes out if its "*hh" is complete: it lacks only its ending.
      const bool checksummed =
          cur.size() >= 5 && cur[cur.size() - 3] == '*' &&
          std::isxdigit(static_cast<unsigned char>(cur[cur.size() - 2])) != 0 &&
          std::isxdigit(static_cast<unsigned char>(cur.back())) != 0;
      if (state == st::in && checksummed) {
        r.lines.push_back({cur, line_ending::none, line});
        ++r.stats.sentences;
      } else if (state == st::in) {
        ++r.stats.interrupted;
        r.stats.dropped_bytes += cur.size();
      }
      state = st::in;
      cur = std::string(1, c);
      continue;
    }
    switch (state) {
      case st::idle: ++r.stats.noise_bytes; break;
      case st::discard: ++r.stats.dropped_bytes; break;
      case st::in:
        if (u < 0x20 || u > 0x7E) {
          ++r.stats.invalid_bytes;
          r.stats.dropped_bytes += cur.size() + 1;
          state = st::discard;
        } else {
          cur += c;
          if (cur.size() > capacity) {
            ++r.stats.overlong;
            r.stats.dropped_bytes += cur.size();
            state = st::discard;
          }
        }
        break;
    }
  }
  if (state == st::in) {
    r.lines.push_back({cur, line_ending::none, line});
    ++r.stats.sentences;
  }
  return r;
}

}  // namespace

// ADL cannot see a printer for a seawire type from here, so tell Catch directly.
namespace Catch {
template <>
struct StringMaker<framer_stats> {
  static std::string convert(const framer_stats& s) {
    return "{sentences " + std::to_string(s.sentences) + ", noise " +
           std::to_string(s.noise_bytes) + ", interrupted " + std::to_string(s.interrupted) +
           ", overlong " + std::to_string(s.overlong) + ", invalid " +
           std::to_string(s.invalid_bytes) + ", dropped " + std::to_string(s.dropped_bytes) + "}";
  }
};
}  // namespace Catch

TEST_CASE("line endings: CRLF, LF, CR, mixed", "[framer]") {
  framer<> f;
  const auto out = frame(f, {"$A,1*00\r\n$B,2\n$C,3\r$D,4\r\n\n$E\r\r\n$F\n"sv});
  const std::vector<rec> want{
      {"$A,1*00", line_ending::crlf, 1}, {"$B,2", line_ending::lf, 2}, {"$C,3", line_ending::cr, 3},
      {"$D,4", line_ending::crlf, 4},    {"$E", line_ending::cr, 6},   {"$F", line_ending::lf, 8},
  };
  CHECK(out == want);
  CHECK(f.stats() == framer_stats{6, 0, 0, 0, 0, 0});
}

TEST_CASE("a lone '$' and an empty-bodied line are candidates too", "[framer]") {
  framer<> f;
  const auto out = frame(f, {"$\r\n$,*\n"sv});
  CHECK(out == std::vector<rec>{{"$", line_ending::crlf, 1}, {"$,*", line_ending::lf, 2}});
}

TEST_CASE("CR LF split across chunks", "[framer]") {
  SECTION("sentence CR | LF is one CR LF ending") {
    framer<> f;
    f.feed("$GPRMC,1*00\r");
    CHECK_FALSE(f.next().has_value());  // held: the next chunk decides CR vs CR LF
    f.feed("\n$GPGGA,2\r\n");
    auto l = f.next();
    REQUIRE(l.has_value());
    CHECK(own(*l) == rec{"$GPRMC,1*00", line_ending::crlf, 1});
    l = f.next();
    REQUIRE(l.has_value());
    CHECK(own(*l) == rec{"$GPGGA,2", line_ending::crlf, 2});
    CHECK_FALSE(f.next().has_value());
    CHECK_FALSE(f.finish().has_value());
  }
  SECTION("sentence CR | '$' is a bare CR") {
    framer<> f;
    CHECK(frame(f, {"$A\r"sv, "$B\r\n"sv}) ==
          std::vector<rec>{{"$A", line_ending::cr, 1}, {"$B", line_ending::crlf, 2}});
  }
  SECTION("sentence CR | empty chunk | LF") {
    framer<> f;
    CHECK(frame(f, {"$A\r"sv, ""sv, ""sv, "\n"sv, "$B\n"sv}) ==
          std::vector<rec>{{"$A", line_ending::crlf, 1}, {"$B", line_ending::lf, 2}});
  }
  SECTION("sentence CR | LF LF: the second LF is a blank line") {
    framer<> f;
    CHECK(frame(f, {"$A\r"sv, "\n\n$B\n"sv}) ==
          std::vector<rec>{{"$A", line_ending::crlf, 1}, {"$B", line_ending::lf, 3}});
  }
  SECTION("sentence CR then end of stream") {
    framer<> f;
    CHECK(frame(f, {"$A\r"sv}) == std::vector<rec>{{"$A", line_ending::cr, 1}});
  }
  SECTION("noise CR | LF counts one line") {
    framer<> f;
    CHECK(frame(f, {"junk\r"sv, "\n$B\r\n"sv}) == std::vector<rec>{{"$B", line_ending::crlf, 2}});
    CHECK(f.stats().noise_bytes == 4);
  }
  SECTION("dropped line CR | LF counts one line") {
    framer<> f;
    CHECK(frame(f, {"$BAD\x01line\r"sv, "\n$B\r\n"sv}) ==
          std::vector<rec>{{"$B", line_ending::crlf, 2}});
    CHECK(f.stats().invalid_bytes == 1);
    CHECK(f.stats().dropped_bytes == 9);
  }
  SECTION("sentence split mid-text, ending split too") {
    framer<> f;
    CHECK(frame(f, {"$GP"sv, "RMC,"sv, "1\r"sv, "\n"sv}) ==
          std::vector<rec>{{"$GPRMC,1", line_ending::crlf, 1}});
  }
}

namespace {
// "$A" ended by a CR, the link quiet (flushed), then `rest`: the lines `rest` yields.
std::vector<rec> after_flushed_cr(std::string_view rest) {
  framer<> f;
  std::vector<rec> out;
  f.feed("$A\r");
  drain(f, out);
  REQUIRE(f.flush().has_value());
  f.feed(rest);
  drain(f, out);
  CHECK(f.stats().noise_bytes == 0);
  return out;
}
}  // namespace

TEST_CASE("flush(): a line held on its CR comes out when the link goes quiet", "[framer]") {
  SECTION("CR-only sender: each line comes out at once, LF-free") {
    framer<> f;
    std::vector<rec> out;
    f.feed("$A,1*00\r");
    CHECK_FALSE(f.next().has_value());
    const auto l = f.flush();
    REQUIRE(l.has_value());
    CHECK(own(*l) == rec{"$A,1*00", line_ending::cr, 1});
    CHECK_FALSE(f.flush().has_value());  // once
    f.feed("$B\r");
    drain(f, out);
    CHECK(out.empty());
    const auto b = f.flush();
    REQUIRE(b.has_value());
    CHECK(own(*b) == rec{"$B", line_ending::cr, 2});
    CHECK(f.stats().sentences == 2);
  }
  SECTION("the LF that comes after all the same completes the break: no blank line") {
    CHECK(after_flushed_cr("\n$B\r\n") == std::vector<rec>{{"$B", line_ending::crlf, 2}});
  }
  SECTION("LF LF after: the second is a blank line") {
    CHECK(after_flushed_cr("\n\n$B\n") == std::vector<rec>{{"$B", line_ending::lf, 3}});
  }
  SECTION("nothing held: a sentence without its ending keeps waiting") {
    framer<> f;
    std::vector<rec> out;
    f.feed("$A,1");
    drain(f, out);
    CHECK_FALSE(f.flush().has_value());
    f.feed("2\r\n");
    drain(f, out);
    CHECK(out == std::vector<rec>{{"$A,12", line_ending::crlf, 1}});
    CHECK_FALSE(f.flush().has_value());  // idle
    CHECK_FALSE(f.finish().has_value());
  }
}

TEST_CASE("byte-by-byte feeding gives the same lines and stats as one chunk", "[framer]") {
  const std::string_view stream =
      "noise\r\n$GPRMC,123519,A*6A\r\n\r\n$PYDIR,45,55*57\n$BF\x80X\r\n$GP$GPGGA,1\r"
      "$CPNVG,1\r\nxx$END"sv;
  framer<> whole;
  const auto a = frame(whole, {stream});
  framer<> bytes;
  const auto b = frame_bytewise(bytes, stream);
  CHECK(a == b);
  CHECK(whole.stats() == bytes.stats());
  const std::vector<rec> want{
      {"$GPRMC,123519,A*6A", line_ending::crlf, 2},
      {"$PYDIR,45,55*57", line_ending::lf, 4},
      {"$GPGGA,1", line_ending::cr, 6},
      {"$CPNVG,1", line_ending::crlf, 7},
      {"$END", line_ending::none, 8},
  };
  CHECK(a == want);
  CHECK(whole.stats() == framer_stats{5, 7, 1, 0, 1, 3 + 5});
  check_accounting(stream, a, whole.stats());
}

TEST_CASE("garbage before '$' is noise; CR and LF only count lines", "[framer]") {
  framer<> f;
  const auto out = frame(f, {"\x00\xff garbage*,\r\n\n\rmore\x80$GPRMC,1\r\n"sv});
  CHECK(out == std::vector<rec>{{"$GPRMC,1", line_ending::crlf, 4}});
  CHECK(f.stats().noise_bytes == 2 + 10 + 5);
  CHECK(f.stats().dropped_bytes == 0);
}

TEST_CASE("'$' in the middle restarts the sentence", "[framer]") {
  SECTION("in one chunk") {
    framer<> f;
    CHECK(frame(f, {"$GPRMC,12$GPGGA,1*00\r\n"sv}) ==
          std::vector<rec>{{"$GPGGA,1*00", line_ending::crlf, 1}});
    CHECK(f.stats() == framer_stats{1, 0, 1, 0, 0, 9});
  }
  SECTION("partial sentence buffered from an earlier chunk") {
    framer<> f;
    CHECK(frame(f, {"$GPR"sv, "MC,12"sv, "$GPGGA"sv, ",1\n"sv}) ==
          std::vector<rec>{{"$GPGGA,1", line_ending::lf, 1}});
    CHECK(f.stats() == framer_stats{1, 0, 1, 0, 0, 9});
  }
  SECTION("'$$$'") {
    framer<> f;
    CHECK(frame(f, {"$$$A\n"sv}) == std::vector<rec>{{"$A", line_ending::lf, 1}});
    CHECK(f.stats() == framer_stats{1, 0, 2, 0, 0, 2});
  }
}

TEST_CASE("a '$' right after a whole \"*hh\" ends that sentence: only its line ending is missing",
          "[framer]") {
  const std::string_view stream = "$PYDIR,45,55*57$PYDIR,0,0*56\r\n$A*6f$B*4e"sv;
  const std::vector<rec> want{{"$PYDIR,45,55*57", line_ending::none, 1},
                              {"$PYDIR,0,0*56", line_ending::crlf, 1},
                              {"$A*6f", line_ending::none, 2},  // lower-case hex is hex
                              {"$B*4e", line_ending::none, 2}};
  framer<> f;
  CHECK(frame(f, {stream}) == want);
  CHECK(f.stats() == framer_stats{4, 0, 0, 0, 0, 0});
  // However the stream is cut: the checksum may lie in an earlier chunk than the '$'.
  for (std::size_t cut = 1; cut < stream.size(); ++cut) {
    INFO("cut at " << cut);
    framer<> g;
    CHECK(frame(g, {stream.substr(0, cut), stream.substr(cut)}) == want);
    framer<> h;
    CHECK(frame_bytewise(h, stream) == want);
  }
  // Anything short of two hex digits after the '*' may be a sentence cut short: dropped.
  for (const std::string_view cut :
       {"$A,1*5"sv, "$A,1*"sv, "$A,1*5G"sv, "$A,1*G5"sv, "$A,15"sv, "$*5"sv, "$*57"sv}) {
    INFO(cut);
    framer<> g;
    CHECK(frame(g, {std::string(cut) + "$B*42\n"}) ==
          std::vector<rec>{{"$B*42", line_ending::lf, 1}});
    CHECK(g.stats().interrupted == 1);
    CHECK(g.stats().dropped_bytes == cut.size());
  }
  // A '!' after the checksum is no start (inside a sentence it is text): the line goes on, and
  // its parse says what follows the checksum.
  framer<> g;
  CHECK(frame(g, {"$A*41!AIVDM,1*00\n"sv}) ==
        std::vector<rec>{{"$A*41!AIVDM,1*00", line_ending::lf, 1}});
}

TEST_CASE("'!' starts a sentence where '$' would: between sentences and in noise", "[framer]") {
  constexpr std::string_view ais = "!AIVDM,1,1,,B,15M67FC000G?ufbE`vJ8?wv4R0<4,0*10"sv;
  SECTION("alone") {
    framer<> f;
    const std::string stream = std::string(ais) + "\r\n";
    const auto out = frame(f, {stream});
    CHECK(out == std::vector<rec>{{std::string(ais), line_ending::crlf, 1}});
    CHECK(f.stats() == framer_stats{1, 0, 0, 0, 0, 0});
  }
  SECTION("mixed with '$' sentences, in a log") {
    framer<> f;
    const std::string stream = "$GPRMC,1*00\r\n" + std::string(ais) + "\r\n!AIVDO,1\n$GPGGA,2\r";
    const auto out = frame(f, {stream});
    CHECK(out == std::vector<rec>{{"$GPRMC,1*00", line_ending::crlf, 1},
                                  {std::string(ais), line_ending::crlf, 2},
                                  {"!AIVDO,1", line_ending::lf, 3},
                                  {"$GPGGA,2", line_ending::cr, 4}});
    CHECK(f.stats() == framer_stats{4, 0, 0, 0, 0, 0});
    framer<> g;
    CHECK(frame_bytewise(g, stream) == out);
    CHECK(g.stats() == f.stats());
  }
  SECTION("after noise, which it ends") {
    framer<> f;
    CHECK(frame(f, {"junk!AIVDM,1\r\n\x01!!B\n"sv}) ==
          std::vector<rec>{{"!AIVDM,1", line_ending::crlf, 1}, {"!!B", line_ending::lf, 2}});
    CHECK(f.stats() == framer_stats{2, 5, 0, 0, 0, 0});
  }
  SECTION("a lone '!' is a candidate, as a lone '$' is") {
    framer<1> f;
    CHECK(frame(f, {"!\n!A\n!"sv}) ==
          std::vector<rec>{{"!", line_ending::lf, 1}, {"!", line_ending::none, 3}});
    CHECK(f.stats() == framer_stats{2, 0, 0, 1, 0, 2});
  }
}

TEST_CASE("'!' inside a sentence is text: it neither interrupts nor starts one", "[framer]") {
  SECTION("in a '$' sentence's text field") {
    framer<> f;
    const std::string_view stream = "$BFMIS,Mission done!,ok!\r\n$A!\n"sv;
    CHECK(frame(f, {stream}) == std::vector<rec>{{"$BFMIS,Mission done!,ok!", line_ending::crlf, 1},
                                                 {"$A!", line_ending::lf, 2}});
    CHECK(f.stats() == framer_stats{2, 0, 0, 0, 0, 0});
  }
  SECTION("in a '!' sentence") {
    framer<> f;
    CHECK(frame(f, {"!AB!CD!\n"sv}) == std::vector<rec>{{"!AB!CD!", line_ending::lf, 1}});
    CHECK(f.stats().interrupted == 0);
  }
  SECTION("'$' still interrupts a '!' sentence") {
    framer<> f;
    CHECK(frame(f, {"!AIVDM,1$GPGGA\n"sv}) == std::vector<rec>{{"$GPGGA", line_ending::lf, 1}});
    CHECK(f.stats() == framer_stats{1, 0, 1, 0, 0, 8});
  }
  SECTION("in a discarded rest: dropped with it, no new sentence") {
    framer<> f;
    CHECK(frame(f, {"$A\x01x!AIVDM\n!B\n"sv}) == std::vector<rec>{{"!B", line_ending::lf, 2}});
    CHECK(f.stats() == framer_stats{1, 0, 0, 0, 1, 3 + 7});
    framer<4> g;
    CHECK(frame(g, {"!ABCD!EF\n!B\n"sv}) == std::vector<rec>{{"!B", line_ending::lf, 2}});
    CHECK(g.stats() == framer_stats{1, 0, 0, 1, 0, 8});
  }
  SECTION("past the capacity, it is the byte that makes the line overlong") {
    framer<4> f;
    CHECK(frame(f, {"$ABC!\n"sv}).empty());
    CHECK(f.stats() == framer_stats{0, 0, 0, 1, 0, 5});
  }
}

TEST_CASE("'!' split across chunks", "[framer]") {
  SECTION("a '!' sentence cut after its '!', after noise") {
    framer<> f;
    CHECK(frame(f, {"junk"sv, "!"sv, "AIV"sv, "DM\r"sv, "\n"sv}) ==
          std::vector<rec>{{"!AIVDM", line_ending::crlf, 1}});
    CHECK(f.stats() == framer_stats{1, 4, 0, 0, 0, 0});
  }
  SECTION("a '!' that begins a chunk inside a '$' sentence is text") {
    framer<> f;
    CHECK(frame(f, {"$BF,hi"sv, "!"sv, " there\n"sv}) ==
          std::vector<rec>{{"$BF,hi! there", line_ending::lf, 1}});
  }
  SECTION("after a CR held at a chunk's end: the next sentence") {
    framer<> f;
    CHECK(frame(f, {"$A\r"sv, "!B\n"sv}) ==
          std::vector<rec>{{"$A", line_ending::cr, 1}, {"!B", line_ending::lf, 2}});
  }
  SECTION("in a discarded rest that a chunk boundary cuts") {
    framer<> f;
    CHECK(frame(f, {"$A\x01"sv, "!"sv, "B\n!C\n"sv}) ==
          std::vector<rec>{{"!C", line_ending::lf, 2}});
    CHECK(f.stats() == framer_stats{1, 0, 0, 0, 1, 5});
  }
  SECTION("a chunk of noise, then a '!' 20 bytes in (the 16-byte scan)") {
    framer<> f;
    const std::string noise(20, '#');
    const std::string stream = noise + "!A\n" + std::string(40, '%') + "!B";
    CHECK(frame(f, {stream}) ==
          std::vector<rec>{{"!A", line_ending::lf, 1}, {"!B", line_ending::none, 2}});
    CHECK(f.stats().noise_bytes == 60);
  }
}

TEST_CASE("NUL, control and 8-bit bytes drop the sentence", "[framer]") {
  const auto bad =
      GENERATE("\x00"sv, "\x01"sv, "\t"sv, "\x1b"sv, "\x7f"sv, "\x80"sv, "\xc3"sv, "\xff"sv);
  std::string stream = "$GP";
  stream += bad;
  stream += "RMC,1*00\r\n$OK,1\r\n";
  framer<> f;
  const auto out = frame(f, {stream});
  CHECK(out == std::vector<rec>{{"$OK,1", line_ending::crlf, 2}});
  CHECK(f.stats() == framer_stats{1, 0, 0, 0, 1, 3 + 1 + 8});
  check_accounting(stream, out, f.stats());
  framer<> g;
  CHECK(frame_bytewise(g, stream) == out);
  CHECK(g.stats() == f.stats());
}

TEST_CASE("a '$' after an invalid byte starts a fresh sentence", "[framer]") {
  framer<> f;
  CHECK(frame(f, {"$A\x00xx$B\n"sv}) == std::vector<rec>{{"$B", line_ending::lf, 1}});
  CHECK(f.stats() == framer_stats{1, 0, 0, 0, 1, 5});
}

TEST_CASE("a 1 MiB line without terminator between valid sentences", "[framer]") {
  std::string stream = "$GPRMC,1*00\r\n$";
  stream.append(std::size_t{1} << 20, 'X');
  stream += "$GPGGA,2*00\r\n$GPVTG,3\r\n";
  const std::uint64_t huge = (std::uint64_t{1} << 20) + 1;
  const std::vector<rec> want{
      {"$GPRMC,1*00", line_ending::crlf, 1},
      {"$GPGGA,2*00", line_ending::crlf, 2},
      {"$GPVTG,3", line_ending::crlf, 3},
  };
  SECTION("one chunk, default capacity") {
    framer<> f;
    CHECK(frame(f, {stream}) == want);
    CHECK(f.stats() == framer_stats{3, 0, 0, 1, 0, huge});
  }
  SECTION("4 KiB chunks, NMEA-sized capacity") {
    framer<82> f;
    std::vector<std::string_view> chunks;
    const std::string_view all = stream;
    for (std::size_t i = 0; i < all.size(); i += 4096) chunks.push_back(all.substr(i, 4096));
    CHECK(frame(f, chunks) == want);
    CHECK(f.stats() == framer_stats{3, 0, 0, 1, 0, huge});
  }
  SECTION("terminated by CR LF instead") {
    std::string s2 = "$";
    s2.append(std::size_t{1} << 20, 'Y');
    s2 += "\r\n$OK\r\n";
    framer<> f;
    CHECK(frame(f, {s2}) == std::vector<rec>{{"$OK", line_ending::crlf, 2}});
    CHECK(f.stats() == framer_stats{1, 0, 0, 1, 0, huge});
  }
}

TEST_CASE("capacity boundary: exactly Capacity fits, one more is overlong", "[framer]") {
  const std::string fits = "$" + std::string(7, 'a');  // 8 bytes
  const std::string over = "$" + std::string(8, 'b');  // 9 bytes
  const std::string stream = fits + "\r\n" + over + "\r\n" + fits + "\n";
  SECTION("in one chunk") {
    framer<8> f;
    CHECK(frame(f, {stream}) ==
          std::vector<rec>{{fits, line_ending::crlf, 1}, {fits, line_ending::lf, 3}});
    CHECK(f.stats() == framer_stats{2, 0, 0, 1, 0, 9});
  }
  SECTION("byte by byte") {
    framer<8> f;
    CHECK(frame_bytewise(f, stream) ==
          std::vector<rec>{{fits, line_ending::crlf, 1}, {fits, line_ending::lf, 3}});
    CHECK(f.stats() == framer_stats{2, 0, 0, 1, 0, 9});
  }
  SECTION("the byte past the capacity decides: invalid there is invalid, not overlong") {
    framer<8> f;
    CHECK(frame(f, {fits + "\x01zz\n$A\n"}).size() == 1);
    CHECK(f.stats() == framer_stats{1, 0, 0, 0, 1, 11});
  }
  SECTION("an invalid byte past the capacity is just discarded with the overlong line") {
    framer<8> f;
    CHECK(frame(f, {over + "\x01zz\n$A\n"}).size() == 1);
    CHECK(f.stats() == framer_stats{1, 0, 0, 1, 0, 12});
  }
  SECTION("capacity 1 holds only '$'") {
    framer<1> f;
    CHECK(frame(f, {"$\n$A\n$\r"sv}) ==
          std::vector<rec>{{"$", line_ending::lf, 1}, {"$", line_ending::cr, 3}});
    CHECK(f.stats() == framer_stats{2, 0, 0, 1, 0, 2});
  }
}

TEST_CASE("finish()", "[framer]") {
  SECTION("yields a pending unterminated sentence once") {
    framer<> f;
    f.feed("$A\r\n$GPRMC,1");
    auto l = f.next();
    REQUIRE(l.has_value());
    CHECK_FALSE(f.next().has_value());
    l = f.finish();
    REQUIRE(l.has_value());
    CHECK(own(*l) == rec{"$GPRMC,1", line_ending::none, 2});
    CHECK_FALSE(f.finish().has_value());
    CHECK(f.stats().sentences == 2);
  }
  SECTION("nothing pending") {
    framer<> f;
    CHECK_FALSE(f.finish().has_value());
    f.feed("$A\r\njunk");
    CHECK(f.next().has_value());
    CHECK_FALSE(f.next().has_value());
    CHECK_FALSE(f.finish().has_value());
  }
  SECTION("an overlong line in progress yields nothing") {
    framer<4> f;
    CHECK(frame(f, {"$ABCDEFG"sv}).empty());
    CHECK(f.stats() == framer_stats{0, 0, 0, 1, 0, 8});
  }
  SECTION("an invalid line in progress yields nothing") {
    framer<> f;
    CHECK(frame(f, {"$AB\xff"sv}).empty());
    CHECK(f.stats() == framer_stats{0, 0, 0, 0, 1, 4});
  }
  SECTION("a held CR line ends with CR") {
    framer<> f;
    f.feed("$A,1\r");
    CHECK_FALSE(f.next().has_value());
    const auto l = f.finish();
    REQUIRE(l.has_value());
    CHECK(own(*l) == rec{"$A,1", line_ending::cr, 1});
  }
}

TEST_CASE("line numbers count CR, LF and CR LF alike, including inside dropped lines", "[framer]") {
  framer<4> f;
  const auto out = frame(f, {"\n\r\r\n$TOOLONG\n$\x01\r\n$A\n\n$B"sv});
  CHECK(out == std::vector<rec>{{"$A", line_ending::lf, 6}, {"$B", line_ending::none, 8}});
}

TEST_CASE("lines wholly inside a chunk are views into it; split lines come from the buffer",
          "[framer]") {
  const std::string_view chunk1 = "$IN,1\r\n$SPLIT,"sv;
  const std::string_view chunk2 = "2\r\n$IN,3\r"sv;
  framer<> f;
  f.feed(chunk1);
  auto l = f.next();
  REQUIRE(l.has_value());
  CHECK(l->text.data() == chunk1.data());
  CHECK_FALSE(f.next().has_value());
  f.feed(chunk2);
  l = f.next();
  REQUIRE(l.has_value());
  CHECK(l->text == "$SPLIT,2");
  CHECK((l->text.data() < chunk2.data() || l->text.data() >= chunk2.data() + chunk2.size()));
  // The held CR line cannot be a view: chunk2 may be gone by the time "\n" shows up.
  CHECK_FALSE(f.next().has_value());
  f.feed("\n");
  l = f.next();
  REQUIRE(l.has_value());
  CHECK(own(*l) == rec{"$IN,3", line_ending::crlf, 3});
}

TEST_CASE("feed with a callback drains the chunk", "[framer]") {
  framer<> f;
  std::vector<rec> out;
  const auto on_line = [&out](const framed_line& l) { out.push_back(own(l)); };
  f.feed("$A\r\n$B", on_line);
  f.feed("\n$C\r", on_line);
  f.feed("\n", on_line);
  CHECK(out == std::vector<rec>{{"$A", line_ending::crlf, 1},
                                {"$B", line_ending::lf, 2},
                                {"$C", line_ending::crlf, 3}});
}

TEST_CASE("reset() starts a new stream", "[framer]") {
  framer<> f;
  f.feed("junk\n$PARTIAL");
  CHECK_FALSE(f.next().has_value());
  f.reset();
  CHECK(f.stats() == framer_stats{});
  CHECK(frame(f, {"$A\n"sv}) == std::vector<rec>{{"$A", line_ending::lf, 1}});
}

TEST_CASE("memory is the buffer and a few counters", "[framer]") {
  // The counters, the stream position, the 256 bytes a drop report shows and the item it hands
  // out (the framer is a stream_reader, which can report its drops): fixed, whatever the
  // capacity.
  constexpr std::size_t overhead = sizeof(framer<8>) - 8;
  STATIC_REQUIRE(overhead <= seawire::nmea::stream_drop::max_shown +
                                 sizeof(seawire::nmea::stream_item<>) + 256);
  STATIC_REQUIRE(sizeof(framer<1024>) <= 1024 + overhead + 8);
  STATIC_REQUIRE(sizeof(framer<65536>) <= 65536 + overhead + 8);
  STATIC_REQUIRE(framer<82>::capacity == 82);
}

namespace {

constexpr bool constexpr_framing() {
  framer<16> f;
  f.feed("xx$GPR");
  if (f.next()) return false;
  f.feed("MC,1\r\n$A\r");
  const auto a = f.next();
  if (!a || a->text != "$GPRMC,1" || a->ending != line_ending::crlf || a->line != 1) return false;
  if (f.next()) return false;
  f.feed("\n$THIS_IS_TOO_LONG_FOR_16\n$B");
  const auto b = f.next();
  if (!b || b->text != "$A" || b->ending != line_ending::crlf || b->line != 2) return false;
  if (f.next()) return false;
  const auto c = f.finish();
  if (!c || c->text != "$B" || c->ending != line_ending::none || c->line != 4) return false;
  return f.stats() == framer_stats{3, 2, 0, 1, 0, 24};
}

constexpr bool constexpr_bang_framing() {
  framer<16> f;
  f.feed("noise, long enough for the word scan!AIVDM,A!B\r\n$C\n");
  const auto a = f.next();
  if (!a || a->text != "!AIVDM,A!B" || a->ending != line_ending::crlf) return false;
  const auto c = f.next();
  if (!c || c->text != "$C" || c->line != 2) return false;
  return !f.next() && f.stats().noise_bytes == 36;
}

}  // namespace

TEST_CASE("usable in constant expressions", "[framer]") {
  STATIC_REQUIRE(constexpr_framing());
  STATIC_REQUIRE(constexpr_bang_framing());
}

namespace {

// Every position of a 40-byte run, every class of byte the scans must stop at. Run both in
// constant evaluation (the 64-bit word path) and at run time (SSE2 or NEON where the target has
// it). Constant evaluation tries three start offsets per position (Clang's step limit); run time,
// all.
constexpr bool scans_find_every_special(bool every_start) {
  using scan = seawire::nmea::detail::framer_scan;
  constexpr unsigned char specials[] = {0x00, 0x09, 0x0A, 0x0D, 0x1F, 0x21,
                                        0x24, 0x7F, 0x80, 0xC3, 0xFF};
  constexpr std::size_t n = 40;
  for (std::size_t at = 0; at < n; ++at) {
    for (const unsigned char sp : specials) {
      char s[n] = {};
      for (std::size_t i = 0; i < n; ++i) s[i] = static_cast<char>(0x20 + (i * 7) % 0x5F);
      for (std::size_t i = 0; i < n; ++i) {
        if (s[i] == '$' || s[i] == '!') s[i] = '~';
      }
      s[at] = static_cast<char>(sp);
      for (std::size_t from = 0;;) {
        // '!' is text inside a sentence: the scan passes it.
        const bool special = sp != '!';
        if (scan::find_special(s, from, n) != (special ? at : n)) return false;
        if (scan::find_special(s, from, at) != at) return false;
        if (from == at) break;
        from = every_start ? from + 1 : from < at / 2 ? at / 2 : at;
      }
    }
  }
  return true;
}

}  // namespace

TEST_CASE("scans stop at exactly the first special byte", "[framer]") {
  STATIC_REQUIRE(scans_find_every_special(false));
  CHECK(scans_find_every_special(true));
}

namespace {

// A stream built so that the right output is known by construction: valid sentences between
// garbage, NUL and 8-bit bytes, invalid sentences, interrupted ones, overlong ones, and one
// 1 MiB line that no line ending closes.
struct built_stream {
  std::string bytes;
  std::vector<rec> lines;
  framer_stats stats;
};

constexpr std::size_t property_capacity = 1024;

built_stream build_stream(std::uint64_t seed) {
  prng r{seed};
  built_stream b;
  struct pending {
    std::size_t dollar;  // offset of the sentence's '$'
    std::size_t ending;  // offset of its line ending, or npos
    std::string text;
  };
  std::vector<pending> valid;

  const auto printable = [&r] {
    char c = static_cast<char>(0x20 + r.below(0x5F));
    return c == '$' ? '#' : c;
  };
  const auto body = [&](std::size_t n) {
    std::string s;
    for (std::size_t i = 0; i < n; ++i) s += printable();
    return s;
  };
  const auto ending = [&r]() -> std::string_view {
    switch (r.below(3)) {
      case 0: return "\r\n";
      case 1: return "\n";
      default: return "\r";
    }
  };
  // '!' starts a sentence only between sentences; after one cut short, a '$' must do it.
  const auto add_valid = [&](bool terminated, bool bang_ok = true, std::string_view tail = {}) {
    const char start = bang_ok && r.chance(30) ? '!' : '$';
    // A checksum after at least one byte, else "$*hh" is no sentence with only its ending lost.
    pending p{b.bytes.size(), std::string::npos,
              start + body(r.below(120) + (tail.empty() ? 0 : 1))};
    p.text += tail;
    b.bytes += p.text;
    if (terminated) {
      p.ending = b.bytes.size();
      b.bytes += ending();
    }
    valid.push_back(std::move(p));
    ++b.stats.sentences;
  };
  const auto bad_byte = [&r] {
    constexpr std::string_view bad = "\x00\x01\t\x1b\x7f\x80\xc3\xfe\xff"sv;
    return bad[r.below(bad.size())];
  };

  const std::size_t segments = 40 + r.below(60);
  const std::size_t mib_at = r.below(segments);
  for (std::size_t k = 0; k < segments; ++k) {
    if (k == mib_at) {
      // 1 MiB, no line ending; bad bytes well past the capacity must not change its verdict.
      const std::size_t start = b.bytes.size();
      b.bytes += '$';
      b.bytes += body(std::size_t{1} << 20);
      for (int i = 0; i < 8; ++i)
        b.bytes[start + 4096 + r.below(std::size_t{1} << 19)] = bad_byte();
      ++b.stats.overlong;
      b.stats.dropped_bytes += b.bytes.size() - start;
      add_valid(true, false);  // the '$' that ends it
      continue;
    }
    const std::size_t kind = r.below(100);
    if (kind < 50) {
      add_valid(true);
    } else if (kind < 70) {  // garbage: anything but '$' and '!', CR and LF included
      const std::size_t n = r.below(200);
      for (std::size_t i = 0; i < n; ++i) {
        char c = static_cast<char>(r.below(256));
        if (c == '$' || c == '!') c = '\0';
        b.bytes += c;
        if (c != '\r' && c != '\n') ++b.stats.noise_bytes;
      }
    } else if (kind < 82) {  // invalid byte inside an otherwise short sentence
      std::string s = (r.chance(30) ? "!" : "$") + body(r.below(50));
      s += bad_byte();
      for (std::size_t i = 0, n = r.below(50); i < n; ++i) {
        char c = static_cast<char>(r.below(256));
        if (c == '$' || c == '\r' || c == '\n') c = 'x';
        if (r.chance(5)) c = '!';  // discarded with the rest: no start there
        s += c;
      }
      b.bytes += s;
      b.bytes += ending();
      ++b.stats.invalid_bytes;
      b.stats.dropped_bytes += s.size();
    } else if (kind < 88) {  // cut short by the next '$' (a '!' would be text)
      std::string s = (r.chance(30) ? "!" : "$") + body(r.below(property_capacity));
      if (s.size() >= 4 && s[s.size() - 3] == '*') s[s.size() - 3] = '#';  // a checksum's cut
      b.bytes += s;
      ++b.stats.interrupted;
      b.stats.dropped_bytes += s.size();
      add_valid(true, false);
    } else if (kind < 94) {  // a whole "*hh" sentence with no line ending before the next '$'
      constexpr std::string_view hex = "0123456789ABCDEFabcdef";
      const std::string checksum{'*', hex[r.below(hex.size())], hex[r.below(hex.size())]};
      add_valid(false, true, checksum);
      add_valid(true, false);
    } else {  // overlong but properly terminated
      const std::string s = (r.chance(30) ? "!" : "$") + body(property_capacity + r.below(3000));
      b.bytes += s;
      b.bytes += ending();
      ++b.stats.overlong;
      b.stats.dropped_bytes += s.size();
    }
  }
  if (seed % 2 == 1) add_valid(false);  // the stream stops mid-sentence: finish() yields it

  // Line numbers and CR-vs-CR LF follow from the finished bytes.
  std::uint64_t line = 1;
  std::size_t counted = 0;
  bool prev_cr = false;
  for (const auto& p : valid) {
    for (; counted < p.dollar; ++counted) {
      const char c = b.bytes[counted];
      if (c == '\r' || (c == '\n' && !prev_cr)) ++line;
      prev_cr = c == '\r';
    }
    line_ending e = line_ending::none;
    if (p.ending != std::string::npos) {
      if (b.bytes[p.ending] == '\n') {
        e = line_ending::lf;
      } else {
        const bool lf = p.ending + 1 < b.bytes.size() && b.bytes[p.ending + 1] == '\n';
        e = lf ? line_ending::crlf : line_ending::cr;
      }
    }
    b.lines.push_back({p.text, e, line});
  }
  return b;
}

}  // namespace

TEST_CASE("property: any chunking of a hostile stream yields exactly its valid sentences",
          "[framer][property]") {
  for (std::uint64_t stream_seed = 1; stream_seed <= 8; ++stream_seed) {
    const built_stream b = build_stream(stream_seed);
    INFO("stream seed " << stream_seed << ", " << b.bytes.size() << " bytes");
    REQUIRE(b.lines.size() > 20);

    // The construction itself must agree with the plain reference loop.
    const reference_result ref = reference_frame(b.bytes, property_capacity);
    REQUIRE(ref.lines == b.lines);
    REQUIRE(ref.stats == b.stats);

    {
      framer<property_capacity> f;
      const auto out = frame(f, {b.bytes});
      REQUIRE(out == b.lines);
      REQUIRE(f.stats() == b.stats);
      check_accounting(b.bytes, out, f.stats());
    }
    for (std::uint64_t chunk_seed = 1; chunk_seed <= 25; ++chunk_seed) {
      prng r{stream_seed * 1000 + chunk_seed};
      // Byte by byte is the harshest chunking but 1M feeds a run: two streams get it in full.
      const std::size_t max_chunk = chunk_seed == 1 && stream_seed <= 2 ? 1 : pick_max_chunk(r);
      INFO("chunk seed " << chunk_seed << ", chunks of 1.." << max_chunk);
      framer<property_capacity> f;
      const auto out = frame(f, chop(b.bytes, r, max_chunk));
      REQUIRE(out == b.lines);
      REQUIRE(f.stats() == b.stats);
    }
  }
}

namespace {

// Random soup dense in '$', '!', CR, LF and bad bytes, so every state meets every byte class at
// every chunk boundary.
std::string soup(prng& r, std::size_t n) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = r.below(100);
    if (k < 6) {
      s += '$';
    } else if (k < 11) {
      s += '!';
    } else if (k < 15) {
      s += '\r';
    } else if (k < 19) {
      s += '\n';
    } else if (k < 21) {
      s += static_cast<char>(r.below(0x20));
    } else if (k < 23) {
      s += static_cast<char>(0x7F + r.below(0x81));
    } else {
      s += static_cast<char>(0x20 + r.below(0x5F));
    }
  }
  return s;
}

template <std::size_t N>
void check_soup_against_reference(std::uint64_t seed) {
  prng r{seed};
  const std::string s = soup(r, 2000 + r.below(20000));
  const reference_result ref = reference_frame(s, N);
  INFO("capacity " << N << ", seed " << seed);
  for (int run = 0; run < 8; ++run) {
    const std::size_t max_chunk = run == 0 ? s.size() : run == 1 ? 1 : pick_max_chunk(r);
    INFO("chunks of 1.." << max_chunk);
    framer<N> f;
    const auto out = frame(f, chop(s, r, max_chunk));
    REQUIRE(out == ref.lines);
    REQUIRE(f.stats() == ref.stats);
    check_accounting(s, out, f.stats());
  }
}

}  // namespace

TEST_CASE("property: random soup matches the byte-at-a-time reference", "[framer][property]") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    check_soup_against_reference<1>(seed);
    check_soup_against_reference<2>(seed);
    check_soup_against_reference<7>(seed);
    check_soup_against_reference<8>(seed);
    check_soup_against_reference<9>(seed);
    check_soup_against_reference<16>(seed);
    check_soup_against_reference<82>(seed);
  }
}

// nmea::stream_reader without frames, with drop reports on: the same lines as the reference in
// the same order, and between them drop reports whose sizes add up to what the counters say
// was dropped, each one where the stream has it (its offset and shown bytes are the stream's).
namespace {

template <std::size_t N>
void check_soup_drop_reports(std::uint64_t seed) {
  prng r{seed};
  const std::string s = soup(r, 2000 + r.below(20000));
  const reference_result ref = reference_frame(s, N);
  INFO("capacity " << N << ", seed " << seed);
  for (int run = 0; run < 4; ++run) {
    const std::size_t max_chunk = run == 0 ? s.size() : run == 1 ? 1 : pick_max_chunk(r);
    INFO("chunks of 1.." << max_chunk);
    seawire::nmea::stream_reader<N> reader;
    reader.report_drops(true);
    std::vector<rec> lines;
    std::uint64_t dropped = 0;
    std::uint64_t last_offset = 0;
    bool in_order = true;
    bool shown_right = true;
    const auto take = [&](const auto& item) {
      in_order = in_order && item.offset >= last_offset;
      last_offset = item.offset;
      if (item.is_sentence()) {
        lines.push_back(
            {std::string(item.sentence.text), item.sentence.ending, item.sentence.line});
        shown_right = shown_right &&
                      s.compare(item.offset, item.sentence.text.size(), item.sentence.text) == 0;
      } else {
        REQUIRE(item.is_drop());
        dropped += item.drop.size;
        // A noise run shows its bytes, which need not be contiguous (line breaks inside it are
        // not noise); a dropped line shows the stream's bytes from the report's offset.
        if (item.drop.reason != seawire::nmea::drop_reason::noise)
          shown_right =
              shown_right && s.compare(item.offset, item.drop.bytes.size(), item.drop.bytes) == 0;
      }
    };
    for (const std::string_view chunk : chop(s, r, max_chunk)) reader.feed(chunk, take);
    reader.finish(take);
    CHECK(in_order);
    CHECK(shown_right);
    REQUIRE(lines == ref.lines);
    const auto& st = reader.stats();
    CHECK(dropped == st.noise_bytes + st.dropped_bytes);
    CHECK(st.noise_bytes == ref.stats.noise_bytes);
    CHECK(st.dropped_bytes == ref.stats.dropped_bytes);
    CHECK(st.interrupted == ref.stats.interrupted);
    CHECK(st.overlong == ref.stats.overlong);
    CHECK(st.invalid_bytes == ref.stats.invalid_bytes);
    CHECK(st.frames == 0);
  }
}

}  // namespace

TEST_CASE("stream_reader without frames: the framer's lines, with every drop reported in order",
          "[framer][property]") {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    check_soup_drop_reports<7>(seed);
    check_soup_drop_reports<82>(seed);
  }
}

TEST_CASE("stream_reader without frames: each kind of drop, where it happened", "[framer]") {
  using namespace seawire::nmea;
  stream_reader<16> reader;
  reader.report_drops(true);
  std::vector<std::string> seen;
  const auto take = [&](const auto& item) {
    if (item.is_sentence()) {
      seen.push_back("line " + std::to_string(item.line) + ": " + std::string(item.sentence.text));
    } else {
      seen.push_back("line " + std::to_string(item.line) + " @" + std::to_string(item.offset) +
                     " " + std::string(name(item.drop.reason)) + " " +
                     std::to_string(item.drop.size) + " \"" + std::string(item.drop.bytes) + "\"");
    }
  };
  reader.feed("junk$A,1\n$B,2$C,3\r\n$D,\x01x\n$E,this is far too long\n", take);
  reader.finish(take);
  CHECK(seen == std::vector<std::string>{
                    "line 1 @0 noise 4 \"junk\"",
                    "line 1: $A,1",
                    "line 2 @9 interrupted 4 \"$B,2\"",
                    "line 2: $C,3",
                    "line 3 @19 invalid_byte 5 \"$D,\x01x\"",
                    "line 4 @25 overlong 23 \"$E,this is far too long\"",
                });
}
