// SPDX-License-Identifier: BSL-1.0
// NMEA 2000 lookups beyond a plain enumeration, checked against expectations written here by
// hand: a lookup that names raw values among its top (sentinel) values, a lookup whose names
// depend on another field (keyed_lookup), a number without sentinels, spare bits; through
// decode, encode, the walk's JSON and CSV writers and the JSON reader.

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/pgns.hpp"

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

// ---------------------------------------------------------------------------------------------
// The PGNs that use them: a capture from canboat's sample logs each (canboat's analyzer's reading
// in the comments), decoded field by field by hand from the layout, encoded back.

namespace {

template <n2k::pgn_like P, std::size_t N>
P decode_bytes(const std::array<std::uint8_t, N>& b) {
  return n2k::decode<P>(std::span<const std::uint8_t>(b));
}

template <n2k::pgn_like P, std::size_t N>
void check_sent(const P& m, const std::array<std::uint8_t, N>& want) {
  const auto e = n2k::encode(m);
  REQUIRE(e);
  CHECK(std::ranges::equal(e.value.view(), want));
  CHECK(n2k::decode<P>(e.value.view()) == m);
}

template <n2k::pgn_like P>
std::string pgn_json(const P& m) {
  seawire::nmea::json_buffer<2048> b;
  n2k::write_json(b, m);
  REQUIRE_FALSE(b.overflow());
  return std::string(b.view());
}

template <n2k::pgn_like P>
seawire::result<P> read_pgn(const members& m) {
  return n2k::read_json<P>([&](std::string_view o, std::string_view k) {
    const auto it = m.find(std::string(k));
    return o.empty() && it != m.end() ? it->second : seawire::nmea::json_value{};
  });
}

/// lookup_titles(E) has a text exactly where lookup_names(E) has a name.
template <class E>
void check_titles() {
  const auto names = lookup_names(E{});
  const auto titles = lookup_titles(E{});
  REQUIRE(names.size() == titles.size());
  for (std::size_t i = 0; i < names.size(); ++i) CHECK(names[i].empty() == titles[i].empty());
}

}  // namespace

