// SPDX-License-Identifier: BSL-1.0
// The sentence layer: checksum, parse() under each policy, the field reader, the writer.

#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"

using namespace seawire;
using namespace seawire::nmea;

namespace {
constexpr std::string_view kGga =
    "$GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,M,-33.2,M,,*5C\r\n";
// The spec's two BFNVG examples: this sentence with a wrong checksum (really *4E), written *5B
// in one and *5b in the other.
constexpr std::string_view kSeedBfnvg =
    "$BFNVG,081025.987,4221.81092,N,07106.84603,W,1,45.3,20.1,203.1,-3.4,4.5,081025.980";

constexpr parse_policy with_checksum(checksum_policy c) {
  parse_policy p;
  p.checksum = c;
  return p;
}

// A writer's whole sentence of whole numbers: begin(), next_field() and put_uint() for each
// number, seal(). What seal() says: the sentence's length in `out`, or why not.
seawire::result<std::size_t> seal_numbers(std::span<char> out, std::string_view address, char start,
                                          std::initializer_list<std::uint64_t> numbers) {
  writer w(out);
  w.begin(address, start);
  for (const std::uint64_t n : numbers) {
    w.next_field();
    w.put_uint(n);
  }
  return w.seal();
}
}  // namespace

static_assert(checksum("GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,M,-33.2,M,,") ==
              0x5C);
static_assert(parse(kGga).value.field_count == 14);
static_assert(parse(kGga).value.address == "GPGGA");

TEST_CASE("checksum is the XOR of the bytes between $ and *") {
  CHECK(checksum("") == 0);
  CHECK(checksum("PYDIR,0,0") == 0x56);
  CHECK(checksum("PAPGPSCTRL,1") == 0x11);
  CHECK(checksum("A") == 'A');
}

TEST_CASE("parse splits address, body and fields") {
  const auto r = parse(kGga);
  REQUIRE(r);
  CHECK(r.value.address == "GPGGA");
  CHECK(r.value.field_count == 14);
  CHECK(r.value.checksum == checksum_state::valid);
  CHECK(r.value.received_checksum == 0x5C);
  CHECK(r.value.body.substr(0, 9) == "164959.00");
  CHECK(r.value.line.back() == 'C');  // ending stripped
  CHECK(r.value.field(1).text == "164959.00");
  CHECK(r.value.field(14).text.empty());
  CHECK(r.value.field(14).present);
  CHECK_FALSE(r.value.field(15).present);
}

TEST_CASE("addresses longer or shorter than five characters") {
  auto r = parse("$PAPGPSCTRL,1*11");
  REQUIRE(r);
  CHECK(r.value.address == "PAPGPSCTRL");
  CHECK(r.value.field_count == 1);
  r = parse("$BPLOG*00", with_checksum(checksum_policy::ignore));
  REQUIRE(r);
  CHECK(r.value.address == "BPLOG");
  CHECK(r.value.field_count == 0);
  r = parse("$BPLOG,*7A");  // one blank field
  REQUIRE(r);
  CHECK(r.value.field_count == 1);
}

TEST_CASE("line endings CRLF, LF, CR and none are accepted by default") {
  for (std::string_view end : {"\r\n", "\n", "\r", ""}) {
    const std::string line = std::string("$PYDIR,45,55*57") + std::string(end);
    const auto r = parse(line);
    INFO(line);
    REQUIRE(r);
    CHECK(r.value.line == "$PYDIR,45,55*57");
  }
  parse_policy crlf;
  crlf.require_crlf = true;
  CHECK(parse("$PYDIR,45,55*57\r\n", crlf));
  CHECK(parse("$PYDIR,45,55*57\n", crlf).ec == errc::bad_line_ending);
  CHECK(parse("$PYDIR,45,55*57", crlf).ec == errc::bad_line_ending);
}

