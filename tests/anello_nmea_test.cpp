// SPDX-License-Identifier: BSL-1.0
// The NMEA side of the ANELLO Maritime INS: $PAPGPSCTRL, the input set and its policy, the SI
// helpers that build VHW/VBW, and the RMC the INS outputs.

#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <variant>

#include "seawire/anello/gpsctrl.hpp"
#include "seawire/anello/inputs.hpp"
#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/heading.hpp"
#include "seawire/nmea/message.hpp"

#include "support.hpp"

namespace {

using namespace support;

using namespace seawire;
using seawire::anello::gps_control;
using seawire::anello::papgpsctrl;
using seawire::nmea::decimal;

template <class T>
constexpr bool round_trips(std::string_view text,
                           const nmea::parse_policy& policy = nmea::parse_policy::strict()) {
  const auto r = nmea::decode<T>(text, policy);
  return r && nmea::encode(r.value).view() == text;
}

/// Decode with the set, encode whatever came out, compare bytes.
template <class Set>
std::string reencode(const typename Set::variant& v) {
  return std::visit(
      [](const auto& m) -> std::string {
        if constexpr (std::is_same_v<std::decay_t<decltype(m)>, nmea::unknown_sentence>) {
          return "unknown";
        } else {
          return std::string(nmea::encode(m).view());
        }
      },
      v);
}

using support::infinity;
using support::not_a_number;

// The verified ANELLO vectors, byte for byte, at compile time.
static_assert(nmea::checksum("PAPGPSCTRL,1") == 0x11);
static_assert(nmea::checksum("PAPGPSCTRL,0") == 0x10);
static_assert(nmea::checksum("PAPGPSCTRL,2") == 0x12);
static_assert(nmea::checksum("VMVBW,0.0,0.0,A,0.0,0.0,A") == 0x58);
static_assert(round_trips<papgpsctrl>("$PAPGPSCTRL,1*11\r\n"));
static_assert(round_trips<papgpsctrl>("$PAPGPSCTRL,0*10\r\n"));
static_assert(round_trips<papgpsctrl>("$PAPGPSCTRL,2*12\r\n"));
static_assert(round_trips<standard::vbw>("$VMVBW,0.0,0.0,A,0.0,0.0,A*58\r\n"));
static_assert(nmea::decode<papgpsctrl>("$PAPGPSCTRL,1*11\r\n").value.control == gps_control::use);
static_assert(nmea::encode(papgpsctrl{gps_control::ignore}).view() == "$PAPGPSCTRL,0*10\r\n");

// The SI helpers are constexpr too.
static_assert([] {
  anello::vhw_si in;
  in.heading_true_deg = 87.3;
  in.speed_mps = 2.4;
  return nmea::encode(anello::make_vhw(in).value).view() == "$VWVHW,87.3,T,,M,4.67,N,8.64,K*49\r\n";
}());

// The RMC forms an INS sends.
static_assert(nmea::checksum("GNRMC,154258.00,A,3249.72026,N,11713.79556,W,0.05,89.00,030724,,") ==
              0x06);
static_assert(round_trips<standard::rmc>(
    "$GNRMC,154258.00,A,3249.72026,N,11713.79556,W,0.05,89.00,030724,,*06\r\n"));
static_assert(round_trips<standard::rmc>(
    "$GNRMC,154258.00,A,3249.72026,N,11713.79556,W,0.05,89.00,030724,,,A*6B\r\n"));
static_assert(round_trips<standard::rmc>(
    "$INRMC,154258.000,A,3249.72026,N,11713.79556,W,0.05,89.00,030724,12.3,E,E,C*65\r\n"));
static_assert(round_trips<standard::rmc>("$INRMC,,V,,,,,,,,,,N*43\r\n"));

}  // namespace

// =============================================================================================
// $PAPGPSCTRL

