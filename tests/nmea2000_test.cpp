// SPDX-License-Identifier: BSL-1.0
// NMEA 2000: CAN identifiers, field values and sentinels, the six PGNs against real captures
// decoded by canboat, fast packets (splitting, assembling, every drop reason), log formats.

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "seawire/nmea2000/can_id.hpp"
#include "seawire/nmea2000/fast_packet.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/nmea2000/reader.hpp"
#include "support.hpp"

namespace n2k = seawire::nmea2000;
using seawire::errc;
using support::hex_bytes;
using support::hex_of;

namespace {

template <n2k::pgn_like P>
P decode_hex(std::string_view hex) {
  const auto b = hex_bytes(hex);
  return n2k::decode<P>(b);
}

template <std::size_t N>
std::string json_of(const n2k::message_header& h, const auto& msg) {
  seawire::nmea::json_buffer<N> b;
  n2k::write_json(b, h, msg);
  REQUIRE_FALSE(b.overflow());
  return std::string(b.view());
}

std::vector<std::string> read_lines(const std::string& name) {
  std::ifstream in(std::string(SEAWIRE_TEST_DATA_DIR) + "/n2k/" + name);
  REQUIRE(in.good());
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// CAN identifier

static_assert(n2k::parse_can_id(0x09F20023).value.pgn == 127488);
static_assert(n2k::make_can_id({2, 130578, 0x23, 255}).value == 0x09FE1223);

TEST_CASE("CAN identifiers of the six PGNs, both ways") {
  const struct {
    std::uint32_t id;
    std::uint32_t pgn;
    std::uint8_t prio;
  } rows[] = {{0x09F20023, 127488, 2}, {0x09F20123, 127489, 2}, {0x09F50323, 128259, 2},
              {0x19F51323, 128275, 6}, {0x15FD0723, 130311, 5}, {0x09FE1223, 130578, 2}};
  for (const auto& row : rows) {
    const auto f = n2k::parse_can_id(row.id);
    REQUIRE(f);
    CHECK(f.value.pgn == row.pgn);
    CHECK(f.value.priority == row.prio);
    CHECK(f.value.source == 0x23);
    CHECK(f.value.destination == 255);
    CHECK(n2k::make_can_id(f.value).value == row.id);
  }
  // priority 6 on a PGN whose default is 2 (real devices do this)
  CHECK(n2k::parse_can_id(0x19F20000).value.priority == 6);
  CHECK(n2k::parse_can_id(0x19F20000).value.pgn == 127488);
}

TEST_CASE("addressed (PDU1) identifiers carry the destination in PS") {
  // ISO request 59904 (0xEA00) to address 0x1C from 0x23
  const auto f = n2k::parse_can_id(0x18EA1C23);
  REQUIRE(f);
  CHECK(f.value.pgn == 59904);
  CHECK(f.value.destination == 0x1C);
  CHECK(f.value.priority == 6);
  CHECK(n2k::make_can_id(f.value).value == 0x18EA1C23);
  CHECK(n2k::is_addressed(59904));
  CHECK_FALSE(n2k::is_addressed(128259));
}

TEST_CASE("bad CAN identifiers are refused") {
  CHECK(n2k::parse_can_id(0x20000000).ec == errc::bad_can_id);           // 30 bits
  CHECK(n2k::parse_can_id(0x89F20023).ec == errc::bad_can_id);           // EFF flag left on
  CHECK(n2k::make_can_id({8, 128259, 1, 255}).ec == errc::bad_can_id);   // priority
  CHECK(n2k::make_can_id({2, 0x40000, 1, 255}).ec == errc::bad_can_id);  // 19-bit PGN
  CHECK(n2k::make_can_id({6, 59905, 1, 255}).ec == errc::bad_can_id);    // PDU1, low byte
  CHECK(n2k::make_can_id({2, 128259, 1, 7}).ec == errc::bad_can_id);     // PDU2 addressed
}

// ---------------------------------------------------------------------------------------------
// field values

TEST_CASE("sentinels are states, not numbers") {
  using u16 = n2k::unsigned_number<16, n2k::resolution{1, -2}>;
  CHECK(u16{}.state() == n2k::field_state::not_available);
  CHECK_FALSE(u16{}.value());
  CHECK(u16::from_raw(0xFFFE).state() == n2k::field_state::out_of_range);
  CHECK(u16::from_raw(0xFFFD).state() == n2k::field_state::reserved);
  CHECK(u16::from_raw(0xFFFC).state() == n2k::field_state::value);
  CHECK(*u16::from_raw(0xFFFC).value() == Approx(655.32));
  using s16 = n2k::signed_number<16, n2k::resolution{1, -3}>;
  CHECK(s16::from_raw(0x7FFF).state() == n2k::field_state::not_available);
  CHECK(s16::from_raw(0x7FFE).state() == n2k::field_state::out_of_range);
  CHECK(s16::from_raw(0x7FFD).state() == n2k::field_state::reserved);
  CHECK(*s16::from_raw(-32768).value() == Approx(-32.768));  // an ordinary value
  using u4 = n2k::unsigned_number<4>;
  CHECK(u4::from_raw(15).state() == n2k::field_state::not_available);
  CHECK(u4::from_raw(14).state() == n2k::field_state::out_of_range);
  CHECK(u4::from_raw(13).state() == n2k::field_state::value);
  using l2 = n2k::lookup<n2k::humidity_source, 2>;
  // lookups, as canboat reads them: three sentinels above 2 bits, two of 2 bits (J1939's
  // "error" and "not available" of a two-bit state)
  CHECK(l2::from_raw(3).state() == n2k::field_state::not_available);
  CHECK(l2::from_raw(2).state() == n2k::field_state::out_of_range);
  CHECK(l2::from_raw(1).state() == n2k::field_state::value);
  using l6 = n2k::lookup<n2k::temperature_source, 6>;
  CHECK(l6::from_raw(63).state() == n2k::field_state::not_available);
  CHECK(l6::from_raw(62).state() == n2k::field_state::out_of_range);
  CHECK(l6::from_raw(61).state() == n2k::field_state::reserved);
  CHECK(l6::from_raw(60).state() == n2k::field_state::value);
  using l8 = n2k::lookup<n2k::water_reference, 8>;
  CHECK(l8::from_raw(253).state() == n2k::field_state::reserved);
  CHECK(l8::from_raw(252).state() == n2k::field_state::value);
  // flag words have no sentinel: all ones is every flag
  const auto all = n2k::flags<n2k::engine_status_1, 16>::from_raw(0xFFFF);
  CHECK(all.test(n2k::engine_status_1::emergency_stop));
  CHECK(all.state() == n2k::field_state::value);
}

TEST_CASE("physical values become raw integers exactly") {
  using temp = n2k::unsigned_number<16, n2k::resolution{1, -2}>;
  auto t = temp::from(363.15);  // 363.15 / 0.01 in doubles is 36314.999...
  REQUIRE(t);
  CHECK(t.value.raw() == 36315);
  using humidity = n2k::signed_number<16, n2k::resolution{4, -3}>;
  CHECK(humidity::from(60.116).value.raw() == 15029);
  CHECK(humidity::from(-0.002).value.raw() == -1);  // halves away from zero
  using rpm = n2k::unsigned_number<16, n2k::resolution{25, -2}>;
  CHECK(rpm::from(798.5).value.raw() == 3194);
  CHECK(rpm::from(798.6).value.raw() == 3194);
  CHECK(rpm::from(798.63).value.raw() == 3195);
  using pa = n2k::unsigned_number<16, n2k::resolution{1, 2}>;
  CHECK(pa::from(158300).value.raw() == 1583);
  CHECK(pa::from(6553200).value.raw() == 65532);
  CHECK(pa::from(6553300).ec == errc::out_of_range);  // would be the out-of-range sentinel
  CHECK(pa::from(-100).ec == errc::out_of_range);
  CHECK(pa::from(std::numeric_limits<double>::quiet_NaN()).ec == errc::not_finite);
  CHECK(pa::from(std::numeric_limits<double>::infinity()).ec == errc::not_finite);
  using speed = n2k::signed_number<16, n2k::resolution{1, -3}>;
  CHECK(speed::from(-32.768).value.raw() == -32768);
  CHECK(speed::from(32.764).value.raw() == 32764);
  CHECK(speed::from(32.765).ec == errc::out_of_range);
  CHECK(speed::from(1e300).ec == errc::out_of_range);
  CHECK(speed::from(1e-300).value.raw() == 0);
  CHECK(speed::from(seawire::nmea::decimal::parse("2.5005").value).value.raw() == 2501);
  n2k::speed_water_referenced m;
  CHECK(m.speed_water_mps.assign(3.2) == errc::ok);
  CHECK(m.speed_water_mps.raw() == 320);
  CHECK(m.speed_water_mps.assign(700.0) == errc::out_of_range);
  CHECK(m.speed_water_mps.raw() == 320);  // unchanged
}

// A plain number never becomes a field value: it could mean the raw integer or the physical value.
static_assert(!std::is_constructible_v<n2k::unsigned_number<16, n2k::resolution{1, -2}>, double>);
static_assert(!std::is_constructible_v<n2k::unsigned_number<16, n2k::resolution{1, -2}>, int>);
static_assert(!std::is_assignable_v<n2k::unsigned_number<8>&, int>);
static_assert(!std::is_assignable_v<n2k::signed_number<16>&, double>);
static_assert(std::is_assignable_v<n2k::lookup<n2k::water_reference, 8>&, n2k::water_reference>);

TEST_CASE("date and time of day") {
  using namespace std::chrono;
  const auto d = n2k::day_count::from(sys_days(year{2024} / July / 3));
  REQUIRE(d);
  CHECK(d.value.raw() == 19907);
  CHECK(*d.value.value() == sys_days(year{2024} / July / 3));
  CHECK(n2k::day_count::from(sys_days(year{1969} / December / 31)).ec == errc::out_of_range);
  const auto t = n2k::time_since_midnight::from(hours(15) + minutes(42) + seconds(58));
  REQUIRE(t);
  CHECK(t.value.raw() == 565780000);
  CHECK(n2k::time_since_midnight::from(seconds(86402)).ec == errc::out_of_range);
  CHECK(n2k::time_since_midnight::from(seconds(-1)).ec == errc::out_of_range);
}

// ---------------------------------------------------------------------------------------------
// the six PGNs: real captures (canboat's samples), values as canboat decodes them

TEST_CASE("127488 Engine Parameters, Rapid Update") {
  const auto m = decode_hex<n2k::engine_parameters_rapid>("007a0cffff7fffff");
  CHECK(m.instance.raw() == 0);
  CHECK(*m.speed_rpm.value() == 798.5);
  CHECK_FALSE(m.boost_pressure_pa.value());
  CHECK_FALSE(m.tilt_trim_pct.value());
  CHECK(n2k::encode(m).value ==
        std::array<std::uint8_t, 8>{0x00, 0x7a, 0x0c, 0xff, 0xff, 0x7f, 0xff, 0xff});
  // reserved bytes sent as 00 00 by some engines: ignored, re-sent as ones
  const auto y = decode_hex<n2k::engine_parameters_rapid>("00fcff00008000 00");
  CHECK(*y.speed_rpm.value() == 16383.0);
  CHECK(*y.boost_pressure_pa.value() == 0);
  CHECK(*y.tilt_trim_pct.value() == -128);
  CHECK(n2k::encode(y).value[6] == 0xFF);
}

TEST_CASE("127489 Engine Parameters, Dynamic") {
  const auto m = decode_hex<n2k::engine_parameters_dynamic>(
      "002f06ffffe3736505ff7f72100000ffffffffff060000007f7f");
  CHECK(*m.oil_pressure_pa.value() == 158300);
  CHECK_FALSE(m.oil_temperature_k.value());
  CHECK(*m.temperature_k.value() == Approx(296.67));
  CHECK(*m.alternator_potential_v.value() == Approx(13.81));
  CHECK_FALSE(m.fuel_rate_lph.value());
  CHECK(*m.total_engine_hours_s.value() == 4210);
  CHECK_FALSE(m.coolant_pressure_pa.value());
  CHECK_FALSE(m.fuel_pressure_pa.value());
  CHECK(m.discrete_status_1 ==
        n2k::flags<n2k::engine_status_1, 16>{n2k::engine_status_1::over_temperature,
                                             n2k::engine_status_1::low_oil_pressure});
  CHECK(m.discrete_status_2.raw() == 0);
  CHECK(m.engine_load_pct.state() == n2k::field_state::not_available);
  // signed n/a sent as all ones by some devices decodes as -0.1 L/h and -1 %, as canboat does
  const auto o = decode_hex<n2k::engine_parameters_dynamic>(
      "0b0000ffffb9796e0affffc8d3ea00ffffffffff00000000ffff");
  CHECK(*o.fuel_rate_lph.value() == Approx(-0.1));
  CHECK(*o.engine_load_pct.value() == -1);
  CHECK(*o.total_engine_hours_s.value() == 15389640);
  const auto b = hex_bytes("002f06ffffe3736505ff7f72100000ffffffffff060000007f7f");
  const auto e = n2k::encode(m);
  REQUIRE(e);
  CHECK(std::vector<std::uint8_t>(e.value.begin(), e.value.end()) == b);
}

TEST_CASE("128259 Speed, Water Referenced") {
  const auto m = decode_hex<n2k::speed_water_referenced>("ff0000ffff03ffff");
  CHECK_FALSE(m.sid.value());
  CHECK(*m.speed_water_mps.value() == 0);
  CHECK_FALSE(m.speed_ground_mps.value());
  CHECK(m.speed_type == n2k::water_reference::correlation);
  CHECK(m.speed_type.name() == "correlation");
  CHECK(m.speed_direction.state() == n2k::field_state::not_available);
  // special values, one of each state
  const auto s = decode_hex<n2k::speed_water_referenced>("07feff fdff feefff");
  CHECK(*s.sid.value() == 7);
  CHECK(s.speed_water_mps.state() == n2k::field_state::out_of_range);
  CHECK(s.speed_ground_mps.state() == n2k::field_state::reserved);
  CHECK(s.speed_type.state() == n2k::field_state::out_of_range);
  CHECK(s.speed_direction.state() == n2k::field_state::not_available);
  // a value the lookup does not name is kept
  const auto u = decode_hex<n2k::speed_water_referenced>("01e80300000bffff");
  CHECK(u.speed_type.raw() == 11);
  CHECK(u.speed_type.name().empty());
  CHECK(u.speed_type.value());
}

TEST_CASE("128275 Distance Log") {
  const auto m = decode_hex<n2k::distance_log>("ffffffffffffe3bb0900e3bb0900");
  CHECK_FALSE(m.date.value());
  CHECK_FALSE(m.time.value());
  CHECK(*m.log_m.value() == 637923);
  CHECK(*m.trip_log_m.value() == 637923);
  const auto d = decode_hex<n2k::distance_log>("c34d201eb92140e20100d21e0000");
  using namespace std::chrono;
  CHECK(*d.date.value() == sys_days(year{2024} / July / 3));
  CHECK(d.time.value()->count() == 565780000);
  CHECK(*d.log_m.value() == 123456);
  CHECK(*d.trip_log_m.value() == 7890);
}

TEST_CASE("130311 Environmental Parameters") {
  const auto m = decode_hex<n2k::environmental_parameters>("b5418e75b53af203");
  CHECK(*m.sid.value() == 181);
  CHECK(m.temperature_source == n2k::temperature_source::outside);
  CHECK(m.humidity_source == n2k::humidity_source::outside);
  CHECK(*m.temperature_k.value() == Approx(300.94));
  CHECK(*m.humidity_pct.value() == Approx(60.116));
  CHECK(*m.atmospheric_pressure_pa.value() == 101000);
  const auto c0 = decode_hex<n2k::environmental_parameters>("ffc0d96fff7fffff");
  CHECK(c0.temperature_source == n2k::temperature_source::sea);
  CHECK(c0.humidity_source.state() == n2k::field_state::not_available);
}

TEST_CASE("130578 Vessel Speed Components") {
  const auto m = decode_hex<n2k::vessel_speed_components>("ff7fff7f910dbafeff7f03fe");
  CHECK_FALSE(m.longitudinal_water_mps.value());
  CHECK_FALSE(m.transverse_water_mps.value());
  CHECK(*m.longitudinal_ground_mps.value() == Approx(3.473));
  CHECK(*m.transverse_ground_mps.value() == Approx(-0.326));
  CHECK_FALSE(m.stern_water_mps.value());
  CHECK(*m.stern_ground_mps.value() == Approx(-0.509));
}

TEST_CASE("a payload shorter than the PGN leaves the missing fields not available") {
  const auto m = decode_hex<n2k::speed_water_referenced>("0132");  // sid only, speed cut
  CHECK(*m.sid.value() == 1);
  CHECK(m.speed_water_mps.state() == n2k::field_state::not_available);
  CHECK(n2k::decode<n2k::distance_log>(std::span<const std::uint8_t>{}) == n2k::distance_log{});
}

TEST_CASE("encode refuses a raw value wider than its field, naming it") {
  n2k::speed_water_referenced m;
  m.speed_direction = n2k::unsigned_number<4>::from_raw(16);
  const auto e = n2k::encode(m);
  CHECK(e.ec == errc::value_too_large);
  CHECK(e.field == 5);
  CHECK(n2k::field_name<n2k::speed_water_referenced>(e.field) == "speed_direction");
}

TEST_CASE("tables: lengths, framing and offsets as the standard lays them out") {
  CHECK(n2k::description_of<n2k::engine_parameters_rapid>::length == 8);
  CHECK(n2k::description_of<n2k::engine_parameters_dynamic>::length == 26);
  CHECK(n2k::description_of<n2k::speed_water_referenced>::length == 8);
  CHECK(n2k::description_of<n2k::distance_log>::length == 14);
  CHECK(n2k::description_of<n2k::environmental_parameters>::length == 8);
  CHECK(n2k::description_of<n2k::vessel_speed_components>::length == 12);
  std::map<std::string_view, unsigned> offsets;
  n2k::pgn_table<n2k::engine_parameters_dynamic>.for_each(
      [&](const auto& f, unsigned offset, std::uint16_t) { offsets[f.name] = offset; });
  CHECK(offsets["total_engine_hours_s"] == 88);
  CHECK(offsets["discrete_status_1"] == 160);
  CHECK(offsets["engine_torque_pct"] == 200);
  CHECK(n2k::ins_input_pgns::info(130578)->transport == n2k::framing::fast_packet);
  CHECK(n2k::ins_input_pgns::info(128259)->transport == n2k::framing::single_frame);
  CHECK_FALSE(n2k::ins_input_pgns::info(60928));
}

// ---------------------------------------------------------------------------------------------
// fast packets

TEST_CASE("split a payload into frames, as the worked 128275 example") {
  const auto p = hex_bytes("c34d201eb92140e20100d21e0000");
  const auto f = n2k::split_fast_packet(p, 0);
  REQUIRE(f);
  REQUIRE(f.value.count == 3);
  CHECK(f.value.frames[0].view().size() == 8);
  CHECK(std::vector<std::uint8_t>(f.value.frames[0].bytes.begin(), f.value.frames[0].bytes.end()) ==
        hex_bytes("000EC34D201EB921"));
  CHECK(std::vector<std::uint8_t>(f.value.frames[1].bytes.begin(), f.value.frames[1].bytes.end()) ==
        hex_bytes("0140E20100D21E00"));
  CHECK(std::vector<std::uint8_t>(f.value.frames[2].bytes.begin(), f.value.frames[2].bytes.end()) ==
        hex_bytes("0200FFFFFFFFFFFF"));
  CHECK(n2k::split_fast_packet(std::vector<std::uint8_t>(224), 0).ec == errc::bad_length);
  CHECK(n2k::split_fast_packet(p, 8).ec == errc::out_of_range);
  CHECK(n2k::fast_packet_frame_count(223) == 32);
  CHECK(n2k::fast_packet_frame_count(6) == 1);
  CHECK(n2k::fast_packet_frame_count(7) == 2);
  CHECK(n2k::fast_packet_frame_count(26) == 4);
}

TEST_CASE("the sequencer counts per PGN and source, modulo 8") {
  n2k::fast_packet_sequencer<4> s;
  CHECK(s.next(130578, 1) == 0);
  CHECK(s.next(130578, 1) == 1);
  CHECK(s.next(130578, 2) == 0);
  CHECK(s.next(127489, 1) == 0);
  for (int i = 0; i < 6; ++i) (void)s.next(130578, 1);
  CHECK(s.next(130578, 1) == 0);  // wrapped
}

namespace {

struct feeder {
  n2k::fast_packet_assembler<4> a;
  std::vector<std::vector<std::uint8_t>> done;
  void feed(std::uint8_t src, std::uint32_t pgn, std::string_view hex) {
    const auto b = hex_bytes(hex);
    const auto p = a.feed(n2k::can_id{2, pgn, src, 255}, b);
    if (p) done.emplace_back(p->payload.begin(), p->payload.end());
  }
  [[nodiscard]] bool balanced() const {
    return a.frames_in() == a.frames_assembled() + a.frames_dropped() + a.frames_pending();
  }
};

}  // namespace

TEST_CASE("assembler: interleaved sources and PGNs, a short last frame") {
  feeder f;
  f.feed(1, 127489, "601A00B706670D0B");
  f.feed(2, 130578, "400CC40988FF280A");
  f.feed(1, 127489, "6186BA042600105F");
  f.feed(2, 130578, "41D4FEFF7FFF7FFF");
  f.feed(1, 127489, "62090000008F027F");
  f.feed(1, 127489, "63000000007F7F");  // 7 bytes: the last frame shortened, not padded
  REQUIRE(f.done.size() == 2);
  CHECK(f.done[0] == hex_bytes("C40988FF280AD4FEFF7FFF7F"));
  CHECK(f.done[1].size() == 26);
  CHECK(f.done[1] == hex_bytes("00B706670D0B86BA042600105F090000008F027F000000007F7F"));
  CHECK(f.a.packets() == 2);
  CHECK(f.balanced());
  CHECK(f.a.frames_dropped() == 0);
}

TEST_CASE("assembler: each fault is dropped, counted, and the next packet still assembles") {
  feeder f;
  SECTION("missing frame: the log ends with the packet unfinished") {
    f.feed(1, 127489, "601A00B706670D0B");
    f.feed(1, 127489, "62090000008F027F");  // frame 2 held: frame 1 may still come
    CHECK(f.a.frames_pending() == 2);
    f.a.flush();
    CHECK(f.a.drops(n2k::fast_packet_drop::missing_frame) == 1);
    CHECK(f.a.frames_dropped() == 2);
  }
  SECTION("missing frame: a new frame 0 of the same sequence after frame 0 and more") {
    f.feed(1, 127489, "601A00B706670D0B");
    f.feed(1, 127489, "6186BA042600105F");
    f.feed(1, 127489, "601A00B706670D0B");
    CHECK(f.a.drops(n2k::fast_packet_drop::missing_frame) == 1);
    CHECK(f.a.frames_dropped() == 2);
    CHECK(f.a.frames_pending() == 1);  // the new frame 0 begins the next packet
  }
  SECTION("repeated frame") {
    f.feed(1, 127489, "601A00B706670D0B");
    f.feed(1, 127489, "6186BA042600105F");
    f.feed(1, 127489, "6186BA042600105F");
    CHECK(f.a.drops(n2k::fast_packet_drop::repeated_frame) == 1);
    CHECK(f.a.frames_dropped() == 2);
    CHECK(f.a.frames_pending() == 1);
  }
  SECTION("repeated frame 0") {
    f.feed(1, 127489, "601A00B706670D0B");
    f.feed(1, 127489, "601A00B706670D0B");
    CHECK(f.a.drops(n2k::fast_packet_drop::repeated_frame) == 1);
    CHECK(f.a.frames_dropped() == 1);
  }
  SECTION("sequence counter changes mid-packet") {
    f.feed(1, 127489, "601A00B706670D0B");
    f.feed(1, 127489, "8186BA042600105F");
    CHECK(f.a.drops(n2k::fast_packet_drop::sequence_changed) == 1);
    CHECK(f.a.frames_dropped() == 1);
    CHECK(f.a.frames_pending() == 1);  // frame 1 of sequence 4, waiting for its frame 0
  }
  SECTION("frame 0 announcing more than 223 bytes") {
    f.feed(1, 130578, "40E0C40988FF280A");
    CHECK(f.a.drops(n2k::fast_packet_drop::too_long) == 1);
    CHECK(f.a.frames_dropped() == 1);
  }
  SECTION("a middle frame shorter than 8 bytes") {
    f.feed(1, 127489, "601A00B706670D0B");
    f.feed(1, 127489, "6186BA04");
    f.feed(1, 127489, "62090000008F027F");
    f.feed(1, 127489, "63000000007F7FFF");
    CHECK(f.a.drops(n2k::fast_packet_drop::short_frame) == 1);
    CHECK(f.a.frames_dropped() == 4);
    CHECK(f.done.empty());
  }
  SECTION("an empty frame, a frame 0 without its length") {
    f.feed(1, 127489, "");
    f.feed(1, 127489, "60");
    CHECK(f.a.drops(n2k::fast_packet_drop::short_frame) == 2);
    CHECK(f.a.frames_pending() == 0);
  }
  SECTION("a new frame 0 before the packet was complete") {
    f.feed(1, 127489, "601A00B706670D0B");
    f.feed(1, 127489, "6186BA042600105F");
    CHECK(f.a.frames_pending() == 2);
  }
  SECTION("frames without their frame 0 at the end of the log") {
    f.feed(1, 127489, "6186BA042600105F");
    f.feed(1, 127489, "62090000008F027F");
    f.a.flush();
    CHECK(f.a.drops(n2k::fast_packet_drop::orphan_frame) == 1);
    CHECK(f.a.frames_dropped() == 2);
  }
  SECTION("more unfinished packets than slots") {
    for (std::uint8_t src = 1; src <= 5; ++src) f.feed(src, 127489, "601A00B706670D0B");
    CHECK(f.a.drops(n2k::fast_packet_drop::evicted) == 1);
    CHECK(f.a.frames_pending() == 4);
  }
  CHECK(f.balanced());
  // whatever happened above, a whole packet now assembles
  f.done.clear();
  f.feed(1, 127489, "001A017F07670D43");
  f.feed(1, 127489, "0185B00423003CC9");
  f.feed(1, 127489, "02090000008F027F");
  f.feed(1, 127489, "03000000007F7FFF");
  REQUIRE(f.done.size() == 1);
  CHECK(f.done[0].size() == 26);
  f.a.flush();
  CHECK(f.a.frames_pending() == 0);
  CHECK(f.balanced());
}

TEST_CASE("assembler: frames of a packet in any order but frame 0 last") {
  // 127489 from a candump capture, frames 0-3 of sequence 3
  const std::string_view frames[] = {"601A00B706670D0B", "6186BA042600105F", "62090000008F027F",
                                     "63000000007F7FFF"};
  const auto payload = hex_bytes("00B706670D0B86BA042600105F090000008F027F000000007F7F");
  const std::vector<std::vector<int>> orders = {{0, 2, 1, 3}, {1, 0, 2, 3}, {0, 3, 2, 1},
                                                {2, 1, 0, 3}, {3, 0, 1, 2}, {0, 1, 3, 2}};
  for (const auto& order : orders) {
    INFO(order[0] << order[1] << order[2] << order[3]);
    feeder f;
    for (const int k : order) f.feed(1, 127489, frames[k]);
    REQUIRE(f.done.size() == 1);
    CHECK(f.done[0] == payload);
    CHECK(f.a.frames_dropped() == 0);
    CHECK(f.balanced());
  }
  // interleaved with another source's packet
  feeder f;
  f.feed(1, 127489, frames[1]);
  f.feed(2, 130578, "400CC40988FF280A");
  f.feed(1, 127489, frames[0]);
  f.feed(1, 127489, frames[3]);
  f.feed(2, 130578, "41D4FEFF7FFF7FFF");
  f.feed(1, 127489, frames[2]);
  REQUIRE(f.done.size() == 2);
  CHECK(f.done[0] == hex_bytes("C40988FF280AD4FEFF7FFF7F"));
  CHECK(f.done[1] == payload);
}

TEST_CASE("assembler: a frame 0 that would complete frames held before it begins a new packet") {
  // A sender that keeps one sequence counter for every packet (canboatjs sends 2 always): the
  // body of a packet whose frame 0 was lost is held, then the next packet's frame 0 comes. Glued
  // together they would make a packet neither sender sent; canboat drops the held frames too.
  feeder f;
  f.feed(1, 130578, "41D4FEFF7FFF7FFF");  // body of a packet whose frame 0 was lost
  f.feed(1, 130578, "400CC40988FF280A");  // the next packet
  CHECK(f.done.empty());
  CHECK(f.a.drops(n2k::fast_packet_drop::orphan_frame) == 1);
  f.feed(1, 130578, "41000001000200FF");
  REQUIRE(f.done.size() == 1);
  CHECK(f.done[0] == hex_bytes("C40988FF280A000001000200"));
  // frames held past the count the frame 0 that comes announces belong to no packet of it
  f.feed(1, 130578, "4300000000000000");
  f.feed(1, 130578, "400CC40988FF280A");
  CHECK(f.a.drops(n2k::fast_packet_drop::orphan_frame) == 2);
  // and a frame past that count, after frame 0, is dropped alone
  f.feed(1, 130578, "4200000000000000");
  CHECK(f.a.drops(n2k::fast_packet_drop::orphan_frame) == 3);
  f.feed(1, 130578, "41D4FEFF7FFF7FFF");
  REQUIRE(f.done.size() == 2);
  CHECK(f.done[1] == hex_bytes("C40988FF280AD4FEFF7FFF7F"));
  CHECK(f.balanced());
}

TEST_CASE("assembler: a packet longer than its PGN's known length is assembled whole") {
  // 130578 is 12 bytes; a newer sender appends 7: 19 bytes in 3 frames. Up to 223 bytes taken.
  feeder f;
  f.feed(1, 130578, "4013C40988FF280A");
  f.feed(1, 130578, "41D4FEFF7FFF7FFF");
  f.feed(1, 130578, "42010203040506FF");
  REQUIRE(f.done.size() == 1);
  CHECK(f.done[0] == hex_bytes("C40988FF280AD4FEFF7FFF7FFF010203040506"));
  const auto m = n2k::decode<n2k::vessel_speed_components>(f.done[0]);
  CHECK(*m.longitudinal_water_mps.value() == Approx(2.5));
  // the longest payload, 223 bytes in 32 frames
  std::vector<std::uint8_t> big(223);
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<std::uint8_t>(i);
  const auto split = n2k::split_fast_packet(big, 5);
  REQUIRE(split);
  CHECK(split.value.count == 32);
  n2k::fast_packet_assembler<1> a;
  std::optional<n2k::assembled_packet> done;
  for (const auto& fr : split.value.view())
    done = a.feed(n2k::can_id{2, 130578, 9, 255}, fr.view());
  REQUIRE(done);
  CHECK(std::vector<std::uint8_t>(done->payload.begin(), done->payload.end()) == big);
}

// ---------------------------------------------------------------------------------------------
// log formats

TEST_CASE("each log format reads its line") {
  const auto c = n2k::parse_log_line("(1502984866.953084) slcan0 09F50374#001200FFFF00FFFF");
  REQUIRE(c);
  CHECK(c.value.format == n2k::log_format::candump_log);
  CHECK(*c.value.time_us == 1502984866953084);
  CHECK(c.value.interface.view() == "slcan0");
  CHECK(c.value.id.pgn == 128259);
  CHECK(c.value.id.source == 0x74);
  CHECK(c.value.size == 8);
  const auto d = n2k::parse_log_line("  can0  09F8027F   [8]  00 FC FF FF 00 00 FF FF");
  REQUIRE(d);
  CHECK(d.value.format == n2k::log_format::candump);
  CHECK(d.value.id.pgn == 129026);
  CHECK_FALSE(d.value.time_us);
  const auto p = n2k::parse_log_line(
      "2016-04-09T16:41:39.628Z,2,127489,16,255,26,00,2f,06,ff,ff,e3,73,65,05,ff,7f,72,10,00,00,"
      "ff,ff,ff,ff,ff,06,00,00,00,7f,7f\r\n");
  REQUIRE(p);
  CHECK(p.value.format == n2k::log_format::canboat);
  CHECK(p.value.assembled);
  CHECK(p.value.size == 26);
  CHECK(*p.value.time_us == 1460220099628000);
  const auto old =
      n2k::parse_log_line("2011-04-25-10:16:42.094,6,128275,35,255,8,01,17,3c,2d,00,17,3c,2d");
  REQUIRE(old);
  CHECK(*old.value.time_us == 1303726602094000);
  CHECK_FALSE(old.value.assembled);
  const auto zone = n2k::parse_log_line(
      "2016-04-09T09:41:39.628-07:00,2,127488,16,255,8,00,7a,0c,ff,ff,7f,ff,ff");
  REQUIRE(zone);
  CHECK(*zone.value.time_us == 1460220099628000);
  const auto y = n2k::parse_log_line("21:55:35.925 R 19F51323 20 0E FF FF FF FF FF FF");
  REQUIRE(y);
  CHECK(y.value.format == n2k::log_format::yd_raw);
  CHECK(*y.value.time_us == ((21 * 60 + 55) * 60 + 35) * 1000000LL + 925000);
  CHECK(y.value.id.pgn == 128275);
  const auto short_last = n2k::parse_log_line("17:33:21.108 R 19F51323 02 00");
  REQUIRE(short_last);
  CHECK(short_last.value.size == 2);
}

TEST_CASE("a canboat line's byte may be one hex digit, as canboat reads it") {
  const auto r = n2k::parse_log_line("2022-04-17-04:35:34.254,2,128259,35,255,3,0,f,12");
  REQUIRE(r);
  CHECK(std::vector<std::uint8_t>(r.value.data().begin(), r.value.data().end()) ==
        hex_bytes("000F12"));
  CHECK(n2k::parse_log_line("2022-04-17-04:35:34.254,2,128259,35,255,2,0,123").ec ==
        errc::bad_number);
  CHECK(n2k::parse_log_line("21:55:35.925 R 09F50323 0 12").ec == errc::bad_number);
}

TEST_CASE("malformed log lines name the token and the reason") {
  const struct {
    std::string_view line;
    errc ec;
    std::uint16_t field;
  } rows[] = {
      {"(1502984866.953084) slcan0 09F50374#001200FFFF00FFF", errc::bad_length, 3},
      {"(1502984866.953084) slcan0 09F50374#001200FFFF00FFFFAA", errc::bad_length, 3},
      {"(1502984866.953084) slcan0 09F50374#0012ZZFFFF00FFFF", errc::bad_number, 3},
      {"(1502984866.953084) slcan0 9F50374#001200FFFF00FFFF", errc::bad_can_id, 3},
      {"(1502984866.953084) slcan0 3FF50374#001200FFFF00FFFF", errc::bad_can_id, 3},
      {"(15029x4866.953084) slcan0 09F50374#001200FFFF00FFFF", errc::bad_time, 1},
      {"(1502984866.953084) slcan0 123#R", errc::bad_can_id, 3},
      {"(1502984866.953084) slcan0 09F50374#R", errc::bad_log_line, 3},
      {"  can0  09F8027F   [7]  00 FC FF FF 00 00 FF FF", errc::bad_length, 4},
      {"  can0  09F8027F   [9]  00 FC FF FF 00 00 FF FF", errc::bad_length, 3},
      {"  can0  09F8027F   [2]  00 FCF", errc::bad_number, 4},
      {"2016-04-09T16:41:39.628Z,2,127489,16,255,3,00,2f", errc::bad_length, 7},
      {"2016-04-09T16:41:39.628Z,9,127489,16,255,2,00,2f", errc::bad_can_id, 2},
      {"2016-04-09T16:41:39.628Z,2,127489,16,255,224,00", errc::bad_length, 6},
      {"2016-04-09T16:41:39.628Z,2,127489,x,255,2,00,2f", errc::bad_number, 4},
      {"2016-04-09T16:41:39.628Z,2,127489,16,255,2,00,2fa", errc::bad_number, 7},
      {"21:55:35.925 X 19F51323 20 0E", errc::bad_log_line, 2},
      {"21:55:35.925 R 19F51323 20 0E FF FF FF FF FF FF FF", errc::bad_number, 4},
      {"25:55:35.925 R 19F51323 20", errc::bad_time, 1},
  };
  for (const auto& row : rows) {
    INFO(std::string(row.line));
    const auto r = n2k::parse_log_line(row.line);
    CHECK(r.ec == row.ec);
    CHECK(r.field == row.field);
  }
  CHECK(n2k::parse_log_line("hello world").ec == errc::bad_log_line);
  CHECK(n2k::parse_log_line("   \r\n").ec == errc::empty_input);
  CHECK(n2k::log_field_name(n2k::log_format::candump_log, 3) == "frame");
  CHECK(n2k::log_field_name(n2k::log_format::canboat, 6) == "length");
}

TEST_CASE("every format writes what it reads") {
  const std::string_view lines[] = {
      "(1502984866.953084) slcan0 09F50374#001200FFFF00FFFF",
      "(1720021378.000000) can0 19F51323#000EC34D201EB921",
      "  can0  09F8027F   [8]  00 FC FF FF 00 00 FF FF",
      "2016-04-09T16:41:39.628Z,2,127489,16,255,26,00,2f,06,ff,ff,e3,73,65,05,ff,7f,72,10,00,00,"
      "ff,ff,ff,ff,ff,06,00,00,00,7f,7f",
      "2020-08-22T13:52:55.194Z,2,128259,35,255,8,ff,00,00,ff,ff,03,ff,ff",
      "21:55:35.925 R 19F51323 20 0E FF FF FF FF FF FF",
      "17:33:21.108 T 19F51323 02 00",
  };
  for (const std::string_view line : lines) {
    INFO(std::string(line));
    const auto r = n2k::parse_log_line(line);
    REQUIRE(r);
    seawire::nmea::json_buffer<1024> out;
    REQUIRE(n2k::write_log_line(out, r.value, r.value.format) == errc::ok);
    CHECK(out.view() == std::string(line) + "\n");
  }
  // across formats: the same frame, the time as each format keeps it
  const auto r = n2k::parse_log_line("(1720021378.123000) can0 19F51323#000EC34D201EB921");
  seawire::nmea::json_buffer<256> out;
  REQUIRE(n2k::write_log_line(out, r.value, n2k::log_format::yd_raw) == errc::ok);
  CHECK(out.view() == "15:42:58.123 R 19F51323 00 0E C3 4D 20 1E B9 21\n");
  out.clear();
  REQUIRE(n2k::write_log_line(out, r.value, n2k::log_format::canboat) == errc::ok);
  CHECK(out.view() == "2024-07-03T15:42:58.123Z,6,128275,35,255,8,00,0e,c3,4d,20,1e,b9,21\n");
  out.clear();
  const auto fast = n2k::parse_log_line(lines[3]);
  CHECK(n2k::write_log_line(out, fast.value, n2k::log_format::candump_log) == errc::bad_length);
}

// ---------------------------------------------------------------------------------------------
// JSON

TEST_CASE("JSON of a message, and back") {
  const auto rec = n2k::parse_log_line("(1502984866.953084) slcan0 09F50374#001200FFFF00FFFF");
  REQUIRE(rec);
  const auto m = n2k::decode<n2k::speed_water_referenced>(rec.value.data());
  const std::string json = json_of<512>(n2k::header_of(rec.value), m);
  CHECK(json ==
        R"({"type":"PGN128259","time_s":1502984866.953084,"interface":"slcan0","prio":2,"src":116,)"
        R"("dst":255,"sid":0,"speed_water_mps":0.18,"speed_ground_mps":null,)"
        R"("speed_type":"paddle_wheel","speed_direction":null})");
  const auto dyn = decode_hex<n2k::engine_parameters_dynamic>(
      "002f06ffffe3736505ff7f72100000ffffffffff060000017eff");
  const std::string j2 = json_of<1024>(n2k::message_header{}, dyn);
  CHECK(j2.find(R"("discrete_status_1":["over_temperature","low_oil_pressure"])") !=
        std::string::npos);
  CHECK(j2.find(R"("discrete_status_2":["bit_8"])") != std::string::npos);
  CHECK(j2.find(R"("engine_load_pct":"out_of_range")") != std::string::npos);
  CHECK(j2.find(R"("alternator_potential_v":13.81)") != std::string::npos);
  const auto dl = decode_hex<n2k::distance_log>("c34d201eb92140e20100d21e0000");
  const std::string j3 = json_of<512>(n2k::message_header{}, dl);
  CHECK(j3.find(R"("date":"2024-07-03","time":"15:42:58.0000","log_m":123456)") !=
        std::string::npos);

  // back: a lookup over a tiny hand-made member table
  std::map<std::pair<std::string, std::string>, seawire::nmea::json_value> members{
      {{"", "sid"}, {n2k::json_kind::number, "7"}},
      {{"", "speed_water_mps"}, {n2k::json_kind::number, "3.25"}},
      {{"", "speed_ground_mps"}, {n2k::json_kind::string, "out_of_range"}},
      {{"", "speed_type"}, {n2k::json_kind::string, "doppler"}},
  };
  const auto lookup = [&](std::string_view o, std::string_view k) {
    const auto it = members.find({std::string(o), std::string(k)});
    return it == members.end() ? seawire::nmea::json_value{} : it->second;
  };
  const auto back = n2k::read_json<n2k::speed_water_referenced>(lookup);
  REQUIRE(back);
  CHECK(back.value.sid.raw() == 7);
  CHECK(back.value.speed_water_mps.raw() == 325);
  CHECK(back.value.speed_ground_mps.state() == n2k::field_state::out_of_range);
  CHECK(back.value.speed_type == n2k::water_reference::doppler);
  CHECK(back.value.speed_direction.state() == n2k::field_state::not_available);
  members[{"", "speed_type"}] = {n2k::json_kind::string, "sonar"};
  const auto bad = n2k::read_json<n2k::speed_water_referenced>(lookup);
  CHECK(bad.ec == errc::bad_enum);
  CHECK(n2k::field_name<n2k::speed_water_referenced>(bad.field) == "speed_type");
  members[{"", "speed_type"}] = {n2k::json_kind::number, "3"};
  members[{"", "speed_water_mps"}] = {n2k::json_kind::number, "655.33"};
  const auto range = n2k::read_json<n2k::speed_water_referenced>(lookup);
  CHECK(range.ec == errc::out_of_range);
  CHECK(range.field == 2);
  members[{"", "speed_water_mps"}] = {n2k::json_kind::string, "reserved"};
  members[{"", "speed_direction"}] = {n2k::json_kind::string, "reserved"};  // 4 bits: no such
  CHECK(n2k::read_json<n2k::speed_water_referenced>(lookup).ec == errc::out_of_range);

  // flags from an array
  std::map<std::pair<std::string, std::string>, seawire::nmea::json_value> f{
      {{"", "discrete_status_1"}, {n2k::json_kind::other, "["}},
      {{"discrete_status_1", "0"}, {n2k::json_kind::string, "check_engine"}},
      {{"discrete_status_1", "1"}, {n2k::json_kind::string, "bit_15"}},
      {{"", "discrete_status_2"}, {n2k::json_kind::number, "256"}},
  };
  const auto flookup = [&](std::string_view o, std::string_view k) {
    const auto it = f.find({std::string(o), std::string(k)});
    return it == f.end() ? seawire::nmea::json_value{} : it->second;
  };
  const auto fl = n2k::read_json<n2k::engine_parameters_dynamic>(flookup);
  REQUIRE(fl);
  CHECK(fl.value.discrete_status_1.raw() == 0x8001);
  CHECK(fl.value.discrete_status_2.raw() == 256);
}

// ---------------------------------------------------------------------------------------------
// every vector file: read through the log reader, each message decoded and encoded back

TEST_CASE("every captured and synthetic vector reads, and encodes back to its payload") {
  const char* files[] = {"01_plain_fast_mixed.in",    "02_candump_log_127489.in",
                         "03_candump_log_mixed.in",   "04_ydraw.in",
                         "05_plain_frames_128275.in", "06_fast_130578.in",
                         "07_yanmar_127489.in",       "08_synthetic_fast_lines.in",
                         "09_synthetic_candump.in",   "10_synthetic_ydraw.in",
                         "11_special_values.in",      "12_format_fast_header.in",
                         "13_ydraw_out_of_order.in",  "14_lookup_edges.in"};
  // messages canboat decoded from each file (its .out.json has one line per message)
  std::size_t total = 0;
  for (const char* name : files) {
    INFO(name);
    n2k::log_reader<> reader;
    std::size_t messages = 0;
    for (const std::string& line : read_lines(name)) {
      INFO(line);
      const auto r = reader.read_line(line, [&](const n2k::message_header& h, auto payload) {
        ++messages;
        const bool known = n2k::ins_input_pgns::visit(h.id.pgn, payload, [&](const auto& m) {
          const auto e = n2k::encode(m);
          REQUIRE(e);
          using P = std::remove_cvref_t<decltype(m)>;
          CHECK(n2k::decode<P>(e.value) == m);
          // A message of another length than the PGN's (cut short, or with fields appended by
          // a newer sender) comes back at the PGN's length, or cut before a flag word not sent
          if (payload.size() != n2k::description_of<P>::length) return;
          // bit-identical but for reserved bits, which are sent as ones whatever was received
          std::vector<std::uint8_t> expected(payload.begin(), payload.end());
          n2k::pgn_table<P>.for_each([&](const auto& f, unsigned offset, std::uint16_t) {
            if (std::remove_cvref_t<decltype(f)>::is_reserved)
              seawire::detail::put_bits<n2k::payload_order>(expected, offset, f.bits,
                                                            ~std::uint64_t{0});
          });
          CHECK(std::vector<std::uint8_t>(e.value.begin(), e.value.end()) == expected);
        });
        CHECK(known);
      });
      CHECK(r.ec == errc::ok);
    }
    CHECK(reader.assembler().frames_dropped() == 0);
    // a log may end inside a packet (03 and 04 do): flushing drops those frames, counted
    const auto pending = reader.assembler().frames_pending();
    reader.flush();
    CHECK(reader.assembler().frames_dropped() == pending);
    CHECK(
        messages ==
        read_lines(std::string(name).replace(std::string(name).size() - 3, 3, ".out.json")).size());
    total += messages;
  }
  CHECK(total == 74 + 13 + 7 + 8);
}

// ---------------------------------------------------------------------------------------------
// frames without data, log format headers, FAST lines of any length

TEST_CASE("a frame of 0 data bytes reads in every format, its fields not available") {
  for (const std::string_view line :
       {"(1502984866.953084) can0 09F50323#", "  can0  09F50323   [0]",
        "2024-07-03T15:42:58.000Z,2,128259,35,255,0", "21:55:35.925 R 09F50323"}) {
    INFO(std::string(line));
    const auto r = n2k::parse_log_line(line);
    REQUIRE(r);
    CHECK(r.value.size == 0);
    CHECK(r.value.id.pgn == 128259);
    n2k::log_reader<> reader;
    int n = 0;
    CHECK(reader.read_line(line, [&](const n2k::message_header&, auto payload) {
      ++n;
      CHECK(n2k::decode<n2k::speed_water_referenced>(payload) == n2k::speed_water_referenced{});
    }));
    CHECK(n == 1);
  }
  // a frame of a fast-packet PGN without data cannot be part of a packet
  n2k::log_reader<> reader;
  CHECK(reader.read_line("21:55:35.925 R 19F51323", [](const auto&, auto) { FAIL(); }));
  CHECK(reader.assembler().drops(n2k::fast_packet_drop::short_frame) == 1);
}

TEST_CASE("canboat's format header: its names, in any case; others refused precisely") {
  using cf = n2k::canboat_format;
  const std::pair<std::string_view, cf> good[] = {
      {"# format=PLAIN", cf::plain},
      {"# format=FAST\r\n", cf::fast},
      {"# format=plain_or_fast", cf::plain_or_fast},
      {"# format=PLAIN_MIX_FAST", cf::plain_mix_fast},
      {"# format=YDWG02", cf::ydwg02},
      {"# format=ACTISENSE_N2K_ASCII", cf::actisense_n2k_ascii}};
  for (const auto& [line, f] : good) {
    INFO(std::string(line));
    const auto r = n2k::parse_format_header(line);
    REQUIRE(r);
    CHECK(r.value == f);
    CHECK(n2k::is_readable(f));
  }
  for (const cf f : {cf::airmar, cf::chetco, cf::garmin_csv1, cf::garmin_csv2}) {
    const std::string line = "# format=" + std::string(n2k::name(f));
    const auto r = n2k::parse_format_header(line);
    CHECK(r.ec == errc::unknown_log_format);
    CHECK(r.value == f);
    CHECK(r.field == 1);
    CHECK(r.column == 9);
    CHECK_FALSE(n2k::log_format_of(f));
  }
  CHECK(n2k::canboat_format_named("Plain_Mix_Fast") == cf::plain_mix_fast);
  CHECK(n2k::canboat_format_named("ACTISENSE_N2K_ASCII") == cf::actisense_n2k_ascii);
  CHECK_FALSE(n2k::canboat_format_named("SEATALK"));
  CHECK(n2k::parse_format_header("# format=FASTER").ec == errc::unknown_log_format);
  CHECK(n2k::parse_format_header("# format=").ec == errc::unknown_log_format);
  CHECK(n2k::parse_format_header("# a comment").ec == errc::bad_log_line);
  CHECK(n2k::parse_format_header("format=FAST").ec == errc::bad_log_line);
  CHECK(n2k::is_log_comment("# anything"));
  CHECK_FALSE(n2k::is_log_comment(" (1502984866.953084) can0 09F50323#"));
}

namespace {

struct collected {
  std::uint32_t pgn;
  std::vector<std::uint8_t> payload;
};

/// Every message the reader gives for `lines`, and every line's result code.
std::pair<std::vector<collected>, std::vector<errc>> read_all(
    const std::vector<std::string_view>& lines) {
  n2k::log_reader<> reader;
  std::vector<collected> out;
  std::vector<errc> codes;
  codes.reserve(lines.size());
  for (const std::string_view l : lines) {
    codes.push_back(reader
                        .read_line(l,
                                   [&](const n2k::message_header& h, auto p) {
                                     out.push_back({h.id.pgn, {p.begin(), p.end()}});
                                   })
                        .ec);
  }
  return {out, codes};
}

}  // namespace

TEST_CASE("canboat lines: a FAST log's line is a whole message, whatever its length") {
  // 128275 of 8 bytes (date, time and a log cut short: a sender's short message) and 14 bytes
  constexpr std::string_view short_fast =
      "2024-07-03T15:42:58.000Z,6,128275,35,255,8,c3,4d,20,1e,b9,21,40,e2";
  constexpr std::string_view whole =
      "2024-07-03T15:42:58.000Z,6,128275,35,255,14,c3,4d,20,1e,b9,21,40,e2,01,00,d2,1e,00,00";
  SECTION("after a # format=FAST header") {
    const auto [msgs, codes] = read_all({"# format=FAST", short_fast});
    CHECK(codes == std::vector<errc>{errc::ok, errc::ok});
    REQUIRE(msgs.size() == 1);
    const auto m = n2k::decode<n2k::distance_log>(msgs[0].payload);
    CHECK(m.date.raw() == 19907);
    CHECK(m.time.raw() == 565780000);
    CHECK(m.log_m.state() == n2k::field_state::not_available);  // cut short: not sent
  }
  SECTION("without a header, in a log whose first line is longer than 8 bytes (canboat: FAST)") {
    const auto [msgs, codes] = read_all({whole, short_fast});
    REQUIRE(msgs.size() == 2);
    CHECK(msgs[1].payload.size() == 8);
  }
  SECTION("without a header, PLAIN_OR_FAST: frames until the first longer line") {
    // the three frames of 128275, then a whole message, then 8 bytes: from then on FAST
    const auto [msgs, codes] = read_all(
        {"2021-08-07-17:06:37.553,6,128275,35,255,8,00,0e,ff,ff,ff,ff,ff,ff",
         "2021-08-07-17:06:37.556,6,128275,35,255,8,01,17,3c,2d,00,17,3c,2d",
         "2021-08-07-17:06:37.559,6,128275,35,255,8,02,00,ff,ff,ff,ff,ff,ff", whole, short_fast});
    REQUIRE(msgs.size() == 3);
    CHECK(msgs[0].payload == hex_bytes("ffffffffffff173c2d00173c2d00"));
    CHECK(msgs[1].payload.size() == 14);
    CHECK(msgs[2].payload.size() == 8);
  }
  SECTION("# format=PLAIN_MIX_FAST: each line by its length") {
    const auto [msgs, codes] =
        read_all({"# format=PLAIN_MIX_FAST", whole,
                  "2021-08-07-17:06:37.553,6,128275,35,255,8,00,0e,ff,ff,ff,ff,ff,ff",
                  "2021-08-07-17:06:37.556,6,128275,35,255,8,01,17,3c,2d,00,17,3c,2d",
                  "2021-08-07-17:06:37.559,6,128275,35,255,8,02,00,ff,ff,ff,ff,ff,ff"});
    REQUIRE(msgs.size() == 2);
    CHECK(msgs[1].payload == hex_bytes("ffffffffffff173c2d00173c2d00"));
  }
  SECTION("# format=PLAIN: every line a frame; a longer one is refused") {
    n2k::log_reader<> reader;
    CHECK(reader.read_line("# format=PLAIN", [](const auto&, auto) {}));
    const auto r = reader.read_line(whole, [](const auto&, auto) { FAIL(); });
    CHECK(r.ec == errc::bad_length);
    CHECK(r.field == 6);
    CHECK(r.column == whole.find(",14,") + 1);
    CHECK(reader.canboat_lines() == n2k::canboat_format::plain);
  }
  SECTION("# format=YDWG02: Yacht Devices RAW lines only") {
    const auto [msgs, codes] =
        read_all({"# format=YDWG02", "21:55:35.425 R 15FD0723 FF C0 D9 6F FF 7F FF FF",
                  "(1502984866.953084) slcan0 09F50374#001200FFFF00FFFF"});
    CHECK(msgs.size() == 1);
    CHECK(codes[2] == errc::bad_time);
    n2k::log_reader<> reader;
    CHECK_FALSE(reader.header_format());
    CHECK(reader.read_line("# format=ydwg02", [](const auto&, auto) {}));
    CHECK(reader.header_format() == n2k::log_format::yd_raw);
  }
  SECTION("blank lines after a header, or with the format given, are blank lines") {
    const auto [msgs, codes] = read_all({"# format=FAST", "", "  \r", whole});
    CHECK(codes == std::vector<errc>{errc::ok, errc::empty_input, errc::empty_input, errc::ok});
    n2k::log_reader<> reader;
    CHECK(reader
              .read_line(
                  "\r\n", [](const auto&, auto) {}, n2k::log_format::yd_raw)
              .ec == errc::empty_input);
  }
  SECTION("a header for a format seawire does not read, and other comments") {
    const auto [msgs, codes] = read_all({"# format=AIRMAR", "# recorded at the dock", whole});
    CHECK(codes == std::vector<errc>{errc::unknown_log_format, errc::empty_input, errc::ok});
    CHECK(msgs.size() == 1);
  }
}

TEST_CASE("a fast packet longer than its PGN decodes the same from frames and from a FAST line") {
  // 130578 with 7 bytes more than its 12: from candump frames and from one canboat line
  const auto [frames, c1] = read_all({"(1720021378.000000) can0 09FE1223#4013C40988FF280A",
                                      "(1720021378.000000) can0 09FE1223#41D4FEFF7FFF7FFF",
                                      "(1720021378.000000) can0 09FE1223#42010203040506FF"});
  const auto [line, c2] =
      read_all({"2024-07-03T15:42:58.000Z,2,130578,35,255,19,c4,09,88,ff,28,"
                "0a,d4,fe,ff,7f,ff,7f,ff,01,02,03,04,05,06"});
  REQUIRE(frames.size() == 1);
  REQUIRE(line.size() == 1);
  CHECK(frames[0].payload == line[0].payload);
  CHECK(n2k::decode<n2k::vessel_speed_components>(frames[0].payload) ==
        n2k::decode<n2k::vessel_speed_components>(line[0].payload));
  CHECK(*n2k::decode<n2k::vessel_speed_components>(frames[0].payload)
             .longitudinal_water_mps.value() == Approx(2.5));
}

// ---------------------------------------------------------------------------------------------
// fields a short message did not send

TEST_CASE("a flag word not sent is not available, not 'no flag set'") {
  // 127489 cut after the reserved byte: no discrete status words, no load or torque
  const auto m =
      decode_hex<n2k::engine_parameters_dynamic>("002f06ffffe3736505ff7f72100000ffffffffff");
  CHECK(m.discrete_status_1.state() == n2k::field_state::not_available);
  CHECK_FALSE(m.discrete_status_1.has_value());
  CHECK_FALSE(m.discrete_status_1 == n2k::flags<n2k::engine_status_1, 16>::none());
  CHECK(m.discrete_status_2.state() == n2k::field_state::not_available);
  const std::string j = json_of<1024>(n2k::message_header{}, m);
  CHECK(j.find(R"("discrete_status_1":null,"discrete_status_2":null)") != std::string::npos);
  // sent with no flag set: []
  const auto z = decode_hex<n2k::engine_parameters_dynamic>(
      "002f06ffffe3736505ff7f72100000ffffffffff00000000");
  CHECK(z.discrete_status_1 == n2k::flags<n2k::engine_status_1, 16>::none());
  CHECK(json_of<1024>(n2k::message_header{}, z).find(R"("discrete_status_1":[],)") !=
        std::string::npos);
  // CSV: empty cell for not sent, "none" for no flag set
  seawire::nmea::json_buffer<1024> csv;
  n2k::write_csv(csv, n2k::message_header{}, m);
  n2k::write_csv(csv, n2k::message_header{}, z);
  CHECK(std::string(csv.view()).find(",,,") != std::string::npos);
  CHECK(std::string(csv.view()).find(",none,none,,") != std::string::npos);
  // half a word sent (23 bytes): not available either
  const auto h =
      decode_hex<n2k::engine_parameters_dynamic>("002f06ffffe3736505ff7f72100000ffffffffff060000");
  CHECK(h.discrete_status_1.raw() == 6);
  CHECK(h.discrete_status_2.state() == n2k::field_state::not_available);
}

TEST_CASE("encode leaves a flag word not available out, with everything after it") {
  const auto b = hex_bytes("002f06ffffe3736505ff7f72100000ffffffffff");
  const auto m = n2k::decode<n2k::engine_parameters_dynamic>(b);
  const auto e = n2k::encode(m);
  REQUIRE(e);
  CHECK(e.value.size() == 20);
  CHECK(e.value == std::span<const std::uint8_t>(b));
  CHECK(n2k::decode<n2k::engine_parameters_dynamic>(e.value) == m);
  // the second word not available, the first sent: cut after the first
  auto one = m;
  one.discrete_status_1 = {n2k::engine_status_1::check_engine};
  const auto e1 = n2k::encode(one);
  REQUIRE(e1);
  CHECK(e1.value.size() == 22);
  CHECK(n2k::decode<n2k::engine_parameters_dynamic>(e1.value) == one);
  // a field after a word not available cannot be sent: refused, naming the word
  auto load = m;
  REQUIRE(load.engine_load_pct.assign(50) == errc::ok);
  const auto bad = n2k::encode(load);
  CHECK(bad.ec == errc::missing_field);
  CHECK(n2k::field_name<n2k::engine_parameters_dynamic>(bad.field) == "discrete_status_1");
  // set(), none() and {...} make a word available
  n2k::engine_parameters_dynamic built;
  CHECK(n2k::encode(built).value.size() == 20);
  built.discrete_status_1.set(n2k::engine_status_1::water_flow);
  built.discrete_status_2 = n2k::flags<n2k::engine_status_2, 16>::none();
  const auto full = n2k::encode(built);
  REQUIRE(full);
  CHECK(full.value.size() == 26);
  CHECK(full.value[20] == 0x80);
  CHECK(full.value[22] == 0x00);
}

TEST_CASE("times of 24 h and later decode, print, and read back") {
  for (const std::int64_t raw :
       {863999999LL, 864000000LL, 864005000LL, 864010000LL, 900000000LL, 4294967292LL}) {
    INFO(raw);
    n2k::distance_log m;
    m.time = n2k::time_since_midnight::from_raw(raw);
    const std::string j = json_of<512>(n2k::message_header{}, m);
    const auto at = j.find(R"("time":")") + 8;
    const std::string text = j.substr(at, j.find('"', at) - at);
    std::int64_t ticks = 0;
    CHECK(n2k::detail::parse_time_of_day(text, ticks) == errc::ok);
    CHECK(ticks == raw);
  }
  // as canboat prints them
  n2k::distance_log m;
  m.time = n2k::time_since_midnight::from_raw(864000000);
  CHECK(json_of<512>(n2k::message_header{}, m).find(R"("time":"24:00:00.0000")") !=
        std::string::npos);
  m.time = n2k::time_since_midnight::from_raw(4294967292);
  CHECK(json_of<512>(n2k::message_header{}, m).find(R"("time":"119:18:16.7292")") !=
        std::string::npos);
  std::int64_t t = 0;
  CHECK(n2k::detail::parse_time_of_day("23:59:60.5", t) == errc::ok);
  CHECK(t == 864005000);
  CHECK(n2k::detail::parse_time_of_day("119:18:16.7293", t) == errc::out_of_range);
  CHECK(n2k::detail::parse_time_of_day("12:59:60", t) == errc::bad_time);
  CHECK(n2k::detail::parse_time_of_day("1:00:00", t) == errc::bad_time);
  CHECK(n2k::detail::parse_time_of_day("10:60:00", t) == errc::bad_time);
  CHECK(n2k::detail::parse_time_of_day("10:00:00.12345", t) == errc::bad_time);
  CHECK(n2k::detail::parse_time_of_day("10:00:00.", t) == errc::bad_time);
}

// ---------------------------------------------------------------------------------------------
// whatever decodes encodes: random payloads of every PGN through decode, encode and JSON

namespace {

/// The members of one flat JSON object as write_json writes it: numbers, strings, null, arrays
/// of strings (enough to read back what the library wrote).
struct flat_json {
  std::map<std::pair<std::string, std::string>, seawire::nmea::json_value> members;
  std::vector<std::string> texts;  // keeps the views' text

  explicit flat_json(std::string_view j) {
    texts.reserve(j.size());
    std::size_t i = 1;  // after '{'
    while (i < j.size() && j[i] != '}') {
      const std::size_t k0 = i + 1;
      const std::size_t k1 = j.find('"', k0);
      const std::string key(j.substr(k0, k1 - k0));
      i = k1 + 2;  // after ':'
      if (j[i] == '[') {
        add("", key, n2k::json_kind::other, "[");
        ++i;
        int n = 0;
        while (j[i] != ']') {
          const std::size_t e = j.find('"', i + 1);
          add(key, std::to_string(n++), n2k::json_kind::string, j.substr(i + 1, e - i - 1));
          i = e + 1;
          if (j[i] == ',') ++i;
        }
        ++i;
      } else if (j[i] == '"') {
        const std::size_t e = j.find('"', i + 1);
        add("", key, n2k::json_kind::string, j.substr(i + 1, e - i - 1));
        i = e + 1;
      } else {
        const std::size_t e = j.find_first_of(",}", i);
        const std::string_view v = j.substr(i, e - i);
        add("", key, v == "null" ? n2k::json_kind::null : n2k::json_kind::number, v);
        i = e;
      }
      if (j[i] == ',') ++i;
    }
  }
  void add(const std::string& o, const std::string& k, n2k::json_kind kind, std::string_view v) {
    texts.emplace_back(v);
    members[{o, k}] = {kind, texts.back()};
  }
  seawire::nmea::json_value operator()(std::string_view o, std::string_view k) const {
    const auto it = members.find({std::string(o), std::string(k)});
    return it == members.end() ? seawire::nmea::json_value{} : it->second;
  }
};

}  // namespace

TEST_CASE("random messages of every PGN: decode, encode, JSON and back give the same message") {
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;
  const auto next = [&] {  // xorshift64*
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return state * 0x2545F4914F6CDD1DULL;
  };
  std::size_t checked = 0;
  n2k::ins_input_pgns::for_each_type([&](const auto& tag) {
    using P = std::remove_cvref_t<decltype(tag)>;
    constexpr std::size_t length = n2k::description_of<P>::length;
    for (int round = 0; round < 3000; ++round) {
      // lengths from none to past the PGN's; bytes biased to the top of the range (sentinels)
      const std::size_t size = round < 2000 ? length : next() % (length + 9);
      std::vector<std::uint8_t> payload(size);
      for (auto& b : payload) {
        const std::uint64_t r = next();
        b = static_cast<std::uint8_t>(r % 4 == 0 ? 0xFF - (r >> 8) % 4 : (r >> 8) & 0xFF);
      }
      INFO(n2k::pgn_table<P>.info.pgn << " " << hex_of(payload));
      const P m = n2k::decode<P>(payload);
      const auto e = n2k::encode(m);
      REQUIRE(e);
      CHECK(n2k::decode<P>(e.value) == m);
      seawire::nmea::json_buffer<1024> j;
      n2k::write_json(j, m);
      INFO(std::string(j.view()));
      const flat_json members(j.view());
      const auto back = n2k::read_json<P>(members);
      REQUIRE(back);
      CHECK(back.value == m);
      ++checked;
    }
  });
  CHECK(checked == std::size_t{6} * 3000);
}
