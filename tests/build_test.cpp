// SPDX-License-Identifier: BSL-1.0
// Messages filled from the doubles a program has: each number at its field's declared
// precision (or the places asked for, or the shortest that reads back), and the first value
// that cannot be sent refused once, naming its field.

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "seawire/seawire.hpp"

namespace {

using namespace seawire;
using nmea::builder;
using nmea::decimal;

// Every number and position field of every message declares the precision a double is
// rounded to: checked here for each message of each family, so a new field cannot forget.
template <class T>
constexpr bool declares_precisions() {
  return T::nmea.fields.apply([](const auto&... d) {
    return (
        (!nmea::detail::fills_from_double<typename std::remove_cvref_t<decltype(d)>::value_type> ||
         d.opts.precision >= 0) &&
        ...);
  });
}
template <class... T>
constexpr bool all_declare(nmea::message_set<T...>*) {
  return (declares_precisions<T>() && ...);
}
using every_message =
    nmea::merge_sets<kingfisher::from_vehicle, kingfisher::to_vehicle, sandshark::from_vehicle,
                     sandshark::to_vehicle, robotx::reports, anello::nmea_inputs,
                     nmea::message_set<standard::gga>>::type;
static_assert(all_declare(static_cast<every_message*>(nullptr)));

// Constant evaluation: a command built from doubles at compile time.
constexpr auto pydev_90 = builder<kingfisher::pydev>{}
                              .set<&kingfisher::pydev::heading_deg>(90.04)
                              .set<&kingfisher::pydev::speed_mps>(1.5)
                              .result();
static_assert(pydev_90.ok());
static_assert(nmea::encode(pydev_90.value).view() == "$PYDEV,90.0,1.50*53\r\n");
static_assert(nmea::precision_of<&kingfisher::pydev::speed_mps>() == 2);
static_assert(nmea::precision_of<&standard::rmc::lat>() == 5);

std::string sentence(const auto& m) {
  const auto s = nmea::encode(m);
  REQUIRE(s);
  return std::string(s.view());
}

}  // namespace

TEST_CASE("builder: each field at its declared precision, or the places asked for") {
  const auto cmd = builder<kingfisher::pydev>{}
                       .set<&kingfisher::pydev::heading_deg>(203.14159)
                       .set<&kingfisher::pydev::speed_mps>(1.456)
                       .result();
  REQUIRE(cmd);
  CHECK(cmd.value.heading_deg == decimal::parse("203.1").value);
  CHECK(cmd.value.speed_mps == decimal::parse("1.46").value);

  const auto three = builder<kingfisher::pydev>{}
                         .set<&kingfisher::pydev::heading_deg>(203.14159, nmea::places{3})
                         .set<&kingfisher::pydev::speed_mps>(1.5, nmea::places{0})
                         .result();
  REQUIRE(three);
  CHECK(sentence(three.value).starts_with("$PYDEV,203.142,2*"));

  // Shortest: the fewest digits that read back as the same double.
  const auto s = builder<kingfisher::pydev>{}
                     .set<&kingfisher::pydev::heading_deg>(203.1, nmea::shortest)
                     .set<&kingfisher::pydev::speed_mps>(0.1 + 0.2, nmea::shortest)
                     .result();
  REQUIRE(s);
  CHECK(s.value.heading_deg == decimal::parse("203.1").value);
  CHECK(s.value.speed_mps == decimal::parse("0.30000000000000004").value);
  CHECK(s.value.speed_mps.to_double() == 0.1 + 0.2);
}

TEST_CASE("builder: the first value refused is reported once, naming its field") {
  auto b = builder<kingfisher::pydir>{};
  b.set<&kingfisher::pydir::thrust_left>(40.0)
      .set<&kingfisher::pydir::thrust_right>(150.0)  // beyond 100 %
      .set<&kingfisher::pydir::thrust_left>(std::numeric_limits<double>::quiet_NaN());
  const auto r = b.result();
  CHECK_FALSE(b);
  CHECK(r.ec == errc::out_of_range);
  CHECK(r.field == 2);
  CHECK(nmea::field_name<kingfisher::pydir>(r.field) == "thrust_right");
  // What was accepted is there; what was refused left the member as it was.
  CHECK(b.message().thrust_left == decimal::parse("40.0").value);
  CHECK(b.message().thrust_right == decimal{});

  const auto nan = builder<kingfisher::pydev>{}
                       .set<&kingfisher::pydev::speed_mps>(std::nan(""))
                       .set<&kingfisher::pydev::heading_deg>(360.0)
                       .result();
  CHECK(nan.ec == errc::not_finite);
  CHECK(nan.field == 2);
  // The heading's range is [0, 360): 359.96 at one place rounds to 360.0, refused.
  CHECK(builder<kingfisher::pydev>{}.set<&kingfisher::pydev::heading_deg>(359.96).result().ec ==
        errc::out_of_range);
  // Later fields are numbered as on the wire: GGA's altitude is field 9 (after 2+2 position
  // fields), its geoid separation 11 (after the altitude's unit letter).
  const auto g = builder<standard::gga>{}.set<&standard::gga::hdop>(-1.0).result();
  CHECK(g.ec == errc::out_of_range);
  CHECK(g.field == 8);
  const auto lat = builder<standard::gga>{}.set<&standard::gga::lat>(91.0).result();
  CHECK(lat.ec == errc::out_of_range);
  CHECK(lat.field == 2);
}

