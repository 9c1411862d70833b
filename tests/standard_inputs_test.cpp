// SPDX-License-Identifier: BSL-1.0
// RPM, RSA, VHW, VBW, VWR: the standard sentences a vehicle sends an INS for aiding. Vectors
// were built for these tests; their checksums are checked below with nmea::checksum and were
// cross-checked by hand with pynmea2 (same values for every field).

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>

#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/standard/rpm.hpp"
#include "seawire/standard/rsa.hpp"
#include "seawire/standard/vbw.hpp"
#include "seawire/standard/vhw.hpp"
#include "seawire/standard/vwr.hpp"

#include "support.hpp"

namespace {

using namespace support;

using namespace seawire;
using namespace seawire::standard;
using seawire::nmea::decimal;

// ---------------------------------------------------------------------------------------------
// helpers

template <class T>
constexpr bool round_trips(std::string_view text) {
  const auto r = nmea::decode<T>(text, nmea::parse_policy::strict());
  return r && nmea::encode(r.value).view() == text;
}

constexpr std::array<std::string_view, 8> talkers = {"II", "VW", "VM", "VD",
                                                     "IN", "GP", "ER", "AG"};

// Canonical vectors, checksums checked against the XOR of the body.
static_assert(nmea::checksum("IIRPM,S,1,1200.5,12.5,A") == 0x40);
static_assert(nmea::checksum("ERRPM,E,2,-850,-25.0,A") == 0x66);
static_assert(nmea::checksum("IIRPM,E,0,,,V") == 0x40);
static_assert(nmea::checksum("AGRSA,-5.2,A,-4.8,A") == 0x4D);
static_assert(nmea::checksum("IIRSA,10.5,A,,V") == 0x4D);
static_assert(nmea::checksum("IIRSA,,,,") == 0x40);
static_assert(nmea::checksum("VWVHW,45.0,T,31.3,M,5.20,N,9.63,K") == 0x5F);
static_assert(nmea::checksum("VWVHW,045.0,T,031.3,M,5.20,N,9.63,K") == 0x5F);
static_assert(nmea::checksum("IIVHW,,T,,M,5.2,N,9.6,K") == 0x5D);
static_assert(nmea::checksum("IIVHW,,,,,,,,") == 0x49);
static_assert(nmea::checksum("VDVBW,4.91,-0.12,A,5.02,0.08,A") == 0x7C);
static_assert(nmea::checksum("VDVBW,4.91,-0.12,A,5.02,0.08,A,0.05,A,0.04,A") == 0x7D);
static_assert(nmea::checksum("VWVBW,2.3,,A,,,V") == 0x7A);
static_assert(nmea::checksum("WIVWR,45.0,L,12.6,N,6.5,M,23.3,K") == 0x7C);
static_assert(nmea::checksum("IIVWR,,,,N,,M,,K") == 0x1B);
static_assert(nmea::checksum("WIVWR,045.0,L,12.6,N,6.5,M,23.3,K") == 0x4C);

// Round trips at compile time: decode under the strict policy, encode, same bytes.
static_assert(round_trips<rpm>("$IIRPM,S,1,1200.5,12.5,A*40\r\n"));
static_assert(round_trips<rpm>("$ERRPM,E,2,-850,-25.0,A*66\r\n"));
static_assert(round_trips<rsa>("$AGRSA,-5.2,A,-4.8,A*4D\r\n"));
static_assert(round_trips<rsa>("$IIRSA,,,,*40\r\n"));
static_assert(round_trips<vhw>("$VWVHW,45.0,T,31.3,M,5.20,N,9.63,K*5F\r\n"));
static_assert(round_trips<vhw>("$IIVHW,,T,,M,5.2,N,9.6,K*5D\r\n"));
static_assert(round_trips<vhw>("$VWVHW,045.0,T,031.3,M,5.20,N,9.63,K*5F\r\n"));
static_assert(round_trips<vbw>("$VDVBW,4.91,-0.12,A,5.02,0.08,A*7C\r\n"));
static_assert(round_trips<vbw>("$VDVBW,4.91,-0.12,A,5.02,0.08,A,0.05,A,0.04,A*7D\r\n"));
// NMEA 3.0's stern fields sent blank: they stay, as they came (wire_fields), whole or in part.
static_assert(round_trips<vbw>("$VDVBW,4.91,-0.12,A,5.02,0.08,A,,,,*7C\r\n"));
static_assert(round_trips<vbw>("$VDVBW,4.91,-0.12,A,5.02,0.08,A,0.05,A,,*26\r\n"));
static_assert(nmea::decode<vbw>("$VDVBW,4.91,-0.12,A,5.02,0.08,A,,,,*7C\r\n").value.wire_fields ==
              10);
static_assert(
    nmea::decode<vbw>("$VDVBW,4.91,-0.12,A,5.02,0.08,A,0.05,A,,*26\r\n").value.wire_fields == 10);
static_assert(round_trips<vwr>("$WIVWR,45.0,L,12.6,N,6.5,M,23.3,K*7C\r\n"));
static_assert(round_trips<vwr>("$IIVWR,,,,N,,M,,K*1B\r\n"));
static_assert(round_trips<vwr>("$WIVWR,045.0,L,12.6,N,6.5,M,23.3,K*4C\r\n"));

}  // namespace

