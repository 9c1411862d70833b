// SPDX-License-Identifier: BSL-1.0
// seawire/fmt.hpp: messages and value types through {fmt}, in the plain and the JSON form.
// Built everywhere; the checks need {fmt} (SEAWIRE_HAS_FMT, set by tests/CMakeLists.txt).

#include <catch2/catch.hpp>

#if SEAWIRE_HAS_FMT
#include <fmt/format.h>

#include <string>
#include <string_view>

#include "seawire/anello/frame.hpp"
#include "seawire/anello/frame_json.hpp"
#include "seawire/fmt.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/sandshark/messages.hpp"
#include "seawire/standard/rmc.hpp"
#include "support.hpp"

using namespace seawire;
using namespace seawire::nmea;
using support::must_decode;
using support::string_sink;

namespace {
constexpr std::string_view kNvg =
    "$CPNVG,164959.034,4221.711142,N,7105.44878,W,1,0,0,234.32964,-6.796959,-1.706798,"
    "164959.006*78";
}  // namespace

TEST_CASE("messages: plain and JSON") {
  const auto nvg = must_decode<kingfisher::cpnvg>(kNvg);
  CHECK(fmt::format("{}", nvg) ==
        "CPNVG{timestamp=16:49:59.034, latitude=42.36185236666667, longitude=-71.0908130, "
        "position_quality=true, altitude_m=0, depth_m=0, heading_deg=234.32964, "
        "roll_deg=-6.796959, pitch_deg=-1.706798, nav_timestamp=16:49:59.006}");
  // {:j} is write_json, byte for byte.
  string_sink k;
  write_json(k, nvg);
  CHECK(fmt::format("{:j}", nvg) == k.s);

  const auto sts = must_decode<sandshark::bpsts>("$BPSTS,231133.12,1,BWSI Autonomy OK*46");
  CHECK(fmt::format("{}", sts) ==
        R"(BPSTS{timestamp=23:11:33.12, all_ok=true, message="BWSI Autonomy OK"})");
  const auto rmc = must_decode<standard::rmc>("$GNRMC,164959.00,V,,,,,,,311214,,,N*61");
  CHECK(fmt::format("{}", rmc) ==
        "GNRMC{time=16:49:59.00, status=V, latitude=null, longitude=null, speed_knots=null, "
        "course_true=null, date=2014-12-31, magnetic_variation=null, mode=N, "
        "navigational_status=null}");
  const auto gat = must_decode<robotx::rxgat>("$RXGAT,101218,161229,AUVSI,1,2,Y,RGB*25");
  CHECK(fmt::format("{}", gat) ==
        R"(RXGAT{date=2018-12-10, time=16:12:29, team_id="AUVSI", entrance_gate=1, exit_gate=2, )"
        R"(light_buoy_active=Y, light_pattern=RGB})");
}

TEST_CASE("value types on their own") {
  const auto nvg = must_decode<kingfisher::cpnvg>(kNvg);
  CHECK(fmt::format("{}", nvg.lat) == "42.36185236666667");
  CHECK(fmt::format("{}", nvg.lon) == "-71.0908130");
  CHECK(fmt::format("{}", nvg.timestamp) == "16:49:59.034");
  CHECK(fmt::format("{:j}", nvg.timestamp) == R"("16:49:59.034")");
  CHECK(fmt::format("{}", *nvg.heading_deg) == "234.32964");
  CHECK(fmt::format("{:>12}|", std::string_view("x")) == "           x|");  // fmt itself intact
  CHECK(fmt::format("{}", date{2018, 12, 10}) == "2018-12-10");
  CHECK(fmt::format("{}", text<16>("BWSI")) == "BWSI");
  CHECK(fmt::format("{:j}", text<16>("a\"b")) == R"("a\"b")");
  CHECK(fmt::format("{}", sandshark::log_state::on) == "ON");
  // A whole number as the number it is (a std::uint8_t one not as a character).
  CHECK(fmt::format("{}", nmea::integer<std::uint8_t>{65}) == "65");
  CHECK(fmt::format("{:j}", nmea::integer<std::int32_t>{-7}) == "-7");
  CHECK(fmt::format("{:j}", standard::rmc_status::warning) == R"("V")");
  const auto hrb =
      must_decode<robotx::rxhrb>("$RXHRB,111221,161229,21.31198,N,157.88972,W,ROBOT,2,1*11");
  CHECK(fmt::format("{} {}", *hrb.lat, *hrb.lon) == "21.31198 -157.88972");
}

