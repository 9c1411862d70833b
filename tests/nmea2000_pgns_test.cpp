// SPDX-License-Identifier: BSL-1.0
// The NMEA 2000 PGNs beyond the ANELLO inputs and 127250: for each, a payload from a real capture
// (canboat's sample logs; canboat's analyzer's reading of it in the comment) decoded field by field
// against the bit layout worked out by hand, encoded back to the same bytes, and decoded again to
// the same message. tools/decode/n2k_test.py compares every message of their vectors with
// canboat's analyzer.

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>

#include "seawire/nmea/decimal.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/registry.hpp"

namespace n2k = seawire::nmea2000;
using n2k::field_state;

namespace {

seawire::nmea::decimal dec(std::int64_t mantissa, int places) {
  return seawire::nmea::decimal::scaled(mantissa, places);
}

std::chrono::sys_days days(int y, unsigned m, unsigned d) {
  return std::chrono::sys_days{std::chrono::year{y} / std::chrono::month{m} / std::chrono::day{d}};
}

template <n2k::pgn_like P>
void check_info(std::uint32_t pgn, unsigned priority, n2k::framing transport, unsigned interval_ms,
                std::size_t length) {
  constexpr n2k::pgn_info info = n2k::pgn_table<P>.info;
  CHECK(info.pgn == pgn);
  CHECK(info.priority == priority);
  CHECK(info.transport == transport);
  CHECK(info.interval_ms == interval_ms);
  CHECK(n2k::description_of<P>::length == length);
  CHECK(seawire::registry::pgns::knows(pgn));
  CHECK(seawire::registry::pgns::length(pgn) == length);
}

/// encode(m) is `sent` byte for byte, and decodes back to m.
template <n2k::pgn_like P, std::size_t N>
void check_codec(const P& m, const std::array<std::uint8_t, N>& sent) {
  const auto e = n2k::encode(m);
  REQUIRE(e);
  CHECK(std::ranges::equal(e.value.view(), sent));
  CHECK(n2k::decode<P>(e.value.view()) == m);
  CHECK(n2k::decode<P>(sent) == m);
}

}  // namespace

TEST_CASE("127251 Rate of Turn: a capture decoded by hand, encoded back", "[127251]") {
  check_info<n2k::rate_of_turn>(127251, 2, n2k::framing::single_frame, 100, 8);
  // 2016-02-28T19:57:02.364Z, source 7; canboat: {"sid":null,"rate":-0.00407641}
  constexpr std::array<std::uint8_t, 8> wire{0xff, 0x73, 0x02, 0xfe, 0xff, 0xff, 0xff, 0xff};
  const auto m = n2k::decode<n2k::rate_of_turn>(wire);
  // byte 0: ff
  CHECK(m.sid.state() == field_state::not_available);
  // bytes 1-4: 73 02 fe ff, 0xfffe0273 - 2^32 = -130445, x 3.125e-8
  CHECK(m.rate_radps.raw() == -130445);
  CHECK(*m.rate_radps.exact() == dec(-407640625, 11));  // -0.00407640625
  check_codec(m, wire);
}

TEST_CASE("127257 Attitude: a capture decoded by hand, encoded back", "[127257]") {
  check_info<n2k::attitude>(127257, 3, n2k::framing::single_frame, 1000, 8);
  // 2026-08-03T05:05:27.984Z, source 27; canboat:
  // {"sid":0,"yaw":null,"pitch":0.0178,"roll":-0.0674}
  constexpr std::array<std::uint8_t, 8> wire{0x00, 0xff, 0x7f, 0xb2, 0x00, 0x5e, 0xfd, 0xff};
  const auto m = n2k::decode<n2k::attitude>(wire);
  // byte 0: 00, 0x0 = 0
  CHECK(m.sid.raw() == 0);
  // bytes 1-2: ff 7f
  CHECK(m.yaw_rad.state() == field_state::not_available);
  // bytes 3-4: b2 00, 0xb2 = 178, x 0.0001
  CHECK(m.pitch_rad.raw() == 178);
  CHECK(*m.pitch_rad.exact() == dec(178, 4));  // 0.0178
  // bytes 5-6: 5e fd, 0xfd5e - 2^16 = -674, x 0.0001
  CHECK(m.roll_rad.raw() == -674);
  CHECK(*m.roll_rad.exact() == dec(-674, 4));  // -0.0674
  check_codec(m, wire);
}

