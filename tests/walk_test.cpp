// SPDX-License-Identifier: BSL-1.0
// The walk over a message's fields (walk.hpp): for a sentence, a PGN and the 0xAB00 frame, each
// field once in wire order with its name, key, unit, wire facts, value and state; the layout
// without a message; and the writers that are loops over it.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "seawire/anello/frame.hpp"
#include "seawire/anello/frame_json.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/csv.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/standard/rmc.hpp"
#include "seawire/walk.hpp"

namespace {

using namespace seawire;

// What a walk gave for one field.
struct seen {
  std::string name;
  std::string key;
  std::string unit;
  unsigned number = 0;
  unsigned bit_offset = 0;
  unsigned bits = 0;
  byte_order order = byte_order::text;
  position_axis axis = position_axis::none;
  field_state state = field_state::value;
  std::string json;  // the value as its wire's JSON text
};

template <class M>
std::vector<seen> walk(const M& msg) {
  std::vector<seen> out;
  visit_fields(msg, [&](const auto& f) {
    nmea::json_buffer<128> text;
    put_field_value<nmea::json_style::json>(text, f);
    out.push_back({std::string(f.name), std::string(f.key), std::string(f.unit), f.number,
                   f.bit_offset, f.bits, f.order, f.axis, f.state, std::string(text.view())});
  });
  return out;
}

template <class M>
std::vector<seen> layout() {
  std::vector<seen> out;
  visit_layout<M>([&](auto f) {
    out.push_back({std::string(f.name),
                   std::string(f.key),
                   std::string(f.unit),
                   f.number,
                   f.bit_offset,
                   f.bits,
                   f.order,
                   f.axis,
                   field_state::value,
                   {}});
  });
  return out;
}

// The walk and the writers over it are constant expressions.
constexpr std::size_t available(const anello::sensor_frame_raw& f) {
  std::size_t n = 0;
  visit_fields(f, [&](const auto& v) {
    if (v.has_value()) ++n;
  });
  return n;
}
static_assert(available(anello::sensor_frame_raw{}) == 0);
static_assert([] {
  anello::sensor_frame_raw f;
  f.heading = 1;
  f.pressure = 1013;
  return available(f);
}() == 2);
static_assert([] {
  nmea::json_buffer<256> out;
  nmea2000::speed_water_referenced m;
  m.sid = nmea2000::unsigned_number<8>::from_raw(3);
  nmea2000::write_json(out, m);
  return out.view() ==
         "{\"type\":\"PGN128259\",\"sid\":3,\"speed_water_mps\":null,\"speed_ground_mps\":null,"
         "\"speed_type\":null,\"speed_direction\":null}";
}());

}  // namespace

TEST_CASE("walk: a sentence's fields in wire order, with wire field numbers and states") {
  const auto line = std::string_view(
      "$CPNVG,081025.987,4221.81092,N,7106.84603,W,1,0,,203.1,-3.4,4.5,081025.980*4A");
  const auto r = nmea::decode<kingfisher::cpnvg>(
      line, nmea::parse_policy{.checksum = nmea::checksum_policy::ignore});
  REQUIRE(r);
  const std::vector<seen> v = walk(r.value);
  REQUIRE(v.size() == 10);  // 12 wire fields: two positions with their letters
  CHECK(v[9].number == 12);
  REQUIRE(v.size() == field_count_of<kingfisher::cpnvg>);
  // Every declared field once, in declaration order, under its declared name.
  std::vector<std::string> declared;
  kingfisher::cpnvg::nmea.fields.apply(
      [&](const auto&... d) { (declared.emplace_back(d.name), ...); });
  REQUIRE(declared.size() == v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    CHECK(v[i].name == declared[i]);
    CHECK(v[i].key == declared[i]);
  }
  CHECK(v[0].name == "timestamp");
  CHECK(v[0].number == 1);
  CHECK(v[1].name == "latitude");
  CHECK(v[1].number == 2);  // with its hemisphere letter: 2 and 3
  CHECK(v[1].axis == position_axis::latitude);
  CHECK(v[2].number == 4);
  CHECK(v[2].axis == position_axis::longitude);
  CHECK(v[3].number == 6);
  CHECK(v[0].axis == position_axis::none);
  for (const seen& s : v) {
    CHECK(s.order == byte_order::text);
    CHECK(s.bits == 0);
  }
  CHECK(v[4].name == "altitude_m");
  CHECK(v[4].unit == "m");
  CHECK(v[4].state == field_state::value);
  CHECK(v[5].name == "depth_m");
  CHECK(v[5].state == field_state::not_available);  // blank on the wire
  CHECK(v[5].json == "null");
  CHECK(v[6].unit == "deg");
  CHECK(v[0].unit.empty());
  CHECK(v[1].json == "42.3635153333333");
  CHECK(v[2].json == "-71.1141005");
}

