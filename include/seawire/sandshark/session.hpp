// SPDX-License-Identifier: BSL-1.0
#pragma once
// Sandshark SPI sessions, sans I/O: the payload (backseat) state machine and the vehicle (BAM)
// one a simulator or test double needs. Time is passed in as a steady_clock::time_point, and each
// session is built with a utc_clock (steady time tied to system_clock UTC) for its timestamps;
// see session_common.hpp for the conventions both share.

#include "seawire/sandshark/payload_session.hpp"  // IWYU pragma: export
#include "seawire/sandshark/session_common.hpp"   // IWYU pragma: export
#include "seawire/sandshark/vehicle_session.hpp"  // IWYU pragma: export