TEST_CASE("PAPGPSCTRL: the three values", "[anello][papgpsctrl]") {
  const auto use = nmea::decode<papgpsctrl>("$PAPGPSCTRL,1*11\r\n");
  REQUIRE(use.ec == errc::ok);
  CHECK(use.value.control == gps_control::use);
  CHECK(nmea::encode(use.value).view() == "$PAPGPSCTRL,1*11\r\n");

  const auto ignore = nmea::decode<papgpsctrl>("$PAPGPSCTRL,0*10\r\n");
  REQUIRE(ignore.ec == errc::ok);
  CHECK(ignore.value.control == gps_control::ignore);
  CHECK(nmea::encode(ignore.value).view() == "$PAPGPSCTRL,0*10\r\n");

  // Not in the spec; ANELLO's scripts send it to switch the internal GPS off.
  const auto off = nmea::decode<papgpsctrl>("$PAPGPSCTRL,2*12\r\n");
  REQUIRE(off.ec == errc::ok);
  CHECK(off.value.control == gps_control::disable_internal);
  CHECK(nmea::encode(off.value).view() == "$PAPGPSCTRL,2*12\r\n");

  // The default is the INS's default.
  CHECK(nmea::encode(papgpsctrl{}).view() == "$PAPGPSCTRL,1*11\r\n");
  CHECK(nmea::field_name<papgpsctrl>(1) == "control");
}

TEST_CASE("PAPGPSCTRL: malformed input, errc and field number", "[anello][papgpsctrl]") {
  const bad_case cases[] = {
      {"PAPGPSCTRL,3", errc::bad_enum, 1},     {"PAPGPSCTRL,01", errc::bad_enum, 1},
      {"PAPGPSCTRL,1.0", errc::bad_enum, 1},   {"PAPGPSCTRL,-1", errc::bad_enum, 1},
      {"PAPGPSCTRL,Y", errc::bad_enum, 1},     {"PAPGPSCTRL,", errc::missing_field, 1},
      {"PAPGPSCTRL", errc::too_few_fields, 1},
  };
  for (const auto& c : cases) check_bad<papgpsctrl>(c, anello::input_policy);
  const auto extra =
      nmea::decode<papgpsctrl>(sealed("PAPGPSCTRL,1,0"), nmea::parse_policy::strict());
  CHECK(extra.ec == errc::too_many_fields);
  CHECK(extra.field == 2);
  // The INS's own policy ignores trailing fields.
  CHECK(nmea::decode<papgpsctrl>(sealed("PAPGPSCTRL,1,0"), anello::input_policy).value.control ==
        gps_control::use);

  // The address is matched whole: neither a shorter nor a longer one is PAPGPSCTRL.
  CHECK(nmea::decode<papgpsctrl>(sealed("PAPGPSCTR,1")).ec == errc::wrong_address);
  CHECK(nmea::decode<papgpsctrl>(sealed("PAPGPSCTRLX,1")).ec == errc::wrong_address);
  CHECK(nmea::decode<papgpsctrl>(sealed("XXGPSCTRL,1")).ec == errc::wrong_address);
}

TEST_CASE("PAPGPSCTRL: the encoder refuses a value that is not one of the three",
          "[anello][papgpsctrl]") {
  const auto out = nmea::encode(papgpsctrl{static_cast<gps_control>('5')});
  CHECK(out.ec == errc::bad_enum);
  CHECK(out.field == 1);
  CHECK(out.view().empty());
}

// =============================================================================================
// The input set and its policy

TEST_CASE("nmea_inputs: each input from any talker, re-encoded byte for byte", "[anello]") {
  struct input {
    std::string body;
    std::size_t index;  // in nmea_inputs::variant (0 = unknown_sentence)
  };
  const input inputs[] = {
      {"ERRPM,E,1,1500.0,,A", 1},
      {"IIRPM,S,2,-300,-40.5,A", 1},
      {"AGRSA,12.0,A,11.5,A", 2},
      {"IIRSA,-3.5,A,,V", 2},
      {"VWVHW,087.3,T,,M,4.67,N,8.64,K", 3},
      {"INVHW,,T,,M,0.00,N,0.00,K", 3},
      {"VMVBW,0.0,0.0,A,0.0,0.0,A", 4},
      {"VDVBW,4.86,-0.19,A,4.90,-0.22,A", 4},
      {"GPVBW,4.86,-0.19,A,,,V", 4},
      {"WIVWR,30.0,R,15.0,N,7.7,M,27.8,K", 5},
      {"IIVWR,170,L,,N,3.0,M,,K", 5},
      {"PAPGPSCTRL,1", 6},
      {"PAPGPSCTRL,2", 6},
  };
  for (const auto& in : inputs) {
    const std::string text = sealed(in.body);
    INFO(text);
    const auto r = anello::decode_input(text);
    REQUIRE(r.ec == errc::ok);
    CHECK(r.value.index() == in.index);
    CHECK(reencode<anello::nmea_inputs>(r.value) == text);
  }
}

