// SPDX-License-Identifier: BSL-1.0
// Sandshark SPI messages: the verified vectors, the spec's examples, the role policies,
// malformed input per message (errc + field). Round trips over generated values are in
// round_trip_test.cpp.

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include "seawire/nmea/checksum.hpp"
#include "seawire/sandshark/messages.hpp"

#include "support.hpp"

using namespace seawire;
using namespace seawire::sandshark;
using namespace seawire::nmea;

namespace {

using namespace support;

template <class M>
std::string encoded(const M& m) {
  const auto b = encode(m);
  REQUIRE(b.ec == errc::ok);
  return std::string(b.view());
}

constexpr time_of_day tod(int h, int m, int s, std::uint32_t frac, int places) {
  return {static_cast<std::uint8_t>(h), static_cast<std::uint8_t>(m), static_cast<std::uint8_t>(s),
          frac, static_cast<std::uint8_t>(places)};
}

// Canonical vectors (uppercase checksums, CR LF): each decodes and re-encodes byte for byte.
template <class M>
constexpr bool round_trips(std::string_view line, const parse_policy& policy) {
  const result<M> r = decode<M>(line, policy);
  return r.ok() && encode(r.value).view() == line;
}

}  // namespace

// -- compile-time round trips ------------------------------------------------------------------

static_assert(round_trips<bplog>("$BPLOG,ACK,ON*1E\r\n", to_vehicle_policy));
static_assert(round_trips<bplog>("$BPLOG,ALL,ON*16\r\n", to_vehicle_policy));
static_assert(round_trips<bpsts>("$BPSTS,231133.12,1,BWSI Autonomy OK*46\r\n", to_vehicle_policy));
static_assert(round_trips<bprmb>("$BPRMB,231137.32,,,,750,0,1*7A\r\n", to_vehicle_policy));
static_assert(round_trips<bprmb>("$BPRMB,231204.72,-15,,,750,0,1*54\r\n", to_vehicle_policy));
static_assert(round_trips<bprmb>("$BPRMB,123456.789,0,0,2,0,0,1*7F\r\n", to_vehicle_policy));
static_assert(round_trips<bfctl>("$BFCTL,081025.987,1*78\r\n", from_vehicle_policy));
static_assert(round_trips<bfack>("$BFACK,081025.990,RMB,081025.950,,2,0,*32\r\n",
                                 from_vehicle_policy));
static_assert(round_trips<bfack>("$BFACK,081025.990,RMB,081025.950,,2,0*1E\r\n",
                                 from_vehicle_policy));
static_assert(round_trips<bfack>("$BFACK,081025.990,RMB,081025.950,,2,0,,*1E\r\n",
                                 from_vehicle_policy));
static_assert(round_trips<bfnvg>(
    "$BFNVG,231131.55,4218.000000,N,07106.000000,W,0,10.0,1.0,45.0,0.0,0.0,231131.55*62\r\n",
    from_vehicle_policy));
static_assert(round_trips<bfsht>("$BFSHT,081025.987*71\r\n", from_vehicle_policy));
static_assert(round_trips<bfver>("$BFVER,081025.987,1.0*7C\r\n", from_vehicle_policy));
static_assert(round_trips<bfmis>("$BFMIS,081025.987,dive1.xml,Running /var/log/mission_12,*44\r\n",
                                 from_vehicle_policy));
static_assert(round_trips<bpabt>("$BPABT,081025.987,leak detected,1*6B\r\n", to_vehicle_policy));
static_assert(round_trips<bpver>("$BPVER,081025.987,1.0*6A\r\n", to_vehicle_policy));
// The spec's BFNVG example with its checksum corrected.
static_assert(round_trips<bfnvg>(
    "$BFNVG,081025.987,4221.81092,N,07106.84603,W,1,45.3,20.1,203.1,-3.4,4.5,081025.980*4E\r\n",
    from_vehicle_policy));
// A new bfack is written in the spec's 8-field form.
constexpr bfack new_ack() {
  bfack a;
  a.timestamp = tod(8, 10, 25, 990, 3);
  a.command = "RMB";
  a.command_timestamp = tod(8, 10, 25, 950, 3);
  return a;
}
static_assert(encode(new_ack()).view() == "$BFACK,081025.990,RMB,081025.950,,2,0,,*1E\r\n");

// -- the verified vectors, value by value ----------------------------------------------------

