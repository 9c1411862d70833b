// SPDX-License-Identifier: BSL-1.0
#pragma once
// The messages seawire-decode and seawire-encode know: every family's sets, merged (a message in
// several sets, such as RMC, counts once). To add a family, include its header and add its sets
// to the list below; nothing else in the programs changes.

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

using all_messages = nmea::merge_sets<standard_messages,                                 //
                                      kingfisher::from_vehicle, kingfisher::to_vehicle,  //
                                      sandshark::from_vehicle, sandshark::to_vehicle,    //
                                      robotx::reports,                                   //
                                      anello::nmea_inputs, anello::nmea_outputs>::type;

// The NMEA 2000 PGNs decoded and encoded by name ("type":"PGN128259"); others go as their bytes.
using n2k_pgns = nmea2000::ins_input_pgns;

}  // namespace seawire::tools
