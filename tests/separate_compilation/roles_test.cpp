// SPDX-License-Identifier: BSL-1.0
// Built with SEAWIRE_SEPARATE_COMPILATION (seawire::compiled): the library sets' decoders and its
// messages' encoders are declared here and defined once, in src/seawire_compiled.cpp; the role
// decoders, compiled here, decode through their set's. Each gives what it gives header-only.
// (The ctest test separate_compilation_declares_only checks with nm that this translation unit
// holds no definition of the sets' decoders and encoders, and references every set decoder
// seawire_compiled defines.)
#include <catch2/catch.hpp>
#include <cstddef>
#include <span>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>

#include "seawire/anello/inputs.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/registry.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/sandshark/messages.hpp"

#if !defined(SEAWIRE_SEPARATE_COMPILATION)
#error "this test is built with SEAWIRE_SEPARATE_COMPILATION (it links seawire::compiled)"
#endif

using namespace seawire;

TEST_CASE("separate compilation: every role decoder, through its set's decoder compiled once") {
  const auto cp = kingfisher::decode_from_vehicle("$CPALT,164959.100,1*62\r\n");
  REQUIRE(cp);
  CHECK(std::get<kingfisher::cpalt>(cp.value).lights_on);
  CHECK(kingfisher::decode_from_vehicle("$CPALT,164959.100,1*63\r\n").ec ==
        errc::checksum_mismatch);

  const auto py = kingfisher::decode_to_vehicle("$PYDIR,45,55*57\r\n");
  REQUIRE(py);
  CHECK(std::get<kingfisher::pydir>(py.value).thrust_left == nmea::decimal::parse("45").value);

  constexpr std::string_view bfnvg =
      "$BFNVG,081025.987,4221.81092,N,07106.84603,W,1,45.3,20.1,203.1,-3.4,4.5,081025.980*4E\r\n";
  const auto nvg = sandshark::decode_from_vehicle(bfnvg);
  REQUIRE(nvg);
  CHECK(std::holds_alternative<sandshark::bfnvg>(nvg.value));
  const auto view = nmea::parse(bfnvg, sandshark::from_vehicle_policy);
  REQUIRE(view);
  const auto nvg_view = sandshark::decode_from_vehicle(view.value);
  REQUIRE(nvg_view);
  CHECK(std::get<sandshark::bfnvg>(nvg_view.value) == std::get<sandshark::bfnvg>(nvg.value));

  const auto log = sandshark::decode_to_vehicle("$BPLOG,NVG,ON*08\r\n");
  REQUIRE(log);
  CHECK(std::holds_alternative<sandshark::bplog>(log.value));
  const auto log_view = nmea::parse("$BPLOG,NVG,ON*08\r\n", sandshark::to_vehicle_policy);
  REQUIRE(log_view);
  const auto log_again = sandshark::decode_to_vehicle(log_view.value);
  REQUIRE(log_again);
  CHECK(std::get<sandshark::bplog>(log_again.value) == std::get<sandshark::bplog>(log.value));

  const auto vhw = anello::decode_input("$VWVHW,87.3,T,,M,4.67,N,8.64,K*49\r\n");
  REQUIRE(vhw);
  CHECK(std::get<standard::vhw>(vhw.value).speed_knots == nmea::decimal::parse("4.67").value);
  CHECK(anello::decode_input("$VWVHW,87.3,T,,M,4.67,N,8.64,K\r\n").ec == errc::missing_checksum);

  const auto rmc = anello::decode_output(
      "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70\r\n");
  REQUIRE(rmc);
  CHECK(std::holds_alternative<standard::rmc>(rmc.value));

  const auto gat = robotx::decode_report("$RXGAT,101218,161229,AUVSI,1,2,Y,RGB*25\r\n");
  REQUIRE(gat);
  CHECK(std::get<robotx::rxgat>(gat.value).team_id == "AUVSI");
}

namespace {
template <class... M>
constexpr bool encoders_compiled(const nmea::message_set<M...>*) {
  return (nmea::detail::compiled_encoder<M> && ...);
}
template <class... R>
constexpr bool sets_compiled(const std::tuple<R...>*) {
  return (nmea::detail::compiled_set<typename R::set> && ...);
}
// Every message and every role's set the registry lists is compiled once: a message added to a
// family without its SEAWIRE_COMPILED_ENCODER line fails here.
static_assert(encoders_compiled(static_cast<const registry::sentences*>(nullptr)));
static_assert(
    sets_compiled(static_cast<const std::remove_cvref_t<decltype(registry::roles)>*>(nullptr)));

// Set::decode of a sentence already parsed (the role decoders and Set::decode of a line go
// through the set's decoder of a line).
template <class Set, class M>
bool decodes_parsed_as(std::string_view line, const nmea::parse_policy& policy) {
  const auto s = nmea::parse(line, policy);
  if (!s) return false;
  const auto r = Set::decode(s.value, policy);
  return r && std::holds_alternative<M>(r.value);
}

template <class M>
std::string_view encoded(const M& m, std::span<char> buffer) {
  const result<std::size_t> r = nmea::encode_to(m, buffer);
  return r ? std::string_view(buffer.data(), r.value) : std::string_view{};
}
}  // namespace