TEST_CASE("checksum policies") {
  const auto required = with_checksum(checksum_policy::required);
  const auto verify = with_checksum(checksum_policy::verify_if_present);
  const auto ignore = with_checksum(checksum_policy::ignore);

  SECTION("the spec's BFNVG examples are checksum mismatches, accepted only under ignore") {
    for (const std::string_view sent : {"*5B", "*5b"}) {
      const std::string line = std::string(kSeedBfnvg) + std::string(sent);
      INFO(line);
      CHECK(parse(line, required).ec == errc::checksum_mismatch);
      CHECK(parse(line, verify).ec == errc::checksum_mismatch);
      const auto r = parse(line, ignore);
      REQUIRE(r);
      CHECK(r.value.checksum == checksum_state::mismatch);
      CHECK(r.value.computed_checksum == 0x4E);
      CHECK(r.value.address == "BFNVG");
      CHECK(r.value.field_count == 12);
    }
  }
  SECTION("missing checksum: no '*' at all") {
    const std::string_view line = "$PYDIR,12.5,-3\r\n";
    CHECK(parse(line, required).ec == errc::missing_checksum);
    const auto r = parse(line, verify);
    REQUIRE(r);
    CHECK(r.value.checksum == checksum_state::absent);
    CHECK(r.value.field_count == 2);
  }
  SECTION("'*' with nothing after it is a checksum cut off, under every checksum policy") {
    for (const std::string_view line :
         {"$PYDIR,12.5,-3*\r\n", "$PYDIR,12.5,-3*", "$GPRMC,,V,*\n"}) {
      INFO(line);
      for (const checksum_policy c : {checksum_policy::required, checksum_policy::verify_if_present,
                                      checksum_policy::ignore}) {
        parse_policy p;
        p.checksum = c;
        const auto r = parse(line, p);
        CHECK(r.ec == errc::bad_checksum_format);
        CHECK(r.column == line.find('*') + 1);
      }
    }
  }
  SECTION("where a link allows it, '*' then the line end is no checksum") {
    parse_policy bare = verify;
    bare.empty_checksum = true;
    const auto r = parse("$PYDIR,12.5,-3*\r\n", bare);
    REQUIRE(r);
    CHECK(r.value.checksum == checksum_state::absent);
    CHECK(r.value.field_count == 2);
    CHECK(r.value.body == "12.5,-3");
    bare.checksum = checksum_policy::required;
    CHECK(parse("$PYDIR,12.5,-3*\r\n", bare).ec == errc::missing_checksum);
    CHECK(parse("$PYDIR,12.5,-3*1\r\n", bare).ec == errc::bad_checksum_format);
  }
  SECTION("lower-case hex is accepted unless refused") {
    CHECK(parse("$BPLOG,ACK,ON*1e", required));
    parse_policy upper_only = required;
    upper_only.lowercase_hex = false;
    CHECK(parse("$BPLOG,ACK,ON*1e", upper_only).ec == errc::bad_checksum_format);
    CHECK(parse("$BPLOG,ACK,ON*1E", upper_only));
  }
}

TEST_CASE("malformed sentences: each failure class gives its errc and column") {
  struct row {
    std::string_view line;
    errc expected;
    std::uint16_t column;
  };
  const row rows[] = {
      {"", errc::empty_input, 0},
      {"\r\n", errc::empty_input, 0},
      {"GPGGA,1*00", errc::missing_start, 0},
      {"#AIVDM,1*00", errc::missing_start, 0},
      {" !AIVDM,1*00", errc::missing_start, 0},
      {"!", errc::bad_address, 1},
      {"!AIVDM,1$,0", errc::bad_character, 8},
      {"$", errc::bad_address, 1},
      {"$*00", errc::bad_address, 1},
      {"$,1,2*00", errc::bad_address, 1},
      {"$gprmc,1*00", errc::bad_address, 1},
      {"$GP RMC,1*00", errc::bad_address, 3},
      {"$1GPRM,1*00", errc::bad_address, 1},
      {"$ABCDEFGHIJKLMNOP,1*00", errc::bad_address, 1},
      {"$PYDIR,4\x01,5", errc::bad_character, 8},
      {"$PYDIR,4\x80,5", errc::bad_character, 8},
      {"$PYDIR,4$,5", errc::bad_character, 8},
      {"$PYDIR,45,55*5", errc::bad_checksum_format, 13},
      {"$PYDIR,45,55*577", errc::bad_checksum_format, 13},
      {"$PYDIR,45,55*G7", errc::bad_checksum_format, 13},
      {"$PYDIR,45,55*57 ", errc::trailing_characters, 15},
      {"$PYDIR,45,55*57X", errc::trailing_characters, 15},
      {"$PYDIR,45,55*6f ", errc::trailing_characters, 15},  // the checksum is not checked first
      {"$PYDIR,45,55*57*57", errc::trailing_characters, 15},
      {"$PYDIR,45,55*5757", errc::bad_checksum_format, 13},
      {"$PYDIR,45,55*58", errc::checksum_mismatch, 13},
      {"$PYDIR,45,55*57\r\r\n", errc::trailing_characters, 15},
  };
  for (const auto& r : rows) {
    INFO(r.line);
    const auto p = parse(r.line);
    CHECK(p.ec == r.expected);
    CHECK(p.column == r.column);
    CHECK_FALSE(p);
  }
}