TEST_CASE("127258 Magnetic Variation: a capture decoded by hand, encoded back", "[127258]") {
  check_info<n2k::magnetic_variation>(127258, 7, n2k::framing::single_frame, 1000, 8);
  // 2016-02-28T19:57:02.872Z, source 105; canboat:
  // {"sid":147,"source":"Manual","ageOfService":null,"variation":-0.3403}
  constexpr std::array<std::uint8_t, 8> wire{0x93, 0xf0, 0xff, 0xff, 0xb5, 0xf2, 0xff, 0xff};
  const auto m = n2k::decode<n2k::magnetic_variation>(wire);
  // byte 0: 93, 0x93 = 147
  CHECK(m.sid.raw() == 147);
  CHECK(m.source == n2k::variation_source::manual);  // byte 1 bits 0-3: f0, raw 0
  CHECK(m.source.name() == "manual");
  // bytes 2-3: ff ff
  CHECK(m.age_of_service.state() == field_state::not_available);
  // bytes 4-5: b5 f2, 0xf2b5 - 2^16 = -3403, x 0.0001
  CHECK(m.variation_rad.raw() == -3403);
  CHECK(*m.variation_rad.exact() == dec(-3403, 4));  // -0.3403
  check_codec(m, wire);
}

TEST_CASE("128267 Water Depth: a capture decoded by hand, encoded back", "[128267]") {
  check_info<n2k::water_depth>(128267, 3, n2k::framing::single_frame, 1000, 8);
  // 2016-02-28T19:57:02.828Z, source 36; canboat:
  // {"sid":22,"depth":1.61,"offset":1.31,"range":null}
  constexpr std::array<std::uint8_t, 8> wire{0x16, 0xa1, 0x00, 0x00, 0x00, 0x1e, 0x05, 0xff};
  const auto m = n2k::decode<n2k::water_depth>(wire);
  // byte 0: 16, 0x16 = 22
  CHECK(m.sid.raw() == 22);
  // bytes 1-4: a1 00 00 00, 0xa1 = 161, x 0.01
  CHECK(m.depth_m.raw() == 161);
  CHECK(*m.depth_m.exact() == dec(161, 2));  // 1.61
  // bytes 5-6: 1e 05, 0x51e = 1310, x 0.001
  CHECK(m.offset_m.raw() == 1310);
  CHECK(*m.offset_m.exact() == dec(1310, 3));  // 1.310
  // byte 7: ff
  CHECK(m.range_m.state() == field_state::not_available);
  check_codec(m, wire);
}

TEST_CASE("129025 Position, Rapid Update: a capture decoded by hand, encoded back", "[129025]") {
  check_info<n2k::position_rapid>(129025, 2, n2k::framing::single_frame, 100, 8);
  // 2026-08-03T05:05:28.004Z, source 52; canboat: {"latitude":34.4059417,"longitude":133.5412196}
  constexpr std::array<std::uint8_t, 8> wire{0x19, 0xee, 0x81, 0x14, 0xe4, 0xc5, 0x98, 0x4f};
  const auto m = n2k::decode<n2k::position_rapid>(wire);
  // bytes 0-3: 19 ee 81 14, 0x1481ee19 = 344059417, x 0.0000001
  CHECK(m.latitude_deg.raw() == 344059417);
  CHECK(*m.latitude_deg.exact() == dec(344059417, 7));  // 34.4059417
  // bytes 4-7: e4 c5 98 4f, 0x4f98c5e4 = 1335412196, x 0.0000001
  CHECK(m.longitude_deg.raw() == 1335412196);
  CHECK(*m.longitude_deg.exact() == dec(1335412196, 7));  // 133.5412196
  check_codec(m, wire);
}

TEST_CASE("129026 COG & SOG, Rapid Update: a capture decoded by hand, encoded back", "[129026]") {
  check_info<n2k::cog_sog_rapid>(129026, 2, n2k::framing::single_frame, 250, 8);
  // 2026-08-03T04:55:51.709Z, source 25; canboat:
  // {"sid":143,"cogReference":"True","cog":5.1661,"sog":3.13}
  constexpr std::array<std::uint8_t, 8> wire{0x8f, 0xfc, 0xcd, 0xc9, 0x39, 0x01, 0xff, 0xff};
  const auto m = n2k::decode<n2k::cog_sog_rapid>(wire);
  // byte 0: 8f, 0x8f = 143
  CHECK(m.sid.raw() == 143);
  CHECK(m.cog_reference == n2k::heading_reference::true_north);  // byte 1 bits 0-1: fc, raw 0
  CHECK(m.cog_reference.name() == "true");
  // bytes 2-3: cd c9, 0xc9cd = 51661, x 0.0001
  CHECK(m.cog_rad.raw() == 51661);
  CHECK(*m.cog_rad.exact() == dec(51661, 4));  // 5.1661
  // bytes 4-5: 39 01, 0x139 = 313, x 0.01
  CHECK(m.sog_mps.raw() == 313);
  CHECK(*m.sog_mps.exact() == dec(313, 2));  // 3.13
  check_codec(m, wire);
}