TEST_CASE("nmea_inputs: the ANELLO vectors through the set and its policy", "[anello]") {
  // Runtime only: clang 14 cannot switch a std::variant's member in a constant expression.
  const auto vbw = anello::decode_input("$VMVBW,0.0,0.0,A,0.0,0.0,A*58\r\n");
  REQUIRE(vbw.ec == errc::ok);
  const auto* m = std::get_if<standard::vbw>(&vbw.value);
  REQUIRE(m != nullptr);
  CHECK(m->talker == "VM");
  CHECK(m->longitudinal_water_knots == decimal::scaled(0, 1));
  CHECK(m->water_status == standard::vbw_status::valid);
  CHECK(m->ground_status == standard::vbw_status::valid);
  CHECK(nmea::encode(*m).view() == "$VMVBW,0.0,0.0,A,0.0,0.0,A*58\r\n");

  const auto ignore = anello::decode_input("$PAPGPSCTRL,0*10");
  REQUIRE(ignore.ec == errc::ok);
  const auto* c = std::get_if<papgpsctrl>(&ignore.value);
  REQUIRE(c != nullptr);
  CHECK(c->control == gps_control::ignore);
}

TEST_CASE("nmea_inputs: what the INS does not take is not an error", "[anello]") {
  const std::string gga =
      "$GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,M,-33.2,M,,*5C";
  const auto r = anello::decode_input(gga);
  REQUIRE(r.ec == errc::ok);
  const auto* u = std::get_if<nmea::unknown_sentence>(&r.value);
  REQUIRE(u != nullptr);
  CHECK(u->sentence.address == "GPGGA");

  STATIC_REQUIRE(anello::nmea_inputs::knows("VMVBW"));
  STATIC_REQUIRE(anello::nmea_inputs::knows("IIVHW"));
  STATIC_REQUIRE(anello::nmea_inputs::knows("PAPGPSCTRL"));
  STATIC_REQUIRE_FALSE(anello::nmea_inputs::knows("GPRMC"));
  STATIC_REQUIRE_FALSE(anello::nmea_inputs::knows("VBW"));  // a talker is part of the address
  CHECK(anello::nmea_inputs::field_name("VMVBW", 3) == "water_status");
  CHECK(anello::nmea_inputs::field_name("IIVHW", 6) == "speed_knots");
  CHECK(anello::nmea_inputs::field_name("ERRPM", 4) == "pitch_percent");
  CHECK(anello::nmea_inputs::field_name("WIVWR", 2) == "side");
}

TEST_CASE("nmea_inputs: a bad field is reported with its number", "[anello]") {
  const auto vhw = anello::decode_input(sealed("VWVHW,87.3,M,,M,4.67,N,8.64,K"));
  CHECK(vhw.ec == errc::bad_unit);
  CHECK(vhw.field == 2);
  CHECK(anello::nmea_inputs::field_name("VWVHW", vhw.field) == "heading_true_deg");

  const auto vbw = anello::decode_input(sealed("VMVBW,0.0,0.0,X,0.0,0.0,A"));
  CHECK(vbw.ec == errc::bad_enum);
  CHECK(vbw.field == 3);

  const auto ctl = anello::decode_input(sealed("PAPGPSCTRL,9"));
  CHECK(ctl.ec == errc::bad_enum);
  CHECK(ctl.field == 1);
}

