// SPDX-License-Identifier: BSL-1.0
// No seawire number is made from a floating-point value without saying how many places: a
// double assigned to a speed or depth would otherwise be cut to an integer and sent as a
// different command. Everything here is decided when the test compiles; the run repeats the
// constant checks so a failure also shows in the test report.

#include <catch2/catch.hpp>
#include <concepts>
#include <optional>
#include <type_traits>

#include "seawire/seawire.hpp"
#include "support.hpp"

// ---------------------------------------------------------------------------------------------
// The family namespaces hold their own names only: `using namespace seawire::kingfisher` does not
// also bring in seawire::nmea (a header's using-directive would reach every file that includes
// it). Each probe namespace below sees a user's own `decimal`, `field`, `sentence`, `latitude`
// and `parse` beside one family's names; were the family to pull seawire::nmea in, each use
// would be ambiguous and this file would not compile.
namespace user_names {
struct decimal {};
struct field {};
struct sentence {};
struct latitude {};
struct parse {};
}  // namespace user_names
#define SEAWIRE_PROBE_FAMILY(family)                                            \
  namespace probe_##family {                                                    \
    using namespace user_names;      /* NOLINT(google-build-using-namespace) */ \
    using namespace seawire::family; /* NOLINT(google-build-using-namespace) */ \
    static_assert(std::is_same_v<decimal, user_names::decimal> &&               \
                  std::is_same_v<field, user_names::field> &&                   \
                  std::is_same_v<sentence, user_names::sentence> &&             \
                  std::is_same_v<latitude, user_names::latitude> &&             \
                  std::is_same_v<parse, user_names::parse>);                    \
  }
SEAWIRE_PROBE_FAMILY(standard)
SEAWIRE_PROBE_FAMILY(bluefin)
SEAWIRE_PROBE_FAMILY(kingfisher)
SEAWIRE_PROBE_FAMILY(sandshark)
SEAWIRE_PROBE_FAMILY(robotx)
SEAWIRE_PROBE_FAMILY(anello)
#undef SEAWIRE_PROBE_FAMILY

