// SPDX-License-Identifier: BSL-1.0
#include "seawire/kingfisher/messages.hpp"
#include "seawire/sandshark/messages.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

#include "support.hpp"

namespace {

using namespace support;

namespace kf = seawire::kingfisher;
namespace nmea = seawire::nmea;
using nmea::decimal;
using nmea::time_of_day;
using seawire::errc;

// --------------------------------------------------------------------------------------------
// helpers

// Field-by-field equality through the message description, for messages without == (the
// relayed RMC and GGA).
template <class T>
constexpr bool same_fields(const T& a, const T& b) {
  return T::nmea.fields.apply(
      [&](const auto&... d) { return ((a.*(d.member) == b.*(d.member)) && ...); });
}

template <class T>
constexpr bool reencodes(std::string_view line, const nmea::parse_policy& p) {
  const auto d = nmea::decode<T>(line, p);
  return d && nmea::encode(d.value).view() == line;
}
template <class T>
constexpr bool from_vehicle_reencodes(std::string_view line) {
  return reencodes<T>(line, kf::payload_policy());
}
template <class T>
constexpr bool to_vehicle_reencodes(std::string_view line) {
  return reencodes<T>(line, kf::vehicle_policy());
}

constexpr time_of_day hms(int h, int m, int s, std::uint32_t fraction, int places) {
  return {static_cast<std::uint8_t>(h), static_cast<std::uint8_t>(m), static_cast<std::uint8_t>(s),
          fraction, static_cast<std::uint8_t>(places)};
}

// Canonical vectors (verified vectors, plus CPALT/PYCLT with recomputed sums).
constexpr std::string_view real_cpimu =
    "$CPIMU,164958.858,-0.061035,-0.000097,-0.061035,-0.026916,0.104533,-0.932172*57\r\n";
constexpr std::string_view real_gprmc =
    "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70\r\n";
constexpr std::string_view real_gpgga =
    "$GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,M,-33.2,M,,*5C\r\n";
constexpr std::string_view real_cpnvg =
    "$CPNVG,164959.034,4221.711142,N,7105.44878,W,1,0,0,234.32964,-6.796959,-1.706798,"
    "164959.006*78\r\n";
constexpr std::string_view real_cpnvr =
    "$CPNVR,164959.063,0.02941,-0.068552,0,0.060938,0,-0.061132*59\r\n";
constexpr std::string_view real_cprcm =
    "$CPRCM,164959.065,0,234.326694,-1.655603,-6.628557,164959.060*62\r\n";
constexpr std::string_view real_cprbs = "$CPRBS,172909.322,15.121597,15.121597,15.121597,0*76\r\n";
constexpr std::string_view sim_cpnvg =
    "$CPNVG,105707.24,0000.00,N,00000.00,W,1,,,0,,,105707.24*64\r\n";
constexpr std::string_view sim_cprbs = "$CPRBS,105707.24,1,15.2,15.1,15.3,0*67\r\n";
constexpr std::string_view cpalt_on = "$CPALT,164959.100,1*62\r\n";
constexpr std::string_view pydir_stop = "$PYDIR,0,0*56\r\n";
constexpr std::string_view pydir_45_55 = "$PYDIR,45,55*57\r\n";
constexpr std::string_view pydev_90 = "$PYDEV,90,1.5*7D\r\n";
constexpr std::string_view pydep_vec = "$PYDEP,-10,50*71\r\n";
constexpr std::string_view pyclt_on = "$PYCLT,1*4F\r\n";
constexpr std::string_view pyclt_off = "$PYCLT,0*4E\r\n";

// Every canonical vector decodes and re-encodes byte for byte, at compile time.
static_assert(from_vehicle_reencodes<kf::cpimu>(real_cpimu));
static_assert(from_vehicle_reencodes<seawire::standard::rmc>(real_gprmc));
static_assert(from_vehicle_reencodes<seawire::standard::gga>(real_gpgga));
static_assert(from_vehicle_reencodes<kf::cpnvg>(real_cpnvg));
static_assert(from_vehicle_reencodes<kf::cpnvr>(real_cpnvr));
static_assert(from_vehicle_reencodes<kf::cprcm>(real_cprcm));
static_assert(from_vehicle_reencodes<kf::cprbs>(real_cprbs));
static_assert(from_vehicle_reencodes<kf::cpnvg>(sim_cpnvg));
static_assert(from_vehicle_reencodes<kf::cprbs>(sim_cprbs));
static_assert(from_vehicle_reencodes<kf::cpalt>(cpalt_on));
static_assert(to_vehicle_reencodes<kf::pydir>(pydir_stop));
static_assert(to_vehicle_reencodes<kf::pydir>(pydir_45_55));
static_assert(to_vehicle_reencodes<kf::pydev>(pydev_90));
static_assert(to_vehicle_reencodes<kf::pydep>(pydep_vec));
static_assert(to_vehicle_reencodes<kf::pyclt>(pyclt_on));
static_assert(to_vehicle_reencodes<kf::pyclt>(pyclt_off));
// The spec's CPNVG example carries the checksum of its BFNVG original.
static_assert(nmea::decode<kf::cpnvg>("$CPNVG,081025.987,4221.81092,N,07106.84603,W,1,,,203.1,"
                                      "-3.4,4.5,081025.980*5B\r\n",
                                      kf::payload_policy())
                  .ec == errc::checksum_mismatch);
// Commands built in code encode to the vectors.
static_assert(nmea::encode(kf::pydir{45, 55}).view() == pydir_45_55);
static_assert(nmea::encode(kf::pydev{90, decimal::scaled(15, 1)}).view() == pydev_90);
static_assert(nmea::encode(kf::pydep{-10, 50}).view() == pydep_vec);
static_assert(nmea::encode(kf::pyclt{true}).view() == pyclt_on);
// Decoding gives back the message that was encoded, compared whole.
static_assert(nmea::decode<kf::pydir>(pydir_45_55).value == kf::pydir{45, 55});
static_assert(nmea::decode<kf::pydev>(pydev_90).value == kf::pydev{90, decimal::scaled(15, 1)});
static_assert(nmea::decode<kf::pyclt>(pyclt_off).value == kf::pyclt{false});
static_assert(nmea::decode<kf::cpnvg>(sim_cpnvg).value !=
              nmea::decode<kf::cpnvg>(real_cpnvg).value);

template <class T, class V>
const T& holds(const V& v) {
  const T* p = std::get_if<T>(&v);
  REQUIRE(p != nullptr);
  return *p;
}

// --------------------------------------------------------------------------------------------
// vectors

TEST_CASE("real vehicle capture decodes with the payload role and re-encodes byte for byte") {
  SECTION("CPIMU, seven fields, no nav timestamp") {
    const auto r = kf::decode_from_vehicle(real_cpimu);
    REQUIRE(r);
    const auto& m = holds<kf::cpimu>(r.value);
    CHECK(m.timestamp == hms(16, 49, 58, 858, 3));
    CHECK(m.rate_x_dps->to_double() == -0.061035);
    CHECK(m.rate_y_dps->to_double() == -0.000097);
    CHECK(m.rate_z_dps->to_double() == -0.061035);
    CHECK(m.accel_x_mps2->to_double() == -0.026916);
    CHECK(m.accel_y_mps2->to_double() == 0.104533);
    CHECK(m.accel_z_mps2->to_double() == -0.932172);
    CHECK_FALSE(m.nav_timestamp.has_value());
    CHECK(m.effective_nav_timestamp() == m.timestamp);
    CHECK(nmea::encode(m).view() == real_cpimu);
  }
  SECTION("CPNVG with unpadded longitude degrees") {
    const auto r = kf::decode_from_vehicle(real_cpnvg);
    REQUIRE(r);
    const auto& m = holds<kf::cpnvg>(r.value);
    CHECK(m.timestamp == hms(16, 49, 59, 34, 3));
    CHECK(m.lat.degrees() == Approx(42.36185236666667).margin(1e-12));
    CHECK(m.lon.degrees() == Approx(-71.0908130).margin(1e-12));
    CHECK(m.lon.whole_degrees == 71);
    CHECK(m.lon.degree_digits == 2);  // written back unpadded
    CHECK(m.gps);
    REQUIRE(m.altitude_m);
    CHECK(m.altitude_m->is_zero());
    REQUIRE(m.depth_m);
    CHECK(m.depth_m->is_zero());
    REQUIRE(m.heading_deg);
    CHECK(m.heading_deg->to_double() == 234.32964);
    REQUIRE(m.roll_deg);
    CHECK(m.roll_deg->to_double() == -6.796959);
    REQUIRE(m.pitch_deg);
    CHECK(m.pitch_deg->to_double() == -1.706798);
    REQUIRE(m.nav_timestamp);
    CHECK(*m.nav_timestamp == hms(16, 49, 59, 6, 3));
    CHECK(m.effective_nav_timestamp() == hms(16, 49, 59, 6, 3));
    CHECK(nmea::encode(m).view() == real_cpnvg);
  }
  SECTION("CPNVR") {
    const auto r = kf::decode_from_vehicle(real_cpnvr);
    REQUIRE(r);
    const auto& m = holds<kf::cpnvr>(r.value);
    CHECK(m.timestamp == hms(16, 49, 59, 63, 3));
    CHECK(m.vel_east_mps.value().to_double() == 0.02941);
    CHECK(m.vel_north_mps.value().to_double() == -0.068552);
    CHECK(m.vel_down_mps.value().is_zero());
    CHECK(m.pitch_rate_dps.value().to_double() == 0.060938);
    CHECK(m.roll_rate_dps.value().is_zero());
    CHECK(m.yaw_rate_dps.value().to_double() == -0.061132);
    CHECK(nmea::encode(m).view() == real_cpnvr);
  }
  SECTION("CPRCM with compass id 0") {
    const auto r = kf::decode_from_vehicle(real_cprcm);
    REQUIRE(r);
    const auto& m = holds<kf::cprcm>(r.value);
    CHECK(m.timestamp == hms(16, 49, 59, 65, 3));
    CHECK(m.compass_id == 0);
    CHECK(m.heading_deg->to_double() == 234.326694);
    CHECK(m.pitch_deg->to_double() == -1.655603);
    CHECK(m.roll_deg->to_double() == -6.628557);
    CHECK(m.nav_timestamp == hms(16, 49, 59, 60, 3));
    CHECK(m.effective_nav_timestamp() == hms(16, 49, 59, 60, 3));
    CHECK(nmea::encode(m).view() == real_cprcm);
  }
  SECTION("CPRBS without the battery id (five fields)") {
    const auto r = kf::decode_from_vehicle(real_cprbs);
    REQUIRE(r);
    const auto& m = holds<kf::cprbs>(r.value);
    CHECK(m.timestamp == hms(17, 29, 9, 322, 3));
    CHECK_FALSE(m.battery_id.has_value());
    CHECK(m.stack_voltage_v->to_double() == 15.121597);
    CHECK(m.min_cell_voltage_v->to_double() == 15.121597);
    CHECK(m.max_cell_voltage_v->to_double() == 15.121597);
    CHECK(m.temperature_c->is_zero());
    CHECK(nmea::encode(m).view() == real_cprbs);
  }
  SECTION("relayed GPRMC and GPGGA") {
    const auto rmc = kf::decode_from_vehicle(real_gprmc);
    REQUIRE(rmc);
    const auto& m = holds<seawire::standard::rmc>(rmc.value);
    CHECK(m.lat.value().degrees() == Approx(42.36185233333333).margin(1e-12));
    CHECK(m.lon.value().degrees() == Approx(-71.0908130).margin(1e-12));
    CHECK(nmea::encode(m).view() == real_gprmc);

    const auto gga = kf::decode_from_vehicle(real_gpgga);
    REQUIRE(gga);
    const auto& g = holds<seawire::standard::gga>(gga.value);
    CHECK(g.satellites == std::uint8_t{6});
    CHECK(nmea::encode(g).view() == real_gpgga);
  }
}

TEST_CASE("simulator and payload driver vectors") {
  SECTION("CPNVG at 0,0 with blank altitude, depth, roll and pitch") {
    const auto r = kf::decode_from_vehicle(sim_cpnvg);
    REQUIRE(r);
    const auto& m = holds<kf::cpnvg>(r.value);
    CHECK(m.timestamp == hms(10, 57, 7, 24, 2));
    CHECK(m.lat.degrees() == 0.0);
    CHECK(std::signbit(m.lon.degrees()));  // "W" at 0.0: the sign comes from the letter
    CHECK(m.lat.degree_digits == 2);
    CHECK(m.lon.degree_digits == 3);
    CHECK(m.gps);
    CHECK_FALSE(m.altitude_m.has_value());
    CHECK_FALSE(m.depth_m.has_value());
    CHECK(m.heading_deg == decimal(0));
    CHECK_FALSE(m.roll_deg.has_value());
    CHECK_FALSE(m.pitch_deg.has_value());
    CHECK(m.nav_timestamp == hms(10, 57, 7, 24, 2));
    CHECK(nmea::encode(m).view() == sim_cpnvg);
  }
  SECTION("CPRBS with the battery id (six fields)") {
    const auto r = kf::decode_from_vehicle(sim_cprbs);
    REQUIRE(r);
    const auto& m = holds<kf::cprbs>(r.value);
    CHECK(m.battery_id == std::uint16_t{1});
    CHECK(m.stack_voltage_v == decimal::scaled(152, 1));
    CHECK(m.min_cell_voltage_v == decimal::scaled(151, 1));
    CHECK(m.max_cell_voltage_v == decimal::scaled(153, 1));
    CHECK(m.temperature_c == decimal(0));
    CHECK(nmea::encode(m).view() == sim_cprbs);
  }
  SECTION("the spec's CPNVG example is rejected for its checksum; *58 is right") {
    const std::string_view seed =
        "$CPNVG,081025.987,4221.81092,N,07106.84603,W,1,,,203.1,-3.4,4.5,081025.980*5B\r\n";
    const auto bad = kf::decode_from_vehicle(seed);
    CHECK(bad.ec == errc::checksum_mismatch);
    const auto good = kf::decode_from_vehicle(
        "$CPNVG,081025.987,4221.81092,N,07106.84603,W,1,,,203.1,-3.4,4.5,081025.980*58\r\n");
    REQUIRE(good);
    const auto& m = holds<kf::cpnvg>(good.value);
    CHECK(m.lon.degrees() == Approx(-71.1141005).margin(1e-12));
    CHECK(m.heading_deg == decimal::scaled(2031, 1));
    CHECK(m.roll_deg == decimal::scaled(-34, 1));
    CHECK(m.pitch_deg == decimal::scaled(45, 1));
    CHECK_FALSE(m.altitude_m.has_value());
  }
  SECTION("CPALT lights state") {
    const auto r = kf::decode_from_vehicle(cpalt_on);
    REQUIRE(r);
    const auto& m = holds<kf::cpalt>(r.value);
    CHECK(m.timestamp == hms(16, 49, 59, 100, 3));
    CHECK(m.lights_on);
    const auto off = kf::decode_from_vehicle("$CPALT,164959.100,0*63\r\n");
    REQUIRE(off);
    CHECK_FALSE(holds<kf::cpalt>(off.value).lights_on);
  }
  SECTION("PY* commands with the vehicle role") {
    const auto dir = kf::decode_to_vehicle(pydir_45_55);
    REQUIRE(dir);
    CHECK(holds<kf::pydir>(dir.value).thrust_left == decimal(45));
    CHECK(holds<kf::pydir>(dir.value).thrust_right == decimal(55));
    const auto stop = kf::decode_to_vehicle(pydir_stop);
    REQUIRE(stop);
    CHECK(holds<kf::pydir>(stop.value).thrust_left.is_zero());
    const auto dev = kf::decode_to_vehicle(pydev_90);
    REQUIRE(dev);
    CHECK(holds<kf::pydev>(dev.value).heading_deg == decimal(90));
    CHECK(holds<kf::pydev>(dev.value).speed_mps.to_double() == 1.5);
    const auto dep = kf::decode_to_vehicle(pydep_vec);
    REQUIRE(dep);
    CHECK(holds<kf::pydep>(dep.value).yaw_rate == decimal(-10));
    CHECK(holds<kf::pydep>(dep.value).thrust == decimal(50));
    const auto clt = kf::decode_to_vehicle(pyclt_on);
    REQUIRE(clt);
    CHECK(holds<kf::pyclt>(clt.value).lights_on);
    const auto clt_off = kf::decode_to_vehicle(pyclt_off);
    REQUIRE(clt_off);
    CHECK_FALSE(holds<kf::pyclt>(clt_off.value).lights_on);
  }
}

TEST_CASE("optional and variant forms") {
  SECTION("CPIMU with the eighth field, the nav timestamp") {
    const std::string line = sealed(
        "CPIMU,164958.858,-0.061035,-0.000097,-0.061035,-0.026916,0.104533,-0.932172,164958.850");
    const auto r = kf::decode_from_vehicle(line);
    REQUIRE(r);
    const auto& m = holds<kf::cpimu>(r.value);
    CHECK(m.nav_timestamp == hms(16, 49, 58, 850, 3));
    CHECK(m.effective_nav_timestamp() == hms(16, 49, 58, 850, 3));
    CHECK(nmea::encode(m).view() == line);
  }
  SECTION("CPIMU with a blank eighth field reads as no nav timestamp, and is written back so") {
    const std::string line =
        sealed("CPIMU,164958.858,-0.061035,-0.000097,-0.061035,-0.026916,0.104533,-0.932172,");
    const auto r = kf::decode_from_vehicle(line);
    REQUIRE(r);
    auto m = holds<kf::cpimu>(r.value);
    CHECK_FALSE(m.nav_timestamp.has_value());
    CHECK(m.effective_nav_timestamp() == hms(16, 49, 58, 858, 3));
    CHECK(m.wire_fields == 8);
    CHECK(nmea::encode(m).view() == line);  // the spec's eight-field form, as it came
    // The same values without the remembered blank: the real vehicle's seven-field form.
    m.wire_fields = 0;
    CHECK(nmea::encode(m).view() == real_cpimu);
    // A value for the eighth field is written whatever wire_fields says.
    m.nav_timestamp = hms(16, 49, 58, 850, 3);
    m.wire_fields = 7;
    CHECK(nmea::encode(m).view() ==
          sealed("CPIMU,164958.858,-0.061035,-0.000097,-0.061035,-0.026916,0.104533,-0.932172,"
                 "164958.850"));
    // The seven-field form decodes with nothing to keep.
    const auto seven = kf::decode_from_vehicle(real_cpimu);
    REQUIRE(seven);
    CHECK(holds<kf::cpimu>(seven.value).wire_fields == 0);
    // Nor does the eight-field form with a value there.
    const auto eight = kf::decode_from_vehicle(nmea::encode(m).view());
    REQUIRE(eight);
    CHECK(holds<kf::cpimu>(eight.value).wire_fields == 0);
  }
  SECTION("CPRBS in the six-field form with a blank battery id keeps its six fields") {
    const std::string line = sealed("CPRBS,105707.24,,15.2,15.1,15.3,0");
    const auto r = kf::decode_from_vehicle(line);
    REQUIRE(r);
    auto m = holds<kf::cprbs>(r.value);
    CHECK_FALSE(m.battery_id.has_value());
    CHECK(m.stack_voltage_v == decimal::scaled(152, 1));
    CHECK(m.wire_fields == 6);
    CHECK(nmea::encode(m).view() == line);
    CHECK(nmea::form_field_count(m) == 6);
    CHECK(nmea::field_name<kf::cprbs>(3, nmea::form_field_count(m)) == "stack_voltage_v");
    // All blank, the same.
    const std::string blank = sealed("CPRBS,105707.24,,,,,");
    const auto b = kf::decode_from_vehicle(blank);
    REQUIRE(b);
    CHECK(nmea::encode(holds<kf::cprbs>(b.value)).view() == blank);
    // Without the remembered form: the vehicle's five fields.
    m.wire_fields = 0;
    CHECK(nmea::encode(m).view() == sealed("CPRBS,105707.24,15.2,15.1,15.3,0"));
    CHECK(nmea::form_field_count(m) == 5);
    // The five-field form and the six-field form with an id remember nothing.
    CHECK(holds<kf::cprbs>(kf::decode_from_vehicle(real_cprbs).value).wire_fields == 0);
    CHECK(holds<kf::cprbs>(kf::decode_from_vehicle(sim_cprbs).value).wire_fields == 0);
  }
  SECTION("CPRCM with a blank nav timestamp uses the sentence timestamp") {
    const std::string line = sealed("CPRCM,164959.065,1,234.3,-1.6,-6.6,");
    const auto r = kf::decode_from_vehicle(line);
    REQUIRE(r);
    const auto& m = holds<kf::cprcm>(r.value);
    CHECK(m.compass_id == 1);
    CHECK_FALSE(m.nav_timestamp.has_value());
    CHECK(m.effective_nav_timestamp() == hms(16, 49, 59, 65, 3));
    CHECK(nmea::encode(m).view() == line);  // the blank field stays: the spec form has six
  }
  SECTION("CPNVG with a blank nav timestamp uses the sentence timestamp") {
    const std::string line = sealed("CPNVG,164959.034,4221.7,N,7105.4,W,0,,,234.3,,,");
    const auto r = kf::decode_from_vehicle(line);
    REQUIRE(r);
    const auto& m = holds<kf::cpnvg>(r.value);
    CHECK_FALSE(m.gps);
    CHECK(m.effective_nav_timestamp() == hms(16, 49, 59, 34, 3));
    CHECK(nmea::encode(m).view() == line);
  }
  SECTION("CPNVR and CPNVG in their all-blank forms (no estimate yet)") {
    const std::string nvr = sealed("CPNVR,164959.063,,,,,,");
    const auto r = kf::decode_from_vehicle(nvr);
    REQUIRE(r);
    const auto& m = holds<kf::cpnvr>(r.value);
    CHECK_FALSE(m.vel_east_mps.has_value());
    CHECK_FALSE(m.yaw_rate_dps.has_value());
    CHECK(nmea::encode(m).view() == nvr);
    const std::string nvg = sealed("CPNVG,164959.034,4221.7,N,7105.4,W,0,,,,,,");
    const auto g = kf::decode_from_vehicle(nvg);
    REQUIRE(g);
    const auto& n = holds<kf::cpnvg>(g.value);
    CHECK_FALSE(n.heading_deg.has_value());
    CHECK_FALSE(n.nav_timestamp.has_value());
    CHECK(nmea::encode(n).view() == nvg);
  }
  SECTION("CPRBS: an id given in code selects the six-field form") {
    kf::cprbs m;
    m.timestamp = hms(10, 57, 7, 24, 2);
    m.stack_voltage_v = decimal::scaled(152, 1);
    m.min_cell_voltage_v = decimal::scaled(151, 1);
    m.max_cell_voltage_v = decimal::scaled(153, 1);
    m.temperature_c = decimal(0);
    CHECK(nmea::encode(m).view() == sealed("CPRBS,105707.24,15.2,15.1,15.3,0"));
    m.battery_id = 1;
    CHECK(nmea::encode(m).view() == sim_cprbs);
  }
}

// --------------------------------------------------------------------------------------------
// roles

TEST_CASE("payload role: CP* and GPS sentences known, anything else unknown, checksum required") {
  SECTION("PY* commands are not for a payload: unknown_sentence, not an error") {
    const auto r = kf::decode_from_vehicle(pydir_45_55);
    REQUIRE(r);
    const auto& u = holds<nmea::unknown_sentence>(r.value);
    CHECK(u.sentence.address == "PYDIR");
  }
  SECTION("an unknown address is unknown_sentence with its fields") {
    const std::string line = sealed("CPXYZ,1,2");
    const auto r = kf::decode_from_vehicle(line);
    REQUIRE(r);
    const auto& u = holds<nmea::unknown_sentence>(r.value);
    CHECK(u.sentence.address == "CPXYZ");
    CHECK(u.sentence.field_count == 2);
    const auto vtg = kf::decode_from_vehicle(sealed("GPVTG,156.78,T,,M,0.145,N,0.269,K,A"));
    REQUIRE(vtg);
    CHECK(std::holds_alternative<nmea::unknown_sentence>(vtg.value));
  }
  SECTION("a CP* line without its checksum is refused") {
    CHECK(kf::decode_from_vehicle("$CPRBS,172909.322,15.121597,15.121597,15.121597,0\r\n").ec ==
          errc::missing_checksum);
    // '*' then the line end: a checksum cut off, not "no checksum", on the vehicle's link.
    CHECK(kf::decode_from_vehicle("$CPRBS,172909.322,15.121597,15.121597,15.121597,0*\r\n").ec ==
          errc::bad_checksum_format);
  }
  SECTION("a wrong checksum is refused") {
    CHECK(
        kf::decode_from_vehicle("$CPNVR,164959.063,0.02941,-0.068552,0,0.060938,0,-0.061132*58\r\n")
            .ec == errc::checksum_mismatch);
  }
  SECTION("lower-case hex and LF-only endings are accepted") {
    std::string lower(real_gpgga.substr(0, real_gpgga.size() - 2));
    lower.replace(lower.size() - 2, 2, "5c\n");
    const auto r = kf::decode_from_vehicle(lower);
    REQUIRE(r);
    CHECK(std::holds_alternative<seawire::standard::gga>(r.value));
    const auto nvg =
        kf::decode_from_vehicle("$CPNVG,105707.24,0000.00,N,00000.00,W,1,,,0,,,105707.24*64");
    CHECK(nvg);
  }
  SECTION("the known sets") {
    CHECK(kf::from_vehicle::knows("CPNVG"));
    CHECK(kf::from_vehicle::knows("CPALT"));
    CHECK(kf::from_vehicle::knows("GPRMC"));
    CHECK(kf::from_vehicle::knows("GPGGA"));
    CHECK_FALSE(kf::from_vehicle::knows("PYDIR"));
    CHECK(kf::to_vehicle::knows("PYCLT"));
    CHECK_FALSE(kf::to_vehicle::knows("CPNVG"));
    CHECK(kf::payload_policy().checksum == nmea::checksum_policy::required);
    CHECK(kf::vehicle_policy().checksum == nmea::checksum_policy::verify_if_present);
  }
}

TEST_CASE("vehicle role: PY* known, checksum optional but never wrong") {
  SECTION("'*' with no checksum digits") {
    const auto r = kf::decode_to_vehicle("$PYDIR,12.5,-3*\r\n");
    REQUIRE(r);
    const auto& m = holds<kf::pydir>(r.value);
    CHECK(m.thrust_left.to_double() == 12.5);
    CHECK(m.thrust_right.to_double() == -3.0);
    CHECK(nmea::encode(m).view() == "$PYDIR,12.5,-3*50\r\n");
  }
  SECTION("no '*' at all") {
    const auto r = kf::decode_to_vehicle("$PYDIR,12.5,-3\r\n");
    REQUIRE(r);
    CHECK(holds<kf::pydir>(r.value).thrust_right == decimal(-3));
  }
  SECTION("right and wrong checksums") {
    CHECK(kf::decode_to_vehicle("$PYDIR,12.5,-3*50\r\n"));
    CHECK(kf::decode_to_vehicle("$PYDIR,12.5,-3*51\r\n").ec == errc::checksum_mismatch);
    CHECK(kf::decode_to_vehicle("$PYDIR,12.5,-3*5\r\n").ec == errc::bad_checksum_format);
  }
  SECTION("'+' signs are accepted on receive and never written") {
    const auto r = kf::decode_to_vehicle("$PYDIR,+45,+5.5\r\n");
    REQUIRE(r);
    const auto& m = holds<kf::pydir>(r.value);
    CHECK(m.thrust_left == decimal(45));
    CHECK(nmea::encode(m).view() == sealed("PYDIR,45,5.5"));
    // The strict policy (what seawire itself sends) refuses them.
    CHECK(kf::decode_to_vehicle(sealed("PYDIR,+45,5.5"), nmea::parse_policy::strict()).ec ==
          errc::bad_number);
  }
  SECTION("CP* lines are not for a vehicle: unknown_sentence") {
    const auto r = kf::decode_to_vehicle(real_cpnvg);
    REQUIRE(r);
    CHECK(holds<nmea::unknown_sentence>(r.value).sentence.address == "CPNVG");
  }
}

// --------------------------------------------------------------------------------------------
// malformed input

void check_table(const std::vector<bad_case>& table, bool from_vehicle) {
  for (const auto& c : table) {
    if (from_vehicle) {
      check_bad(c, [](std::string_view line) { return kf::decode_from_vehicle(line); });
    } else {
      check_bad(c, [](std::string_view line) { return kf::decode_to_vehicle(line); });
    }
  }
}

TEST_CASE("malformed CPNVG") {
  const std::string tail = "1,0,0,234.3,-6.7,-1.7,164959.006";
  check_table(
      {
          {"CPNVG", errc::too_few_fields, 1},
          {"CPNVG,,4221.7,N,7105.4,W," + tail, errc::missing_field, 1},
          {"CPNVG,1649,4221.7,N,7105.4,W," + tail, errc::bad_time, 1},
          {"CPNVG,164959.x,4221.7,N,7105.4,W," + tail, errc::bad_time, 1},
          {"CPNVG,244959,4221.7,N,7105.4,W," + tail, errc::hour_out_of_range, 1},
          {"CPNVG,166059,4221.7,N,7105.4,W," + tail, errc::minute_out_of_range, 1},
          {"CPNVG,164960.5,4221.7,N,7105.4,W," + tail, errc::second_out_of_range, 1},
          {"CPNVG,164961.000,4221.7,N,7105.4,W," + tail, errc::second_out_of_range, 1},
          {"CPNVG,164959,,N,7105.4,W," + tail, errc::missing_field, 2},
          {"CPNVG,164959,4261.7,N,7105.4,W," + tail, errc::minute_out_of_range, 2},
          {"CPNVG,164959,9100.0,N,7105.4,W," + tail, errc::bad_latitude, 2},
          {"CPNVG,164959,42x1.7,N,7105.4,W," + tail, errc::bad_latitude, 2},
          {"CPNVG,164959,.7,N,7105.4,W," + tail, errc::bad_latitude, 2},
          {"CPNVG,164959,61.7,N,7105.4,W," + tail, errc::minute_out_of_range, 2},
          {"CPNVG,164959,4221.7,N,.4,W," + tail, errc::bad_longitude, 4},
          {"CPNVG,164959,4221.7,N,nan,W," + tail, errc::bad_longitude, 4},
          {"CPNVG,164959,-4221.7,N,7105.4,W," + tail, errc::bad_latitude, 2},
          {"CPNVG,164959,4221.7,X,7105.4,W," + tail, errc::bad_hemisphere, 3},
          {"CPNVG,164959,4221.7,E,7105.4,W," + tail, errc::bad_hemisphere, 3},
          {"CPNVG,164959,4221.7,,7105.4,W," + tail, errc::bad_hemisphere, 3},
          {"CPNVG,164959,4221.7,N,18100.0,W," + tail, errc::bad_longitude, 4},
          {"CPNVG,164959,4221.7,N,071005.4,W," + tail, errc::bad_longitude, 4},
          {"CPNVG,164959,4221.7,N,7105.4,N," + tail, errc::bad_hemisphere, 5},
          {"CPNVG,164959,4221.7,N,7105.4", errc::too_few_fields, 5},
          {"CPNVG,164959,4221.7,N,7105.4,W", errc::too_few_fields, 6},
          {"CPNVG,164959,4221.7,N,7105.4,W,2,0,0,234.3,-6.7,-1.7,", errc::bad_flag, 6},
          {"CPNVG,164959,4221.7,N,7105.4,W,,0,0,234.3,-6.7,-1.7,", errc::missing_field, 6},
          {"CPNVG,164959,4221.7,N,7105.4,W,1,abc,0,234.3,-6.7,-1.7,", errc::bad_number, 7},
          {"CPNVG,164959,4221.7,N,7105.4,W,1,0,1..2,234.3,-6.7,-1.7,", errc::bad_number, 8},
          {"CPNVG,164959,4221.7,N,7105.4,W,1,0,0,361,-6.7,-1.7,", errc::out_of_range, 9},
          {"CPNVG,164959,4221.7,N,7105.4,W,1,0,0,-0.5,-6.7,-1.7,", errc::out_of_range, 9},
          {"CPNVG,164959,4221.7,N,7105.4,W,1,0,0,2e2,-6.7,-1.7,", errc::bad_number, 9},
          {"CPNVG,164959,4221.7,N,7105.4,W,1,0,0,234.3,-181,-1.7,", errc::out_of_range, 10},
          {"CPNVG,164959,4221.7,N,7105.4,W,1,0,0,234.3,-6.7,91,", errc::out_of_range, 11},
          {"CPNVG,164959,4221.7,N,7105.4,W,1,0,0,234.3,-6.7,-1.7,16495", errc::bad_time, 12},
      },
      true);
}

TEST_CASE("the vehicle's unpadded positions under one degree are minutes of zero degrees") {
  // The vehicle prints degrees * 100 + minutes as a number: within one degree of the equator or
  // the prime meridian there are no degree digits at all.
  struct row {
    std::string lat, lon;
    double lat_deg, lon_deg;
    unsigned lat_degree_digits, lon_degree_digits;
  };
  const std::vector<row> rows = {
      {"4221.711138,N", "22.2,W", 42.0 + 21.711138 / 60, -22.2 / 60, 2, 0},
      {"44.598,S", "7105.44878,W", -44.598 / 60, -(71.0 + 5.44878 / 60), 0, 2},
      {"0,S", "0,W", -0.0, -0.0, 0, 0},
      {"00.00,N", "000.00,W", 0.0, -0.0, 0, 1},
      {"5.5,N", "59.999,E", 5.5 / 60, 59.999 / 60, 0, 0},
      {"05.25,S", "0130.5,E", -5.25 / 60, 1.0 + 30.5 / 60, 0, 2},
  };
  for (const row& r : rows) {
    const std::string body = "CPNVG,164959.034," + r.lat + "," + r.lon + ",1,0,0,234.3,-6.8,-1.7,";
    const std::string line = sealed(body);
    INFO(line);
    const auto d = kf::decode_from_vehicle(line);
    REQUIRE(d);
    const auto& m = holds<kf::cpnvg>(d.value);
    CHECK(m.lat.degrees() == Approx(r.lat_deg).margin(1e-12));
    CHECK(m.lon.degrees() == Approx(r.lon_deg).margin(1e-12));
    CHECK(std::signbit(m.lat.degrees()) == std::signbit(r.lat_deg));
    CHECK(std::signbit(m.lon.degrees()) == std::signbit(r.lon_deg));
    CHECK(m.lat.written_degree_digits() == r.lat_degree_digits);
    CHECK(m.lon.written_degree_digits() == r.lon_degree_digits);
    // Written back as it came, but for the fraction digit every DDMM.m position carries.
    std::string want = line;
    for (const std::string_view whole : {",0,S", ",0,W"}) {
      const auto at = want.find(whole);
      if (at != std::string::npos) want.insert(at + 2, ".0");
    }
    CHECK(nmea::encode(m).view() == resealed(want));
    // The same message under the sending rules, and the same through the generic decoder.
    CHECK(nmea::decode<kf::cpnvg>(line, nmea::parse_policy::strict()).ec ==
          (r.lat.find('.') == std::string::npos ? errc::bad_latitude : errc::ok));
    CHECK(nmea::decode<kf::cpnvg>(line));
  }
  SECTION("BFNVG, GPRMC and GPGGA keep the padded form: decimal-degree text is refused") {
    CHECK(nmea::decode<seawire::sandshark::bfnvg>(
              sealed("BFNVG,231131.55,22.2,N,07106.000000,W,0,10.0,1.0,45.0,0.0,0.0,231131.55"))
              .ec == errc::bad_latitude);
    const auto rmc = kf::decode_from_vehicle(
        sealed("GPRMC,164959.00,A,37.352387,N,07105.44878,W,0.145,156.78,311214,,,A"));
    CHECK(rmc.ec == errc::bad_latitude);
    CHECK(rmc.field == 3);
    const auto gga = kf::decode_from_vehicle(
        sealed("GPGGA,164959.00,4221.71114,N,12.203,W,1,06,2.80,46.6,M,-33.2,M,,"));
    CHECK(gga.ec == errc::bad_longitude);
    CHECK(gga.field == 4);
  }
  SECTION("encode writes the unpadded form only for a message whose sender writes it") {
    kf::cpnvg nvg = holds<kf::cpnvg>(
        kf::decode_from_vehicle(sealed("CPNVG,164959.034,0,S,22.2,W,1,0,0,234.3,-6.8,-1.7,"))
            .value);
    seawire::standard::rmc rmc;
    rmc.lat = nvg.lat;
    rmc.lon = nvg.lon;
    const auto r = nmea::encode(rmc);
    CHECK(r.ec == errc::bad_latitude);
    CHECK(r.field == 3);
    rmc.lat = nmea::latitude::from_degrees(-0.01, 4).value;  // padded: 0000.6000
    CHECK(nmea::encode(rmc).ec == errc::bad_longitude);
    rmc.lon = nmea::longitude::from_degrees(-0.37, 4).value;
    CHECK(nmea::encode(rmc));
    // Unpadded with whole degrees is no form at all.
    kf::cpnvg odd = nvg;
    odd.lon.whole_degrees = 1;
    CHECK(nmea::encode(odd).ec == errc::bad_longitude);
    // A position from degrees is always padded, in a CP* message too.
    nvg.lon = nmea::longitude::from_degrees(-0.37, 4).value;
    CHECK(nmea::encode(nvg).view().find(",00022.2000,W,") != std::string_view::npos);
  }
}

TEST_CASE("the vehicle's nan is \"not available\": the rest of the sentence is kept") {
  SECTION("CPNVR velocities when nearly stopped, in any case and sign") {
    for (const std::string_view nan : {"nan", "NaN", "NAN", "-nan", "-NaN", "+nan"}) {
      const std::string n(nan);
      const std::string line =
          sealed("CPNVR,164959.063," + n + "," + n + ",0,0.060938,-0,-0.061132");
      INFO(line);
      const auto d = kf::decode_from_vehicle(line);
      REQUIRE(d);
      const auto& m = holds<kf::cpnvr>(d.value);
      CHECK_FALSE(m.vel_east_mps.has_value());
      CHECK_FALSE(m.vel_north_mps.has_value());
      REQUIRE(m.vel_down_mps);
      CHECK(m.vel_down_mps->is_zero());
      REQUIRE(m.yaw_rate_dps);
      CHECK(m.yaw_rate_dps->to_double() == -0.061132);
      REQUIRE(m.roll_rate_dps);
      CHECK(m.roll_rate_dps->negative);  // "-0" keeps its sign
      // Never written: a value that is not there goes out blank.
      CHECK(nmea::encode(m).view() == sealed("CPNVR,164959.063,,,0,0.060938,-0,-0.061132"));
      // The sending rules refuse it, naming the field.
      const auto strict = nmea::decode<kf::cpnvr>(line, nmea::parse_policy::strict());
      CHECK(strict.ec == errc::bad_number);
      CHECK(strict.field == 2);
    }
  }
  SECTION("every optional number of every CP* and BF* navigation sentence") {
    CHECK(kf::decode_from_vehicle(
        sealed("CPNVG,164959.034,4221.711142,N,7105.44878,W,1,nan,nan,nan,nan,nan,164959.006")));
    CHECK(kf::decode_from_vehicle(sealed("CPRCM,164959.065,nan,nan,nan,nan,164959.060")));
    CHECK(kf::decode_from_vehicle(sealed("CPRBS,172909.322,nan,nan,nan,nan")));
    CHECK(kf::decode_from_vehicle(sealed("CPRBS,172909.322,1,nan,15.1,15.2,nan")));
    CHECK(kf::decode_from_vehicle(sealed("CPIMU,164958.858,nan,nan,nan,nan,nan,nan")));
    CHECK(nmea::decode<seawire::sandshark::bfnvr>(sealed("BFNVR,081025.987,nan,0,0,0,0,NaN")));
    const auto rcm = kf::decode_from_vehicle(sealed("CPRCM,164959.065,0,nan,-1.6,-6.6,"));
    REQUIRE(rcm);
    CHECK_FALSE(holds<kf::cprcm>(rcm.value).heading_deg.has_value());
    CHECK(holds<kf::cprcm>(rcm.value).pitch_deg->to_double() == -1.6);
  }
  SECTION("not where a value is required, nor from senders that do not write it") {
    // Text that merely starts like it is no nan.
    CHECK(kf::decode_from_vehicle(sealed("CPNVR,164959.063,nanx,0,0,0,0,0")).ec ==
          errc::bad_number);
    CHECK(kf::decode_from_vehicle(sealed("CPNVR,164959.063,na,0,0,0,0,0")).ec == errc::bad_number);
    // A command to the vehicle: the payload's own numbers are NMEA numbers.
    const auto dir = kf::decode_to_vehicle("$PYDIR,nan,0*\r\n");
    CHECK(dir.ec == errc::bad_number);
    CHECK(dir.field == 1);
    // A relayed GPS sentence keeps the rules of its own sender.
    CHECK(kf::decode_from_vehicle(
              sealed("GPRMC,164959.00,A,4221.71114,N,07105.44878,W,nan,156.78,311214,,,A"))
              .ec == errc::bad_number);
  }
}

TEST_CASE("the vehicle's seconds rounded up to 60.000 are the next minute's first instant") {
  // The vehicle prints seconds with "%06.3f": from hh:mm:59.9995 on that is "60.000".
  const std::string nvg = sealed(
      "CPNVG,164960.000,4221.711142,N,7105.44878,W,1,0,0,234.32964,-6.796959,-1.706798,164959.006");
  const auto d = kf::decode_from_vehicle(nvg);
  REQUIRE(d);
  const auto& m = holds<kf::cpnvg>(d.value);
  CHECK(m.timestamp.second == 60);
  CHECK(m.timestamp.since_midnight() == std::chrono::hours(16) + std::chrono::minutes(50));
  CHECK(nmea::encode(m).view() == nvg);  // written back as it came
  for (const std::string& line :
       {sealed("CPIMU,235960.000,-0.061035,-0.000097,-0.061035,-0.026916,0.104533,-0.932172"),
        sealed("CPRCM,164959.065,0,234.326694,-1.655603,-6.628557,000060.000"),
        sealed("CPNVR,120060,0.02941,-0.068552,0,0.060938,0,-0.061132"),
        sealed("CPRBS,172960.00,15.121597,15.121597,15.121597,0"), sealed("CPALT,164960.000,1")}) {
    INFO(line);
    const auto r = kf::decode_from_vehicle(line);
    REQUIRE(r);
    std::visit(
        [&](const auto& msg) {
          if constexpr (nmea::message_like<std::remove_cvref_t<decltype(msg)>>)
            CHECK(nmea::encode(msg).view() == line);
        },
        r.value);
  }
  // A fraction that is not zero is no rounding, and the leap second stays 23:59's.
  CHECK(kf::decode_from_vehicle(sealed("CPALT,164960.001,1")).ec == errc::second_out_of_range);
  CHECK(kf::decode_from_vehicle(sealed("CPALT,235960.5,1")));
  // A relayed GPS sentence and a command keep the rule of their own senders.
  const auto rmc = kf::decode_from_vehicle(
      sealed("GPRMC,164960.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A"));
  CHECK(rmc.ec == errc::second_out_of_range);
  CHECK(rmc.field == 1);
  // Encode follows the message: a GPRMC with second 60 before 23:59 is refused.
  seawire::standard::rmc fix;
  fix.time = m.timestamp;
  CHECK(nmea::encode(fix).ec == errc::second_out_of_range);
}

TEST_CASE("malformed CPNVR") {
  check_table(
      {
          {"CPNVR,,0.1,0.2,0,0,0,0", errc::missing_field, 1},
          {"CPNVR,99,0.1,0.2,0,0,0,0", errc::bad_time, 1},
          {"CPNVR,164959.063,east,0.2,0,0,0,0", errc::bad_number, 2},
          {"CPNVR,164959.063,0.1,-,0,0,0,0", errc::bad_number, 3},
          {"CPNVR,164959.063,0.1,0.2,.,0,0,0", errc::bad_number, 4},
          {"CPNVR,164959.063,0.1,0.2,0,0,0,1.2.3", errc::bad_number, 7},
      },
      true);
}

TEST_CASE("blank fields from the vehicle are \"no data\" (spec 2.4), not errors") {
  // Each measurement blank in turn, in every sentence that carries measurements.
  const std::vector<std::string> lines = {
      "CPRCM,164959.065,,234.3,-1.6,-6.6,164959.060",
      "CPRCM,164959.065,0,,-1.6,-6.6,164959.060",
      "CPRCM,164959.065,0,234.3,,-6.6,164959.060",
      "CPRCM,164959.065,0,234.3,-1.6,,164959.060",
      "CPRCM,164959.065,,,,,",
      "CPRBS,172909.322,,15.1,15.1,0",
      "CPRBS,172909.322,15.1,15.1,15.1,",
      "CPRBS,105707.24,1,,,,",
      "CPIMU,164958.858,,0,0,0,0,0",
      "CPIMU,164958.858,0,0,0,0,0,",
      "CPIMU,164958.858,,,,,,",
  };
  for (const std::string& body : lines) {
    const std::string line = sealed(body);
    INFO(line);
    const auto r = kf::decode_from_vehicle(line);
    REQUIRE(r.ec == errc::ok);
    // Written back as it came: a blank stays blank.
    std::visit(
        [&](const auto& m) {
          if constexpr (!std::is_same_v<std::decay_t<decltype(m)>, nmea::unknown_sentence>)
            CHECK(nmea::encode(m).view() == line);
        },
        r.value);
  }
  const auto rcm = kf::decode_from_vehicle(sealed("CPRCM,164959.065,0,,-1.6,-6.6,164959.060"));
  REQUIRE(rcm.ec == errc::ok);
  const auto& m = std::get<kf::cprcm>(rcm.value);
  CHECK_FALSE(m.heading_deg.has_value());
  CHECK(m.pitch_deg == decimal::scaled(-16, 1));

  // Blank is not absent: the vehicle writes every field, so a sentence cut short is an error.
  for (const char* cut :
       {"CPRCM,164959.065,0,234.3", "CPRBS,172909.322,15.1,15.1", "CPIMU,164958.858,0,0,0"}) {
    INFO(cut);
    CHECK(kf::decode_from_vehicle(sealed(cut)).ec == errc::too_few_fields);
  }
}

TEST_CASE("malformed CPRCM") {
  check_table(
      {
          {"CPRCM", errc::too_few_fields, 1},
          {"CPRCM,,0,234.3,-1.6,-6.6,164959.060", errc::missing_field, 1},
          {"CPRCM,256000,0,234.3,-1.6,-6.6,164959.060", errc::hour_out_of_range, 1},
          {"CPRCM,164959.065", errc::too_few_fields, 2},
          {"CPRCM,164959.065,x,234.3,-1.6,-6.6,164959.060", errc::bad_number, 2},
          {"CPRCM,164959.065,1.5,234.3,-1.6,-6.6,164959.060", errc::bad_number, 2},
          {"CPRCM,164959.065,-1,234.3,-1.6,-6.6,164959.060", errc::out_of_range, 2},
          {"CPRCM,164959.065,0,360.5,-1.6,-6.6,164959.060", errc::out_of_range, 3},
          {"CPRCM,164959.065,0,234.3", errc::too_few_fields, 4},
          {"CPRCM,164959.065,0,234.3,95,-6.6,164959.060", errc::out_of_range, 4},
          {"CPRCM,164959.065,0,234.3,-1.6,-180.5,164959.060", errc::out_of_range, 5},
          {"CPRCM,164959.065,0,234.3,-1.6,-6.6,99", errc::bad_time, 6},
      },
      true);
}

TEST_CASE("malformed CPRBS, both forms") {
  check_table(
      {
          {"CPRBS", errc::too_few_fields, 1},
          {"CPRBS,,15.1,15.1,15.1,0", errc::missing_field, 1},
          {"CPRBS,17290,15.1,15.1,15.1,0", errc::bad_time, 1},
          // five-field form (no id): errors name the field's position on the wire
          {"CPRBS,172909.322,15.1,volts,15.1,0", errc::bad_number, 3},
          {"CPRBS,172909.322,15.1,15.1,15.1", errc::too_few_fields, 5},
          {"CPRBS,172909.322,15.1", errc::too_few_fields, 3},
          // six-field form (with id)
          {"CPRBS,105707.24,x,15.2,15.1,15.3,0", errc::bad_number, 2},
          {"CPRBS,105707.24,1.5,15.2,15.1,15.3,0", errc::bad_number, 2},
          {"CPRBS,105707.24,-1,15.2,15.1,15.3,0", errc::out_of_range, 2},
          {"CPRBS,105707.24,70000,15.2,15.1,15.3,0", errc::out_of_range, 2},
          {"CPRBS,105707.24,1,15.2,15.1,15.3,hot", errc::bad_number, 6},
      },
      true);
}

TEST_CASE("malformed CPIMU") {
  check_table(
      {
          {"CPIMU,,0,0,0,0,0,0", errc::missing_field, 1},
          {"CPIMU,1649588.858,0,0,0,0,0,0", errc::bad_time, 1},
          {"CPIMU,164958.858,0,0,z,0,0,0", errc::bad_number, 4},
          {"CPIMU,164958.858,0,0,0,0,0", errc::too_few_fields, 7},
          {"CPIMU,164958.858,0,0,0,0,0,0,246000", errc::hour_out_of_range, 8},
          {"CPIMU,164958.858,0,0,0,0,0,0,1x", errc::bad_time, 8},
      },
      true);
}

TEST_CASE("malformed CPALT") {
  check_table(
      {
          {"CPALT", errc::too_few_fields, 1},
          {"CPALT,,1", errc::missing_field, 1},
          {"CPALT,164959.100", errc::too_few_fields, 2},
          {"CPALT,164959.100,", errc::missing_field, 2},
          {"CPALT,164959.100,2", errc::bad_flag, 2},
          {"CPALT,164959.100,ON", errc::bad_flag, 2},
      },
      true);
}

TEST_CASE("malformed and out-of-range PY* commands") {
  check_table(
      {
          {"PYDIR", errc::too_few_fields, 1},
          {"PYDIR,,0", errc::missing_field, 1},
          {"PYDIR,0", errc::too_few_fields, 2},
          {"PYDIR,0,", errc::missing_field, 2},
          {"PYDIR,abc,0", errc::bad_number, 1},
          {"PYDIR,1e2,0", errc::bad_number, 1},
          {"PYDIR,--5,0", errc::bad_number, 1},
          {"PYDIR, 5,0", errc::bad_number, 1},
          {"PYDIR,150,0", errc::out_of_range, 1},
          {"PYDIR,100.01,0", errc::out_of_range, 1},
          {"PYDIR,0,-100.5", errc::out_of_range, 2},
          {"PYDEV", errc::too_few_fields, 1},
          {"PYDEV,,1.5", errc::missing_field, 1},
          {"PYDEV,90", errc::too_few_fields, 2},
          {"PYDEV,90,", errc::missing_field, 2},
          {"PYDEV,360,1.5", errc::out_of_range, 1},
          {"PYDEV,-1,1.5", errc::out_of_range, 1},
          {"PYDEV,north,1.5", errc::bad_number, 1},
          {"PYDEV,90,-0.1", errc::out_of_range, 2},
          {"PYDEV,90,fast", errc::bad_number, 2},
          {"PYDEP,,50", errc::missing_field, 1},
          {"PYDEP,x,50", errc::bad_number, 1},
          {"PYDEP,-10", errc::too_few_fields, 2},
          {"PYDEP,-10,101", errc::out_of_range, 2},
          {"PYDEP,-10,-100.5", errc::out_of_range, 2},
          {"PYCLT", errc::too_few_fields, 1},
          {"PYCLT,", errc::missing_field, 1},
          {"PYCLT,2", errc::bad_flag, 1},
          {"PYCLT,ON", errc::bad_flag, 1},
      },
      false);
}

TEST_CASE("spec limits are inclusive where the spec says so") {
  CHECK(kf::decode_to_vehicle("$PYDIR,-100,100"));
  CHECK(kf::decode_to_vehicle("$PYDEP,-0.5,-100"));
  CHECK(kf::decode_to_vehicle("$PYDEV,359.99,0"));
  CHECK(kf::decode_to_vehicle("$PYDEV,0,0.0"));
  CHECK(kf::decode_from_vehicle(sealed("CPRCM,164959.065,0,360,90,-180,")));
}

// --------------------------------------------------------------------------------------------
// encoding

TEST_CASE("encoders refuse what the spec forbids, naming the field") {
  SECTION("thrust 150") {
    const auto b = nmea::encode(kf::pydir{150, 0});
    CHECK(b.ec == errc::out_of_range);
    CHECK(b.field == 1);
    CHECK(b.view().empty());
  }
  SECTION("starboard thrust -101") {
    const auto b = nmea::encode(kf::pydir{0, -101});
    CHECK(b.ec == errc::out_of_range);
    CHECK(b.field == 2);
  }
  SECTION("PYDEP thrust 100.5") {
    const auto b = nmea::encode(kf::pydep{0, decimal::scaled(1005, 1)});
    CHECK(b.ec == errc::out_of_range);
    CHECK(b.field == 2);
  }
  SECTION("heading 360 and a negative speed") {
    const auto h = nmea::encode(kf::pydev{360, 1});
    CHECK(h.ec == errc::out_of_range);
    CHECK(h.field == 1);
    const auto s = nmea::encode(kf::pydev{90, decimal::scaled(-5, 1)});
    CHECK(s.ec == errc::out_of_range);
    CHECK(s.field == 2);
    CHECK(nmea::encode(kf::pydev{decimal::scaled(35999, 2), 0}));
  }
  SECTION("from_double refuses NaN and infinities, with the field") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const auto l = kf::pydir::from_percent(nan, 10);
    CHECK(l.ec == errc::not_finite);
    CHECK(l.field == 1);
    const auto r = kf::pydir::from_percent(10, -inf);
    CHECK(r.ec == errc::not_finite);
    CHECK(r.field == 2);
    const auto dev = kf::pydev::from_heading(90, inf);
    CHECK(dev.ec == errc::not_finite);
    CHECK(dev.field == 2);
    const auto dep = kf::pydep::from_rate(nan, 10);
    CHECK(dep.ec == errc::not_finite);
    CHECK(dep.field == 1);
  }
  SECTION("helpers convert; encode checks the range once") {
    const auto c = kf::pydir::from_percent(150, 20);
    REQUIRE(c);
    const auto b = nmea::encode(c.value);
    CHECK(b.ec == errc::out_of_range);
    CHECK(b.field == 1);
  }
  SECTION("vehicle-side messages are checked too") {
    kf::cprcm m;
    m.timestamp = hms(16, 49, 59, 65, 3);
    m.heading_deg = 400;
    const auto b = nmea::encode(m);
    CHECK(b.ec == errc::out_of_range);
    CHECK(b.field == 3);

    kf::cpimu i;
    i.timestamp = hms(24, 0, 0, 0, 0);
    const auto t = nmea::encode(i);
    CHECK(t.ec == errc::hour_out_of_range);
    CHECK(t.field == 1);

    kf::cpnvg n;
    n.timestamp = hms(16, 49, 59, 34, 3);
    n.lat.whole_degrees = 42;
    n.lat.minutes = 60;
    const auto p = nmea::encode(n);
    CHECK(p.ec == errc::minute_out_of_range);
    CHECK(p.field == 2);
    n.lat.minutes = decimal::scaled(217, 1);
    n.lon.hemi = nmea::hemisphere::north;
    const auto h = nmea::encode(n);
    CHECK(h.ec == errc::bad_hemisphere);
    CHECK(h.field == 5);  // the letter, as decode says
  }
}