TEST_CASE("unknown sentences: the line, or its fields as JSON") {
  const auto s = parse("$GPGSV,1,1,01,12,45,180,40*47");
  REQUIRE(s);
  const unknown_sentence u{s.value};
  CHECK(fmt::format("{}", u) == "$GPGSV,1,1,01,12,45,180,40*47");
  CHECK(fmt::format("{:j}", u) ==
        R"({"type":"GPGSV","fields":["1","1","01","12","45","180","40"]})");
}

TEST_CASE("NMEA 2000 messages and field values") {
  namespace n2k = seawire::nmea2000;
  const std::array<std::uint8_t, 8> frame{0x00, 0x12, 0x00, 0xFF, 0xFF, 0x00, 0xFF, 0xFF};
  const auto speed = n2k::decode<n2k::speed_water_referenced>(frame);
  CHECK(fmt::format("{}", speed) ==
        "PGN128259{sid=0, speed_water_mps=0.18, speed_ground_mps=null, speed_type=paddle_wheel, "
        "speed_direction=null}");
  // {:j} is write_json without a frame header, byte for byte.
  string_sink k;
  n2k::write_json(k, speed);
  CHECK(k.s == R"({"type":"PGN128259","sid":0,"speed_water_mps":0.18,"speed_ground_mps":null,)"
               R"("speed_type":"paddle_wheel","speed_direction":null})");
  CHECK(fmt::format("{:j}", speed) == k.s);

  CHECK(fmt::format("{}", speed.speed_water_mps) == "0.18");
  CHECK(fmt::format("{}", speed.speed_ground_mps) == "null");
  CHECK(fmt::format("{:j}", speed.speed_type) == R"("paddle_wheel")");

  n2k::engine_parameters_dynamic engine{};
  engine.discrete_status_1 = n2k::flags<n2k::engine_status_1, 16>::from_raw(0x0003);
  engine.temperature_k = n2k::unsigned_number<16, n2k::res::hundredth>::from_raw(0xFFFE);
  CHECK(fmt::format("{}", engine.discrete_status_1) == "[check_engine,over_temperature]");
  CHECK(fmt::format("{:j}", engine.discrete_status_1) == R"(["check_engine","over_temperature"])");
  CHECK(fmt::format("{}", engine.temperature_k) == "out_of_range");
  CHECK(fmt::format("{:j}", engine.temperature_k) == R"("out_of_range")");

  n2k::distance_log log{};
  log.date = n2k::day_count::from_raw(17'000);
  log.time = n2k::time_since_midnight::from_raw(453'251'234);
  CHECK(fmt::format("{} {}", log.date, log.time) == "2016-07-18 12:35:25.1234");
}

TEST_CASE("the ANELLO 0xAB00 frame: plain and JSON") {
  const anello::sensor_frame_raw f{.heading = 89,
                                   .lat = 32828671,
                                   .lon = -117229926,
                                   .sog = 0,
                                   .gps_time_ms = 0x00000190794363D0,
                                   .gga_quality = 4,
                                   .air_temp = 215};
  const std::string plain = fmt::format("{}", f);
  CHECK(
      plain.starts_with("AB00{heading_deg=89, latitude_deg=32.828671, longitude_deg=-117.229926, "
                        "sog_mps=0.0, cog_deg=null, gps_time=2024-07-03T15:42:58.000Z, "));
  CHECK(plain.find(", fix_quality=4, ") != std::string::npos);
  CHECK(plain.ends_with(", air_temp_c=21.5, pressure_hpa=null}"));
  // {:j} is anello::write_json, byte for byte.
  string_sink k;
  anello::write_json(k, f);
  CHECK(k.s.starts_with(R"({"type":"AB00","heading_deg":89,"latitude":32.828671,)"));
  CHECK(fmt::format("{:j}", f) == k.s);
}

#else
TEST_CASE("seawire/fmt.hpp needs {fmt}: not tested in this build") { SUCCEED(); }
#endif
