// SPDX-License-Identifier: BSL-1.0
// Field codecs and the message description, through small test messages that use every
// value type and option.

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <string>

#include "seawire/detail/calendar.hpp"
#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/message.hpp"

#include "support.hpp"

using namespace seawire;
using namespace seawire::nmea;

namespace {

using namespace support;

enum class status : char { valid = 'A', invalid = 'V' };

enum class switch_state : std::uint8_t { on, off };
constexpr std::array<std::string_view, 2> enum_words(switch_state) noexcept {
  return {"ON", "OFF"};
}
constexpr std::array<std::pair<std::string_view, switch_state>, 1> enum_aliases(
    switch_state) noexcept {
  return {{{"OF", switch_state::off}}};
}

// $TSALL,<time>,<date>,<lat>,<N/S>,<lon>,<E/W>,<num>,<count>,<flag>,<status>,<word>,<text>
struct all_types {
  time_of_day time;                       // 1
  date day;                               // 2
  latitude lat;                           // 3,4
  longitude lon;                          // 5,6
  decimal value;                          // 7  -100..100
  std::int16_t count = 0;                 // 8
  bool flag = false;                      // 9
  status state = status::valid;           // 10
  switch_state power = switch_state::on;  // 11
  text<8> label;                          // 12
  static constexpr auto nmea = sentence<"TSALL">(
      field<&all_types::time>("time"), field<&all_types::day>("date"),
      field<&all_types::lat>("latitude"), field<&all_types::lon>("longitude"),
      field<&all_types::value>("value", in_range(-100, 100)), field<&all_types::count>("count"),
      field<&all_types::flag>("flag"), field<&all_types::state>("state"),
      field<&all_types::power>("power"), field<&all_types::label>("label"));
};

// $TSOPT,<speed>,N,<heading>,<id>[,<tail>]  with optional values, a unit, a half-open range
struct optionals {
  std::optional<decimal> speed;    // 1,2 knots + 'N'
  std::optional<decimal> heading;  // 3 [0, 360)
  std::optional<std::uint8_t> id;  // 4 only in the 5-field form
  std::optional<decimal> level;    // 4 or 5
  std::optional<text<4>> tail;     // may be absent entirely
  static constexpr auto nmea =
      sentence<"TSOPT">(field<&optionals::speed>("speed", unit('N'), at_least(0)),
                        field<&optionals::heading>("heading", in_range_below(0, 360)),
                        field<&optionals::id>("id", only_with_field_count(6)),
                        field<&optionals::level>("level", max_places(1)),
                        field<&optionals::tail>("tail", may_be_absent));
};

constexpr std::string_view kAll =
    "$TSALL,235960.123456789,290224,0000.0000,S,17959.9999,E,-0.0,-32768,1,V,OFF,a b:c*3C\r\n";

}  // namespace

static_assert(encode(decode<all_types>(kAll).value).view() == kAll);

TEST_CASE("every value type decodes and re-encodes exactly") {
  const auto r = decode<all_types>(kAll);
  REQUIRE(r);
  const auto& m = r.value;
  CHECK((m.time.hour == 23 && m.time.minute == 59 && m.time.second == 60));
  CHECK((m.time.fraction == 123456789 && m.time.places == 9));
  CHECK((m.day.year == 2024 && m.day.month == 2 && m.day.day == 29));
  CHECK(m.lat.degrees() == 0.0);
  CHECK(std::signbit(m.lat.degrees()));  // S at zero keeps its sign
  CHECK(m.lon.degrees() == Approx(179.9999998333));
  CHECK(m.value.negative);
  CHECK(m.value.is_zero());
  CHECK(m.count == -32768);
  CHECK(m.flag);
  CHECK(m.state == status::invalid);
  CHECK(m.power == switch_state::off);
  CHECK(m.label == "a b:c");
  CHECK(encode(m).view() == kAll);
}