TEST_CASE("60928 ISO Address Claim: the NAME's fields, the function named by the class") {
  STATIC_REQUIRE(n2k::pgn_table<n2k::iso_address_claim>.info.pgn == 60928);
  STATIC_REQUIRE(n2k::description_of<n2k::iso_address_claim>::length == 8);
  // dirona-actisense-serial.raw, src 41: unique 1620519, Maretron, instances 0, PC Gateway,
  // Internetwork device, system 0, Marine Industry, arbitrary address capable Yes
  const std::array<std::uint8_t, 8> wire{0x27, 0xBA, 0x38, 0x11, 0x00, 0x82, 0x32, 0xC0};
  const auto m = decode_bytes<n2k::iso_address_claim>(wire);
  CHECK(m.unique_number.raw() == 0x18BA27);  // bits 0-20
  CHECK(m.manufacturer_code.raw() == 137);   // bits 21-31: 0x1138BA27 >> 21
  CHECK(m.manufacturer_code.name() == "maretron");
  CHECK(m.device_instance_lower.raw() == 0);                 // byte 4 bits 0-2
  CHECK(m.device_instance_upper.raw() == 0);                 // byte 4 bits 3-7
  CHECK(m.device_function.raw() == 130);                     // byte 5
  CHECK(m.device_class == n2k::device_class::internetwork);  // byte 6 >> 1 = 25
  CHECK(m.device_function.name(25) == "pc_gateway");
  CHECK(m.device_function.title(25) == "PC Gateway");
  CHECK(m.system_instance.raw() == 0);                     // byte 7 bits 0-3
  CHECK(m.industry_group == n2k::industry_group::marine);  // byte 7 bits 4-6
  CHECK(m.arbitrary_address_capable == n2k::yes_no::yes);  // bit 63
  check_sent(m, wire);
  CHECK(pgn_json(m) ==
        R"({"type":"PGN60928","unique_number":1620519,"manufacturer_code":"maretron",)"
        R"("device_instance_lower":0,"device_instance_upper":0,"device_function":"pc_gateway",)"
        R"("device_class":"internetwork","system_instance":0,"industry_group":"marine",)"
        R"("arbitrary_address_capable":"yes"})");

  // the same function number in another class, in a class without names for it, in none
  auto other = m;
  other.device_class = n2k::device_class::safety;
  CHECK(pgn_json(other).find(
            R"("device_function":"emergency_position_indicating_radio_beacon_epirb")") !=
        std::string::npos);
  other.device_class = decltype(other.device_class)::from_raw(5);
  CHECK(pgn_json(other).find(R"("device_function":130,"device_class":5,)") != std::string::npos);
  other.device_class = decltype(other.device_class)::from_raw(126);  // out of range: no key
  CHECK(pgn_json(other).find(R"("device_function":130,"device_class":"out_of_range",)") !=
        std::string::npos);
  // named top values: class 125 and industry 5 are values; device instances all ones too
  other.device_class = n2k::device_class::entertainment;
  other.industry_group = n2k::industry_group::industrial;
  other.device_instance_lower = decltype(other.device_instance_lower)::from_raw(7);
  other.device_instance_upper = decltype(other.device_instance_upper)::from_raw(31);
  const std::string j = pgn_json(other);
  CHECK(j.find(R"("device_instance_lower":7,"device_instance_upper":31,)") != std::string::npos);
  CHECK(j.find(R"("device_function":"multimedia_player","device_class":"entertainment",)") !=
        std::string::npos);
  CHECK(j.find(R"("industry_group":"industrial")") != std::string::npos);
  const auto e = n2k::encode(other);
  REQUIRE(e);
  // byte 4: 7 | 31 << 3; byte 6: spare 0 | 125 << 1; byte 7: 0 | 5 << 4 | 1 << 7
  CHECK(e.value[4] == 0xFF);
  CHECK(e.value[6] == 0xFA);
  CHECK(e.value[7] == 0xD0);

  // read back: the function's name for the class given, wherever the class is
  members in{{"unique_number", num("1620519")},
             {"manufacturer_code", str("maretron")},
             {"device_instance_lower", num("0")},
             {"device_instance_upper", num("0")},
             {"device_function", str("pc_gateway")},
             {"device_class", str("internetwork")},
             {"system_instance", num("0")},
             {"industry_group", str("marine")},
             {"arbitrary_address_capable", str("yes")}};
  auto back = read_pgn<n2k::iso_address_claim>(in);
  REQUIRE(back);
  CHECK(back.value == m);
  in["device_class"] = str("safety");
  back = read_pgn<n2k::iso_address_claim>(in);
  CHECK(back.ec == errc::bad_enum);
  CHECK(n2k::field_name<n2k::iso_address_claim>(back.field) == "device_function");
  in["device_function"] = str("emergency_position_indicating_radio_beacon_epirb");
  back = read_pgn<n2k::iso_address_claim>(in);
  REQUIRE(back);
  CHECK(back.value.device_function.raw() == 130);
  in.erase("device_instance_upper");  // no sentinel: cannot be left out
  back = read_pgn<n2k::iso_address_claim>(in);
  CHECK(back.ec == errc::missing_field);
  CHECK(n2k::field_name<n2k::iso_address_claim>(back.field) == "device_instance_upper");
}

TEST_CASE("60928: the code tables") {
  check_titles<n2k::manufacturer_code>();
  check_titles<n2k::device_class>();
  check_titles<n2k::industry_group>();
  using M = n2k::lookup<n2k::manufacturer_code, 11>;
  CHECK(M::from_raw(137).name() == "maretron");
  CHECK(lookup_titles(n2k::manufacturer_code{})[1851] == "Raymarine");
  CHECK(M::from_raw(2000).name().empty());  // no manufacturer: the number
  CHECK(M::from_raw(2000).has_value());
  CHECK(M::from_raw(2045).state() == field_state::reserved);
  // every function belongs to a class that has a name, with a name and a text of its own
  for (const n2k::keyed_name& f : n2k::device_functions::entries) {
    INFO(f.key << " " << f.value);
    CHECK_FALSE(lookup_names(n2k::device_class{})[f.key].empty());
    CHECK(f.value <= 252);
  }
  using F = n2k::keyed_lookup<n2k::device_functions, 8>;
  CHECK(F::from_raw(130).name(10) == "diagnostic");
  CHECK(F::from_raw(140).name(10) == "bus_traffic_logger");
  CHECK(F::from_raw(130).name(60) == "bottom_depth");
  CHECK(F::from_raw(130).title(20) == "Emergency Position Indicating Radio Beacon (EPIRB)");
  CHECK(F::from_raw(99).name(60).empty());
}

