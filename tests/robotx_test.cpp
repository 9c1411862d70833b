// SPDX-License-Identifier: BSL-1.0
// RobotX 2018 reports: the spec's five examples, verified vectors and malformed input per
// message (round trips over generated values: round_trip_test.cpp).
#include "seawire/robotx/messages.hpp"

#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "support.hpp"

namespace {

using namespace support;

using namespace std::string_view_literals;
namespace nmea = seawire::nmea;
namespace rx = seawire::robotx;
using nmea::decimal;
using seawire::errc;

// The spec's examples, with the CR LF the spec ends every message with.
constexpr std::string_view seed_hrb =
    "$RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,2,1*06\r\n";
constexpr std::string_view seed_gat = "$RXGAT,101218,161229,AUVSI,1,2,Y,RGB*25\r\n";
constexpr std::string_view seed_cod = "$RXCOD,101218,161229,AUVSI,RGB*49\r\n";
constexpr std::string_view seed_dok = "$RXDOK,101218,161229,AUVSI,R,TRIAN*28\r\n";
constexpr std::string_view seed_del = "$RXDEL,101218,161229,AUVSI,R,CIRCL*32\r\n";
// Verified too: a 2022 heartbeat (same layout), and one that is wrong on purpose.
constexpr std::string_view hrb_2022 = "$RXHRB,111221,161229,21.31198,N,157.88972,W,ROBOT,2,1*11";
constexpr std::string_view hrb_bad = "$RXHRB,29620,1384,0,N,0,E,USYD_ROWBOT,3,1*5e";

template <class M>
constexpr bool round_trips(std::string_view line) {
  const auto r = nmea::decode<M>(line, rx::judge_policy);
  return r.ok() && nmea::encode(r.value).view() == line;
}
static_assert(round_trips<rx::rxhrb>(seed_hrb));
static_assert(round_trips<rx::rxgat>(seed_gat));
static_assert(round_trips<rx::rxcod>(seed_cod));
static_assert(round_trips<rx::rxdok>(seed_dok));
static_assert(round_trips<rx::rxdel>(seed_del));
static_assert(nmea::decode<rx::rxhrb>(hrb_bad, rx::judge_policy).ec == errc::checksum_mismatch);

std::string encoded(const auto& msg) { return std::string(nmea::encode(msg).view()); }

template <class M>
void check_rows(const std::vector<bad_case>& rows) {
  for (const bad_case& row : rows) check_bad<M>(row, rx::judge_policy);
}

}  // namespace

TEST_CASE("RXHRB: the spec's heartbeat decodes to the values in Table 1") {
  const auto r = nmea::decode<rx::rxhrb>(seed_hrb, rx::judge_policy);
  REQUIRE(r.ok());
  const rx::rxhrb& m = r.value;
  CHECK(m.date == nmea::date{2018, 12, 10});
  CHECK(m.time == nmea::time_of_day{16, 12, 29, 0, 0});
  REQUIRE(m.lat);
  CHECK(m.lat->value == decimal::scaled(2131198, 5));
  CHECK(m.lat->hemi == nmea::hemisphere::north);
  CHECK(m.lat->degrees() == Approx(21.31198));
  REQUIRE(m.lon);
  CHECK(m.lon->value == decimal::scaled(15788972, 5));
  CHECK(m.lon->hemi == nmea::hemisphere::west);
  CHECK(m.lon->degrees() == Approx(-157.88972));
  CHECK(m.team_id == "AUVSI"sv);
  CHECK(m.system_mode == rx::system_mode::autonomous);
  CHECK(m.auv_status == rx::auv_status::stowed);
  CHECK(encoded(m) == seed_hrb);
}