TEST_CASE("'!' starts a sentence too: encapsulation sentences such as !AIVDM") {
  constexpr std::string_view ais = "!AIVDM,1,1,,B,15M67FC000G?ufbE`vJ8?wv4R0<4,0*10\r\n";
  const auto r = parse(ais, with_checksum(checksum_policy::required));
  REQUIRE(r);
  CHECK(r.value.start == '!');
  CHECK(r.value.address == "AIVDM");
  CHECK(r.value.field_count == 6);
  CHECK(r.value.field(5).text == "15M67FC000G?ufbE`vJ8?wv4R0<4");
  // The checksum is the XOR of the bytes between the '!' and the '*', as for '$'.
  CHECK(r.value.computed_checksum == checksum("AIVDM,1,1,,B,15M67FC000G?ufbE`vJ8?wv4R0<4,0"));
  CHECK(r.value.checksum == checksum_state::valid);
  CHECK(parse("!AIVDM,1,1,,B,15M67FC000G?ufbE`vJ8?wv4R0<4,0*11").ec == errc::checksum_mismatch);
  // Long enough for the 16-byte scan, and short enough for the byte loop.
  CHECK(parse("!AIVDO,1*48").value.start == '!');
  CHECK(parse("!AIVDO,1*48").value.computed_checksum == checksum("AIVDO,1"));
  CHECK(parse("$GPGGA,1").value.start == '$');
  // A '!' inside a sentence is text, whichever the start.
  const auto inner = parse("$BPLOG,hello!,ON");
  REQUIRE(inner);
  CHECK(inner.value.start == '$');
  CHECK(inner.value.field(1).text == "hello!");
  CHECK(parse("!!AB").ec == errc::bad_address);
  // A failed parse holds the default start.
  CHECK(parse("!AIVDM,1*00").value.start == '$');
}

TEST_CASE("maximum length is enforced") {
  parse_policy p;
  p.max_length = 82;
  std::string line = "$GPTXT," + std::string(80, 'A');
  CHECK(parse(line, p).ec == errc::too_long);
  line.resize(82);
  CHECK(parse(line, p));
  const std::string huge = "$GPTXT," + std::string(1 << 20, ',');
  CHECK(parse(huge).ec == errc::too_long);
}

TEST_CASE("field_reader walks fields, marks blanks and the end, tracks columns") {
  const auto s = parse("$XXABC,a,,ccc,*00", with_checksum(checksum_policy::ignore));
  REQUIRE(s);
  parse_policy p;
  field_reader r(s.value, p);
  CHECK(r.field_count() == 4);
  auto t = r.take();
  CHECK((t.present && t.text == "a" && r.index() == 1 && r.column() == 7));
  t = r.take();
  CHECK((t.present && t.blank() && r.index() == 2 && r.column() == 9));
  CHECK(r.peek().text == "ccc");
  t = r.take();
  CHECK((t.text == "ccc" && r.column() == 10));
  t = r.take();
  CHECK((t.present && t.blank() && r.index() == 4 && r.column() == 14));
  CHECK(r.at_end());
  t = r.take();
  CHECK_FALSE(t.present);
  CHECK(r.index() == 5);
}

