// SPDX-License-Identifier: BSL-1.0
#pragma once
// The messages seawire-decode and seawire-encode know: every family's sets with the policy of the
// role that receives them, merged (a message in several sets, such as RMC, counts once). To add a
// family, include its header and add its sets to the list below; nothing else in the programs
// changes.

#include <string_view>
#include <tuple>
#include <type_traits>

#include "seawire/anello/inputs.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/sandshark/messages.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/rmc.hpp"
#include "seawire/standard/rpm.hpp"
#include "seawire/standard/rsa.hpp"
#include "seawire/standard/vbw.hpp"
#include "seawire/standard/vhw.hpp"
#include "seawire/standard/vwr.hpp"

namespace seawire::tools {

using standard_messages =
    nmea::message_set<standard::rmc, standard::gga, standard::rpm, standard::rsa, standard::vhw,
                      standard::vbw, standard::vwr>;

/// A set of messages and the policy of the role that receives them.
template <class Set>
struct role {
  using set = Set;
  nmea::parse_policy policy;
};

/// Every family's sets, each with its receiver's policy. seawire-decode reads a sentence by the
/// policy of the first role here whose set has its address, so a log of what a payload sends a
/// Kingfisher is read as the vehicle reads it (a bare '*' is no checksum) and a log of what the
/// vehicle sends as a payload reads it (checksum required). Standard sentences come first: a
/// GPRMC in a log may come from any receiver, so it is read by the liberal default.
inline constexpr std::tuple roles{
    role<standard_messages>{nmea::parse_policy{}},
    role<kingfisher::from_vehicle>{kingfisher::payload_policy()},
    role<kingfisher::to_vehicle>{kingfisher::vehicle_policy()},
    role<sandshark::from_vehicle>{sandshark::from_vehicle_policy},
    role<sandshark::to_vehicle>{sandshark::to_vehicle_policy},
    role<robotx::reports>{robotx::judge_policy},
    role<anello::nmea_inputs>{anello::input_policy},
    role<anello::nmea_outputs>{anello::output_policy},
};

template <class Roles>
struct sets_of;
template <class... R>
struct sets_of<std::tuple<R...>> {
  using type = typename nmea::merge_sets<typename R::set...>::type;
};
/// Every message of every role, once (RMC is in several).
using all_messages = sets_of<std::remove_cvref_t<decltype(roles)>>::type;

/// The policy of the first role whose set has this address; the default policy for an address
/// that no set has.
[[nodiscard]] constexpr nmea::parse_policy receiving_policy(std::string_view address) noexcept {
  nmea::parse_policy p;
  std::apply(
      [&](const auto&... r) {
        (void)((std::remove_cvref_t<decltype(r)>::set::knows(address) ? (p = r.policy, true)
                                                                      : false) ||
               ...);
      },
      roles);
  return p;
}

// The NMEA 2000 PGNs decoded and encoded by name ("type":"PGN128259"); others go as their bytes.
using n2k_pgns = nmea2000::ins_input_pgns;

}  // namespace seawire::tools
