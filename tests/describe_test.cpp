// SPDX-License-Identifier: BSL-1.0
// describe(): errors told for people, with the sentence, the field, what it held, why, and
// what the field allows.

#include <catch2/catch.hpp>
#include <cstring>
#include <string>

#include "seawire/seawire.hpp"

namespace {
using namespace seawire;

template <class Set>
std::string told(std::string_view line, const nmea::parse_policy& p = {}) {
  char buf[256];
  const auto r = Set::decode(line, p);
  REQUIRE_FALSE(r);
  const std::string_view v = nmea::describe<Set>(buf, r, line, p);
  CHECK(std::strlen(buf) == v.size());  // a C string too
  return std::string(v);
}
}  // namespace

TEST_CASE("describe: field, text, reason and the range the field allows") {
  using kf = kingfisher::to_vehicle;
  CHECK(told<kf>("$PYDIR,150,0\r\n") ==
        R"(PYDIR field 1 (thrust_left) "150": value outside the range the spec allows: -100..100)");
  CHECK(
      told<kf>("$PYDEV,360,1.5\r\n") ==
      R"(PYDEV field 1 (heading_deg) "360": value outside the range the spec allows: 0..360 (360 excluded))");
  CHECK(told<kf>("$PYDEV,90,-1\r\n") ==
        R"(PYDEV field 2 (speed_mps) "-1": value outside the range the spec allows: at least 0)");
  CHECK(told<kf>("$PYDIR,1.2.3,0\r\n") ==
        R"(PYDIR field 1 (thrust_left) "1.2.3": not a number of the field's form)");
  CHECK(told<kf>("$PYDIR,12.5\r\n").starts_with("PYDIR field 2 (thrust_right): "));
  using s = sandshark::to_vehicle;
  CHECK(told<s>("$BPLOG,NV,ON\r\n") ==
        R"(BPLOG field 1 (code) "NV": wrong length: exactly 3 characters)");
}

TEST_CASE("describe: errors of the sentence as a whole say where") {
  using set = kingfisher::to_vehicle;
  CHECK(told<set>("$PYDIR,45,55*58\r\n") ==
        "checksum does not match the sentence (sent 58, computed 57) at column 13");
  CHECK(told<set>("PYDIR,45,55\r\n").ends_with(" at column 0"));
  // What follows a whole checksum is shown, without the line ending, unprintable bytes in hex.
  CHECK(told<set>("$PYDIR,45,55*6f \r\n") ==
        R"(unexpected characters after the checksum (" ") at column 15)");
  CHECK(told<set>("$PYDIR,45,55*57X\n") ==
        R"(unexpected characters after the checksum ("X") at column 15)");
  CHECK(told<set>("$PYDIR,45,55*57\x01\"\r\r\n") ==
        R"(unexpected characters after the checksum ("\x01\x22\x0D") at column 15)");
  CHECK(told<set>("$PYDIR,45,55*577\r\n") ==
        "checksum is not two hex digits (upper-case where required) at column 13");
  // One message type, without a set.
  char buf[200];
  const std::string_view line =
      "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,400,311214,,,A";
  const auto r = nmea::decode<standard::rmc>(line);
  REQUIRE_FALSE(r);
  CHECK(nmea::describe<standard::rmc>(buf, r, line) ==
        R"(GPRMC field 8 (course_true) "400": value outside the range the spec allows: 0..360)");
}

TEST_CASE("describe: a small buffer cuts the text and still ends it") {
  char small[12];
  const std::string_view line = "$PYDIR,150,0\r\n";
  const auto r = kingfisher::to_vehicle::decode(line);
  const std::string_view v = nmea::describe<kingfisher::to_vehicle>(small, r, line);
  CHECK(v == "PYDIR field");
  CHECK(small[11] == '\0');
  char none[1];
  CHECK(nmea::describe<kingfisher::to_vehicle>(none, r, line).empty());
  CHECK(none[0] == '\0');
}
