// SPDX-License-Identifier: BSL-1.0
// error_text(): errors told for people, with the sentence, the field, what it held, why, and
// what the field allows.

#include <catch2/catch.hpp>
#include <cstring>
#include <initializer_list>
#include <string>

#include "seawire/anello/frame_json.hpp"
#include "seawire/seawire.hpp"
#include "support.hpp"

namespace {
using namespace seawire;
using support::sealed;

template <class Set>
std::string told(std::string_view line, const nmea::parse_policy& p = {}) {
  char buf[256];
  const auto r = Set::decode(line, p);
  REQUIRE_FALSE(r);
  const std::string_view v = nmea::error_text<Set>(buf, r, line, p);
  CHECK(std::strlen(buf) == v.size());  // a C string too
  return std::string(v);
}

// A line, the whole text error_text must give for it, and the policy it is read under.
struct told_row {
  std::string line;
  std::string text;
  nmea::parse_policy policy{};
};

// Each row's line through told<Set>; a failure names the line.
template <class Set>
void check_told(std::initializer_list<told_row> rows) {
  for (const told_row& row : rows) {
    INFO("line: " << row.line);
    CHECK(told<Set>(row.line, row.policy) == row.text);
  }
}
}  // namespace

TEST_CASE("error_text: field, text, reason and the range the field allows") {
  using kf = kingfisher::to_vehicle;
  check_told<kf>({
      {"$PYDIR,150,0\r\n",
       R"(PYDIR field 1 (thrust_left) "150": value outside the range the spec allows: -100..100)"},
      {"$PYDEV,360,1.5\r\n",
       R"(PYDEV field 1 (heading_deg) "360": value outside the range the spec allows: 0..360 (360 excluded))"},
      {"$PYDEV,90,-1\r\n",
       R"(PYDEV field 2 (speed_mps) "-1": value outside the range the spec allows: at least 0)"},
      {"$PYDIR,1.2.3,0\r\n",
       R"(PYDIR field 1 (thrust_left) "1.2.3": not a number of the field's form)"},
  });
  CHECK(told<kf>("$PYDIR,12.5\r\n").starts_with("PYDIR field 2 (thrust_right): "));
  using s = sandshark::to_vehicle;
  CHECK(told<s>("$BPLOG,NV,ON\r\n") ==
        R"(BPLOG field 1 (code) "NV": wrong length: exactly 3 characters)");
}

TEST_CASE("error_text: errors of the sentence as a whole say where") {
  using set = kingfisher::to_vehicle;
  CHECK(told<set>("PYDIR,45,55\r\n").ends_with(" at column 0"));
  check_told<set>({
      {"$PYDIR,45,55*58\r\n",
       "checksum does not match the sentence (sent 58, computed 57) at column 13"},
      {"$PYDIR,45,55*577\r\n",
       "checksum is not two hex digits (upper-case where required) at column 13"},
      // What follows a whole checksum is shown, without the line ending, unprintable bytes in
      // hex.
      {"$PYDIR,45,55*6f \r\n", R"(unexpected characters after the checksum (" ") at column 15)"},
      {"$PYDIR,45,55*57X\n", R"(unexpected characters after the checksum ("X") at column 15)"},
      {"$PYDIR,45,55*57\x01\"\r\r\n",
       R"(unexpected characters after the checksum ("\x01\x22\x0D") at column 15)"},
  });
  // One message type, without a set.
  char buf[200];
  const std::string_view line =
      "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,400,311214,,,A";
  const auto r = nmea::decode<standard::rmc>(line);
  REQUIRE_FALSE(r);
  CHECK(nmea::error_text<standard::rmc>(buf, r, line) ==
        R"(GPRMC field 8 (course_true) "400": value outside the range the spec allows: 0..360)");
}

