// SPDX-License-Identifier: BSL-1.0
// What the PGN descriptions carry for canboat's JSON (seawire-decode --format canboat): the
// titles of every lookup and flag enum (lookup_titles, titled_enum, lookup_title), a number
// field's titles (field<&P::m, E>), and canboat's std unit of each field by its unit
// (canboat_std_unit). tools/decode/canboat_json_test.py checks the output against canboat's
// analyzer.

#include <array>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/canboat.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/registry.hpp"
#include "seawire/walk.hpp"

namespace n2k = seawire::nmea2000;
namespace registry = seawire::registry;

namespace {

// Every lookup and flag enum of a described PGN has titles, one for each name and none where it
// has none, and titles past the names only for sentinel values of the field.
template <class E, class V>
void check_titles(std::string_view where) {
  INFO(where);
  STATIC_REQUIRE(n2k::titled_enum<E>);
  const auto names = lookup_names(E{});
  const auto titles = lookup_titles(E{});
  REQUIRE(titles.size() >= names.size());
  for (std::size_t i = 0; i < titles.size(); ++i) {
    INFO(i);
    if (i < names.size()) {
      CHECK(names[i].empty() == titles[i].empty());
    } else if constexpr (requires { V::max_valid_raw; }) {
      CHECK(static_cast<std::int64_t>(i) > V::max_valid_raw);  // past the names: sentinels only
    } else {
      FAIL("a flag set's titles go past its names");
    }
    CHECK(n2k::lookup_title<E>(i) == titles[i]);
  }
  CHECK(n2k::lookup_title<E>(titles.size()).empty());
}

}  // namespace

TEST_CASE("every lookup and flag enum of a described PGN has canboat's titles") {
  std::size_t enums = 0;
  registry::for_each_type<registry::pgns>([&](auto tag) {
    using P = typename decltype(tag)::type;
    n2k::pgn_table<P>.for_each([&](const auto& f, unsigned, std::uint16_t) {
      using F = std::remove_cvref_t<decltype(f)>;
      if constexpr (!F::is_reserved) {
        using E = n2k::value_enum_t<typename F::value_type>;
        if constexpr (!std::is_void_v<E>) {
          check_titles<E, typename F::value_type>(f.name);
          ++enums;
        }
      }
    });
  });
  CHECK(enums >= 25);
}

TEST_CASE("lookup_title: canboat's texts by raw value") {
  CHECK(n2k::lookup_title<n2k::water_reference>(3) == "Correlation (ultra sound)");
  CHECK(n2k::lookup_title<n2k::temperature_source>(0) == "Sea Temperature");
  CHECK(n2k::lookup_title<n2k::engine_status_1>(15) == "Emergency Stop");
  CHECK(n2k::lookup_title<n2k::engine_status_2>(8).empty());  // bits 8-15 have none
  CHECK(n2k::lookup_title<n2k::wind_reference>(0) == "True (ground referenced to North)");
  // A 2-bit heading reference: raw 2 is out of range to seawire, "Error" to canboat; 3 nothing.
  CHECK(n2k::lookup_title<n2k::heading_reference>(2) == "Error");
  CHECK(n2k::lookup_title<n2k::heading_reference>(3).empty());
  CHECK(n2k::lookup<n2k::heading_reference, 2>::from_raw(2).state() ==
        n2k::field_state::out_of_range);
  CHECK(n2k::lookup_title<n2k::engine_instance>(1) == "Dual Engine Starboard");
  STATIC_REQUIRE(!n2k::named_enum<n2k::engine_instance>);  // titles only: the field is a number
}

TEST_CASE("a number field with titles: a number to seawire, titled for canboat") {
  using row = std::remove_cvref_t<decltype(seawire::detail::row_at<0>(
      n2k::pgn_table<n2k::engine_parameters_rapid>.fields))>;
  STATIC_REQUIRE(std::is_same_v<row::titles, n2k::engine_instance>);
  STATIC_REQUIRE(std::is_same_v<row::value_type, n2k::unsigned_number<8>>);
  STATIC_REQUIRE(row::bits == 8 && !row::is_reserved);
  // Decoded, encoded and written as the number it is.
  const std::array<std::uint8_t, 8> bytes{1, 0x7a, 0x0c, 0xff, 0xff, 0x7f, 0xff, 0xff};
  const auto m = n2k::decode<n2k::engine_parameters_rapid>(bytes);
  CHECK(m.instance.raw() == 1);
  const auto e = n2k::encode(m);
  REQUIRE(e.ec == seawire::errc::ok);
  CHECK(e.value == std::span<const std::uint8_t>(bytes));
  seawire::nmea::json_buffer<512> sink;
  n2k::write_json(sink, n2k::message_header{}, m);
  REQUIRE_FALSE(sink.overflow());
  const std::string json(sink.view());
  CHECK(json.find(R"("instance":1,)") != std::string::npos);
}