TEST_CASE("field_reader agrees with a plain split, over every body length and comma layout") {
  // Bodies of 0 to 200 bytes (across the reader's 64-byte windows and 16-byte blocks), commas
  // placed by a fixed pseudo-random sequence, some runs of commas: the fields the reader hands
  // out, their columns and its end are those of a split at each ','.
  std::uint32_t x = 0x2545F491U;
  const auto next = [&x] {
    x ^= x << 13U;
    x ^= x >> 17U;
    x ^= x << 5U;
    return x;
  };
  for (std::size_t len = 0; len <= 200; ++len) {
    for (int round = 0; round < 8; ++round) {
      std::string body;
      for (std::size_t i = 0; i < len; ++i) {
        const std::uint32_t r = next() % 100;
        body += r < (round < 4 ? 15U : 60U) ? ',' : static_cast<char>('A' + r % 26);
      }
      const std::string line = "$XXABC," + body;
      const auto s = parse(line, with_checksum(checksum_policy::ignore));
      REQUIRE(s);
      parse_policy p;
      field_reader r(s.value, p);
      std::size_t start = 0;
      std::size_t fields = 0;
      for (;;) {
        const std::size_t comma = body.find(',', start);
        const std::size_t end = comma == std::string::npos ? body.size() : comma;
        INFO(line << " field " << fields + 1);
        CHECK(r.peek().text == body.substr(start, end - start));
        const field_token t = r.take();
        REQUIRE(t.present);
        CHECK(t.text == body.substr(start, end - start));
        CHECK(r.column() == 7 + start);
        ++fields;
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
      CHECK(r.at_end());
      CHECK_FALSE(r.take().present);
      CHECK(fields == s.value.field_count);
    }
  }
}

TEST_CASE("field_reader: fields that span whole 64-byte windows without a comma") {
  // The reader keeps one 64-byte window of field ends at a time; a window with no end in it
  // must be skipped, and the end of the body must be found at every offset into a window.
  const std::size_t lengths[] = {0, 1, 62, 63, 64, 65, 127, 128, 129, 191, 192, 193, 300};
  for (const std::size_t a : lengths) {
    for (const std::size_t b : lengths) {
      for (const std::size_t c : lengths) {
        const std::string fields[] = {std::string(a, 'A'), std::string(b, 'B'),
                                      std::string(c, 'C')};
        const std::string line = "$XXABC," + fields[0] + ',' + fields[1] + ',' + fields[2];
        parse_policy p;
        p.checksum = checksum_policy::ignore;
        p.max_length = 2048;
        const auto s = parse(line, p);
        REQUIRE(s);
        REQUIRE(s.value.field_count == 3);
        field_reader r(s.value, p);
        std::size_t column = 7;
        for (const std::string& f : fields) {
          INFO(a << ' ' << b << ' ' << c << " field of " << f.size());
          CHECK_FALSE(r.at_end());
          CHECK(r.peek().present);
          CHECK(r.peek().text == f);
          const field_token t = r.take();
          REQUIRE(t.present);
          CHECK(t.text == f);
          CHECK(r.column() == column);
          column += f.size() + 1;
        }
        CHECK(r.at_end());
        CHECK_FALSE(r.peek().present);
        CHECK_FALSE(r.take().present);
        CHECK_FALSE(r.take().present);
        CHECK(r.index() == 5);
      }
    }
  }
}

TEST_CASE("comma_bits8: one bit per ',' byte, none for any other byte value") {
  for (unsigned v = 0; v < 256; ++v) {
    for (unsigned at = 0; at < 8; ++at) {
      // v at byte `at`, ',' and its neighbours 0x2B / 0x2D / 0xAC elsewhere.
      std::uint64_t w = 0;
      std::uint64_t want = 0;
      for (unsigned k = 0; k < 8; ++k) {
        const unsigned b = k == at ? v
                                   : (k % 4 == 0   ? 0x2CU
                                      : k % 4 == 1 ? 0x2BU
                                      : k % 4 == 2 ? 0x2DU
                                                   : 0xACU);
        w |= std::uint64_t{b} << (8 * k);
        if (b == 0x2C) want |= 1U << k;
      }
      INFO(v << " at " << at);
      CHECK(seawire::nmea::detail::comma_bits8(w) == want);
    }
  }
}

TEST_CASE("field_reader on a sentence without fields never points past the line") {
  const auto s = parse("$RXHRB", with_checksum(checksum_policy::ignore));
  REQUIRE(s);
  parse_policy p;
  field_reader r(s.value, p);
  CHECK(r.at_end());
  CHECK_FALSE(r.take().present);
  CHECK(r.column() <= s.value.line.size());
}

TEST_CASE("writer seals with upper-case checksum and CR LF, and reports overflow") {
  char buf[64];
  const auto r = seal_numbers(buf, "PYDIR", '$', {45, 55});
  REQUIRE(r);
  CHECK(std::string_view(buf, r.value) == "$PYDIR,45,55*57\r\n");

  char small[10];
  CHECK(seal_numbers(small, "PYDIR", '$', {45}).ec == errc::buffer_too_small);

  char bang[32];
  const auto sealed = seal_numbers(bang, "AIVDO", '!', {1});
  REQUIRE(sealed);
  CHECK(std::string_view(bang, sealed.value) == "!AIVDO,1*48\r\n");

  char pad[16];
  writer z(pad);
  z.begin("X");
  z.next_field();
  z.put_uint(6, 2);
  z.put_uint(0, 4);
  CHECK(z.view() == "$X,060000");
}

TEST_CASE("what a writer may be given: addresses and field text") {
  using seawire::nmea::is_address;
  using seawire::nmea::is_field_text;
  CHECK(is_address("GPRMC"));
  CHECK(is_address("P"));
  CHECK(is_address("AIVDM"));
  CHECK(is_address("ABCDEFGHIJ12345"));
  CHECK_FALSE(is_address(""));
  CHECK_FALSE(is_address("ABCDEFGHIJ123456"));  // 16 characters
  CHECK_FALSE(is_address("1GPS"));              // a digit first
  CHECK_FALSE(is_address("gprmc"));
  CHECK_FALSE(is_address("GP-RMC"));
  CHECK(is_field_text(""));
  CHECK(is_field_text("Running [log dir] 12.5 m/s"));
  for (const char c : std::string_view("$,*!\\^~")) {
    INFO("reserved " << c);
    CHECK_FALSE(is_field_text(std::string("a") + c));
  }
  CHECK_FALSE(is_field_text("tab\there"));
  CHECK_FALSE(is_field_text("\x7F"));
  CHECK_FALSE(is_field_text("\xC3\xA9"));
}