TEST_CASE("decimal keeps its written form") {
  for (std::string_view s : {"0", "-0", "-0.0", "4.50", "123456789.0123456789", "0.0001",
                             "9999999999999999999", "100", "000.0", "011.3", "-007", "00.50"}) {
    decimal d;
    REQUIRE(nmea::detail::parse_decimal(s, false, d) == errc::ok);
    char buf[64];
    writer w(buf);
    nmea::detail::write_decimal(w, d);
    CHECK(w.view() == s);
  }
  decimal d;
  CHECK(nmea::detail::parse_decimal("+5", true, d) == errc::ok);
  CHECK(d == decimal{5});
  CHECK(nmea::detail::parse_decimal("+5", false, d) == errc::bad_number);
  CHECK(nmea::detail::parse_decimal(".5", false, d) == errc::ok);
  CHECK(d == decimal::scaled(5, 1));
  for (std::string_view bad : {"", "-", "+", ".", "1e5", "1.2.3", "0x10", "--1", "1-", "inf", "nan",
                               " ", "   ", "1 2", "- 1", "1. 5", " -", "\t1", "1\t"}) {
    INFO(bad);
    CHECK(nmea::detail::parse_decimal(bad, true, d) == errc::bad_number);
    CHECK(nmea::detail::parse_decimal(bad, true, d, true) == errc::bad_number);
  }
  // SPI 4.2: "the first non-whitespace character will be the minus sign": receivers that allow
  // it (parse_policy::spaced_numbers) take spaces around a number; by default, and in the
  // strict (send-side) reading, they are not part of a number.
  for (const auto& [spaced, want] : {std::pair<std::string_view, decimal>{" 1", decimal{1}},
                                     {"1 ", decimal{1}},
                                     {"  -5.0  ", decimal::scaled(-50, 1)},
                                     {" +12.25", decimal::scaled(1225, 2)}}) {
    INFO(spaced);
    REQUIRE(nmea::detail::parse_decimal(spaced, true, d, true) == errc::ok);
    CHECK(d == want);
    CHECK(nmea::detail::parse_decimal(spaced, true, d) == errc::bad_number);
    CHECK(nmea::detail::parse_decimal(spaced, false, d, true) == errc::bad_number);
  }
  REQUIRE(nmea::detail::parse_decimal(" 007 ", true, d, true) == errc::ok);
  CHECK(d.mantissa == 7);
  CHECK(d.int_width == 3);  // the digits as written, without the spaces
  CHECK(nmea::detail::parse_decimal("10000000000000000000", false, d) == errc::number_too_long);
  CHECK(nmea::detail::parse_decimal(std::string(400, '9'), false, d) == errc::number_too_long);
  CHECK(nmea::detail::parse_decimal("0.00000000000000000001", false, d) == errc::number_too_long);
  // Leading zeros are not significant digits.
  CHECK(nmea::detail::parse_decimal("0000000000000000000000001", false, d) == errc::ok);
  CHECK(d.mantissa == 1);
}

TEST_CASE("decimal compare, to_double and from_double") {
  CHECK(decimal::scaled(45, 1).compare(decimal::scaled(450, 2)) == 0);
  CHECK(decimal::scaled(45, 1) != decimal::scaled(450, 2));  // equality is of the written form
  CHECK(decimal(-1).compare(decimal(0)) < 0);
  CHECK(decimal(0).compare(decimal(-1)) > 0);
  CHECK(decimal::scaled(-15, 1).compare(decimal(-1)) < 0);
  CHECK(decimal(100).compare(decimal::scaled(99999, 3)) > 0);
  decimal neg_zero;
  neg_zero.negative = true;
  CHECK(neg_zero.compare(decimal(0)) == 0);
  CHECK(decimal::scaled(156780, 3).to_double() == 156.78);
  CHECK(decimal::scaled(-33, 0).to_double() == -33.0);

  auto r = decimal::from_double(1.5, 2);
  REQUIRE(r);
  CHECK(r.value == decimal::scaled(150, 2));
  r = decimal::from_double(-0.004, 2);
  REQUIRE(r);
  CHECK(r.value == decimal::scaled(0, 2));  // rounds to zero: no "-0.00"
  CHECK(decimal::from_double(0.145, 3).value == decimal::scaled(145, 3));
  CHECK(decimal::from_double(std::nan(""), 2).ec == errc::not_finite);
  CHECK(decimal::from_double(HUGE_VAL, 2).ec == errc::not_finite);
  CHECK(decimal::from_double(1e19, 0).ec == errc::value_too_large);
  CHECK(decimal::from_double(1.0, 19).ec == errc::value_too_large);
}

