// SPDX-License-Identifier: BSL-1.0
// RMC and GGA: real receiver output, every NMEA version's form, blanks, bad input.

#include <catch2/catch.hpp>
#include <random>
#include <string>

#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/rmc.hpp"

#include "support.hpp"

using namespace seawire;
using namespace seawire::nmea;
using standard::gga;
using standard::rmc;

namespace {

using namespace support;
// From a real Kingfisher vehicle (2014), relayed from its GPS receiver.
constexpr std::string_view kRmc =
    "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70\r\n";
constexpr std::string_view kGga =
    "$GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,M,-33.2,M,,*5C\r\n";

}  // namespace

// decode -> encode is the identity on canonical input, at compile time.
static_assert(encode(decode<rmc>(kRmc).value).view() == kRmc);
static_assert(encode(decode<gga>(kGga).value).view() == kGga);

TEST_CASE("RMC from a real receiver") {
  const auto r = decode<rmc>(kRmc);
  REQUIRE(r);
  const rmc& m = r.value;
  CHECK(m.talker == "GP");
  REQUIRE(m.time);
  CHECK((m.time->hour == 16 && m.time->minute == 49 && m.time->second == 59));
  CHECK((m.time->fraction == 0 && m.time->places == 2));
  CHECK(m.status == standard::rmc_status::active);
  REQUIRE(m.lat);
  CHECK(m.lat->degrees() == Approx(42.0 + 21.71114 / 60.0).epsilon(1e-12));
  REQUIRE(m.lon);
  CHECK(m.lon->degrees() == Approx(-(71.0 + 5.44878 / 60.0)).epsilon(1e-12));
  CHECK(*m.speed_knots == decimal::scaled(145, 3));
  CHECK(*m.course_true == decimal::scaled(15678, 2));
  CHECK((m.date->day == 31 && m.date->month == 12 && m.date->year == 2014));
  CHECK_FALSE(m.magnetic_variation);
  CHECK(m.mode == standard::mode_indicator::autonomous);
  CHECK_FALSE(m.navigational_status);
  CHECK(encode(m).view() == kRmc);
}

TEST_CASE("RMC in the forms of NMEA 2.2, 2.3 and 4.1, from any talker") {
  const std::string forms[] = {
      sealed("GPRMC,081836,A,3751.65,S,14507.36,E,000.0,360.0,130998,011.3,E"),  // 11 fields
      sealed("GNRMC,092750.000,A,5321.6802,N,00630.3372,W,0.02,31.66,280511,,,A"),
      sealed("INRMC,235959.99,V,,,,,,,010180,,,N"),
      sealed("GNRMC,120000.00,A,0000.0000,S,00000.0000,W,0.00,0.00,290224,3.1,W,D,S"),
      sealed("GPRMC,,V,,,,,,,,,,N"),
      // Blank mode (2.3) and blank navigational status (4.1): written back blank, not left out.
      sealed("GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,"),
      sealed("GNRMC,120000.00,A,0000.0000,S,00000.0000,W,0.00,0.00,290224,3.1,W,D,"),
      sealed("GNRMC,120000.00,V,,,,,,,290224,,,,"),
  };
  for (const auto& line : forms) {
    INFO(line);
    const auto r = decode<rmc>(line);
    REQUIRE(r);
    CHECK(encode(r.value).view() == line);
  }
  const auto v22 = decode<rmc>(forms[0]).value;
  CHECK(v22.talker == "GP");
  CHECK_FALSE(v22.mode);
  CHECK(*v22.magnetic_variation->degrees() == Approx(11.3));
  CHECK(v22.lat->degrees() == Approx(-(37 + 51.65 / 60)));
  CHECK((v22.date->year == 1998 && v22.date->month == 9 && v22.date->day == 13));

  const auto v41 = decode<rmc>(forms[3]).value;
  CHECK(v41.talker == "GN");
  CHECK(*v41.magnetic_variation->degrees() == Approx(-3.1));
  CHECK(v41.mode == standard::mode_indicator::differential);
  CHECK(v41.navigational_status == standard::nav_status::safe);

  const auto nofix = decode<rmc>(forms[4]).value;
  CHECK(nofix.status == standard::rmc_status::warning);
  CHECK_FALSE(nofix.time);
  CHECK_FALSE(nofix.lat);
  CHECK_FALSE(nofix.date);
  CHECK(nofix.mode == standard::mode_indicator::not_valid);

  // What decode keeps of a blank tail: the sentence's field count, when a value does not
  // need it anyway.
  CHECK(v22.wire_fields == 0);
  CHECK(v41.wire_fields == 0);
  CHECK(decode<rmc>(forms[5]).value.wire_fields == 12);
  CHECK(decode<rmc>(forms[6]).value.wire_fields == 13);
  CHECK(decode<rmc>(forms[7]).value.wire_fields == 13);
  CHECK(decode<rmc>(sealed("GNRMC,120000.00,A,,,,,,,290224,,,,S")).value.wire_fields == 0);
  // Built in code, no mode: the 11-field form.
  rmc built = decode<rmc>(forms[5]).value;
  built.wire_fields = 0;
  CHECK(encode(built).view() == sealed("GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,"
                                       "311214,,"));
  // A mode set later is written, and the fields wire_fields asks for after it.
  built.mode = standard::mode_indicator::autonomous;
  built.wire_fields = 13;
  CHECK(encode(built).view() == sealed("GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,"
                                       "311214,,,A,"));
}