TEST_CASE("127245 Rudder: a capture decoded by hand, encoded back", "[127245]") {
  check_info<n2k::rudder>(127245, 2, n2k::framing::single_frame, 100, 8);
  // 2024-02-17T05:15:49.768Z, source 204; canboat:
  // {"instance":0,"directionOrder":null,"angleOrder":0.2595,"position":0.2554}
  constexpr std::array<std::uint8_t, 8> wire{0x00, 0xff, 0x23, 0x0a, 0xfa, 0x09, 0xff, 0xff};
  const auto m = n2k::decode<n2k::rudder>(wire);
  // byte 0: 00, 0x0 = 0
  CHECK(m.instance.raw() == 0);
  // byte 1 bits 0-2: ff
  CHECK(m.direction_order.state() == field_state::not_available);
  // bytes 2-3: 23 0a, 0xa23 = 2595, x 0.0001
  CHECK(m.angle_order_rad.raw() == 2595);
  CHECK(*m.angle_order_rad.exact() == dec(2595, 4));  // 0.2595
  // bytes 4-5: fa 09, 0x9fa = 2554, x 0.0001
  CHECK(m.position_rad.raw() == 2554);
  CHECK(*m.position_rad.exact() == dec(2554, 4));  // 0.2554
  check_codec(m, wire);
}

TEST_CASE("130306 Wind Data: a capture decoded by hand, encoded back", "[130306]") {
  check_info<n2k::wind_data>(130306, 2, n2k::framing::single_frame, 100, 8);
  // 2026-07-02T06:01:32.997Z, source 38; canboat:
  // {"sid":79,"windSpeed":8.11,"windAngle":2.7581,"reference":"True (boat referenced)"}
  constexpr std::array<std::uint8_t, 8> wire{0x4f, 0x2b, 0x03, 0xbd, 0x6b, 0xfb, 0xff, 0xff};
  const auto m = n2k::decode<n2k::wind_data>(wire);
  // byte 0: 4f, 0x4f = 79
  CHECK(m.sid.raw() == 79);
  // bytes 1-2: 2b 03, 0x32b = 811, x 0.01
  CHECK(m.wind_speed_mps.raw() == 811);
  CHECK(*m.wind_speed_mps.exact() == dec(811, 2));  // 8.11
  // bytes 3-4: bd 6b, 0x6bbd = 27581, x 0.0001
  CHECK(m.wind_angle_rad.raw() == 27581);
  CHECK(*m.wind_angle_rad.exact() == dec(27581, 4));     // 2.7581
  CHECK(m.reference == n2k::wind_reference::true_boat);  // byte 5 bits 0-2: fb, raw 3
  CHECK(m.reference.name() == "true_boat");
  check_codec(m, wire);
}

TEST_CASE("130312 Temperature: a capture decoded by hand, encoded back", "[130312]") {
  check_info<n2k::temperature>(130312, 5, n2k::framing::single_frame, 2000, 8);
  // 2016-02-28T19:57:02.827Z, source 42; canboat:
  // {"sid":174,"instance":1,"source":143,"actualTemperature":327.94,"setTemperature":null}
  constexpr std::array<std::uint8_t, 8> wire{0xae, 0x01, 0x8f, 0x1a, 0x80, 0xff, 0xff, 0xff};
  const auto m = n2k::decode<n2k::temperature>(wire);
  // byte 0: ae, 0xae = 174
  CHECK(m.sid.raw() == 174);
  // byte 1: 01, 0x1 = 1
  CHECK(m.instance.raw() == 1);
  CHECK(m.source.raw() == 143);  // byte 2: 8f, a value the standard has not named
  CHECK(m.source.name().empty());
  // bytes 3-4: 1a 80, 0x801a = 32794, x 0.01
  CHECK(m.actual_temperature_k.raw() == 32794);
  CHECK(*m.actual_temperature_k.exact() == dec(32794, 2));  // 327.94
  // bytes 5-6: ff ff
  CHECK(m.set_temperature_k.state() == field_state::not_available);
  check_codec(m, wire);
}

