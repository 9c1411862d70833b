// SPDX-License-Identifier: BSL-1.0
// A letter field's letters are its enum's enumerators, read from the enum itself
// (nmea::enum_letters). These tests hold that reading to enums whose letters are known, to the
// listings each supported compiler prints, and to every letter enum of every message: each of
// its letters decodes to that enumerator and every other byte is refused.

#include <catch2/catch.hpp>
#include <cstddef>
#include <set>
#include <string>
#include <string_view>

#include "seawire/seawire.hpp"

namespace {

namespace nmea = seawire::nmea;
using seawire::errc;

enum class probe : char { a = 'A', seven = '7', z = 'z' };
// Values outside printable ASCII (a '\0' sentinel) are not letters; two names for one value are
// one letter. (A space or punctuation enumerator is a compile error:
// tests/compile_fail/letter_enums.cpp.)
enum class odd : char { b = 'B', also_b = 'B', nul = '\0', tab = '\t' };

#if !defined(__clang__)  // with Clang, a compile error (tests/compile_fail/letter_enums.cpp)
template <class T, int N>
struct holder {
  enum class inner : char { q = 'Q', r = 'R' };  // printed as holder<int, 2>::inner: a comma
};
static_assert(nmea::enum_letters<holder<int, 2>::inner> == "QR");
#endif

static_assert(nmea::enum_letters<probe> == "7Az");
static_assert(nmea::enum_letters<odd> == "B");
static_assert(nmea::enum_letters<seawire::standard::rmc_status> == "AV");
static_assert(nmea::enum_letters<seawire::standard::mode_indicator> == "ADEFMNPRS");
static_assert(nmea::enum_letters<seawire::standard::gps_quality> == "012345678");
static_assert(nmea::enum_letters<seawire::robotx::color> == "BGR");
static_assert(nmea::enum_letters<seawire::sandshark::ack_status> == "0123");
static_assert(nmea::enum_letters<nmea::hemisphere> == "ENSW");
// A word enum or an enum of another underlying type is not a letter enum.
static_assert(!nmea::char_enum_like<seawire::sandshark::log_state>);
static_assert(!nmea::char_enum_like<seawire::nmea2000::field_state>);

std::string letters_of(std::string_view listing) {
  const auto set = nmea::detail::enumerators_among_candidates(listing);
  if (!set.parsed) return "<not parsed>";
  return std::string(set.chars.data(), set.size);
}

// A listing of the 62 candidates in a compiler's style, `named` ones as names.
std::string listing(std::string_view head, std::string_view open, std::string_view sep,
                    std::string_view close, std::string_view named, std::string_view type) {
  std::string s(head);
  s += open;
  const std::string_view candidates = nmea::detail::letter_candidates;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (i != 0) s += sep;
    s += type;
    if (named.find(candidates[i]) != std::string_view::npos) {
      s += "::letter_";
      s += candidates[i];
    } else {
      s.insert(s.size() - type.size(), "(");
      s += ")" + std::to_string(static_cast<int>(candidates[i]));
    }
  }
  s += close;
  return s;
}

// The letters among '0'-'9', 'A'-'Z', 'a'-'z' that decode to themselves as E, in order.
template <class E>
std::string letters_decoded() {
  std::string letters;
  nmea::parse_policy policy;
  policy.checksum = nmea::checksum_policy::ignore;
  for (int c = 1; c < 256; ++c) {
    const std::string line = std::string("$XXYYY,") + static_cast<char>(c) + "\r\n";
    const auto s = nmea::parse(line, policy);
    if (!s) continue;  // a byte no sentence may hold: it never reaches a field
    nmea::field_reader r(s.value, policy);
    E e{};
    const errc ec = nmea::codec<E>::read(r, e);
    if (ec == errc::ok) {
      CHECK(static_cast<unsigned char>(e) == c);
      letters += static_cast<char>(c);
    } else {
      CHECK(ec == errc::bad_enum);
    }
  }
  return letters;
}

