// SPDX-License-Identifier: BSL-1.0
// Actisense N2K ASCII log lines (nmea2000/log.hpp): read from an Actisense W2K-1's own log,
// written back byte for byte, told apart from the other formats, refused with the token at
// fault; each line a whole message, fast packet or not.

#include <catch2/catch.hpp>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/nmea2000/reader.hpp"

namespace {
namespace n2k = seawire::nmea2000;
using seawire::errc;

std::vector<std::uint8_t> bytes_of(const n2k::log_record& r) {
  return {r.data().begin(), r.data().end()};
}
}  // namespace

TEST_CASE("actisense: a line is time of day, address, PGN and the whole message") {
  // From an Actisense W2K-1 log: Vessel Heading from source 0x13.
  const auto r = n2k::parse_log_line("A000057.086 13FF2 1F112 005679FF7FFF7FFD");
  REQUIRE(r);
  CHECK(r.value.format == n2k::log_format::actisense_n2k_ascii);
  CHECK(*r.value.time_us == 57'086'000);
  CHECK(r.value.id.source == 0x13);
  CHECK(r.value.id.destination == 0xFF);
  CHECK(r.value.id.priority == 2);
  CHECK(r.value.id.pgn == 127250);
  CHECK(r.value.assembled);
  CHECK(bytes_of(r.value) ==
        std::vector<std::uint8_t>{0x00, 0x56, 0x79, 0xFF, 0x7F, 0xFF, 0x7F, 0xFD});
  // A fast-packet message whole on one line (29 bytes), and one of 10.
  const auto f = n2k::parse_log_line(
      "A000057.100 05FF6 1F805 00D4470000000000000000000000000000000000000000000000000000");
  REQUIRE(f);
  CHECK(f.value.id.pgn == 129029);
  CHECK(f.value.size == 29);
  CHECK(f.value.assembled);
  // An addressed PGN keeps its destination; a broadcast one's is everyone's.
  const auto a = n2k::parse_log_line("A123456.7 0A236 0EA00 14F001");
  REQUIRE(a);
  CHECK(a.value.id.pgn == 59904);
  CHECK(a.value.id.destination == 0x23);
  CHECK(a.value.id.priority == 6);
  CHECK(*a.value.time_us == ((12 * 60 + 34) * 60 + 56) * 1'000'000LL + 700'000);
  const auto b = n2k::parse_log_line("A000000 0A236 1F112 FF");
  REQUIRE(b);
  CHECK(b.value.id.destination == n2k::broadcast_address);
  CHECK(*b.value.time_us == 0);
  CHECK(n2k::detect_log_format("A000057.086 13FF2 1F112 00") ==
        n2k::log_format::actisense_n2k_ascii);
  CHECK(n2k::log_format_named("actisense_n2k_ascii") == n2k::log_format::actisense_n2k_ascii);
  CHECK(n2k::log_format_of(n2k::canboat_format::actisense_n2k_ascii) ==
        n2k::log_format::actisense_n2k_ascii);
}

TEST_CASE("actisense: malformed lines name the token and the reason") {
  const struct {
    std::string_view line;
    errc ec;
    std::uint16_t field;
  } rows[] = {
      {"A240057.086 13FF2 1F112 00", errc::bad_time, 1},
      {"A006057.086 13FF2 1F112 00", errc::bad_time, 1},
      {"A000057. 13FF2 1F112 00", errc::bad_time, 1},
      {"A0000570 13FF2 1F112 00", errc::bad_time, 1},
      {"A000057.086 13FF 1F112 00", errc::bad_can_id, 2},
      {"A000057.086 13FF8 1F112 00", errc::bad_can_id, 2},  // priority 8
      {"A000057.086 13FFG 1F112 00", errc::bad_can_id, 2},
      {"A000057.086 13FF2 4F112 00", errc::bad_can_id, 3},  // beyond 18 bits
      {"A000057.086 13FF2 11F112 00", errc::bad_can_id, 3},
      {"A000057.086 13FF2 1F112 005", errc::bad_length, 4},
      {"A000057.086 13FF2 1F112 00ZZ", errc::bad_number, 4},
      {"A000057.086 13FF2 1F112 00 11", errc::bad_log_line, 4},
  };
  for (const auto& row : rows) {
    INFO(std::string(row.line));
    const auto r = n2k::parse_log_line(row.line);
    CHECK(r.ec == row.ec);
    CHECK(r.field == row.field);
  }
  std::string long_line = "A000057.086 13FF2 1F805 ";
  long_line.append(2 * 224, '0');  // one byte more than a fast packet holds
  CHECK(n2k::parse_log_line(long_line).ec == errc::bad_length);
  CHECK(n2k::log_field_name(n2k::log_format::actisense_n2k_ascii, 2) == "address");
  CHECK(n2k::log_field_name(n2k::log_format::actisense_n2k_ascii, 4) == "data");
}

TEST_CASE("actisense: lines are written as they are read, whole messages included") {
  const std::string_view lines[] = {
      "A000057.086 13FF2 1F112 005679FF7FFF7FFD",
      "A235959.999 09FF7 0FF00 3F9FDCFFFFFFFFFF",
      "A000057.100 05FF6 1F805 00D4470000000000000000000000000000000000000000000000000000",
      "A123456.700 0A236 0EA00 14F001",
  };
  for (const std::string_view line : lines) {
    INFO(std::string(line));
    const auto r = n2k::parse_log_line(line);
    REQUIRE(r);
    seawire::nmea::json_buffer<1024> out;
    REQUIRE(n2k::write_log_line(out, r.value, n2k::log_format::actisense_n2k_ascii) == errc::ok);
    CHECK(out.view() == std::string(line) + "\n");
  }
  // From a candump -L frame: the time of day of its Unix time, to the millisecond.
  const auto c = n2k::parse_log_line("(1720021378.123456) can0 19F51323#000EC34D201EB921");
  REQUIRE(c);
  seawire::nmea::json_buffer<256> out;
  REQUIRE(n2k::write_log_line(out, c.value, n2k::log_format::actisense_n2k_ascii) == errc::ok);
  CHECK(out.view() == "A154258.123 23FF6 1F513 000EC34D201EB921\n");
}

TEST_CASE("actisense: the reader hands a fast-packet PGN's line on whole") {
  // 130578 is a fast packet; on an Actisense line its 12 bytes are the message, not a frame.
  n2k::log_reader<> reader;
  std::vector<std::vector<std::uint8_t>> got;
  const auto r = reader.read_line("A000001.000 23FF2 1FE12 FA00FFFF0000FFFF00000000",
                                  [&](const n2k::message_header& h, auto payload) {
                                    CHECK(h.id.pgn == 130578);
                                    got.emplace_back(payload.begin(), payload.end());
                                  });
  CHECK(r.ec == errc::ok);
  REQUIRE(got.size() == 1);
  CHECK(got[0].size() == 12);
  // A short one too: 6 bytes that a frame reading would take for a header.
  got.clear();
  (void)reader.read_line("A000001.000 23FF2 1FE12 FA00FFFF0000",
                         [&](const n2k::message_header&, auto payload) {
                           got.emplace_back(payload.begin(), payload.end());
                         });
  REQUIRE(got.size() == 1);
  CHECK(got[0] == std::vector<std::uint8_t>{0xFA, 0x00, 0xFF, 0xFF, 0x00, 0x00});
}
