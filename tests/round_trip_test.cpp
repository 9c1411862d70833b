// SPDX-License-Identifier: BSL-1.0
// Every message of seawire/registry.hpp, with values drawn from the domain its description
// declares (tests/generate.hpp): encode must write it, decode must read it back to the same values
// under the strict policy, the default one and the role's own (by the message type and through
// its message set), and what decode gives must encode to the same bytes. The same for every PGN
// (encode, decode, encode again) and the 0xAB00 frame.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>

#include "../fuzz/fuzz_common.hpp"
#include "generate.hpp"
#include "seawire/anello/frame.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/registry.hpp"
#include "support.hpp"

namespace nm = seawire::nmea;
namespace rx = seawire::robotx;
namespace registry = seawire::registry;

/// RobotX light patterns: three colours.
template <>
struct support::values<rx::light_pattern> {
  static void fill(prng& g, rx::light_pattern& p, const nm::field_options&) {
    constexpr std::string_view letters = seawire::nmea::enum_letters<rx::color>;
    for (auto& c : p.colors) c = static_cast<rx::color>(letters[g.below(letters.size())]);
  }
};

namespace {

/// What decode(encode(m)) must give: the same values field by field and the same talker (the
/// fuzz targets' definition), and the same message, but for a message that keeps the field count
/// it was decoded from, which may differ in that count only.
template <nm::message_like M>
bool same_values(const M& a, const M& b) {
  if (!seawire::fuzz::same_message(a, b)) return false;
  if constexpr (!nm::keeps_wire_fields<M> && std::equality_comparable<M>) return a == b;
  return true;
}

struct counts {
  int messages = 0;
  int failures = 0;
};

template <class Set, nm::message_like M>
void round_trip(support::prng& g, const nm::parse_policy& role, int iterations, counts& c) {
  for (int i = 0; i < iterations && c.failures < 5; ++i) {
    const M m = support::generate<M>(g);
    const auto first = nm::encode(m);
    if (!first) {
      FAIL_CHECK(M::nmea.address << ": a value inside the declared domain was refused: "
                                 << seawire::name(first.ec) << " field " << first.field << " ("
                                 << nm::field_name<M>(first.field) << ")");
      ++c.failures;
      continue;
    }
    ++c.messages;
    const std::string line(first.view());
    bool ok = true;
    // The sentence from '$' to the checksum, without its CR LF: what max_length bounds.
    const std::size_t length = line.size() - 2;
    for (const nm::parse_policy& p : {nm::parse_policy::strict(), nm::parse_policy{}, role}) {
      const auto back = nm::decode<M>(line, p);
      const auto via_set = Set::decode(line, p);
      if (length > p.max_length) {
        // Longer than this receiver takes (BFMIS's three texts can be): refused as too long.
        if (back.ec != seawire::errc::too_long || via_set.ec != seawire::errc::too_long) {
          FAIL_CHECK(M::nmea.address << ": a sentence of " << length << " bytes, longer than "
                                     << p.max_length << ", was not refused as too long");
          ok = false;
        }
        continue;
      }
      const bool this_ok =
          back && same_values(back.value, m) && nm::encode(back.value).view() == line && via_set &&
          std::holds_alternative<M>(via_set.value) && same_values(std::get<M>(via_set.value), m);
      if (!this_ok) {
        FAIL_CHECK(M::nmea.address << ": round trip failed for " << line << " ("
                                   << seawire::name(back.ec) << " field " << back.field << ")");
        ok = false;
      }
    }
    if (!ok) ++c.failures;
  }
}

template <class... Ms>
void round_trip_set(std::uint64_t seed, nm::message_set<Ms...>*, const nm::parse_policy& role,
                    int iterations) {
  using Set = nm::message_set<Ms...>;
  support::prng g{seed};
  (
      [&] {
        counts c;
        round_trip<Set, Ms>(g, role, iterations, c);
        INFO(Ms::nmea.address);
        CHECK(c.failures == 0);
        CHECK(c.messages == iterations);
      }(),
      ...);
}

constexpr int iterations = 2000;

// A generator for every message the registry lists: a message added there without one does not
// compile here.
template <class... T>
constexpr bool all_generated(registry::type_list<T...>*) {
  return (support::generated_type<T> && ...);
}
static_assert(all_generated(static_cast<registry::types<registry::sentences>*>(nullptr)));
static_assert(all_generated(static_cast<registry::types<registry::pgns>*>(nullptr)));
static_assert(all_generated(static_cast<registry::types<registry::frames>*>(nullptr)));

}  // namespace