namespace {

using namespace seawire;
using namespace seawire::nmea::literals;
using nmea::decimal;

// Whether `t = v` compiles, and whether T is made from V at all (T(v), T{v} or T t = v).
template <class T, class V>
concept assignable_from = requires(T& t, V v) {
  t = v;
};
template <class T, class V>
concept made_from = std::is_constructible_v<T, V> || std::is_convertible_v<V, T> || requires(V v) {
  T{v};
};

// Refused from every floating-point type, directly and through std::optional.
template <class T>
constexpr bool refuses_floating() {
  return !made_from<T, double> && !made_from<T, float> && !made_from<T, long double> &&
         !assignable_from<T, double> && !assignable_from<T, float> &&
         !assignable_from<T, long double> && !made_from<std::optional<T>, double> &&
         !made_from<std::optional<T>, float> && !assignable_from<std::optional<T>, double> &&
         !assignable_from<std::optional<T>, float>;
}

static_assert(refuses_floating<decimal>());
static_assert(refuses_floating<nmea::latitude>());
static_assert(refuses_floating<nmea::longitude>());
static_assert(refuses_floating<nmea::decimal_latitude>());
static_assert(refuses_floating<nmea::decimal_longitude>());
static_assert(refuses_floating<nmea::time_of_day>());
static_assert(refuses_floating<nmea::date>());
static_assert(refuses_floating<nmea::magnetic_variation>());
static_assert(refuses_floating<nmea::integer<std::uint8_t>>());
static_assert(refuses_floating<nmea::integer<std::int32_t>>());

// Integers stay implicit where that reads well; bool is not a number.
static_assert(made_from<decimal, int> && assignable_from<decimal, int>);
static_assert(made_from<decimal, std::int64_t> && made_from<decimal, unsigned>);
static_assert(assignable_from<std::optional<decimal>, int>);
static_assert(!made_from<decimal, bool>);

// The scaled-integer form is a named factory that takes integers only.
template <class M, class P>
concept scalable = requires(M m, P p) {
  decimal::scaled(m, p);
};
static_assert(scalable<int, int> && scalable<std::int64_t, unsigned>);
static_assert(!scalable<double, int> && !scalable<int, double> && !scalable<float, float>);
static_assert(!made_from<decimal, std::pair<int, int>>);
static_assert(!std::is_constructible_v<decimal, int, int>);     // no positional (scaled, places)
static_assert(!std::is_constructible_v<decimal, double, int>);  // decimal(1.5, 1) was "0.1"

// Members of messages, plain and optional, on both sides of each link.
template <auto Member, class V>
concept member_takes = assignable_from<seawire::detail::member_type_t<Member>, V>;
template <auto Member>
constexpr bool member_refuses_floating() {
  return !member_takes<Member, double> && !member_takes<Member, float> && member_takes<Member, int>;
}
static_assert(member_refuses_floating<&kingfisher::pydev::speed_mps>());
static_assert(member_refuses_floating<&kingfisher::pydev::heading_deg>());
static_assert(member_refuses_floating<&kingfisher::pydir::thrust_left>());
static_assert(member_refuses_floating<&kingfisher::pydep::thrust>());
static_assert(member_refuses_floating<&kingfisher::cpnvg::heading_deg>());
static_assert(member_refuses_floating<&kingfisher::cpnvg::depth_m>());
static_assert(member_refuses_floating<&sandshark::bprmb::heading>());
static_assert(member_refuses_floating<&sandshark::bprmb::depth>());
static_assert(member_refuses_floating<&sandshark::bprmb::speed>());
static_assert(member_refuses_floating<&standard::rmc::speed_knots>());
static_assert(member_refuses_floating<&standard::gga::altitude_m>());
static_assert(member_refuses_floating<&standard::vhw::speed_knots>());
// Whole-number members: any integer, never a floating-point value.
static_assert(member_refuses_floating<&standard::gga::satellites>());
static_assert(member_refuses_floating<&standard::gga::dgps_station>());
static_assert(member_refuses_floating<&standard::rpm::number>());
static_assert(member_refuses_floating<&kingfisher::cprcm::compass_id>());
static_assert(member_refuses_floating<&kingfisher::cprbs::battery_id>());
static_assert(member_refuses_floating<&sandshark::bfack::behavior_id>());
static_assert(member_refuses_floating<&sandshark::bfack::future_use>());
static_assert(member_takes<&standard::gga::satellites, std::int64_t> &&
              member_takes<&standard::rpm::number, unsigned long long>);
static_assert(!member_takes<&standard::rpm::number, bool>);
static_assert(!member_takes<&standard::rpm::number, char>);  // '7' would be 55
// Decimal members take whole numbers too, never a character ('A' would be 65).
static_assert(!member_takes<&kingfisher::pydir::thrust_left, char> &&
              !member_takes<&kingfisher::pydir::thrust_left, char8_t> &&
              !member_takes<&kingfisher::pydir::thrust_left, bool> &&
              member_takes<&kingfisher::pydir::thrust_left, short>);
static_assert(!std::is_constructible_v<decimal, char> &&
              !std::is_constructible_v<decimal, wchar_t>);
// A member of a character type is no number field: no number codec, no range or zero_pad.
template <class T>
concept has_codec = requires {
  nmea::codec<T>::width;
};
static_assert(!has_codec<char8_t> && !has_codec<wchar_t> && has_codec<short>);
static_assert(!nmea::detail::is_integer_field<char> && !nmea::detail::is_integer_field<char16_t> &&
              !nmea::detail::is_unsigned_integer_field<char8_t> &&
              nmea::detail::is_unsigned_integer_field<unsigned char>);
// Nor an NMEA 2000 field's physical value, by from() or assign().
template <class N, class V>
concept n2k_takes = requires(N n, V v) {
  N::from(v);
  n.assign(v);
};
using n2k_speed = nmea2000::unsigned_number<16, nmea2000::resolution{1, -2}>;
static_assert(n2k_takes<n2k_speed, int> && n2k_takes<n2k_speed, double> &&
              n2k_takes<n2k_speed, decimal>);
static_assert(!n2k_takes<n2k_speed, char> && !n2k_takes<n2k_speed, bool> &&
              !n2k_takes<n2k_speed, char8_t> && !n2k_takes<n2k_speed, wchar_t>);
static_assert(!member_takes<&standard::rpm::number, char8_t> &&
              !member_takes<&standard::rpm::number, char16_t> &&
              !member_takes<&standard::rpm::number, char32_t> &&
              !member_takes<&standard::rpm::number, wchar_t>);
// Compared with any whole number as numbers, never through a character type.
template <class L, class R>
concept comparable_with = requires(const L& l, const R& r) {
  l == r;
};
static_assert(comparable_with<nmea::integer<std::uint8_t>, long> &&
              !comparable_with<nmea::integer<std::uint8_t>, char8_t>);
static_assert(nmea::integer<std::uint32_t>{~0ULL} != 5 &&
              !nmea::integer<std::uint32_t>{~0ULL}.fits());  // kept outside T: refused
// Read back as T only on request: a value assigned outside T would come back wrapped.
static_assert(!std::is_convertible_v<nmea::integer<std::uint8_t>, std::uint8_t> &&
              std::is_constructible_v<std::uint8_t, nmea::integer<std::uint8_t>>);
static_assert(!member_takes<&standard::rmc::lat, double>);
static_assert(!member_takes<&standard::rmc::time, double>);
static_assert(!member_takes<&standard::rmc::magnetic_variation, double>);
static_assert(!member_takes<&robotx::rxhrb::lat, double>);

// The ways that say how many places.
static_assert(1.5_dec == decimal::scaled(15, 1));
static_assert(4.50_dec == decimal::scaled(450, 2) && 4.50_dec != 4.5_dec);
static_assert(45_dec == decimal{45});
static_assert(-1.5_dec == decimal::scaled(-15, 1));
static_assert((-0.0_dec).negative && (-0.0_dec).is_zero());
static_assert(decimal::parse("1.5").value == 1.5_dec);
static_assert(decimal::parse("-203.10").value == decimal::scaled(-20310, 2));
static_assert(decimal::parse("+1.5").ec == errc::bad_number);  // senders never write '+'
static_assert(decimal::parse("1e5").ec == errc::bad_number);
static_assert(decimal::parse("").ec == errc::bad_number);
static_assert(decimal::parse("12345678901234567890").ec == errc::number_too_long);
static_assert(decimal::from_double(1.5, 1).value == 1.5_dec);
static_assert(decimal::from_double(203.1, 2).value == decimal::scaled(20310, 2));

// No message has a plain integer field (it would take a double and cut it): each one is an
// nmea::integer, so the checks above hold for every field, not only the ones listed.
template <class M>
consteval bool no_plain_integer_fields() {
  bool ok = true;
  M::nmea.fields.apply([&](const auto&... d) {
    ((ok = ok && !(std::is_integral_v<typename std::remove_cvref_t<decltype(d)>::value_type> &&
                   !std::is_same_v<typename std::remove_cvref_t<decltype(d)>::value_type, bool>)),
     ...);
  });
  return ok;
}
template <class... Ms>
consteval bool no_plain_integer_fields(nmea::message_set<Ms...>*) {
  return (no_plain_integer_fields<Ms>() && ...);
}
using every_message =
    nmea::merge_sets<kingfisher::from_vehicle, kingfisher::to_vehicle, sandshark::from_vehicle,
                     sandshark::to_vehicle, robotx::reports, anello::nmea_inputs,
                     anello::nmea_outputs>::type;
static_assert(no_plain_integer_fields(static_cast<every_message*>(nullptr)));

// A whole number compares as the number it is, not as its type's wrapped value.
static_assert(nmea::integer<std::uint8_t>{300} != 44 && nmea::integer<std::uint8_t>{300} == 300);
static_assert(nmea::integer<std::uint8_t>{7} < 8 && 8 > nmea::integer<std::uint8_t>{7});
static_assert(!nmea::integer<std::uint8_t>{-1}.fits() && nmea::integer<std::int8_t>{-1}.fits());

}  // namespace