TEST_CASE("input_policy: checksum required, otherwise liberal", "[anello][policy]") {
  // RS-232 has no error check of its own: a sentence without a checksum is refused.
  const auto bare = anello::decode_input("$VMVBW,0.0,0.0,A,0.0,0.0,A\r\n");
  CHECK(bare.ec == errc::missing_checksum);
  // ... which the library's default receiver would have taken.
  CHECK(nmea::decode<standard::vbw>("$VMVBW,0.0,0.0,A,0.0,0.0,A\r\n").ec == errc::ok);

  CHECK(anello::decode_input("$PAPGPSCTRL,1*10\r\n").ec == errc::checksum_mismatch);
  CHECK(anello::decode_input("$PAPGPSCTRL,1*\r\n").ec == errc::bad_checksum_format);
  // Lower-case hex, LF only, no line ending at all (a UDP datagram): all accepted.
  CHECK(anello::decode_input("$IIRSA,10.5,A,,V*4d\r\n").ec == errc::ok);
  CHECK(anello::decode_input("$PAPGPSCTRL,1*11\n").ec == errc::ok);
  CHECK(anello::decode_input("$PAPGPSCTRL,1*11").ec == errc::ok);
  // Fields a later NMEA version appends are ignored.
  const auto longer = anello::decode_input(sealed("VWVHW,87.3,T,,M,4.67,N,8.64,K,extra"));
  CHECK(longer.ec == errc::ok);
  CHECK(std::get_if<standard::vhw>(&longer.value) != nullptr);

  STATIC_REQUIRE(anello::input_policy.checksum == nmea::checksum_policy::required);
  STATIC_REQUIRE(anello::output_policy.checksum == nmea::checksum_policy::required);
}

// =============================================================================================
// SI values to VHW and VBW

TEST_CASE("make_vhw: m/s to knots and km/h, headings in degrees", "[anello][si]") {
  anello::vhw_si in;
  in.heading_true_deg = 87.3;
  in.heading_magnetic_deg = 75.04;
  in.speed_mps = 2.4;  // 4.6652 kn, 8.64 km/h
  const auto r = anello::make_vhw(in);
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.talker == "VW");
  CHECK(r.value.heading_true_deg == decimal::scaled(873, 1));
  CHECK(r.value.heading_magnetic_deg == decimal::scaled(750, 1));
  CHECK(r.value.speed_knots == decimal::scaled(467, 2));
  CHECK(r.value.speed_kmh == decimal::scaled(864, 2));
  CHECK(nmea::encode(r.value).view() == sealed("VWVHW,87.3,T,75.0,M,4.67,N,8.64,K"));

  // One knot is 1852 m per hour, exactly.
  anello::vhw_si knot;
  knot.speed_mps = 1852.0 / 3600.0;
  const auto k = anello::make_vhw(knot);
  REQUIRE(k.ec == errc::ok);
  CHECK(k.value.speed_knots == decimal::scaled(100, 2));
  CHECK(k.value.speed_kmh == decimal::scaled(185, 2));  // 1.852 km/h
  CHECK_FALSE(k.value.heading_true_deg.has_value());
  CHECK(nmea::encode(k.value).view() == sealed("VWVHW,,T,,M,1.00,N,1.85,K"));

  anello::vhw_si fast;
  fast.speed_mps = 10.0;
  fast.speed_places = 3;
  fast.talker = "IN";
  const auto f = anello::make_vhw(fast);
  CHECK(f.value.speed_knots == decimal::scaled(19438, 3));  // 19.4384...
  CHECK(f.value.speed_kmh == decimal::scaled(36000, 3));
  CHECK(f.value.talker == "IN");

  // Decoded back to m/s.
  const auto back = anello::speed_through_water_mps(f.value);
  REQUIRE(back.has_value());
  CHECK(*back == Approx(10.0).margin(0.0003));
  standard::vhw kmh_only;
  kmh_only.speed_kmh = decimal::scaled(36, 0);
  CHECK(anello::speed_through_water_mps(kmh_only) == 10.0);
  CHECK_FALSE(anello::speed_through_water_mps(standard::vhw{}).has_value());
}

