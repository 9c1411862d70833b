// SPDX-License-Identifier: BSL-1.0
// One rounding rule for every double that becomes a wire number: the double's shortest decimal
// (what std::to_chars writes), rounded half away from zero to the places or step the wire needs.
// Checked path by path (decimal::from_double, positions, magnetic variation, nmea::builder,
// nmea2000::number::from, the ANELLO frame) against a table Python's decimal module computed
// (tests/data/rounding_table.txt, checked by tests/rounding_table.py), and the
// shortest digits against std::to_chars over many random doubles.

#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <system_error>

#include "seawire/seawire.hpp"

namespace {

using namespace seawire;
using namespace seawire::nmea::literals;
using nmea::decimal;
using nmea::latitude;
using nmea::longitude;
using seawire::detail::shortest_decimal;

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

constexpr shortest_decimal shortest_of(double v) {
  shortest_decimal s;
  (void)seawire::detail::shortest(v, s);
  return s;
}
constexpr bool is_shortest(double v, std::uint64_t digits, int exponent) {
  const shortest_decimal s = shortest_of(v);
  return s.digits == digits && s.exponent == exponent;
}

// The shortest digits, in constant expressions too.
static_assert(is_shortest(1.005, 1005, -3));
static_assert(is_shortest(2.675, 2675, -3));
static_assert(is_shortest(0.1 + 0.2, 30000000000000004, -17));
static_assert(is_shortest(1.0000000000000002, 10000000000000002, -16));
static_assert(is_shortest(1e23, 1, 23));
static_assert(is_shortest(5e-324, 5, -324));
static_assert(is_shortest(1.7976931348623157e308, 17976931348623157, 292));
static_assert(is_shortest(0.0, 0, 0) && !shortest_of(0.0).negative && shortest_of(-0.0).negative);
static_assert(is_shortest(100.0, 1, 2));

// And the rule on each path, in constant expressions.
static_assert(decimal::from_double(1.005, 2).value == decimal::scaled(101, 2));
static_assert(decimal::from_double(2.675, 2).value == decimal::scaled(268, 2));
static_assert(decimal::from_double(-1.005, 2).value == -decimal::scaled(101, 2));
static_assert(decimal::from_double(0.125, 2).value == decimal::scaled(13, 2));
static_assert(decimal::shortest(203.1).value == 203.1_dec);
static_assert(nmea2000::unsigned_number<16, nmea2000::res::hundredth>::from(1.005).value.raw() ==
              101);
static_assert(latitude::from_degrees(0.000125, 3).value.minutes == decimal::scaled(8, 3));

/// The round_scaled helper itself: m x 10^t / den, halves away from zero, exactly.
constexpr std::uint64_t scaled(std::uint64_t m, int t, std::uint64_t den) {
  std::uint64_t q = 0;
  return seawire::detail::round_scaled(m, t, den, q) ? q : ~std::uint64_t{0};
}

TEST_CASE("round_scaled: halves away from zero, exactly, at every scale") {
  CHECK(scaled(1005, -1, 1) == 101);
  CHECK(scaled(1004, -1, 1) == 100);
  CHECK(scaled(15, 0, 10) == 2);
  CHECK(scaled(14, 0, 10) == 1);
  CHECK(scaled(1005, -3, 4) == 0);   // 0.25125 of a step
  CHECK(scaled(1005, 0, 4) == 251);  // 251.25
  CHECK(scaled(1002, 0, 4) == 251);  // 250.5: the tie goes up
  CHECK(scaled(7, 18, 1) == 7'000'000'000'000'000'000ULL);
  CHECK(scaled(19, 18, 1) == ~std::uint64_t{0});  // 1.9e19 does not fit 64 bits
  CHECK(scaled(1, 20, 1) == ~std::uint64_t{0});
  CHECK(scaled(~std::uint64_t{0}, 0, 1) == ~std::uint64_t{0} - 0);  // fits exactly
  CHECK(scaled(5'000'000'000'000'000'000ULL, -19, 1) == 1);         // 0.5
  CHECK(scaled(4'999'999'999'999'999'999ULL, -19, 1) == 0);
  CHECK(scaled(9'999'999'999'999'999'999ULL, -20, 1) == 0);  // 0.0999...
  CHECK(scaled(0, 400, 1) == 0);
  // A divisor times 10^k beyond 64 bits: the halves still compare exactly.
  CHECK(scaled(10'000'000'000'000'000'000ULL, -19, 3) == 0);  // 1/3
  CHECK(scaled(15'000'000'000'000'000'000ULL, -19, 3) == 1);  // 1/2
  CHECK(scaled(14'999'999'999'999'999'999ULL, -19, 3) == 0);
  // Against the plain computation over many random cases where den x 10^-t fits 64 bits.
  std::mt19937_64 rng(7);
  for (int i = 0; i < 100000; ++i) {
    const std::uint64_t m = rng() >> (rng() % 64);
    const int t = -static_cast<int>(rng() % 16);
    const std::uint64_t den = 1 + rng() % 5000;
    const std::uint64_t divisor = seawire::detail::pow10_table[-t] * den;  // below 5e18
    const std::uint64_t want = m / divisor + (2 * (m % divisor) >= divisor ? 1 : 0);
    INFO(m << " " << t << " " << den);
    REQUIRE(scaled(m, t, den) == want);
  }
}

TEST_CASE("shortest: the digits std::to_chars writes, for any double") {
  std::mt19937_64 rng(11);
  const auto check = [](double v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
    const std::string text(buf, r.ptr);
    std::uint64_t digits = 0;
    int fraction = 0;
    bool point = false;
    std::size_t i = text[0] == '-' ? 1 : 0;
    for (; text[i] != 'e'; ++i) {
      if (text[i] == '.') {
        point = true;
        continue;
      }
      digits = digits * 10 + static_cast<std::uint64_t>(text[i] - '0');
      if (point) ++fraction;
    }
    int exponent = std::stoi(text.substr(i + 1)) - fraction;
    while (digits != 0 && digits % 10 == 0) {
      digits /= 10;
      ++exponent;
    }
    if (digits == 0) exponent = 0;
    shortest_decimal s;
    REQUIRE(seawire::detail::shortest(v, s) == errc::ok);
    INFO(text);
    REQUIRE(s.digits == digits);
    REQUIRE(s.exponent == exponent);
    REQUIRE(s.negative == std::signbit(v));
  };
  for (int i = 0; i < 100000; ++i) {  // any bit pattern
    const std::uint64_t bits = rng();
    double v = 0;
    std::memcpy(&v, &bits, sizeof v);
    if (std::isfinite(v)) check(v);
  }
  for (int e = -1074; e <= 1023; ++e) {  // powers of two (the interval is lopsided there)
    const double v = std::ldexp(1.0, e);
    check(v);
    check(std::nextafter(v, 0.0));
    if (e < 1023) check(std::nextafter(v, inf));
  }
  for (int i = 0; i < 20000; ++i) check(static_cast<double>(rng() % 100'000'000) / 1000.0);
  shortest_decimal s;
  CHECK(seawire::detail::shortest(nan, s) == errc::not_finite);
  CHECK(seawire::detail::shortest(-inf, s) == errc::not_finite);
}

TEST_CASE("round_double: deciding from the double agrees with the shortest digits") {
  // round_double skips the shortest digits when no tie is near; it must give what rounding
  // the shortest digits gives, for ties (k / 10^j written with a last 5) and any other value.
  std::mt19937_64 rng(3);
  const std::uint64_t dens[] = {1, 4, 25, 3, 1'000'000'007};
  std::size_t decided_by_digits = 0;
  for (int i = 0; i < 300000; ++i) {
    double v = 0;
    if (i % 2 == 0) {
      const auto j = static_cast<int>(rng() % 12);
      v = static_cast<double>(rng() % 100'000'000) /
          static_cast<double>(seawire::detail::pow10_table[j]);
    } else {
      const std::uint64_t bits =
          (rng() & 0x800F'FFFF'FFFF'FFFFULL) | ((980 + rng() % 100) << 52U);  // 2^-43 .. 2^56
      std::memcpy(&v, &bits, sizeof v);
    }
    if (rng() % 2 == 0) v = -v;
    const std::uint64_t mul = rng() % 2 == 0 ? 1 : 60;
    const int t = static_cast<int>(rng() % 24) - 4;
    const std::uint64_t den = dens[rng() % 5];
    seawire::detail::rounded_double got;
    const errc e = seawire::detail::round_double(v, mul, t, den, got);
    const shortest_decimal s = shortest_of(v);
    std::uint64_t want = 0;
    const bool fits = seawire::detail::round_scaled(s.digits * mul, s.exponent + t, den, want);
    INFO(v << " x " << mul << " x 10^" << t << " / " << den);
    if (fits) {
      REQUIRE(e == errc::ok);
      REQUIRE(got.magnitude == want);
    } else {
      // The digits' product passed 64 bits; the quotient may still fit (a large den), and then
      // only the double decided it.
      REQUIRE((e == errc::value_too_large || den > 1));
    }
    REQUIRE(got.negative == std::signbit(v));
    // How often the digits were needed: a tie within the double's interval.
    const double scaled_value =
        std::fabs(v) * static_cast<double>(mul) * std::pow(10.0, t) / static_cast<double>(den);
    if (std::fabs(scaled_value - std::floor(scaled_value) - 0.5) < 1e-9) ++decided_by_digits;
  }
  CHECK(decided_by_digits > 1000);  // ties were among the cases
  seawire::detail::rounded_double r;
  CHECK(seawire::detail::round_double(nan, 1, 0, 1, r) == errc::not_finite);
  CHECK(seawire::detail::round_double(-inf, 1, 0, 1, r) == errc::not_finite);
}

/// A row of tests/data/rounding_table.txt.
struct row {
  double x = 0;
  std::string text;  // repr
  std::string kind;
  std::string param;
  std::string expected;
};

std::vector<row> table() {
  std::ifstream in(SEAWIRE_TEST_DATA_DIR "/rounding_table.txt");
  std::vector<row> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    row r;
    std::string hex;
    words >> hex >> r.text >> r.kind >> r.param >> r.expected;
    const bool negative = hex[0] == '-';
    const std::string body = hex.substr(negative ? 3 : 2);  // without the sign and "0x"
    const auto [p, ec] =
        std::from_chars(body.data(), body.data() + body.size(), r.x, std::chars_format::hex);
    REQUIRE(ec == std::errc{});
    REQUIRE(p == body.data() + body.size());
    if (negative) r.x = -r.x;
    rows.push_back(r);
  }
  return rows;
}

/// The signed integer of an expected column ("-101"), and whether it is one.
bool expected_int(const std::string& s, std::int64_t& v, std::uint64_t& magnitude, bool& negative) {
  if (s == "!") return false;
  negative = s[0] == '-';
  magnitude = std::stoull(s.substr(negative ? 1 : 0));
  v = negative ? -static_cast<std::int64_t>(magnitude) : static_cast<std::int64_t>(magnitude);
  return true;
}

template <nmea2000::resolution R>
void check_n2k(const row& r) {
  const auto got = nmea2000::signed_number<32, R>::from(r.x);
  std::int64_t want = 0;
  std::uint64_t mag = 0;
  bool neg = false;
  if (!expected_int(r.expected, want, mag, neg)) {
    CHECK(got.ec == errc::out_of_range);
    return;
  }
  REQUIRE(got.ec == errc::ok);
  CHECK(got.value.raw() == want);
}

TEST_CASE("every path rounds as Python's decimal module does (rounding_table.txt)") {
  const std::vector<row> rows = table();
  REQUIRE(rows.size() > 5000);
  std::size_t ties = 0;
  for (const row& r : rows) {
    INFO(r.text << " " << r.kind << " " << r.param << " -> " << r.expected);
    std::int64_t want = 0;
    std::uint64_t mag = 0;
    bool neg = false;
    const bool fits = expected_int(r.expected, want, mag, neg);
    if (r.kind == "dec") {
      const auto places = static_cast<unsigned>(std::stoi(r.param));
      const result<decimal> d = decimal::from_double(r.x, places);
      if (!fits) {
        CHECK(d.ec == errc::value_too_large);
        continue;
      }
      REQUIRE(d.ec == errc::ok);
      CHECK(d.value.mantissa == mag);
      CHECK(d.value.places == places);
      CHECK(d.value.negative == neg);  // a value that rounds to zero is the plain zero
      if (r.text.size() > 2 && r.text.back() == '5') ++ties;
      // The magnetic variation and decimal-degree positions round the magnitude the same way.
      if (places <= 15 && mag <= 180 * seawire::detail::pow10_table[places]) {
        const auto v = nmea::magnetic_variation::from_degrees(r.x, places);
        REQUIRE(v.ec == errc::ok);
        CHECK(v.value.value->mantissa == mag);
        CHECK(v.value.direction == (neg ? nmea::hemisphere::west : nmea::hemisphere::east));
        const auto lon = nmea::decimal_longitude::from_degrees(r.x, places);
        REQUIRE(lon.ec == errc::ok);
        CHECK(lon.value.value.mantissa == mag);
        CHECK(lon.value.hemi == (neg ? nmea::hemisphere::west : nmea::hemisphere::east));
      }
      // The ANELLO frame: altitude in tenths, latitude in millionths, motor in whole percent.
      anello::sensor_values values;
      if (places == 1 && mag <= 2'147'483'646) {
        values.alt_msl_m = r.x;
        const auto f = anello::build_frame(values);
        REQUIRE(f.ec == errc::ok);
        CHECK(f.value.alt_msl == want);
      } else if (places == 6 && mag <= 90'000'000) {
        values.latitude_deg = r.x;
        const auto f = anello::build_frame(values);
        REQUIRE(f.ec == errc::ok);
        CHECK(f.value.lat == want);
      } else if (places == 0 && mag <= 100) {
        values.motor_pct = r.x;
        const auto f = anello::build_frame(values);
        REQUIRE(f.ec == errc::ok);
        CHECK(f.value.motor == want);
      }
    } else if (r.kind == "n2k") {
      namespace res = nmea2000::res;
      if (r.param == "unit") check_n2k<nmea2000::resolution{}>(r);
      if (r.param == "quarter") check_n2k<res::quarter>(r);
      if (r.param == "hundred") check_n2k<res::hundred>(r);
      if (r.param == "thousand") check_n2k<res::thousand>(r);
      if (r.param == "tenth") check_n2k<res::tenth>(r);
      if (r.param == "hundredth") check_n2k<res::hundredth>(r);
      if (r.param == "thousandth") check_n2k<res::thousandth>(r);
      if (r.param == "humidity") check_n2k<res::humidity>(r);
    } else {
      REQUIRE(r.kind == "lon");
      const auto places = static_cast<unsigned>(std::stoi(r.param));
      const auto lon = longitude::from_degrees(r.x, places);
      if (!fits) {
        CHECK(lon.ec == errc::out_of_range);
        continue;
      }
      REQUIRE(lon.ec == errc::ok);
      const std::uint64_t per_degree = 60 * seawire::detail::pow10_table[places];
      CHECK(lon.value.whole_degrees == mag / per_degree);
      CHECK(lon.value.minutes.mantissa == mag % per_degree);
      CHECK(lon.value.minutes.places == places);
      CHECK(lon.value.hemi == (neg ? nmea::hemisphere::west : nmea::hemisphere::east));
      const auto lat = latitude::from_degrees(r.x, places);
      if (mag <= 90 * per_degree) {
        REQUIRE(lat.ec == errc::ok);
        CHECK(lat.value.whole_degrees == lon.value.whole_degrees);
        CHECK(lat.value.minutes == lon.value.minutes);
      } else {
        CHECK(lat.ec == errc::out_of_range);
      }
    }
  }
  CHECK(ties > 100);  // the table is rich in halfway cases
}

TEST_CASE("decimal::from_double: the quoted halfway cases, zeros, limits, refusals") {
  struct quoted {
    double v;
    unsigned places;
    std::string_view text;
  };
  for (const quoted& q : std::initializer_list<quoted>{
           {1.005, 2, "1.01"},
           {2.675, 2, "2.68"},
           {-1.005, 2, "-1.01"},
           {0.125, 2, "0.13"},
           {1.115, 2, "1.12"},
           {1e-7, 2, "0.00"},
           {-0.001, 2, "0.00"},  // the plain zero: the wire's value is zero
           {-0.0, 1, "0.0"},
           {1.0000000000000002, 15, "1.000000000000000"},
           {1.0000000000000002, 16, "1.0000000000000002"},
           {0.49999999999999994, 0, "0"},  // shortest 0.49999999999999994: below the half
           {4503599627370497.0, 0, "4503599627370497"},
           {9.999999999999998e18, 0, "9999999999999998000"},  // not ...7952: shortest digits,
           {0.1, 19, "0.1000000000000000000"},
           {1.2345678901234567e-10, 19, "0.0000000001234567890"},
       }) {
    INFO(q.v << " at " << q.places);
    const auto d = decimal::from_double(q.v, q.places);
    REQUIRE(d.ec == errc::ok);
    CHECK(d.value == decimal::parse(q.text).value);
  }
  CHECK(decimal::from_double(nan, 2).ec == errc::not_finite);
  CHECK(decimal::from_double(inf, 2).ec == errc::not_finite);
  CHECK(decimal::from_double(-inf, 0).ec == errc::not_finite);
  CHECK(decimal::from_double(1e19, 0).ec == errc::value_too_large);  // 20 digits
  CHECK(decimal::from_double(123456789012345678.0, 2).ec == errc::value_too_large);
  CHECK(decimal::from_double(1.0, 19).ec == errc::value_too_large);
  CHECK(decimal::from_double(0.5, 20).ec == errc::value_too_large);  // past 19 places
  // Text keeps a written "-0.00": only a double's zero is plain.
  CHECK(decimal::parse("-0.00").value.negative);
  CHECK(decimal::shortest(-0.0).value == decimal{});
  CHECK(decimal::shortest(1e-20).ec == errc::value_too_large);  // 20 places
  CHECK(decimal::shortest(1e19).ec == errc::value_too_large);   // 20 digits
  CHECK(decimal::shortest(nan).ec == errc::not_finite);
}

TEST_CASE("positions: the minutes of the shortest degrees, ties away from zero, carries") {
  // 0.000125 degrees is 0.0075 minutes: a tie at three places.
  auto lat = latitude::from_degrees(0.000125, 3);
  REQUIRE(lat);
  CHECK(lat.value.minutes == decimal::scaled(8, 3));
  lat = latitude::from_degrees(-0.000125, 3);
  REQUIRE(lat);
  CHECK(lat.value.minutes == decimal::scaled(8, 3));
  CHECK(lat.value.hemi == nmea::hemisphere::south);
  // 42.000175 degrees is 42 degrees 0.0105 minutes: 0.011 at three places (the double's own
  // value, 42.00017499999999..., would give 0.010).
  lat = latitude::from_degrees(42.000175, 3);
  REQUIRE(lat);
  CHECK(lat.value.whole_degrees == 42);
  CHECK(lat.value.minutes == decimal::scaled(11, 3));
  // 59.99995' rounds up into the next degree; at the range's edge, only exactly 90 remains.
  auto lon = longitude::from_degrees(10.9999999999, 3);
  REQUIRE(lon);
  CHECK(lon.value.whole_degrees == 11);
  CHECK(lon.value.minutes == decimal::scaled(0, 3));
  CHECK(latitude::from_degrees(89.99999999999999, 4).value.whole_degrees == 90);
  CHECK(latitude::from_degrees(90.0001, 4).ec == errc::out_of_range);
  CHECK(longitude::from_degrees(180.00000000000003, 12).ec == errc::out_of_range);
  CHECK(longitude::from_degrees(-180.0, 12).value.whole_degrees == 180);
  // Rounded to zero: the plain zero, N or E (the value on the wire is zero).
  lat = latitude::from_degrees(-1e-9, 4);
  REQUIRE(lat);
  CHECK(lat.value.minutes.is_zero());
  CHECK(lat.value.hemi == nmea::hemisphere::north);
  CHECK(nmea::decimal_latitude::from_degrees(-0.000001, 5).value.hemi == nmea::hemisphere::north);
  CHECK(nmea::magnetic_variation::from_degrees(-0.04, 1).value.direction == nmea::hemisphere::east);
  CHECK(nmea::magnetic_variation::from_degrees(-0.05, 1).value.direction == nmea::hemisphere::west);
  CHECK(latitude::from_degrees(nan).ec == errc::not_finite);
  CHECK(longitude::from_degrees(-inf).ec == errc::not_finite);
  CHECK(nmea::decimal_latitude::from_degrees(inf).ec == errc::not_finite);
  CHECK(nmea::magnetic_variation::from_degrees(nan).ec == errc::not_finite);
}

TEST_CASE("builder: declared places, places{n} and shortest all follow the rule") {
  const auto r = nmea::builder<standard::gga>{}
                     .set<&standard::gga::hdop>(1.005)  // declared: 2 places
                     .set<&standard::gga::altitude_m>(2.675, nmea::places{2})
                     .set<&standard::gga::geoid_separation_m>(-1.005, nmea::places{2})
                     .set<&standard::gga::lat>(0.000125, nmea::places{3})
                     .set<&standard::gga::dgps_age_s>(0.1 + 0.2, nmea::shortest)
                     .result();
  REQUIRE(r);
  CHECK(*r.value.hdop == 1.01_dec);
  CHECK(*r.value.altitude_m == 2.68_dec);
  CHECK(*r.value.geoid_separation_m == -1.01_dec);
  CHECK(r.value.lat->minutes == decimal::scaled(8, 3));
  CHECK(*r.value.dgps_age_s == 0.30000000000000004_dec);
  // -0.0 and values that round to zero are written as the plain zero.
  const auto z = nmea::builder<standard::gga>{}
                     .set<&standard::gga::altitude_m>(-0.04)
                     .set<&standard::gga::geoid_separation_m>(-0.0, nmea::shortest)
                     .result();
  REQUIRE(z);
  CHECK(*z.value.altitude_m == 0.0_dec);
  CHECK(*z.value.geoid_separation_m == 0_dec);
  // The shortest mode is a constant expression too.
  static_assert(nmea::builder<standard::gga>{}
                    .set<&standard::gga::hdop>(0.7, nmea::shortest)
                    .message()
                    .hdop == 0.7_dec);
  const auto bad = nmea::builder<standard::gga>{}.set<&standard::gga::hdop>(nan).result();
  CHECK(bad.ec == errc::not_finite);
  CHECK(nmea::field_name<standard::gga>(bad.field) == "hdop");
}

TEST_CASE("NMEA 2000 number::from: every resolution the PGNs declare, at the range's edges") {
  namespace res = nmea2000::res;
  using nmea2000::signed_number;
  using nmea2000::unsigned_number;
  CHECK(unsigned_number<16, res::hundredth>::from(1.005).value.raw() == 101);
  CHECK(signed_number<16, res::hundredth>::from(-1.005).value.raw() == -101);
  CHECK(signed_number<16, res::thousandth>::from(2.6745).value.raw() == 2675);
  CHECK(unsigned_number<16, res::quarter>::from(0.125).value.raw() == 1);  // 0.5 step
  CHECK(unsigned_number<16, res::quarter>::from(0.124).value.raw() == 0);
  CHECK(unsigned_number<16, res::tenth>::from(1.15).value.raw() == 12);
  CHECK(unsigned_number<16, res::hundred>::from(150.0).value.raw() == 2);
  CHECK(unsigned_number<16, res::thousand>::from(2500.0).value.raw() == 3);
  CHECK(signed_number<16, res::humidity>::from(0.002).value.raw() == 1);  // a half step
  CHECK(signed_number<16, res::humidity>::from(-0.002).value.raw() == -1);
  CHECK(unsigned_number<8>::from(2.5).value.raw() == 3);
  // Edges: 655.32 is the largest ordinary value of a 16-bit hundredth (the top three are
  // sentinels); 655.325 rounds past it.
  CHECK(unsigned_number<16, res::hundredth>::from(655.32).value.raw() == 65532);
  CHECK(unsigned_number<16, res::hundredth>::from(655.324).value.raw() == 65532);
  CHECK(unsigned_number<16, res::hundredth>::from(655.325).ec == errc::out_of_range);
  CHECK(unsigned_number<16, res::hundredth>::from(-0.005).ec == errc::out_of_range);
  CHECK(unsigned_number<16, res::hundredth>::from(-0.0049).value.raw() == 0);
  CHECK(signed_number<16, res::thousandth>::from(-32.768).value.raw() == -32768);
  CHECK(signed_number<16, res::thousandth>::from(-32.7685).ec == errc::out_of_range);
  CHECK(signed_number<16, res::thousandth>::from(1e300).ec == errc::out_of_range);
  CHECK(signed_number<16, res::thousandth>::from(1e-300).value.raw() == 0);
  CHECK(signed_number<16, res::thousandth>::from(nan).ec == errc::not_finite);
  CHECK(signed_number<16, res::thousandth>::from(-inf).ec == errc::not_finite);
  // A decimal rounds by the same arithmetic as a double's shortest digits.
  CHECK(unsigned_number<16, res::hundredth>::from(1.005_dec).value.raw() == 101);
  CHECK(signed_number<16, res::humidity>::from(-0.006_dec).value.raw() == -2);  // -1.5 steps
  // Through a PGN's member.
  nmea2000::speed_water_referenced m;
  REQUIRE(m.speed_water_mps.assign(2.675) == errc::ok);
  CHECK(m.speed_water_mps.raw() == 268);
}

TEST_CASE("ANELLO frame: sensor values rounded by the rule, refused precisely") {
  anello::sensor_values v;
  v.sog_mps = 1.05;             // tenths: 10.5 steps
  v.alt_msl_m = -2.675;         // tenths: -26.75
  v.latitude_deg = 42.0000005;  // millionths: a tie
  v.heading_deg = 359.5;        // whole degrees
  auto f = anello::build_frame(v);
  REQUIRE(f.ec == errc::ok);
  CHECK(f.value.sog == 11);
  CHECK(f.value.alt_msl == -27);
  CHECK(f.value.lat == 42000001);
  CHECK(f.value.heading == 360);
  v.heading_deg = 360.5;  // rounds to 361: beyond the spec's 0..360
  f = anello::build_frame(v);
  CHECK(f.ec == errc::out_of_range);
  CHECK(f.field == 1);
  v.heading_deg = nan;
  f = anello::build_frame(v);
  CHECK(f.ec == errc::not_finite);
  CHECK(f.field == 1);
  v.heading_deg = 1e300;
  CHECK(anello::build_frame(v).ec == errc::out_of_range);
  v.heading_deg.reset();
  v.air_temp_c = -0.05;  // -0.1 C is the field's "not available": refused
  CHECK(anello::build_frame(v).ec == errc::value_too_large);
  v.air_temp_c = -0.04;
  CHECK(anello::build_frame(v).value.air_temp == 0);
}

}  // namespace
