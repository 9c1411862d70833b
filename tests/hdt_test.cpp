// SPDX-License-Identifier: BSL-1.0
// HDT, heading true. The literal vectors' checksums were computed for these tests and each line
// was parsed with pynmea2, which reads the same heading and letter.

#include <catch2/catch.hpp>

#include <string>
#include <string_view>
#include <variant>

#include "seawire/nmea/csv.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/registry.hpp"
#include "seawire/standard/hdt.hpp"

#include "support.hpp"

namespace {

using namespace support;

using namespace seawire;
using seawire::nmea::decimal;
using seawire::standard::hdt;

// Decoded strictly (as seawire sends: with CR LF), and encoded back to the same bytes.
bool canonical(std::string_view line) {
  const std::string sent = std::string(line) + "\r\n";
  const auto r = nmea::decode<hdt>(sent, nmea::parse_policy::strict());
  return r && nmea::encode(r.value).view() == sent;
}

}  // namespace

TEST_CASE("HDT: heading true from a gyrocompass and from GNSS compasses", "[hdt]") {
  struct vector {
    std::string_view line;
    std::string_view talker;
    decimal heading;
  };
  for (const vector& v : {vector{"$HEHDT,274.07,T*19", "HE", decimal::scaled(27407, 2)},
                          vector{"$GPHDT,123.456,T*32", "GP", decimal::scaled(123456, 3)},
                          vector{"$HCHDT,238.5,T*25", "HC", decimal::scaled(2385, 1)},
                          vector{"$HEHDT,0.0,T*2F", "HE", decimal::scaled(0, 1)},
                          vector{"$HEHDT,359.99,T*10", "HE", decimal::scaled(35999, 2)}}) {
    INFO(v.line);
    const auto r = nmea::decode<hdt>(v.line);
    REQUIRE(r);
    CHECK(r.value.talker == v.talker);
    REQUIRE(r.value.heading_true_deg);
    CHECK(*r.value.heading_true_deg == v.heading);
    CHECK(canonical(v.line));
  }
}

TEST_CASE("HDT: a compass without a heading sends it blank, the letter kept or blank", "[hdt]") {
  const auto with_letter = nmea::decode<hdt>("$HEHDT,,T*01");
  REQUIRE(with_letter);
  CHECK_FALSE(with_letter.value.heading_true_deg);
  CHECK(canonical("$HEHDT,,T*01"));
  const auto without = nmea::decode<hdt>("$HEHDT,,*55");
  REQUIRE(without);
  CHECK_FALSE(without.value.heading_true_deg);
  CHECK(canonical("$HEHDT,,*55"));
  // Built in code, the letter is written.
  CHECK(nmea::encode(hdt{}).view() == sealed("HEHDT,,T"));
  hdt h;
  h.talker = "GN";
  h.heading_true_deg = decimal(90);
  CHECK(nmea::encode(h).view() == sealed("GNHDT,90,T"));
}

TEST_CASE("HDT: malformed input, errc and field number", "[hdt]") {
  const bad_case cases[] = {
      {"HEHDT,274.07,M", errc::bad_unit, 2},  // a magnetic heading is HDG or HDM, not HDT
      {"HEHDT,274.07,t", errc::bad_unit, 2},
      {"HEHDT,,X", errc::bad_unit, 2},  // a wrong letter even without a value
      {"HEHDT,27x.07,T", errc::bad_number, 1},
      {"HEHDT,360.01,T", errc::out_of_range, 1},
      {"HEHDT,-0.5,T", errc::out_of_range, 1},
      {"HEHDT,274.07", errc::too_few_fields, 2},  // a value that lost its unit letter
      {"HEVHW,274.07,T", errc::wrong_address, 0},
  };
  for (const auto& c : cases) check_bad<hdt>(c);
  // A field past the letter: ignored by default (newer senders append fields), refused strictly.
  CHECK(nmea::decode<hdt>(sealed("HEHDT,274.07,T,")).ok());
  check_bad<hdt>({"HEHDT,274.07,T,", errc::too_many_fields, 3}, nmea::parse_policy::strict());
  hdt over;
  over.heading_true_deg = decimal::scaled(3605, 1);
  CHECK(nmea::encode(over).ec == errc::out_of_range);
}

TEST_CASE("HDT: in the registry, read by the standard sentences' policy", "[hdt]") {
  const auto r = registry::sentences::decode(std::string_view("$HEHDT,274.07,T*19"));
  REQUIRE(r);
  REQUIRE(std::holds_alternative<hdt>(r.value));
  CHECK(std::get<hdt>(r.value).heading_true_deg == decimal::scaled(27407, 2));
  CHECK(registry::standard_sentences::knows("HEHDT"));
  CHECK(registry::receiving_policy("HEHDT").checksum == registry::standard_nmea.policy.checksum);
}

TEST_CASE("HDT: a CSV row of one blank heading is a quoted empty cell, not an empty line",
          "[hdt][csv]") {
  support::string_sink header;
  nmea::write_csv_header<hdt>(header);
  CHECK(header.s == "heading_true_deg\n");
  const auto blank = nmea::decode<hdt>(std::string_view("$HEHDT,,T"));
  REQUIRE(blank);
  support::string_sink row;
  nmea::write_csv(row, blank.value);
  CHECK(row.s == "\"\"\n");
  const auto some = nmea::decode<hdt>(std::string_view("$HEHDT,274.07,T"));
  REQUIRE(some);
  support::string_sink full;
  nmea::write_csv(full, some.value);
  CHECK(full.s == "274.07\n");
}