TEST_CASE("BPLOG vectors: code and ON/OFF word; lowercase checksum accepted, written upper") {
  const auto ack = decode<bplog>("$BPLOG,ACK,ON*1e", to_vehicle_policy);
  REQUIRE(ack.ok());
  CHECK(ack.value.code == "ACK");
  CHECK(ack.value.state == log_state::on);
  CHECK_FALSE(ack.value.is_all());
  CHECK(encoded(ack.value) == "$BPLOG,ACK,ON*1E\r\n");

  const auto all = decode<bplog>("$BPLOG,ALL,ON*16", to_vehicle_policy);
  REQUIRE(all.ok());
  CHECK(all.value.code == "ALL");
  CHECK(all.value.is_all());

  const auto off = decode<bplog>(sealed("BPLOG,NVG,OFF"), to_vehicle_policy);
  REQUIRE(off.ok());
  CHECK(off.value.code == "NVG");
  CHECK(off.value.state == log_state::off);
  CHECK(encoded(off.value) == sealed("BPLOG,NVG,OFF"));
}

TEST_CASE("BPSTS vector: status text keeps its spaces") {
  const auto r = decode<bpsts>("$BPSTS,231133.12,1,BWSI Autonomy OK*46", to_vehicle_policy);
  REQUIRE(r.ok());
  CHECK(r.value.timestamp == tod(23, 11, 33, 12, 2));
  CHECK(r.value.all_ok);
  CHECK(r.value.message == "BWSI Autonomy OK");
}

TEST_CASE("BFNVG vector from the training vehicle") {
  const auto r = decode_from_vehicle(
      "$BFNVG,231131.55,4218.000000,N,07106.000000,W,0,10.0,1.0,45.0,0.0,0.0,231131.55*62");
  REQUIRE(r.ok());
  const bfnvg* n = std::get_if<bfnvg>(&r.value);
  REQUIRE(n != nullptr);
  CHECK(n->timestamp == tod(23, 11, 31, 55, 2));
  CHECK(n->lat.degrees() == Approx(42.3));
  CHECK(n->lon.degrees() == Approx(-71.1));
  CHECK_FALSE(n->gps);
  CHECK(n->altitude_m == decimal::scaled(100, 1));
  CHECK(n->depth_m == decimal::scaled(10, 1));
  CHECK(n->heading_deg == decimal::scaled(450, 1));
  CHECK(n->roll_deg == decimal::scaled(0, 1));
  CHECK(n->pitch_deg == decimal::scaled(0, 1));
  CHECK(n->nav_timestamp == tod(23, 11, 31, 55, 2));
}

TEST_CASE("the spec's BFNVG examples carry wrong checksums and are rejected") {
  const std::string body =
      "BFNVG,081025.987,4221.81092,N,07106.84603,W,1,45.3,20.1,203.1,-3.4,4.5,081025.980";
  for (const char* cs : {"*5B", "*5b"}) {
    const std::string line = "$" + body + cs;
    INFO(line);
    const auto r = decode_from_vehicle(line);
    CHECK(r.ec == errc::checksum_mismatch);
    CHECK(decode<bfnvg>(line, from_vehicle_policy).ec == errc::checksum_mismatch);
  }
  // With the right checksum (*4E) the same line is the spec's example as meant.
  const auto ok = decode<bfnvg>("$" + body + "*4E", from_vehicle_policy);
  REQUIRE(ok.ok());
  CHECK(ok.value.lat.degrees() == Approx(42.0 + 21.81092 / 60));
  CHECK(ok.value.lon.degrees() == Approx(-(71.0 + 6.84603 / 60)));
  CHECK(ok.value.gps);
  CHECK(ok.value.altitude_m == decimal::scaled(453, 1));
  CHECK(ok.value.depth_m == decimal::scaled(201, 1));
  CHECK(ok.value.heading_deg == decimal::scaled(2031, 1));
  CHECK(ok.value.roll_deg == decimal::scaled(-34, 1));
  CHECK(ok.value.pitch_deg == decimal::scaled(45, 1));
  CHECK(ok.value.nav_timestamp == tod(8, 10, 25, 980, 3));
}