TEST_CASE("GGA from a real receiver") {
  const auto r = decode<gga>(kGga);
  REQUIRE(r);
  const gga& m = r.value;
  CHECK(m.talker == "GP");
  CHECK(m.quality == standard::gps_quality::gps);
  CHECK(*m.satellites == 6);
  CHECK(*m.hdop == decimal::scaled(280, 2));
  CHECK(*m.altitude_m == decimal::scaled(466, 1));
  CHECK(*m.geoid_separation_m == decimal::scaled(-332, 1));
  CHECK_FALSE(m.dgps_age_s);
  CHECK_FALSE(m.dgps_station);
  CHECK(m.lat->degrees() == Approx(42.3618523333));
  CHECK(encode(m).view() == kGga);

  const std::string dgps =
      sealed("GNGGA,001043.00,4404.14036,N,12118.85961,W,2,12,0.98,1113.0,M,-21.3,M,1.2,0042");
  const auto d = decode<gga>(dgps);
  REQUIRE(d);
  CHECK(d.value.quality == standard::gps_quality::dgps);
  CHECK(*d.value.dgps_age_s == decimal::scaled(12, 1));
  CHECK(*d.value.dgps_station == 42);
  CHECK(encode(d.value).view() == dgps);

  const std::string nofix = sealed("GPGGA,,,,,,0,,,,M,,M,,");
  const auto n = decode<gga>(nofix);
  REQUIRE(n);
  CHECK(n.value.quality == standard::gps_quality::invalid);
  CHECK_FALSE(n.value.altitude_m);
  CHECK(encode(n.value).view() == nofix);
}

TEST_CASE("RMC and GGA malformed input: errc and field number") {
  struct row {
    std::string body;
    errc expected;
    std::uint16_t field;
  };
  const row rmc_rows[] = {
      {"GPRMC,164959.00,X,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A", errc::bad_enum, 2},
      {"GPRMC,164959.00,,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A", errc::missing_field,
       2},
      {"GPRMC,164999.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A",
       errc::second_out_of_range, 1},
      {"GPRMC,164959.00,A,4271.71114,N,07105.44878,W,0.145,156.78,311214,,,A",
       errc::minute_out_of_range, 3},
      {"GPRMC,164959.00,A,4221.71114,X,07105.44878,W,0.145,156.78,311214,,,A", errc::bad_hemisphere,
       4},
      {"GPRMC,164959.00,A,4221.71114,N,07105.44878,N,0.145,156.78,311214,,,A", errc::bad_hemisphere,
       6},
      {"GPRMC,164959.00,A,4221.71114,N,07105.44878,W,-0.145,156.78,311214,,,A", errc::out_of_range,
       7},
      {"GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.1.45,156.78,311214,,,A", errc::bad_number,
       7},
      {"GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,361,311214,,,A", errc::out_of_range, 8},
      {"GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311314,,,A",
       errc::month_out_of_range, 9},
      {"GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,321214,,,A",
       errc::day_out_of_range, 9},
      {"GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,3.1,N,A",
       errc::bad_variation_direction, 11},
      {"GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,-3.1,E,A",
       errc::bad_variation, 10},
      {"GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,3..1,E,A",
       errc::bad_variation, 10},
      {"GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,Z", errc::bad_enum, 12},
      {"GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A,X", errc::bad_enum,
       13},
      {"GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78", errc::ok, 0},
      {"GPRMC,164959.00", errc::too_few_fields, 2},
  };
  for (const auto& r : rmc_rows) {
    const std::string line = sealed(r.body);
    INFO(line);
    const auto d = decode<rmc>(line);
    CHECK(d.ec == r.expected);
    CHECK(d.field == r.field);
  }
  const row gga_rows[] = {
      {"GPGGA,164959.00,4221.71114,N,07105.44878,W,9,06,2.80,46.6,M,-33.2,M,,", errc::bad_enum, 6},
      {"GPGGA,164959.00,4221.71114,N,07105.44878,W,1,-6,2.80,46.6,M,-33.2,M,,", errc::out_of_range,
       7},
      {"GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,F,-33.2,M,,", errc::bad_unit, 10},
      {"GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,M,-33.2,M,,1024",
       errc::out_of_range, 14},
      {"GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6", errc::too_few_fields, 10},
  };
  for (const auto& r : gga_rows) {
    const std::string line = sealed(r.body);
    INFO(line);
    const auto d = decode<gga>(line);
    CHECK(d.ec == r.expected);
    CHECK(d.field == r.field);
  }
}

