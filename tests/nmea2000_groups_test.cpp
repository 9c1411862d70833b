// SPDX-License-Identifier: BSL-1.0
// NMEA 2000 repeating field groups and 64-bit numbers: 126464 PGN List, 129540 GNSS Sats in View,
// 129029 GNSS Position Data. Payloads from real captures (canboat's sample logs; canboat's
// analyzer's reading in the comments) decoded against a decode written here by hand from the bit
// layouts (bytes little-endian, no library bit reader), then the edges: a count of 0, at the
// capacity, past the payload, past the capacity, a sentinel; a group to the end of the payload;
// the 64-bit extremes and sentinels, their decimal text exact; JSON and CSV forms, JSON read back.

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hex_of.hpp"
#include "n2k_json_support.hpp"
#include "seawire/nmea/csv.hpp"
#include "seawire/nmea/decimal.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/registry.hpp"

namespace n2k = seawire::nmea2000;
using n2k::field_state;
using seawire::errc;
using support::hex_bytes;

namespace {

using support::fake_json;
using support::json_of;

using support::le;
std::int64_t le_signed(const std::vector<std::uint8_t>& p, std::size_t at, std::size_t n) {
  const std::uint64_t v = le(p, at, n);
  if (n == 8) return static_cast<std::int64_t>(v);
  const std::uint64_t sign = std::uint64_t{1} << (8 * n - 1);
  return (v & sign) != 0 ? static_cast<std::int64_t>(v) - static_cast<std::int64_t>(sign << 1)
                         : static_cast<std::int64_t>(v);
}

template <class V>
std::string text_of(const V& v) {
  seawire::nmea::json_buffer<64> j;
  n2k::write_json_value(j, v);
  return std::string(j.view());
}

using seawire::nmea::json_kind;

// 129540 from canboat's samples/129540.raw (216 bytes): 18 satellites in view, the 18th cut short
// by the payload's end after its SNR and 2 of the 4 bytes of its range residuals. canboat: sid
// 236, satsInView 18, the first {"prn":30,"elevation":1.0646,"azimuth":4.2935,"snr":41.00,
// "rangeResiduals":0.00000,"status":"Used"}, the last {"prn":86,"elevation":0.5410,"azimuth":
// 4.6076,"snr":32.00} (and rangeResiduals 0 read from the 2 bytes there are).
constexpr std::string_view sats_hex =
    "ecff121e9629b7a7041000000000f24916139565a00f00000000f24b961a70e6a00f00000000f2070b20cf7e3c0f"
    "00000000f20339193846d80e00000000f255501d4de0d80e00000000f211221507d4740e00000000f2475d014375"
    "740e00000000f206d115c29a100e00000000f20e5c1faaf0100e00000000f21ce819e4ebac0d00000000f2017f16"
    "c513480d00000000f213a20d59c4480d00000000f233ad1e2bad480d00000000f20974054375e40c00000000f24a"
    "8a367e52e40c00000000f216c513c431800c00000000f2562215fcb3800c0000";

// 129029 from canboat's samples/ac42-commissioning.raw (43 bytes, no reference station). canboat:
// date 2026.06.08, time 01:51:24.2000, latitude 21.2835018, longitude -157.8428998, altitude
// 21.203671, "GPS+SBAS/WAAS+GLONASS", "DGNSS fix", "No integrity checking", 26 SVs, hdop 0.50,
// pdop 0.70, geoidal separation 3.30, 0 reference stations.
constexpr std::string_view position_hex =
    "ff845090edfb03c0f228385224f4020066c075304b18ead78a43010000000024fc1a320046004a01000000";

// 126464 from canboat's samples/maretron-alm100-pgnlist.raw: "Transmit PGN list", 16 PGNs.
constexpr std::string_view pgn_list_hex =
    "0000e80000ea0000eb0000ec0000ee0000ef0002ff0000ed0100ee0100ef0114f00116f00102ff0109ff0101ff01"
    "08ff01";

}  // namespace