TEST_CASE("command helpers") {
  SECTION("pydir::from_percent rounds to the places asked for") {
    const auto c = kf::pydir::from_percent(12.46, -3.04);
    REQUIRE(c);
    CHECK(nmea::encode(c.value).view() == sealed("PYDIR,12.5,-3.0"));
    const auto whole = kf::pydir::from_percent(45.2, 54.7, 0);
    REQUIRE(whole);
    CHECK(nmea::encode(whole.value).view() == pydir_45_55);
    // A value that rounds to zero is written without a sign.
    const auto z = kf::pydir::from_percent(-0.04, 0);
    REQUIRE(z);
    CHECK(nmea::encode(z.value).view() == sealed("PYDIR,0.0,0.0"));
  }
  SECTION("pydev::from_heading wraps the heading into [0, 360)") {
    // Each field at its declared precision: one place for the heading, two for the speed.
    const auto a = kf::pydev::from_heading(90, 1.5);
    REQUIRE(a);
    CHECK(nmea::encode(a.value).view() == sealed("PYDEV,90.0,1.50"));
    const auto w = kf::pydev::from_heading(-90, 1);
    REQUIRE(w);
    CHECK(w.value.heading_deg == decimal::scaled(2700, 1));
    const auto r = kf::pydev::from_heading(359.97, 1);
    REQUIRE(r);
    CHECK(r.value.heading_deg == decimal::scaled(0, 1));
    const auto big = kf::pydev::from_heading(725.5, 0, 2);
    REQUIRE(big);
    CHECK(big.value.heading_deg == decimal::scaled(550, 2));
    const auto full = kf::pydev::from_heading(-360, 0);
    REQUIRE(full);
    CHECK(full.value.heading_deg == decimal::scaled(0, 1));
    CHECK_FALSE(full.value.heading_deg.negative);
    CHECK(kf::pydev::from_heading(10, 1, 16).ec == errc::value_too_large);
    // The speed is not wrapped or clamped: encode refuses it.
    const auto slow = kf::pydev::from_heading(10, -1);
    REQUIRE(slow);
    CHECK(nmea::encode(slow.value).field == 2);
  }
  SECTION("pydep::from_rate") {
    const auto c = kf::pydep::from_rate(-0.1746, 50, 3);
    REQUIRE(c);
    CHECK(nmea::encode(c.value).view() == sealed("PYDEP,-0.175,50.000"));
  }
}