TEST_CASE("RXGAT: the spec's gates report decodes to the values in Table 2") {
  const auto r = nmea::decode<rx::rxgat>(seed_gat, rx::judge_policy);
  REQUIRE(r.ok());
  CHECK(r.value.date == nmea::date{2018, 12, 10});
  CHECK(r.value.time == nmea::time_of_day{16, 12, 29, 0, 0});
  CHECK(r.value.team_id == "AUVSI"sv);
  CHECK(r.value.entrance_gate == rx::gate::one);
  CHECK(r.value.exit_gate == rx::gate::two);
  CHECK(r.value.light_buoy_active == rx::light_buoy::on);
  REQUIRE(r.value.light_pattern);
  // The example message says RGB (Table 2's example column says RBG; the checksum 25 is RGB's).
  CHECK(r.value.light_pattern->colors[0] == rx::color::red);
  CHECK(r.value.light_pattern->colors[1] == rx::color::green);
  CHECK(r.value.light_pattern->colors[2] == rx::color::blue);
  CHECK(encoded(r.value) == seed_gat);
}

TEST_CASE("RXCOD: the spec's light buoy report decodes to the values in Table 3") {
  const auto r = nmea::decode<rx::rxcod>(seed_cod, rx::judge_policy);
  REQUIRE(r.ok());
  CHECK(r.value.date == nmea::date{2018, 12, 10});
  CHECK(r.value.time == nmea::time_of_day{16, 12, 29, 0, 0});
  CHECK(r.value.team_id == "AUVSI"sv);
  CHECK(r.value.light_pattern == rx::light_pattern::from("RGB").value);
  CHECK(encoded(r.value) == seed_cod);
}

TEST_CASE("RXDOK: the spec's dock report decodes to the values in Table 4") {
  const auto r = nmea::decode<rx::rxdok>(seed_dok, rx::judge_policy);
  REQUIRE(r.ok());
  CHECK(r.value.date == nmea::date{2018, 12, 10});
  CHECK(r.value.time == nmea::time_of_day{16, 12, 29, 0, 0});
  CHECK(r.value.team_id == "AUVSI"sv);
  CHECK(r.value.shape_color == rx::color::red);
  CHECK(r.value.shape == rx::dock_shape::triangle);
  CHECK(encoded(r.value) == seed_dok);
}

TEST_CASE("RXDEL: the spec's deliver report decodes to the values in Table 5") {
  const auto r = nmea::decode<rx::rxdel>(seed_del, rx::judge_policy);
  REQUIRE(r.ok());
  CHECK(r.value.date == nmea::date{2018, 12, 10});
  CHECK(r.value.time == nmea::time_of_day{16, 12, 29, 0, 0});
  CHECK(r.value.team_id == "AUVSI"sv);
  CHECK(r.value.shape_color == rx::color::red);
  CHECK(r.value.shape == rx::deliver_shape::circle);
  CHECK(encoded(r.value) == seed_del);
}

TEST_CASE("RXHRB: the 2022 heartbeat has the 2018 layout") {
  const auto r = nmea::decode<rx::rxhrb>(hrb_2022, rx::judge_policy);
  REQUIRE(r.ok());
  CHECK(r.value.date == nmea::date{2021, 12, 11});
  CHECK(r.value.time == nmea::time_of_day{16, 12, 29, 0, 0});
  CHECK(r.value.team_id == "ROBOT"sv);
  CHECK(r.value.system_mode == rx::system_mode::autonomous);
  CHECK(r.value.auv_status == rx::auv_status::stowed);
  CHECK(encoded(r.value) == std::string(hrb_2022) + "\r\n");
}

TEST_CASE("RXHRB: the bad-on-purpose heartbeat fails on each error in turn") {
  // Judges' policy: the checksum is checked first (5e sent, 11 computed).
  const auto judged = nmea::decode<rx::rxhrb>(hrb_bad, rx::judge_policy);
  CHECK(judged.ec == errc::checksum_mismatch);
  CHECK(judged.field == 0);

  // Checksum ignored: the decoder stops at the first bad field. Fix each and see the next.
  nmea::parse_policy p = rx::judge_policy;
  p.checksum = nmea::checksum_policy::ignore;
  const auto date = nmea::decode<rx::rxhrb>(hrb_bad, p);
  CHECK(date.ec == errc::bad_date);
  CHECK(date.field == 1);

  const auto time = nmea::decode<rx::rxhrb>("$RXHRB,290620,1384,0,N,0,E,USYD_ROWBOT,3,1*5e", p);
  CHECK(time.ec == errc::bad_time);
  CHECK(time.field == 2);

  const auto team = nmea::decode<rx::rxhrb>("$RXHRB,290620,130804,0,N,0,E,USYD_ROWBOT,3,1*5e", p);
  CHECK(team.ec == errc::bad_length);
  CHECK(team.field == 7);

  // Mode 3 is "killed" from 2022 on; the 2018 table has only 1 and 2.
  const auto mode = nmea::decode<rx::rxhrb>("$RXHRB,290620,130804,0,N,0,E,USYD_,3,1*5e", p);
  CHECK(mode.ec == errc::bad_enum);
  CHECK(mode.field == 8);

  const auto fixed = nmea::decode<rx::rxhrb>("$RXHRB,290620,130804,0,N,0,E,USYD_,2,1*5e", p);
  REQUIRE(fixed.ok());
  CHECK(fixed.value.date == nmea::date{2020, 6, 29});
  CHECK(fixed.value.lat->value.is_zero());
  CHECK(fixed.value.lon->hemi == nmea::hemisphere::east);
}