TEST_CASE("whole numbers: kept whole, checked against their type when encoded") {
  const auto start = nmea::decode<standard::gga>(
      support::sealed("GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"));
  REQUIRE(start);
  standard::gga g = start.value;
  g.satellites = 8;
  const auto n = static_cast<std::uint8_t>(*g.satellites);  // as its type, on request
  CHECK(n == 8);
  auto ok = nmea::encode(g);
  REQUIRE(ok);
  CHECK(ok.view().find(",08,") != std::string_view::npos);  // two digits, as GGA has them

  // 300 does not go out as 44: the field is refused, by number.
  g.satellites = 300;
  CHECK(*g.satellites == 300);
  const auto bad = nmea::encode(g);
  CHECK(bad.ec == errc::out_of_range);
  CHECK(nmea::field_name<standard::gga>(bad.field) == "satellites");
  g.satellites = -1;
  CHECK(nmea::encode(g).ec == errc::out_of_range);

  // Decoded values are within the type; a sender's 300 is refused at decode.
  const auto d = nmea::decode<standard::gga>(
      support::sealed("GPGGA,123519,4807.038,N,01131.000,E,1,300,0.9,545.4,M,46.9,M,,"));
  CHECK(d.ec == errc::out_of_range);
  CHECK(d.field == 7);

  const auto ack = nmea::decode<sandshark::bfack>("$BFACK,081025.990,RMB,081025.950,,2,0,*32\r\n");
  REQUIRE(ack);
  sandshark::bfack a = ack.value;
  a.behavior_id = -7;
  CHECK(nmea::encode(a).view() == "$BFACK,081025.990,RMB,081025.950,-7,2,0,*28\r\n");
  CHECK(a.behavior_id == -7);
  a.behavior_id = std::int64_t{1} << 40;
  const auto too_big = nmea::encode(a);
  CHECK(too_big.ec == errc::out_of_range);
  CHECK(nmea::field_name<sandshark::bfack>(too_big.field) == "behavior_id");
}