TEST_CASE("groups: the PGNs' facts, capacities from the 223-byte payload", "[groups]") {
  using S = n2k::gnss_sats_in_view;
  using G = n2k::gnss_position_data;
  using L = n2k::pgn_list_message;
  CHECK(n2k::pgn_table<S>.info.pgn == 129540);
  CHECK(n2k::pgn_table<G>.info.pgn == 129029);
  CHECK(n2k::pgn_table<L>.info.pgn == 126464);
  CHECK(n2k::pgn_table<S>.info.transport == n2k::framing::fast_packet);
  CHECK(n2k::pgn_table<G>.info.priority == 3);
  // capacity = (223 - fixed bytes) / bytes of one repetition
  CHECK(decltype(S::satellites)::capacity == (223 - 3) / 12);
  CHECK(decltype(G::stations)::capacity == (223 - 43) / 4);
  CHECK(decltype(L::pgns)::capacity == (223 - 1) / 3);
  CHECK(n2k::description_of<S>::length == 3 + 18 * 12);
  CHECK(n2k::description_of<G>::length == 43 + 45 * 4);
  CHECK(n2k::description_of<L>::length == 1 + 74 * 3);
  CHECK(seawire::registry::pgns::knows(129540));
  CHECK(seawire::registry::pgns::knows(129029));
  CHECK(seawire::registry::pgns::knows(126464));
}

TEST_CASE("129540: a capture against the hand decode, the last satellite cut short", "[groups]") {
  const std::vector<std::uint8_t> p = hex_bytes(sats_hex);
  REQUIRE(p.size() == 216);
  const auto m = n2k::decode<n2k::gnss_sats_in_view>(p);
  CHECK(m.sid.raw() == p[0]);
  CHECK(m.range_residual_mode.raw() == (p[1] & 0x03));
  CHECK(m.sats_in_view.raw() == p[2]);
  REQUIRE(m.sats_in_view.raw() == 18);
  REQUIRE(m.satellites.size() == 18);  // the 18th starts in the payload
  for (std::size_t i = 0; i < 17; ++i) {
    INFO("satellite " << i);
    const std::size_t at = 3 + 12 * i;
    const auto& s = *m.satellites.at(i);
    CHECK(s.prn.raw() == p[at]);
    CHECK(s.elevation_rad.raw() == le_signed(p, at + 1, 2));
    CHECK(s.azimuth_rad.raw() == static_cast<std::int64_t>(le(p, at + 3, 2)));
    CHECK(s.snr_db.raw() == le_signed(p, at + 5, 2));
    CHECK(s.range_residuals_m.raw() == le_signed(p, at + 7, 4));
    CHECK(s.status.raw() == (p[at + 11] & 0x0F));
    CHECK(s.gnss_system.raw() == p[at + 11] >> 4);
  }
  // canboat's first satellite
  const auto& first = *m.satellites.at(0);
  CHECK(first.prn.raw() == 30);
  CHECK(*first.elevation_rad.exact() == seawire::nmea::decimal::scaled(10646, 4));
  CHECK(*first.azimuth_rad.exact() == seawire::nmea::decimal::scaled(42935, 4));
  CHECK(*first.snr_db.exact() == seawire::nmea::decimal::scaled(4100, 2));
  CHECK(first.status == n2k::satellite_status::used);
  CHECK(first.gnss_system.state() == field_state::not_available);  // 0xF
  // the 18th: 9 bytes; the residuals (4 bytes) and the status byte are not held in full
  const auto& last = *m.satellites.at(17);
  CHECK(last.prn.raw() == 86);
  CHECK(*last.snr_db.exact() == seawire::nmea::decimal::scaled(3200, 2));
  CHECK(last.range_residuals_m.state() == field_state::not_available);
  CHECK(last.status.state() == field_state::not_available);

  // encode: 18 whole repetitions (219 bytes), the received bytes first, the rest all ones
  const auto e = n2k::encode(m);
  REQUIRE(e);
  REQUIRE(e.value.size() == 219);
  std::vector<std::uint8_t> want = p;
  want[1] |= 0xFC;         // the reserved bits after the mode
  want.resize(219, 0xFF);  // the cut residuals not available (0x7FFFFFFF), the status byte too
  want[214] = 0xFF;
  want[215] = 0xFF;
  want[217] = 0x7F;
  CHECK(std::ranges::equal(e.value.view(), want));
  CHECK(n2k::decode<n2k::gnss_sats_in_view>(e.value.view()) == m);
}