TEST_CASE("judge policy: the checksum is required, either hex case accepted") {
  const auto missing =
      nmea::decode<rx::rxcod>("$RXCOD,101218,161229,AUVSI,RGB\r\n", rx::judge_policy);
  CHECK(missing.ec == errc::missing_checksum);
  const auto wrong = nmea::decode<rx::rxcod>("$RXCOD,101218,161229,AUVSI,RGB*48", rx::judge_policy);
  CHECK(wrong.ec == errc::checksum_mismatch);
  // One checksum with a lower-case digit: RXHRB ... ROBO1 ... is 0x7F.
  const auto lower_f = nmea::decode<rx::rxhrb>(
      "$RXHRB,101218,161229,21.31198,N,157.88972,W,ROBO1,2,1*7f", rx::judge_policy);
  CHECK(lower_f.ok());
  // Encoding always writes the checksum, upper case.
  CHECK(encoded(lower_f.value) == "$RXHRB,101218,161229,21.31198,N,157.88972,W,ROBO1,2,1*7F\r\n");
}

TEST_CASE("shapes: CRUC and CRUCI are read by both messages, each writes its own table's") {
  const auto dok_cruci =
      nmea::decode<rx::rxdok>(sealed("RXDOK,101218,161229,AUVSI,G,CRUCI"), rx::judge_policy);
  REQUIRE(dok_cruci.ok());
  CHECK(dok_cruci.value.shape == rx::dock_shape::cruciform);
  CHECK(encoded(dok_cruci.value) == sealed("RXDOK,101218,161229,AUVSI,G,CRUC"));

  const auto del_cruc =
      nmea::decode<rx::rxdel>(sealed("RXDEL,101218,161229,AUVSI,B,CRUC"), rx::judge_policy);
  REQUIRE(del_cruc.ok());
  CHECK(del_cruc.value.shape == rx::deliver_shape::cruciform);
  CHECK(encoded(del_cruc.value) == sealed("RXDEL,101218,161229,AUVSI,B,CRUCI"));

  CHECK(rx::as_deliver_shape(rx::dock_shape::triangle) == rx::deliver_shape::triangle);
  CHECK(rx::as_dock_shape(rx::deliver_shape::cruciform) == rx::dock_shape::cruciform);
  CHECK(nmea::to_string(rx::dock_shape::circle) == "CIRCL");
  CHECK(nmea::to_string(rx::deliver_shape::cruciform) == "CRUCI");
}

