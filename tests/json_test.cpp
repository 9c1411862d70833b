// SPDX-License-Identifier: BSL-1.0
// nmea/json.hpp and anello/frame_json.hpp: every value type's JSON form, whole messages, unknown
// sentences and errors, the exact position conversions, and reading messages back. Where
// nlohmann-json is installed, every document written here must also parse as JSON. And
// nmea/csv.hpp with the frame's CSV: the same values as table cells.

#include <algorithm>
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "anello_seed.hpp"
#include "seawire/anello/frame_json.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/csv.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/sandshark/messages.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/rmc.hpp"
#include "support.hpp"

#if SEAWIRE_HAS_NLOHMANN_JSON
#include <nlohmann/json.hpp>
#endif

using namespace seawire;
using namespace seawire::nmea;
using support::must_decode;
using support::string_sink;

namespace {

template <class T>
std::string value_json(const T& v) {
  string_sink k;
  write_json_value(k, v);
  return k.s;
}

template <class T>
std::string message_json(const T& m) {
  string_sink k;
  write_json(k, m);
  return k.s;
}

bool valid_json(const std::string& s) {
#if SEAWIRE_HAS_NLOHMANN_JSON
  return nlohmann::json::accept(s);
#else
  return !s.empty();
#endif
}

// A JSON object as read_json sees it: key -> (kind, text), plus a "precision" object.
struct object {
  std::map<std::string, json_value, std::less<>> members;
  std::map<std::string, json_value, std::less<>> precision;
  json_value operator()(std::string_view obj, std::string_view key) const {
    const auto& m = obj.empty() ? members : precision;
    const auto it = m.find(key);
    return it == m.end() ? json_value{} : it->second;
  }
};

#if SEAWIRE_HAS_NLOHMANN_JSON
// Flattens one JSON object with nlohmann's SAX interface, which hands out a number's text.
struct flat_reader : nlohmann::json_sax<nlohmann::json> {
  std::vector<std::string> storage;  // texts live here (reserved: views stay valid)
  object out;
  std::string current_key;
  int depth = 0;
  bool in_precision = false;

  flat_reader() { storage.reserve(256); }
  bool put(json_kind kind, std::string text) {
    storage.push_back(std::move(text));
    auto& m = in_precision ? out.precision : out.members;
    m[current_key] = json_value{kind, storage.back()};
    return true;
  }
  bool null() override { return put(json_kind::null, ""); }
  bool boolean(bool b) override { return put(json_kind::boolean, b ? "true" : "false"); }
  bool number_integer(number_integer_t v) override {
    return put(json_kind::number, std::to_string(v));
  }
  bool number_unsigned(number_unsigned_t v) override {
    return put(json_kind::number, std::to_string(v));
  }
  bool number_float(number_float_t, const string_t& s) override {
    return put(json_kind::number, s);
  }
  bool string(string_t& s) override { return put(json_kind::string, s); }
  bool binary(binary_t&) override { return false; }
  bool start_object(std::size_t) override {
    ++depth;
    if (depth == 2) in_precision = current_key == "precision";
    return true;
  }
  bool key(string_t& k) override {
    current_key = k;
    return true;
  }
  bool end_object() override {
    if (--depth == 1) in_precision = false;
    return true;
  }
  bool start_array(std::size_t) override { return put(json_kind::other, ""); }
  bool end_array() override { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }
};

// decode -> JSON -> (nlohmann SAX) -> read_json -> encode: the wire line comes back.
template <class T>
std::string through_json(std::string_view line) {
  const T m = must_decode<T>(line);
  const std::string js = message_json(m);
  flat_reader reader;
  REQUIRE(nlohmann::json::sax_parse(js, &reader));
  const json_value type = reader.out.members.at("type");
  const result<T> back = read_json<T>(type.text, reader.out);
  REQUIRE(back);
  return std::string(encode(back.value).view());
}
#endif

}  // namespace

// The writers are constexpr: a whole message as JSON at compile time.
static_assert([] {
  json_buffer<128> b;
  write_json(b, kingfisher::pydir{decimal(45), decimal::scaled(-5, 1)});
  return b.view() == R"({"type":"PYDIR","thrust_left":45,"thrust_right":-0.5})";
}());

TEST_CASE("decimals keep the wire's digits") {
  const auto dec = [](std::string_view s) {
    decimal d;
    REQUIRE(nmea::detail::parse_decimal(s, true, d) == errc::ok);
    return value_json(d);
  };
  CHECK(dec("203.10") == "203.10");
  CHECK(dec("-0.0") == "-0.0");
  CHECK(dec("-0") == "-0");
  CHECK(dec("0.05") == "0.05");
  CHECK(dec("4.50") == "4.50");
  CHECK(dec("+7") == "7");
  CHECK(dec("011.3") == "11.3");  // JSON has no leading zeros; the value stays
  CHECK(dec("000.0") == "0.0");
  CHECK(dec("1234567890123456789") == "1234567890123456789");
  CHECK(dec("0.0000000000000000001") == "0.0000000000000000001");
  CHECK(valid_json(dec("-0.0")));
  CHECK(valid_json(dec("011.3")));
}

TEST_CASE("integers, flags, optionals") {
  CHECK(value_json(std::uint8_t{6}) == "6");
  CHECK(value_json(std::int32_t{-42}) == "-42");
  CHECK(value_json(std::int64_t{INT64_MIN}) == "-9223372036854775808");
  CHECK(value_json(std::uint64_t{UINT64_MAX}) == "18446744073709551615");
  CHECK(value_json(true) == "true");
  CHECK(value_json(false) == "false");
  CHECK(value_json(std::optional<decimal>{}) == "null");
  CHECK(value_json(std::optional<decimal>{decimal::scaled(15, 1)}) == "1.5");
}

TEST_CASE("NMEA positions: signed decimal degrees, exact or within 5e-10 of the wire") {
  const auto rmc = must_decode<standard::rmc>(
      "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,"
      "311214,,,A*70");
  CHECK(value_json(*rmc.lat) == "42.3618523333333");  // 21.71114 / 60 repeats: 13 digits
  CHECK(value_json(*rmc.lon) == "-71.0908130");       // 5.44878 / 60 ends: exact
  const auto nvg = must_decode<kingfisher::cpnvg>(
      "$CPNVG,164959.034,4221.711142,N,7105.44878,W,1,0,0,234.32964,-6.796959,-1.706798,"
      "164959.006*78");
  CHECK(value_json(nvg.lat) == "42.36185236666667");
  CHECK(value_json(nvg.lon) == "-71.0908130");  // unpadded degrees: same value
  // At exactly zero the sign still comes from the hemisphere letter.
  const auto zero =
      must_decode<kingfisher::cpnvg>("$CPNVG,105707.24,0000.00,N,00000.00,W,1,,,0,,,105707.24*64");
  CHECK(value_json(zero.lat) == "0.0000");
  CHECK(value_json(zero.lon) == "-0.0000");
  CHECK(valid_json(value_json(zero.lon)));
  // No minute fraction: written as one fraction digit ("59.0").
  latitude l;
  l.whole_degrees = 89;
  l.minutes = decimal(59);
  l.hemi = hemisphere::south;
  CHECK(value_json(l) == "-89.983333333");
  l.minutes = decimal::scaled(599, 1);
  CHECK(value_json(l) == "-89.998333333");  // 59.9/60 = 0.99833...
  l.minutes = decimal::scaled(5991, 2);
  CHECK(value_json(l) == "-89.9985");  // 59.91/60 = 0.9985 exactly
  // A receiver writing two minute digits: 0.76' / 60 = 0.012666...'s degrees to 1e-10.
  const auto two =
      must_decode<standard::gga>("$GPGGA,105027.80,5612.99,N,01200.76,E,1,03,2.5,160.0,M,,M,,*7A");
  CHECK(value_json(*two.lon) == "12.0126666667");
  CHECK(value_json(*two.lat) == "56.2165");
}