TEST_CASE("BPRMB vectors: blank fields, rudder, pitch mode") {
  const auto a = decode<bprmb>("$BPRMB,231137.32,,,,750,0,1*7a", to_vehicle_policy);
  REQUIRE(a.ok());
  CHECK(a.value.timestamp == tod(23, 11, 37, 32, 2));
  CHECK_FALSE(a.value.heading.has_value());
  CHECK_FALSE(a.value.depth.has_value());
  CHECK_FALSE(a.value.depth_mode.has_value());
  CHECK(a.value.speed == decimal(750));
  CHECK(a.value.speed_mode == speed_mode::rpm);
  CHECK(a.value.horizontal_mode == horizontal_mode::rudder);
  // The lowercase checksum is accepted; the canonical form writes it upper case.
  CHECK(encoded(a.value) == "$BPRMB,231137.32,,,,750,0,1*7A\r\n");

  const auto b = decode<bprmb>("$BPRMB,231204.72,-15,,,750,0,1*54", to_vehicle_policy);
  REQUIRE(b.ok());
  CHECK(b.value.heading == decimal(-15));
  CHECK(b.value.horizontal_mode == horizontal_mode::rudder);

  const auto c = decode<bprmb>("$BPRMB,123456.789,0,0,2,0,0,1*7F", to_vehicle_policy);
  REQUIRE(c.ok());
  CHECK(c.value.timestamp == tod(12, 34, 56, 789, 3));
  CHECK(c.value.heading == decimal(0));
  CHECK(c.value.depth == decimal(0));
  CHECK(c.value.depth_mode == depth_mode::pitch);
  CHECK(c.value.speed == decimal(0));
  CHECK(c.value.speed_mode == speed_mode::rpm);
  CHECK(c.value.horizontal_mode == horizontal_mode::rudder);

  // All blank after the timestamp: nothing of the behaviour is modified.
  const auto blank = decode<bprmb>(sealed("BPRMB,231137.32,,,,,,"), to_vehicle_policy);
  REQUIRE(blank.ok());
  CHECK_FALSE(blank.value.heading);
  CHECK_FALSE(blank.value.speed);
  CHECK_FALSE(blank.value.horizontal_mode);
  CHECK(encoded(blank.value) == sealed("BPRMB,231137.32,,,,,,"));

  // Every depth mode.
  for (char m : std::string_view("0123")) {
    const auto r =
        decode<bprmb>(sealed(std::string("BPRMB,231137.32,,5,") + m + ",,,"), to_vehicle_policy);
    REQUIRE(r.ok());
    CHECK(static_cast<char>(*r.value.depth_mode) == m);
  }
}

TEST_CASE("BFCTL vector") {
  const auto r = decode_from_vehicle("$BFCTL,081025.987,1*78");
  REQUIRE(r.ok());
  const bfctl* c = std::get_if<bfctl>(&r.value);
  REQUIRE(c != nullptr);
  CHECK(c->timestamp == tod(8, 10, 25, 987, 3));
  CHECK(c->control);
  const auto off = decode<bfctl>(sealed("BFCTL,081025.987,0"), from_vehicle_policy);
  REQUIRE(off.ok());
  CHECK_FALSE(off.value.control);
}

TEST_CASE("BFACK with and without the trailing fields, each written back as it came") {
  // Goby's form: 7 fields, the description blank.
  const auto seven = decode_from_vehicle("$BFACK,081025.990,RMB,081025.950,,2,0,*32");
  REQUIRE(seven.ok());
  const bfack* a = std::get_if<bfack>(&seven.value);
  REQUIRE(a != nullptr);
  CHECK(a->timestamp == tod(8, 10, 25, 990, 3));
  CHECK(a->command == "RMB");
  CHECK(a->names("BPRMB"));
  CHECK_FALSE(a->names("BPLOG"));
  CHECK(a->command_timestamp == tod(8, 10, 25, 950, 3));
  CHECK_FALSE(a->behavior_id.has_value());
  CHECK(a->status == ack_status::ok);
  CHECK(a->future_use == 0);
  REQUIRE(a->description.has_value());
  CHECK(a->description->empty());
  CHECK_FALSE(a->trailing.has_value());
  CHECK(encoded(*a) == "$BFACK,081025.990,RMB,081025.950,,2,0,*32\r\n");

  // 6 fields: no description at all.
  const auto six = decode<bfack>("$BFACK,081025.990,RMB,081025.950,,2,0*1E", from_vehicle_policy);
  REQUIRE(six.ok());
  CHECK_FALSE(six.value.description.has_value());
  CHECK_FALSE(six.value.trailing.has_value());
  CHECK(encoded(six.value) == "$BFACK,081025.990,RMB,081025.950,,2,0*1E\r\n");

  // The spec's form: 8 fields, field 8 empty.
  const auto eight =
      decode<bfack>(sealed("BFACK,081025.990,RMB,081025.950,7,3,0,working,"), from_vehicle_policy);
  REQUIRE(eight.ok());
  CHECK(eight.value.behavior_id == 7);
  CHECK(eight.value.status == ack_status::pending);
  CHECK(eight.value.description == text<256>("working"));
  REQUIRE(eight.value.trailing.has_value());
  CHECK(eight.value.trailing->empty());
  CHECK(encoded(eight.value) == sealed("BFACK,081025.990,RMB,081025.950,7,3,0,working,"));

  // Fields past 8 are ignored (SPI 4.2).
  const auto nine =
      decode<bfack>(sealed("BFACK,081025.990,LOG,,,0,0,bad code,,future"), from_vehicle_policy);
  REQUIRE(nine.ok());
  CHECK(nine.value.status == ack_status::invalid);
  CHECK_FALSE(nine.value.command_timestamp.has_value());
  CHECK(nine.value.names("BPLOG"));

  // Every status code.
  for (char s : std::string_view("0123")) {
    const auto r = decode<bfack>(sealed(std::string("BFACK,231137.32,STS,231137.30,,") + s + ",0,"),
                                 from_vehicle_policy);
    REQUIRE(r.ok());
    CHECK(static_cast<char>(r.value.status) == s);
  }
}

