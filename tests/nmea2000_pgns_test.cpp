// SPDX-License-Identifier: BSL-1.0
// The NMEA 2000 PGNs beyond the ANELLO inputs and 127250: for each, a payload from a real capture
// (canboat's sample logs; canboat's analyzer's reading of it in the comment) decoded field by field
// against the bit layout worked out by hand, encoded back to the same bytes, and decoded again to
// the same message. tools/decode/n2k_test.py compares every message of their vectors with
// canboat's analyzer.

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
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

template <n2k::pgn_like P>
void check_info(std::uint32_t pgn, unsigned priority, n2k::framing transport, unsigned interval_ms,
                std::size_t length) {
  constexpr n2k::pgn_info info = P::n2k.info;
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
