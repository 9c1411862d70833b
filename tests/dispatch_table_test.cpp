// SPDX-License-Identifier: BSL-1.0
// Finding a sentence's message in a large set by the compile-time dispatch table: the same
// message as trying the set's messages in order, for every address of every set and for
// addresses near them.

#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

#include "seawire/nmea/dispatch.hpp"
#include "seawire/registry.hpp"

#include "support.hpp"

using namespace seawire;
using namespace seawire::nmea;

namespace {

template <class M>
constexpr std::string_view address_of() {
  return std::remove_cvref_t<decltype(M::nmea)>::address;
}

// The reference: the first message of the set whose description matches the address, by its
// own matches() (no key, no table); a '!' sentence matches none.
template <class... Ms>
std::size_t first_match(message_set<Ms...>*, std::string_view address, char start = '$') {
  if (start != '$') return sizeof...(Ms);
  std::size_t i = 0;
  (void)((Ms::nmea.matches(address) || (++i, false)) || ...);
  return i;
}

template <class... Ms>
std::vector<std::string> addresses(message_set<Ms...>*) {
  return {std::string(address_of<Ms>())...};
}

// The addresses to try for a set: each declared address with talkers in place of "--" (a
// proprietary 'P' among them), each with one byte changed, cut, lengthened or in lower case,
// and random ones from the same letters.
template <class Set>
std::vector<std::string> addresses_near(support::prng& g) {
  std::vector<std::string> out;
  std::string letters;
  for (std::string a : addresses(static_cast<Set*>(nullptr))) {
    letters += a;
    if (a.starts_with("--")) {
      for (const std::string_view talker : {"GP", "GN", "II", "VW", "PG", "P1", "--", "G"}) {
        std::string t = std::string(talker) + a.substr(2);
        out.push_back(t);
      }
      a = "GP" + a.substr(2);
    }
    out.push_back(a);
    for (std::size_t i = 0; i < a.size(); ++i) {
      std::string changed = a;
      changed[i] = static_cast<char>(changed[i] == 'Z' ? 'A' : changed[i] + 1);
      out.push_back(changed);
      std::string lower = a;
      lower[i] = static_cast<char>(lower[i] | 0x20);
      out.push_back(lower);
    }
    out.push_back(a.substr(0, a.size() - 1));
    out.push_back(a + "X");
    out.push_back(a + a.substr(a.size() - 1));
  }
  for (int k = 0; k < 2000; ++k) {
    std::string r;
    const std::size_t n = 1 + g.below(12);
    for (std::size_t i = 0; i < n; ++i) r += letters[g.below(letters.size())];
    out.push_back(r);
  }
  return out;
}

template <class Set>
void check_set(std::string_view name, support::prng& g) {
  INFO(name);
  for (const std::string& a : addresses_near<Set>(g)) {
    INFO(a);
    const std::size_t want = first_match(static_cast<Set*>(nullptr), a);
    CHECK(Set::index_of(a) == want);
    CHECK(Set::knows(a) == (want < Set::size));
    // Through decode: the sentence as a line, its message (or unknown_sentence) by the same
    // index. Only the address is looked at first: a wrong body is that message's error.
    const std::string line = "$" + a + ",";
    const auto s = parse(line);
    if (!s) continue;  // an address parse() refuses (lower case): no dispatch at all
    const auto r = Set::decode(s.value);
    if (r) CHECK(r.value.index() == (want == Set::size ? 0 : want + 1));
    const auto bang = parse("!" + a + ",");
    REQUIRE(bang);
    const auto u = Set::decode(bang.value);
    REQUIRE(u);
    CHECK(std::holds_alternative<unknown_sentence>(u.value));
  }
}

// Sixteen messages or more, so that the table is used (nmea::detail::dispatch_by_table_from);
// addresses that only differ past their eighth byte, and an exact address that an any-talker
// one also matches.
template <seawire::detail::fixed_string A>
struct msg {
  std::uint16_t n = 0;
  static constexpr auto nmea = sentence<A>(field<&msg::n>("n"));
};
template <seawire::detail::fixed_string A>
struct any_talker_msg {
  talker_id talker;
  std::uint16_t n = 0;
  static constexpr auto nmea =
      sentence<A>(field<&any_talker_msg::n>("n")).template talker_in<&any_talker_msg::talker>();
};

// The two messages given, then fourteen more (among them any-talker addresses, one of them longer
// than eight bytes, and a long exact one).
template <class... First>
using with_fourteen_more =
    message_set<First..., msg<"AAAAA">, msg<"AAAAB">, msg<"AAAAC">, msg<"AAAAD">, msg<"AAAAE">,
                msg<"AAAAF">, msg<"AAAAG">, msg<"AAAAH">, msg<"AAAAI">, msg<"AAAAJ">, msg<"AAAAK">,
                any_talker_msg<"--LONGADDR">, any_talker_msg<"--AAM">, msg<"PLONGADDRESS">>;
using exact_first = with_fourteen_more<msg<"GPXYZ">, any_talker_msg<"--XYZ">>;
using talker_first = with_fourteen_more<any_talker_msg<"--XYZ">, msg<"GPXYZ">>;
using long_alike = with_fourteen_more<msg<"PLONGADDR1">, msg<"PLONGADDR2">, msg<"PLONGADDRX">>;
static_assert(exact_first::size >= seawire::nmea::detail::dispatch_by_table_from &&
              talker_first::size >= seawire::nmea::detail::dispatch_by_table_from &&
              long_alike::size >= seawire::nmea::detail::dispatch_by_table_from);

}  // namespace