TEST_CASE("error_text: a small buffer cuts the text and still ends it") {
  char small[12];
  const std::string_view line = "$PYDIR,150,0\r\n";
  const auto r = kingfisher::to_vehicle::decode(line);
  const std::string_view v = nmea::error_text<kingfisher::to_vehicle>(small, r, line);
  CHECK(v == "PYDIR field");
  CHECK(small[11] == '\0');
  char none[1];
  CHECK(nmea::error_text<kingfisher::to_vehicle>(none, r, line).empty());
  CHECK(none[0] == '\0');
}

TEST_CASE("error_text: a declaration's later wire fields are named for what they are") {
  using rx = robotx::reports;
  using kf = kingfisher::from_vehicle;
  // A blank hemisphere letter: which letter, and that it is blank.
  check_told<rx>({
      {sealed("RXHRB,101218,161229,29.6412654321,,-82.3456789012,,GATOR,1,1"),
       R"(RXHRB field 4 (latitude's hemisphere letter) "": hemisphere letter is missing (blank))"},
      {sealed("RXHRB,101218,161229,29.6412654321,N,82.3456789012,,GATOR,1,1"),
       R"(RXHRB field 6 (longitude's hemisphere letter) "": hemisphere letter is missing (blank))"},
  });
  check_told<kf>({
      {sealed("CPNVG,101218,4221.7,,07105.4,W,1,1,0,0,0,0,0,0,0"),
       R"(CPNVG field 3 (latitude's hemisphere letter) "": hemisphere letter is missing (blank))"},
      // A letter of the other axis: the letters this one allows.
      {sealed("GPRMC,134213.686,A,4221.7,E,07105.4,W,0,0,291263,,"),
       R"(GPRMC field 4 (latitude's hemisphere letter) "E": hemisphere letter is not N or S)"},
      {sealed("GPRMC,134213.686,A,4221.7,N,07105.4,S,0,0,291263,,"),
       R"(GPRMC field 6 (longitude's hemisphere letter) "S": hemisphere letter is not E or W)"},
      // The magnetic variation's letter (the mode after it), and a unit letter.
      {sealed("GPRMC,134213.686,A,4221.7,N,07105.4,W,0,0,291263,3.1,X,A"),
       R"(GPRMC field 11 (magnetic_variation's direction letter) "X": magnetic variation letter is not E or W)"},
      {sealed("GPGGA,134213.686,4221.7,N,07105.4,W,1,08,0.9,545.4,F,46.9,M,,"),
       R"(GPGGA field 10 (altitude_m's unit letter) "F": unit letter is not the one this field requires: the unit is M)"},
  });
  // field_about tells the parts apart; field_name stays the declared name.
  const nmea::field_about lat = nmea::about_field<standard::rmc>(3);
  const nmea::field_about ns = nmea::about_field<standard::rmc>(4);
  CHECK(lat.name == "latitude");
  CHECK(lat.part.empty());
  CHECK(ns.name == "latitude");
  CHECK(ns.part == "hemisphere letter");
  CHECK(nmea::field_name<standard::rmc>(4) == "latitude");
}