TEST_CASE("round trip over the declared domains: every role of the registry", "[round_trip]") {
  std::uint64_t seed = 0;
  registry::for_each_role([&](const auto& role) {
    using Set = typename std::remove_cvref_t<decltype(role)>::set;
    INFO(role.title);
    round_trip_set(++seed, static_cast<Set*>(nullptr), role.policy, iterations);
  });
  CHECK(seed == std::tuple_size_v<std::remove_cvref_t<decltype(registry::roles)>>);
}

TEST_CASE("round trip over the declared domains: every PGN of the registry", "[round_trip]") {
  namespace n2k = seawire::nmea2000;
  support::prng g{9};
  registry::for_each_type<registry::pgns>([&](auto tag) {
    using P = typename decltype(tag)::type;
    INFO("PGN " << seawire::nmea2000::pgn_table<P>.info.pgn);
    int failures = 0;
    for (int i = 0; i < iterations && failures < 5; ++i) {
      const P m = support::generate<P>(g);
      const auto first = n2k::encode(m);
      const P back = n2k::decode<P>(first.value.view());
      const auto again = n2k::encode(back);
      if (!first || !(back == m) || !again ||
          !std::ranges::equal(again.value.view(), first.value.view())) {
        FAIL_CHECK("round trip failed (" << seawire::name(first.ec) << " field " << first.field
                                         << ")");
        ++failures;
      }
    }
    CHECK(failures == 0);
  });
}

TEST_CASE("round trip over the declared domains: the 0xAB00 frame", "[round_trip]") {
  namespace an = seawire::anello;
  support::prng g{10};
  registry::for_each_type<registry::frames>([&](auto tag) {
    using F = typename decltype(tag)::type;
    for (int i = 0; i < iterations; ++i) {
      const F frame = support::generate<F>(g);
      REQUIRE(an::validate(frame).ok());
      const auto bytes = an::encode_frame(frame);
      const auto back = an::decode_frame(bytes);
      REQUIRE(back.ok());
      CHECK(back.value == frame);
      const auto rebuilt = an::build_frame(an::to_values(frame));
      REQUIRE(rebuilt.ok());
      CHECK(rebuilt.value == frame);
    }
  });
}

TEST_CASE("the generator reaches the corners of each domain", "[round_trip]") {
  // The domain is what the description says; check that the generator visits its edges, so
  // that a passing round trip means the edges were tried.
  namespace kf = seawire::kingfisher;
  support::prng g{8};
  bool thrust_min = false;
  bool thrust_max = false;
  bool padded = false;
  bool empty_depth = false;
  bool six_field_cprbs = false;
  bool five_field_cprbs = false;
  for (int i = 0; i < 4000; ++i) {
    const auto dir = support::generate<kf::pydir>(g);
    thrust_min = thrust_min || dir.thrust_left == seawire::nmea::decimal(-100);
    thrust_max = thrust_max || dir.thrust_right == seawire::nmea::decimal(100);
    CHECK(dir.thrust_left.compare(-100) >= 0);
    CHECK(dir.thrust_left.compare(100) <= 0);
    const auto nvg = support::generate<kf::cpnvg>(g);
    padded = padded || nvg.lon.degree_digits == 3;
    empty_depth = empty_depth || !nvg.depth_m;
    if (nvg.heading_deg) CHECK(nvg.heading_deg->compare(360) <= 0);
    const auto rbs = support::generate<kf::cprbs>(g);
    const auto line = nm::encode(rbs);
    REQUIRE(line);
    const auto parsed = nm::parse(line.view());
    REQUIRE(parsed);
    six_field_cprbs = six_field_cprbs || parsed.value.field_count == 6;
    five_field_cprbs = five_field_cprbs || parsed.value.field_count == 5;
  }
  CHECK(thrust_min);
  CHECK(thrust_max);
  CHECK(padded);
  CHECK(empty_depth);
  CHECK(six_field_cprbs);
  CHECK(five_field_cprbs);
}

