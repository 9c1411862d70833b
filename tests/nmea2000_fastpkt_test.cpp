// SPDX-License-Identifier: BSL-1.0
// A whole NMEA 2000 bus, beyond the PGNs seawire declares: the standard's list of fast-packet PGNs
// (fast_packets.hpp) checked against a second statement of canboat's database written here, the
// log reader assembling a PGN it has no description of, and canboat's pseudo-PGNs (a gateway's
// own messages) read, skipped and counted.

#include <catch2/catch.hpp>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/fast_packets.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/nmea2000/reader.hpp"
#include "seawire/registry.hpp"

namespace {
namespace n2k = seawire::nmea2000;
using seawire::errc;

// canboat's database (analyzer/pgn-generated-data.h), its PGNs of type "Fast" below the
// pseudo-PGNs, written as runs of consecutive numbers rather than one by one: the table in the
// library is one list, this a second, so a slip in one shows against the other.
constexpr std::pair<std::uint32_t, std::uint32_t> canboat_fast_runs[] = {
    {126208, 126208}, {126464, 126464}, {126720, 126720}, {126983, 126988}, {126996, 126996},
    {126998, 126998}, {127233, 127233}, {127237, 127237}, {127489, 127491}, {127494, 127498},
    {127503, 127504}, {127506, 127507}, {127509, 127514}, {128275, 128275}, {128520, 128520},
    {128538, 128538}, {129029, 129029}, {129038, 129041}, {129044, 129045}, {129284, 129285},
    {129301, 129302}, {129538, 129538}, {129540, 129542}, {129545, 129545}, {129547, 129547},
    {129549, 129549}, {129551, 129551}, {129556, 129556}, {129792, 129816}, {130052, 130054},
    {130060, 130061}, {130064, 130074}, {130320, 130324}, {130329, 130330}, {130561, 130575},
    {130577, 130578}, {130580, 130581}, {130583, 130584}, {130586, 130586}, {130816, 130852},
    {130856, 130856}, {130860, 130860}, {130880, 130881}, {130900, 130900}, {130910, 130913},
    {130918, 130918}, {130921, 130921}, {130939, 130939}, {130944, 130947}, {130951, 130951},
    {131008, 131008}, {131011, 131012}};

bool canboat_says_fast(std::uint32_t pgn) {
  for (const auto& [first, last] : canboat_fast_runs)
    if (pgn >= first && pgn <= last) return true;
  return false;
}

// The standard's framing by range (NMEA 2000 and ISO 11783 PGN ranges): the two proprietary
// fast-packet ranges whole, the proprietary single-frame ones (61184 addressed, 65280-65535)
// and everything below 0x10000 single.
bool standard_range_says_fast(std::uint32_t pgn) {
  return (pgn >= 126720 && pgn <= 126975) || (pgn >= 130816 && pgn <= 131071);
}

struct delivered {
  n2k::message_header head;
  std::vector<std::uint8_t> payload;
};

using bus_reader = n2k::log_reader<seawire::registry::pgns>;

// What a log_reader of every declared PGN handed on of `lines`, and the reader after them.
struct read_out {
  std::vector<delivered> got;
  bus_reader reader;
};

read_out read_all(std::span<const std::string_view> lines) {
  read_out out;
  for (const std::string_view line : lines) {
    INFO(std::string(line));
    const auto r = out.reader.read_line(line, [&](const n2k::message_header& h, auto payload) {
      out.got.push_back({h, {payload.begin(), payload.end()}});
    });
    CHECK(r.ec == errc::ok);
  }
  return out;
}

}  // namespace

TEST_CASE("fast-packet list: every PGN as canboat's database and the standard's ranges say") {
  std::size_t fast = 0;
  for (std::uint32_t pgn = 0; pgn <= n2k::max_pgn + 1024; ++pgn) {
    const bool want = canboat_says_fast(pgn) || standard_range_says_fast(pgn);
    if (n2k::is_fast_packet_pgn(pgn) != want) {
      INFO("PGN " << pgn);
      CHECK(n2k::is_fast_packet_pgn(pgn) == want);
    }
    fast += want ? 1 : 0;
  }
  // 123 standard PGNs, 256 + 256 proprietary
  CHECK(fast == 123 + 512);
  CHECK(n2k::standard_fast_packet_pgns.size() == 123);
  // the edges of each range, and the single-frame proprietary ranges
  static_assert(n2k::is_fast_packet_pgn(126720) && n2k::is_fast_packet_pgn(126975));
  static_assert(!n2k::is_fast_packet_pgn(126719) && !n2k::is_fast_packet_pgn(126976));
  static_assert(n2k::is_fast_packet_pgn(130816) && n2k::is_fast_packet_pgn(131071));
  static_assert(!n2k::is_fast_packet_pgn(130815) && !n2k::is_fast_packet_pgn(131072));
  static_assert(!n2k::is_fast_packet_pgn(61184) && !n2k::is_fast_packet_pgn(65280) &&
                !n2k::is_fast_packet_pgn(65535));
  static_assert(n2k::is_fast_packet_pgn(129029) && !n2k::is_fast_packet_pgn(129025));
  // canboat's pseudo-PGNs come whole, never as frames
  static_assert(!n2k::is_fast_packet_pgn(262386) && !n2k::is_fast_packet_pgn(262400));
}