TEST_CASE("field names are what users see") {
  CHECK(nmea::field_name<kf::cpnvg>(2) == "latitude");
  CHECK(nmea::field_name<kf::cpnvg>(3) == "latitude");
  CHECK(nmea::field_name<kf::cpnvg>(4) == "longitude");
  CHECK(nmea::field_name<kf::cpnvg>(12) == "nav_timestamp");
  CHECK(nmea::field_name<kf::cprcm>(2) == "compass_id");
  CHECK(nmea::field_name<kf::cprbs>(6) == "temperature_c");
  // The five-field CPRBS (no battery id) numbered as it comes on the wire.
  CHECK(nmea::field_name<kf::cprbs>(2) == "battery_id");
  CHECK(nmea::field_name<kf::cprbs>(2, 5) == "stack_voltage_v");
  CHECK(nmea::field_name<kf::cprbs>(5, 5) == "temperature_c");
  CHECK(nmea::field_name<kf::cprbs>(6, 5).empty());
  CHECK(nmea::field_name<kf::cprbs>(2, 6) == "battery_id");
  CHECK(kf::from_vehicle::field_name("CPRBS", 5, 5) == "temperature_c");
  const auto bad = kf::decode_from_vehicle(sealed("CPRBS,172909.322,15.1,15.1,15.1,x"));
  CHECK(bad.ec == errc::bad_number);
  CHECK(bad.field == 5);
  const auto parsed = nmea::parse(sealed("CPRBS,172909.322,15.1,15.1,15.1,x"));
  REQUIRE(parsed);
  CHECK(kf::from_vehicle::field_name("CPRBS", bad.field, parsed.value.field_count) ==
        "temperature_c");
  CHECK(nmea::field_name<kf::cpimu>(8) == "nav_timestamp");
  CHECK(nmea::field_name<kf::cpalt>(2) == "lights_on");
  CHECK(nmea::field_name<kf::pydep>(1) == "yaw_rate");
  CHECK(nmea::field_name<kf::pydev>(1) == "heading_deg");
  CHECK(nmea::field_name<kf::pydev>(2) == "speed_mps");
  CHECK(nmea::field_name<kf::pydir>(2) == "thrust_right");
  CHECK(nmea::field_name<kf::pyclt>(1) == "lights_on");
  std::vector<std::string_view> names;
  nmea::for_each_field(kf::pydir{}, [&](std::string_view n, const auto&) { names.push_back(n); });
  CHECK(names == std::vector<std::string_view>{"thrust_left", "thrust_right"});
}