namespace {

/// decode as M (the default policy), then encode: the sentence --format nmea writes back.
template <nm::message_like M>
std::string written_back(const std::string& line) {
  const auto m = nm::decode<M>(line);
  if (!m) return std::string("decode: ") + std::string(seawire::name(m.ec));
  const auto out = nm::encode(m.value);
  if (!out) return std::string("encode: ") + std::string(seawire::name(out.ec));
  return std::string(out.view());
}

/// The same for the standard sentences the forms below are of, chosen by address.
std::string written_back_standard(const std::string& line) {
  namespace st = seawire::standard;
  const std::string_view address = std::string_view(line).substr(3, 3);
  if (address == "VHW") return written_back<st::vhw>(line);
  if (address == "RMC") return written_back<st::rmc>(line);
  if (address == "GGA") return written_back<st::gga>(line);
  if (address == "VWR") return written_back<st::vwr>(line);
  return "no message for " + line;
}

}  // namespace

TEST_CASE("forms kept and forms normalized, as docs/round-trip.md lists them", "[round_trip]") {
  namespace st = seawire::standard;
  using support::sealed;
  struct row {
    std::string received;
    std::string written;  // the same as received: kept as it came
  };
  const auto same = [](const std::string& s) { return row{s, s}; };
  const std::string rmc = "GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.011,,311214,";
  const std::string gga = "GPGGA,105027.80,5612.9900,N,01200.7600,E,1,03,2.5,160.0,";
  // Kept: what the wire says, in the forms real senders write.
  for (const row& r : {
           same(sealed("IIVHW,,T,,M,5.2,N,9.6,K")),  // blank values with their letters
           same(sealed(rmc + ",E,A")),               // a variation letter without a value
           same(sealed(rmc + ",W")),                 // the same in the 11-field RMC
           same(sealed(rmc + "15.3,W,A")),           // a variation with its letter
           same(sealed(gga + "M,,M,,")),             // GGA's blank geoid separation
           same(sealed(gga + "M,,,,")),              // ... with its letter blank too
           same(sealed("IIVHW,,,211.0,M,5.2,N,,")),  // blank letters beside blank values
           same(sealed("IIVHW,,T,,,5.2,N,,K")),      // some blank, some not
           same(sealed("GPGGA,105027.80,,,,,0,00,99.99,,,,,,")),  // u-blox without a fix
           same(sealed("GPGGA,105027.80,,,,,,,,,,,,,")),          // no fix, not even a quality
           same(sealed("WIVWR,45.0,L,,,,,,")),                    // one of VWR's three speeds
       }) {
    INFO(r.received);
    CHECK(written_back_standard(r.received) == r.written);
  }
  // Normalized, each row as the doc's table gives it. A value has its unit letter.
  CHECK(written_back<st::gga>(sealed(gga + ",,M,,")) == sealed(gga + "M,,M,,"));
  CHECK(written_back<st::vhw>(sealed("IIVHW,,,211.0,,5.2,N,,")) ==
        sealed("IIVHW,,,211.0,M,5.2,N,,"));
  CHECK(written_back<st::gga>(
            sealed("GPGGA,105027.80,5612.9900,N,01200.7600,E,1,3,2.5,160.0,M,,M,,")) ==
        sealed(gga + "M,,M,,"));
  CHECK(written_back<st::rmc>(sealed(rmc + "999.9,E,A")) == sealed(rmc + ",E,A"));
  CHECK(written_back<st::rmc>(sealed(rmc + "15.3,,A")) == sealed(rmc + ",,A"));
  CHECK(written_back<st::rmc>(
            sealed("GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.011,,181207,0,A")) ==
        sealed("GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.011,,181207,,,A"));
  // What a normalization writes is canonical: it comes back unchanged.
  for (const std::string& canonical :
       {sealed("IIVHW,,,211.0,M,5.2,N,,"), sealed(gga + "M,,M,,"), sealed(rmc + ",E,A")}) {
    INFO(canonical);
    CHECK(written_back_standard(canonical) == canonical);
  }
}
