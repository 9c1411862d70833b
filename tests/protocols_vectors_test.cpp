// SPDX-License-Identifier: BSL-1.0
// Every verified vector of the protocol notes (tests/data/protocols_vectors.txt) through one
// decoder that knows every family: the vectors decode, and canonical ones re-encode byte for byte.

#include <catch2/catch.hpp>
#include <fstream>
#include <set>
#include <string>
#include <variant>

#include "seawire/anello/inputs.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/sandshark/messages.hpp"

using namespace seawire;

namespace {
using everything =
    nmea::merge_sets<kingfisher::from_vehicle, kingfisher::to_vehicle, sandshark::from_vehicle,
                     sandshark::to_vehicle, robotx::reports, anello::nmea_inputs>::type;
}  // namespace

TEST_CASE("every verified vector decodes as the notes say") {
  std::ifstream in(SEAWIRE_TEST_DATA_DIR "/protocols_vectors.txt");
  REQUIRE(in.good());
  std::string row;
  std::set<std::string> kinds;  // the expectations met: canonical, decodes, error names
  while (std::getline(in, row)) {
    if (row.empty() || row[0] == '#') continue;
    const auto space = row.find(' ');
    REQUIRE(space != std::string::npos);
    const std::string expect = row.substr(0, space);
    const std::string line = row.substr(space + 1) + "\r\n";
    INFO(line);
    const auto r = everything::decode(line);
    kinds.insert(expect == "canonical" || expect == "decodes" ? expect : "error");
    if (expect == "canonical" || expect == "decodes") {
      REQUIRE(r);
      REQUIRE_FALSE(std::holds_alternative<nmea::unknown_sentence>(r.value));
      std::visit(
          [&](const auto& msg) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(msg)>, nmea::unknown_sentence>) {
              const auto out = nmea::encode(msg);
              REQUIRE(out);
              if (expect == "canonical") {
                CHECK(out.view() == line);
              } else {
                // Non-canonical (lower-case checksum): the same values, written canonically.
                const auto again = nmea::decode<std::decay_t<decltype(msg)>>(
                    out.view(), nmea::parse_policy::strict());
                REQUIRE(again);
                CHECK(again.value == msg);
                CHECK(out.view().substr(0, out.view().find('*')) ==
                      std::string_view(line).substr(0, line.find('*')));
              }
            }
          },
          r.value);
    } else {
      CHECK(name(r.ec) == expect);
    }
  }
  // The file was read through, and it holds vectors of each kind (a row added needs no edit).
  CHECK(kinds == std::set<std::string>{"canonical", "decodes", "error"});
}