TEST_CASE("error_text: what is wrong with a refused position's text") {
  using rx = robotx::reports;
  using kf = kingfisher::from_vehicle;
  // DDMM.m without its minute digits before the point, whatever the value; decimal degrees in
  // a DDMM.m field are the same mistake.
  const std::string ddmm =
      "DDMM.m needs two minute digits and at least one degree digit before the point";
  check_told<kf>({
      // A sign where the letter carries it, either axis.
      {sealed("GPRMC,134213.686,A,-4221.7,N,07105.4,W,0,0,291263,,"),
       R"(GPRMC field 3 (latitude) "-4221.7": a sign is not allowed: the hemisphere letter carries it)"},
      {sealed("CPNVG,101218,4221.7,N,-07105.4,W,1,1,0,0,0,0,0,0,0"),
       R"(CPNVG field 4 (longitude) "-07105.4": a sign is not allowed: the hemisphere letter carries it)"},
      {sealed("GPRMC,134213.686,A,00.00,N,000.00,W,0,0,291263,0,E"),
       R"(GPRMC field 3 (latitude) "00.00": )" + ddmm},
      {sealed("GPRMC,134213.686,A,0000.00,N,00.00,W,0,0,291263,0,E"),
       R"(GPRMC field 5 (longitude) "00.00": )" + ddmm},
      {sealed("GPRMC,134213.686,A,37.352387,N,07105.4,W,0,0,291263,0,E"),
       R"(GPRMC field 3 (latitude) "37.352387": )" + ddmm},
      {sealed("GPRMC,134213.686,A,.5,N,07105.4,W,0,0,291263,0,E"),
       R"(GPRMC field 3 (latitude) ".5": )" + ddmm},
      // Too many degree digits, stray characters, too many fraction digits, beyond the axis.
      {sealed("GPRMC,134213.686,A,004221.7,N,07105.4,W,0,0,291263,0,E"),
       R"(GPRMC field 3 (latitude) "004221.7": DDMM.m has at most 2 degree digits before the minutes)"},
      {sealed("GPRMC,134213.686,A,4221.7,N,0007105.4,W,0,0,291263,0,E"),
       R"(GPRMC field 5 (longitude) "0007105.4": DDDMM.m has at most 3 degree digits before the minutes)"},
      {sealed("GPRMC,134213.686,A,000000000000000000004221.7,N,07105.4,W,0,0,291263,0,E"),
       R"(GPRMC field 3 (latitude) "000000000000000000004221.7": DDMM.m has at most 2 degree digits before the minutes)"},
      {sealed("GPRMC,134213.686,A,4221.7.1,N,07105.4,W,0,0,291263,0,E"),
       R"(GPRMC field 3 (latitude) "4221.7.1": DDMM.m holds only digits and one decimal point)"},
      {sealed("GPRMC,134213.686,A,4221.1234567890123,N,07105.4,W,0,0,291263,0,E"),
       R"(GPRMC field 3 (latitude) "4221.1234567890123": more than 12 fraction digits of a minute)"},
      {sealed("GPRMC,134213.686,A,9000.1,N,07105.4,W,0,0,291263,0,E"),
       R"(GPRMC field 3 (latitude) "9000.1": beyond 90 degrees)"},
      {sealed("GPRMC,134213.686,A,4221.7,N,18000.01,W,0,0,291263,0,E"),
       R"(GPRMC field 5 (longitude) "18000.01": beyond 180 degrees)"},
      // A fraction refused only by a strict policy.
      {sealed("GPRMC,134213.686,A,4221,N,07105.4,W,0,0,291263,0,E"),
       R"(GPRMC field 3 (latitude) "4221": no fraction: DDMM.m is sent with at least one digit after the point)",
       nmea::parse_policy::strict()},
      // Minutes of 60 keep their own error's words.
      {sealed("GPRMC,134213.686,A,4261.7,N,07105.4,W,0,0,291263,0,E"),
       R"(GPRMC field 3 (latitude) "4261.7": minutes out of range (00-59))"},
      // A signed magnetic variation.
      {sealed("GPRMC,134213.686,A,4221.7,N,07105.4,W,0,0,291263,-3.1,E"),
       R"(GPRMC field 10 (magnetic_variation) "-3.1": a sign is not allowed: the E/W letter carries it)"},
  });
  // The error of DDMM.m without its minute digits stays bad_latitude / bad_longitude.
  const auto rmc = kf::decode(sealed("GPRMC,134213.686,A,00.00,N,000.00,W,0,0,291263,0,E"));
  CHECK(rmc.ec == errc::bad_latitude);
  check_told<rx>({
      // A sign where the letter carries it, in decimal degrees, either axis.
      {sealed("RXHRB,101218,161229,29.6412654321,N,-82.3456789012,W,GATOR,1,1"),
       R"(RXHRB field 5 (longitude) "-82.3456789012": a sign is not allowed: the hemisphere letter carries it)"},
      {sealed("RXHRB,101218,161229,+29.6412654321,N,82.3456789012,W,GATOR,1,1"),
       R"(RXHRB field 3 (latitude) "+29.6412654321": a sign is not allowed: the hemisphere letter carries it)"},
      // Beyond the axis, and stray characters.
      {sealed("RXHRB,101218,161229,90.5,N,82.3,W,GATOR,1,1"),
       R"(RXHRB field 3 (latitude) "90.5": beyond 90 degrees)"},
      {sealed("RXHRB,101218,161229,29.6,N,82.3.4,W,GATOR,1,1"),
       R"(RXHRB field 5 (longitude) "82.3.4": not a number of decimal degrees)"},
  });
}