TEST_CASE("make_vhw: headings wrap into [0, 360)", "[anello][si]") {
  const auto heading = [](double deg) {
    anello::vhw_si in;
    in.heading_true_deg = deg;
    const auto r = anello::make_vhw(in);
    REQUIRE(r.ec == errc::ok);
    return *r.value.heading_true_deg;
  };
  CHECK(heading(-92.5) == decimal::scaled(2675, 1));
  CHECK(heading(-180.0) == decimal::scaled(1800, 1));
  CHECK(heading(360.0) == decimal::scaled(0, 1));
  CHECK(heading(359.96) == decimal::scaled(0, 1));  // rounds to 360.0, which is north
  CHECK(heading(359.94) == decimal::scaled(3599, 1));
  CHECK(heading(720.25) == decimal::scaled(3, 1));
  CHECK(heading(-0.0) == decimal::scaled(0, 1));
  CHECK_FALSE(heading(-0.0).negative);
}

TEST_CASE("wrap_heading: any double heading into [0, 360) at a field's places") {
  using nmea::wrap_heading;
  CHECK(wrap_heading(-0.3, 1).value == decimal::scaled(3597, 1));
  CHECK(wrap_heading(359.996, 2).value == decimal::scaled(0, 2));  // 360.00 is north
  CHECK(wrap_heading(359.994, 2).value == decimal::scaled(35999, 2));
  CHECK(wrap_heading(-360.0, 0).value == decimal::scaled(0, 0));
  CHECK(wrap_heading(1085.5, 3).value == decimal::scaled(5500, 3));
  CHECK(wrap_heading(-1e12, 0).value == decimal::scaled(80, 0));  // -1e12 = -2777777778 turns + 80
  CHECK(wrap_heading(1.001e12, 0).ec == errc::out_of_range);
  CHECK(wrap_heading(-infinity, 1).ec == errc::not_finite);
  CHECK(wrap_heading(not_a_number, 1).ec == errc::not_finite);
  CHECK(wrap_heading(10.0, 20).ec == errc::value_too_large);
}

TEST_CASE("make_vhw: refusals name the wire field", "[anello][si]") {
  struct bad {
    anello::vhw_si in;
    errc ec;
    std::uint16_t field;
  };
  anello::vhw_si nan_heading;
  nan_heading.heading_true_deg = not_a_number;
  anello::vhw_si huge_heading;
  huge_heading.heading_true_deg = 1e13;
  anello::vhw_si inf_magnetic;
  inf_magnetic.heading_magnetic_deg = -infinity;
  anello::vhw_si astern;
  astern.speed_mps = -0.5;  // VHW has no sign
  anello::vhw_si nan_speed;
  nan_speed.speed_mps = not_a_number;
  anello::vhw_si inf_speed;
  inf_speed.speed_mps = infinity;
  const bad cases[] = {
      {nan_heading, errc::not_finite, 1},  {huge_heading, errc::out_of_range, 1},
      {inf_magnetic, errc::not_finite, 3}, {astern, errc::out_of_range, 5},
      {nan_speed, errc::not_finite, 5},    {inf_speed, errc::not_finite, 5},
  };
  for (const auto& c : cases) {
    const auto r = anello::make_vhw(c.in);
    CHECK(name(r.ec) == name(c.ec));
    CHECK(r.field == c.field);
  }

  // A speed that rounds to zero is zero, not an error and not "-0.00".
  anello::vhw_si creep;
  creep.speed_mps = -0.001;
  const auto z = anello::make_vhw(creep);
  REQUIRE(z.ec == errc::ok);
  CHECK(nmea::encode(z.value).view() == sealed("VWVHW,,T,,M,0.00,N,0.00,K"));
}

