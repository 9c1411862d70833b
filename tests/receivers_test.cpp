// SPDX-License-Identifier: BSL-1.0
// What GPS receivers and instruments in the field send: every real fix is kept, every corrupt
// line is refused, and what is kept is written back as it came where that carries meaning.

#include <catch2/catch.hpp>
#include <string>
#include <string_view>

#include "seawire/seawire.hpp"

#include "support.hpp"

namespace {

using namespace support;

using namespace seawire;
using nmea::decimal;

template <class T>
std::string round_trip(const std::string& line) {
  const auto d = nmea::decode<T>(line);
  REQUIRE(d);
  const auto e = nmea::encode(d.value);
  REQUIRE(e);
  return std::string(e.view());
}

}  // namespace

TEST_CASE("GGA with a blank fix quality: not available, and the rest of the fix kept") {
  const std::string line =
      sealed("GPGGA,105027.80,5612.9956,N,00306.6983,W,,3,2.506,160.002,M,,M,,");
  const auto g = nmea::decode<standard::gga>(line);
  REQUIRE(g);
  CHECK_FALSE(g.value.quality.has_value());
  REQUIRE(g.value.lat);
  CHECK(g.value.lat->degrees() == Approx(56.0 + 12.9956 / 60));
  REQUIRE(g.value.lon);
  CHECK(g.value.lon->degrees() == Approx(-(3.0 + 6.6983 / 60)));
  CHECK(g.value.satellites == 3);
  CHECK(g.value.hdop == decimal::parse("2.506").value);
  CHECK(g.value.altitude_m == decimal::parse("160.002").value);
  CHECK_FALSE(g.value.geoid_separation_m);
  // Satellites are written with two digits, the standard's form (a documented normalization).
  CHECK(round_trip<standard::gga>(line) ==
        sealed("GPGGA,105027.80,5612.9956,N,00306.6983,W,,03,2.506,160.002,M,,M,,"));

  // A quality that is there is still checked.
  CHECK(nmea::decode<standard::gga>(
            sealed("GPGGA,105027.80,5612.9956,N,00306.6983,W,9,03,2.5,160.0,M,,M,,"))
            .ec == errc::bad_enum);
  standard::gga built;
  built.quality = standard::gps_quality::dgps;
  const auto out = nmea::encode(built);
  REQUIRE(out);
  CHECK(out.view().starts_with("$GPGGA,,,,,,2,"));
}