TEST_CASE("decimal-degree positions keep their digits") {
  const auto hrb =
      must_decode<robotx::rxhrb>("$RXHRB,111221,161229,21.31198,N,157.88972,W,ROBOT,2,1*11");
  CHECK(value_json(*hrb.lat) == "21.31198");
  CHECK(value_json(*hrb.lon) == "-157.88972");
}

TEST_CASE("times, dates, text, enums") {
  CHECK(value_json(time_of_day{8, 10, 25, 987, 3}) == R"("08:10:25.987")");
  CHECK(value_json(time_of_day{16, 49, 59, 0, 2}) == R"("16:49:59.00")");
  CHECK(value_json(time_of_day{16, 12, 29, 0, 0}) == R"("16:12:29")");
  CHECK(value_json(time_of_day{23, 59, 60, 123456789, 9}) == R"("23:59:60.123456789")");
  CHECK(value_json(date{2018, 12, 10}) == R"("2018-12-10")");
  CHECK(value_json(date{1999, 1, 2}) == R"("1999-01-02")");
  CHECK(value_json(text<32>("BWSI Autonomy OK")) == R"("BWSI Autonomy OK")");
  text<16> nasty;
  REQUIRE(nasty.assign(std::string_view("a\"b\\c\x01\n", 7)));
  CHECK(value_json(nasty) == R"("a\"b\\c\u0001\n")");
  CHECK(valid_json(value_json(nasty)));
  text<4> high;  // bytes outside ASCII (only user-built text can hold them) stay valid JSON
  REQUIRE(high.assign("\xE9\x7F"));
  CHECK(value_json(high) == R"("\u00E9\u007F")");
  CHECK(value_json(standard::rmc_status::warning) == R"("V")");
  CHECK(value_json(sandshark::log_state::off) == R"("OFF")");
  CHECK(value_json(robotx::dock_shape::cruciform) == R"("CRUC")");
  CHECK(value_json(robotx::deliver_shape::cruciform) == R"("CRUCI")");
  // A value type with a codec and no JSON form of its own: its wire text.
  CHECK(value_json(robotx::light_pattern::from("RGB").value) == R"("RGB")");
}

TEST_CASE("whole messages: type first, then fields in wire order") {
  CHECK(message_json(must_decode<kingfisher::cpnvg>(
            "$CPNVG,164959.034,4221.711142,N,7105.44878,W,1,0,0,234.32964,-6.796959,-1.706798,"
            "164959.006*78")) ==
        R"({"type":"CPNVG","timestamp":"16:49:59.034","latitude":42.36185236666667,)"
        R"("longitude":-71.0908130,"position_quality":true,"altitude_m":0,"depth_m":0,)"
        R"("heading_deg":234.32964,"roll_deg":-6.796959,"pitch_deg":-1.706798,)"
        R"("nav_timestamp":"16:49:59.006"})");
  // Talker-agnostic messages: "type" is the address as it came.
  CHECK(message_json(must_decode<standard::gga>(
            "$GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,M,-33.2,M,,*5C")) ==
        R"({"type":"GPGGA","time":"16:49:59.00","latitude":42.3618523333333,)"
        R"("longitude":-71.0908130,"quality":"1","satellites":6,"hdop":2.80,"altitude_m":46.6,)"
        R"("geoid_separation_m":-33.2,"dgps_age_s":null,"dgps_station":null})");
  standard::rmc rmc = must_decode<standard::rmc>(
      "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70");
  rmc.talker = "GN";
  CHECK(message_json(rmc).starts_with(R"({"type":"GNRMC","time":"16:49:59.00",)"));
  // Text, blank text and absent optional text.
  CHECK(message_json(must_decode<sandshark::bfack>("$BFACK,081025.990,RMB,081025.950,,2,0,*32")) ==
        R"({"type":"BFACK","timestamp":"08:10:25.990","command":"RMB",)"
        R"("command_timestamp":"08:10:25.950","behavior_id":null,"status":"2","future_use":0,)"
        R"("description":"","trailing":null})");
  CHECK(message_json(must_decode<robotx::rxdok>("$RXDOK,101218,161229,AUVSI,R,TRIAN*28")) ==
        R"({"type":"RXDOK","date":"2018-12-10","time":"16:12:29","team_id":"AUVSI",)"
        R"("shape_color":"R","shape":"TRIAN"})");
  CHECK(valid_json(message_json(must_decode<sandshark::bpsts>("$BPSTS,231133.12,1,OK*73"))));
}