TEST_CASE("126993 Heartbeat: controller state 2 (bus off) is named") {
  // raymarine-ev1.raw, src 1: 00:01:00.000, counter 155, Error Active, null, Operational
  const std::array<std::uint8_t, 8> wire{0x60, 0xEA, 0x9B, 0xCC, 0xFF, 0xFF, 0xFF, 0xFF};
  const auto m = decode_bytes<n2k::heartbeat>(wire);
  CHECK(m.data_transmit_offset_s.raw() == 60000);  // 0xEA60 at 0.001 s
  CHECK(m.sequence_counter.raw() == 155);
  CHECK(m.controller_1_state == n2k::controller_state::error_active);  // byte 3 bits 0-1: 0
  CHECK(m.controller_2_state.state() == field_state::not_available);   // bits 2-3: 3
  CHECK(m.equipment_status == n2k::equipment_status::operational);     // bits 4-5: 0
  check_sent(m, wire);
  auto off = m;
  off.controller_1_state = n2k::controller_state::bus_off;
  off.equipment_status = decltype(off.equipment_status)::from_raw(2);
  CHECK(pgn_json(off).find(R"("controller_1_state":"bus_off","controller_2_state":null,)"
                           R"("equipment_status":"out_of_range")") != std::string::npos);
  CHECK(n2k::encode(off).value[3] == (2 | 3 << 2 | 2 << 4 | 0xC0));
  check_titles<n2k::controller_state>();
  check_titles<n2k::equipment_status>();
}

TEST_CASE("127237 Heading/Track control: steering mode 5 (track control) is named") {
  // sample-single.raw.txt: all not available but heading reference True and track 0
  const std::array<std::uint8_t, 21> wire{0xFF, 0x3F, 0xFF, 0xFF, 0x7F, 0xFF, 0xFF,
                                          0x00, 0x00, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
                                          0x7F, 0xFF, 0x7F, 0xFF, 0x7F, 0xFF, 0xFF};
  const auto m = decode_bytes<n2k::heading_track_control>(wire);
  CHECK(m.rudder_limit_exceeded.state() == field_state::not_available);
  CHECK(m.override.state() == field_state::not_available);
  CHECK(m.steering_mode.state() == field_state::not_available);      // byte 1 bits 0-2: 7
  CHECK(m.turn_mode.state() == field_state::not_available);          // bits 3-5: 7
  CHECK(m.heading_reference == n2k::heading_reference::true_north);  // bits 6-7: 0
  CHECK(m.commanded_rudder_direction.state() == field_state::not_available);
  CHECK(m.track_rad.raw() == 0);  // bytes 7-8
  CHECK(m.vessel_heading_rad.state() == field_state::not_available);
  check_sent(m, wire);
  using S = decltype(m.steering_mode);
  CHECK(S::from_raw(5) == n2k::steering_mode::track_control);
  CHECK(S::from_raw(5).has_value());
  CHECK(S::from_raw(6).state() == field_state::out_of_range);
  CHECK(S::from_raw(7).state() == field_state::not_available);
  auto t = m;
  t.steering_mode = n2k::steering_mode::track_control;
  t.rate_of_turn_order_radps = decltype(t.rate_of_turn_order_radps)::from_raw(-32);  // -0.001
  CHECK(pgn_json(t).find(R"("steering_mode":"track_control")") != std::string::npos);
  CHECK(pgn_json(t).find(R"("rate_of_turn_order_radps":-0.00100000)") != std::string::npos);
  CHECK(n2k::encode(t).value[1] == 0x3D);
  check_titles<n2k::steering_mode>();
  check_titles<n2k::turn_mode>();
}

