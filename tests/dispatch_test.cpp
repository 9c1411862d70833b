// SPDX-License-Identifier: BSL-1.0
// merge_sets: the union of message sets, each message once.

#include <catch2/catch.hpp>
#include <string_view>
#include <type_traits>
#include <variant>

#include "seawire/nmea/dispatch.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/rmc.hpp"
#include "seawire/standard/vhw.hpp"

using namespace seawire;
using namespace seawire::nmea;
using standard::gga;
using standard::rmc;
using standard::vhw;

namespace {
// A message of this test's own, to have a third distinct type.
struct ping {
  std::uint16_t n = 0;
  static constexpr auto nmea = sentence<"XXPNG">(field<&ping::n>("n"));
};
}  // namespace

// Disjoint sets are concatenated in order.
static_assert(std::is_same_v<merge_sets<message_set<rmc>, message_set<gga, ping>>::type,
                             message_set<rmc, gga, ping>>);
// A message in several sets appears once, at its first place.
static_assert(std::is_same_v<merge_sets<message_set<rmc, gga>, message_set<vhw, rmc>,
                                        message_set<gga, ping, rmc>>::type,
                             message_set<rmc, gga, vhw, ping>>);
// A single set is itself, minus repeats.
static_assert(std::is_same_v<merge_sets<message_set<rmc, gga>>::type, message_set<rmc, gga>>);
static_assert(std::is_same_v<merge_sets<message_set<rmc, rmc>>::type, message_set<rmc>>);

TEST_CASE("a merged set with shared messages decodes into its variant") {
  using all = merge_sets<message_set<rmc, gga>, message_set<ping, rmc>>::type;
  STATIC_REQUIRE(all::size == 3);
  const auto r = all::decode(
      std::string_view("$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70"));
  REQUIRE(r);
  REQUIRE(std::holds_alternative<rmc>(r.value));
  CHECK(std::get<rmc>(r.value).talker == "GP");
  const auto p = all::decode(std::string_view("$XXPNG,7"));
  REQUIRE(p);
  REQUIRE(std::holds_alternative<ping>(p.value));
  CHECK(std::get<ping>(p.value).n == 7);
}
