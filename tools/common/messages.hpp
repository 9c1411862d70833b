// SPDX-License-Identifier: BSL-1.0
#pragma once
// The messages seawire-decode and seawire-encode know: those of seawire/registry.hpp, where a
// message is added once for every program, docs generator, fuzz target and test.

#include <string_view>

#include "seawire/nmea/sentence.hpp"
#include "seawire/registry.hpp"

namespace seawire::tools {

/// Every message of every role, once (RMC is in several).
using all_messages = registry::sentences;

/// The policy of the role that receives this address (registry::receiving_policy).
[[nodiscard]] constexpr nmea::parse_policy receiving_policy(std::string_view address) noexcept {
  return registry::receiving_policy(address);
}

/// The NMEA 2000 PGNs decoded and encoded by name ("type":"PGN128259"); others go as their bytes.
using n2k_pgns = registry::pgns;

}  // namespace seawire::tools
