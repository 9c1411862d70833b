// SPDX-License-Identifier: BSL-1.0
// NMEA 2000 lookups beyond a plain enumeration, checked against expectations written here by
// hand: a lookup that names raw values among its top (sentinel) values, a lookup whose names
// depend on another field (keyed_lookup), a number without sentinels, spare bits; through
// decode, encode, the walk's JSON and CSV writers and the JSON reader.

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>

#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/json.hpp"

namespace n2k = seawire::nmea2000;
using n2k::field_state;
using seawire::errc;

namespace lookups_test {

// A 2-bit lookup naming raw 2, as a gear's reverse: 2 is a value, 3 still "not available".
enum class gear : std::uint8_t { ahead = 0, idle = 1, astern = 2 };
constexpr std::array<std::string_view, 3> lookup_names(gear) noexcept {
  return {"ahead", "idle", "astern"};
}

// A 3-bit lookup naming 6 but not 5: 5 stays reserved, 6 is a value, 7 not available.
enum class mode : std::uint8_t { first = 0, sixth = 6 };
constexpr std::array<std::string_view, 7> lookup_names(mode) noexcept {
  return {"first", "", "", "", "", "", "sixth"};
}

// A 2-bit lookup naming every raw value: none is "not available".
enum class quarter : std::uint8_t { q0, q1, q2, q3 };
constexpr std::array<std::string_view, 4> lookup_names(quarter) noexcept {
  return {"q0", "q1", "q2", "q3"};
}

// Names keyed by (kind, value): value 5 is "cat" of kind 1 but "eel" of kind 2.
struct pet_names {
  static constexpr std::array<n2k::keyed_name, 5> entries{{
      {1, 5, "cat", "Cat"},
      {1, 7, "dog", "Dog"},
      {2, 5, "eel", "Eel"},
      {2, 252, "emu", "Emu"},
      {9, 0, "ant", "Ant"},
  }};
};

// A PGN of the test's own: the keyed field before its key, a no-sentinel number, spare bits.
struct pets {
  n2k::keyed_lookup<pet_names, 8> pet;
  n2k::unsigned_number<4> kind;
  n2k::lookup<gear, 2> gear_state;
  n2k::lookup<mode, 3> mode_state;
  n2k::lookup<quarter, 2> quarter_state;
  n2k::unsigned_no_sentinel<3> instance;

  static constexpr auto n2k =
      n2k::describe_pgn(n2k::pgn_info{65300, "pets", "Pets", 6, n2k::framing::single_frame, 0},
                        n2k::keyed_field<&pets::pet, &pets::kind>("pet", "Pet"),
                        n2k::field<&pets::kind>("kind", "Kind"), n2k::spare<4>,
                        n2k::field<&pets::gear_state>("gear_state", "Gear"),
                        n2k::field<&pets::mode_state>("mode_state", "Mode"),
                        n2k::field<&pets::quarter_state>("quarter_state", "Quarter"),
                        n2k::field<&pets::instance>("instance", "Instance"), n2k::reserved<6>);
  [[nodiscard]] constexpr bool operator==(const pets&) const noexcept = default;
};

}  // namespace lookups_test

namespace {

using lookups_test::pets;

std::string json_of(const pets& m) {
  seawire::nmea::json_buffer<512> b;
  n2k::write_json(b, m);
  REQUIRE_FALSE(b.overflow());
  return std::string(b.view());
}

template <class T>
std::string value_json(const T& v) {
  seawire::nmea::json_buffer<64> b;
  n2k::write_json_value(b, v);
  return std::string(b.view());
}

template <class L>
concept offers_not_available = requires {
  L::not_available();
};

using members = std::map<std::string, seawire::nmea::json_value>;

seawire::nmea::json_value num(std::string_view t) { return {n2k::json_kind::number, t}; }
seawire::nmea::json_value str(std::string_view t) { return {n2k::json_kind::string, t}; }

/// pets from JSON members `m`; the two fields that cannot be left out (quarter_state, every raw
/// value named, and instance, no sentinel) are q0 and 0 unless `m` has them (or `all` is false).
seawire::result<pets> read(members m, bool all = true) {
  if (all) {
    m.try_emplace("quarter_state", str("q0"));
    m.try_emplace("instance", num("0"));
  }
  return n2k::read_json<pets>([&](std::string_view o, std::string_view k) {
    const auto it = m.find(std::string(k));
    return o.empty() && it != m.end() ? it->second : seawire::nmea::json_value{};
  });
}

}  // namespace