TEST_CASE("blank fields: position, AUV status and task answers may be blank") {
  const auto hrb =
      nmea::decode<rx::rxhrb>(sealed("RXHRB,101218,161229,,,,,AUVSI,1,"), rx::judge_policy);
  REQUIRE(hrb.ok());
  CHECK_FALSE(hrb.value.lat);
  CHECK_FALSE(hrb.value.lon);
  CHECK_FALSE(hrb.value.auv_status);
  CHECK(hrb.value.system_mode == rx::system_mode::remote);
  CHECK(encoded(hrb.value) == sealed("RXHRB,101218,161229,,,,,AUVSI,1,"));

  const auto gat =
      nmea::decode<rx::rxgat>(sealed("RXGAT,101218,161229,AUVSI,3,,N,"), rx::judge_policy);
  REQUIRE(gat.ok());
  CHECK(gat.value.entrance_gate == rx::gate::three);
  CHECK_FALSE(gat.value.exit_gate);
  CHECK(gat.value.light_buoy_active == rx::light_buoy::off);
  CHECK_FALSE(gat.value.light_pattern);
  CHECK(encoded(gat.value) == sealed("RXGAT,101218,161229,AUVSI,3,,N,"));

  for (std::string_view body : {"RXCOD,101218,161229,AUVSI,"sv, "RXDOK,101218,161229,AUVSI,,"sv,
                                "RXDEL,101218,161229,AUVSI,,"sv}) {
    INFO(body);
    const auto r = rx::decode_report(sealed(body));
    REQUIRE(r.ok());
    std::visit(
        [&](const auto& m) {
          if constexpr (!std::is_same_v<std::decay_t<decltype(m)>, nmea::unknown_sentence>)
            CHECK(encoded(m) == sealed(body));
        },
        r.value);
  }
}

TEST_CASE("positions: unsigned decimal degrees, the sign from the hemisphere only") {
  const auto south = nmea::decode<rx::rxhrb>(
      sealed("RXHRB,101218,161229,33.88710,S,151.18770,E,USYD_,2,2"), rx::judge_policy);
  REQUIRE(south.ok());
  CHECK(south.value.lat->degrees() == Approx(-33.8871));
  CHECK(south.value.lon->degrees() == Approx(151.1877));
  CHECK(south.value.lat->value == decimal::scaled(3388710, 5));  // trailing zero kept

  // 0 with S/W: the letter still gives the sign.
  const auto zero = nmea::decode<rx::rxhrb>(sealed("RXHRB,101218,161229,0.0,S,0.0,W,AUVSI,2,1"),
                                            rx::judge_policy);
  REQUIRE(zero.ok());
  CHECK(zero.value.lat->hemi == nmea::hemisphere::south);
  CHECK(encoded(zero.value) == sealed("RXHRB,101218,161229,0.0,S,0.0,W,AUVSI,2,1"));

  // from_degrees: the caller's signed degrees become value + letter.
  rx::rxhrb m;
  m.team_id = "AUVSI";
  m.lat = nmea::decimal_latitude::from_degrees(21.311984, 5).value;
  m.lon = nmea::decimal_longitude::from_degrees(-157.889721, 5).value;
  CHECK(encoded(m) == sealed("RXHRB,010100,000000,21.31198,N,157.88972,W,AUVSI,2,"));
}