TEST_CASE("builder: a simulator's fixes, vehicle reports and RobotX heartbeats") {
  SECTION("RMC and GGA: positions with five minute digits") {
    auto rmc = builder<standard::rmc>{}
                   .set<&standard::rmc::lat>(42.36185233)
                   .set<&standard::rmc::lon>(-71.09081300)
                   .set<&standard::rmc::speed_knots>(0.1449)
                   .set<&standard::rmc::course_true>(156.784)
                   .set<&standard::rmc::magnetic_variation>(-15.27)
                   .result();
    REQUIRE(rmc);
    rmc.value.time = nmea::time_of_day{16, 49, 59, 0, 2};
    rmc.value.date = nmea::date{2014, 12, 31};
    CHECK(sentence(rmc.value) ==
          "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,15.3,W*53\r\n");
    const auto v = builder<standard::rmc>{}.set<&standard::rmc::magnetic_variation>(181.0).result();
    CHECK(v.ec == errc::variation_out_of_range);
    CHECK(v.field == 10);
  }
  SECTION("vehicle reports: CPNVG and BFNVG") {
    const auto nvg = builder<kingfisher::cpnvg>{}
                         .set<&kingfisher::cpnvg::lat>(42.5)
                         .set<&kingfisher::cpnvg::lon>(-71.25)
                         .set<&kingfisher::cpnvg::heading_deg>(234.329)
                         .set<&kingfisher::cpnvg::depth_m>(0.04)
                         .result();
    REQUIRE(nvg);
    CHECK(nvg.value.lat.minutes == decimal::parse("30.00000").value);
    CHECK(nvg.value.heading_deg == decimal::parse("234.33").value);
    CHECK(nvg.value.depth_m == decimal::parse("0.0").value);
    const auto roll = builder<sandshark::bfnvg>{}.set<&sandshark::bfnvg::roll_deg>(-181.0).result();
    CHECK(roll.ec == errc::out_of_range);
    CHECK(roll.field == 10);
    CHECK(nmea::field_name<sandshark::bfnvg>(roll.field) == "roll_deg");
  }
  SECTION("RobotX: decimal degrees with five digits") {
    const auto hb = builder<robotx::rxhrb>{}
                        .set<&robotx::rxhrb::lat>(21.311978)
                        .set<&robotx::rxhrb::lon>(-157.889721)
                        .result();
    REQUIRE(hb);
    CHECK(hb.value.lat->value == decimal::parse("21.31198").value);
    CHECK(hb.value.lon->hemi == nmea::hemisphere::west);
    CHECK(hb.value.lon->value == decimal::parse("157.88972").value);
  }
  SECTION("shortest positions read back as the same double") {
    const double deg = 42.361852333333;
    const auto r = builder<standard::gga>{}.set<&standard::gga::lat>(deg, nmea::shortest).result();
    REQUIRE(r);
    REQUIRE(r.value.lat);
    CHECK(r.value.lat->degrees() == deg);
  }
}

TEST_CASE("PY* helpers round to each field's declared precision") {
  const auto dep = kingfisher::pydep::from_rate(-10.126, 50.04);
  REQUIRE(dep);
  CHECK(sentence(dep.value).starts_with("$PYDEP,-10.13,50.0*"));
  const auto dev = kingfisher::pydev::from_heading(-90.04, 1.456);
  REQUIRE(dev);
  CHECK(sentence(dev.value).starts_with("$PYDEV,270.0,1.46*"));
  const auto dir = kingfisher::pydir::from_percent(45.04, -55.06);
  REQUIRE(dir);
  CHECK(sentence(dir.value).starts_with("$PYDIR,45.0,-55.1*"));
  // Asked-for places still apply to both.
  CHECK(sentence(kingfisher::pydev::from_heading(90, 1.5, 0).value).starts_with("$PYDEV,90,2*"));
}

TEST_CASE("BPRMB request: heading, depth and speed with their modes") {
  const nmea::time_of_day t{23, 12, 4, 72, 2};
  const auto r = sandshark::bprmb::request(t, 90.04, 5.0, 1.25);
  REQUIRE(r);
  CHECK(sentence(r.value) == "$BPRMB,231204.72,90.0,5.0,0,1.3,1,0*6F\r\n");
  const auto heading_only = sandshark::bprmb::request(t, 270.0, std::nullopt, std::nullopt);
  REQUIRE(heading_only);
  CHECK(sentence(heading_only.value) == "$BPRMB,231204.72,270.0,,,,,0*55\r\n");
  const auto bad = sandshark::bprmb::request(t, 360.0, 5.0, 1.0);
  CHECK(bad.ec == errc::out_of_range);
  CHECK(bad.field == 2);
  CHECK(sandshark::bprmb::request(t, 10.0, -1.0, 1.0).field == 3);
  CHECK(sandshark::bprmb::request(t, 10.0, 1.0, std::nan("")).ec == errc::not_finite);
  CHECK(sandshark::bprmb::request(t, 10.0, 1.0, std::nan("")).field == 5);
}