TEST_CASE("positions: split at the decimal point, unpadded degrees, domain checks") {
  struct row {
    std::string_view lat, lon;
    double lat_deg, lon_deg;
  };
  const row ok[] = {{"4221.711142", "7105.44878", 42.3618523667, -71.090813},
                    {"4221.711142", "07105.44878", 42.3618523667, -71.090813},
                    {"0000.00", "00000.00", 0.0, -0.0},
                    {"9000.000", "18000.000", 90.0, -180.0},
                    {"521.5", "521.5", 5.3583333333, -5.3583333333},
                    {"4221", "07105", 42.35, -71.0833333333}};
  for (const auto& r : ok) {
    const std::string line = sealed("TSALL,000000,010100," + std::string(r.lat) + ",N," +
                                    std::string(r.lon) + ",W,0,0,0,A,ON,");
    INFO(line);
    const auto d = decode<all_types>(line);
    REQUIRE(d);
    CHECK(d.value.lat.degrees() == Approx(r.lat_deg));
    CHECK(d.value.lon.degrees() == Approx(r.lon_deg));
    // Written back as it came, but for the one fraction digit a position always has.
    std::string lat(r.lat);
    std::string lon(r.lon);
    if (lat.find('.') == std::string::npos) lat += ".0";
    if (lon.find('.') == std::string::npos) lon += ".0";
    CHECK(encode(d.value).view() ==
          sealed("TSALL,000000,010100," + lat + ",N," + lon + ",W,0,0,0,A,ON,"));
  }
}