TEST_CASE("RXHRB: malformed fields give the errc and the field number") {
  check_rows<rx::rxhrb>({
      {"RXHRB,,161229,21.31198,N,157.88972,W,AUVSI,2,1", errc::missing_field, 1},
      {"RXHRB,10121,161229,21.31198,N,157.88972,W,AUVSI,2,1", errc::bad_date, 1},
      {"RXHRB,1012188,161229,21.31198,N,157.88972,W,AUVSI,2,1", errc::bad_date, 1},
      {"RXHRB,10-218,161229,21.31198,N,157.88972,W,AUVSI,2,1", errc::bad_date, 1},
      {"RXHRB,101318,161229,21.31198,N,157.88972,W,AUVSI,2,1", errc::month_out_of_range, 1},
      {"RXHRB,290219,161229,21.31198,N,157.88972,W,AUVSI,2,1", errc::day_out_of_range, 1},
      {"RXHRB,101218,,21.31198,N,157.88972,W,AUVSI,2,1", errc::missing_field, 2},
      {"RXHRB,101218,16122,21.31198,N,157.88972,W,AUVSI,2,1", errc::bad_time, 2},
      {"RXHRB,101218,161229.5,21.31198,N,157.88972,W,AUVSI,2,1", errc::bad_time, 2},
      {"RXHRB,101218,241229,21.31198,N,157.88972,W,AUVSI,2,1", errc::hour_out_of_range, 2},
      {"RXHRB,101218,166029,21.31198,N,157.88972,W,AUVSI,2,1", errc::minute_out_of_range, 2},
      {"RXHRB,101218,161260,21.31198,N,157.88972,W,AUVSI,2,1", errc::second_out_of_range, 2},
      {"RXHRB,101218,161229,-21.31198,N,157.88972,W,AUVSI,2,1", errc::bad_latitude, 3},
      {"RXHRB,101218,161229,+21.31198,N,157.88972,W,AUVSI,2,1", errc::bad_latitude, 3},
      {"RXHRB,101218,161229,90.1,N,157.88972,W,AUVSI,2,1", errc::bad_latitude, 3},
      {"RXHRB,101218,161229,21.3x,N,157.88972,W,AUVSI,2,1", errc::bad_latitude, 3},
      {"RXHRB,101218,161229,21.31198,E,157.88972,W,AUVSI,2,1", errc::bad_hemisphere, 4},
      {"RXHRB,101218,161229,21.31198,n,157.88972,W,AUVSI,2,1", errc::bad_hemisphere, 4},
      {"RXHRB,101218,161229,21.31198,N,180.5,W,AUVSI,2,1", errc::bad_longitude, 5},
      {"RXHRB,101218,161229,21.31198,N,-157.88972,W,AUVSI,2,1", errc::bad_longitude, 5},
      {"RXHRB,101218,161229,21.31198,N,157.88972,N,AUVSI,2,1", errc::bad_hemisphere, 6},
      {"RXHRB,101218,161229,21.31198,N,157.88972,W,,2,1", errc::missing_field, 7},
      {"RXHRB,101218,161229,21.31198,N,157.88972,W,AUVS,2,1", errc::bad_length, 7},
      {"RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI1,2,1", errc::bad_length, 7},
      {"RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,,1", errc::missing_field, 8},
      {"RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,0,1", errc::bad_enum, 8},
      {"RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,3,1", errc::bad_enum, 8},
      {"RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,22,1", errc::bad_enum, 8},
      {"RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,2,6", errc::bad_enum, 9},
      {"RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,2,0", errc::bad_enum, 9},
      {"RXHRB,101218,161229,21.31198,N,157.88972,W", errc::too_few_fields, 7},
      {"RXHRB,101218,161229,21.31198", errc::too_few_fields, 4},
      {"RXHRB", errc::too_few_fields, 1},
      {"RXGAT,101218,161229,21.31198,N,157.88972,W,AUVSI,2,1", errc::wrong_address, 0},
  });
}

TEST_CASE("RXGAT: malformed fields give the errc and the field number") {
  check_rows<rx::rxgat>({
      {"RXGAT,1012,161229,AUVSI,1,2,Y,RGB", errc::bad_date, 1},
      {"RXGAT,101218,1612,AUVSI,1,2,Y,RGB", errc::bad_time, 2},
      {"RXGAT,101218,161229,AUV,1,2,Y,RGB", errc::bad_length, 3},
      {"RXGAT,101218,161229,,1,2,Y,RGB", errc::missing_field, 3},
      {"RXGAT,101218,161229,AUVSI,4,2,Y,RGB", errc::bad_enum, 4},
      {"RXGAT,101218,161229,AUVSI,0,2,Y,RGB", errc::bad_enum, 4},
      {"RXGAT,101218,161229,AUVSI,1,A,Y,RGB", errc::bad_enum, 5},
      {"RXGAT,101218,161229,AUVSI,1,2,y,RGB", errc::bad_enum, 6},
      {"RXGAT,101218,161229,AUVSI,1,2,1,RGB", errc::bad_enum, 6},
      {"RXGAT,101218,161229,AUVSI,1,2,Y,RG", errc::bad_length, 7},
      {"RXGAT,101218,161229,AUVSI,1,2,Y,RGBR", errc::bad_length, 7},
      {"RXGAT,101218,161229,AUVSI,1,2,Y,RGY", errc::bad_enum, 7},
      {"RXGAT,101218,161229,AUVSI,1,2,Y,rgb", errc::bad_enum, 7},
  });
}

