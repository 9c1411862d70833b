// SPDX-License-Identifier: BSL-1.0
// Built with SEAWIRE_SEPARATE_COMPILATION (seawire::compiled): the role decoders are declared
// here and defined once, in src/seawire_compiled.cpp. Each gives what it gives header-only.
// (The ctest test separate_compilation_declares_only checks with nm that this translation unit
// holds no definition of them.)
#include <catch2/catch.hpp>
#include <string_view>
#include <variant>

#include "seawire/anello/inputs.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/sandshark/messages.hpp"

#if !defined(SEAWIRE_SEPARATE_COMPILATION)
#error "this test is built with SEAWIRE_SEPARATE_COMPILATION (it links seawire::compiled)"
#endif

using namespace seawire;

TEST_CASE("separate compilation: every role decoder, declared here, defined once") {
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