TEST_CASE("the spec's other messages") {
  const auto sht = decode_from_vehicle("$BFSHT,081025.987*71");
  REQUIRE(sht.ok());
  REQUIRE(std::holds_alternative<bfsht>(sht.value));
  CHECK(std::get<bfsht>(sht.value).timestamp == tod(8, 10, 25, 987, 3));

  const auto ver = decode_from_vehicle("$BFVER,081025.987,1.0*7C");
  REQUIRE(ver.ok());
  CHECK(std::get<bfver>(ver.value).version == "1.0");

  const auto mis = decode_from_vehicle(sealed("BFMIS,081025.987,dive1.xml,Running /var/log/m12,"));
  REQUIRE(mis.ok());
  const bfmis& m = std::get<bfmis>(mis.value);
  CHECK(m.dive_file == "dive1.xml");
  CHECK(m.status == "Running /var/log/m12");
  CHECK(m.details.empty());
  CHECK(m.running());
  CHECK(m.state() == mission_state::running);
  CHECK(m.log_directory() == "/var/log/m12");

  const auto aborted =
      decode<bfmis>(sealed("BFMIS,081026.000,,Aborted,depth limit exceeded"), from_vehicle_policy);
  REQUIRE(aborted.ok());
  CHECK(aborted.value.dive_file.empty());
  CHECK_FALSE(aborted.value.running());
  CHECK(aborted.value.state() == mission_state::aborted);
  CHECK(aborted.value.log_directory().empty());
  CHECK(aborted.value.details == "depth limit exceeded");
  const auto odd = decode<bfmis>(sealed("BFMIS,081026.000,,Paused,"), from_vehicle_policy);
  REQUIRE(odd.ok());
  CHECK(odd.value.state() == mission_state::unknown);
  // Every text the spec names, exactly (case and spaces count); a blank status names none.
  const std::pair<std::string_view, mission_state> named[] = {
      {"Offline", mission_state::offline},
      {"Waiting", mission_state::waiting},
      {"Invalid Dive File", mission_state::invalid_dive_file},
      {"Invalid Wrapup File", mission_state::invalid_wrapup_file},
      {"Ready", mission_state::ready},
      {"Running", mission_state::running},
      {"WrappingUp", mission_state::wrapping_up},
      {"Aborting", mission_state::aborting},
      {"Completed", mission_state::completed},
      {"Aborted", mission_state::aborted},
      {"Stopped", mission_state::stopped},
      {"", mission_state::unknown},
      {"ready", mission_state::unknown},
      {"Ready ", mission_state::unknown},
  };
  for (const auto& [text, state] : named) {
    INFO(text);
    bfmis t;
    REQUIRE(t.status.assign(text));
    CHECK(t.state() == state);
  }

  const auto nvr = decode_from_vehicle(sealed("BFNVR,081025.987,0.1,-0.2,0.03,1.5,-2,0.25"));
  REQUIRE(nvr.ok());
  const bfnvr& v = std::get<bfnvr>(nvr.value);
  CHECK(v.vel_east_mps == decimal::scaled(1, 1));
  CHECK(v.vel_north_mps == decimal::scaled(-2, 1));
  CHECK(v.vel_down_mps == decimal::scaled(3, 2));
  CHECK(v.pitch_rate_dps == decimal::scaled(15, 1));
  CHECK(v.roll_rate_dps == decimal(-2));
  CHECK(v.yaw_rate_dps == decimal::scaled(25, 2));

  const auto abt = decode_to_vehicle("$BPABT,081025.987,leak detected,1*6B");
  REQUIRE(abt.ok());
  const bpabt& b = std::get<bpabt>(abt.value);
  CHECK(b.message == "leak detected");
  CHECK(b.reason == abort_reason::with_errors);
  const auto abt_blank = decode<bpabt>(sealed("BPABT,081025.987,done,"), to_vehicle_policy);
  REQUIRE(abt_blank.ok());
  CHECK_FALSE(abt_blank.value.reason.has_value());
  CHECK(abt_blank.value.effective_reason() == abort_reason::with_errors);
  const auto abt_ok = decode<bpabt>(sealed("BPABT,081025.987,done,0"), to_vehicle_policy);
  REQUIRE(abt_ok.ok());
  CHECK(abt_ok.value.effective_reason() == abort_reason::success);

  const auto bpv = decode_to_vehicle("$BPVER,081025.987,1.0*6A");
  REQUIRE(bpv.ok());
  CHECK(std::get<bpver>(bpv.value).version == "1.0");
}