TEST_CASE("trailing optional fields left out are accepted (the validator flags them)") {
  const auto r = nmea::decode<rx::rxgat>(sealed("RXGAT,101218,161229,AUVSI,1"), rx::judge_policy);
  REQUIRE(r.ok());
  CHECK(r.value.entrance_gate == rx::gate::one);
  CHECK_FALSE(r.value.exit_gate);
  CHECK_FALSE(r.value.light_pattern);
  // Written back with every comma the spec's sentence has.
  CHECK(encoded(r.value) == sealed("RXGAT,101218,161229,AUVSI,1,,,"));
}

TEST_CASE("RXCOD: malformed fields give the errc and the field number") {
  check_rows<rx::rxcod>({
      {"RXCOD,321218,161229,AUVSI,RGB", errc::day_out_of_range, 1},
      {"RXCOD,001218,161229,AUVSI,RGB", errc::day_out_of_range, 1},
      {"RXCOD,101218,16:12:29,AUVSI,RGB", errc::bad_time, 2},
      {"RXCOD,101218,161229,AUVSI?,RGB", errc::bad_length, 3},
      {"RXCOD,101218,161229,AUVSI,RGBG", errc::bad_length, 4},
      {"RXCOD,101218,161229,AUVSI,R G", errc::bad_enum, 4},
      {"RXCOD,101218,161229", errc::too_few_fields, 3},
  });
}

TEST_CASE("RXDOK: malformed fields give the errc and the field number") {
  check_rows<rx::rxdok>({
      {"RXDOK,100018,161229,AUVSI,R,TRIAN", errc::month_out_of_range, 1},
      {"RXDOK,101218,161229,AUVSI,Y,TRIAN", errc::bad_enum, 4},
      {"RXDOK,101218,161229,AUVSI,RB,TRIAN", errc::bad_enum, 4},
      {"RXDOK,101218,161229,AUVSI,R,TRIANGLE", errc::bad_enum, 5},
      {"RXDOK,101218,161229,AUVSI,R,trian", errc::bad_enum, 5},
      {"RXDOK,101218,161229,AUVSI,R,CRU", errc::bad_enum, 5},
      {"RXDOK,101218,161229,AUVSI,R,CIRCLE", errc::bad_enum, 5},
  });
}

TEST_CASE("RXDEL: malformed fields give the errc and the field number") {
  check_rows<rx::rxdel>({
      {"RXDEL,101218,161229,AUVSI,R,SQUAR", errc::bad_enum, 5},
      {"RXDEL,101218,161229,AUVSI,G,CRUCIF", errc::bad_enum, 5},
      {"RXDEL,101218,161229,AUVSI,r,CIRCL", errc::bad_enum, 4},
      {"RXDEL,101218,161229,AUVSI ,R,CIRCL", errc::bad_length, 3},
      {"RXDEL,101218,999999,AUVSI,R,CIRCL", errc::hour_out_of_range, 2},
  });
}

TEST_CASE("encode refuses what the spec does not allow, naming the field") {
  rx::rxhrb hb;
  hb.date = {2018, 12, 10};
  hb.time = {16, 12, 29, 0, 0};
  hb.team_id = "AUVSI";
  CHECK(encoded(hb) == sealed("RXHRB,101218,161229,,,,,AUVSI,2,"));

  auto short_team = hb;
  short_team.team_id = "AUV";
  CHECK(nmea::encode(short_team).ec == errc::bad_length);
  CHECK(nmea::encode(short_team).field == 7);

  auto reserved = hb;
  reserved.team_id = "AU,SI";
  CHECK(nmea::encode(reserved).ec == errc::bad_text);
  CHECK(nmea::encode(reserved).field == 7);

  auto fraction = hb;
  fraction.time.places = 2;
  fraction.time.fraction = 50;
  CHECK(nmea::encode(fraction).ec == errc::bad_time);
  CHECK(nmea::encode(fraction).field == 2);

  auto bad_day = hb;
  bad_day.date = {2018, 2, 29};
  CHECK(nmea::encode(bad_day).ec == errc::day_out_of_range);
  CHECK(nmea::encode(bad_day).field == 1);

  auto negative = hb;
  negative.lat = nmea::decimal_latitude{decimal::scaled(-2131198, 5), nmea::hemisphere::south};
  CHECK(nmea::encode(negative).ec == errc::bad_latitude);
  CHECK(nmea::encode(negative).field == 3);

  auto wrong_letter = hb;
  wrong_letter.lon = nmea::decimal_longitude{decimal::scaled(1, 0), nmea::hemisphere::north};
  CHECK(nmea::encode(wrong_letter).ec == errc::bad_hemisphere);
  CHECK(nmea::encode(wrong_letter).field == 6);  // the letter, as decode says

  auto mode = hb;
  mode.system_mode = static_cast<rx::system_mode>('3');
  CHECK(nmea::encode(mode).ec == errc::bad_enum);
  CHECK(nmea::encode(mode).field == 8);

  rx::rxcod cod;
  cod.team_id = "AUVSI";
  cod.light_pattern = rx::light_pattern{};  // three unset colours
  CHECK(nmea::encode(cod).ec == errc::bad_enum);
  CHECK(nmea::encode(cod).field == 4);

  rx::rxdok dok;
  dok.team_id = "AUVSI";
  dok.shape = static_cast<rx::dock_shape>(3);
  CHECK(nmea::encode(dok).ec == errc::bad_enum);
  CHECK(nmea::encode(dok).field == 5);
}