TEST_CASE("unknown sentences and errors") {
  const auto s = parse("$XXFOO,1,,a b*00", {checksum_policy::ignore});
  REQUIRE(s);
  string_sink k;
  write_json(k, unknown_sentence{s.value});
  CHECK(k.s == R"({"type":"XXFOO","fields":["1","","a b"]})");
  CHECK(valid_json(k.s));
  const auto bare = parse("$XXBAR");
  REQUIRE(bare);
  k.s.clear();
  write_json(k, unknown_sentence{bare.value});
  CHECK(k.s == R"({"type":"XXBAR","fields":[]})");
  // A '!' sentence says so; a '$' one has no "start".
  const auto ais = parse("!AIVDM,1,1,,B,15M67FC000G?ufbE`vJ8?wv4R0<4,0*10");
  REQUIRE(ais);
  k.s.clear();
  write_json(k, unknown_sentence{ais.value});
  CHECK(
      k.s ==
      R"({"type":"AIVDM","start":"!","fields":["1","1","","B","15M67FC000G?ufbE`vJ8?wv4R0<4","0"]})");
  CHECK(valid_json(k.s));

  k.s.clear();
  write_json_error(k, 12, errc::minute_out_of_range, 2, "CPNVG field 2 (latitude): \"61\"",
                   "$CPNVG,1,2\\");
  CHECK(k.s == R"({"line":12,"error":"minute_out_of_range","field":2,)"
               R"("detail":"CPNVG field 2 (latitude): \"61\"","input":"$CPNVG,1,2\\"})");
  CHECK(valid_json(k.s));
}

TEST_CASE("json_buffer reports overflow") {
  json_buffer<10> b;
  write_json(b, kingfisher::pyclt{true});
  CHECK(b.overflow());
  CHECK(b.size() == 10);
  b.clear();
  CHECK_FALSE(b.overflow());
  b.put("{}");
  CHECK(b.view() == "{}");
}

namespace {
// A sink that lends its own storage (room/commit) when `lend` is set and refuses when not, so that
// numbers written in place can be held to the same text as numbers put through a copy.
struct lending_sink {
  std::string s;
  bool lend = true;
  std::size_t lent_at = 0;
  std::size_t lent = 0;
  // The lent block is followed by guard bytes, so that a writer going past it is caught.
  static constexpr std::string_view guard = "GUARDGUARDGUARDG";
  char* room(std::size_t n) {
    if (!lend) return nullptr;
    lent_at = s.size();
    lent = n;
    s.resize(lent_at + n, '#');
    s += guard;
    return s.data() + lent_at;
  }
  void commit(std::size_t k) {
    REQUIRE(k <= lent);
    CHECK(std::string_view(s).substr(lent_at + lent) == guard);
    s.resize(lent_at + k);
    lent = 0;
  }
  void put(char c) { s += c; }
  void put(std::string_view v) { s += v; }
};
static_assert(seawire::detail::sink_with_room<lending_sink>);
static_assert(seawire::detail::sink_with_room<json_buffer<8>>);
static_assert(!seawire::detail::sink_with_room<string_sink>);

// v's JSON written into a sink that lends its storage, one that refuses to, one that has none,
// and a json_buffer: the four must be the same text, which is returned.
template <class T>
std::string json_every_way(const T& v) {
  lending_sink lends;
  lending_sink refuses;
  refuses.lend = false;
  string_sink plain;
  json_buffer<256> buffer;
  write_json_value(lends, v);
  write_json_value(refuses, v);
  write_json_value(plain, v);
  write_json_value(buffer, v);
  CHECK(lends.s == plain.s);
  CHECK(refuses.s == plain.s);
  CHECK(buffer.view() == plain.s);
  CHECK_FALSE(buffer.overflow());
  return plain.s;
}

constexpr std::string_view decimal_in_buffer() {
  json_buffer<160> b;  // room for the time's whole lent block after the decimal
  decimal d;
  d.mantissa = 123456;
  d.places = 3;
  d.negative = true;
  write_json_value(b, d);
  write_json_value(b, time_of_day{16, 49, 59, 980, 3});
  return b.view() == R"(-123.456"16:49:59.980")" ? "ok" : "differs";
}
}  // namespace

TEST_CASE("numbers, times and dates are the same text written in a sink's storage or copied") {
  static_assert(decimal_in_buffer() == "ok");  // in place, at compile time too
  std::mt19937_64 rng(11);
  for (int i = 0; i < 3000; ++i) {
    decimal d;
    const unsigned digits = static_cast<unsigned>(rng() % 21);
    d.mantissa = digits == 20 ? rng() : rng() % seawire::detail::pow10_table[digits];
    d.places = static_cast<std::uint8_t>(rng() % 21);  // 20: past the most, null
    d.negative = rng() % 2 == 0;
    const std::string text = json_every_way(d);
    if (d.places > seawire::detail::max_fraction_digits) {
      CHECK(text == "null");
    } else {
      CHECK(text.size() <= seawire::detail::max_fixed_chars);
    }
    const auto whole = static_cast<std::int64_t>(rng());
    std::string expected = std::to_string(whole);
    CHECK(json_every_way(whole) == expected);
  }
  CHECK(json_every_way(decimal{}) == "0");
  CHECK(json_every_way(std::numeric_limits<std::uint64_t>::max()) == "18446744073709551615");
  CHECK(json_every_way(std::numeric_limits<std::int64_t>::min()) == "-9223372036854775808");
  CHECK(json_every_way(time_of_day{16, 49, 59, 980, 3}) == R"("16:49:59.980")");
  CHECK(json_every_way(time_of_day{0, 0, 0}) == R"("00:00:00")");
  CHECK(json_every_way(time_of_day{23, 59, 60, 5, 2}) == R"("23:59:60.05")");
  // Parts no decoder makes (a struct filled by hand) are written whole, not cut to two digits.
  CHECK(json_every_way(time_of_day{200, 7, 100, 12345, 2}) == R"("200:07:100.12345")");
  CHECK(json_every_way(time_of_day{1, 2, 3, 7, 19}) == R"("01:02:03.0000000000000000007")");
  CHECK(json_every_way(date{2014, 12, 31}) == R"("2014-12-31")");
  CHECK(json_every_way(date{7, 1, 2}) == R"("0007-01-02")");
  CHECK(json_every_way(date{12345, 123, 200}) == R"("12345-123-200")");
}

TEST_CASE("json_buffer near its end: numbers that do not fit are cut and the overflow kept") {
  decimal d;
  d.mantissa = 123456789;
  d.places = 4;  // "12345.6789", 10 characters
  json_buffer<50> b;
  for (int i = 0; i < 4; ++i) {
    write_json_value(b, d);
    b.put(',');
  }
  CHECK_FALSE(b.overflow());  // 44 of 50 (from the second number on, no whole lent block)
  write_json_value(b, d);
  CHECK(b.overflow());
  CHECK(b.view() == "12345.6789,12345.6789,12345.6789,12345.6789,12345.");
}

TEST_CASE("from_decimal_degrees inverts to_decimal_degrees exactly") {
  std::mt19937_64 rng(7);
  for (unsigned p = 1; p <= 12; ++p) {
    for (int i = 0; i < 500; ++i) {
      latitude l;
      l.whole_degrees = static_cast<std::uint16_t>(rng() % 90);
      l.minutes.places = static_cast<std::uint8_t>(p);
      l.minutes.mantissa = rng() % (60 * seawire::detail::pow10_table[p]);
      l.hemi = rng() % 2 ? hemisphere::north : hemisphere::south;
      const decimal deg = to_decimal_degrees(l);
      const bool ends = l.minutes.mantissa % 3 == 0;  // minutes / 60 terminates
      CHECK(deg.places == (ends ? p + 2 : std::min(p + 8, 17u)));
      // Within 5e-10 degrees of the wire's value (long double has 64 mantissa bits).
      const long double exact =
          static_cast<long double>(l.whole_degrees) +
          static_cast<long double>(l.minutes.mantissa) /
              (60.0L * static_cast<long double>(seawire::detail::pow10_table[p]));
      const long double got = static_cast<long double>(deg.mantissa) /
                              static_cast<long double>(seawire::detail::pow10_table[deg.places]);
      CHECK(std::fabs(static_cast<double>(got - exact)) <= (ends ? 1e-15 : 5.000001e-10));
      const auto back = from_decimal_degrees<latitude>(deg, static_cast<int>(p));
      REQUIRE(back);
      CHECK(back.value == l);
      INFO("minute places " << p << ", minutes " << l.minutes.mantissa);
      const auto by_default = from_decimal_degrees<latitude>(deg);  // the same minutes
      REQUIRE(by_default);
      if (p <= 9) {
        CHECK(by_default.value == l);
      } else {
        // Past 9 digits the counts are shared: a trailing zero of the minutes may go, but the
        // degrees written from what comes back are the same.
        CHECK(to_decimal_degrees(by_default.value) == deg);
      }
    }
  }
}

TEST_CASE("from_decimal_degrees finds a longitude's minute digits, trailing zeros too") {
  std::mt19937_64 rng(11);
  for (unsigned p = 1; p <= 8; ++p) {
    for (int i = 0; i < 500; ++i) {
      longitude l;
      l.whole_degrees = static_cast<std::uint16_t>(rng() % 180);
      l.minutes.places = static_cast<std::uint8_t>(p);
      l.minutes.mantissa = rng() % (60 * seawire::detail::pow10_table[p]);
      if (i % 4 == 0) l.minutes.mantissa -= l.minutes.mantissa % 10;  // a trailing zero
      l.hemi = rng() % 2 ? hemisphere::east : hemisphere::west;
      const auto back = from_decimal_degrees<longitude>(to_decimal_degrees(l));
      REQUIRE(back);
      CHECK(back.value == l);
    }
  }
}

TEST_CASE("from_decimal_degrees: rounding, carry, default places, range") {
  const auto lon = [](std::string_view s, int places = -1) {
    decimal d;
    REQUIRE(nmea::detail::parse_decimal(s, false, d) == errc::ok);
    return from_decimal_degrees<longitude>(d, places);
  };
  auto r = lon("-71.0908130");
  REQUIRE(r);
  CHECK(r.value.whole_degrees == 71);
  CHECK(r.value.minutes == decimal::scaled(544878, 5));
  CHECK(r.value.hemi == hemisphere::west);
  // Fewer than three fraction digits: 4 minute places.
  r = lon("42.5");
  REQUIRE(r);
  CHECK(r.value.minutes == decimal::scaled(300000, 4));
  r = lon("7");
  REQUIRE(r);
  CHECK((r.value.whole_degrees == 7 && r.value.minutes == decimal::scaled(0, 4)));
  // -0 keeps its hemisphere.
  r = lon("-0.0000");
  REQUIRE(r);
  CHECK((r.value.whole_degrees == 0 && r.value.hemi == hemisphere::west));
  // An explicit precision, and the carry when the minutes round up to 60.
  r = lon("12.9999999", 2);
  REQUIRE(r);
  CHECK((r.value.whole_degrees == 13 && r.value.minutes == decimal::scaled(0, 2)));
  r = lon("12.5", 6);
  REQUIRE(r);
  CHECK(r.value.minutes == decimal::scaled(30000000, 6));
  // Range.
  CHECK(lon("180.0000").ec == errc::ok);
  CHECK(lon("180.0001").ec == errc::bad_longitude);
  CHECK(lon("-181").ec == errc::bad_longitude);
  CHECK(lon("12.5", 13).ec == errc::out_of_range);
  CHECK(lon("12.5", 0).ec == errc::out_of_range);  // "1230,E": no digit after the point
  decimal d;
  REQUIRE(nmea::detail::parse_decimal("90.00001", false, d) == errc::ok);
  CHECK(from_decimal_degrees<latitude>(d).ec == errc::bad_latitude);
  // Decimal-degree positions: digits as given, or to the requested places.
  REQUIRE(nmea::detail::parse_decimal("-157.88972", false, d) == errc::ok);
  auto dl = from_decimal_degrees<decimal_longitude>(d);
  REQUIRE(dl);
  CHECK((dl.value.value == decimal::scaled(15788972, 5) && dl.value.hemi == hemisphere::west));
  dl = from_decimal_degrees<decimal_longitude>(d, 2);
  CHECK(dl.value.value == decimal::scaled(15789, 2));
  dl = from_decimal_degrees<decimal_longitude>(d, 7);
  CHECK(dl.value.value == decimal::scaled(1578897200, 7));
}

TEST_CASE("time and date text") {
  auto t = parse_time_text("08:10:25.987");
  REQUIRE(t);
  CHECK(t.value == time_of_day{8, 10, 25, 987, 3});
  t = parse_time_text("16:12:29");
  REQUIRE(t);
  CHECK(t.value == time_of_day{16, 12, 29, 0, 0});
  t = parse_time_text("164959.00");  // the wire's form is accepted too
  REQUIRE(t);
  CHECK(t.value == time_of_day{16, 49, 59, 0, 2});
  CHECK(parse_time_text("24:00:00").ec == errc::hour_out_of_range);
  CHECK(parse_time_text("12:60:00").ec == errc::minute_out_of_range);
  CHECK(parse_time_text("12:00:60").ec == errc::second_out_of_range);
  CHECK(parse_time_text("23:59:60").ec == errc::ok);
  CHECK(parse_time_text("8:10:25").ec == errc::bad_time);
  CHECK(parse_time_text("08:10:25.").ec == errc::bad_time);
  CHECK(parse_time_text("08:10:25.1234567890").ec == errc::bad_time);
  CHECK(parse_time_text("").ec == errc::bad_time);

  auto d = parse_date_text("2018-12-10");
  REQUIRE(d);
  CHECK(d.value == date{2018, 12, 10});
  d = parse_date_text("311214");
  REQUIRE(d);
  CHECK(d.value == date{2014, 12, 31});
  CHECK(parse_date_text("2018-13-10").ec == errc::month_out_of_range);
  CHECK(parse_date_text("2019-02-29").ec == errc::day_out_of_range);
  CHECK(parse_date_text("2020-02-29").ec == errc::ok);
  CHECK(parse_date_text("1979-12-31").ec == errc::out_of_range);
  CHECK(parse_date_text("2018/12/10").ec == errc::bad_date);
}

TEST_CASE("read_json: values, blanks, errors name the wire field") {
  object o;
  o.members["timestamp"] = {json_kind::string, "16:49:59.034"};
  o.members["latitude"] = {json_kind::number, "42.36185237"};
  o.members["longitude"] = {json_kind::number, "-71.0908130"};
  o.members["position_quality"] = {json_kind::boolean, "true"};
  o.members["altitude_m"] = {json_kind::null, ""};
  o.members["heading_deg"] = {json_kind::number, "234.30"};
  auto r = read_json<kingfisher::cpnvg>("CPNVG", o);
  REQUIRE(r);
  CHECK(r.value.lat.minutes == decimal::scaled(21711142, 6));
  CHECK(r.value.lon.degree_digits == 3);
  CHECK_FALSE(r.value.altitude_m);
  CHECK_FALSE(r.value.depth_m);  // absent
  CHECK(*r.value.heading_deg == decimal::scaled(23430, 2));
  CHECK(encode(r.value).view() ==
        "$CPNVG,164959.034,4221.711142,N,07105.44878,W,1,,,234.30,,,*62\r\n");

  // A precision override for one position.
  o.precision["latitude"] = {json_kind::number, "3"};
  r = read_json<kingfisher::cpnvg>("CPNVG", o);
  REQUIRE(r);
  CHECK(r.value.lat.minutes == decimal::scaled(21711, 3));
  o.precision.clear();

  CHECK(read_json<kingfisher::cpnvg>("CPNVR", o).ec == errc::wrong_address);
  o.members["latitude"] = {json_kind::string, "north"};
  r = read_json<kingfisher::cpnvg>("CPNVG", o);
  CHECK(r.ec == errc::bad_latitude);
  CHECK(r.field == 2);
  CHECK(field_name<kingfisher::cpnvg>(r.field) == "latitude");
  o.members["latitude"] = {json_kind::number, "42.5"};
  o.members.erase("timestamp");
  r = read_json<kingfisher::cpnvg>("CPNVG", o);
  CHECK(r.ec == errc::missing_field);
  CHECK(r.field == 1);
  o.members["timestamp"] = {json_kind::string, "16:49:59.034"};
  o.members["heading_deg"] = {json_kind::number, "1e2"};
  r = read_json<kingfisher::cpnvg>("CPNVG", o);
  CHECK(r.ec == errc::bad_number);
  CHECK(r.field == 9);  // positions span two wire fields each
  CHECK(field_name<kingfisher::cpnvg>(r.field) == "heading_deg");
  o.members["heading_deg"] = {json_kind::boolean, "true"};
  CHECK(read_json<kingfisher::cpnvg>("CPNVG", o).ec == errc::bad_number);

  // A sentence with a shorter form: numbered in the form the object gives, as encode_to does.
  object b;
  b.members["timestamp"] = {json_kind::string, "17:29:09.322"};
  b.members["stack_voltage_v"] = {json_kind::number, "15.1"};
  b.members["min_cell_voltage_v"] = {json_kind::number, "15.1"};
  b.members["max_cell_voltage_v"] = {json_kind::number, "15.2"};
  b.members["temperature_c"] = {json_kind::string, "warm"};
  const auto five = read_json<kingfisher::cprbs>("CPRBS", b);
  CHECK(five.ec == errc::bad_number);
  CHECK(five.field == 5);
  CHECK(form_field_count(five.value) == 5);
  CHECK(field_name<kingfisher::cprbs>(five.field, form_field_count(five.value)) == "temperature_c");
  b.members["battery_id"] = {json_kind::number, "1"};
  const auto six = read_json<kingfisher::cprbs>("CPRBS", b);
  CHECK(six.field == 6);
  CHECK(form_field_count(six.value) == 6);
  CHECK(field_name<kingfisher::cprbs>(six.field, form_field_count(six.value)) == "temperature_c");
  b.members["temperature_c"] = {json_kind::number, "20"};
  const auto written = read_json<kingfisher::cprbs>("CPRBS", b);
  REQUIRE(written);
  kingfisher::cprbs no_id = written.value;
  no_id.battery_id.reset();
  no_id.max_cell_voltage_v->places = 40;  // no such decimal: encode refuses it, at wire field 4
  const auto enc = encode(no_id);
  REQUIRE_FALSE(enc);
  CHECK(enc.field == 4);
  CHECK(field_name<kingfisher::cprbs>(enc.field, form_field_count(no_id)) == "max_cell_voltage_v");

  CHECK(has_field<kingfisher::cpnvg>("heading_deg"));
  CHECK_FALSE(has_field<kingfisher::cpnvg>("heading"));
  CHECK_FALSE(has_field<kingfisher::cpnvg>("type"));
}

TEST_CASE("read_json: talker from the type, enums, text, lenient forms") {
  object o;
  o.members["status"] = {json_kind::string, "A"};
  o.members["date"] = {json_kind::string, "311214"};
  auto r = read_json<standard::rmc>("GNRMC", o);
  REQUIRE(r);
  CHECK(r.value.talker == "GN");
  CHECK(encode(r.value).view() == "$GNRMC,,A,,,,,,,311214,,*3C\r\n");
  o.members["status"] = {json_kind::string, "X"};
  r = read_json<standard::rmc>("GNRMC", o);
  CHECK(r.ec == errc::bad_enum);
  CHECK(r.field == 2);

  object s;
  s.members["timestamp"] = {json_kind::string, "231133.12"};
  s.members["all_ok"] = {json_kind::number, "1"};
  s.members["message"] = {json_kind::string, "BWSI Autonomy OK"};
  auto st = read_json<sandshark::bpsts>("BPSTS", s);
  REQUIRE(st);
  CHECK(encode(st.value).view() == "$BPSTS,231133.12,1,BWSI Autonomy OK*46\r\n");
  s.members.erase("message");  // blank text is empty text
  st = read_json<sandshark::bpsts>("BPSTS", s);
  REQUIRE(st);
  CHECK(st.value.message.empty());
  s.members["all_ok"] = {json_kind::number, "2"};
  CHECK(read_json<sandshark::bpsts>("BPSTS", s).ec == errc::bad_flag);

  object g;
  g.members["date"] = {json_kind::string, "2018-12-10"};
  g.members["time"] = {json_kind::string, "16:12:29"};
  g.members["team_id"] = {json_kind::string, "AUVSI"};
  g.members["entrance_gate"] = {json_kind::number, "1"};  // a number for a digit enum
  g.members["light_pattern"] = {json_kind::string, "RGB"};
  auto gat = read_json<robotx::rxgat>("RXGAT", g);
  REQUIRE(gat);
  CHECK(encode(gat.value).view() == "$RXGAT,101218,161229,AUVSI,1,,,RGB*4E\r\n");
  g.members["light_pattern"] = {json_kind::string, "RGX"};
  gat = read_json<robotx::rxgat>("RXGAT", g);
  CHECK(gat.ec == errc::bad_enum);
  CHECK(gat.field == 7);
  g.members["light_pattern"] = {json_kind::string, "RG,B"};
  CHECK(read_json<robotx::rxgat>("RXGAT", g).ec == errc::bad_length);

  object i;
  i.members["satellites"] = {json_kind::number, "300"};
  i.members["quality"] = {json_kind::string, "1"};
  CHECK(read_json<standard::gga>("GPGGA", i).ec == errc::out_of_range);
  i.members["satellites"] = {json_kind::number, "-1"};
  CHECK(read_json<standard::gga>("GPGGA", i).ec == errc::out_of_range);
  i.members["satellites"] = {json_kind::number, "6.0"};
  CHECK(read_json<standard::gga>("GPGGA", i).ec == errc::bad_number);
  i.members["satellites"] = {json_kind::number, "6"};
  auto gga = read_json<standard::gga>("GPGGA", i);
  REQUIRE(gga);
  CHECK(encode(gga.value).view() == "$GPGGA,,,,,,1,06,,,M,,M,,*61\r\n");
}

#if SEAWIRE_HAS_NLOHMANN_JSON
TEST_CASE("decode -> JSON -> read_json -> encode gives the line back") {
  const std::vector<std::string_view> kingfisher_lines = {
      "$CPIMU,164958.858,-0.061035,-0.000097,-0.061035,-0.026916,0.104533,-0.932172*57\r\n",
      "$CPNVR,164959.063,0.02941,-0.068552,0,0.060938,0,-0.061132*59\r\n",
      "$CPRCM,164959.065,0,234.326694,-1.655603,-6.628557,164959.060*62\r\n",
      "$CPRBS,172909.322,15.121597,15.121597,15.121597,0*76\r\n",
      "$CPRBS,105707.24,1,15.2,15.1,15.3,0*67\r\n",
      "$PYDEV,90,1.5*7D\r\n",
      "$PYDEP,-10,50*71\r\n",
  };
  CHECK(through_json<kingfisher::cpimu>(kingfisher_lines[0]) == kingfisher_lines[0]);
  CHECK(through_json<kingfisher::cpnvr>(kingfisher_lines[1]) == kingfisher_lines[1]);
  CHECK(through_json<kingfisher::cprcm>(kingfisher_lines[2]) == kingfisher_lines[2]);
  CHECK(through_json<kingfisher::cprbs>(kingfisher_lines[3]) == kingfisher_lines[3]);
  CHECK(through_json<kingfisher::cprbs>(kingfisher_lines[4]) == kingfisher_lines[4]);
  CHECK(through_json<kingfisher::pydev>(kingfisher_lines[5]) == kingfisher_lines[5]);
  CHECK(through_json<kingfisher::pydep>(kingfisher_lines[6]) == kingfisher_lines[6]);
  const std::string_view rmc =
      "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70\r\n";
  CHECK(through_json<standard::rmc>(rmc) == rmc);
  const std::string_view gga =
      "$GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,M,-33.2,M,,*5C\r\n";
  CHECK(through_json<standard::gga>(gga) == gga);
  const std::string_view nvg =
      "$BFNVG,231131.55,4218.000000,N,07106.000000,W,0,10.0,1.0,45.0,0.0,0.0,231131.55*62\r\n";
  CHECK(through_json<sandshark::bfnvg>(nvg) == nvg);
  const std::string_view zero = "$CPNVG,105707.24,0000.00,N,00000.00,W,1,,,0,,,105707.24*64\r\n";
  CHECK(through_json<kingfisher::cpnvg>(zero) == zero);
  // Unpadded longitude degrees come back padded: same meaning, canonical form.
  CHECK(through_json<kingfisher::cpnvg>("$CPNVG,164959.034,4221.711142,N,7105.44878,W,1,0,0,"
                                        "234.32964,-6.796959,-1.706798,164959.006*78\r\n") ==
        "$CPNVG,164959.034,4221.711142,N,07105.44878,W,1,0,0,234.32964,-6.796959,-1.706798,"
        "164959.006*48\r\n");
  const std::string_view ack1 = "$BFACK,081025.990,RMB,081025.950,,2,0,*32\r\n";
  const std::string_view ack2 = "$BFACK,081025.990,RMB,081025.950,,2,0*1E\r\n";
  CHECK(through_json<sandshark::bfack>(ack1) == ack1);
  CHECK(through_json<sandshark::bfack>(ack2) == ack2);
  const std::string_view rmb = "$BPRMB,231204.72,-15,,,750,0,1*54\r\n";
  CHECK(through_json<sandshark::bprmb>(rmb) == rmb);
  const std::string_view log = "$BPLOG,ACK,ON*1E\r\n";
  CHECK(through_json<sandshark::bplog>(log) == log);
  const std::string_view hrb = "$RXHRB,111221,161229,21.31198,N,157.88972,W,ROBOT,2,1*11\r\n";
  CHECK(through_json<robotx::rxhrb>(hrb) == hrb);
  const std::string_view gat = "$RXGAT,101218,161229,AUVSI,1,2,Y,RGB*25\r\n";
  CHECK(through_json<robotx::rxgat>(gat) == gat);
  const std::string_view del = "$RXDEL,101218,161229,AUVSI,R,CIRCL*32\r\n";
  CHECK(through_json<robotx::rxdel>(del) == del);
}
#endif

TEST_CASE("ANELLO frame JSON: the spec's example frame, exact digits, null for not available") {
  const auto f = anello::decode_frame(support::seed);
  REQUIRE(f);
  string_sink k;
  anello::write_json(k, f.value);
  CHECK(k.s ==
        R"({"type":"AB00","heading_deg":89,"latitude":32.828671,"longitude":-117.229926,)"
        R"("sog_mps":0.0,"cog_deg":null,"gps_time":"2024-07-03T15:42:58.000Z","alt_msl_m":48.0,)"
        R"("geoid_sep_m":null,"hdop":null,"fix_quality":null,"motor_pct":0,"rudder_pct":0,)"
        R"("stw_mps":0.0,"wind_speed_abs_mps":0.2,"wind_dir_abs_deg":108,)"
        R"("wind_speed_rel_mps":0.3,"wind_dir_rel_deg":90,"air_temp_c":null,"pressure_hpa":null})");
  CHECK(valid_json(k.s));
  CHECK(anello::has_json_field("latitude"));
  CHECK(anello::has_json_field("pressure_hpa"));
  CHECK_FALSE(anello::has_json_field("latitude_deg"));
}

// Every field at the ends of its wire type (the largest value short of "not available", and
// the smallest): the object is put together in a buffer sized at compile time, so these are the
// longest it can be. Also in constant evaluation, where a frame with nothing available is all
// nulls.
TEST_CASE("ANELLO frame JSON: every field at its widest fits, and it is written at compile time") {
  static_assert([] {
    seawire::nmea::json_buffer<1024> b;
    anello::write_json(b, anello::sensor_frame_raw{});
    return b.view().starts_with(R"({"type":"AB00","heading_deg":null,"latitude":null,)") &&
           b.view().ends_with(R"("air_temp_c":null,"pressure_hpa":null})");
  }());
  for (const bool high : {true, false}) {
    anello::sensor_frame_raw f;
    anello::sensor_fields.apply([&](const auto&... field) {
      const auto set = [&](const auto& row) {
        using row_type = std::remove_cvref_t<decltype(row)>;
        using raw = typename row_type::raw_type;
        f.*row_type::raw_member = high ? static_cast<raw>(std::numeric_limits<raw>::max() - 1)
                                       : std::numeric_limits<raw>::min();
      };
      (set(field), ...);
    });
    string_sink k;
    anello::write_json(k, f);
    INFO(k.s);
    CHECK(valid_json(k.s));
    CHECK(k.s.size() <= anello::detail::frame_json_max_size);
    CHECK(k.s.find("null") == std::string::npos);
  }
}

TEST_CASE("ANELLO frame JSON read back: exact, strict, errors by field number") {
  object o;
  o.members["heading_deg"] = {json_kind::number, "89"};
  o.members["latitude"] = {json_kind::number, "32.828671"};
  o.members["longitude"] = {json_kind::number, "-117.229926"};
  o.members["sog_mps"] = {json_kind::number, "0.0"};
  o.members["gps_time"] = {json_kind::string, "2024-07-03T15:42:58.000Z"};
  o.members["alt_msl_m"] = {json_kind::number, "48.0"};
  o.members["motor_pct"] = {json_kind::number, "0"};
  o.members["rudder_pct"] = {json_kind::number, "0"};
  o.members["stw_mps"] = {json_kind::number, "0.0"};
  o.members["wind_speed_abs_mps"] = {json_kind::number, "0.2"};
  o.members["wind_dir_abs_deg"] = {json_kind::number, "108"};
  o.members["wind_speed_rel_mps"] = {json_kind::number, "0.3"};
  o.members["wind_dir_rel_deg"] = {json_kind::number, "90"};
  auto r = anello::read_frame_json(o);
  REQUIRE(r);
  // The spec's example sends 0xFFFF for air temperature; "not available" is written as 0x7FFF.
  auto expected = anello::decode_frame(support::seed).value;
  expected.air_temp = 0x7FFF;
  CHECK(r.value == expected);

  o.members["sog_mps"] = {json_kind::number, "1.25"};  // rounded to 0.1, halves away from zero
  r = anello::read_frame_json(o);
  REQUIRE(r);
  CHECK(r.value.sog == 13);
  o.members["gps_time"] = {json_kind::number, "1720021378000"};  // milliseconds
  r = anello::read_frame_json(o);
  REQUIRE(r);
  CHECK(r.value.gps_time_ms == 1720021378000ULL);

  o.members["heading_deg"] = {json_kind::number, "361"};
  r = anello::read_frame_json(o);
  CHECK(r.ec == errc::out_of_range);
  CHECK(r.field == 1);
  CHECK(r.column == 8);
  o.members["heading_deg"] = {json_kind::number, "89"};
  o.members["air_temp_c"] = {json_kind::number, "-0.1"};
  r = anello::read_frame_json(o);
  CHECK(r.ec == errc::value_too_large);
  CHECK(r.field == 18);
  o.members["air_temp_c"] = {json_kind::number, "21.5"};
  r = anello::read_frame_json(o);
  REQUIRE(r);
  CHECK(r.value.air_temp == 215);
  o.members["gps_time"] = {json_kind::string, "2024-02-30T00:00:00Z"};
  r = anello::read_frame_json(o);
  CHECK(r.ec == errc::day_out_of_range);
  CHECK(r.field == 6);
  o.members["gps_time"] = {json_kind::string, "2024-07-03T15:42:58.0001Z"};
  CHECK(anello::read_frame_json(o).ec == errc::bad_time);
  // Before the epoch the frame counts from: out of range, not a bad month.
  o.members["gps_time"] = {json_kind::string, "1969-12-31T23:59:59.999Z"};
  r = anello::read_frame_json(o);
  CHECK(r.ec == errc::out_of_range);
  CHECK(r.field == 6);
  o.members["gps_time"] = {json_kind::string, "1970-13-01T00:00:00Z"};
  CHECK(anello::read_frame_json(o).ec == errc::month_out_of_range);
  o.members["gps_time"] = {json_kind::string, "2024-07-03T15:42:58Z"};
  r = anello::read_frame_json(o);
  REQUIRE(r);
  CHECK(r.value.gps_time_ms == 1720021378000ULL);

  // Times outside ISO's four-digit years are written as milliseconds.
  anello::sensor_frame_raw far;
  far.gps_time_ms = 253402300800000ULL;
  string_sink k;
  anello::write_json(k, far);
  CHECK(k.s.find(R"("gps_time":253402300800000,)") != std::string::npos);
}

TEST_CASE("ANELLO frame JSON read back: a code is a whole number, measurements are rounded") {
  object o;
  const auto with = [&](const char* key, json_kind kind, const char* text) {
    o.members.clear();
    o.members[key] = {kind, text};
    return anello::read_frame_json(o);
  };
  // The GGA fix quality is a code: 7.5 is no quality, and 7.0 is not written as one.
  for (const char* text : {"7.5", "7.0", "0.4", "-0.5"}) {
    INFO(text);
    const auto r = with("fix_quality", json_kind::number, text);
    CHECK(r.ec == errc::bad_number);
    CHECK(r.field == 10);
    CHECK(r.column == 39);
  }
  auto r = with("fix_quality", json_kind::number, "7");
  REQUIRE(r);
  CHECK(r.value.gga_quality == 7);
  r = with("fix_quality", json_kind::string, "8");
  REQUIRE(r);
  CHECK(r.value.gga_quality == 8);
  CHECK(with("fix_quality", json_kind::number, "9").ec == errc::out_of_range);
  // Measured values, whole units on the wire too, are still rounded (halves away from zero).
  r = with("heading_deg", json_kind::number, "89.5");
  REQUIRE(r);
  CHECK(r.value.heading == 90);
  r = with("motor_pct", json_kind::number, "-99.5");
  REQUIRE(r);
  CHECK(r.value.motor == -100);
  r = with("motor_pct", json_kind::number, "-100.5");
  CHECK(r.ec == errc::out_of_range);
  CHECK(r.field == 11);
  r = with("pressure_hpa", json_kind::number, "1013.25");
  REQUIRE(r);
  CHECK(r.value.pressure == 1013);
}

namespace {
// A flat JSON object as write_json(frame) writes it (no commas inside values), read into the
// lookup read_frame_json asks.
struct flat_frame_object {
  std::vector<std::string> storage;
  object o;
  explicit flat_frame_object(std::string_view js) {
    storage.reserve(64);
    REQUIRE(js.size() >= 2);
    js = js.substr(1, js.size() - 2);
    while (!js.empty()) {
      const std::size_t comma = js.find(',');
      const std::string_view member = js.substr(0, comma);
      js = comma == std::string_view::npos ? std::string_view{} : js.substr(comma + 1);
      const std::size_t colon = member.find("\":");
      REQUIRE(colon != std::string_view::npos);
      const std::string key(member.substr(1, colon - 1));
      std::string_view text = member.substr(colon + 2);
      json_kind kind = json_kind::number;
      if (text == "null") {
        kind = json_kind::null;
      } else if (text.front() == '"') {
        kind = json_kind::string;
        text = text.substr(1, text.size() - 2);
      }
      storage.emplace_back(text);
      o.members[key] = {kind, storage.back()};
    }
  }
};
}  // namespace

// What seawire-decode accepts (validate), seawire-encode must send back: every frame validate()
// accepts reads back from its JSON as the same frame, and every frame it refuses is refused.
TEST_CASE("ANELLO frame JSON: validate() and read_frame_json agree on every field's values") {
  std::mt19937_64 rng(11);
  const auto base = anello::decode_frame(support::seed);
  REQUIRE(base);
  int accepted = 0, refused = 0;
  anello::detail::visit_sensor_fields([&](std::uint16_t number, const auto& field) {
    using field_type = std::remove_cvref_t<decltype(field)>;
    using raw_type = typename field_type::raw_type;
    using limits = std::numeric_limits<raw_type>;
    const auto [lo, hi] = field.wire_limits();
    std::vector<raw_type> values = {limits::min(), static_cast<raw_type>(limits::min() + 1), 0,
                                    static_cast<raw_type>(limits::max() - 1), limits::max()};
    if constexpr (std::is_signed_v<raw_type>) values.push_back(static_cast<raw_type>(-1));
    // The edges of the sender's range and one past them (in 64 bits: gps_time's hi is
    // INT64_MAX, and one past it is a uint64 the wire carries).
    for (const std::int64_t edge : {lo, lo + 1, hi - 1, hi}) {
      if (std::in_range<raw_type>(edge)) values.push_back(static_cast<raw_type>(edge));
    }
    if (std::in_range<raw_type>(lo) && std::cmp_greater(lo, limits::min()))
      values.push_back(static_cast<raw_type>(lo - 1));
    if (std::cmp_less(hi, limits::max()))
      values.push_back(static_cast<raw_type>(static_cast<std::uint64_t>(hi) + 1));
    for (int k = 0; k < 300; ++k) values.push_back(static_cast<raw_type>(rng()));
    for (int k = 0; k < 300; ++k) {
      const auto span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
      const std::uint64_t off = span == ~std::uint64_t{0} ? rng() : rng() % (span + 1);
      values.push_back(static_cast<raw_type>(static_cast<std::uint64_t>(lo) + off));
    }
    for (const raw_type raw : values) {
      anello::sensor_frame_raw f = base.value;
      f.*field_type::raw_member = raw;
      string_sink k;
      anello::write_json(k, f);
      const flat_frame_object json(k.s);
      const auto back = anello::read_frame_json(json.o);
      INFO("field " << number << " raw " << +raw << ": " << k.s);
      if (anello::validate(f)) {
        ++accepted;
        REQUIRE(back.ok());
        // "Not available" comes back as the type's maximum (the spec's 0xFFFF air temperature
        // as 0x7FFF), every other value as it was.
        anello::sensor_frame_raw expected = f;
        anello::detail::visit_sensor_fields([&](std::uint16_t, const auto& g) {
          using g_type = std::remove_cvref_t<decltype(g)>;
          auto& r = expected.*g_type::raw_member;
          if (g.not_available(r)) r = anello::detail::not_available<typename g_type::raw_type>;
          return true;
        });
        REQUIRE(back.value == expected);
      } else {
        ++refused;
        REQUIRE_FALSE(back.ok());
        CHECK(back.field == number);
      }
    }
    return true;
  });
  CHECK(accepted > 19 * 300);
  CHECK(refused > 0);
}

TEST_CASE("magnetic variation: signed degrees east positive, null without a value") {
  nmea::magnetic_variation v{decimal::scaled(153, 1), hemisphere::west};
  CHECK(value_json(v) == "-15.3");
  v.direction = hemisphere::east;
  CHECK(value_json(v) == "15.3");
  v.value.reset();  // a letter that came without a usable value
  CHECK(value_json(v) == "null");

  nmea::magnetic_variation back;
  REQUIRE(read_json_value(json_value{json_kind::number, "-15.30"}, back) == errc::ok);
  CHECK(back.value == decimal::scaled(1530, 2));
  CHECK(back.direction == hemisphere::west);
  REQUIRE(read_json_value(json_value{json_kind::number, "-0.0"}, back) == errc::ok);
  CHECK(back.direction == hemisphere::west);  // the sign of -0.0 is the letter W
  CHECK(read_json_value(json_value{json_kind::string, "east"}, back) == errc::bad_variation);
}

TEST_CASE("to_chars: every value type as people read it, as std::to_chars does") {
  const auto text = [](const auto& v) {
    char buf[64];
    const std::to_chars_result r = nmea::to_chars(buf, buf + sizeof buf, v);
    REQUIRE(r.ec == std::errc{});
    return std::string(buf, r.ptr);
  };
  CHECK(text(decimal::scaled(450, 2)) == "4.50");
  CHECK(text(-decimal::scaled(0, 1)) == "-0.0");
  const auto rmc = must_decode<standard::rmc>(
      "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,15.3,W,A*3E");
  CHECK(text(*rmc.lat) == "42.3618523333333");
  CHECK(text(*rmc.lon) == "-71.0908130");
  CHECK(text(*rmc.time) == "16:49:59.00");
  CHECK(text(*rmc.date) == "2014-12-31");
  CHECK(text(rmc.status) == "A");
  CHECK(text(*rmc.magnetic_variation) == "-15.3");
  CHECK(text(nmea::text<8>("survey")) == "survey");
  CHECK(text(robotx::system_mode::autonomous) == "2");
  // Too small: value_too_large, as std::to_chars says it.
  char small[4];
  const auto r = nmea::to_chars(small, small + sizeof small, *rmc.lat);
  CHECK(r.ec == std::errc::value_too_large);
  CHECK(r.ptr == small + sizeof small);
}

TEST_CASE("times, dates and numbers in JSON: padded as the wire has them, every digit kept") {
  CHECK(value_json(nmea::time_of_day(8, 1, 2)) == "\"08:01:02\"");
  CHECK(value_json(nmea::time_of_day(23, 59, 60, 5, 3)) == "\"23:59:60.005\"");
  CHECK(value_json(nmea::date(2014, 2, 3)) == "\"2014-02-03\"");
  CHECK(value_json(nmea::date(980, 12, 31)) == "\"0980-12-31\"");
  // Values no decoder makes (a program may still hold one): no digit is lost.
  nmea::time_of_day odd;
  odd.hour = 255;
  odd.minute = 7;
  odd.second = 100;
  odd.fraction = 12345;
  odd.places = 2;
  CHECK(value_json(odd) == "\"255:07:100.12345\"");
  odd.fraction = 5;
  odd.places = 30;  // padded to at most 24 digits
  CHECK(value_json(odd) == "\"255:07:100.000000000000000000000005\"");
  nmea::date far;
  far.year = 12345;
  far.month = 100;
  far.day = 5;
  CHECK(value_json(far) == "\"12345-100-05\"");
  // Decimals: the wire's fraction digits, a zero before the point, the sign kept.
  CHECK(value_json(decimal::scaled(5, 2)) == "0.05");
  CHECK(value_json(decimal::scaled(-5, 3)) == "-0.005");
  CHECK(value_json(decimal::scaled(1234500, 4)) == "123.4500");
  CHECK(value_json(decimal{0}) == "0");
  CHECK(value_json(decimal::scaled(std::numeric_limits<std::int64_t>::max(), 19)) ==
        "0.9223372036854775807");
  CHECK(value_json(decimal::scaled(-5, 30)) == "null");  // more places than a number can have
  CHECK(value_json(std::uint64_t{18446744073709551615U}) == "18446744073709551615");
}

TEST_CASE("ANELLO frame: fields named by number, and errors told for people") {
  using namespace seawire::anello;
  const sensor_field_about heading = about_sensor_field(1);
  CHECK(heading.found);
  CHECK(heading.name == "heading_deg");
  CHECK(heading.json_key == "heading_deg");
  CHECK_FALSE(heading.is_code);
  const sensor_field_about lat = about_sensor_field(2);
  CHECK(lat.name == "latitude_deg");
  CHECK(lat.json_key == "latitude");
  CHECK(about_sensor_field(10).name == "fix_quality");
  CHECK(about_sensor_field(10).is_code);
  CHECK(about_sensor_field(19).name == "pressure_hpa");
  CHECK_FALSE(about_sensor_field(0).found);
  CHECK_FALSE(about_sensor_field(20).found);
  // Every field has a JSON key the frame's JSON reader knows.
  for (std::uint16_t n = 1; n <= sensor_field_count; ++n) {
    INFO("field " << n);
    CHECK(has_json_field(about_sensor_field(n).json_key));
  }

  sensor_frame_raw f;
  f.heading = 361;
  f.lat = -90'000'001;
  std::array<char, 160> buf;
  const auto r = validate(f);
  REQUIRE(r.field == 1);
  CHECK(error_text(buf, r, f) ==
        "AB00 field 1 (heading_deg) 361: " + std::string(seawire::message(r.ec)));
  f.heading = 359;
  const auto r2 = validate(f);
  REQUIRE(r2.field == 2);
  CHECK(error_text(buf, r2, f) ==
        "AB00 field 2 (latitude) -90.000001: " + std::string(seawire::message(r2.ec)));
  std::array<char, 12> small;
  CHECK(error_text(small, r2, f) == "AB00 field ");  // cut to fit, NUL kept
  CHECK(small.back() == '\0');
  CHECK(error_text(buf, validate(sensor_frame_raw{}), sensor_frame_raw{}) == "ok");
}

TEST_CASE("CSV: a header of field names, rows of the JSON values, blank for not available") {
  string_sink h;
  write_csv_header<kingfisher::cpnvg>(h);
  CHECK(h.s ==
        "timestamp,latitude,longitude,position_quality,altitude_m,depth_m,heading_deg,roll_deg,"
        "pitch_deg,nav_timestamp\n");

  const auto nvg = must_decode<kingfisher::cpnvg>(
      "$CPNVG,164959.034,4221.711142,N,07105.44878,W,1,0,0,234.32964,-6.796959,-1.706798,"
      "164959.006*48\r\n");
  string_sink row;
  write_csv(row, nvg);
  CHECK(row.s ==
        "16:49:59.034,42.36185236666667,-71.0908130,true,0,0,234.32964,-6.796959,-1.706798,"
        "16:49:59.006\n");

  // Blank fields and a variation without a value are empty cells; one with a value is signed.
  auto rmc = must_decode<standard::rmc>("$GPRMC,164959.00,V,,,,,,,311214,,,N*7F\r\n");
  string_sink blank;
  write_csv(blank, rmc);
  CHECK(blank.s == "16:49:59.00,V,,,,,2014-12-31,,N,\n");
  rmc.magnetic_variation = nmea::magnetic_variation{decimal::scaled(153, 1), hemisphere::west};
  blank.s.clear();
  write_csv(blank, rmc);
  CHECK(blank.s == "16:49:59.00,V,,,,,2014-12-31,-15.3,N,\n");
  rmc.magnetic_variation = nmea::magnetic_variation{std::nullopt, hemisphere::east};
  blank.s.clear();
  write_csv(blank, rmc);
  CHECK(blank.s == "16:49:59.00,V,,,,,2014-12-31,,N,\n");
}

TEST_CASE("CSV: text is quoted only when it must be, quotes doubled") {
  string_sink s;
  write_csv_text(s, "Running /var/log/mission_12");
  CHECK(s.s == "Running /var/log/mission_12");
  s.s.clear();
  write_csv_text(s, R"(said "stop", twice)");
  CHECK(s.s == R"("said ""stop"", twice")");
  s.s.clear();
  write_csv_text(s, "two\nlines");
  CHECK(s.s == "\"two\nlines\"");
  s.s.clear();
  write_csv_text(s, "");
  CHECK(s.s.empty());

  sandshark::bfmis m;
  m.timestamp = {23, 11, 21, 30, 2};
  m.dive_file = "dive1.xml";
  m.status = "Aborted";
  m.details = R"(depth "12.5" > max, surfacing)";
  string_sink row;
  write_csv(row, m);
  CHECK(row.s == R"(23:11:21.30,dive1.xml,Aborted,"depth ""12.5"" > max, surfacing")"
                 "\n");
}

TEST_CASE("CSV of ANELLO frames: the JSON keys, unquoted values, empty when not available") {
  const auto f = anello::decode_frame(support::seed);
  REQUIRE(f);
  string_sink h;
  anello::write_csv_header(h);
  CHECK(h.s ==
        "heading_deg,latitude,longitude,sog_mps,cog_deg,gps_time,alt_msl_m,geoid_sep_m,hdop,"
        "fix_quality,motor_pct,rudder_pct,stw_mps,wind_speed_abs_mps,wind_dir_abs_deg,"
        "wind_speed_rel_mps,wind_dir_rel_deg,air_temp_c,pressure_hpa\n");
  string_sink row;
  anello::write_csv(row, f.value);
  CHECK(row.s ==
        "89,32.828671,-117.229926,0.0,,2024-07-03T15:42:58.000Z,48.0,,,,0,0,0.0,0.2,108,0.3,90,,"
        "\n");
}