TEST_CASE("129029: a capture against the hand decode, 64-bit fields", "[groups]") {
  const std::vector<std::uint8_t> p = hex_bytes(position_hex);
  REQUIRE(p.size() == 43);
  const auto m = n2k::decode<n2k::gnss_position_data>(p);
  CHECK(m.sid.state() == field_state::not_available);
  CHECK(m.date.raw() == static_cast<std::int64_t>(le(p, 1, 2)));
  CHECK(m.time.raw() == static_cast<std::int64_t>(le(p, 3, 4)));
  CHECK(m.latitude_deg.raw() == le_signed(p, 7, 8));
  CHECK(m.longitude_deg.raw() == le_signed(p, 15, 8));
  CHECK(m.altitude_m.raw() == le_signed(p, 23, 8));
  CHECK(m.gnss_type.raw() == (p[31] & 0x0F));
  CHECK(m.method.raw() == p[31] >> 4);
  CHECK(m.integrity.raw() == (p[32] & 0x03));
  CHECK(m.number_of_svs.raw() == p[33]);
  CHECK(m.hdop.raw() == le_signed(p, 34, 2));
  CHECK(m.pdop.raw() == le_signed(p, 36, 2));
  CHECK(m.geoidal_separation_m.raw() == le_signed(p, 38, 4));
  CHECK(m.reference_stations.raw() == 0);
  CHECK(m.stations.empty());
  // canboat's values, which it rounds to 7 fraction digits of a degree (21.2835018,
  // -157.8428998): ours exact at 1e-16, the raw value's digits
  const std::string j = json_of(m);
  CHECK(m.latitude_deg.raw() == 212835017941381824);
  CHECK(m.longitude_deg.raw() == -1578428997887302144);
  CHECK(j.find("\"latitude_deg\":21.2835017941381824,") != std::string::npos);
  CHECK(j.find("\"longitude_deg\":-157.8428997887302144,") != std::string::npos);
  CHECK(*m.latitude_deg.value() == Approx(21.2835018).margin(5e-8));
  CHECK(j.find("\"altitude_m\":21.203671,") != std::string::npos);
  CHECK(j.find("\"gnss_type\":\"gps_sbas_glonass\",\"method\":\"dgnss_fix\"") != std::string::npos);
  CHECK(j.find("\"reference_stations\":0,\"stations\":[]}") != std::string::npos);
  CHECK(m.latitude_deg.exact()->places == 16);

  const auto e = n2k::encode(m);
  REQUIRE(e);
  std::vector<std::uint8_t> want = p;
  want[32] |= 0xFC;
  CHECK(std::ranges::equal(e.value.view(), want));
}

TEST_CASE("126464: a group to the end of the payload", "[groups]") {
  const std::vector<std::uint8_t> p = hex_bytes(pgn_list_hex);
  REQUIRE(p.size() == 49);
  const auto m = n2k::decode<n2k::pgn_list_message>(p);
  CHECK(m.function_code == n2k::pgn_list_function::transmit);
  REQUIRE(m.pgns.size() == 16);
  for (std::size_t i = 0; i < 16; ++i)
    CHECK(m.pgns.at(i)->pgn.raw() == static_cast<std::int64_t>(le(p, 1 + 3 * i, 3)));
  CHECK(m.pgns.at(0)->pgn.raw() == 59392);
  CHECK(m.pgns.at(15)->pgn.raw() == 130824);
  const auto e = n2k::encode(m);
  REQUIRE(e);
  CHECK(std::ranges::equal(e.value.view(), p));

  SECTION("a last repetition cut short: held, its field not available") {
    const std::vector<std::uint8_t> cut(p.begin(), p.begin() + 8);  // 1 + 3 + 3 + 1
    const auto c = n2k::decode<n2k::pgn_list_message>(cut);
    REQUIRE(c.pgns.size() == 3);
    CHECK(c.pgns.at(2)->pgn.state() == field_state::not_available);
    const auto again = n2k::encode(c);
    REQUIRE(again);
    CHECK(again.value.size() == 10);
    CHECK(n2k::decode<n2k::pgn_list_message>(again.value.view()) == c);
  }
  SECTION("at the capacity and past it") {
    std::vector<std::uint8_t> full(1 + 75 * 3, 0);
    for (std::size_t i = 0; i < 75; ++i) full[1 + 3 * i] = static_cast<std::uint8_t>(i);
    const auto f = n2k::decode<n2k::pgn_list_message>(full);
    REQUIRE(f.pgns.size() == 74);  // 223 bytes hold 74; the 75th is past any fast packet
    CHECK(f.pgns.at(73)->pgn.raw() == 73);
    CHECK(f.pgns.full());
    const auto e2 = n2k::encode(f);
    REQUIRE(e2);
    CHECK(e2.value.size() == 223);
    CHECK(std::ranges::equal(e2.value.view(), std::span(full).first(223)));
    auto more = f;
    n2k::pgn_list_message::entry x;
    CHECK_FALSE(more.pgns.push_back(x));  // full: nothing changes
    CHECK(more == f);
  }
  SECTION("none") {
    const std::array<std::uint8_t, 1> only{1};
    const auto z = n2k::decode<n2k::pgn_list_message>(only);
    CHECK(z.function_code == n2k::pgn_list_function::receive);
    CHECK(z.pgns.empty());
    CHECK(json_of(z) == R"({"type":"PGN126464","function_code":"receive","pgns":[]})");
  }
}