TEST_CASE("130313 Humidity: a capture decoded by hand, encoded back", "[130313]") {
  check_info<n2k::humidity>(130313, 5, n2k::framing::single_frame, 2000, 8);
  // 2016-02-28T19:57:03.053Z, source 130; canboat:
  // {"sid":23,"instance":0,"source":"Outside","actualHumidity":60.116,"setHumidity":null}
  constexpr std::array<std::uint8_t, 8> wire{0x17, 0x00, 0x01, 0xb5, 0x3a, 0xff, 0x7f, 0xff};
  const auto m = n2k::decode<n2k::humidity>(wire);
  // byte 0: 17, 0x17 = 23
  CHECK(m.sid.raw() == 23);
  // byte 1: 00, 0x0 = 0
  CHECK(m.instance.raw() == 0);
  CHECK(m.source == n2k::humidity_source::outside);  // byte 2: 01, raw 1
  CHECK(m.source.name() == "outside");
  // bytes 3-4: b5 3a, 0x3ab5 = 15029, x 0.004
  CHECK(m.actual_humidity_pct.raw() == 15029);
  CHECK(*m.actual_humidity_pct.exact() == dec(60116, 3));  // 60.116
  // bytes 5-6: ff 7f
  CHECK(m.set_humidity_pct.state() == field_state::not_available);
  check_codec(m, wire);
}

TEST_CASE("130314 Actual Pressure: a capture decoded by hand, encoded back", "[130314]") {
  check_info<n2k::actual_pressure>(130314, 5, n2k::framing::single_frame, 2000, 8);
  // 2016-02-28T19:57:02.825Z, source 88; canboat:
  // {"sid":100,"instance":0,"source":"Hydraulic","pressure":93633.0}
  constexpr std::array<std::uint8_t, 8> wire{0x64, 0x00, 0x04, 0x8a, 0x49, 0x0e, 0x00, 0xff};
  const auto m = n2k::decode<n2k::actual_pressure>(wire);
  // byte 0: 64, 0x64 = 100
  CHECK(m.sid.raw() == 100);
  // byte 1: 00, 0x0 = 0
  CHECK(m.instance.raw() == 0);
  CHECK(m.source == n2k::pressure_source::hydraulic);  // byte 2: 04, raw 4
  CHECK(m.source.name() == "hydraulic");
  // bytes 3-6: 8a 49 0e 00, 0xe498a = 936330, x 0.1
  CHECK(m.pressure_pa.raw() == 936330);
  CHECK(*m.pressure_pa.exact() == dec(936330, 1));  // 93633.0
  check_codec(m, wire);
}

TEST_CASE("130316 Temperature Extended Range: a capture decoded by hand, encoded back",
          "[130316]") {
  check_info<n2k::temperature_extended>(130316, 5, n2k::framing::single_frame, 2000, 8);
  // 2026-07-02T06:01:33.433Z, source 35; canboat: {"sid":null,"instance":0,"source":"Sea
  // Temperature","temperature":303.064,"setTemperature":null}
  constexpr std::array<std::uint8_t, 8> wire{0xff, 0x00, 0x00, 0xd8, 0x9f, 0x04, 0xff, 0xff};
  const auto m = n2k::decode<n2k::temperature_extended>(wire);
  // byte 0: ff
  CHECK(m.sid.state() == field_state::not_available);
  // byte 1: 00, 0x0 = 0
  CHECK(m.instance.raw() == 0);
  CHECK(m.source == n2k::temperature_source::sea);  // byte 2: 00, raw 0
  CHECK(m.source.name() == "sea");
  // bytes 3-5: d8 9f 04, 0x49fd8 = 303064, x 0.001
  CHECK(m.temperature_k.raw() == 303064);
  CHECK(*m.temperature_k.exact() == dec(303064, 3));  // 303.064
  // bytes 6-7: ff ff
  CHECK(m.set_temperature_k.state() == field_state::not_available);
  check_codec(m, wire);
}

TEST_CASE("127508 Battery Status: a capture decoded by hand, encoded back", "[127508]") {
  check_info<n2k::battery_status>(127508, 6, n2k::framing::single_frame, 1500, 8);
  // 2016-02-28T19:57:02.824Z, source 4; canboat:
  // {"instance":11,"voltage":26.3,"current":0.0,"temperature":0.0,"sid":0}
  constexpr std::array<std::uint8_t, 8> wire{0x0b, 0x46, 0x0a, 0x00, 0x00, 0x00, 0x00, 0x00};
  const auto m = n2k::decode<n2k::battery_status>(wire);
  // byte 0: 0b, 0xb = 11
  CHECK(m.instance.raw() == 11);
  // bytes 1-2: 46 0a, 0xa46 = 2630, x 0.01
  CHECK(m.voltage_v.raw() == 2630);
  CHECK(*m.voltage_v.exact() == dec(2630, 2));  // 26.30
  // bytes 3-4: 00 00, 0x0 = 0, x 0.1
  CHECK(m.current_a.raw() == 0);
  CHECK(*m.current_a.exact() == dec(0, 1));  // 0.0
  // bytes 5-6: 00 00, 0x0 = 0, x 0.01
  CHECK(m.temperature_k.raw() == 0);
  CHECK(*m.temperature_k.exact() == dec(0, 2));  // 0.00
  // byte 7: 00, 0x0 = 0
  CHECK(m.sid.raw() == 0);
  check_codec(m, wire);
}