TEST_CASE("walk: a blank variation and blank optionals are not available") {
  standard::rmc m;
  m.time = nmea::time_of_day{8, 10, 25, 0, 0};
  m.magnetic_variation = nmea::magnetic_variation{};  // a letter without a value
  std::vector<seen> v = walk(m);
  REQUIRE(v.size() == 10);
  CHECK(v[0].state == field_state::value);
  CHECK(v[1].name == "status");
  CHECK(v[1].state == field_state::value);
  CHECK(v[2].state == field_state::not_available);  // latitude: nullopt
  CHECK(v[7].name == "magnetic_variation");
  CHECK(v[7].number == 10);
  CHECK(v[7].state == field_state::not_available);
  m.magnetic_variation->value = nmea::decimal(3);
  v = walk(m);
  CHECK(v[7].state == field_state::value);
  CHECK(v[8].number == 12);
}

TEST_CASE("walk: a PGN's fields with bit offsets, widths and the sentinels' states") {
  nmea2000::speed_water_referenced m;
  m.sid = nmea2000::unsigned_number<8>::from_raw(7);
  m.speed_water_mps = nmea2000::unsigned_number<16, nmea2000::res::hundredth>::from_raw(18);
  m.speed_ground_mps = decltype(m.speed_ground_mps)::out_of_range();
  m.speed_type = nmea2000::water_reference::doppler;
  m.speed_direction = decltype(m.speed_direction)::not_available();
  const std::vector<seen> v = walk(m);
  REQUIRE(v.size() == 5);  // the reserved bits are no field
  CHECK(v[0].name == "sid");
  CHECK(v[0].number == 1);
  CHECK(v[0].bit_offset == 0);
  CHECK(v[0].bits == 8);
  CHECK(v[0].json == "7");
  CHECK(v[1].key == "speed_water_mps");
  CHECK(v[1].unit == "mps");
  CHECK(v[1].bit_offset == 8);
  CHECK(v[1].bits == 16);
  CHECK(v[1].order == byte_order::little_endian);
  CHECK(v[1].json == "0.18");
  CHECK(v[2].state == field_state::out_of_range);
  CHECK(v[2].json == "\"out_of_range\"");
  CHECK(v[3].bit_offset == 40);
  CHECK(v[3].json == "\"doppler\"");
  CHECK(v[4].bit_offset == 48);
  CHECK(v[4].bits == 4);
  CHECK(v[4].state == field_state::not_available);
  m.speed_direction = decltype(m.speed_direction)::from_raw(14);  // 4 bits: 15 n/a, 14
  CHECK(walk(m)[4].state == field_state::out_of_range);
  m.speed_water_mps = decltype(m.speed_water_mps)::reserved();
  CHECK(walk(m)[1].state == field_state::reserved);

  // The rows, reserved bits included, cover the payload.
  unsigned rows = 0;
  unsigned end = 0;
  bool reserved_last = false;
  visit_rows<nmea2000::speed_water_referenced>([&](auto f) {
    ++rows;
    CHECK(f.number == rows);
    CHECK(f.bit_offset == end);
    end = f.bit_offset + f.bits;
    reserved_last = f.reserved;
  });
  CHECK(rows == 6);
  CHECK(reserved_last);
  CHECK(end == 8 * nmea2000::description_of<nmea2000::speed_water_referenced>::length);
}

TEST_CASE("walk: the frame's fields are big-endian, raw with their scale") {
  anello::sensor_frame_raw f;
  f.heading = 89;
  f.lat = 32828671;
  f.sog = 5;
  f.air_temp = -1;  // also "not available"
  const std::vector<seen> v = walk(f);
  REQUIRE(v.size() == anello::sensor_field_count);
  CHECK(v[0].name == "heading_deg");
  CHECK(v[0].number == 1);
  CHECK(v[0].bit_offset == 64);  // after the 8-byte header
  CHECK(v[0].bits == 16);
  CHECK(v[0].order == byte_order::big_endian);
  CHECK(v[0].json == "89");
  CHECK(v[1].name == "latitude_deg");
  CHECK(v[1].key == "latitude");
  CHECK(v[1].axis == position_axis::latitude);
  CHECK(v[1].json == "32.828671");
  CHECK(v[2].key == "longitude");
  CHECK(v[2].axis == position_axis::longitude);
  CHECK(v[2].state == field_state::not_available);
  CHECK(v[2].json == "null");
  CHECK(v[3].json == "0.5");
  CHECK(v[17].name == "air_temp_c");
  CHECK(v[17].unit == "c");
  CHECK(v[17].state == field_state::not_available);
  CHECK(v[18].bit_offset + v[18].bits == 8 * anello::frame_size);
  // Offsets agree with the table's byte offsets, one field after the other.
  std::size_t i = 0;
  anello::detail::visit_sensor_fields([&](std::uint16_t n, const auto& field) {
    CHECK(v[i].number == n);
    CHECK(v[i].bit_offset == 8 * field.offset);
    CHECK(v[i].name == field.name);
    ++i;
    return true;
  });
  CHECK(i == v.size());
}