TEST_CASE("groups: the count's edges", "[groups]") {
  using S = n2k::gnss_sats_in_view;
  // one satellite's 12 bytes: PRN 7, elevation 0.5 rad, azimuth 1 rad, SNR 40 dB, residuals 0,
  // used, GPS
  const std::array<std::uint8_t, 12> sat{0x07, 0x88, 0x13, 0x10, 0x27, 0xA0,
                                         0x0F, 0x00, 0x00, 0x00, 0x00, 0x02};
  const auto payload = [&](std::uint8_t count, std::size_t sats) {
    std::vector<std::uint8_t> p{0x01, 0xFD, count};
    for (std::size_t i = 0; i < sats; ++i) p.insert(p.end(), sat.begin(), sat.end());
    return p;
  };

  SECTION("count 0: no repetition, whatever follows") {
    const auto m = n2k::decode<S>(payload(0, 2));
    CHECK(m.sats_in_view.raw() == 0);
    CHECK(m.satellites.empty());
    const auto e = n2k::encode(m);
    REQUIRE(e);
    CHECK(e.value.size() == 3);
  }
  SECTION("count at the capacity: 18 satellites, 219 bytes, bit for bit") {
    const auto p = payload(18, 18);
    const auto m = n2k::decode<S>(p);
    REQUIRE(m.satellites.size() == 18);
    CHECK(m.satellites.full());
    CHECK(*m.satellites.at(17)->elevation_rad.exact() == seawire::nmea::decimal::scaled(5000, 4));
    const auto e = n2k::encode(m);
    REQUIRE(e);
    CHECK(std::ranges::equal(e.value.view(), p));
  }
  SECTION("count past the payload: what is there, the count as sent") {
    const auto p = payload(5, 2);
    const auto m = n2k::decode<S>(p);
    CHECK(m.sats_in_view.raw() == 5);
    REQUIRE(m.satellites.size() == 2);
    const auto e = n2k::encode(m);
    REQUIRE(e);
    CHECK(std::ranges::equal(e.value.view(), p));  // the sender's bytes, count 5 and all
  }
  SECTION("count past the capacity: decoded as held, encode refuses it") {
    const auto p = payload(30, 19);
    const auto m = n2k::decode<S>(p);
    CHECK(m.sats_in_view.raw() == 30);
    CHECK(m.satellites.size() == 18);  // never past the storage
    const auto e = n2k::encode(m);
    CHECK(e.ec == errc::out_of_range);
    CHECK(e.field == 4);  // sats_in_view's row
    CHECK(e.column == 2);
    CHECK(n2k::field_name<S>(e.field) == "sats_in_view");
  }
  SECTION("a count that is a sentinel says nothing: the repetitions the payload holds") {
    for (const std::uint8_t c : std::array<std::uint8_t, 3>{0xFF, 0xFE, 0xFD}) {
      const auto p = payload(c, 2);
      const auto m = n2k::decode<S>(p);
      CHECK(m.sats_in_view.state() != field_state::value);
      CHECK(m.satellites.size() == 2);
      const auto e = n2k::encode(m);
      REQUIRE(e);
      CHECK(std::ranges::equal(e.value.view(), p));
    }
  }
  SECTION("encode: more repetitions than the count says") {
    auto m = n2k::decode<S>(payload(2, 2));
    m.sats_in_view = decltype(m.sats_in_view)::from_raw(1);
    const auto e = n2k::encode(m);
    CHECK(e.ec == errc::too_many_fields);
    CHECK(e.field == 5);
    CHECK(e.column == 3);
    m.sats_in_view = decltype(m.sats_in_view)::not_available();
    CHECK(n2k::encode(m).ok());  // says nothing
  }
  SECTION("encode: a repetition's field that does not fit its width") {
    auto m = n2k::decode<S>(payload(2, 2));
    auto& second = m.satellites.items()[1];
    second.status = decltype(second.status)::from_raw(16);
    const auto e = n2k::encode(m);
    CHECK(e.ec == errc::value_too_large);
    CHECK(e.field == 5);
    CHECK(e.column == 3 + 12 + 11);  // the second satellite's status byte
  }
}