TEST_CASE("127505 Fluid Level: a capture decoded by hand, encoded back", "[127505]") {
  check_info<n2k::fluid_level>(127505, 6, n2k::framing::single_frame, 2500, 8);
  // 2016-02-28T19:57:03.879Z, source 89; canboat:
  // {"instance":2,"type":"Fuel","level":93.68,"capacity":246.0}
  constexpr std::array<std::uint8_t, 8> wire{0x02, 0x7c, 0x5b, 0x9c, 0x09, 0x00, 0x00, 0xff};
  const auto m = n2k::decode<n2k::fluid_level>(wire);
  // byte 0 bits 0-3: 02, 0x2 = 2
  CHECK(m.instance.raw() == 2);
  CHECK(m.fluid_type == n2k::tank_type::fuel);  // byte 0 bits 4-7: 02, raw 0
  CHECK(m.fluid_type.name() == "fuel");
  // bytes 1-2: 7c 5b, 0x5b7c = 23420, x 0.004
  CHECK(m.level_pct.raw() == 23420);
  CHECK(*m.level_pct.exact() == dec(93680, 3));  // 93.680
  // bytes 3-6: 9c 09 00 00, 0x99c = 2460, x 0.1
  CHECK(m.capacity_l.raw() == 2460);
  CHECK(*m.capacity_l.exact() == dec(2460, 1));  // 246.0
  check_codec(m, wire);
}

TEST_CASE("127506 DC Detailed Status: a capture decoded by hand, encoded back", "[127506]") {
  check_info<n2k::dc_detailed_status>(127506, 6, n2k::framing::fast_packet, 1500, 11);
  // 2026-06-08T01:51:25.526Z, source 0; canboat:
  // {"sid":93,"instance":0,"dcType":null,"stateOfCharge":73,"stateOfHealth":null,"timeRemaining":"18:12:00","rippleVoltage":null,"remainingCapacity":null}
  constexpr std::array<std::uint8_t, 11> wire{0x5d, 0x00, 0xff, 0x49, 0xff, 0x44,
                                              0x04, 0xff, 0xff, 0xff, 0xff};
  const auto m = n2k::decode<n2k::dc_detailed_status>(wire);
  // byte 0: 5d, 0x5d = 93
  CHECK(m.sid.raw() == 93);
  // byte 1: 00, 0x0 = 0
  CHECK(m.instance.raw() == 0);
  // byte 2: ff
  CHECK(m.dc_type.state() == field_state::not_available);
  // byte 3: 49, 0x49 = 73
  CHECK(m.state_of_charge_pct.raw() == 73);
  // byte 4: ff
  CHECK(m.state_of_health_pct.state() == field_state::not_available);
  // bytes 5-6: 44 04, 0x444 = 1092, x 60
  CHECK(m.time_remaining_s.raw() == 1092);
  CHECK(*m.time_remaining_s.exact() == dec(65520, 0));  // 65520
  // bytes 7-8: ff ff
  CHECK(m.ripple_voltage_v.state() == field_state::not_available);
  // bytes 9-10: ff ff
  CHECK(m.remaining_capacity_ah.state() == field_state::not_available);
  check_codec(m, wire);
}

TEST_CASE("129283 Cross Track Error: a capture decoded by hand, encoded back", "[129283]") {
  check_info<n2k::cross_track_error>(129283, 3, n2k::framing::single_frame, 1000, 8);
  // 2026-07-02T06:01:33.052Z, source 24; canboat:
  // {"sid":104,"xteMode":"Autonomous","navigationTerminated":"No","xte":-6949.75}
  constexpr std::array<std::uint8_t, 8> wire{0x68, 0x30, 0x41, 0x65, 0xf5, 0xff, 0xff, 0xff};
  const auto m = n2k::decode<n2k::cross_track_error>(wire);
  // byte 0: 68, 0x68 = 104
  CHECK(m.sid.raw() == 104);
  CHECK(m.xte_mode == n2k::residual_mode::autonomous);  // byte 1 bits 0-3: 30, raw 0
  CHECK(m.xte_mode.name() == "autonomous");
  CHECK(m.navigation_terminated == n2k::yes_no::no);  // byte 1 bits 6-7: 30, raw 0
  CHECK(m.navigation_terminated.name() == "no");
  // bytes 2-5: 41 65 f5 ff, 0xfff56541 - 2^32 = -694975, x 0.01
  CHECK(m.xte_m.raw() == -694975);
  CHECK(*m.xte_m.exact() == dec(-694975, 2));  // -6949.75
  check_codec(m, wire);
}

