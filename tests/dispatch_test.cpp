// SPDX-License-Identifier: BSL-1.0
// merge_sets: the union of message sets, each message once; which sentence is which message.

#include <catch2/catch.hpp>
#include <concepts>
#include <cstring>
#include <new>
#include <string_view>
#include <type_traits>
#include <variant>

#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/registry.hpp"
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

TEST_CASE("a '!' sentence is no message, whatever its address: it stays unknown") {
  using all = message_set<rmc, ping>;
  const std::string_view bang_ping = "!XXPNG,7";
  const auto r = all::decode(bang_ping);
  REQUIRE(r);
  REQUIRE(std::holds_alternative<unknown_sentence>(r.value));
  CHECK(std::get<unknown_sentence>(r.value).sentence.start == '!');
  CHECK(std::get<unknown_sentence>(r.value).sentence.address == "XXPNG");
  // Long enough for the 8-byte address key too.
  const std::string_view bang_rmc =
      "!GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70";
  const auto m = all::decode(bang_rmc);
  REQUIRE(m);
  CHECK(std::holds_alternative<unknown_sentence>(m.value));
  bool unknown = false;
  const auto s = parse(bang_rmc);
  REQUIRE(s);
  const auto v = all::visit(s.value, {}, [&](const auto& msg) {
    unknown = std::is_same_v<std::remove_cvref_t<decltype(msg)>, unknown_sentence>;
  });
  CHECK(v);
  CHECK(unknown);
  // Asked for by type: not that message.
  CHECK(decode<ping>(bang_ping).ec == errc::wrong_address);
  CHECK(decode<rmc>(s.value).ec == errc::wrong_address);
  CHECK(decode<ping>(std::string_view("$XXPNG,7")).value.n == 7);
}

TEST_CASE("a proprietary sentence is not a standard one from a talker named P.") {
  // Garmin's sensor configuration sentence ends in RMC but is no RMC: a payload reading the
  // Kingfisher's relayed GPS lines must ignore it (unknown_sentence), not report RMC errors.
  constexpr std::string_view pgrmc =
      "$PGRMC,A,218.8,100,6378137.000,298.257223563,0.0,0.0,0.0,A,3,1,1,4,30*72\r\n";
  const auto k = kingfisher::decode_from_vehicle(pgrmc);
  REQUIRE(k);
  CHECK(std::holds_alternative<unknown_sentence>(k.value));
  CHECK(decode<standard::rmc>(pgrmc).ec == errc::wrong_address);
  // Talkers of standard sentences are two letters (or a letter and a digit), never P + one.
  standard::rmc m;
  CHECK(encode(m));
  m.talker = "PG";
  CHECK(encode(m).ec == errc::bad_address);
}

namespace {
/// Whether M default-initialized over storage full of 0xA5 bytes equals M{}.
template <class M>
bool whole_when_default_initialized() {
  static_assert(std::equality_comparable<M>);
  alignas(M) unsigned char storage[sizeof(M)];
  // Volatile stores, which the compiler may not drop as dead before the object's construction.
  volatile unsigned char* bytes = storage;
  for (std::size_t i = 0; i < sizeof storage; ++i) bytes[i] = 0xA5;
  const M* m = ::new (static_cast<void*>(storage)) M;
  const bool whole = *m == M{};
  m->~M();
  return whole;
}
/// M default-initialized and copied, at compile time: Clang refuses to copy a member left
/// indeterminate there, so this is a constant only where every member has an initializer.
template <class M>
constexpr bool copies_whole() {
  M m;
  const M copy = m;
  (void)copy;
  return true;
}
template <class M>
concept whole_by_default = requires {
  typename std::bool_constant<copies_whole<M>()>;
};

template <class... Ms>
void check_whole(message_set<Ms...>*) {
#if defined(__clang__)
  static_assert((whole_by_default<Ms> && ...));
#endif
  const auto check = [](std::string_view address, bool whole) {
    INFO(address);
    CHECK(whole);
  };
  (check(std::remove_cvref_t<decltype(Ms::nmea)>::address, whole_when_default_initialized<Ms>()),
   ...);
}
// A message like those users write, with one member left without an initializer: what the
// checks above exist to catch.
struct partly_initialized {
  std::uint16_t n = 0;
  double left;  // NOLINT(cppcoreguidelines-pro-type-member-init): on purpose
  [[maybe_unused]] static constexpr auto nmea =
      sentence<"XXPRT">(field<&partly_initialized::n>("n"));
};
#if defined(__clang__)
static_assert(!whole_by_default<partly_initialized>);
static_assert(whole_by_default<ping>);
#endif
}  // namespace