// Long addresses alike in their first eight bytes and their length cannot be told apart by
// key: that set is tried in turn, and still finds each.
template <class... Ms>
constexpr bool table_usable(message_set<Ms...>*) {
  return seawire::nmea::detail::dispatch_table_of<Ms...>.usable;
}
template <class... Ms>
constexpr bool uses_table(message_set<Ms...>*) {
  return seawire::nmea::detail::use_dispatch_table<Ms...>();
}
// The set of every sentence is found by its table (no two of its keys alike), as are the test's
// sets but long_alike.
static_assert(uses_table(static_cast<registry::sentences*>(nullptr)));
static_assert(uses_table(static_cast<exact_first*>(nullptr)) &&
              uses_table(static_cast<talker_first*>(nullptr)) &&
              !uses_table(static_cast<long_alike*>(nullptr)));
static_assert(!table_usable(static_cast<long_alike*>(nullptr)));
static_assert(table_usable(static_cast<registry::sentences*>(nullptr)));
static_assert(table_usable(static_cast<exact_first*>(nullptr)));
// At compile time too.
static_assert(registry::sentences::index_of("GNRMC") == 0);
static_assert(registry::sentences::index_of("PGRMC") == registry::sentences::size);
static_assert(exact_first::index_of("GPXYZ") == 0 && exact_first::index_of("GNXYZ") == 1);
static_assert(talker_first::index_of("GPXYZ") == 0);

TEST_CASE("the dispatch table finds the message trying each in turn would") {
  support::prng g{20261127};
  check_set<registry::sentences>("every sentence", g);
  registry::for_each_role([&](const auto& role) {
    using set = typename std::remove_cvref_t<decltype(role)>::set;
    check_set<set>(role.title, g);
  });
  check_set<exact_first>("exact address first", g);
  check_set<talker_first>("any-talker address first", g);
  check_set<long_alike>("long addresses alike", g);
}

TEST_CASE("of an exact and an any-talker address that both match, the first in the set wins") {
  const std::string_view gp = "$GPXYZ,5";
  const auto a = exact_first::decode(gp);
  REQUIRE(a);
  CHECK(std::get<msg<"GPXYZ">>(a.value).n == 5);
  const auto b = talker_first::decode(gp);
  REQUIRE(b);
  CHECK(std::get<any_talker_msg<"--XYZ">>(b.value).talker.view() == "GP");
  const auto c = exact_first::decode(std::string_view("$GNXYZ,6"));
  REQUIRE(c);
  CHECK(std::get<any_talker_msg<"--XYZ">>(c.value).n == 6);
  // A 'P' first is proprietary, no talker: unknown to both.
  const auto p = talker_first::decode(std::string_view("$PGXYZ,6"));
  REQUIRE(p);
  CHECK(std::holds_alternative<unknown_sentence>(p.value));
  // visit takes the same one.
  const auto s = parse(gp);
  REQUIRE(s);
  std::size_t seen = 0;
  const auto v = exact_first::visit(s.value, {}, [&](const auto& m) {
    seen = std::is_same_v<std::remove_cvref_t<decltype(m)>, msg<"GPXYZ">> ? 1 : 2;
  });
  CHECK(v);
  CHECK(seen == 1);
}

TEST_CASE("long addresses alike in their first eight bytes: each its own message") {
  for (const std::string_view a : {"PLONGADDR1", "PLONGADDR2", "PLONGADDRX", "PLONGADDRESS"}) {
    INFO(a);
    const auto r = long_alike::decode("$" + std::string(a) + ",9");
    REQUIRE(r);
    CHECK(r.value.index() == first_match(static_cast<long_alike*>(nullptr), a) + 1);
  }
  const auto none = long_alike::decode(std::string_view("$PLONGADDR3,9"));
  REQUIRE(none);
  CHECK(std::holds_alternative<unknown_sentence>(none.value));
}