TEST_CASE("126992 System Time: a capture decoded by hand, encoded back", "[126992]") {
  check_info<n2k::system_time>(126992, 3, n2k::framing::single_frame, 1000, 8);
  // 2016-04-09T16:41:09.087Z, source 18; canboat:
  // {"sid":90,"source":"GPS","date":"2016.04.09","time":"16:41:07.0000"}
  constexpr std::array<std::uint8_t, 8> wire{0x5a, 0xf0, 0x04, 0x42, 0x30, 0x7f, 0xcd, 0x23};
  const auto m = n2k::decode<n2k::system_time>(wire);
  // byte 0: 5a, 0x5a = 90
  CHECK(m.sid.raw() == 90);
  CHECK(m.source == n2k::time_source::gps);  // byte 1 bits 0-3: f0, raw 0
  CHECK(m.source.name() == "gps");
  CHECK(m.date.raw() == 16900);  // bytes 2-3: 04 42, days since 1970-01-01
  CHECK(m.date.value() == days(2016, 4, 9));
  CHECK(m.time.raw() == 600670000);  // bytes 4-7: 30 7f cd 23, 16:41:07.0000 in 0.0001 s
  check_codec(m, wire);
}

TEST_CASE("129033 Time & Date: a capture decoded by hand, encoded back", "[129033]") {
  check_info<n2k::time_date>(129033, 3, n2k::framing::single_frame, 1000, 8);
  // 2016-04-09T16:41:10.065Z, source 0; canboat:
  // {"date":"2016.04.09","time":"16:41:08.0000","localOffset":null}
  constexpr std::array<std::uint8_t, 8> wire{0x04, 0x42, 0x40, 0xa6, 0xcd, 0x23, 0xff, 0x7f};
  const auto m = n2k::decode<n2k::time_date>(wire);
  CHECK(m.date.raw() == 16900);  // bytes 0-1: 04 42, days since 1970-01-01
  CHECK(m.date.value() == days(2016, 4, 9));
  CHECK(m.time.raw() == 600680000);  // bytes 2-5: 40 a6 cd 23, 16:41:08.0000 in 0.0001 s
  // bytes 6-7: ff 7f
  CHECK(m.local_offset_s.state() == field_state::not_available);
  check_codec(m, wire);
}

TEST_CASE("129539 GNSS DOPs: a capture decoded by hand, encoded back", "[129539]") {
  check_info<n2k::gnss_dops>(129539, 6, n2k::framing::single_frame, 1000, 8);
  // 2016-02-28T19:57:03.429Z, source 33; canboat:
  // {"sid":199,"desiredMode":"Auto","actualMode":"3D","hdop":0.79,"vdop":1.22,"tdop":null}
  constexpr std::array<std::uint8_t, 8> wire{0xc7, 0xd3, 0x4f, 0x00, 0x7a, 0x00, 0xff, 0x7f};
  const auto m = n2k::decode<n2k::gnss_dops>(wire);
  // byte 0: c7, 0xc7 = 199
  CHECK(m.sid.raw() == 199);
  CHECK(m.desired_mode == n2k::gnss_mode::automatic);  // byte 1 bits 0-2: d3, raw 3
  CHECK(m.desired_mode.name() == "auto");
  CHECK(m.actual_mode == n2k::gnss_mode::fix_3d);  // byte 1 bits 3-5: d3, raw 2
  CHECK(m.actual_mode.name() == "3d");
  // bytes 2-3: 4f 00, 0x4f = 79, x 0.01
  CHECK(m.hdop.raw() == 79);
  CHECK(*m.hdop.exact() == dec(79, 2));  // 0.79
  // bytes 4-5: 7a 00, 0x7a = 122, x 0.01
  CHECK(m.vdop.raw() == 122);
  CHECK(*m.vdop.exact() == dec(122, 2));  // 1.22
  // bytes 6-7: ff 7f
  CHECK(m.tdop.state() == field_state::not_available);
  check_codec(m, wire);
}