TEST_CASE("64-bit numbers: extremes, sentinels, exact decimal text", "[groups]") {
  using lat = n2k::signed_number<64, n2k::resolution{1, -16}>;
  using alt = n2k::signed_number<64, n2k::resolution{1, -6}>;
  constexpr std::int64_t top = std::numeric_limits<std::int64_t>::max();
  constexpr std::int64_t low = std::numeric_limits<std::int64_t>::min();
  STATIC_REQUIRE(lat::top_raw == top);
  STATIC_REQUIRE(lat::min_raw == low);
  STATIC_REQUIRE(lat::max_valid_raw == top - 3);
  CHECK(lat::from_raw(top).state() == field_state::not_available);
  CHECK(lat::from_raw(top - 1).state() == field_state::out_of_range);
  CHECK(lat::from_raw(top - 2).state() == field_state::reserved);
  CHECK(lat::from_raw(top - 3).state() == field_state::value);
  CHECK(lat{}.state() == field_state::not_available);
  CHECK(text_of(lat::from_raw(low)) == "-922.3372036854775808");
  CHECK(text_of(lat::from_raw(top - 3)) == "922.3372036854775804");
  CHECK(text_of(lat::from_raw(top - 1)) == "\"out_of_range\"");
  CHECK(text_of(lat::from_raw(std::int64_t{1} << 62)) == "461.1686018427387904");
  CHECK(text_of(lat::from_raw(-1)) == "-0.0000000000000001");
  CHECK(text_of(alt::from_raw(low)) == "-9223372036854.775808");

  // text -> raw exactly, and back
  for (const std::int64_t raw : {low, low + 1, std::int64_t{1} << 62, -(std::int64_t{1} << 62),
                                 std::int64_t{-1}, std::int64_t{0}, top - 3}) {
    INFO(raw);
    const std::string t = text_of(lat::from_raw(raw));
    const auto d = seawire::nmea::decimal::parse(t);
    REQUIRE(d);
    const auto back = lat::from(d.value);
    REQUIRE(back);
    CHECK(back.value.raw() == raw);
  }
  CHECK(lat::from(seawire::nmea::decimal::parse("922.3372036854775805").value).ec ==
        errc::out_of_range);  // a sentinel is no value
  CHECK(lat::from(21.2835018).value.raw() == 212835018000000000);
  CHECK(lat::from(-157.8428998).value.raw() == -1578428998000000000);

  // on the wire: 8 bytes, two's complement, and back
  n2k::gnss_position_data m;
  m.latitude_deg = lat::from_raw(low);
  m.longitude_deg = n2k::signed_number<64, n2k::resolution{1, -16}>::from_raw(top - 3);
  m.altitude_m = alt::from_raw(-1);
  const auto e = n2k::encode(m);
  REQUIRE(e);
  CHECK(e.value.size() == 43);
  CHECK(e.value[7] == 0x00);
  CHECK(e.value[14] == 0x80);
  CHECK(e.value[15] == 0xFC);
  CHECK(e.value[22] == 0x7F);
  for (std::size_t i = 23; i < 31; ++i) CHECK(e.value[i] == 0xFF);
  CHECK(n2k::decode<n2k::gnss_position_data>(e.value.view()) == m);
}