TEST_CASE("make_vbw: body-frame speeds, m/s to knots, status from what is given", "[anello][si]") {
  anello::vbw_si water;
  water.longitudinal_water_mps = 2.5;  // 4.8596 kn
  water.transverse_water_mps = -0.1;   // to port, 0.1944 kn
  const auto r = anello::make_vbw(water);
  REQUIRE(r.ec == errc::ok);
  CHECK(r.value.longitudinal_water_knots == decimal::scaled(486, 2));
  CHECK(r.value.transverse_water_knots == decimal::scaled(-19, 2));
  CHECK(r.value.water_status == standard::vbw_status::valid);
  CHECK_FALSE(r.value.longitudinal_ground_knots.has_value());
  CHECK(r.value.ground_status == standard::vbw_status::invalid);
  CHECK(nmea::encode(r.value).view() == "$VWVBW,4.86,-0.19,A,,,V*7A\r\n");

  // ANELLO's own vector, from SI zeros.
  anello::vbw_si still;
  still.longitudinal_water_mps = 0.0;
  still.transverse_water_mps = 0.0;
  still.longitudinal_ground_mps = 0.0;
  still.transverse_ground_mps = -0.0;
  still.speed_places = 1;
  still.talker = "VM";
  CHECK(nmea::encode(anello::make_vbw(still).value).view() == "$VMVBW,0.0,0.0,A,0.0,0.0,A*58\r\n");

  // A Doppler log's bottom track alone.
  anello::vbw_si ground;
  ground.longitudinal_ground_mps = 1.0;
  const auto g = anello::make_vbw(ground);
  CHECK(g.value.water_status == standard::vbw_status::invalid);
  CHECK(g.value.ground_status == standard::vbw_status::valid);
  CHECK(nmea::encode(g.value).view() == sealed("VWVBW,,,V,1.94,,A"));

  anello::vbw_si broken;
  broken.longitudinal_ground_mps = 1.0;
  broken.transverse_ground_mps = not_a_number;
  const auto b = anello::make_vbw(broken);
  CHECK(b.ec == errc::not_finite);
  CHECK(b.field == 5);
}

TEST_CASE("make_vhw and make_vbw: round trip through the wire", "[anello][si][property]") {
  for (int i = 0; i <= 400; ++i) {
    const double mps = i * 0.037;
    anello::vhw_si in;
    in.heading_true_deg = i * 0.9 - 180.0;
    in.speed_mps = mps;
    const auto out = nmea::encode(anello::make_vhw(in).value);
    REQUIRE(out.ec == errc::ok);
    const auto r = anello::decode_input(out.view());
    REQUIRE(r.ec == errc::ok);
    const auto* m = std::get_if<standard::vhw>(&r.value);
    REQUIRE(m != nullptr);
    // Knots with 2 places: within half a hundredth of a knot.
    CHECK(*anello::speed_through_water_mps(*m) ==
          Approx(mps).margin(0.005 / anello::knots_per_mps));
    const double h = m->heading_true_deg->to_double();
    CHECK(h >= 0.0);
    CHECK(h < 360.0);

    anello::vbw_si b;
    b.longitudinal_water_mps = mps - 5.0;
    b.transverse_water_mps = 0.5 - mps / 10.0;
    const auto bout = nmea::encode(anello::make_vbw(b).value);
    REQUIRE(bout.ec == errc::ok);
    const auto br = anello::decode_input(bout.view());
    const auto* bm = std::get_if<standard::vbw>(&br.value);
    REQUIRE(bm != nullptr);
    CHECK(bm->longitudinal_water_knots->to_double() / anello::knots_per_mps ==
          Approx(mps - 5.0).margin(0.005 / anello::knots_per_mps));
  }
}

// =============================================================================================
// RMC, the INS output