TEST_CASE("129284 Navigation Data: a capture decoded by hand, encoded back", "[129284]") {
  check_info<n2k::navigation_data>(129284, 3, n2k::framing::fast_packet, 1000, 34);
  // 2026-07-02T06:01:33.057Z, source 24; canboat:
  // {"sid":104,"distanceToWaypoint":2430371.52,"courseBearingReference":"True","perpendicularCrossed":"No","arrivalCircleEntered":"No","calculationType":"Rhumbline","etaTime":"04:58:14.0000","etaDate":"2026.07.10","bearingOriginToDestinationWaypoint":5.2555,"bearingPositionToDestinationWaypoint":5.1649,"originWaypointNumber":0,"destinationWaypointNumber":0,"destinationLatitude":33.176417,"destinationLongitude":135.0576675,"waypointClosingVelocity":3.56}
  constexpr std::array<std::uint8_t, 34> wire{0x68, 0xe0, 0x73, 0x7c, 0x0e, 0x40, 0x60, 0x68, 0xaa,
                                              0x0a, 0xa4, 0x50, 0x4b, 0xcd, 0xc1, 0xc9, 0x00, 0x00,
                                              0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xca, 0x51, 0xc6,
                                              0x13, 0x23, 0x2a, 0x80, 0x50, 0x64, 0x01};
  const auto m = n2k::decode<n2k::navigation_data>(wire);
  // byte 0: 68, 0x68 = 104
  CHECK(m.sid.raw() == 104);
  // bytes 1-4: e0 73 7c 0e, 0xe7c73e0 = 243037152, x 0.01
  CHECK(m.distance_to_waypoint_m.raw() == 243037152);
  CHECK(*m.distance_to_waypoint_m.exact() == dec(243037152, 2));  // 2430371.52
  CHECK(m.course_bearing_reference ==
        n2k::heading_reference::true_north);  // byte 5 bits 0-1: 40, raw 0
  CHECK(m.course_bearing_reference.name() == "true");
  CHECK(m.perpendicular_crossed == n2k::yes_no::no);  // byte 5 bits 2-3: 40, raw 0
  CHECK(m.perpendicular_crossed.name() == "no");
  CHECK(m.arrival_circle_entered == n2k::yes_no::no);  // byte 5 bits 4-5: 40, raw 0
  CHECK(m.arrival_circle_entered.name() == "no");
  CHECK(m.calculation_type == n2k::bearing_mode::rhumb_line);  // byte 5 bits 6-7: 40, raw 1
  CHECK(m.calculation_type.name() == "rhumb_line");
  CHECK(m.eta_time.raw() == 178940000);  // bytes 6-9: 60 68 aa 0a, 04:58:14.0000 in 0.0001 s
  CHECK(m.eta_date.raw() == 20644);      // bytes 10-11: a4 50, days since 1970-01-01
  CHECK(m.eta_date.value() == days(2026, 7, 10));
  // bytes 12-13: 4b cd, 0xcd4b = 52555, x 0.0001
  CHECK(m.bearing_origin_to_destination_rad.raw() == 52555);
  CHECK(*m.bearing_origin_to_destination_rad.exact() == dec(52555, 4));  // 5.2555
  // bytes 14-15: c1 c9, 0xc9c1 = 51649, x 0.0001
  CHECK(m.bearing_position_to_destination_rad.raw() == 51649);
  CHECK(*m.bearing_position_to_destination_rad.exact() == dec(51649, 4));  // 5.1649
  // bytes 16-19: 00 00 00 00, 0x0 = 0
  CHECK(m.origin_waypoint_number.raw() == 0);
  // bytes 20-23: 00 00 00 00, 0x0 = 0
  CHECK(m.destination_waypoint_number.raw() == 0);
  // bytes 24-27: ca 51 c6 13, 0x13c651ca = 331764170, x 0.0000001
  CHECK(m.destination_latitude_deg.raw() == 331764170);
  CHECK(*m.destination_latitude_deg.exact() == dec(331764170, 7));  // 33.1764170
  // bytes 28-31: 23 2a 80 50, 0x50802a23 = 1350576675, x 0.0000001
  CHECK(m.destination_longitude_deg.raw() == 1350576675);
  CHECK(*m.destination_longitude_deg.exact() == dec(1350576675, 7));  // 135.0576675
  // bytes 32-33: 64 01, 0x164 = 356, x 0.01
  CHECK(m.waypoint_closing_velocity_mps.raw() == 356);
  CHECK(*m.waypoint_closing_velocity_mps.exact() == dec(356, 2));  // 3.56
  check_codec(m, wire);
}