TEST_CASE("lookups: a raw value the lookup names is a value, even among the top ones") {
  using G = n2k::lookup<lookups_test::gear, 2>;
  using M = n2k::lookup<lookups_test::mode, 3>;
  using Q = n2k::lookup<lookups_test::quarter, 2>;
  // raw -> (state, name), worked out from the rule: named = value; else the top values of 2
  // bits are out_of_range, not_available; of 3 bits reserved, out_of_range, not_available.
  const std::array<std::pair<field_state, std::string_view>, 4> g{
      {{field_state::value, "ahead"},
       {field_state::value, "idle"},
       {field_state::value, "astern"},
       {field_state::not_available, ""}}};
  for (std::int64_t raw = 0; raw < 4; ++raw) {
    INFO("gear raw " << raw);
    const auto [st, name] = g[static_cast<std::size_t>(raw)];
    CHECK(G::from_raw(raw).state() == st);
    CHECK(G::from_raw(raw).name() == name);
    CHECK(G::is_value(raw) == (st == field_state::value));
  }
  const std::array<std::pair<field_state, std::string_view>, 8> m{
      {{field_state::value, "first"},
       {field_state::value, ""},
       {field_state::value, ""},
       {field_state::value, ""},
       {field_state::value, ""},
       {field_state::reserved, ""},
       {field_state::value, "sixth"},
       {field_state::not_available, ""}}};
  for (std::int64_t raw = 0; raw < 8; ++raw) {
    INFO("mode raw " << raw);
    const auto [st, name] = m[static_cast<std::size_t>(raw)];
    CHECK(M::from_raw(raw).state() == st);
    CHECK(M::from_raw(raw).name() == name);
  }
  CHECK(M::from_raw(6).value() == lookups_test::mode::sixth);
  CHECK_FALSE(M::from_raw(5).value());
  for (std::int64_t raw = 0; raw < 4; ++raw) CHECK(Q::from_raw(raw).has_value());
  // a lookup every raw value of which is named has no "not available" to offer
  STATIC_REQUIRE(offers_not_available<G>);
  STATIC_REQUIRE_FALSE(offers_not_available<Q>);
  CHECK(G::not_available().raw() == 3);
  // out of the field: no value
  CHECK_FALSE(G::from_raw(4).fits());
  CHECK_FALSE(G::is_value(4));
  CHECK_FALSE(G::is_value(-1));

  // JSON: the name of a named top value, null / the state of an unnamed one
  CHECK(value_json(G::from_raw(2)) == R"("astern")");
  CHECK(value_json(G::from_raw(3)) == "null");
  CHECK(value_json(M::from_raw(5)) == R"("reserved")");
  CHECK(value_json(M::from_raw(6)) == R"("sixth")");
  CHECK(value_json(M::from_raw(4)) == "4");
  CHECK(value_json(Q::from_raw(3)) == R"("q3")");
}

TEST_CASE("lookups: the JSON reader takes a named top value by name or number, never as a state") {
  members m{
      {"gear_state", str("astern")}, {"mode_state", str("sixth")}, {"quarter_state", str("q3")}};
  auto r = read(m);
  REQUIRE(r);
  CHECK(r.value.gear_state.raw() == 2);
  CHECK(r.value.mode_state.raw() == 6);
  CHECK(r.value.quarter_state.raw() == 3);
  m = {{"gear_state", num("2")}, {"mode_state", num("6")}, {"quarter_state", str("3")}};
  r = read(m);
  REQUIRE(r);
  CHECK(r.value.gear_state.raw() == 2);
  CHECK(r.value.mode_state.raw() == 6);
  CHECK(r.value.quarter_state.raw() == 3);
  // the unnamed top values: by state, not by number
  m = {{"mode_state", str("reserved")}};
  r = read(m);
  REQUIRE(r);
  CHECK(r.value.mode_state.raw() == 5);
  CHECK(r.value.gear_state.raw() == 3);  // absent: not available
  for (const auto& [key, v] :
       std::initializer_list<std::pair<std::string, seawire::nmea::json_value>>{
           {"gear_state", str("out_of_range")},  // 2 is astern: no out_of_range in this field
           {"gear_state", num("3")},             // 3 is not available, no value
           {"mode_state", num("5")},
           {"quarter_state", num("4")}}) {
    INFO(key << " " << v.text);
    const auto bad = read(members{{key, v}});
    CHECK(bad.ec == errc::out_of_range);
    CHECK(n2k::field_name<pets>(bad.field) == key);
  }
  // a field that has no "not available" cannot be left out: null or absent is refused
  auto missing = read(members{{"quarter_state", {n2k::json_kind::null, "null"}}});
  CHECK(missing.ec == errc::missing_field);
  CHECK(n2k::field_name<pets>(missing.field) == "quarter_state");
  CHECK(read(members{{"quarter_state", str("not_available")}}).ec == errc::missing_field);
  missing = read(members{{"instance", num("1")}}, false);
  CHECK(missing.ec == errc::missing_field);
  CHECK(n2k::field_name<pets>(missing.field) == "quarter_state");
  missing = read(members{{"quarter_state", str("q2")}}, false);
  CHECK(missing.ec == errc::missing_field);
  CHECK(n2k::field_name<pets>(missing.field) == "instance");
}