TEST_CASE("canboat_std_unit: canboat's std units by seawire's unit") {
  using n2k::canboat_display;
  using n2k::canboat_std_unit;
  CHECK(canboat_std_unit("rad", true) == n2k::canboat_unit{canboat_display::degrees, "deg", 1});
  CHECK(canboat_std_unit("rad", false) == n2k::canboat_unit{canboat_display::degrees, "deg", 1});
  CHECK(canboat_std_unit("radps", true) ==
        n2k::canboat_unit{canboat_display::degrees, "deg/s", -1});
  CHECK(canboat_std_unit("k", false) == n2k::canboat_unit{canboat_display::celsius, "C", -1});
  CHECK(canboat_std_unit("k", true) == n2k::canboat_unit{});  // a difference: kept in K
  CHECK(canboat_std_unit("pa", false) == n2k::canboat_unit{canboat_display::bar, "bar", 3});
  CHECK(canboat_std_unit("s", true) == n2k::canboat_unit{canboat_display::duration, "s", -1});
  CHECK(canboat_std_unit("deg", true) == n2k::canboat_unit{canboat_display::coordinate, "deg", 7});
  for (const std::string_view same : {"m", "mps", "v", "a", "pct", "rpm", "lph", "l", "ah", ""})
    CHECK(canboat_std_unit(same, false) == n2k::canboat_unit{});
}

namespace {
struct unit_counts {
  std::size_t degrees = 0, celsius = 0, bar = 0, durations = 0, coordinates = 0;
};
// The fields of M (a PGN, or a repeating group's repetition) by the display their unit has.
template <class M>
void count_units(unit_counts& c) {
  seawire::visit_layout<M>([&](auto layout) {
    using L = decltype(layout);
    using V = typename L::value_type;
    if constexpr (n2k::detail::is_group_value<V>) {
      count_units<typename V::item_type>(c);
    } else if constexpr (n2k::detail::is_opaque_bytes<V>) {
      // bytes: no unit
    } else {
      const n2k::canboat_unit u = n2k::canboat_std_unit(L::unit, V::is_signed);
      INFO(L::name);
      switch (u.display) {
        case n2k::canboat_display::degrees:
          CHECK((L::unit == "rad" || L::unit == "radps"));
          ++c.degrees;
          break;
        case n2k::canboat_display::celsius: ++c.celsius; break;
        case n2k::canboat_display::bar: ++c.bar; break;
        case n2k::canboat_display::duration: ++c.durations; break;
        case n2k::canboat_display::coordinate: ++c.coordinates; break;
        case n2k::canboat_display::number: CHECK(L::unit != "rad"); break;
      }
    }
  });
}
}  // namespace

TEST_CASE("every described field's unit has its canboat display") {
  // The fields whose unit canboat changes, found through the walk (into repeating groups too):
  // each one's display follows from its unit, whatever PGN it is in.
  unit_counts c;
  registry::for_each_type<registry::pgns>(
      [&](auto tag) { count_units<typename decltype(tag)::type>(c); });
  // 127250 (3), 127251, 127257 (3), 127258, 129026, 127245 (2), 130306, 129284 (2), 130577 (3)
  CHECK(c.degrees >= 17);     // at least: PGNs added later add theirs
  CHECK(c.celsius >= 8);      // 127489 (2), 130311, 130312 (2), 130316 (2), 127508
  CHECK(c.bar >= 6);          // 127488, 127489 (3), 130311, 130314
  CHECK(c.durations >= 3);    // engine hours, time remaining, local offset
  CHECK(c.coordinates >= 4);  // 129025 (2), 129284 (2)
}

TEST_CASE("PGN and field titles are canboat's names") {
  CHECK(n2k::pgn_table<n2k::speed_water_referenced>.info.title == "Speed");
  CHECK(seawire::detail::row_at<0>(n2k::pgn_table<n2k::speed_water_referenced>.fields).title ==
        "SID");
  CHECK(seawire::detail::row_at<6>(n2k::pgn_table<n2k::engine_parameters_dynamic>.fields).title ==
        "Total Engine hours");
  CHECK(seawire::detail::row_at<0>(n2k::pgn_table<n2k::distance_log>.fields).title == "Date");
  CHECK(n2k::field_name<n2k::cross_track_error>(2) == "xte_mode");  // json names unchanged
}