TEST_CASE("127252 Heave and 127493 Transmission Parameters: reserved bits, gear 2 (reverse)") {
  // susteranna2020.raw: SID 0, heave -0.63 m, reserved bits not all ones (sent back as ones)
  const std::array<std::uint8_t, 8> heave{0x00, 0xC1, 0xFF, 0xFF, 0xFF, 0xFF, 0x7F, 0xFD};
  const auto h = decode_bytes<n2k::heave>(heave);
  CHECK(h.sid.raw() == 0);
  CHECK(h.heave_m.raw() == -63);
  CHECK(h.heave_m.value() == -0.63);
  check_sent(h, std::array<std::uint8_t, 8>{0x00, 0xC1, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF});

  // boatkit-yanmar-controls.raw: Dual Engine Starboard, Forward, reserved "00", no flag set
  const std::array<std::uint8_t, 8> tp{0x01, 0x00, 0xFF, 0xFF, 0xFF, 0xFF, 0x00, 0xFF};
  const auto t = decode_bytes<n2k::transmission_parameters_dynamic>(tp);
  CHECK(t.instance.raw() == 1);
  CHECK(t.transmission_gear == n2k::gear_status::forward);
  CHECK(t.oil_pressure_pa.state() == field_state::not_available);
  CHECK(t.oil_temperature_k.state() == field_state::not_available);
  CHECK(t.discrete_status_1 == n2k::flags<n2k::transmission_status, 8>::none());
  check_sent(t, std::array<std::uint8_t, 8>{0x01, 0xFC, 0xFF, 0xFF, 0xFF, 0xFF, 0x00, 0xFF});
  // reverse is raw 2, a value; 3 not available
  const std::array<std::uint8_t, 8> rev{0x00, 0xFE, 0x10, 0x27, 0xE8, 0x0B, 0x25, 0xFF};
  const auto r = decode_bytes<n2k::transmission_parameters_dynamic>(rev);
  CHECK(r.transmission_gear == n2k::gear_status::reverse);
  CHECK(r.oil_pressure_pa.value() == 1'000'000.0);  // 10000 x 100 Pa
  CHECK(r.oil_temperature_k.raw() == 3048);
  CHECK(pgn_json(r).find(R"("transmission_gear":"reverse","oil_pressure_pa":1000000,)"
                         R"("oil_temperature_k":304.8,"discrete_status_1":)"
                         R"(["check_transmission","low_oil_pressure","bit_5"]})") !=
        std::string::npos);
  check_sent(r, rev);
  check_titles<n2k::gear_status>();
  check_titles<n2k::transmission_status>();
}

TEST_CASE("129038 and 129039 AIS position reports: named top values, spare bits") {
  // sample-single.raw.txt: Scheduled Class A position report, Initial, MMSI 244710102,
  // 5.2917916 E 52.6989916 N, High, in use, time stamp 52, COG 1.8727, SOG 1.69, "30 F5 01",
  // transceiver 20, heading 2.3633, ROT 0.22853, under way using engine, Not available,
  // reserved "00", spare "06"; 27 of the 28 bytes (no sequence ID)
  const std::array<std::uint8_t, 27> a{0x01, 0xD6, 0xFA, 0x95, 0x0E, 0x9C, 0x76, 0x27, 0x03,
                                       0x5C, 0x3A, 0x69, 0x1F, 0xD3, 0x27, 0x49, 0xA9, 0x00,
                                       0x30, 0xF5, 0xA1, 0x51, 0x5C, 0x91, 0x1C, 0x00, 0xFE};
  const auto m = decode_bytes<n2k::ais_class_a_position>(a);
  CHECK(m.message_id == n2k::ais_message_id::scheduled_class_a_position_report);
  CHECK(m.repeat_indicator == n2k::ais_repeat_indicator::initial);
  CHECK(m.user_id.raw() == 244710102);
  CHECK(m.longitude_deg.raw() == 52917916);
  CHECK(m.latitude_deg.raw() == 526989916);
  CHECK(m.position_accuracy == n2k::position_accuracy::high);
  CHECK(m.raim == n2k::raim_flag::in_use);
  CHECK(m.time_stamp.raw() == 52);  // byte 13 >> 2
  CHECK(m.time_stamp.name().empty());
  CHECK(m.cog_rad.raw() == 18727);
  CHECK(m.sog_mps.raw() == 169);
  CHECK(m.communication_state.raw() == 0x1F530);  // bits 144-162
  CHECK(m.transceiver_information.raw() == 20);   // byte 20 >> 3, a value without a name
  CHECK(m.heading_rad.raw() == 23633);
  CHECK(m.rate_of_turn_radps.raw() == 7313);  // 0.22853125 rad/s
  CHECK(m.nav_status == n2k::nav_status::under_way_using_engine);
  CHECK(m.special_maneuver == n2k::ais_special_maneuver::unavailable);
  CHECK(m.sid.state() == field_state::not_available);
  // sent back: reserved bits ones, spare bits zeros, the sequence ID not available
  auto sent = std::array<std::uint8_t, 28>{};
  std::ranges::copy(a, sent.begin());
  sent[25] = 0xC0;
  sent[26] = 0xF8;
  sent[27] = 0xFF;
  check_sent(m, sent);
  // the named top values of a 6-bit time stamp and a 2-bit repeat indicator are values
  auto t = m;
  t.time_stamp = decltype(t.time_stamp)::from_raw(63);
  t.repeat_indicator = n2k::ais_repeat_indicator::final_retransmission;
  t.nav_status = decltype(t.nav_status)::from_raw(14);
  t.special_maneuver = n2k::ais_special_maneuver::reserved_3;
  const std::string j = pgn_json(t);
  CHECK(j.find(R"("repeat_indicator":"final_retransmission")") != std::string::npos);
  CHECK(j.find(R"("time_stamp":"positioning_inoperative")") != std::string::npos);
  CHECK(j.find(R"("nav_status":"ais_sart","special_maneuver":"reserved_3")") != std::string::npos);
  t.nav_status = decltype(t.nav_status)::from_raw(13);  // unnamed: reserved
  CHECK(pgn_json(t).find(R"("nav_status":"reserved")") != std::string::npos);

  // sample-single.raw.txt: Standard Class B position report, MMSI 244010225, Low, not in use,
  // time stamp 38, "06 00 06", Own information not broadcast, heading null, CS, No, Yes, Entire
  // marine band, Yes, Assigned, ITDMA; 26 of the 27 bytes
  const std::array<std::uint8_t, 26> b{0x12, 0xF1, 0x4C, 0x8B, 0x0E, 0x82, 0x61, 0x41, 0x03,
                                       0x19, 0xE0, 0x52, 0x1F, 0x98, 0x00, 0x00, 0x00, 0x00,
                                       0x06, 0x00, 0x26, 0xFF, 0xFF, 0x00, 0xF4, 0xFF};
  const auto c = decode_bytes<n2k::ais_class_b_position>(b);
  CHECK(c.message_id == n2k::ais_message_id::standard_class_b_position_report);
  CHECK(c.user_id.raw() == 244010225);
  CHECK(c.position_accuracy == n2k::position_accuracy::low);
  CHECK(c.raim == n2k::raim_flag::not_in_use);
  CHECK(c.time_stamp.raw() == 38);
  CHECK(c.communication_state.raw() == 0x60006);
  CHECK(c.transceiver_information == n2k::ais_transceiver::own_information_not_broadcast);
  CHECK(c.heading_rad.state() == field_state::not_available);
  CHECK(c.unit_type == n2k::ais_unit_type::cs);  // byte 24 bit 2
  CHECK(c.integrated_display == n2k::yes_no::no);
  CHECK(c.dsc == n2k::yes_no::yes);
  CHECK(c.band == n2k::ais_band::entire_marine_band);
  CHECK(c.can_handle_msg_22 == n2k::yes_no::yes);
  CHECK(c.ais_mode == n2k::ais_mode::assigned);
  CHECK(c.ais_communication_state == n2k::ais_communication_state::itdma);
  auto sent_b = std::array<std::uint8_t, 27>{};
  std::ranges::copy(b, sent_b.begin());
  sent_b[26] = 0xFF;
  check_sent(c, sent_b);

  check_titles<n2k::ais_message_id>();
  check_titles<n2k::ais_repeat_indicator>();
  check_titles<n2k::position_accuracy>();
  check_titles<n2k::raim_flag>();
  check_titles<n2k::ais_time_stamp>();
  check_titles<n2k::ais_transceiver>();
  check_titles<n2k::nav_status>();
  check_titles<n2k::ais_special_maneuver>();
  check_titles<n2k::ais_unit_type>();
  check_titles<n2k::ais_band>();
  check_titles<n2k::ais_mode>();
  check_titles<n2k::ais_communication_state>();
}