TEST_CASE("130577 Direction Data: a capture decoded by hand, encoded back", "[130577]") {
  check_info<n2k::direction_data>(130577, 3, n2k::framing::fast_packet, 1000, 14);
  // 2026-06-23T23:16:12.648Z, source 52; canboat: {"dataMode":"Differential
  // enhanced","cogReference":"True","sid":null,"cog":5.0188,"sog":4.04,"heading":5.0467,"speedThroughWater":null,"set":null,"drift":null}
  constexpr std::array<std::uint8_t, 14> wire{0xc1, 0xff, 0x0c, 0xc4, 0x94, 0x01, 0x23,
                                              0xc5, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff};
  const auto m = n2k::decode<n2k::direction_data>(wire);
  CHECK(m.data_mode == n2k::residual_mode::differential);  // byte 0 bits 0-3: c1, raw 1
  CHECK(m.data_mode.name() == "differential");
  CHECK(m.cog_reference == n2k::heading_reference::true_north);  // byte 0 bits 4-5: c1, raw 0
  CHECK(m.cog_reference.name() == "true");
  // byte 1: ff
  CHECK(m.sid.state() == field_state::not_available);
  // bytes 2-3: 0c c4, 0xc40c = 50188, x 0.0001
  CHECK(m.cog_rad.raw() == 50188);
  CHECK(*m.cog_rad.exact() == dec(50188, 4));  // 5.0188
  // bytes 4-5: 94 01, 0x194 = 404, x 0.01
  CHECK(m.sog_mps.raw() == 404);
  CHECK(*m.sog_mps.exact() == dec(404, 2));  // 4.04
  // bytes 6-7: 23 c5, 0xc523 = 50467, x 0.0001
  CHECK(m.heading_rad.raw() == 50467);
  CHECK(*m.heading_rad.exact() == dec(50467, 4));  // 5.0467
  // bytes 8-9: ff ff
  CHECK(m.speed_water_mps.state() == field_state::not_available);
  // bytes 10-11: ff ff
  CHECK(m.set_rad.state() == field_state::not_available);
  // bytes 12-13: ff ff
  CHECK(m.drift_mps.state() == field_state::not_available);
  check_codec(m, wire);
}

TEST_CASE("59904 ISO Request: a capture decoded by hand, encoded back", "[59904]") {
  check_info<n2k::iso_request>(59904, 6, n2k::framing::single_frame, 0, 3);
  // 2016-02-28T19:57:02.825Z, source 41; canboat: {"pgn":126998}
  constexpr std::array<std::uint8_t, 3> wire{0x16, 0xf0, 0x01};
  const auto m = n2k::decode<n2k::iso_request>(wire);
  // bytes 0-2: 16 f0 01, 0x1f016 = 126998
  CHECK(m.requested_pgn.raw() == 126998);
  check_codec(m, wire);
}

TEST_CASE("59392 ISO Acknowledgement: a capture decoded by hand, encoded back", "[59392]") {
  check_info<n2k::iso_acknowledgement>(59392, 6, n2k::framing::single_frame, 0, 8);
  // 2016-02-28T19:57:02.825Z, source 60; canboat:
  // {"control":"NAK","groupFunction":null,"pgn":126998}
  constexpr std::array<std::uint8_t, 8> wire{0x01, 0xff, 0xff, 0xff, 0xff, 0x16, 0xf0, 0x01};
  const auto m = n2k::decode<n2k::iso_acknowledgement>(wire);
  CHECK(m.control == n2k::iso_control::nak);  // byte 0: 01, raw 1
  CHECK(m.control.name() == "nak");
  // byte 1: ff
  CHECK(m.group_function.state() == field_state::not_available);
  // bytes 5-7: 16 f0 01, 0x1f016 = 126998
  CHECK(m.acknowledged_pgn.raw() == 126998);
  check_codec(m, wire);
}

TEST_CASE("126992 System Time: dates past 2038 and to the end of the 16-bit day count",
          "[126992]") {
  // days 0x7000 = 28672 since 1970-01-01: 2048-07-02 (canboat's analyzer shows 1912-05-26,
  // its seconds wrapping at 32 bits); time 0
  constexpr std::array<std::uint8_t, 8> wire{0x01, 0xf0, 0x00, 0x70, 0x00, 0x00, 0x00, 0x00};
  const auto m = n2k::decode<n2k::system_time>(wire);
  CHECK(m.date.raw() == 28672);
  CHECK(m.date.value() == days(2048, 7, 2));
  CHECK(m.time.raw() == 0);
  check_codec(m, wire);
  // 0xfffc = 65532 days, the last ordinary value: 2149-06-03
  n2k::system_time last = m;
  last.date = n2k::day_count::from_raw(0xfffc);
  CHECK(last.date.value() == days(2149, 6, 3));
  check_codec(last, std::array<std::uint8_t, 8>{0x01, 0xf0, 0xfc, 0xff, 0x00, 0x00, 0x00, 0x00});
}