// -- roles and policies ----------------------------------------------------------------------

TEST_CASE("from the vehicle a checksum is required; to the vehicle it may be left out") {
  CHECK(decode_from_vehicle("$BFCTL,081025.987,1").ec == errc::missing_checksum);
  CHECK(decode_from_vehicle("$BFCTL,081025.987,1*").ec == errc::bad_checksum_format);
  CHECK(decode_from_vehicle("$BFCTL,081025.987,1*79").ec == errc::checksum_mismatch);

  const auto bare = decode_to_vehicle("$BPLOG,ALL,ON\r\n");
  REQUIRE(bare.ok());
  CHECK(std::get<bplog>(bare.value).code == "ALL");
  // "May or may not include the checksum": a '*' with no digits is neither (cut off).
  CHECK(decode_to_vehicle("$BPLOG,ALL,ON*\r\n").ec == errc::bad_checksum_format);
  // A wrong checksum is never accepted, in either case of hex.
  CHECK(decode_to_vehicle("$BPLOG,ALL,ON*17").ec == errc::checksum_mismatch);
  CHECK(decode_to_vehicle("$BPLOG,ACK,ON*1f").ec == errc::checksum_mismatch);
}

TEST_CASE("extra trailing fields and unknown messages are ignored (SPI 4.2)") {
  const auto extra = decode_from_vehicle(sealed("BFCTL,081025.987,1,new field,another"));
  REQUIRE(extra.ok());
  CHECK(std::get<bfctl>(extra.value).control);
  const auto extra_to = decode_to_vehicle(sealed("BPLOG,NVG,ON,1"));
  REQUIRE(extra_to.ok());
  CHECK(std::get<bplog>(extra_to.value).code == "NVG");

  const std::string future = sealed("BFXYZ,081025.987,42");
  const auto unknown = decode_from_vehicle(future);
  REQUIRE(unknown.ok());
  const auto* u = std::get_if<nmea::unknown_sentence>(&unknown.value);
  REQUIRE(u != nullptr);
  CHECK(u->sentence.address == "BFXYZ");
  // A payload sentence reaching a payload is not a vehicle message either.
  CHECK(std::holds_alternative<nmea::unknown_sentence>(
      decode_from_vehicle("$BPLOG,ALL,ON*16").value));
  CHECK(std::holds_alternative<nmea::unknown_sentence>(
      decode_to_vehicle(sealed("BFCTL,081025.987,1")).value));
}