TEST_CASE("129029's integrity names all four raw values: each a value, none not available") {
  using I = n2k::lookup<n2k::gnss_integrity, 2>;
  STATIC_REQUIRE(std::is_same_v<decltype(n2k::gnss_position_data::integrity), I>);
  STATIC_REQUIRE_FALSE(offers_not_available<I>);
  // canboat's texts: No integrity checking, Safe, Caution, Unsafe
  constexpr std::array<std::string_view, 4> names{"none", "safe", "caution", "unsafe"};
  constexpr std::array<std::string_view, 4> titles{"No integrity checking", "Safe", "Caution",
                                                   "Unsafe"};
  for (std::int64_t raw = 0; raw < 4; ++raw) {
    INFO(raw);
    const auto k = static_cast<std::size_t>(raw);
    CHECK(I::from_raw(raw).state() == field_state::value);
    CHECK(I::from_raw(raw).name() == names[k]);
    CHECK(n2k::lookup_title<n2k::gnss_integrity>(static_cast<std::uint64_t>(raw)) == titles[k]);
    const auto back = I::from_name(names[k]);
    REQUIRE(back);
    CHECK(back.value.raw() == raw);
  }
  CHECK(I::from_raw(2) == n2k::gnss_integrity::caution);
  CHECK(I::from_raw(3) == n2k::gnss_integrity::unsafe);
  check_titles<n2k::gnss_integrity>();
}
