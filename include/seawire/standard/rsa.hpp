// SPDX-License-Identifier: BSL-1.0
#pragma once
// $--RSA: rudder sensor angle, from any talker.
//
//   $AGRSA,-5.2,A,-4.8,A*4D
//
// A single-rudder vessel fills fields 1-2 and leaves 3-4 blank (or writes V in 4). NMEA calls the
// value a relative measure, proportional to the rudder angle but not necessarily in degrees;
// nearly every sensor writes degrees. Every field may be blank; a blank status decodes as nullopt
// (senders leave it blank as often as they write V) and is written back blank.

#include <optional>
#include <string_view>

#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"

namespace seawire::standard {

/// RSA fields 2 and 4.
enum class rsa_status : char { valid = 'A', invalid = 'V' };

struct rsa {
  nmea::talker_id talker = "II";
  std::optional<nmea::decimal> starboard_angle;  // 1 [Starboard (or single) rudder sensor]
                                                 //   degrees, negative = turn to port
  std::optional<rsa_status> starboard_status;    // 2 [Status] A data valid, V invalid
  std::optional<nmea::decimal> port_angle;       // 3 [Port rudder sensor] degrees, as field 1
  std::optional<rsa_status> port_status;         // 4 [Status] A data valid, V invalid

  friend constexpr bool operator==(const rsa&, const rsa&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"--RSA">(nmea::field<&rsa::starboard_angle>(
                                  "starboard_angle", nmea::precision(1), nmea::in_range(-180, 180)),
                              nmea::field<&rsa::starboard_status>("starboard_status"),
                              nmea::field<&rsa::port_angle>("port_angle", nmea::precision(1),
                                                            nmea::in_range(-180, 180)),
                              nmea::field<&rsa::port_status>("port_status"))
          .talker_in<&rsa::talker>();
};

}  // namespace seawire::standard

SEAWIRE_COMPILED_ENCODER(seawire::standard::rsa)