TEST_CASE("lookups: a keyed lookup names a value by its key, in O(log n), constexpr") {
  using K = n2k::keyed_lookup<lookups_test::pet_names, 8>;
  STATIC_REQUIRE(K::from_raw(5).name(1) == "cat");
  STATIC_REQUIRE(K::from_raw(5).name(2) == "eel");
  STATIC_REQUIRE(K::from_raw(5).title(2) == "Eel");
  // every (key, value) pair against the table read by hand
  const std::map<std::pair<int, int>, std::string_view> by_hand{
      {{1, 5}, "cat"}, {{1, 7}, "dog"}, {{2, 5}, "eel"}, {{2, 252}, "emu"}, {{9, 0}, "ant"}};
  for (int key = 0; key < 16; ++key) {
    for (int value = 0; value < 256; ++value) {
      const auto it = by_hand.find({key, value});
      const std::string_view want = it == by_hand.end() || value > 252 ? "" : it->second;
      if (K::from_raw(value).name(key) != want) FAIL("key " << key << " value " << value);
    }
  }
  // the top three raw values are sentinels whatever the key
  CHECK(K::from_raw(252).state() == field_state::value);
  CHECK(K::from_raw(253).state() == field_state::reserved);
  CHECK(K::from_raw(254).state() == field_state::out_of_range);
  CHECK(K::not_available().raw() == 255);
  CHECK(K::from_raw(255).name(1).empty());
  // names back
  CHECK(K::from_name(2, "eel").value.raw() == 5);
  CHECK(K::from_name(1, "eel").ec == errc::bad_enum);
  // a table out of order, a pair or a name twice in a key, is refused at compile time
  STATIC_REQUIRE(n2k::detail::keyed_table_valid(lookups_test::pet_names::entries));
  constexpr std::array<n2k::keyed_name, 2> unsorted{{{2, 1, "a", "A"}, {1, 9, "b", "B"}}};
  constexpr std::array<n2k::keyed_name, 2> twice{{{1, 1, "a", "A"}, {1, 1, "b", "B"}}};
  constexpr std::array<n2k::keyed_name, 2> same_name{{{1, 1, "a", "A"}, {1, 2, "a", "B"}}};
  constexpr std::array<n2k::keyed_name, 2> other_key{{{1, 1, "a", "A"}, {2, 1, "a", "A"}}};
  STATIC_REQUIRE_FALSE(n2k::detail::keyed_table_valid(unsorted));
  STATIC_REQUIRE_FALSE(n2k::detail::keyed_table_valid(twice));
  STATIC_REQUIRE_FALSE(n2k::detail::keyed_table_valid(same_name));
  STATIC_REQUIRE(n2k::detail::keyed_table_valid(other_key));
}

TEST_CASE("lookups: writers name a keyed field by the key the message holds") {
  pets m;
  m.pet = decltype(m.pet)::from_raw(5);
  m.kind = decltype(m.kind)::from_raw(1);
  CHECK(json_of(m).find(R"("pet":"cat","kind":1,)") != std::string::npos);
  m.kind = decltype(m.kind)::from_raw(2);
  CHECK(json_of(m).find(R"("pet":"eel","kind":2,)") != std::string::npos);
  m.kind = decltype(m.kind)::from_raw(3);  // a pair the table does not name: the number
  CHECK(json_of(m).find(R"("pet":5,"kind":3,)") != std::string::npos);
  m.kind = decltype(m.kind)::from_raw(15);  // the key not available: the number
  CHECK(json_of(m).find(R"("pet":5,"kind":null,)") != std::string::npos);
  m.kind = decltype(m.kind)::from_raw(14);  // the key out of range: the number
  CHECK(json_of(m).find(R"("pet":5,"kind":"out_of_range",)") != std::string::npos);
  m.pet = decltype(m.pet)::from_raw(254);
  CHECK(json_of(m).find(R"("pet":"out_of_range")") != std::string::npos);
  m.pet = decltype(m.pet)::not_available();
  CHECK(json_of(m).find(R"("pet":null)") != std::string::npos);
  // the member alone, without its key, as its number
  CHECK(value_json(decltype(m.pet)::from_raw(5)) == "5");

  // CSV (plain text) through the same walk
  m.pet = decltype(m.pet)::from_raw(0);
  m.kind = decltype(m.kind)::from_raw(9);
  seawire::nmea::json_buffer<256> csv;
  n2k::write_csv(csv, n2k::message_header{}, m);
  // gear and mode not available (empty cells); a default quarter is all ones, named q3, and a
  // default instance all ones, 7
  const std::string row(csv.view());
  CHECK(row.substr(row.find(",ant")) == ",ant,9,,,q3,7\n");
  seawire::nmea::json_buffer<256> head;
  n2k::write_csv_header<pets>(head);
  CHECK(std::string(head.view()) ==
        "time_s,prio,src,dst,pet,kind,gear_state,mode_state,quarter_state,instance\n");
}

