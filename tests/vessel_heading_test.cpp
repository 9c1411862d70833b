// SPDX-License-Identifier: BSL-1.0
// PGN 127250 Vessel Heading. The payloads are canboat's database samples for this PGN (from a
// 2022 capture) with the values canboat's database gives them, and two more captures decoded by
// canboat's field types; the edge payloads were built for these tests.

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/registry.hpp"

namespace n2k = seawire::nmea2000;
using n2k::field_state;
using n2k::heading_reference;
using n2k::vessel_heading;

namespace {

using payload = std::array<std::uint8_t, 8>;

vessel_heading decoded(const payload& p) { return n2k::decode<vessel_heading>(p); }

}  // namespace

TEST_CASE("127250: the table is canboat's", "[127250]") {
  constexpr n2k::pgn_info info = n2k::pgn_table<vessel_heading>.info;
  CHECK(info.pgn == 127250);
  CHECK(info.priority == 2);
  CHECK(info.transport == n2k::framing::single_frame);
  CHECK(info.interval_ms == 100);
  CHECK(n2k::description_of<vessel_heading>::length == 8);
  CHECK(seawire::registry::pgns::knows(127250));
  CHECK(seawire::registry::pgns::length(127250) == 8);
}

TEST_CASE("127250: canboat's samples", "[127250]") {
  // sid 0, heading 3.1410 rad, no deviation or variation, magnetic
  const auto a = decoded({0x00, 0xb2, 0x7a, 0xff, 0x7f, 0xff, 0x7f, 0xfd});
  CHECK(*a.sid.value() == 0);
  CHECK(a.heading_rad.raw() == 31410);
  CHECK(*a.heading_rad.exact() == seawire::nmea::decimal::scaled(31410, 4));
  CHECK(a.deviation_rad.state() == field_state::not_available);
  CHECK(a.variation_rad.state() == field_state::not_available);
  CHECK(a.reference == heading_reference::magnetic);
  CHECK(a.reference.name() == "magnetic");
  // no sid, heading 3.1230 true, variation 0.0374 east
  const auto b = decoded({0xff, 0xfe, 0x79, 0xff, 0x7f, 0x76, 0x01, 0xfc});
  CHECK(b.sid.state() == field_state::not_available);
  CHECK(b.heading_rad.raw() == 31230);
  CHECK(b.variation_rad.raw() == 374);
  CHECK(*b.variation_rad.value() == Approx(0.0374));
  CHECK(b.reference == heading_reference::true_north);
  CHECK(b.reference.name() == "true");
  const auto c = decoded({0xff, 0x59, 0x7a, 0xff, 0x7f, 0x76, 0x01, 0xfc});
  CHECK(c.heading_rad.raw() == 31321);
  // a westerly variation is negative: -0.2610 rad
  const auto d = decoded({0xff, 0x10, 0x3b, 0xff, 0x7f, 0xce, 0xf5, 0xfc});
  CHECK(d.heading_rad.raw() == 15120);
  CHECK(d.variation_rad.raw() == -2610);
  CHECK(*d.variation_rad.exact() == seawire::nmea::decimal::scaled(-2610, 4));
}

TEST_CASE("127250: sentinels and the reference's two unnamed values", "[127250]") {
  const auto e = decoded({0xfe, 0xfe, 0xff, 0xfe, 0x7f, 0x00, 0x80, 0xfe});
  CHECK(e.sid.state() == field_state::out_of_range);
  CHECK(e.heading_rad.state() == field_state::out_of_range);
  CHECK(e.deviation_rad.state() == field_state::out_of_range);
  CHECK(e.variation_rad.raw() == -32768);  // the lowest signed value is a number
  CHECK(e.variation_rad.has_value());
  CHECK(e.reference.state() == field_state::out_of_range);  // 2: "error"
  const auto n = decoded({0xff, 0xff, 0xff, 0xff, 0x7f, 0xff, 0x7f, 0xff});
  CHECK(n.reference.state() == field_state::not_available);  // 3
  CHECK(n.heading_rad.state() == field_state::not_available);
}

TEST_CASE("127250: encode writes the sample back, reserved bits as ones", "[127250]") {
  for (const payload& p : {payload{0x00, 0xb2, 0x7a, 0xff, 0x7f, 0xff, 0x7f, 0xfd},
                           payload{0xff, 0xfe, 0x79, 0xff, 0x7f, 0x76, 0x01, 0xfc},
                           payload{0xff, 0x10, 0x3b, 0xff, 0x7f, 0xce, 0xf5, 0xfc}}) {
    const auto e = n2k::encode(decoded(p));
    REQUIRE(e);
    CHECK(std::ranges::equal(e.value.view(), p));
  }
  // Reserved bits sent as zeros are read past and written as ones.
  const auto z = n2k::encode(decoded({0x00, 0xb2, 0x7a, 0xff, 0x7f, 0xff, 0x7f, 0x01}));
  REQUIRE(z);
  CHECK(z.value.view()[7] == 0xfd);
  // Built from physical values.
  vessel_heading h;
  REQUIRE(h.heading_rad.assign(1.5708) == seawire::errc::ok);
  h.reference = heading_reference::true_north;
  const auto built = n2k::encode(h);
  REQUIRE(built);
  CHECK(std::ranges::equal(built.value.view(),
                           payload{0xff, 0x5c, 0x3d, 0xff, 0x7f, 0xff, 0x7f, 0xfc}));
  // 6.5533 rad is past what the field holds as a value.
  CHECK(h.heading_rad.assign(6.5533) != seawire::errc::ok);
}

TEST_CASE("127250: JSON names the reference", "[127250]") {
  seawire::nmea::json_buffer<512> out;
  n2k::message_header header;
  header.id = {2, 127250, 20, n2k::broadcast_address};
  n2k::write_json(out, header, decoded({0x00, 0xb2, 0x7a, 0xff, 0x7f, 0xff, 0x7f, 0xfd}));
  REQUIRE_FALSE(out.overflow());
  const std::string json(out.view());
  INFO(json);
  CHECK(json.find("\"type\":\"PGN127250\"") != std::string::npos);
  CHECK(json.find("\"heading_rad\":3.141") != std::string::npos);
  CHECK(json.find("\"deviation_rad\":null") != std::string::npos);
  CHECK(json.find("\"reference\":\"magnetic\"") != std::string::npos);
}