TEST_CASE("walk: a frame field a strict sender could not have written is out_of_range") {
  anello::sensor_frame_raw f;
  f.heading = 361;      // the spec allows 0-360
  f.gga_quality = 9;    // qualities 0-8
  f.motor = -101;       // -100..100
  f.rudder = 100;       // in range
  f.air_temp = 0x7FFE;  // the wire type's largest value short of "not available"
  const std::vector<seen> v = walk(f);
  CHECK(v[0].state == field_state::out_of_range);
  CHECK(v[0].json == "361");  // the value is still given: the frame has no sentinel for it
  CHECK(v[9].state == field_state::out_of_range);
  CHECK(v[9].json == "9");
  CHECK(v[10].state == field_state::out_of_range);
  CHECK(v[10].json == "-101");
  CHECK(v[11].state == field_state::value);
  CHECK(v[17].state == field_state::value);
  CHECK(v[17].json == "3276.6");
  // The same fields are the ones validate() refuses, the first of them by number.
  const auto checked = anello::validate(f);
  CHECK(checked.ec == seawire::errc::out_of_range);
  CHECK(checked.field == 1);
  std::size_t out_of_range = 0;
  for (const seen& s : v) out_of_range += s.state == field_state::out_of_range ? 1 : 0;
  CHECK(out_of_range == 3);
  // CSV gives the value too; only "not available" is an empty cell.
  nmea::json_buffer<1024> csv;
  write_csv_cells(csv, f);
  CHECK(std::string_view(csv.view()).starts_with("361,,,,,,,,,9,-101,100,"));
}

TEST_CASE("walk: units from the name's last word, rates and charges too") {
  const auto turn = layout<nmea2000::rate_of_turn>();
  const auto rate =
      std::find_if(turn.begin(), turn.end(), [](const seen& f) { return f.name == "rate_radps"; });
  REQUIRE(rate != turn.end());
  CHECK(rate->unit == "radps");
  const auto dc = layout<nmea2000::dc_detailed_status>();
  const auto charge = std::find_if(dc.begin(), dc.end(),
                                   [](const seen& f) { return f.name == "remaining_capacity_ah"; });
  REQUIRE(charge != dc.end());
  CHECK(charge->unit == "ah");
  CHECK(seawire::detail::unit_of_name("dc_instance").empty());
}

TEST_CASE("walk: the layout has the message's facts without a message") {
  const auto sentence = layout<kingfisher::cpnvg>();
  const auto walked = walk(kingfisher::cpnvg{});
  REQUIRE(sentence.size() == walked.size());
  for (std::size_t i = 0; i < sentence.size(); ++i) {
    CHECK(sentence[i].key == walked[i].key);
    CHECK(sentence[i].number == walked[i].number);
    CHECK(sentence[i].axis == walked[i].axis);
  }
  const auto pgn = layout<nmea2000::speed_water_referenced>();
  REQUIRE(pgn.size() == 5);
  CHECK(pgn[4].bit_offset == 48);
  const auto frame = layout<anello::sensor_frame_raw>();
  REQUIRE(frame.size() == 19);
  CHECK(frame[5].key == "gps_time");
  CHECK(frame[5].bits == 64);
  // Compile-time facts.
  visit_layout<anello::sensor_frame_raw>([](auto f) {
    static_assert(decltype(f)::kind == wire_kind::anello_frame);
    static_assert(!decltype(f)::key.empty());
  });
  static_assert(field_count_of<nmea2000::speed_water_referenced> == 5);
  static_assert(walkable<standard::rmc> && walkable<anello::sensor_frame_raw>);
  static_assert(!walkable<int>);
}

TEST_CASE("walk: every writer is a loop over it") {
  nmea2000::speed_water_referenced m;
  m.sid = nmea2000::unsigned_number<8>::from_raw(0);
  m.speed_water_mps = decltype(m.speed_water_mps)::from_raw(18);
  m.speed_type = nmea2000::water_reference::paddle_wheel;
  // JSON: `,"key":value` per field after the head, keys as the walk gives them.
  nmea::json_buffer<512> fields;
  write_json_fields(fields, m);
  std::string expected;
  visit_fields(m, [&](const auto& f) {
    nmea::json_buffer<64> value;
    put_field_value<nmea::json_style::json>(value, f);
    expected += ",\"" + std::string(f.key) + "\":" + std::string(value.view());
  });
  CHECK(fields.view() == expected);
  CHECK(fields.view() ==
        ",\"sid\":0,\"speed_water_mps\":0.18,\"speed_ground_mps\":null,\"speed_type\":\"paddle_"
        "wheel\",\"speed_direction\":null");
  // CSV: the keys, then the cells.
  nmea::json_buffer<512> csv;
  write_csv_columns<nmea2000::speed_water_referenced>(csv);
  write_csv_cells(csv, m);
  CHECK(csv.view() ==
        "sid,speed_water_mps,speed_ground_mps,speed_type,speed_direction\n0,0.18,,paddle_wheel,\n");
  // Plain: name=value.
  nmea::json_buffer<512> plain;
  write_plain_fields(plain, anello::sensor_frame_raw{});
  CHECK(plain.view().starts_with("{heading_deg=null, latitude_deg=null, "));
  CHECK(plain.view().ends_with("pressure_hpa=null}"));
}