TEST_CASE("fast-packet list: every PGN seawire declares has the framing the list gives it") {
  seawire::registry::pgns::for_each_type([](const auto& tag) {
    using P = std::remove_cvref_t<decltype(tag)>;
    INFO(n2k::pgn_table<P>.info.pgn);
    CHECK((n2k::pgn_table<P>.info.transport == n2k::framing::fast_packet) ==
          n2k::is_fast_packet_pgn(n2k::pgn_table<P>.info.pgn));
    CHECK(bus_reader::is_fast(n2k::pgn_table<P>.info.pgn) ==
          n2k::is_fast_packet_pgn(n2k::pgn_table<P>.info.pgn));
  });
  // a PGN no list declares: the standard's framing
  CHECK(n2k::log_reader<n2k::ins_input_pgns>::is_fast(129029));
  CHECK_FALSE(n2k::log_reader<n2k::ins_input_pgns>::is_fast(65359));
}

TEST_CASE("log reader: a fast-packet PGN seawire does not describe comes whole") {
  // From a capture of a real bus (candump -L): a Raymarine proprietary message (126720, 9
  // bytes in two frames) between two frames of its proprietary single-frame 65359, then an
  // undescribed standard PGN of the "mixed" range (126976, not in the list) sent as two frames.
  constexpr std::string_view lines[] = {
      "(1502984867.025933) slcan0 1DEFFFCC#00093B9FF081AE02",
      "(1502984867.031501) slcan0 1CFF4FCC#3B9FFFFFFF765AFF",
      "(1502984867.025937) slcan0 1DEFFFCC#01000CA5FFFFFFFF",
      "(1502984867.100000) slcan0 1DF000CC#2007010203040506",
      "(1502984867.100001) slcan0 1DF000CC#2107FFFFFFFFFFFF",
  };
  const auto [got, reader] = read_all(lines);
  REQUIRE(got.size() == 4);
  CHECK(got[0].head.id.pgn == 65359);
  CHECK(got[0].payload ==
        std::vector<std::uint8_t>{0x3B, 0x9F, 0xFF, 0xFF, 0xFF, 0x76, 0x5A, 0xFF});
  CHECK(got[1].head.id.pgn == 126720);
  CHECK(got[1].head.id.source == 0xCC);
  CHECK(got[1].head.id.destination == 0xFF);
  CHECK(got[1].head.id.priority == 7);
  CHECK(*got[1].head.time_us == 1502984867025937);  // the frame that completed it
  CHECK(got[1].payload ==
        std::vector<std::uint8_t>{0x3B, 0x9F, 0xF0, 0x81, 0xAE, 0x02, 0x00, 0x0C, 0xA5});
  CHECK(got[2].head.id.pgn == 126976);
  CHECK(got[2].payload ==
        std::vector<std::uint8_t>{0x20, 0x07, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06});
  CHECK(got[3].head.id.pgn == 126976);
  CHECK(reader.assembler().packets() == 1);
  CHECK(reader.assembler().frames_assembled() == 2);
  CHECK(reader.assembler().frames_in() == 2);

  // A log reader of the six INS PGNs assembles a PGN the registry declares but it does not
  // (129284, Navigation Data, 34 bytes) by the list, as one with the registry does.
  const std::vector<std::uint8_t> payload = [] {
    std::vector<std::uint8_t> p(34);
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = static_cast<std::uint8_t>(i * 7 + 1);
    return p;
  }();
  const auto frames = n2k::split_fast_packet(payload, 3);
  REQUIRE(frames);
  n2k::log_reader<n2k::ins_input_pgns> six;
  std::vector<std::vector<std::uint8_t>> whole;
  for (const n2k::frame_data& f : frames.value.view()) {
    n2k::log_record rec;
    rec.id = {3, 129284, 0x23, n2k::broadcast_address};
    rec.time_us = 1;
    REQUIRE(rec.assign(f.view()));
    seawire::nmea::json_buffer<256> line;
    REQUIRE(n2k::write_log_line(line, rec, n2k::log_format::candump_log) == errc::ok);
    CHECK(six.read_line(line.view(), [&](const n2k::message_header& h, auto p) {
      CHECK(h.id.pgn == 129284);
      whole.emplace_back(p.begin(), p.end());
    }));
  }
  REQUIRE(whole.size() == 1);
  CHECK(whole[0] == payload);
}

