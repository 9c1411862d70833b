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