TEST_CASE("separate compilation: the sets' decoders and the messages' encoders, defined once") {
  char buffer[256];
  constexpr std::string_view pydir_line = "$PYDIR,45,55*57\r\n";
  const auto dir = kingfisher::to_vehicle::decode(pydir_line);
  REQUIRE(dir);
  CHECK(encoded(std::get<kingfisher::pydir>(dir.value), buffer) == pydir_line);
  kingfisher::pydir too_much = std::get<kingfisher::pydir>(dir.value);
  too_much.thrust_left = nmea::decimal::parse("150").value;
  const result<std::size_t> refused = nmea::encode_to(too_much, std::span<char>(buffer));
  CHECK(refused.ec == errc::out_of_range);
  CHECK(refused.field == 1);

  constexpr std::string_view gat_line = "$RXGAT,101218,161229,AUVSI,1,2,Y,RGB*25\r\n";
  const auto gat = robotx::reports::decode(gat_line);
  REQUIRE(gat);
  CHECK(encoded(std::get<robotx::rxgat>(gat.value), buffer) == gat_line);

  constexpr std::string_view rmc_line =
      "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70\r\n";
  const auto rmc = registry::standard_sentences::decode(rmc_line);
  REQUIRE(rmc);
  CHECK(encoded(std::get<standard::rmc>(rmc.value), buffer) == rmc_line);
  const auto also = kingfisher::from_vehicle::decode(rmc_line);
  REQUIRE(also);
  CHECK(std::get<standard::rmc>(also.value) == std::get<standard::rmc>(rmc.value));

  const auto bplog = sandshark::to_vehicle::decode("$BPLOG,NVG,ON*08\r\n");
  REQUIRE(bplog);
  CHECK(encoded(std::get<sandshark::bplog>(bplog.value), buffer) == "$BPLOG,NVG,ON*08\r\n");
  CHECK(sandshark::from_vehicle::decode("$BPLOG,NVG,ON*08\r\n").value.index() == 0);  // unknown

  const auto vhw = anello::nmea_inputs::decode("$VWVHW,87.3,T,,M,4.67,N,8.64,K*49\r\n");
  REQUIRE(vhw);
  CHECK(encoded(std::get<standard::vhw>(vhw.value), buffer) ==
        "$VWVHW,87.3,T,,M,4.67,N,8.64,K*49\r\n");
  CHECK(anello::nmea_outputs::decode(rmc_line));

  CHECK(decodes_parsed_as<kingfisher::from_vehicle, kingfisher::cpalt>(
      "$CPALT,164959.100,1*62\r\n", kingfisher::payload_policy()));
  CHECK(decodes_parsed_as<kingfisher::to_vehicle, kingfisher::pydir>(pydir_line,
                                                                     kingfisher::vehicle_policy()));
  CHECK(decodes_parsed_as<sandshark::from_vehicle, sandshark::bfver>(
      "$BFVER,081025.987,1.0*7C\r\n", sandshark::from_vehicle_policy));
  CHECK(decodes_parsed_as<sandshark::to_vehicle, sandshark::bplog>("$BPLOG,NVG,ON*08\r\n",
                                                                   sandshark::to_vehicle_policy));
  CHECK(decodes_parsed_as<robotx::reports, robotx::rxgat>(gat_line, robotx::judge_policy));
  CHECK(decodes_parsed_as<anello::nmea_inputs, standard::vhw>(
      "$VWVHW,87.3,T,,M,4.67,N,8.64,K*49\r\n", anello::input_policy));
  CHECK(decodes_parsed_as<anello::nmea_outputs, standard::rmc>(rmc_line, anello::output_policy));
  CHECK(decodes_parsed_as<registry::standard_sentences, standard::rmc>(rmc_line, {}));

  // visit: the message, unknown_sentence, or a known message's error without a call.
  const auto view = nmea::parse(pydir_line, kingfisher::vehicle_policy());
  REQUIRE(view);
  int calls = 0;
  const auto seen =
      kingfisher::to_vehicle::visit(view.value, kingfisher::vehicle_policy(), [&](const auto& m) {
        ++calls;
        if constexpr (std::is_same_v<std::remove_cvref_t<decltype(m)>, kingfisher::pydir>)
          CHECK(encoded(m, buffer) == pydir_line);
        else
          FAIL("not a PYDIR");
      });
  CHECK((seen && seen.value && calls == 1));
  const auto other = nmea::parse("$PYXXX,1*4C\r\n", kingfisher::vehicle_policy());
  REQUIRE(other);
  const auto unknown =
      kingfisher::to_vehicle::visit(other.value, kingfisher::vehicle_policy(), [&](const auto& m) {
        ++calls;
        CHECK(std::is_same_v<std::remove_cvref_t<decltype(m)>, nmea::unknown_sentence>);
      });
  CHECK((unknown && !unknown.value && calls == 2));
  const auto bad = nmea::parse("$PYDIR,150,0*52\r\n", kingfisher::vehicle_policy());
  REQUIRE(bad);
  const auto refused_visit = kingfisher::to_vehicle::visit(bad.value, kingfisher::vehicle_policy(),
                                                           [&](const auto&) { ++calls; });
  CHECK(refused_visit.ec == errc::out_of_range);
  CHECK(refused_visit.field == 1);
  CHECK(refused_visit.value);
  CHECK(calls == 2);
}