// Mutated vectors: decoding never fails unsafely (ASan/UBSan builds watch), and whatever decodes
// re-encodes to a line that decodes to the same values.
template <class Set>
int mutate_and_check(prng& g, std::string_view vector, int iterations) {
  nmea::parse_policy lax;
  lax.checksum = nmea::checksum_policy::ignore;  // reach the field codecs
  constexpr std::string_view alphabet = "0123456789.,-+NSEWX*$ \x01\x7f";
  int decoded = 0;
  for (int i = 0; i < iterations; ++i) {
    std::string s(vector);
    const auto edits = 1 + g.below(3);
    for (std::uint64_t e = 0; e < edits && !s.empty(); ++e) {
      const auto at = static_cast<std::size_t>(g.below(s.size()));
      switch (g.below(3)) {
        case 0: s[at] = alphabet[g.below(alphabet.size())]; break;
        case 1: s.erase(at, 1); break;
        default: s.insert(at, 1, alphabet[g.below(alphabet.size())]); break;
      }
    }
    if (g.below(8) == 0) s.resize(static_cast<std::size_t>(g.below(s.size() + 1)));
    const auto r = Set::decode(s, lax);
    if (!r || std::holds_alternative<nmea::unknown_sentence>(r.value)) continue;
    ++decoded;
    std::visit(
        [&](const auto& m) {
          using M = std::decay_t<decltype(m)>;
          if constexpr (!std::is_same_v<M, nmea::unknown_sentence>) {
            const auto again = nmea::encode(m);
            INFO("mutated: " << s);
            REQUIRE(again);
            const auto back = nmea::decode<M>(again.view(), lax);
            REQUIRE(back);
            CHECK(same_fields(back.value, m));
          }
        },
        r.value);
  }
  return decoded;
}

TEST_CASE("mutated vectors never break the decoders") {
  prng g{42};
  int decoded = 0;
  for (const auto v :
       {real_cpimu, real_cpnvg, real_cpnvr, real_cprcm, real_cprbs, sim_cpnvg, sim_cprbs, cpalt_on})
    decoded += mutate_and_check<kf::from_vehicle>(g, v, 2000);
  for (const auto v : {pydir_45_55, pydev_90, pydep_vec, pyclt_on})
    decoded += mutate_and_check<kf::to_vehicle>(g, v, 2000);
  CHECK(decoded > 1000);  // the mutations do reach the field codecs
}

}  // namespace