TEST_CASE("lookups: the JSON reader names a keyed field by the key read with it") {
  // the key comes after the keyed field on the wire: read first all the same
  auto r = read(members{{"pet", str("eel")}, {"kind", num("2")}});
  REQUIRE(r);
  CHECK(r.value.pet.raw() == 5);
  r = read(members{{"pet", str("dog")}, {"kind", num("1")}});
  REQUIRE(r);
  CHECK(r.value.pet.raw() == 7);
  r = read(members{{"pet", num("5")}, {"kind", num("3")}});  // a number: any key
  REQUIRE(r);
  CHECK(r.value.pet.raw() == 5);
  r = read(members{{"pet", str("200")}});
  REQUIRE(r);
  CHECK(r.value.pet.raw() == 200);
  r = read(members{{"pet", str("out_of_range")}});
  REQUIRE(r);
  CHECK(r.value.pet.raw() == 254);
  CHECK(read(members{}).value.pet.raw() == 255);
  // a name of another key, a name without a key, a number past the values
  auto bad = read(members{{"pet", str("eel")}, {"kind", num("1")}});
  CHECK(bad.ec == errc::bad_enum);
  CHECK(bad.field == 1);
  bad = read(members{{"pet", str("cat")}});
  CHECK(bad.ec == errc::bad_enum);
  bad = read(members{{"pet", num("253")}, {"kind", num("1")}});
  CHECK(bad.ec == errc::out_of_range);
  CHECK(bad.field == 1);
  // two bad fields: the first row's error, though the keyed field is read last
  bad = read(members{{"pet", str("zebra")}, {"kind", num("1")}, {"gear_state", str("up")}});
  CHECK(bad.ec == errc::bad_enum);
  CHECK(n2k::field_name<pets>(bad.field) == "pet");
  bad = read(members{{"pet", str("cat")}, {"kind", num("1")}, {"gear_state", str("up")}});
  CHECK(bad.ec == errc::bad_enum);
  CHECK(n2k::field_name<pets>(bad.field) == "gear_state");
}

TEST_CASE("lookups: a number without sentinels, spare bits sent as zeros") {
  using I = n2k::unsigned_no_sentinel<3>;
  for (std::int64_t raw = 0; raw < 8; ++raw) CHECK(I::from_raw(raw).state() == field_state::value);
  CHECK(I::from_raw(7).value() == 7.0);
  CHECK_FALSE(I::from_raw(8).fits());
  CHECK(I::from(7).ec == errc::ok);
  CHECK(I::from(8).ec == errc::out_of_range);
  // no state to read
  CHECK(read(members{{"instance", {n2k::json_kind::null, "null"}}}).ec == errc::missing_field);
  CHECK(read(members{{"instance", str("out_of_range")}}).ec == errc::out_of_range);
  CHECK(read(members{{"instance", num("8")}}).ec == errc::out_of_range);
  const auto seven = read(members{{"instance", num("7")}});
  REQUIRE(seven);
  CHECK(seven.value.instance.raw() == 7);

  // the layout: pet 0-7, kind 8-11, spare 12-15, gear 16-17, mode 18-20, quarter 21-22,
  // instance 23-25, reserved 26-31
  pets m;
  m.pet = decltype(m.pet)::from_raw(0x5A);
  m.kind = decltype(m.kind)::from_raw(2);
  m.gear_state = lookups_test::gear::astern;
  m.mode_state = lookups_test::mode::sixth;
  m.quarter_state = lookups_test::quarter::q1;
  m.instance = I::from_raw(7);
  const auto e = n2k::encode(m);
  REQUIRE(e);
  // byte 1: kind 2 | spare 0 << 4; byte 2: 2 | 6 << 2 | 1 << 5 | 7 << 7 (bit 7); byte 3: 7 >> 1
  // (bits 0-1) | reserved ones << 2
  const std::array<std::uint8_t, 4> want{0x5A, 0x02, 0xBA, 0xFF};
  CHECK(std::ranges::equal(e.value.view(), want));
  // received: the spare bits are ignored, whatever they hold
  const std::array<std::uint8_t, 4> ones{0x5A, 0xF2, 0xBA, 0xFF};
  CHECK(n2k::decode<pets>(ones) == m);
  const auto again = n2k::encode(n2k::decode<pets>(ones));
  REQUIRE(again);
  CHECK(std::ranges::equal(again.value.view(), want));
}