TEST_CASE("malformed fields: errc and field number") {
  struct row {
    std::string_view body;
    errc expected;
    std::uint16_t field;
  };
  const row rows[] = {
      // time
      {"TSALL,240000,010100,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::hour_out_of_range, 1},
      {"TSALL,126000,010100,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::minute_out_of_range, 1},
      {"TSALL,125960,010100,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::second_out_of_range, 1},
      {"TSALL,125961,010100,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::second_out_of_range, 1},
      {"TSALL,12000,010100,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::bad_time, 1},
      {"TSALL,120000.1234567890,010100,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::bad_time, 1},
      {"TSALL,1200a0,010100,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::bad_time, 1},
      {"TSALL,120000.,010100,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::bad_time, 1},
      {"TSALL,120000:5,010100,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::bad_time, 1},
      {"TSALL,,010100,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::missing_field, 1},
      // date
      {"TSALL,120000,011300,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::month_out_of_range, 2},
      {"TSALL,120000,010000,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::month_out_of_range, 2},
      {"TSALL,120000,320100,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::day_out_of_range, 2},
      {"TSALL,120000,290223,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::day_out_of_range, 2},
      {"TSALL,120000,310424,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::day_out_of_range, 2},
      {"TSALL,120000,000124,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::day_out_of_range, 2},
      {"TSALL,120000,10118,4221.7,N,07105.4,W,0,0,0,A,ON,", errc::bad_date, 2},
      // latitude / longitude
      {"TSALL,120000,010100,4261.7,N,07105.4,W,0,0,0,A,ON,", errc::minute_out_of_range, 3},
      {"TSALL,120000,010100,9100.0,N,07105.4,W,0,0,0,A,ON,", errc::bad_latitude, 3},
      {"TSALL,120000,010100,9000.1,N,07105.4,W,0,0,0,A,ON,", errc::bad_latitude, 3},
      {"TSALL,120000,010100,04221.7,N,07105.4,W,0,0,0,A,ON,", errc::bad_latitude, 3},
      {"TSALL,120000,010100,21.7,N,07105.4,W,0,0,0,A,ON,", errc::bad_latitude, 3},
      {"TSALL,120000,010100,-4221.7,N,07105.4,W,0,0,0,A,ON,", errc::bad_latitude, 3},
      {"TSALL,120000,010100,42a1.7,N,07105.4,W,0,0,0,A,ON,", errc::bad_latitude, 3},
      {"TSALL,120000,010100,4221.7,E,07105.4,W,0,0,0,A,ON,", errc::bad_hemisphere, 4},
      {"TSALL,120000,010100,4221.7,,07105.4,W,0,0,0,A,ON,", errc::bad_hemisphere, 4},
      {"TSALL,120000,010100,4221.7,n,07105.4,W,0,0,0,A,ON,", errc::bad_hemisphere, 4},
      {"TSALL,120000,010100,4221.7,N,18100.0,W,0,0,0,A,ON,", errc::bad_longitude, 5},
      {"TSALL,120000,010100,4221.0000000000001,N,07105.4,W,0,0,0,A,ON,", errc::bad_latitude, 3},
      {"TSALL,120000,010100,4221.000000000001,N,07105.4,W,0,0,0,A,ON,", errc::ok, 0},
      {"TSALL,120000,010100,4221.7,N,071a5.4,W,0,0,0,A,ON,", errc::bad_longitude, 5},
      {"TSALL,120000,010100,4221.7,N,107105.4,W,0,0,0,A,ON,", errc::bad_longitude, 5},
      {"TSALL,120000,010100,4221.7,N,07105.4,S,0,0,0,A,ON,", errc::bad_hemisphere, 6},
      // numbers and ranges
      {"TSALL,120000,010100,4221.7,N,07105.4,W,100.01,0,0,A,ON,", errc::out_of_range, 7},
      {"TSALL,120000,010100,4221.7,N,07105.4,W,-150,0,0,A,ON,", errc::out_of_range, 7},
      {"TSALL,120000,010100,4221.7,N,07105.4,W,1e2,0,0,A,ON,", errc::bad_number, 7},
      {"TSALL,120000,010100,4221.7,N,07105.4,W,0,32768,0,A,ON,", errc::out_of_range, 8},
      {"TSALL,120000,010100,4221.7,N,07105.4,W,0,1.5,0,A,ON,", errc::bad_number, 8},
      {"TSALL,120000,010100,4221.7,N,07105.4,W,0,0,2,A,ON,", errc::bad_flag, 9},
      {"TSALL,120000,010100,4221.7,N,07105.4,W,0,0,0,X,ON,", errc::bad_enum, 10},
      {"TSALL,120000,010100,4221.7,N,07105.4,W,0,0,0,AV,ON,", errc::bad_enum, 10},
      {"TSALL,120000,010100,4221.7,N,07105.4,W,0,0,0,A,on,", errc::bad_enum, 11},
      {"TSALL,120000,010100,4221.7,N,07105.4,W,0,0,0,A,ON,123456789", errc::text_too_long, 12},
      // layout
      {"TSALL,120000,010100,4221.7,N,07105.4,W,0,0,0,A", errc::too_few_fields, 11},
      {"TSALL,120000", errc::too_few_fields, 2},
      {"TSALL", errc::too_few_fields, 1},
      {"TSALL,120000,010100,4221.7,N", errc::too_few_fields, 5},
      {"TSALL,120000,010100,4221.7", errc::too_few_fields, 4},
  };
  for (const auto& r : rows) {
    const std::string line = sealed(r.body);
    INFO(line);
    const auto d = decode<all_types>(line);
    CHECK(d.ec == r.expected);
    CHECK(d.field == r.field);
    if (r.expected != errc::ok) CHECK(field_name<all_types>(d.field).size() > 0);
  }
}

TEST_CASE("error columns point at the offending field") {
  const std::string line = sealed("TSALL,120000,010100,4261.7,N,07105.4,W,0,0,0,A,ON,");
  const auto d = decode<all_types>(line);
  CHECK(d.ec == errc::minute_out_of_range);
  CHECK(line.substr(d.column, 6) == "4261.7");
}

TEST_CASE("extra trailing fields: ignored by default, refused under strict") {
  const std::string line = sealed("TSALL,120000,010100,4221.7,N,07105.4,W,0,0,0,A,ON,x,extra,more");
  CHECK(decode<all_types>(line));
  const auto strict = decode<all_types>(line, parse_policy::strict());
  CHECK(strict.ec == errc::too_many_fields);
  CHECK(strict.field == 13);
}

TEST_CASE("strict values: no '+' signs, no reserved characters in text; spaces by numbers") {
  const std::string plus = sealed("TSALL,120000,010100,4221.7,N,07105.4,W,+5,0,0,A,ON,");
  CHECK(decode<all_types>(plus));
  CHECK(decode<all_types>(plus).value.value == decimal{5});
  CHECK(decode<all_types>(plus, parse_policy::strict()).ec == errc::bad_number);
  const std::string spaced = sealed("TSALL,120000,010100,4221.7,N,07105.4,W, -5.5,0,0,A,ON,");
  parse_policy spi;
  spi.spaced_numbers = true;
  REQUIRE(decode<all_types>(spaced, spi));
  CHECK(decode<all_types>(spaced, spi).value.value == decimal::scaled(-55, 1));
  CHECK(encode(decode<all_types>(spaced, spi).value).view().find(",-5.5,") !=
        std::string_view::npos);
  for (parse_policy refuses : {parse_policy{}, parse_policy::strict()}) {
    refuses.spaced_numbers = refuses.strict_values;  // strict refuses even with the flag set
    const auto r = decode<all_types>(spaced, refuses);
    CHECK(r.ec == errc::bad_number);
    CHECK(r.field == 7);
  }
  const std::string bang = sealed("TSALL,120000,010100,4221.7,N,07105.4,W,5,0,0,A,ON,hi!");
  CHECK(decode<all_types>(bang));
  CHECK(decode<all_types>(bang, parse_policy::strict()).ec == errc::bad_text);
}

TEST_CASE("word enum aliases are accepted and written in the main spelling") {
  const std::string line = sealed("TSALL,120000,010100,4221.7,N,07105.4,W,5,0,0,A,OF,");
  const auto d = decode<all_types>(line);
  REQUIRE(d);
  CHECK(d.value.power == switch_state::off);
  CHECK(encode(d.value).view().find(",OFF,") != std::string_view::npos);
}

TEST_CASE("optional fields, units, field-count forms and absent tails") {
  SECTION("all blank") {
    const std::string line = sealed("TSOPT,,N,,");
    const auto d = decode<optionals>(line);
    REQUIRE(d);
    CHECK_FALSE(d.value.speed);
    CHECK_FALSE(d.value.heading);
    CHECK_FALSE(d.value.id);
    CHECK_FALSE(d.value.level);
    CHECK_FALSE(d.value.tail);  // not there at all
    CHECK(encode(d.value).view() == line);
  }
  SECTION("blank unit letter is accepted, the right one is written") {
    const auto d = decode<optionals>(sealed("TSOPT,5.2,,359.9,1.5"));
    REQUIRE(d);
    CHECK(*d.value.speed == decimal::scaled(52, 1));
    CHECK(encode(d.value).view() == sealed("TSOPT,5.2,N,359.9,1.5"));
  }
  SECTION("a sentence that stops early: blanks when liberal, too_few_fields when strict") {
    const std::string short_line = sealed("TSOPT,5.2,N");
    const auto liberal = decode<optionals>(short_line);
    REQUIRE(liberal);
    CHECK_FALSE(liberal.value.heading);
    const auto strict = decode<optionals>(short_line, parse_policy::strict());
    CHECK(strict.ec == errc::too_few_fields);
    CHECK(strict.field == 3);
    // Fields declared droppable may still be left out under strict.
    CHECK(decode<optionals>(sealed("TSOPT,5.2,N,1,2"), parse_policy::strict()));
  }
  SECTION("wrong unit letter") {
    const auto d = decode<optionals>(sealed("TSOPT,5.2,K,1,1"));
    CHECK(d.ec == errc::bad_unit);
    CHECK(d.field == 2);
  }
  SECTION("half-open range") {
    CHECK(decode<optionals>(sealed("TSOPT,1,N,360,1")).ec == errc::out_of_range);
    CHECK(decode<optionals>(sealed("TSOPT,1,N,0,1")));
    CHECK(decode<optionals>(sealed("TSOPT,-1,N,0,1")).ec == errc::out_of_range);
  }
  SECTION("max places") {
    CHECK(decode<optionals>(sealed("TSOPT,1,N,0,1.25")).ec == errc::out_of_range);
  }
  SECTION("a field present only in the longer form") {
    const std::string six = sealed("TSOPT,1,N,2,7,3.5,tl");
    const auto d = decode<optionals>(six);
    REQUIRE(d);
    CHECK(*d.value.id == 7);
    CHECK(*d.value.level == decimal::scaled(35, 1));
    CHECK(*d.value.tail == "tl");
    CHECK(encode(d.value).view() == six);
    const std::string five = sealed("TSOPT,1,N,2,3.5,tl");
    const auto e = decode<optionals>(five);
    REQUIRE(e);
    CHECK_FALSE(e.value.id);
    CHECK(*e.value.level == decimal::scaled(35, 1));
    CHECK(encode(e.value).view() == five);
  }
  SECTION("the longer form with an extra trailing field is still the longer form") {
    const auto d = decode<optionals>(sealed("TSOPT,1,N,2,7,3.5,tl,extra"));
    REQUIRE(d);
    CHECK(*d.value.id == 7);
    CHECK(*d.value.level == decimal::scaled(35, 1));
  }
  SECTION("encode numbers fields as the form written has them") {
    optionals o;
    o.level = decimal::scaled(125, 2);  // max_places(1): refused
    const auto e = encode(o);
    CHECK(e.ec == errc::out_of_range);
    CHECK(e.field == 4);  // no id in the short form
    o.id = 3;
    CHECK(encode(o).field == 5);
  }
  SECTION("a blank tail is empty text, an absent one is nullopt") {
    const std::string blank = sealed("TSOPT,1,N,2,3,");
    const auto d = decode<optionals>(blank);
    REQUIRE(d);
    REQUIRE(d.value.tail);
    CHECK(d.value.tail->empty());
    CHECK(encode(d.value).view() == blank);
  }
}

TEST_CASE("encode refuses values outside their domain, naming the field") {
  all_types m;
  m.time = {12, 0, 0, 0, 0};
  m.day = {2024, 1, 1};
  m.lat = latitude::from_degrees(42.5).value;
  m.lon = longitude::from_degrees(-71.25).value;
  REQUIRE(encode(m));

  auto bad = m;
  bad.value = decimal{150};
  auto e = encode(bad);
  CHECK(e.ec == errc::out_of_range);
  CHECK(e.field == 7);
  CHECK(e.size == 0);

  bad = m;
  bad.time.hour = 24;
  CHECK(encode(bad).ec == errc::hour_out_of_range);
  CHECK(encode(bad).field == 1);

  bad = m;
  bad.day.day = 31;
  bad.day.month = 2;
  CHECK(encode(bad).ec == errc::day_out_of_range);

  bad = m;
  bad.day.year = 2080;  // not representable as yy in 1980..2079
  CHECK(encode(bad).ec == errc::out_of_range);

  bad = m;
  bad.lon.hemi = hemisphere::north;
  CHECK(encode(bad).ec == errc::bad_hemisphere);
  CHECK(encode(bad).field == 6);  // the letter, as decode says

  bad = m;
  bad.lat.minutes = decimal{60};
  CHECK(encode(bad).ec == errc::minute_out_of_range);

  bad = m;
  bad.state = static_cast<status>('Q');
  CHECK(encode(bad).ec == errc::bad_enum);
  CHECK(encode(bad).field == 10);

  for (char c : std::string_view("$,*!\\^~\x01")) {
    bad = m;
    const char s[2] = {c, 0};
    REQUIRE(bad.label.assign(s));
    INFO(int(c));
    CHECK(encode(bad).ec == errc::bad_text);
    CHECK(encode(bad).field == 12);
  }

  CHECK(encode<16>(m).ec == errc::buffer_too_small);
}

TEST_CASE("positions from decimal degrees") {
  auto lat = latitude::from_degrees(-33.8568, 4);
  REQUIRE(lat);
  CHECK(lat.value.whole_degrees == 33);
  CHECK(lat.value.minutes == decimal::scaled(514080, 4));
  CHECK(lat.value.hemi == hemisphere::south);
  // 59.99999 minutes rounds up into the next degree.
  auto lon = longitude::from_degrees(10.9999999999, 3);
  REQUIRE(lon);
  CHECK(lon.value.whole_degrees == 11);
  CHECK(lon.value.minutes.mantissa == 0);
  CHECK(latitude::from_degrees(90.0001).ec == errc::out_of_range);
  CHECK(longitude::from_degrees(180.0).value.whole_degrees == 180);
  CHECK(longitude::from_degrees(std::nan("")).ec == errc::not_finite);
  auto dl = decimal_latitude::from_degrees(-21.311984, 5);
  REQUIRE(dl);
  CHECK(dl.value.value == decimal::scaled(2131198, 5));
  CHECK(dl.value.hemi == hemisphere::south);
}

TEST_CASE("time of day from a duration, truncated") {
  using namespace std::chrono;
  const auto t = time_of_day::from_since_midnight(hours(23) + minutes(59) + seconds(59) +
                                                  nanoseconds(999'999'999));
  REQUIRE(t);
  CHECK((t.value.hour == 23 && t.value.minute == 59 && t.value.second == 59));
  CHECK((t.value.fraction == 999 && t.value.places == 3));
  CHECK(t.value.fraction_ns() == 999'000'000);
  CHECK(t.value.since_midnight() == hours(23) + minutes(59) + seconds(59) + milliseconds(999));
  CHECK(time_of_day::from_since_midnight(hours(24)).ec == errc::out_of_range);
  CHECK(time_of_day::from_since_midnight(-nanoseconds(1)).ec == errc::out_of_range);
}

TEST_CASE("round trip over generated values") {
  std::mt19937_64 rng(20261121);
  auto pick = [&](std::uint64_t n) { return rng() % n; };
  for (int i = 0; i < 2000; ++i) {
    all_types m;
    m.time = {static_cast<std::uint8_t>(pick(24)), static_cast<std::uint8_t>(pick(60)),
              static_cast<std::uint8_t>(pick(60)), 0, static_cast<std::uint8_t>(pick(10))};
    m.time.fraction = static_cast<std::uint32_t>(pick(seawire::detail::pow10_table[m.time.places]));
    m.day = {static_cast<std::uint16_t>(1980 + pick(100)), static_cast<std::uint8_t>(1 + pick(12)),
             static_cast<std::uint8_t>(1 + pick(28))};
    m.lat = latitude::from_degrees(static_cast<double>(pick(180'000'000)) / 1e6 - 90.0,
                                   static_cast<unsigned>(1 + pick(6)))
                .value;
    m.lon = longitude::from_degrees(static_cast<double>(pick(360'000'000)) / 1e6 - 180.0,
                                    static_cast<unsigned>(1 + pick(6)))
                .value;
    m.value = decimal::scaled(static_cast<std::int64_t>(pick(200'001)) - 100'000, 3);
    m.count = static_cast<std::int16_t>(static_cast<int>(pick(65536)) - 32768);
    m.flag = pick(2) == 1;
    m.state = pick(2) ? status::valid : status::invalid;
    m.power = pick(2) ? switch_state::on : switch_state::off;
    m.label = "x y";
    const auto e = encode(m);
    REQUIRE(e);
    const auto d = decode<all_types>(e.view(), parse_policy::strict());
    INFO(e.view());
    REQUIRE(d);
    CHECK(encode(d.value).view() == e.view());
    CHECK(d.value.lat == m.lat);
    CHECK(d.value.lon == m.lon);
    CHECK(d.value.time == m.time);
    CHECK(d.value.day == m.day);
    CHECK(d.value.value == m.value);
    CHECK(d.value.count == m.count);
  }
}

TEST_CASE("dispatch by address: variant, visitor, unknown sentences") {
  using set = message_set<all_types, optionals>;
  STATIC_REQUIRE(set::knows("TSOPT"));
  STATIC_REQUIRE_FALSE(set::knows("TSXXX"));
  auto r = set::decode(sealed("TSOPT,1,N,2,3"));
  REQUIRE(r);
  CHECK(std::holds_alternative<optionals>(r.value));
  const std::string unknown = sealed("TSXXX,1,2");
  r = set::decode(unknown);
  REQUIRE(r);
  REQUIRE(std::holds_alternative<unknown_sentence>(r.value));
  CHECK(std::get<unknown_sentence>(r.value).sentence.address == "TSXXX");
  r = set::decode(sealed("TSOPT,1,X,2,3"));
  CHECK(r.ec == errc::bad_unit);
  CHECK(r.field == 2);
  CHECK(set::field_name("TSOPT", 2) == "speed");
  CHECK(set::field_name("TSOPT", 3) == "heading");

  int seen = 0;
  const std::string line = sealed("TSOPT,1,N,2,3");
  const auto s = parse(line);
  REQUIRE(s);
  const auto v = set::visit(s.value, {}, [&](const auto& msg) {
    if constexpr (std::is_same_v<std::decay_t<decltype(msg)>, optionals>) seen = 1;
  });
  CHECK(v);
  CHECK(seen == 1);
}

TEST_CASE("from_double rounds to nearest without the x + 0.5 trap") {
  // Found by clang-tidy (bugprone-incorrect-roundings): static_cast(x + 0.5) rounds the sum
  // first, so a value just below one half went up, and an odd integer past 2^52 became even.
  CHECK(decimal::from_double(0.49999999999999994, 0).value.mantissa == 0);
  CHECK(decimal::from_double(4503599627370497.0, 0).value.mantissa == 4503599627370497ULL);
  CHECK(decimal::from_double(-4503599627370497.0, 0).value.mantissa == 4503599627370497ULL);
  CHECK(decimal::from_double(2.5, 0).value.mantissa == 3);  // halves still go up
  CHECK(decimal::from_double(0.125, 2).value == decimal::scaled(13, 2));
  CHECK(latitude::from_degrees(0.49999999999999994 / 60.0, 1).value.minutes ==
        decimal::scaled(5, 1));
}

TEST_CASE("for_each_field gives declared names in wire order") {
  optionals o;
  std::string names;
  for_each_field(o, [&](std::string_view name, const auto&) {
    names += name;
    names += ' ';
  });
  CHECK(names == "speed heading id level tail ");
}

TEST_CASE("time_of_day and date from system_clock time points and back") {
  using namespace std::chrono;
  // 2014-12-31 16:49:59.980123456 UTC
  const sys_time<nanoseconds> t =
      sys_days{2014y / December / 31} + 16h + 49min + 59s + 980ms + 123us + 456ns;
  const auto tod = time_of_day::from(t);
  REQUIRE(tod);
  CHECK(tod.value == time_of_day{16, 49, 59, 980, 3});  // truncated to 3 places
  CHECK(time_of_day::from(t, 9).value == time_of_day{16, 49, 59, 980123456, 9});
  CHECK(time_of_day::from(t, 0).value == time_of_day{16, 49, 59});
  CHECK(time_of_day::from(t, 10).ec == errc::out_of_range);
  CHECK(date::from(t) == date{2014, 12, 31});
  CHECK(to_sys_time(date::from(t), time_of_day::from(t, 9).value) == t);
  CHECK(to_sys_time(date{2014, 12, 31}, time_of_day{16, 49, 59, 980, 3}) ==
        time_point_cast<nanoseconds>(t - 123us - 456ns));
  // Before 1970, and the clock's own now() at its coarser resolution.
  const auto old = sys_days{1969y / July / 20} + 20h + 17min + 40s;
  CHECK(time_of_day::from(old).value == time_of_day{20, 17, 40, 0, 3});
  CHECK(date::from(old) == date{1969, 7, 20});
  const auto now = system_clock::now();
  const auto back = to_sys_time(date::from(now), time_of_day::from(now, 9).value);
  CHECK(back == time_point_cast<nanoseconds>(now));
  // A leap second has no system_clock time of its own: it is the next day's first second.
  CHECK(to_sys_time(date{2016, 12, 31}, time_of_day{23, 59, 60}) == sys_days{2017y / January / 1});
  CHECK(date{2014, 12, 31}.sys_days() == sys_days{2014y / December / 31});
}

TEST_CASE("calendar: days since 1970 and back, month lengths, the ISO date's form") {
  using seawire::detail::civil_date;
  using seawire::detail::civil_from_days;
  using seawire::detail::days_from_civil;
  CHECK(days_from_civil({1970, 1, 1}) == 0);
  CHECK(days_from_civil({2024, 7, 3}) == 19907);
  CHECK(days_from_civil({1969, 12, 31}) == -1);
  CHECK(days_from_civil({2000, 3, 1}) == 11017);
  CHECK(days_from_civil({2149, 6, 3}) == 65532);  // the last a day_count carries as a value
  // Every day from 1600 to 2400 (leap centuries and not) reads back as itself, one after another.
  std::int64_t prev = days_from_civil({1599, 12, 31});
  for (std::int64_t y = 1600; y <= 2400; ++y) {
    for (unsigned m = 1; m <= 12; ++m) {
      const unsigned last = seawire::detail::days_in_month(m, y);
      CHECK_FALSE(seawire::detail::valid_date({y, m, last + 1}));
      for (unsigned d = 1; d <= last; ++d) {
        const std::int64_t n = days_from_civil({y, m, d});
        REQUIRE(n == prev + 1);
        const civil_date c = civil_from_days(n);
        REQUIRE((c.year == y && c.month == m && c.day == d));
        prev = n;
      }
    }
  }
  CHECK(seawire::detail::days_in_month(2, 1900) == 28);
  CHECK(seawire::detail::days_in_month(2, 2000) == 29);
  CHECK(seawire::detail::days_in_month(2, 2024) == 29);
  CHECK_FALSE(seawire::detail::valid_date({2024, 13, 1}));
  CHECK_FALSE(seawire::detail::valid_date({2024, 0, 1}));
  CHECK_FALSE(seawire::detail::valid_date({2024, 1, 0}));

  civil_date c;
  CHECK(seawire::detail::parse_iso_date("2018-12-10T12:00:00", c));
  CHECK((c.year == 2018 && c.month == 12 && c.day == 10));
  CHECK(
      seawire::detail::parse_iso_date("0000-99-99", c));  // the form only: ranges are the caller's
  CHECK((c.year == 0 && c.month == 99 && c.day == 99));
  CHECK_FALSE(seawire::detail::parse_iso_date("2018-12-1", c));
  CHECK_FALSE(seawire::detail::parse_iso_date("2018/12/10", c));
  CHECK_FALSE(seawire::detail::parse_iso_date("20x8-12-10", c));
  CHECK_FALSE(seawire::detail::parse_iso_date("2018-1a-10", c));
  CHECK_FALSE(seawire::detail::parse_iso_date("+018-12-10", c));
}
