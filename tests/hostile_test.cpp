// SPDX-License-Identifier: BSL-1.0
// Hostile input: what anyone who can write to a TCP port or a serial line may send, through every
// family's decoders, the framer, the binary frame decoder and the mixed stream reader. Each case
// names the exact errc (and column or field) it must give, and valid data after it must still
// come out. Inputs fuzzing found are kept in fuzz/corpus and replayed by the fuzz targets' tests;
// what they showed is pinned here and in the tests of the subject they belong to.

#include <array>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <variant>
#include <vector>

#include "seawire/anello/frame.hpp"
#include "seawire/anello/inputs.hpp"
#include "seawire/anello/stream.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/framer.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/sandshark/messages.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/rmc.hpp"
#include "seawire/standard/rpm.hpp"
#include "seawire/standard/rsa.hpp"
#include "seawire/standard/vbw.hpp"
#include "seawire/standard/vhw.hpp"
#include "seawire/standard/vwr.hpp"

#include "support.hpp"

namespace {

using namespace support;

using namespace seawire;
using namespace seawire::nmea;
using namespace std::string_literals;

using standard_set = message_set<standard::rmc, standard::gga, standard::rpm, standard::rsa,
                                 standard::vhw, standard::vbw, standard::vwr>;
using kingfisher_set = merge_sets<kingfisher::from_vehicle, kingfisher::to_vehicle>::type;
using sandshark_set = merge_sets<sandshark::from_vehicle, sandshark::to_vehicle>::type;
using robotx_set = robotx::reports;
using anello_set = merge_sets<anello::nmea_inputs, anello::nmea_outputs>::type;

// The policy each family's receivers start from, and the strict one.
constexpr parse_policy liberal{.checksum = checksum_policy::ignore};
constexpr parse_policy strict = parse_policy::strict();

// A verified sentence of each family (verified against real receivers and the specs), without its
// line ending.
constexpr std::string_view standard_line =
    "$GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,M,-33.2,M,,*5C";
constexpr std::string_view kingfisher_line =
    "$CPNVR,164959.063,0.02941,-0.068552,0,0.060938,0,-0.061132*59";
constexpr std::string_view sandshark_line = "$BPSTS,231133.12,1,BWSI Autonomy OK*46";
constexpr std::string_view robotx_line = "$RXHRB,111221,161229,21.31198,N,157.88972,W,ROBOT,2,1*11";
constexpr std::string_view anello_line = "$VMVBW,0.0,0.0,A,0.0,0.0,A*58";

/// Calls f(set tag, a valid line of that family) for each family.
template <class F>
void for_each_family(F&& f) {
  f(standard_set{}, standard_line);
  f(kingfisher_set{}, kingfisher_line);
  f(sandshark_set{}, sandshark_line);
  f(robotx_set{}, robotx_line);
  f(anello_set{}, anello_line);
}

template <class Set>
result<typename Set::variant> decode_with(const Set&, std::string_view line, parse_policy p) {
  return Set::decode(line, p);
}

// The spec's 0xAB00 example frame (valid CRC).
constexpr anello::frame_bytes seed_frame = {
    0xAB, 0x00, 0x00, 0x30, 0x8E, 0xF7, 0xF1, 0x76, 0x00, 0x59, 0x01, 0xF4, 0xEC, 0xFF,
    0xF9, 0x03, 0x36, 0x9A, 0x00, 0x00, 0xFF, 0xFF, 0x00, 0x00, 0x01, 0x90, 0x79, 0x43,
    0x63, 0xD0, 0x00, 0x00, 0x01, 0xE0, 0x7F, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x02, 0x00, 0x6C, 0x00, 0x03, 0x00, 0x5A, 0xFF, 0xFF, 0xFF, 0xFF};

std::string as_string(std::span<const std::uint8_t> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

/// Everything a framer yields for `stream`, fed in one chunk, then finished.
std::vector<std::string> frame_all(std::string_view stream, framer_stats* stats = nullptr) {
  static framer<1024> f;  // 1 KiB of buffer: static, off the test's stack
  f.reset();
  std::vector<std::string> out;
  f.feed(stream, [&](const framed_line& l) { out.emplace_back(l.text); });
  if (const auto l = f.finish()) out.emplace_back(l->text);
  if (stats != nullptr) *stats = f.stats();
  return out;
}

struct stream_out {
  std::vector<std::string> sentences;
  std::vector<anello::frame_bytes> frames;
  anello::stream_stats stats;
};

/// Everything a stream reader yields for `stream`, fed in one chunk, then finished.
stream_out read_all(std::string_view stream) {
  static anello::stream_reader<1024> r;
  r.reset();
  stream_out out;
  const auto take = [&](const anello::stream_item& i) {
    if (i.is_frame()) {
      out.frames.push_back(i.bytes);
    } else {
      out.sentences.emplace_back(i.sentence.text);
    }
  };
  r.feed(stream, take);
  r.finish(take);
  out.stats = r.stats();
  return out;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// bytes that are not text

TEST_CASE("NUL, control and 8-bit bytes are bad_character at their column, in every family") {
  for_each_family([](auto set, std::string_view good) {
    REQUIRE(decode_with(set, good, liberal).ok());
    for (const char bad : {'\0', '\x01', '\t', '\x1b', '\x7f', '\x80', '\xab', '\xff'}) {
      // In the address, in the first field, in the last field just before the '*'.
      for (const std::size_t at : {std::size_t{2}, std::size_t{8}, good.find('*') - 1}) {
        std::string line = std::string(good) + "\r\n";
        line[at] = bad;
        INFO(good << " with byte " << int(static_cast<unsigned char>(bad)) << " at " << at);
        for (const parse_policy& p : {liberal, strict}) {
          const auto r = decode_with(set, line, p);
          CHECK(r.ec == errc::bad_character);
          CHECK(r.column == at);
          CHECK(r.field == 0);
        }
      }
      // A CR or LF inside is no line ending either.
      for (const char brk : {'\r', '\n'}) {
        std::string line(good);
        line[8] = brk;
        CHECK(decode_with(set, line, liberal).ec == errc::bad_character);
      }
      // After the checksum's two hex digits a byte is one too many, whatever it is.
      const auto after = decode_with(set, std::string(good) + bad, liberal);
      CHECK(after.ec == errc::trailing_characters);
      CHECK(after.column == good.size());
    }
  });
}

// ---------------------------------------------------------------------------------------------
// size

TEST_CASE("a 1 MiB line is too_long, and the stream readers drop it and carry on") {
  const std::string huge = "$GPRMC," + std::string(1 << 20, 'A');
  for_each_family([&](auto set, std::string_view) {
    const auto r = decode_with(set, huge, liberal);
    CHECK(r.ec == errc::too_long);
    CHECK(r.column == 1024);
  });
  // Even a policy that allows any length refuses it: positions are 16-bit.
  parse_policy any_length = liberal;
  any_length.max_length = std::size_t(-1);
  CHECK(parse(huge, any_length).ec == errc::too_long);

  framer_stats stats;
  const auto lines = frame_all(huge + "\r\n" + std::string(standard_line) + "\r\n", &stats);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0] == standard_line);
  CHECK(stats.overlong == 1);
  CHECK(stats.dropped_bytes == huge.size());

  const stream_out s = read_all(huge + std::string(anello_line) + "\n" + as_string(seed_frame));
  CHECK(s.sentences == std::vector<std::string>{std::string(anello_line)});
  CHECK(s.frames.size() == 1);
  CHECK(s.stats.overlong == 1);
}

TEST_CASE("10^6 commas: too_long, however long the policy lets lines be") {
  const std::string commas = "$GPRMC" + std::string(1'000'000, ',');
  CHECK(standard_set::decode(commas, liberal).ec == errc::too_long);
  // A count of fields past 65535 would wrap the 16-bit field count: 65536 commas must not read
  // as a sentence without fields.
  parse_policy any_length = liberal;
  any_length.max_length = std::size_t(-1);
  CHECK(parse(commas, any_length).ec == errc::too_long);
  CHECK(parse("$GPRMC" + std::string(65'536, ','), any_length).ec == errc::too_long);
  // Within the default length, many blank fields are fine where the extra ones are ignored.
  const std::string many = "$IIRSA" + std::string(1000, ',');
  const auto r = standard_set::decode(many, liberal);
  REQUIRE(r.ok());
  CHECK_FALSE(std::get<standard::rsa>(r.value).starboard_angle.has_value());
  CHECK(standard_set::decode(resealed(many), strict).ec == errc::too_many_fields);
}

// ---------------------------------------------------------------------------------------------
// numbers

TEST_CASE("19-digit numbers are read, 20 and 400 digits are number_too_long") {
  constexpr std::string_view nineteen = "9999999999999999999";
  // A decimal without a range (BPRMB speed): 19 digits come back exactly.
  const std::string ok = resealed("$BPRMB,231137.32,,,," + std::string(nineteen) + ",0,1");
  const auto r = sandshark_set::decode(ok, strict);
  REQUIRE(r.ok());
  const auto& rmb = std::get<sandshark::bprmb>(r.value);
  CHECK(rmb.speed->mantissa == 9'999'999'999'999'999'999ULL);
  CHECK(encode(rmb).view() == ok);
  // With a range (PYDIR thrust -100..100): a number, but out of range.
  const auto pydir = kingfisher_set::decode(resealed("$PYDIR," + std::string(nineteen) + ",0"));
  CHECK(pydir.ec == errc::out_of_range);
  CHECK(pydir.field == 1);

  const std::string twenty = std::string(nineteen) + "9";
  const std::string four_hundred(400, '7');
  for (const std::string& n : {twenty, four_hundred, "0." + four_hundred,
                               "1." + std::string(19, '0'), "-" + four_hundred}) {
    INFO(n.size() << " characters");
    const auto d = sandshark_set::decode(resealed("$BPRMB,231137.32,,,," + n + ",0,1"));
    CHECK(d.ec == errc::number_too_long);
    CHECK(d.field == 5);
    // An integer field, a time, a position.
    const auto id =
        kingfisher_set::decode(resealed("$CPRCM,164959.065," + n + ",234.3,-1.6,-6.6,"));
    CHECK(id.ec == errc::number_too_long);
    CHECK(id.field == 2);
    CHECK(kingfisher_set::decode(resealed("$CPALT," + n + ",1")).ec == errc::bad_time);
    CHECK(kingfisher_set::decode(resealed("$GPRMC,,A," + n + ",N,,,,,,,")).ec ==
          errc::bad_latitude);
  }
  // 19 digits in an unsigned 16-bit field: a number, out of the field's range.
  const auto wide = kingfisher_set::decode(
      resealed("$CPRCM,164959.065," + std::string(nineteen) + ",234.3,-1.6,-6.6,"));
  CHECK(wide.ec == errc::out_of_range);
  CHECK(wide.field == 2);
  // Leading zeros are not significant digits: 400 of them before a 1 still read as 1, with the
  // padding forgotten (it is wider than any sender pads).
  const auto zeros =
      sandshark_set::decode(resealed("$BPRMB,231137.32,,,," + std::string(400, '0') + "1,0,1"));
  REQUIRE(zeros.ok());
  CHECK(std::get<sandshark::bprmb>(zeros.value).speed == decimal(1));
}

TEST_CASE("-0 keeps its sign where a sign may stand, and is refused where none may") {
  const std::string line = resealed("$BPRMB,231137.32,-0,-0.0,,750,0,1");
  const auto r = sandshark_set::decode(line, strict);
  REQUIRE(r.ok());
  const auto& m = std::get<sandshark::bprmb>(r.value);
  CHECK(m.heading->negative);
  CHECK(m.depth->negative);
  CHECK(m.depth->places == 1);
  CHECK(encode(m).view() == line);
  // Ranges compare values: -0 is 0, inside [0, 360) and >= 0.
  CHECK(kingfisher_set::decode(resealed("$PYDEV,-0,-0.0")).ok());
  // RobotX decimal degrees are unsigned: the letter is the sign.
  const auto hrb = robotx_set::decode(resealed("$RXHRB,111221,161229,-0,N,157.88972,W,ROBOT,2,1"));
  CHECK(hrb.ec == errc::bad_latitude);
  CHECK(hrb.field == 3);
  // A time, a date and NMEA positions have no sign at all.
  CHECK(kingfisher_set::decode(resealed("$CPALT,-00000,1")).ec == errc::bad_time);
  CHECK(robotx_set::decode(resealed("$RXHRB,-11221,161229,,,,,ROBOT,2,1")).ec == errc::bad_date);
  CHECK(standard_set::decode(resealed("$GPRMC,,A,-000.0,N,,,,,,,")).ec == errc::bad_latitude);
  // An unsigned integer reads -0 as the 0 it is.
  const auto id = kingfisher_set::decode(resealed("$CPRCM,164959.065,-0,234.3,-1.6,-6.6,"));
  REQUIRE(id.ok());
  CHECK(std::get<kingfisher::cprcm>(id.value).compass_id == 0);
}

TEST_CASE("exponents, hex, inf and nan are not numbers") {
  for (const std::string_view n :
       {"1e5", "1E5", "1.5e-3", "1e", "e5", "inf", "-inf", "nan", "0x10", "1.2.3",
        "1-2", "+-1", "--1",    ".",  "-",  "+",   " ",    "1 2", "- 1",  "1_000"}) {
    INFO(n);
    const auto d =
        sandshark_set::decode(resealed("$BPRMB,231137.32,,,," + std::string(n) + ",0,1"));
    CHECK(d.ec == errc::bad_number);
    CHECK(d.field == 5);
    const auto i = kingfisher_set::decode(
        resealed("$CPRCM,164959.065," + std::string(n) + ",234.3,-1.6,-6.6,"));
    if (n == "nan") {
      // The Kingfisher vehicle's own "not available" (kingfisher::vehicle_numbers).
      REQUIRE(i);
      CHECK_FALSE(std::get<kingfisher::cprcm>(i.value).compass_id.has_value());
      continue;
    }
    CHECK(i.ec == errc::bad_number);
    CHECK(i.field == 2);
  }
  // '+' and, in the Sandshark roles, spaces around a number (SPI 4.2) are what receivers take
  // and the strict policy refuses.
  for (const std::string_view n : {"+5", " 5", "5 ", " -5 "}) {
    INFO(n);
    const std::string line = resealed("$BPRMB,231137.32,,,," + std::string(n) + ",0,1");
    CHECK(sandshark_set::decode(line, sandshark::to_vehicle_policy).ok());
    CHECK(sandshark_set::decode(line, strict).ec == errc::bad_number);
  }
  // Elsewhere a space is not part of a number.
  CHECK(kingfisher_set::decode(resealed("$CPRCM,164959.065, 2,234.3,-1.6,-6.6,")).ec ==
        errc::bad_number);
}

// ---------------------------------------------------------------------------------------------
// framing characters

TEST_CASE("a lone $ or *, and a $ inside a sentence") {
  for_each_family([](auto set, std::string_view good) {
    struct row {
      std::string line;
      errc ec;
      std::uint16_t column;
    };
    const std::string body(good.substr(1));
    const std::vector<row> rows = {
        {"$", errc::bad_address, 1},
        {"$\r\n", errc::bad_address, 1},
        {"*", errc::missing_start, 0},
        {"$*", errc::bad_address, 1},
        {"$*00", errc::bad_address, 1},
        {"**", errc::missing_start, 0},
        {"*" + std::string(good), errc::missing_start, 0},
        {"$$" + body, errc::bad_character, 1},
        {std::string(good.substr(0, 7)) + "$" + body, errc::bad_character, 7},
        {std::string(good) + "$", errc::trailing_characters,
         static_cast<std::uint16_t>(good.size())},
    };
    for (const row& r : rows) {
      INFO(r.line);
      const auto d = decode_with(set, r.line, liberal);
      CHECK(d.ec == r.ec);
      if (r.column != 0) CHECK(d.column == r.column);
    }
  });
  // The framer starts over at a nested '$': the interrupted part is dropped, the rest is read.
  framer_stats stats;
  const auto lines = frame_all("$GPR" + std::string(standard_line) + "\r\n$\r\n*\r\n", &stats);
  CHECK(lines == std::vector<std::string>{std::string(standard_line), "$"});
  CHECK(stats.interrupted == 1);
  CHECK(stats.noise_bytes == 1);  // the lone '*'
  // A '$' right after a whole "*hh" cuts nothing: the sentence before it lacks only its line
  // ending, and both are read. Any other sentence ended by a '$' may have lost its tail.
  for_each_family([](auto, std::string_view good) {
    const std::string data(good.substr(0, good.find('*')));
    framer_stats st;
    CHECK(frame_all(std::string(good) + std::string(good) + "\r\n", &st) ==
          std::vector<std::string>{std::string(good), std::string(good)});
    CHECK(st.interrupted == 0);
    for (const std::string& cut : {data, data + "*", data + "*" + std::string(1, good.back())}) {
      INFO(cut);
      CHECK(frame_all(cut + std::string(good) + "\r\n", &st) ==
            std::vector<std::string>{std::string(good)});
      CHECK(st.interrupted == 1);
      CHECK(st.dropped_bytes == cut.size());
    }
  });
}

TEST_CASE("a checksum of one digit or three, or not hex") {
  for_each_family([](auto set, std::string_view good) {
    const std::string data(good.substr(0, good.find('*')));
    const auto column = static_cast<std::uint16_t>(data.size() + 1);
    for (const std::string_view sum :
         {"7", "7FF", "G0", "0G", " 7", "7 ", "-1", "0x7", "7G7", "1234"}) {
      for (const parse_policy& p : {liberal, strict}) {
        const auto d = decode_with(set, data + "*" + std::string(sum) + "\r\n", p);
        INFO(data << "*" << sum);
        CHECK(d.ec == errc::bad_checksum_format);
        CHECK(d.column == column);
      }
    }
    // Two hex digits then anything but a third ("*6F ", "*57X") is a whole checksum followed by
    // characters where only the line ending may stand.
    const std::string sum(good.substr(good.find('*') + 1, 2));
    for (const std::string& extra :
         std::vector<std::string>{" ", "X", "G", "\t", "*", "*" + sum, "  ", "\r\r", "\x01"}) {
      for (const parse_policy& p : {liberal, strict}) {
        std::string line = data;
        line += '*';
        line += sum;
        line += extra;
        line += "\r\n";
        const auto d = decode_with(set, line, p);
        INFO(line);
        CHECK(d.ec == errc::trailing_characters);
        CHECK(d.column == column + 2);
      }
    }
    // Lower-case hex: receivers take it, the strict policy does not.
    std::string lower = std::string(good);
    for (std::size_t i = data.size() + 1; i < lower.size(); ++i)
      if (lower[i] >= 'A' && lower[i] <= 'F') lower[i] = static_cast<char>(lower[i] - 'A' + 'a');
    if (lower != good) {
      CHECK(decode_with(set, lower, liberal).ok());
      CHECK(decode_with(set, lower + "\r\n", strict).ec == errc::bad_checksum_format);
    }
    // A '*' and nothing after it: a checksum cut off, whatever the policy; only a link that
    // declares it (empty_checksum) reads it as no checksum.
    CHECK(decode_with(set, data + "*", liberal).ec == errc::bad_checksum_format);
    CHECK(decode_with(set, data + "*\r\n", strict).ec == errc::bad_checksum_format);
    parse_policy bare = liberal;
    bare.empty_checksum = true;
    CHECK(decode_with(set, data + "*", bare).ok());
  });
}

// ---------------------------------------------------------------------------------------------
// blanks

namespace {
// Every message of every family with all its wire fields blank, and what decoding must give:
// success where the spec lets every field be blank, else missing_field at the first field
// that may not be.
struct blank_row {
  std::string_view address;
  errc ec;
  std::uint16_t field;
};
constexpr std::array blank_rows = {
    blank_row{"GPRMC", errc::missing_field, 2},
    blank_row{"GPGGA", errc::ok, 0},  // a blank fix quality reads as not available
    blank_row{"IIRPM", errc::missing_field, 1},
    blank_row{"IIRSA", errc::ok, 0},
    blank_row{"VWVHW", errc::ok, 0},
    blank_row{"VWVBW", errc::ok, 0},
    blank_row{"WIVWR", errc::ok, 0},
    blank_row{"CPNVG", errc::missing_field, 1},
    blank_row{"CPNVR", errc::missing_field, 1},
    blank_row{"CPRCM", errc::missing_field, 1},
    blank_row{"CPRBS", errc::missing_field, 1},
    blank_row{"CPIMU", errc::missing_field, 1},
    blank_row{"CPALT", errc::missing_field, 1},
    blank_row{"PYDEP", errc::missing_field, 1},
    blank_row{"PYDEV", errc::missing_field, 1},
    blank_row{"PYDIR", errc::missing_field, 1},
    blank_row{"PYCLT", errc::missing_field, 1},
    blank_row{"BFSHT", errc::missing_field, 1},
    blank_row{"BFVER", errc::missing_field, 1},
    blank_row{"BFNVG", errc::missing_field, 1},
    blank_row{"BFNVR", errc::missing_field, 1},
    blank_row{"BFMIS", errc::missing_field, 1},
    blank_row{"BFACK", errc::missing_field, 1},
    blank_row{"BFCTL", errc::missing_field, 1},
    blank_row{"BPLOG", errc::missing_field, 1},
    blank_row{"BPSTS", errc::missing_field, 1},
    blank_row{"BPRMB", errc::missing_field, 1},
    blank_row{"BPABT", errc::missing_field, 1},
    blank_row{"BPVER", errc::missing_field, 1},
    blank_row{"RXHRB", errc::missing_field, 1},
    blank_row{"RXGAT", errc::missing_field, 1},
    blank_row{"RXCOD", errc::missing_field, 1},
    blank_row{"RXDOK", errc::missing_field, 1},
    blank_row{"RXDEL", errc::missing_field, 1},
    blank_row{"PAPGPSCTRL", errc::missing_field, 1},
};
using every_set =
    merge_sets<standard_set, kingfisher_set, sandshark_set, robotx_set, anello_set>::type;
}  // namespace

TEST_CASE("every field blank: decoded where the spec allows it, missing_field where it does not") {
  for (const blank_row& row : blank_rows) {
    REQUIRE(every_set::knows(row.address));
    std::size_t fields = 0;  // every wire field of the message's longest form
    while (!every_set::field_name(row.address, fields + 1).empty()) ++fields;
    const std::string line = resealed("$" + std::string(row.address) + std::string(fields, ','));
    INFO(line);
    for (const parse_policy& p : {liberal, strict}) {
      const auto d = every_set::decode(line, p);
      CHECK(d.ec == row.ec);
      CHECK(d.field == row.field);
      if (d.ok()) {
        // What decodes encodes, and reads back the same (unit letters are written, so the text
        // need not be all blank).
        std::visit(
            [&](const auto& m) {
              using M = std::remove_cvref_t<decltype(m)>;
              if constexpr (!std::is_same_v<M, unknown_sentence>) {
                const auto again = encode(m);
                REQUIRE(again);
                const auto back = decode<M>(again.view(), strict);
                REQUIRE(back);
                CHECK(encode(back.value).view() == again.view());
              }
            },
            d.value);
      }
    }
  }
  // Every message is in the table: it has as many rows as the sets have messages.
  CHECK(blank_rows.size() == every_set::size);
}

// ---------------------------------------------------------------------------------------------
// the binary frame

TEST_CASE("a frame whose length field is 0 or 0xFFFF") {
  for (const std::uint16_t length : {std::uint16_t{0}, std::uint16_t{0xFFFF}, std::uint16_t{47},
                                     std::uint16_t{49}, std::uint16_t{0x3000}}) {
    INFO("length " << length);
    anello::frame_bytes f = seed_frame;
    f[2] = static_cast<std::uint8_t>(length >> 8U);
    f[3] = static_cast<std::uint8_t>(length & 0xFFU);
    // Refused on the header alone: a lying length is never believed, even with 4 bytes only.
    for (const std::size_t n : {std::size_t{4}, f.size()}) {
      const auto r = anello::decode_frame(std::span<const std::uint8_t>(f.data(), n));
      CHECK(r.ec == errc::bad_length);
      CHECK(r.column == 2);
    }
    // In a stream: counted, dropped, and the good frame and sentence after it come out at once.
    static anello::stream_reader<1024> reader;
    reader.reset();
    std::vector<anello::stream_item_kind> kinds;
    const std::string s = as_string(std::span<const std::uint8_t>(f.data(), 4)) +
                          as_string(seed_frame) + std::string(anello_line) + "\r\n";
    reader.feed(s, [&](const anello::stream_item& i) { kinds.push_back(i.kind); });
    CHECK(kinds ==
          std::vector{anello::stream_item_kind::frame, anello::stream_item_kind::sentence});
    CHECK(reader.stats().bad_length_frames == 1);
  }
  // Short, wrong id, wrong CRC: each its own errc, checked in the contract's order.
  CHECK(anello::decode_frame(std::span<const std::uint8_t>(seed_frame.data(), 3)).ec ==
        errc::truncated);
  CHECK(anello::decode_frame(std::span<const std::uint8_t>(seed_frame.data(), 55)).ec ==
        errc::truncated);
  CHECK(anello::decode_frame(std::span<const std::uint8_t>{}).ec == errc::truncated);
  anello::frame_bytes bad = seed_frame;
  bad[1] = 0x01;
  CHECK(anello::decode_frame(bad).ec == errc::bad_frame_id);
  bad = seed_frame;
  bad[30] ^= 0x40U;
  CHECK(anello::decode_frame(bad).ec == errc::crc_mismatch);
}

// ---------------------------------------------------------------------------------------------
// recovery

TEST_CASE("valid data after hostile data in a stream still comes out") {
  const std::vector<std::string> hostile = {
      std::string("\0\0\0\xff\xfe", 5),
      "$GPRMC,\x01\x02\x03" + std::string(100, '\x80'),
      "$GPR$",
      std::string(5000, '$'),
      std::string(5000, ','),
      "$" + std::string(1 << 20, 'A'),
      "*7F\r\n*\r\r\n\n",
      std::string("\xab\x00\x00\x30", 4) + std::string(20, '\0'),    // a frame header cut short
      std::string("\xab\x00\xff\xff", 4),                            // a lying length
      std::string("\xab\x00\x00\x30", 4) + std::string(52, '\x55'),  // 56 bytes, bad CRC
      std::string("\xab\xab\xab\x00\x00\x00\xab", 7),
  };
  const std::vector<std::string> good = {std::string(standard_line), std::string(kingfisher_line),
                                         std::string(sandshark_line), std::string(robotx_line),
                                         std::string(anello_line)};
  std::string stream;
  for (const std::string& h : hostile) {
    stream += h;
    for (const std::string& g : good) stream += "\r\n" + g;
    stream += "\n";
  }
  // Every good line comes out, in order, and decodes; nothing else decodes.
  const auto decodes = [](const std::string& line) {
    return every_set::decode(line + "\r\n", strict).ok() && every_set::decode(line, liberal).ok();
  };
  std::vector<std::string> framed;
  for (const std::string& l : frame_all(stream))
    if (decodes(l)) framed.push_back(l);
  const stream_out read = read_all(stream);
  std::vector<std::string> streamed;
  for (const std::string& l : read.sentences)
    if (decodes(l)) streamed.push_back(l);
  std::vector<std::string> expected;
  for (std::size_t i = 0; i < hostile.size(); ++i)
    expected.insert(expected.end(), good.begin(), good.end());
  CHECK(framed == expected);
  CHECK(streamed == expected);
  CHECK(read.frames.empty());

  // Frames too: a good frame after each hostile piece (and a line break) comes out.
  std::string mixed;
  for (const std::string& h : hostile) mixed += h + "\r\n" + as_string(seed_frame);
  const stream_out frames = read_all(mixed);
  CHECK(frames.frames.size() == hostile.size());
  for (const auto& f : frames.frames) CHECK(f == seed_frame);
}

// ---------------------------------------------------------------------------------------------
// the fuzz dictionary

namespace {
template <class... Ms>
constexpr auto addresses_of(message_set<Ms...>*) {
  return std::array<std::string_view, sizeof...(Ms)>{Ms::nmea.address...};
}
}  // namespace

TEST_CASE("the fuzz dictionary names every address of every family") {
  // fuzz/nmea.dict, next to tests/: a message added without its address there is fuzzed blind.
  std::ifstream in(std::string(SEAWIRE_TEST_DATA_DIR) + "/../../fuzz/nmea.dict");
  REQUIRE(in);
  const std::string dict((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const std::string_view address : addresses_of(static_cast<every_set*>(nullptr))) {
    INFO(address);
    // "--RMC" (any talker) is there with some talker: "$GPRMC,".
    const std::string entry = address.starts_with("--") ? std::string(address.substr(2)) + ",\""
                                                        : "\"$" + std::string(address) + ",\"";
    CHECK(dict.find(entry) != std::string::npos);
  }
}

// ---------------------------------------------------------------------------------------------
// sentences cut short after the address

TEST_CASE("an address with no fields reports its errors inside the line") {
  // Not at the column one past the end ("$GPGGA" once said too_few_fields at column 7).
  for (const std::string_view line : {"$GPGGA", "$GPRMC", "$CPNVG", "$RXHRB", "$IIRPM"}) {
    INFO(line);
    const auto d = every_set::decode(line, liberal);
    CHECK_FALSE(d.ok());
    CHECK(d.column <= line.size());
  }
}