// =============================================================================================
// RPM

TEST_CASE("RPM: shaft speed and pitch", "[rpm]") {
  const auto r = nmea::decode<rpm>("$IIRPM,S,1,1200.5,12.5,A*40\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.talker == "II");
  CHECK(r.value.source == rpm_source::shaft);
  CHECK(r.value.number == 1);
  CHECK(r.value.speed_rpm == decimal::scaled(12005, 1));
  CHECK(r.value.pitch_percent == decimal::scaled(125, 1));
  CHECK(r.value.status == rpm_status::valid);
}

TEST_CASE("RPM: engine turning counter-clockwise, pitch astern", "[rpm]") {
  const auto r = nmea::decode<rpm>("$ERRPM,E,2,-850,-25.0,A*66\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.talker == "ER");
  CHECK(r.value.source == rpm_source::engine);
  CHECK(r.value.number == 2);
  CHECK(r.value.speed_rpm->to_double() == -850.0);
  CHECK(r.value.pitch_percent == decimal::scaled(-250, 1));
  CHECK(nmea::encode(r.value).view() == "$ERRPM,E,2,-850,-25.0,A*66\r\n");
}

TEST_CASE("RPM: no data, blank values and a blank status", "[rpm]") {
  const auto r = nmea::decode<rpm>("$IIRPM,E,0,,,V*40\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.number == 0);
  CHECK_FALSE(r.value.speed_rpm.has_value());
  CHECK_FALSE(r.value.pitch_percent.has_value());
  CHECK(r.value.status == rpm_status::invalid);
  CHECK(nmea::encode(r.value).view() == "$IIRPM,E,0,,,V*40\r\n");

  // The spec requires a status; senders leave it blank anyway. Blank in, blank out.
  const std::string no_status = sealed("IIRPM,S,1,1200.5,12.5,");
  const auto b = nmea::decode<rpm>(no_status, nmea::parse_policy::strict());
  REQUIRE(b.ec == errc::ok);
  CHECK_FALSE(b.value.status.has_value());
  CHECK(nmea::encode(b.value).view() == no_status);
}

TEST_CASE("RPM: any talker, kept on re-encode", "[rpm]") {
  for (const auto t : talkers) {
    const std::string text = sealed(std::string(t) + "RPM,S,1,1200.5,12.5,A");
    const auto r = nmea::decode<rpm>(text);
    INFO(text);
    REQUIRE(r.ec == errc::ok);
    CHECK(r.value.talker == t);
    CHECK(r.value.speed_rpm == decimal::scaled(12005, 1));
    CHECK(nmea::encode(r.value).view() == text);
  }
}

TEST_CASE("RPM: malformed input, errc and field number", "[rpm]") {
  const bad_case cases[] = {
      {"IIRPM,X,1,1200,10,A", errc::bad_enum, 1},      // source not S/E
      {"IIRPM,s,1,1200,10,A", errc::bad_enum, 1},      // lower case
      {"IIRPM,,1,1200,10,A", errc::missing_field, 1},  // source is required
      {"IIRPM,S,,1200,10,A", errc::missing_field, 2},  // number is required
      {"IIRPM,S,1.5,1200,10,A", errc::bad_number, 2},
      {"IIRPM,S,-1,1200,10,A", errc::out_of_range, 2},
      {"IIRPM,S,256,1200,10,A", errc::out_of_range, 2},
      {"IIRPM,S,1,12O0,10,A", errc::bad_number, 3},  // letter O
      {"IIRPM,S,1,1e3,10,A", errc::bad_number, 3},
      {"IIRPM,S,1,-,10,A", errc::bad_number, 3},
      {"IIRPM,S,1,1200,101,A", errc::out_of_range, 4},
      {"IIRPM,S,1,1200,-100.5,A", errc::out_of_range, 4},
      {"IIRPM,S,1,1200,10,X", errc::bad_enum, 5},
      {"IIRPM,S,1,1200,10,AV", errc::bad_enum, 5},
      {"IIRPM,S", errc::too_few_fields, 2},
      {"IIRPM", errc::too_few_fields, 1},
  };
  for (const auto& c : cases) check_bad<rpm>(c);

  // Under the strict policy: no extra fields, no '+' signs.
  check_bad<rpm>({"IIRPM,S,1,1200,10,A,", errc::too_many_fields, 6}, nmea::parse_policy::strict());
  check_bad<rpm>({"IIRPM,S,1,+1200,10,A", errc::bad_number, 3}, nmea::parse_policy::strict());
  // ... which the default receiver accepts.
  CHECK(nmea::decode<rpm>(sealed("IIRPM,S,1,1200,10,A,")).ec == errc::ok);
  CHECK(nmea::decode<rpm>(sealed("IIRPM,S,1,+1200,10,A")).value.speed_rpm == decimal(1200));

  CHECK(nmea::decode<rpm>(sealed("IIRSA,1,A,2,A")).ec == errc::wrong_address);
  CHECK(nmea::decode<rpm>("$IIRPM,S,1,1200.5,12.5,A*41\r\n").ec == errc::checksum_mismatch);
}

TEST_CASE("RPM: the encoder refuses what the spec forbids", "[rpm]") {
  rpm m;
  m.pitch_percent = decimal::scaled(1005, 1);
  const auto out = nmea::encode(m);
  CHECK(out.ec == errc::out_of_range);
  CHECK(out.field == 4);

  rpm bad_source;
  bad_source.source = static_cast<rpm_source>('X');
  CHECK(nmea::encode(bad_source).ec == errc::bad_enum);
  CHECK(nmea::encode(bad_source).field == 1);

  rpm bad_talker;
  bad_talker.talker = "i";
  CHECK(nmea::encode(bad_talker).ec == errc::bad_address);
}

// =============================================================================================
// RSA

TEST_CASE("RSA: twin rudders to port", "[rsa]") {
  const auto r = nmea::decode<rsa>("$AGRSA,-5.2,A,-4.8,A*4D\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.talker == "AG");
  CHECK(r.value.starboard_angle == decimal::scaled(-52, 1));
  CHECK(r.value.starboard_status == rsa_status::valid);
  CHECK(r.value.port_angle == decimal::scaled(-48, 1));
  CHECK(r.value.port_status == rsa_status::valid);
}

TEST_CASE("RSA: single rudder, port sensor blank and invalid", "[rsa]") {
  const auto r = nmea::decode<rsa>("$IIRSA,10.5,A,,V*4D\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.starboard_angle == decimal::scaled(105, 1));
  CHECK(r.value.starboard_status == rsa_status::valid);
  CHECK_FALSE(r.value.port_angle.has_value());
  CHECK(r.value.port_status == rsa_status::invalid);
  CHECK(nmea::encode(r.value).view() == "$IIRSA,10.5,A,,V*4D\r\n");
}

TEST_CASE("RSA: all blank", "[rsa]") {
  const auto r = nmea::decode<rsa>("$IIRSA,,,,*40\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK_FALSE(r.value.starboard_angle.has_value());
  CHECK_FALSE(r.value.starboard_status.has_value());
  CHECK_FALSE(r.value.port_angle.has_value());
  CHECK_FALSE(r.value.port_status.has_value());
  CHECK(nmea::encode(r.value).view() == "$IIRSA,,,,*40\r\n");
}

TEST_CASE("RSA: any talker, kept on re-encode", "[rsa]") {
  for (const auto t : talkers) {
    const std::string text = sealed(std::string(t) + "RSA,3.5,A,-2.0,V");
    const auto r = nmea::decode<rsa>(text);
    INFO(text);
    REQUIRE(r.ec == errc::ok);
    CHECK(r.value.talker == t);
    CHECK(r.value.port_angle == decimal::scaled(-20, 1));
    CHECK(nmea::encode(r.value).view() == text);
  }
}

TEST_CASE("RSA: malformed input, errc and field number", "[rsa]") {
  const bad_case cases[] = {
      {"IIRSA,1O.5,A,,V", errc::bad_number, 1},       {"IIRSA,10.5.1,A,,V", errc::bad_number, 1},
      {"IIRSA,180.1,A,,V", errc::out_of_range, 1},    {"IIRSA,10.5,X,,V", errc::bad_enum, 2},
      {"IIRSA,10.5,a,,V", errc::bad_enum, 2},         {"IIRSA,10.5,A,--1,V", errc::bad_number, 3},
      {"IIRSA,10.5,A,-181,V", errc::out_of_range, 3}, {"IIRSA,10.5,A,,N", errc::bad_enum, 4},
  };
  for (const auto& c : cases) check_bad<rsa>(c);
  check_bad<rsa>({"IIRSA,10.5,A,,V,", errc::too_many_fields, 5}, nmea::parse_policy::strict());
}

TEST_CASE("RSA: a sentence that stops early leaves the rest blank", "[rsa]") {
  // The message layer's rule for optional fields when receiving liberally: fields past the end
  // of the sentence read as blank. Only a value that lost its unit letter is an error (see VHW).
  const auto r = nmea::decode<rsa>(sealed("IIRSA,10.5,A"));
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.starboard_angle == decimal::scaled(105, 1));
  CHECK_FALSE(r.value.port_angle.has_value());
  CHECK_FALSE(r.value.port_status.has_value());
  // Written back complete.
  CHECK(nmea::encode(r.value).view() == sealed("IIRSA,10.5,A,,"));
  // The strict policy (send-side rules) wants all four fields.
  const auto strict = nmea::decode<rsa>(sealed("IIRSA,10.5,A"), nmea::parse_policy::strict());
  CHECK(strict.ec == errc::too_few_fields);
  CHECK(strict.field == 3);
}

// =============================================================================================
// VHW

TEST_CASE("VHW: heading and speed through water", "[vhw]") {
  const auto r = nmea::decode<vhw>("$VWVHW,45.0,T,31.3,M,5.20,N,9.63,K*5F\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.talker == "VW");
  CHECK(r.value.heading_true_deg == decimal::scaled(450, 1));
  CHECK(r.value.heading_magnetic_deg == decimal::scaled(313, 1));
  CHECK(r.value.speed_knots == decimal::scaled(520, 2));
  CHECK(r.value.speed_kmh == decimal::scaled(963, 2));
}

TEST_CASE("VHW: zero-padded headings keep their padding", "[vhw]") {
  // Many compasses write three integer digits; decimal remembers the width it was given.
  const auto r = nmea::decode<vhw>("$VWVHW,045.0,T,031.3,M,5.20,N,9.63,K*5F\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.heading_true_deg->compare(decimal::scaled(450, 1)) == 0);
  CHECK(r.value.heading_true_deg->int_width == 3);
  CHECK(r.value.heading_magnetic_deg->to_double() == 31.3);
  CHECK(nmea::encode(r.value).view() == "$VWVHW,045.0,T,031.3,M,5.20,N,9.63,K*5F\r\n");
}

TEST_CASE("VHW: speed log without a compass: blank headings", "[vhw]") {
  const auto r = nmea::decode<vhw>("$IIVHW,,T,,M,5.2,N,9.6,K*5D\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK_FALSE(r.value.heading_true_deg.has_value());
  CHECK_FALSE(r.value.heading_magnetic_deg.has_value());
  CHECK(r.value.speed_knots == decimal::scaled(52, 1));
  CHECK(r.value.speed_kmh == decimal::scaled(96, 1));
  CHECK(nmea::encode(r.value).view() == "$IIVHW,,T,,M,5.2,N,9.6,K*5D\r\n");
}

TEST_CASE("VHW: all blank, unit letters blank too", "[vhw]") {
  const auto r = nmea::decode<vhw>("$IIVHW,,,,,,,,*49\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK_FALSE(r.value.heading_true_deg.has_value());
  CHECK_FALSE(r.value.heading_magnetic_deg.has_value());
  CHECK_FALSE(r.value.speed_knots.has_value());
  CHECK_FALSE(r.value.speed_kmh.has_value());
  // Written back as it came: the letters that came blank beside blank values stay blank.
  CHECK(r.value.blank_units == 0b1'0101'0100U);  // wire fields 2, 4, 6 and 8
  CHECK(nmea::encode(r.value).view() == "$IIVHW,,,,,,,,*49\r\n");
  // A message built in code has its letters written; so has a value given later.
  vhw built;
  built.talker = "II";
  CHECK(nmea::encode(built).view() == sealed("IIVHW,,T,,M,,N,,K"));
  vhw later = r.value;
  later.speed_knots = decimal::scaled(52, 1);
  CHECK(nmea::encode(later).view() == sealed("IIVHW,,,,,5.2,N,,"));
}

TEST_CASE("VHW: any talker, kept on re-encode", "[vhw]") {
  for (const auto t : talkers) {
    const std::string text = sealed(std::string(t) + "VHW,271.4,T,,M,3.05,N,5.65,K");
    const auto r = nmea::decode<vhw>(text);
    INFO(text);
    REQUIRE(r.ec == errc::ok);
    CHECK(r.value.talker == t);
    CHECK(r.value.heading_true_deg == decimal::scaled(2714, 1));
    CHECK(nmea::encode(r.value).view() == text);
  }
}

TEST_CASE("VHW: malformed input, errc and field number", "[vhw]") {
  const bad_case cases[] = {
      {"VWVHW,45.0,M,31.3,M,5.2,N,9.6,K", errc::bad_unit, 2},  // true heading marked magnetic
      {"VWVHW,45.0,t,31.3,M,5.2,N,9.6,K", errc::bad_unit, 2},
      {"VWVHW,45.0,T,31.3,T,5.2,N,9.6,K", errc::bad_unit, 4},
      {"VWVHW,45.0,T,31.3,M,5.2,K,9.6,K", errc::bad_unit, 6},  // knots marked km/h
      {"VWVHW,45.0,T,31.3,M,5.2,N,9.6,N", errc::bad_unit, 8},
      {"VWVHW,,X,,M,5.2,N,9.6,K", errc::bad_unit, 2},  // a wrong letter even without a value
      {"VWVHW,45.0,TT,31.3,M,5.2,N,9.6,K", errc::bad_unit, 2},
      {"VWVHW,4x.0,T,31.3,M,5.2,N,9.6,K", errc::bad_number, 1},
      {"VWVHW,45.0,T,31.3,M,5..2,N,9.6,K", errc::bad_number, 5},
      {"VWVHW,360.1,T,31.3,M,5.2,N,9.6,K", errc::out_of_range, 1},
      {"VWVHW,-0.5,T,31.3,M,5.2,N,9.6,K", errc::out_of_range, 1},
      {"VWVHW,45.0,T,400,M,5.2,N,9.6,K", errc::out_of_range, 3},
      {"VWVHW,45.0,T,31.3,M,-5.2,N,9.6,K", errc::out_of_range, 5},  // VHW speed has no sign
      {"VWVHW,45.0,T,31.3,M,5.2,N,-9.6,K", errc::out_of_range, 7},
      {"VWVHW,45.0", errc::too_few_fields, 2},  // a value that lost its unit letter
      {"VWVHW,45.0,T,31.3,M,5.2", errc::too_few_fields, 6},
  };
  for (const auto& c : cases) check_bad<vhw>(c);
  check_bad<vhw>({"VWVHW,45.0,T,31.3,M,5.2,N,9.6,K,", errc::too_many_fields, 9},
                 nmea::parse_policy::strict());
}

TEST_CASE("VHW: a value and its unit letter are one field of the description", "[vhw]") {
  CHECK(nmea::field_name<vhw>(1) == "heading_true_deg");
  CHECK(nmea::field_name<vhw>(2) == "heading_true_deg");
  CHECK(nmea::field_name<vhw>(6) == "speed_knots");
  CHECK(nmea::field_name<vhw>(8) == "speed_kmh");
  CHECK(nmea::field_name<vhw>(9).empty());
}

// =============================================================================================
// VBW

TEST_CASE("VBW: the two forms only, when written and when strict", "[vbw]") {
  // One stern value: the NMEA 3.0 form, all four stern fields.
  vbw m;
  m.talker = "VD";
  m.longitudinal_water_knots = decimal(1);
  m.stern_transverse_water_knots = decimal::scaled(5, 1);
  CHECK(nmea::encode(m).view() == "$VDVBW,1,,,,,,0.5,,,*4B\r\n");
  m.stern_transverse_water_knots.reset();
  m.stern_ground_status = vbw_status::valid;
  CHECK(nmea::encode(m).view() == "$VDVBW,1,,,,,,,,,A*21\r\n");
  m.stern_ground_status.reset();
  CHECK(nmea::encode(m).view() == "$VDVBW,1,,,,,*60\r\n");
  // Strict reading takes 6 and 10 fields; 7 to 9 are a sentence cut short.
  const auto strict = nmea::parse_policy::strict();
  CHECK(nmea::decode<vbw>("$VDVBW,1,,,,,*60\r\n", strict));
  CHECK(nmea::decode<vbw>("$VDVBW,1,,,,,,0.5,,,*4B\r\n", strict));
  const auto seven = nmea::decode<vbw>("$VDVBW,1,,,,,,0.5*67\r\n", strict);
  CHECK(seven.ec == errc::too_few_fields);
  CHECK(seven.field == 8);
  CHECK(seven.column == 17);
  // The default reading takes them, as the fields they have.
  const auto liberal = nmea::decode<vbw>("$VDVBW,1,,,,,,0.5*67\r\n");
  REQUIRE(liberal);
  CHECK(liberal.value.stern_transverse_water_knots == decimal::scaled(5, 1));
}

TEST_CASE("VBW: water and ground speeds along and across the hull", "[vbw]") {
  const auto r = nmea::decode<vbw>("$VDVBW,4.91,-0.12,A,5.02,0.08,A*7C\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.talker == "VD");
  CHECK(r.value.longitudinal_water_knots == decimal::scaled(491, 2));
  CHECK(r.value.transverse_water_knots == decimal::scaled(-12, 2));  // to port
  CHECK(r.value.water_status == vbw_status::valid);
  CHECK(r.value.longitudinal_ground_knots == decimal::scaled(502, 2));
  CHECK(r.value.transverse_ground_knots == decimal::scaled(8, 2));
  CHECK(r.value.ground_status == vbw_status::valid);
  CHECK_FALSE(r.value.stern_transverse_water_knots.has_value());
  CHECK_FALSE(r.value.stern_ground_status.has_value());
  // The 6-field form stays 6 fields.
  CHECK(nmea::encode(r.value).view() == "$VDVBW,4.91,-0.12,A,5.02,0.08,A*7C\r\n");
}

TEST_CASE("VBW: the NMEA 3.0 form with stern speeds", "[vbw]") {
  const auto r = nmea::decode<vbw>("$VDVBW,4.91,-0.12,A,5.02,0.08,A,0.05,A,0.04,A*7D\r\n",
                                   nmea::parse_policy::strict());
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.stern_transverse_water_knots == decimal::scaled(5, 2));
  CHECK(r.value.stern_water_status == vbw_status::valid);
  CHECK(r.value.stern_transverse_ground_knots == decimal::scaled(4, 2));
  CHECK(r.value.stern_ground_status == vbw_status::valid);
  CHECK(nmea::encode(r.value).view() == "$VDVBW,4.91,-0.12,A,5.02,0.08,A,0.05,A,0.04,A*7D\r\n");

  // One stern value set: the NMEA 3.0 form, the other stern fields blank.
  vbw m;
  m.stern_transverse_water_knots = decimal::scaled(-3, 1);
  CHECK(nmea::encode(m).view() == sealed("VWVBW,,,,,,,-0.3,,,"));
}

TEST_CASE("VBW: water speed only, ground blank and invalid", "[vbw]") {
  const auto r = nmea::decode<vbw>("$VWVBW,2.3,,A,,,V*7A\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.longitudinal_water_knots == decimal::scaled(23, 1));
  CHECK_FALSE(r.value.transverse_water_knots.has_value());
  CHECK(r.value.water_status == vbw_status::valid);
  CHECK_FALSE(r.value.longitudinal_ground_knots.has_value());
  CHECK(r.value.ground_status == vbw_status::invalid);
  CHECK(nmea::encode(r.value).view() == "$VWVBW,2.3,,A,,,V*7A\r\n");
}

TEST_CASE("VBW: all blank, and a negative zero that keeps its sign", "[vbw]") {
  const std::string blank = sealed("VWVBW,,,,,,");
  const auto r = nmea::decode<vbw>(blank);
  REQUIRE(r.ec == errc::ok);
  CHECK_FALSE(r.value.longitudinal_water_knots.has_value());
  CHECK_FALSE(r.value.water_status.has_value());
  CHECK_FALSE(r.value.ground_status.has_value());
  CHECK(nmea::encode(r.value).view() == blank);

  const std::string zero = sealed("VWVBW,-0.0,0.00,A,,,V");
  const auto z = nmea::decode<vbw>(zero);
  REQUIRE(z.ec == errc::ok);
  CHECK(z.value.longitudinal_water_knots->negative);
  CHECK(z.value.longitudinal_water_knots->is_zero());
  CHECK(nmea::encode(z.value).view() == zero);
}

TEST_CASE("VBW: any talker, kept on re-encode", "[vbw]") {
  for (const auto t : talkers) {
    const std::string text = sealed(std::string(t) + "VBW,1.5,0.0,A,1.6,-0.1,A");
    const auto r = nmea::decode<vbw>(text);
    INFO(text);
    REQUIRE(r.ec == errc::ok);
    CHECK(r.value.talker == t);
    CHECK(r.value.transverse_ground_knots == decimal::scaled(-1, 1));
    CHECK(nmea::encode(r.value).view() == text);
  }
}

TEST_CASE("VBW: malformed input, errc and field number", "[vbw]") {
  const bad_case cases[] = {
      {"VWVBW,x,0.0,A,0.0,0.0,A", errc::bad_number, 1},
      {"VWVBW,0.0,0,0,A,0.0,0.0,A", errc::bad_enum, 3},  // a comma for a point shifts the fields
      {"VWVBW,0.0,0.0,X,0.0,0.0,A", errc::bad_enum, 3},
      {"VWVBW,0.0,0.0,A,0.0.0,0.0,A", errc::bad_number, 4},
      {"VWVBW,0.0,0.0,A,0.0,+-1,A", errc::bad_number, 5},
      {"VWVBW,0.0,0.0,A,0.0,0.0,1", errc::bad_enum, 6},
      {"VWVBW,0.0,0.0,A,0.0,0.0,A,0.1,B", errc::bad_enum, 8},
      {"VWVBW,0.0,0.0,A,0.0,0.0,A,0.1,A,0.2,Z", errc::bad_enum, 10},
      {"VWVBW,12345678901234567890,0.0,A,,,V", errc::number_too_long, 1},
  };
  for (const auto& c : cases) check_bad<vbw>(c);
  check_bad<vbw>({"VWVBW,0.0,0.0,A,0.0,0.0,A,0.1,A,0.2,A,", errc::too_many_fields, 11},
                 nmea::parse_policy::strict());
}

// =============================================================================================
// VWR

TEST_CASE("VWR: apparent wind on the port bow", "[vwr]") {
  const auto r = nmea::decode<vwr>("$WIVWR,45.0,L,12.6,N,6.5,M,23.3,K*7C\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.talker == "WI");
  CHECK(r.value.angle_deg == decimal::scaled(450, 1));
  CHECK(r.value.side == bow_side::left);
  CHECK(r.value.signed_angle_deg() == -45.0);
  CHECK(r.value.speed_knots == decimal::scaled(126, 1));
  CHECK(r.value.speed_mps == decimal::scaled(65, 1));
  CHECK(r.value.speed_kmh == decimal::scaled(233, 1));
}

TEST_CASE("VWR: only m/s filled, wind from starboard", "[vwr]") {
  const std::string text = sealed("IIVWR,120.5,R,,N,8.2,M,,K");
  const auto r = nmea::decode<vwr>(text);
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.side == bow_side::right);
  CHECK(r.value.signed_angle_deg() == 120.5);
  CHECK_FALSE(r.value.speed_knots.has_value());
  CHECK(r.value.speed_mps == decimal::scaled(82, 1));
  CHECK_FALSE(r.value.speed_kmh.has_value());
  CHECK(nmea::encode(r.value).view() == text);
}

TEST_CASE("VWR: all blank", "[vwr]") {
  const auto r = nmea::decode<vwr>("$IIVWR,,,,N,,M,,K*1B\r\n");
  REQUIRE(r.ec == errc::ok);
  CHECK_FALSE(r.value.angle_deg.has_value());
  CHECK_FALSE(r.value.side.has_value());
  CHECK_FALSE(r.value.signed_angle_deg().has_value());
  CHECK_FALSE(r.value.speed_mps.has_value());
  CHECK(nmea::encode(r.value).view() == "$IIVWR,,,,N,,M,,K*1B\r\n");
}

TEST_CASE("VWR: any talker, kept on re-encode", "[vwr]") {
  for (const auto t : talkers) {
    const std::string text = sealed(std::string(t) + "VWR,90,R,10.0,N,5.1,M,18.5,K");
    const auto r = nmea::decode<vwr>(text);
    INFO(text);
    REQUIRE(r.ec == errc::ok);
    CHECK(r.value.talker == t);
    CHECK(r.value.angle_deg == decimal(90));
    CHECK(nmea::encode(r.value).view() == text);
  }
}

TEST_CASE("VWR: malformed input, errc and field number", "[vwr]") {
  const bad_case cases[] = {
      {"WIVWR,180.5,L,12.6,N,6.5,M,23.3,K", errc::out_of_range, 1},  // angle is 0-180
      {"WIVWR,-45,L,12.6,N,6.5,M,23.3,K", errc::out_of_range, 1},    // the sign is field 2
      {"WIVWR,4 5,L,12.6,N,6.5,M,23.3,K", errc::bad_number, 1},
      {"WIVWR,45.0,P,12.6,N,6.5,M,23.3,K", errc::bad_enum, 2},
      {"WIVWR,45.0,l,12.6,N,6.5,M,23.3,K", errc::bad_enum, 2},
      {"WIVWR,45.0,L,12.6,M,6.5,M,23.3,K", errc::bad_unit, 4},
      {"WIVWR,45.0,L,12.6,N,6.5,N,23.3,K", errc::bad_unit, 6},
      {"WIVWR,45.0,L,12.6,N,6.5,M,23.3,M", errc::bad_unit, 8},
      {"WIVWR,45.0,L,-12.6,N,6.5,M,23.3,K", errc::out_of_range, 3},
      {"WIVWR,45.0,L,12.6,N,6,5,M,23.3,K", errc::bad_unit, 6},  // comma for a point
      {"WIVWR,45.0,L,12.6", errc::too_few_fields, 4},
  };
  for (const auto& c : cases) check_bad<vwr>(c);
  check_bad<vwr>({"WIVWR,45.0,L,12.6,N,6.5,M,23.3,K,", errc::too_many_fields, 9},
                 nmea::parse_policy::strict());
}