// decode() and visit() build a message default-initialized, then write each field its
// description names: the same message as value-initializing it first wherever every member has
// an initializer, as every message of the library does.
TEST_CASE("every message of the library is whole when default-initialized") {
  check_whole(static_cast<registry::sentences*>(nullptr));
}

TEST_CASE("decode gives the message it read, or unknown_sentence with the error, on every path") {
  using set = message_set<rmc, gga, ping>;
  // One pass.
  auto r = set::decode("$XXPNG,42*73");
  REQUIRE(r);
  REQUIRE(std::holds_alternative<ping>(r.value));
  CHECK(std::get<ping>(r.value).n == 42);
  // The general path (the checksum left out, which the one-pass reader does not take).
  r = set::decode("$XXPNG,7");
  REQUIRE(r);
  CHECK(std::get<ping>(r.value).n == 7);
  // Lines the one-pass reader takes up and gives back (a field past the message's last, a '+'
  // sign), which the general path then reads.
  for (const std::string_view line :
       {std::string_view("$XXPNG,7,9*57"), std::string_view("$XXPNG,+7*69")}) {
    INFO(line);
    seawire::nmea::detail::plain_line l;
    REQUIRE(seawire::nmea::detail::frame_plain(line, parse_policy{}, l));
    ping read_in_one_pass;
    CHECK_FALSE(seawire::nmea::detail::decode_plain(l, parse_policy{}, read_in_one_pass));
    r = set::decode(line);
    REQUIRE(r);
    REQUIRE(std::holds_alternative<ping>(r.value));
    CHECK(std::get<ping>(r.value).n == 7);
  }
  // A field the message refuses: unknown_sentence, the field and its column.
  r = set::decode("$XXPNG,x*0D");
  CHECK(r.ec == errc::bad_number);
  CHECK(r.field == 1);
  CHECK(r.column == 7);
  REQUIRE(std::holds_alternative<unknown_sentence>(r.value));
  CHECK(std::get<unknown_sentence>(r.value).sentence.address == "XXPNG");
  // A sentence no message of the set describes.
  r = set::decode("$GPXYZ,1*51");
  REQUIRE(r);
  CHECK(std::get<unknown_sentence>(r.value).sentence.address == "GPXYZ");
  // A line that is no sentence: the error and its column, and an empty unknown_sentence.
  r = set::decode("GPXYZ,1");
  CHECK(r.ec == parse("GPXYZ,1").ec);
  CHECK(r.ec != errc::ok);
  CHECK(r.column == 0);
  REQUIRE(std::holds_alternative<unknown_sentence>(r.value));
  CHECK(std::get<unknown_sentence>(r.value).sentence.line.empty());
}

// The same through a set of 16 messages or more, which finds a sentence's message by its table
// and decodes through a function of that message; at compile time too.
TEST_CASE("decode through a set's table gives the message, the error or unknown_sentence") {
  using set = registry::sentences;
  constexpr std::string_view rmc_line =
      "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70";
  auto r = set::decode(rmc_line);
  REQUIRE(r);
  REQUIRE(std::holds_alternative<rmc>(r.value));
  CHECK(std::get<rmc>(r.value) == decode<rmc>(rmc_line).value);
  CHECK(std::get<rmc>(r.value).speed_knots == decimal::parse("0.145").value);
  // A field the message refuses (the hemisphere).
  r = set::decode("$GPRMC,164959.00,A,4221.71114,Q,07105.44878,W,0.145,156.78,311214,,,A*6F");
  CHECK(r.ec == errc::bad_hemisphere);
  CHECK(r.field == 4);
  REQUIRE(std::holds_alternative<unknown_sentence>(r.value));
  CHECK(std::get<unknown_sentence>(r.value).sentence.address == "GPRMC");
  r = set::decode("$GPXYZ,1*51");
  REQUIRE(r);
  CHECK(std::holds_alternative<unknown_sentence>(r.value));
  static_assert(std::holds_alternative<rmc>(set::decode(rmc_line).value));
  static_assert(std::get<rmc>(set::decode(rmc_line).value).status == standard::rmc_status::active);
  static_assert(
      std::holds_alternative<unknown_sentence>(set::decode(std::string_view("$GPXYZ,1*51")).value));
}