TEST_CASE("decimal: integers convert, the scaled form is named, text and literals are exact") {
  decimal d = 45;
  CHECK(d.mantissa == 45);
  CHECK(d.places == 0);
  d = -7;
  CHECK(d.negative);
  CHECK(d.mantissa == 7);
  CHECK(decimal::scaled(15, 1).to_double() == 1.5);
  CHECK(decimal::scaled(-15, 1).to_double() == -1.5);
  CHECK(decimal::scaled(std::uint64_t{18'000'000'000'000'000'000ULL}, 0).mantissa ==
        18'000'000'000'000'000'000ULL);
  CHECK(decimal::scaled(1, 300).places == 255);  // refused when written (value_too_large)

  const auto p = decimal::parse("0.145");
  REQUIRE(p);
  CHECK(p.value == decimal::scaled(145, 3));
  CHECK(decimal::parse("1.5.0").ec == errc::bad_number);
  CHECK(decimal::parse(" 1.5").ec == errc::bad_number);
  CHECK(decimal::parse("abc").value == decimal{});

  kingfisher::pydev dev;
  dev.heading_deg = 203.1_dec;
  dev.speed_mps = 1.5_dec;
  const auto sentence = nmea::encode(dev);
  REQUIRE(sentence);
  CHECK(sentence.view() == "$PYDEV,203.1,1.5*5A\r\n");
}