TEST_CASE("error_text: a checksum as it was sent") {
  using set = kingfisher::to_vehicle;
  check_told<set>({
      // Lower-case digits are echoed as sent.
      {"$PYDIR,45,55*5a\r\n",
       "checksum does not match the sentence (sent 5a, computed 57) at column 13"},
      // Digits that read in decimal as the computed checksum: the sender wrote it in decimal.
      {"$PYDIR,45,55*87\r\n",
       "checksum does not match the sentence (sent 87, computed 57: written in decimal?) at "
       "column 13"},
      {"$PYDIR,45,55*86\r\n",
       "checksum does not match the sentence (sent 86, computed 57) at column 13"},
  });
  CHECK(nmea::written_in_decimal("82", 0x52));
  CHECK(nmea::written_in_decimal("123", 123));
  CHECK_FALSE(nmea::written_in_decimal("07", 7));  // reads the same in hex: a right checksum
  CHECK_FALSE(nmea::written_in_decimal("8A", 0x52));
  CHECK_FALSE(nmea::written_in_decimal("", 0x52));
}

TEST_CASE("error_text: a text's declared length gives one error on both sides") {
  using s = sandshark::to_vehicle;
  check_told<s>({
      {"$BPLOG,ACKS,ON\r\n", R"(BPLOG field 1 (code) "ACKS": wrong length: exactly 3 characters)"},
      {"$BPLOG,AC,ON\r\n", R"(BPLOG field 1 (code) "AC": wrong length: exactly 3 characters)"},
  });
  CHECK(s::decode("$BPLOG,ACKS,ON\r\n").ec == errc::bad_length);
  CHECK(s::decode("$BPLOG,AC,ON\r\n").ec == errc::bad_length);
  using rx = robotx::reports;
  check_told<rx>({
      {sealed("RXHRB,101218,161229,29.6,N,82.3,W,GATORS,1,1"),
       R"(RXHRB field 7 (team_id) "GATORS": wrong length: exactly 5 characters)"},
      {sealed("RXHRB,101218,161229,29.6,N,82.3,W,GATR,1,1"),
       R"(RXHRB field 7 (team_id) "GATR": wrong length: exactly 5 characters)"},
  });
}

// The former names, kept for one release: the same functions and types under their old names.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
TEST_CASE("error_text: the former names still give the same text and types") {
  const std::string_view line = "$PYDIR,150,0\r\n";
  const auto r = kingfisher::to_vehicle::decode(line);
  char now[128];
  char was[128];
  CHECK(nmea::describe<kingfisher::to_vehicle>(was, r, line) ==
        nmea::error_text<kingfisher::to_vehicle>(now, r, line));
  const auto rmc = nmea::decode<standard::rmc>(
      std::string_view("$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,400,311214,,,A"));
  CHECK(nmea::describe<standard::rmc>(was, rmc, "$GPRMC") ==
        nmea::error_text<standard::rmc>(now, rmc, "$GPRMC"));
  anello::sensor_frame_raw f;
  f.heading = 361;
  const auto v = anello::validate(f);
  CHECK(anello::describe(was, v, f) == anello::error_text(now, v, f));
  STATIC_REQUIRE(std::is_same_v<nmea2000::date, nmea2000::day_count>);
  STATIC_REQUIRE(std::is_same_v<nmea2000::time_of_day, nmea2000::time_since_midnight>);
}
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