TEST_CASE("numbers may have spaces before the minus sign (SPI 4.2, Table 1)") {
  // "If negative, the first non-whitespace character will be the minus sign."
  const auto nvg = decode_from_vehicle(sealed(
      "BFNVG,081025.987,4221.81092,N,07106.84603,W,1,45.3,20.1,203.1,  -3.4, 4.5 ,081025.980"));
  REQUIRE(nvg.ok());
  const auto& n = std::get<bfnvg>(nvg.value);
  CHECK(n.roll_deg == decimal::scaled(-34, 1));
  CHECK(n.pitch_deg == decimal::scaled(45, 1));
  CHECK(encoded(n).find(",-3.4,4.5,") != std::string::npos);  // written without the spaces

  const auto rmb = decode_to_vehicle(sealed("BPRMB,231204.72, -15,,,750,0,1"));
  REQUIRE(rmb.ok());
  CHECK(std::get<bprmb>(rmb.value).heading == decimal{-15});

  // Inside a number a space is still an error, and so is a field of spaces only.
  const auto inside = decode_to_vehicle(sealed("BPRMB,231204.72,- 15,,,750,0,1"));
  CHECK(inside.ec == errc::bad_number);
  CHECK(inside.field == 2);
  CHECK(decode_to_vehicle(sealed("BPRMB,231204.72,   ,,,750,0,1")).ec == errc::bad_number);
}

TEST_CASE("the role sets know their addresses") {
  for (std::string_view a : {"BFSHT", "BFVER", "BFNVG", "BFNVR", "BFMIS", "BFACK", "BFCTL"}) {
    CHECK(from_vehicle::knows(a));
    CHECK_FALSE(to_vehicle::knows(a));
  }
  for (std::string_view a : {"BPLOG", "BPSTS", "BPRMB", "BPABT", "BPVER"}) {
    CHECK(to_vehicle::knows(a));
    CHECK_FALSE(from_vehicle::knows(a));
  }
  CHECK(message_code("BFNVG") == "NVG");
  CHECK(message_code("BPRMB") == "RMB");
  CHECK(message_code("GPRMC") == "GPRMC");
  CHECK(from_vehicle::field_name("BFNVG", 2) == "latitude");
  CHECK(from_vehicle::field_name("BFNVG", 4) == "longitude");
  CHECK(to_vehicle::field_name("BPRMB", 4) == "depth_mode");
  CHECK(from_vehicle::field_name("BFACK", 8) == "trailing");
}

// -- malformed input: errc and field number --------------------------------------------------

TEST_CASE("malformed BFSHT / BFVER / BFCTL") {
  const bad_case sht[] = {
      {"BFSHT", errc::too_few_fields, 1},
      {"BFSHT,", errc::missing_field, 1},
      {"BFSHT,250000.0", errc::hour_out_of_range, 1},
      {"BFSHT,126000", errc::minute_out_of_range, 1},
      {"BFSHT,120060", errc::second_out_of_range, 1},
      {"BFSHT,12:00:00", errc::bad_time, 1},
      {"BFSHT,120000.1234567890", errc::bad_time, 1},
  };
  for (const auto& c : sht) check_bad<bfsht>(c, from_vehicle_policy);
  const bad_case ver[] = {
      {"BFVER,081025.987", errc::too_few_fields, 2},
      {"BFVER,081025.987,", errc::missing_field, 2},
      {"BFVER,081025.987,123456789012345678901234567890123", errc::bad_length, 2},
  };
  for (const auto& c : ver) check_bad<bfver>(c, from_vehicle_policy);
  const bad_case ctl[] = {
      {"BFCTL,081025.987", errc::too_few_fields, 2}, {"BFCTL,081025.987,", errc::missing_field, 2},
      {"BFCTL,081025.987,2", errc::bad_flag, 2},     {"BFCTL,081025.987,true", errc::bad_flag, 2},
      {"BFCTL,,1", errc::missing_field, 1},
  };
  for (const auto& c : ctl) check_bad<bfctl>(c, from_vehicle_policy);
}

