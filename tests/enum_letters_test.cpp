// SPDX-License-Identifier: BSL-1.0
// A single-letter field's enum lists its letters twice: as the enumerators' values and in
// enum_chars(). The library reads the letters from enum_chars (no reflection at compile time, so
// users pay nothing for it); this test reads the enumerators with the compiler's own printing of
// template arguments and holds every enum of every message to the same letters.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstddef>
#include <set>
#include <string>
#include <string_view>
#include <utility>

#include "seawire/seawire.hpp"

namespace {

namespace nmea = seawire::nmea;

// GCC prints "[with auto ...V = {ns::e::a, (ns::e)66}; ...]", Clang "[V = <ns::e::a, (ns::e)66>]":
// a value that is no enumerator is printed as a cast.
template <auto... V>
constexpr std::string_view listing() noexcept {
  return __PRETTY_FUNCTION__;
}

// The letters among '0'-'9', 'A'-'Z' and 'a'-'z' that are enumerators of E, in increasing order.
template <class E, char... C>
std::string enumerator_letters(std::integer_sequence<char, C...>) {
  const std::string_view f = listing<static_cast<E>(C)...>();
  const char candidates[] = {C...};
  std::string letters;
  std::size_t at = f.find("V = ");
  REQUIRE(at != std::string_view::npos);
  at += 5;  // past "V = {" or "V = <"
  for (const char c : candidates) {
    if (f[at] != '(') letters += c;
    at = f.find(", ", at) + 2;
  }
  return letters;
}

template <class E>
std::string enumerator_letters() {
  return enumerator_letters<E>(
      std::integer_sequence<char, '0', '1', '2', '3', '4', '5', '6', '7', '8', '9', 'A', 'B', 'C',
                            'D', 'E', 'F', 'G', 'H', 'I', 'J', 'K', 'L', 'M', 'N', 'O', 'P', 'Q',
                            'R', 'S', 'T', 'U', 'V', 'W', 'X', 'Y', 'Z', 'a', 'b', 'c', 'd', 'e',
                            'f', 'g', 'h', 'i', 'j', 'k', 'l', 'm', 'n', 'o', 'p', 'q', 'r', 's',
                            't', 'u', 'v', 'w', 'x', 'y', 'z'>{});
}

template <class E>
std::string sorted_enum_chars() {
  std::string s(enum_chars(E{}));
  std::sort(s.begin(), s.end());
  return s;
}

// The field's enum, if it is a letter enum not checked yet.
template <class M, class D>
void check_field(const D& d, std::set<std::string>& seen) {
  using V = typename D::value_type;
  if constexpr (nmea::char_enum_like<V>) {
    if (!seen.insert(std::string(listing<V{}>())).second) return;
    INFO(std::string(M::nmea.address) + "." + std::string(d.name));
    CHECK(sorted_enum_chars<V>() == enumerator_letters<V>());
  }
}

template <class M>
void check_message(std::set<std::string>& seen) {
  M::nmea.fields.apply([&](const auto&... d) { (check_field<M>(d, seen), ...); });
}

// Every letter enum of every message of a set, checked once.
template <class... Ms>
void check_set(nmea::message_set<Ms...>*, std::set<std::string>& seen) {
  (check_message<Ms>(seen), ...);
}

template <class Set>
Set* of() {
  return nullptr;
}

}  // namespace

TEST_CASE("enum_chars lists exactly each letter enum's enumerators", "[nmea][enums]") {
  // The probe itself: a value that is no enumerator is told apart from one that is.
  enum class probe : char { a = 'A', seven = '7', z = 'z' };
  CHECK(enumerator_letters<probe>() == "7Az");

  std::set<std::string> seen;
  using all =
      typename nmea::merge_sets<seawire::kingfisher::from_vehicle, seawire::kingfisher::to_vehicle,
                                seawire::sandshark::from_vehicle, seawire::sandshark::to_vehicle,
                                seawire::robotx::reports, seawire::anello::nmea_inputs,
                                seawire::anello::nmea_outputs>::type;
  check_set(of<all>(), seen);
  // Every letter enum of the families: RMC's three, GGA's quality, the Kingfisher, Sandshark,
  // RobotX and ANELLO ones. A new one is checked without being listed here.
  CHECK(seen.size() >= 20);
}