TEST_CASE("pseudo-PGNs: read from canboat and Actisense lines, skipped and counted by the reader") {
  // canboat lines from real logs: an Actisense NGT-1's status (262386, 33 bytes) and 262161
  const auto r = n2k::parse_log_line(
      "2016-02-28T19:57:02.480Z,0,262386,0,0,33,01,0e,00,d7,e2,01,00,00,00,00,00,02,20,04,00,00,"
      "01,00,01,00,00,00,4e,62,02,13,00,01,01,1c,01,0a,0e");
  REQUIRE(r);
  CHECK(r.value.id.pgn == 262386);
  CHECK(n2k::is_pseudo_pgn(r.value.id.pgn));
  CHECK(r.value.id.destination == 0);  // as the line says: no CAN identifier decides it
  CHECK(r.value.size == 33);
  // no CAN identifier carries one: writing it back is refused precisely
  seawire::nmea::json_buffer<1024> out;
  CHECK(n2k::write_log_line(out, r.value, n2k::log_format::canboat) == errc::bad_can_id);
  // Actisense N2K ASCII: five hex digits
  const auto a = n2k::parse_log_line("A000057.086 00002 40100 0102");
  REQUIRE(a);
  CHECK(a.value.id.pgn == 0x40100);
  CHECK(a.value.id.source == 0);
  // A canboat line: any number of 32 bits past 18 (canboat's Actisense reader wrote these, empty,
  // in real logs); more than 32 bits is no number anyone writes.
  const auto odd = n2k::parse_log_line("2016-04-09T16:41:09.092Z,0,16057090,255,1,0");
  REQUIRE(odd);
  CHECK(odd.value.id.pgn == 16057090);
  CHECK(n2k::is_pseudo_pgn(odd.value.id.pgn));
  CHECK(n2k::parse_log_line("2016-02-28T19:57:02.480Z,0,4294967295,0,0,1,01"));
  const auto big = n2k::parse_log_line("2016-02-28T19:57:02.480Z,0,4295229440,0,0,1,01");
  CHECK(big.ec == errc::bad_can_id);
  CHECK(big.field == 3);
  // An Actisense line: canboat's range ends at 0x402FF; past it, no PGN of anyone
  CHECK(n2k::parse_log_line("A000057.086 00002 40300 0102").ec == errc::bad_can_id);
  CHECK(n2k::parse_log_line("A000057.086 00002 402FF 0102"));
  static_assert(n2k::is_pseudo_pgn(0x40000) && n2k::is_pseudo_pgn(0x402FF) &&
                n2k::is_pseudo_pgn(0xFFFFFFFF));
  static_assert(!n2k::is_pseudo_pgn(n2k::max_pgn) && !n2k::is_pseudo_pgn(0));

  // A canboat log without a header whose first line is a frame (PLAIN_OR_FAST): the gateway's
  // 33-byte status among frames does not make the log FAST, the frames after it are still
  // assembled; its lines are skipped (no message), counted.
  constexpr std::string_view lines[] = {
      "2016-02-28T19:57:02.364Z,2,127250,7,255,8,ff,10,3b,ff,7f,ce,f5,fc",
      "2016-02-28T19:57:02.480Z,0,262386,0,0,33,01,0e,00,d7,e2,01,00,00,00,00,00,02,20,04,00,00,"
      "01,00,01,00,00,00,4e,62,02,13,00,01,01,1c,01,0a,0e",
      "2016-02-28T19:57:02.500Z,7,130842,12,255,8,40,0a,3b,9f,01,02,03,04",
      "2016-02-28T19:57:02.501Z,7,130842,12,255,8,41,05,06,07,08,ff,ff,ff",
      "A000057.086 00002 40100 0102",
      "2016-04-09T16:41:09.092Z,0,16057090,255,1,0",
  };
  const auto [got, reader] = read_all(lines);
  CHECK(reader.pseudo_pgn_lines() == 3);
  CHECK(reader.canboat_lines() == n2k::canboat_format::plain_or_fast);
  REQUIRE(got.size() == 2);
  CHECK(got[0].head.id.pgn == 127250);
  CHECK(got[1].head.id.pgn == 130842);
  CHECK(got[1].payload ==
        std::vector<std::uint8_t>{0x3B, 0x9F, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08});

  // A PLAIN log (its header says so): a pseudo-PGN line longer than 8 bytes is no bad frame.
  constexpr std::string_view plain_lines[] = {
      "# format=PLAIN",
      "2011-04-25-10:16:42.460,0,262388,0,0,15,01,0e,00,ab,b0,01,00,47,fd,ff,ff,f2,00,04,00"};
  const read_out plain = read_all(plain_lines);
  CHECK(plain.got.empty());
  CHECK(plain.reader.pseudo_pgn_lines() == 1);
}
