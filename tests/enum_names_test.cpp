// SPDX-License-Identifier: BSL-1.0
// Enumerator names as the compiler spells them (detail/enum_names.hpp), and the name() functions
// built on them: every value of each enum named as declared, a stray value told apart.

#include <catch2/catch.hpp>
#include <cstdint>
#include <string_view>

#include "seawire/detail/enum_names.hpp"
#include "seawire/seawire.hpp"

namespace {
using namespace seawire;
using seawire::detail::enumerator_name;
using seawire::detail::enumerator_names;

namespace outer::inner {
enum class colour : std::uint8_t { red, green_blue, x9 };
enum plain { first, second };
}  // namespace outer::inner

static_assert(enumerator_name<outer::inner::colour::green_blue>() == "green_blue");
static_assert(enumerator_name<outer::inner::colour::x9>() == "x9");
static_assert(enumerator_name<outer::inner::second>() == "second");
static_assert(enumerator_name<static_cast<outer::inner::colour>(3)>().empty());
static_assert(enumerator_name<static_cast<outer::inner::colour>(200)>().empty());
static_assert(enumerator_names<outer::inner::colour, 3>[0] == "red");
static_assert(seawire::detail::enumerator_name_of<3>(static_cast<outer::inner::colour>(7)) ==
              "unknown");
static_assert(seawire::detail::enumerator_name_of<3>(static_cast<outer::inner::colour>(7), "?") ==
              "?");
}  // namespace

TEST_CASE("enum names: each enum's name() gives the enumerator as declared") {
  CHECK(name(nmea::drop_reason::invalid_byte) == "invalid_byte");
  CHECK(name(static_cast<nmea::drop_reason>(250)) == "unknown");
  CHECK(name(nmea2000::field_state::out_of_range) == "out_of_range");
  CHECK(name(static_cast<nmea2000::field_state>(4)) == "unknown");
  CHECK(name(nmea2000::fast_packet_drop::too_long) == "too_long");
  CHECK(name(nmea2000::log_format::yd_raw) == "yd_raw");
  CHECK(name(robotx::rule::checksum_lowercase) == "checksum_lowercase");
  CHECK(name(static_cast<robotx::rule>(robotx::rule_count)) == "unknown_rule");
  CHECK(name(sandshark::payload_event_kind::ack_timeout) == "ack_timeout");
  CHECK(name(static_cast<sandshark::vehicle_event_kind>(99)) == "unknown_event");
  // The table is the whole enum: as many names as the count, none empty, none repeated.
  const auto& rules = enumerator_names<robotx::rule, robotx::rule_count>;
  for (std::size_t i = 0; i < rules.size(); ++i) {
    CHECK_FALSE(rules[i].empty());
    for (std::size_t j = 0; j < i; ++j) CHECK(rules[i] != rules[j]);
  }
  CHECK(rules.front() == "framing");
}

namespace named::scope {
enum class mode : std::int8_t { minus = -1, zero, one };
}  // namespace named::scope
static_assert(seawire::detail::enumerator_name<named::scope::mode::minus>() == "minus");
static_assert(seawire::detail::enumerator_name<named::scope::mode::one>() == "one");
static_assert(seawire::detail::enumerator_name<static_cast<named::scope::mode>(-2)>().empty());
static_assert(seawire::detail::enumerator_name<static_cast<named::scope::mode>(5)>().empty());