TEST_CASE("malformed BFNVG / BFNVR / BFMIS") {
  const bad_case nvg[] = {
      {"BFNVG,081025.987,4261.0,N,07106.8,W,1,,,,,,", errc::minute_out_of_range, 2},
      {"BFNVG,081025.987,9100.0,N,07106.8,W,1,,,,,,", errc::bad_latitude, 2},
      {"BFNVG,081025.987,4221.8,X,07106.8,W,1,,,,,,", errc::bad_hemisphere, 3},
      {"BFNVG,081025.987,4221.8,N,18106.8,W,1,,,,,,", errc::bad_longitude, 4},
      {"BFNVG,081025.987,4221.8,N,07106.8,N,1,,,,,,", errc::bad_hemisphere, 5},
      {"BFNVG,081025.987,4221.8,N,07106.8,W,2,,,,,,", errc::bad_flag, 6},
      {"BFNVG,081025.987,4221.8,N,07106.8,W,1,1e3,,,,,", errc::bad_number, 7},
      {"BFNVG,081025.987,4221.8,N,07106.8,W,1,,,361,,,", errc::out_of_range, 9},
      {"BFNVG,081025.987,4221.8,N,07106.8,W,1,,,,,,99", errc::bad_time, 12},
      {"BFNVG,081025.987,4221.8,N", errc::too_few_fields, 4},
  };
  for (const auto& c : nvg) check_bad<bfnvg>(c, from_vehicle_policy);
  const bad_case nvr[] = {
      {"BFNVR,081025.987,0.1,x,0,0,0,0", errc::bad_number, 3},
      {"BFNVR,081025.987,0.1,0.2,0,0,0,--1", errc::bad_number, 7},
      {"BFNVR,99", errc::bad_time, 1},
  };
  for (const auto& c : nvr) check_bad<bfnvr>(c, from_vehicle_policy);
  const std::string long_dive = "BFMIS,081025.987," + std::string(257, 'd') + ",Ready,";
  const bad_case mis[] = {
      {"BFMIS,081025.987,dive,Running", errc::too_few_fields, 4},
      {"BFMIS,081025.987", errc::too_few_fields, 2},
      {long_dive.c_str(), errc::text_too_long, 2},
  };
  for (const auto& c : mis) check_bad<bfmis>(c, from_vehicle_policy);
}

TEST_CASE("malformed BFACK") {
  const bad_case ack[] = {
      {"BFACK,081025.990,RMB,081025.950,,4,0,", errc::bad_enum, 5},
      {"BFACK,081025.990,RMB,081025.950,,,0,", errc::missing_field, 5},
      {"BFACK,081025.990,RMB,081025.950,,ok,0,", errc::bad_enum, 5},
      {"BFACK,081025.990,,081025.950,,2,0,", errc::missing_field, 2},
      {"BFACK,081025.990,RMB,99,,2,0,", errc::bad_time, 3},
      {"BFACK,081025.990,RMB,081025.950,1.5,2,0,", errc::bad_number, 4},
      {"BFACK,081025.990,RMB,081025.950,99999999999,2,0,", errc::out_of_range, 4},
      {"BFACK,081025.990,RMB,081025.950,,2,x,", errc::bad_number, 6},
      {"BFACK,081025.990,RMB", errc::too_few_fields, 5},
      {"BFACK,081025.990,ABCDEFGHIJKLMNOPQ,,,2,0,", errc::bad_length, 2},
  };
  for (const auto& c : ack) check_bad<bfack>(c, from_vehicle_policy);
}

TEST_CASE("variable-length text: long descriptions, details and log paths, a filled field 8") {
  // SPI table 1: variable text has no set length. What a vehicle writes in an ack or a mission
  // status must not make the line undecodable (the ack would be lost and the command resent).
  const std::string description(200, 'x');
  const std::string ack_line =
      sealed("BFACK,081025.990,VER,000001.000,,2,0," + description + ",future field 8 text here");
  const result<bfack> a = decode<bfack>(ack_line, from_vehicle_policy);
  REQUIRE(a.ok());
  CHECK(a.value.description->view() == description);
  CHECK(a.value.trailing->view() == "future field 8 text here");
  CHECK(encode(a.value).view() == ack_line);

  const std::string dir = "Running /mnt/data/logs/" + std::string(180, 'm');
  const std::string details = "Mission aborted: " + std::string(400, 'z');
  const std::string mis_line = sealed("BFMIS,081025.987,survey.xml," + dir + "," + details);
  const result<bfmis> m = decode<bfmis>(mis_line, from_vehicle_policy);
  REQUIRE(m.ok());
  CHECK(m.value.running());
  CHECK(m.value.log_directory() == dir.substr(8));
  CHECK(m.value.details.view() == details);
  CHECK(encode(m.value).view() == mis_line);
}