template <class V>
void check_enum(std::string_view where, std::set<std::string>& seen) {
  if constexpr (nmea::char_enum_like<V>) {
    if (!seen.insert(std::string(seawire::detail::enum_listing<V{}>())).second) return;
    INFO(std::string(where));
    const std::string_view letters = nmea::enum_letters<V>;
    CHECK(!letters.empty());
    CHECK(letters_decoded<V>() == std::string(letters));
    for (const char c : letters) {
      CHECK(nmea::to_string(static_cast<V>(c)) == std::string_view(&c, 1));
      CHECK(nmea::codec<V>::check(static_cast<V>(c)) == errc::ok);
    }
    CHECK(nmea::to_string(static_cast<V>('#')).empty());
    CHECK(nmea::codec<V>::check(static_cast<V>('#')) == errc::bad_enum);
  }
}

template <class M>
void check_message(std::set<std::string>& seen) {
  M::nmea.fields.apply([&](const auto&... d) {
    (check_enum<typename std::remove_cvref_t<decltype(d)>::value_type>(
         std::string(M::nmea.address) + "." + std::string(d.name), seen),
     ...);
  });
}

template <class... Ms>
void check_set(nmea::message_set<Ms...>*, std::set<std::string>& seen) {
  (check_message<Ms>(seen), ...);
}

}  // namespace

TEST_CASE("a letter enum's letters are its enumerators", "[nmea][enums]") {
  CHECK(letters_decoded<probe>() == "7Az");
  CHECK(letters_decoded<odd>() == "B");
#if !defined(__clang__)
  CHECK(letters_decoded<holder<int, 2>::inner>() == "QR");
#endif
  // A local enum: Clang prints its scope as "f()::e", parentheses in a name.
  enum class local : char { x = 'x', one = '1' };
  CHECK(nmea::enum_letters<local> == "1x");
}

TEST_CASE("the listings of GCC, Clang and MSVC are read alike", "[nmea][enums]") {
  // The shapes each compiler prints (see enum.hpp); enum types with commas and parentheses.
  for (const std::string_view type :
       {std::string_view("ns::e"), std::string_view("ns::h<int, 2>::e"), std::string_view("f()::e"),
        std::string_view("(anonymous namespace)::e"), std::string_view("{anonymous}::e")}) {
    INFO(std::string(type));
    CHECK(letters_of(listing("constexpr std::string_view f() [with auto ...V = ", "{", ", ",
                             "}; std::string_view = std::basic_string_view<char>]", "09AZaz",
                             type)) == "09AZaz");
    CHECK(letters_of(listing("std::string_view f() [V = ", "<", ", ", ">]", "Vq", type)) == "Vq");
    CHECK(letters_of(listing("class std::basic_string_view<char> __cdecl enum_listing", "<", ",",
                             ">(void)", "5N", type)) == "5N");
  }
  // MSVC may print a value that is no enumerator as a bare number.
  std::string bare = "f enum_listing<";
  for (std::size_t i = 0; i < nmea::detail::letter_candidates.size(); ++i)
    bare += (i ? "," : "") + (i == 3 ? std::string("e::three") : std::to_string(48 + i));
  CHECK(letters_of(bare + ">(void)") == "3");
  // What cannot be read is said, not guessed: too few elements, no list at all.
  CHECK(letters_of("f() [with auto ...V = {e::a, (e)66}]") == "<not parsed>");
  CHECK(letters_of("f()") == "<not parsed>");
  CHECK(letters_of("") == "<not parsed>");
}

TEST_CASE("every letter enum of every message reads and writes exactly its letters",
          "[nmea][enums]") {
  std::set<std::string> seen;
  using all =
      typename nmea::merge_sets<seawire::kingfisher::from_vehicle, seawire::kingfisher::to_vehicle,
                                seawire::sandshark::from_vehicle, seawire::sandshark::to_vehicle,
                                seawire::robotx::reports, seawire::anello::nmea_inputs,
                                seawire::anello::nmea_outputs>::type;
  check_set(static_cast<all*>(nullptr), seen);
  // RMC's three, GGA's quality, the Sandshark, RobotX and ANELLO ones; a new one is checked
  // without being listed here.
  CHECK(seen.size() >= 20);
}