TEST_CASE("RMC magnetic variation: its own type, and an impossible one costs no fix") {
  const std::string base = "GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,";
  SECTION("a real variation, signed east positive") {
    const auto r = nmea::decode<standard::rmc>(sealed(base + "15.3,W,A"));
    REQUIRE(r);
    REQUIRE(r.value.magnetic_variation);
    CHECK(r.value.magnetic_variation->value == decimal::parse("15.3").value);
    CHECK(r.value.magnetic_variation->direction == nmea::hemisphere::west);
    CHECK(*r.value.magnetic_variation->degrees() == Approx(-15.3));
    CHECK(round_trip<standard::rmc>(sealed(base + "15.3,W,A")) == sealed(base + "15.3,W,A"));
    CHECK(nmea::decode<standard::rmc>(sealed(base + "180.0,E,A")));
  }
  SECTION("999.9,E (\"unknown\" on some receivers): the fix is kept, the variation is not") {
    for (const std::string v : {"999.9,E", "180.1,W", "360,E"}) {
      INFO(v);
      const auto r = nmea::decode<standard::rmc>(sealed(base + v + ",A"));
      REQUIRE(r);
      REQUIRE(r.value.lat);
      CHECK(r.value.speed_knots == decimal::parse("0.145").value);
      REQUIRE(r.value.magnetic_variation);
      CHECK_FALSE(r.value.magnetic_variation->value);
      CHECK_FALSE(r.value.magnetic_variation->degrees());
      // Written back as the letter alone: "no value" is what the sender meant.
      const std::string letter = v.substr(v.size() - 1);
      CHECK(round_trip<standard::rmc>(sealed(base + v + ",A")) ==
            sealed(base + "," + letter + ",A"));
    }
  }
  SECTION("a letter without a value is kept as it came") {
    const auto r = nmea::decode<standard::rmc>(sealed(base + ",E,A"));
    REQUIRE(r);
    REQUIRE(r.value.magnetic_variation);
    CHECK_FALSE(r.value.magnetic_variation->value);
    CHECK(r.value.magnetic_variation->direction == nmea::hemisphere::east);
    CHECK(round_trip<standard::rmc>(sealed(base + ",E,A")) == sealed(base + ",E,A"));
  }
  SECTION("both blank, or a value with no letter: no variation") {
    for (const std::string v : {",", "15.3,"}) {
      INFO(v);
      const auto r = nmea::decode<standard::rmc>(sealed(base + v + ",A"));
      REQUIRE(r);
      CHECK_FALSE(r.value.magnetic_variation);
      CHECK(round_trip<standard::rmc>(sealed(base + v + ",A")) == sealed(base + ",,A"));
    }
  }
  SECTION("the letter left out and the mode in its place (11 fields, SiRF and Saab receivers)") {
    const std::string sirf =
        "$GPRMC,212614.879,A,4839.9488,N,00214.8863,E,0.56,344.41,181207,0,A*77\r\n";
    const auto r = nmea::decode<standard::rmc>(sirf);
    REQUIRE(r);
    CHECK_FALSE(r.value.magnetic_variation);
    CHECK(r.value.mode == standard::mode_indicator::autonomous);
    REQUIRE(r.value.course_true);
    CHECK(*r.value.course_true == decimal::parse("344.41").value);
    CHECK(round_trip<standard::rmc>(sirf) ==
          "$GPRMC,212614.879,A,4839.9488,N,00214.8863,E,0.56,344.41,181207,,,A*6B\r\n");
    const auto saab = nmea::decode<standard::rmc>(
        "$GPRMC,130711.00,A,5012.790800,N,00806.879600,W,0.5,3.0,010611,,A*6A\r\n");
    REQUIRE(saab);
    CHECK_FALSE(saab.value.magnetic_variation);
    CHECK(saab.value.mode == standard::mode_indicator::autonomous);
    const auto no_fix = nmea::decode<standard::rmc>(sealed(base + "0,N"));
    REQUIRE(no_fix);
    CHECK(no_fix.value.mode == standard::mode_indicator::not_valid);
    // Only as the last field: with 12 fields the 11th is the letter, and 'A' is no letter.
    CHECK(nmea::decode<standard::rmc>(sealed(base + "0,A,A")).ec == errc::bad_variation_direction);
    // 'E' is a direction before it is a mode ("estimated"): the standard form wins.
    const auto e = nmea::decode<standard::rmc>(sealed(base + ",E"));
    REQUIRE(e);
    REQUIRE(e.value.magnetic_variation);
    CHECK(e.value.magnetic_variation->direction == nmea::hemisphere::east);
    CHECK_FALSE(e.value.mode);
  }
  SECTION("corrupt: a malformed number or a letter other than E/W") {
    struct row {
      std::string v;
      errc ec;
      unsigned field;
    };
    for (const row& r :
         {row{"1.2.3,E", errc::bad_variation, 10}, row{"-3.1,E", errc::bad_variation, 10},
          row{"+3.1,E", errc::bad_variation, 10}, row{"abc,W", errc::bad_variation, 10},
          row{"3.1,N", errc::bad_variation_direction, 11},
          row{",X", errc::bad_variation_direction, 11},
          row{"3.1,EW", errc::bad_variation_direction, 11}}) {
      INFO(r.v);
      const auto d = nmea::decode<standard::rmc>(sealed(base + r.v + ",A"));
      CHECK(d.ec == r.ec);
      CHECK(d.field == r.field);
      CHECK(nmea::field_name<standard::rmc>(d.field) == "magnetic_variation");
    }
  }
  SECTION("only 0..180 with E or W is written") {
    standard::rmc m;
    m.magnetic_variation = nmea::magnetic_variation{decimal::parse("180.5").value};
    CHECK(nmea::encode(m).ec == errc::variation_out_of_range);
    m.magnetic_variation =
        nmea::magnetic_variation{decimal::parse("12.5").value, nmea::hemisphere::north};
    CHECK(nmea::encode(m).ec == errc::bad_variation_direction);
    m.magnetic_variation = nmea::magnetic_variation{-decimal::parse("12.5").value};
    CHECK(nmea::encode(m).ec == errc::variation_out_of_range);
    CHECK(nmea::magnetic_variation::from_degrees(180.01, 2).ec == errc::variation_out_of_range);
    const auto v = nmea::magnetic_variation::from_degrees(-14.24, 1);
    REQUIRE(v);
    m.magnetic_variation = v.value;
    const auto out = nmea::encode(m);
    REQUIRE(out);
    CHECK(out.view().find(",14.2,W") != std::string_view::npos);
  }
}

TEST_CASE("without a checksum, a sentence must reach its shortest form") {
  // A line cut off mid-write, as the last line of a log often is.
  const std::string_view cut = "$GNRMC,001053.00,A,4404.14083,N,12118.85886,W,0.\r\n";
  const auto r = nmea::decode<standard::rmc>(cut);
  CHECK(r.ec == errc::too_few_fields);
  CHECK(r.field == 8);  // the first field missing: course_true
  CHECK(nmea::field_name<standard::rmc>(r.field) == "course_true");

  // With a checksum the sender says it stopped there: absent fields read as blank.
  const auto vouched =
      nmea::decode<standard::rmc>(sealed("GNRMC,001053.00,A,4404.14083,N,12118.85886,W,0."));
  REQUIRE(vouched);
  CHECK_FALSE(vouched.value.course_true);
  CHECK_FALSE(vouched.value.date);

  // Fields a sender may leave out (RMC 12 and 13) may still be missing without a checksum.
  const auto v22 = nmea::decode<standard::rmc>(
      "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,\r\n");
  REQUIRE(v22);
  CHECK_FALSE(v22.value.mode);

  // The same rule in every family and through message sets.
  using set = nmea::message_set<standard::rmc, standard::gga, standard::vhw>;
  CHECK(set::decode("$GPGGA,105027.80,5612.9956,N,00306.6983,W,1,03\r\n").ec ==
        errc::too_few_fields);
  CHECK(set::decode(sealed("GPGGA,105027.80,5612.9956,N,00306.6983,W,1,03")).ok());
  CHECK(sandshark::decode_to_vehicle("$BPRMB,081025.987,90.0,5.0,0\r\n").ec ==
        errc::too_few_fields);
  CHECK(kingfisher::decode_to_vehicle("$PYDIR,12.5\r\n").ec == errc::too_few_fields);

  // Under checksum_policy::ignore, a wrong checksum vouches for nothing either.
  nmea::parse_policy ignore;
  ignore.checksum = nmea::checksum_policy::ignore;
  CHECK(
      nmea::decode<standard::rmc>("$GNRMC,001053.00,A,4404.14083,N,12118.85886,W,0.*00\r\n", ignore)
          .ec == errc::too_few_fields);
}