TEST_CASE("malformed BPLOG / BPSTS / BPVER") {
  const bad_case log[] = {
      {"BPLOG,NV,ON", errc::bad_length, 1},
      {"BPLOG,NVGX,ON", errc::bad_length, 1},
      {"BPLOG,,ON", errc::missing_field, 1},
      {"BPLOG,NVG,on", errc::bad_enum, 2},
      {"BPLOG,NVG,YES", errc::bad_enum, 2},
      {"BPLOG,NVG,", errc::missing_field, 2},
      {"BPLOG,NVG", errc::too_few_fields, 2},
      // Case-sensitive 3-letter ids (SPI 4.2, 7.1): not lower case, no blanks or signs.
      {"BPLOG,nvg,ON", errc::bad_text, 1},
      {"BPLOG,N G,ON", errc::bad_text, 1},
      {"BPLOG,Nv-,ON", errc::bad_text, 1},
  };
  for (const auto& c : log) check_bad<bplog>(c, to_vehicle_policy);
  const bad_case sts[] = {
      {"BPSTS,231133.12,2,OK", errc::bad_flag, 2},
      {"BPSTS,231133.12,,OK", errc::missing_field, 2},
      {"BPSTS,231133.12,1", errc::too_few_fields, 3},
      {"BPSTS,2311,1,OK", errc::bad_time, 1},
  };
  for (const auto& c : sts) check_bad<bpsts>(c, to_vehicle_policy);
  // Under the strict policy, text that seawire would never write is refused too.
  check_bad<bpsts>({"BPSTS,231133.12,1,all ok!", errc::bad_text, 3}, parse_policy::strict());
  const bad_case ver[] = {
      {"BPVER,081025.987,", errc::missing_field, 2},
      {"BPVER,081025.987", errc::too_few_fields, 2},
  };
  for (const auto& c : ver) check_bad<bpver>(c, to_vehicle_policy);
}

TEST_CASE("malformed BPRMB / BPABT") {
  const bad_case rmb[] = {
      {"BPRMB,,90,,,,,0", errc::missing_field, 1},
      {"BPRMB,231137.32,abc,,,,,0", errc::bad_number, 2},
      {"BPRMB,231137.32,90,5,4,,,0", errc::bad_enum, 4},
      {"BPRMB,231137.32,90,5,01,,,0", errc::bad_enum, 4},
      {"BPRMB,231137.32,90,,,1.5,2,0", errc::bad_enum, 6},
      {"BPRMB,231137.32,90,,,1.5,1,2", errc::bad_enum, 7},
      {"BPRMB,231137.32,90,,,1..5,1,0", errc::bad_number, 5},
  };
  for (const auto& c : rmb) check_bad<bprmb>(c, to_vehicle_policy);
  const bad_case abt[] = {
      {"BPABT,081025.987,stop,2", errc::bad_enum, 3},
      {"BPABT,081025.987", errc::too_few_fields, 2},
      {"BPABT,1,stop,0", errc::bad_time, 1},
  };
  for (const auto& c : abt) check_bad<bpabt>(c, to_vehicle_policy);
}

TEST_CASE("encoding refuses what the spec forbids, naming the field") {
  bpsts s{tod(1, 2, 3, 0, 0), true, "a,b"};
  auto b = encode(s);
  CHECK(b.ec == errc::bad_text);
  CHECK(b.field == 3);

  bplog l;
  (void)l.code.assign("NV");
  b = encode(l);
  CHECK(b.ec == errc::bad_length);
  CHECK(b.field == 1);

  bprmb r;
  r.timestamp = tod(1, 2, 3, 0, 0);
  r.depth_mode = static_cast<depth_mode>('7');
  b = encode(r);
  CHECK(b.ec == errc::bad_enum);
  CHECK(b.field == 4);

  bfack a;
  a.timestamp = tod(25, 0, 0, 0, 0);
  (void)a.command.assign("RMB");
  const auto ab = encode(a);
  CHECK(ab.ec == errc::hour_out_of_range);
  CHECK(ab.field == 1);

  bpver v{tod(1, 2, 3, 0, 0), {}};
  b = encode(v);
  CHECK(b.ec == errc::bad_length);
  CHECK(b.field == 2);
}

TEST_CASE("every payload sentence fits the 256-byte sentence buffer at full capacity") {
  // The payload session's outbox holds sentence_buffer<256>.
  bpsts s{tod(23, 59, 59, 999999999, 9), true, {}};
  (void)s.message.assign(std::string(128, 'x'));
  CHECK(encode<256>(s).ec == errc::ok);
  bpabt a{tod(23, 59, 59, 999999999, 9), {}, abort_reason::with_errors};
  (void)a.message.assign(std::string(128, 'x'));
  CHECK(encode<256>(a).ec == errc::ok);
  const decimal widest = decimal::scaled(-999999999999999999, 9);
  bprmb r{tod(23, 59, 59, 999999999, 9), widest, widest,
          depth_mode::elevator,          widest, speed_mode::rpm,
          horizontal_mode::rudder};
  CHECK(encode<256>(r).ec == errc::ok);
}