TEST_CASE("RMC/GGA round trip over generated values") {
  std::mt19937_64 rng(42);
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng() >> 11) / static_cast<double>(1ull << 53);
  };
  for (int i = 0; i < 3000; ++i) {
    rmc r;
    r.talker = (i % 2) ? talker_id("GN") : talker_id("GP");
    r.time = time_of_day::from_since_midnight(std::chrono::milliseconds(rng() % 86'400'000),
                                              static_cast<unsigned>(rng() % 4))
                 .value;
    r.status = (i % 3) ? standard::rmc_status::active : standard::rmc_status::warning;
    r.lat = latitude::from_degrees(uniform(-90, 90), static_cast<unsigned>(1 + rng() % 6)).value;
    r.lon = longitude::from_degrees(uniform(-180, 180), static_cast<unsigned>(1 + rng() % 6)).value;
    r.speed_knots = decimal::from_double(uniform(0, 50), 3).value;
    r.course_true = decimal::from_double(uniform(0, 359.99), 2).value;
    r.date = nmea::date{static_cast<std::uint16_t>(1980 + rng() % 100),
                        static_cast<std::uint8_t>(1 + rng() % 12),
                        static_cast<std::uint8_t>(1 + rng() % 28)};
    if (i % 4 == 0)
      r.magnetic_variation = nmea::magnetic_variation::from_degrees(uniform(-30, 30), 1).value;
    if (i % 5 != 0) r.mode = standard::mode_indicator::differential;
    if (i % 5 > 2) r.navigational_status = standard::nav_status::caution;
    const auto e = encode(r);
    REQUIRE(e);
    const auto d = decode<rmc>(e.view(), parse_policy::strict());
    INFO(e.view());
    REQUIRE(d);
    CHECK(encode(d.value).view() == e.view());
    CHECK(d.value.lat == r.lat);
    CHECK(d.value.lon == r.lon);
    CHECK(d.value.date == r.date);
    CHECK(d.value.mode == r.mode);

    gga g;
    g.talker = r.talker;
    g.time = r.time;
    g.lat = r.lat;
    g.lon = r.lon;
    g.quality = standard::gps_quality::rtk;
    g.satellites = static_cast<std::uint8_t>(rng() % 40);
    g.hdop = decimal::from_double(uniform(0, 20), 2).value;
    g.altitude_m = decimal::from_double(uniform(-100, 9000), 1).value;
    g.geoid_separation_m = decimal::from_double(uniform(-100, 100), 1).value;
    const auto ge = encode(g);
    REQUIRE(ge);
    const auto gd = decode<gga>(ge.view(), parse_policy::strict());
    REQUIRE(gd);
    CHECK(encode(gd.value).view() == ge.view());
    CHECK(gd.value.satellites == g.satellites);
  }
}

TEST_CASE("a standard set dispatches any talker") {
  using set = message_set<rmc, gga>;
  for (std::string_view t : {"GP", "GN", "GL", "GA", "BD", "IN", "II"}) {
    const std::string line = sealed(std::string(t) + "GGA,,,,,,0,,,,M,,M,,");
    const auto r = set::decode(line);
    REQUIRE(r);
    REQUIRE(std::holds_alternative<gga>(r.value));
    CHECK(std::get<gga>(r.value).talker == t);
  }
  // Not a talker + RMC: seven characters.
  const std::string odd = sealed("GPXRMC,,V,,,,,,,,,,N");
  CHECK(std::holds_alternative<unknown_sentence>(set::decode(odd).value));
}