TEST_CASE("groups: JSON, CSV and fmt forms; JSON read back", "[groups]") {
  n2k::gnss_position_data m;
  m.reference_stations = decltype(m.reference_stations)::from_raw(2);
  n2k::gnss_position_data::reference_station a;
  a.station_type = n2k::gnss_type::glonass;
  a.station_id = decltype(a.station_id)::from_raw(120);
  a.age_of_corrections_s = decltype(a.age_of_corrections_s)::from_raw(150);
  REQUIRE(m.stations.push_back(a));
  n2k::gnss_position_data::reference_station b;  // every field not available
  REQUIRE(m.stations.push_back(b));
  const std::string j = json_of(m);
  CHECK(j.ends_with(
      R"("reference_stations":2,"stations":[{"station_type":"glonass","station_id":120,)"
      R"("age_of_corrections_s":1.50},{"station_type":null,"station_id":null,)"
      R"("age_of_corrections_s":null}]})"));

  seawire::nmea::json_buffer<2048> csv;
  n2k::write_csv(csv, n2k::message_header{}, m);
  CHECK(std::string(csv.view()).ends_with(",2,glonass|120|1.50;||\n"));
  seawire::nmea::json_buffer<2048> head;
  n2k::write_csv_header<n2k::gnss_position_data>(head);
  CHECK(std::string(head.view()).ends_with(",reference_stations,stations\n"));

  seawire::nmea::json_buffer<2048> plain;
  seawire::write_plain_fields(plain, m);
  CHECK(std::string(plain.view())
            .ends_with("stations=[{station_type=glonass, station_id=120, age_of_corrections_s=1.50}"
                       ", {station_type=null, station_id=null, age_of_corrections_s=null}]}"));

  // read back: the count and each element's members; the integrity, which names every raw
  // value (so has no "not available" to leave out), as m holds it (all ones: unsafe)
  fake_json in;
  in.add("", "integrity", json_kind::string, "unsafe");
  in.add("", "reference_stations", json_kind::number, "2");
  in.add("", "stations", json_kind::other, "[");
  in.add("stations", "0", json_kind::other, "{");
  in.add("stations", "0.station_type", json_kind::string, "glonass");
  in.add("stations", "0.station_id", json_kind::number, "120");
  in.add("stations", "0.age_of_corrections_s", json_kind::number, "1.50");
  in.add("stations", "1", json_kind::other, "{");
  in.add("stations", "1.station_type", json_kind::null, "null");
  const auto r = n2k::read_json<n2k::gnss_position_data>(in);
  REQUIRE(r);
  CHECK(r.value == m);

  SECTION("errors") {
    fake_json bad = in;
    bad.add("stations", "1.station_id", json_kind::number, "4093");  // past the ordinary values
    const auto e = n2k::read_json<n2k::gnss_position_data>(bad);
    CHECK(e.ec == errc::out_of_range);
    CHECK(e.field == 16);
    CHECK(e.column == 43 + 4);  // the second station's first byte

    fake_json no_integrity;  // a field without "not available" cannot be left out
    no_integrity.add("", "reference_stations", json_kind::number, "0");
    const auto n = n2k::read_json<n2k::gnss_position_data>(no_integrity);
    CHECK(n.ec == errc::missing_field);
    CHECK(n2k::field_name<n2k::gnss_position_data>(n.field) == "integrity");

    fake_json not_array;
    not_array.add("", "integrity", json_kind::string, "none");
    not_array.add("", "stations", json_kind::number, "3");
    CHECK(n2k::read_json<n2k::gnss_position_data>(not_array).ec == errc::bad_length);

    fake_json scalar_element;
    scalar_element.add("", "integrity", json_kind::string, "none");
    scalar_element.add("", "stations", json_kind::other, "[");
    scalar_element.add("stations", "0", json_kind::number, "1");
    CHECK(n2k::read_json<n2k::gnss_position_data>(scalar_element).ec == errc::bad_length);

    fake_json too_many;
    too_many.add("", "pgns", json_kind::other, "[");
    for (int i = 0; i < 75; ++i) {
      too_many.add("pgns", std::to_string(i), json_kind::other, "{");
      too_many.add("pgns", std::to_string(i) + ".pgn", json_kind::number, "59904");
    }
    const auto t = n2k::read_json<n2k::pgn_list_message>(too_many);
    CHECK(t.ec == errc::too_many_fields);
    CHECK(t.field == 2);
  }
}
