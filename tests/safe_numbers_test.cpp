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
concept member_takes =
    assignable_from<typename nmea::detail::member_pointer_traits<decltype(Member)>::member_type, V>;
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

}  // namespace

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