TEST_CASE("RMC output: the 11-field form", "[anello][rmc]") {
  const std::string_view text =
      "$GNRMC,154258.00,A,3249.72026,N,11713.79556,W,0.05,89.00,030724,,*06\r\n";
  const auto r = anello::decode_output(text);
  REQUIRE(r.ec == errc::ok);
  const auto* m = std::get_if<standard::rmc>(&r.value);
  REQUIRE(m != nullptr);
  CHECK(m->talker == "GN");
  CHECK(m->time->hour == 15);
  CHECK(m->time->minute == 42);
  CHECK(m->time->second == 58);
  CHECK(m->status == standard::rmc_status::active);
  CHECK(m->lat->degrees() == Approx(32.828671).margin(1e-9));
  CHECK(m->lon->degrees() == Approx(-117.229926).margin(1e-9));
  CHECK(m->speed_knots == decimal::scaled(5, 2));
  CHECK(m->course_true == decimal::scaled(8900, 2));
  CHECK(m->date->year == 2024);
  CHECK(m->date->month == 7);
  CHECK(m->date->day == 3);
  CHECK_FALSE(m->magnetic_variation.has_value());
  CHECK_FALSE(m->mode.has_value());
  CHECK_FALSE(m->navigational_status.has_value());
  CHECK(nmea::encode(*m).view() == text);
}

TEST_CASE("RMC output: the NMEA 2.3 form with a mode", "[anello][rmc]") {
  const std::string_view text =
      "$GNRMC,154258.00,A,3249.72026,N,11713.79556,W,0.05,89.00,030724,,,A*6B\r\n";
  const auto r = anello::decode_output(text);
  REQUIRE(r.ec == errc::ok);
  const auto* m = std::get_if<standard::rmc>(&r.value);
  REQUIRE(m != nullptr);
  CHECK(m->mode == standard::mode_indicator::autonomous);
  CHECK_FALSE(m->navigational_status.has_value());
  CHECK(nmea::encode(*m).view() == text);
}

TEST_CASE("RMC output: the NMEA 4.1 form from an INS talker", "[anello][rmc]") {
  const std::string_view text =
      "$INRMC,154258.000,A,3249.72026,N,11713.79556,W,0.05,89.00,030724,12.3,E,E,C*65\r\n";
  const auto r = anello::decode_output(text);
  REQUIRE(r.ec == errc::ok);
  const auto* m = std::get_if<standard::rmc>(&r.value);
  REQUIRE(m != nullptr);
  CHECK(m->talker == "IN");
  CHECK(m->time->places == 3);
  CHECK(m->magnetic_variation->degrees() == 12.3);
  CHECK(m->mode == standard::mode_indicator::estimated);  // dead reckoning between fixes
  CHECK(m->navigational_status == standard::nav_status::caution);
  CHECK(nmea::encode(*m).view() == text);
}

TEST_CASE("RMC output: before the first fix", "[anello][rmc]") {
  const std::string_view text = "$INRMC,,V,,,,,,,,,,N*43\r\n";
  const auto r = anello::decode_output(text);
  REQUIRE(r.ec == errc::ok);
  const auto* m = std::get_if<standard::rmc>(&r.value);
  REQUIRE(m != nullptr);
  CHECK(m->status == standard::rmc_status::warning);
  CHECK_FALSE(m->time.has_value());
  CHECK_FALSE(m->lat.has_value());
  CHECK_FALSE(m->date.has_value());
  CHECK(m->mode == standard::mode_indicator::not_valid);
  CHECK(nmea::encode(*m).view() == text);
}

TEST_CASE("RMC output: policy and malformed lines", "[anello][rmc]") {
  CHECK(anello::decode_output("$GNRMC,154258.00,A,3249.72026,N,11713.79556,W,0.05,89.00,030724,,")
            .ec == errc::missing_checksum);
  const auto lat = anello::decode_output(
      sealed("GNRMC,154258.00,A,3249.72026,X,11713.79556,W,0.05,89.00,030724,,"));
  CHECK(lat.ec == errc::bad_hemisphere);
  CHECK(lat.field == 4);
  const auto status = anello::decode_output(
      sealed("INRMC,154258.00,X,3249.72026,N,11713.79556,W,0.05,89.00,030724,,"));
  CHECK(status.ec == errc::bad_enum);
  CHECK(status.field == 2);
  // The INS output set knows only RMC.
  const auto other = anello::decode_output(sealed("VMVBW,0.0,0.0,A,0.0,0.0,A"));
  REQUIRE(other.ec == errc::ok);
  CHECK(std::holds_alternative<nmea::unknown_sentence>(other.value));
}
