// SPDX-License-Identifier: BSL-1.0
// Review findings: each case pins a disagreement between the implementation and the specs (or
// what real receivers do) that was fixed, so that it stays fixed.

#include <catch2/catch.hpp>
#include <cstdint>

#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/standard/rmc.hpp"

using namespace seawire;
using namespace seawire::nmea;

TEST_CASE("encode refuses a decimal the decoder could not read back") {
  // 20 digits: decode says number_too_long, so encode must not write them.
  kingfisher::pydep p;
  p.thrust = decimal(50);
  p.yaw_rate.mantissa = 18'446'744'073'709'551'615ULL;
  CHECK(encode(p).ec == errc::value_too_large);
  CHECK(encode(p).field == 1);
  p.yaw_rate.places = 19;  // "1.8446744073709551615": still 20 significant digits
  CHECK(encode(p).ec == errc::value_too_large);
  // The largest mantissa the decoder takes is written and read back.
  p.yaw_rate.mantissa = 9'999'999'999'999'999'999ULL;
  const auto e = encode(p);
  REQUIRE(e);
  const auto d = decode<kingfisher::pydep>(e.view(), parse_policy::strict());
  REQUIRE(d);
  CHECK(d.value == p);

  // Zero padding: the writer pads to 20 digits at most, and reads back what it wrote.
  p.yaw_rate = decimal(1);
  p.yaw_rate.int_width = 20;
  const auto padded = encode(p);
  REQUIRE(padded);
  CHECK(decode<kingfisher::pydep>(padded.view()).value == p);
  p.yaw_rate.int_width = 21;
  CHECK(encode(p).ec == errc::value_too_large);

  // The same through a decimal-degrees position (RobotX), whose own range check (<= 90) would
  // let 1.8446744073709551615 through.
  robotx::rxhrb h;
  h.team_id = "AUVSI";
  h.lat = decimal_latitude{};
  h.lat->value.mantissa = 18'446'744'073'709'551'615ULL;
  h.lat->value.places = 19;
  CHECK(encode(h).ec == errc::value_too_large);
  CHECK(encode(h).field == 3);
}
