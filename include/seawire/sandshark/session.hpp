// SPDX-License-Identifier: BSL-1.0
#pragma once
// Sandshark SPI sessions, sans I/O: payload_session and vehicle_session (docs/sessions.md).

#include "seawire/sandshark/payload_session.hpp"  // IWYU pragma: export
#include "seawire/sandshark/session_common.hpp"   // IWYU pragma: export
#include "seawire/sandshark/vehicle_session.hpp"  // IWYU pragma: export
