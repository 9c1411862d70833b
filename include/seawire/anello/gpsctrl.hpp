// SPDX-License-Identifier: BSL-1.0
#pragma once
// $PAPGPSCTRL,1*11: tell the ANELLO Maritime INS whether to use GPS (proprietary: P, maker AP).
// The spec defines 1 (use GPS, the default) and 0 (ignore); ANELLO's own scripts also send 2
// (internal GPS off), so it is a value too. Anything else, or a blank, is refused: a GPS switch
// should not be guessed.

#include <string_view>

#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"

namespace seawire::anello {

/// PAPGPSCTRL field 1.
enum class gps_control : char {
  ignore = '0',            ///< dead-reckon on the other aiding inputs, GPS ignored
  use = '1',               ///< use GPS (the INS's default)
  disable_internal = '2',  ///< switch the internal GPS off (ANELLO scripts; not in the spec)
};

struct papgpsctrl {
  gps_control control = gps_control::use;  // 1 [GPS control] 1 use, 0 ignore, 2 internal off

  friend constexpr bool operator==(const papgpsctrl&, const papgpsctrl&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"PAPGPSCTRL">(nmea::field<&papgpsctrl::control>("control"));
};

}  // namespace seawire::anello

SEAWIRE_COMPILED_ENCODER(seawire::anello::papgpsctrl)