TEST_CASE("light_pattern::from") {
  constexpr auto rgb = rx::light_pattern::from("RGB");
  static_assert(rgb.ok() && rgb.value.colors[2] == rx::color::blue);
  CHECK(rx::light_pattern::from("BBB").value.colors[1] == rx::color::blue);  // repeats allowed
  CHECK(rx::light_pattern::from("RG").ec == errc::bad_length);
  CHECK(rx::light_pattern::from("").ec == errc::bad_length);
  CHECK(rx::light_pattern::from("RGW").ec == errc::bad_enum);
}

TEST_CASE("reports: decode by address, unknown addresses, visit") {
  const auto hrb = rx::decode_report(seed_hrb);
  REQUIRE(hrb.ok());
  CHECK(std::holds_alternative<rx::rxhrb>(hrb.value));
  CHECK(std::holds_alternative<rx::rxdel>(rx::decode_report(seed_del).value));
  CHECK(std::holds_alternative<rx::rxgat>(rx::decode_report(seed_gat).value));

  const auto other = rx::decode_report("$GPRMC,,V,,,,,,,,,,N*53");
  REQUIRE(other.ok());
  REQUIRE(std::holds_alternative<nmea::unknown_sentence>(other.value));
  CHECK(std::get<nmea::unknown_sentence>(other.value).sentence.address == "GPRMC");

  const auto bad = rx::decode_report(hrb_bad);
  CHECK(bad.ec == errc::checksum_mismatch);

  CHECK(rx::reports::knows("RXCOD"));
  CHECK_FALSE(rx::reports::knows("RXPAT"));
  CHECK(rx::reports::field_name("RXHRB", 4) == "latitude");
  CHECK(rx::reports::field_name("RXHRB", 7) == "team_id");
  CHECK(rx::reports::field_name("RXGAT", 7) == "light_pattern");

  CHECK(rx::address(rx::report_type::dock) == "RXDOK");
  CHECK(rx::report_type_for("RXGAT") == rx::report_type::gates);
  CHECK_FALSE(rx::report_type_for("RXHRX"));
  static_assert(rx::report_type_of<rx::rxcod> == rx::report_type::scan_code);

  std::string seen;
  const auto v = rx::visit_report(seed_dok, [&](const auto& m) {
    if constexpr (std::is_same_v<std::decay_t<decltype(m)>, rx::rxdok>) seen = "dok";
  });
  CHECK(v.ok());
  CHECK(seen == "dok");
  const auto nv = rx::visit_report("$RXDOK,101218,161229,AUVSI,R,TRIAN*29",
                                   [&](const auto&) { seen = "called"; });
  CHECK(nv.ec == errc::checksum_mismatch);
  CHECK(seen == "dok");
}

TEST_CASE("field names are the JSON names") {
  std::vector<std::string_view> names;
  nmea::for_each_field(rx::rxhrb{}, [&](std::string_view n, const auto&) { names.push_back(n); });
  CHECK(names == std::vector<std::string_view>{"date", "time", "latitude", "longitude", "team_id",
                                               "system_mode", "auv_status"});
}
