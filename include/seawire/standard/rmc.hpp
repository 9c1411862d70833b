// SPDX-License-Identifier: BSL-1.0
#pragma once
// $--RMC: recommended minimum navigation information, from any talker.
//
//   $GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70
//
// 11 fields in NMEA 0183 before 2.3; 2.3 adds the mode indicator (12), 4.1 the navigational
// status (13). All three forms are accepted and each is written back in the form it came in.
// Receivers without a fix send the sentence with blank fields; every field but the status may
// be blank. A magnetic variation no variation can have (999.9,E from receivers that mean
// "unknown") reads as not available and does not cost the fix (see nmea/variation.hpp).

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/variation.hpp"

namespace seawire::standard {

/// RMC field 2.
enum class rmc_status : char { active = 'A', warning = 'V' };

/// Positioning mode (RMC 12, GNS, VTG): NMEA 2.3 and later.
enum class mode_indicator : char {
  autonomous = 'A',
  differential = 'D',
  estimated = 'E',
  float_rtk = 'F',
  manual = 'M',
  not_valid = 'N',
  precise = 'P',
  rtk = 'R',
  simulator = 'S',
};

/// Navigational status (RMC 13): NMEA 4.1 and later.
enum class nav_status : char { safe = 'S', caution = 'C', unsafe = 'U', not_valid = 'V' };

struct rmc {
  nmea::talker_id talker = "GP";
  std::optional<nmea::time_of_day> time;                       // 1  UTC time of the fix
  rmc_status status = rmc_status::active;                      // 2  A active, V receiver warning
  std::optional<nmea::latitude> lat;                           // 3,4  DDMM.m, N/S
  std::optional<nmea::longitude> lon;                          // 5,6  DDDMM.m, E/W
  std::optional<nmea::decimal> speed_knots;                    // 7  speed over ground, knots
  std::optional<nmea::decimal> course_true;                    // 8  track made good, degrees true
  std::optional<nmea::date> date;                              // 9  ddmmyy
  std::optional<nmea::magnetic_variation> magnetic_variation;  // 10,11 degrees, E/W
  std::optional<mode_indicator> mode;                          // 12 NMEA 2.3+
  std::optional<standard::nav_status> navigational_status;     // 13 NMEA 4.1+
  std::uint8_t wire_fields = 0;  // the sentence's field count when one of fields 12-13 came
                                 //   blank, to write back as it came (wire_fields_in)

  friend constexpr bool operator==(const rmc&, const rmc&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"--RMC">(
          nmea::field<&rmc::time>("time"), nmea::field<&rmc::status>("status"),
          nmea::field<&rmc::lat>("latitude", nmea::precision(5)),
          nmea::field<&rmc::lon>("longitude", nmea::precision(5)),
          nmea::field<&rmc::speed_knots>("speed_knots", nmea::precision(3), nmea::at_least(0)),
          nmea::field<&rmc::course_true>("course_true", nmea::precision(2), nmea::in_range(0, 360)),
          nmea::field<&rmc::date>("date"),
          nmea::field<&rmc::magnetic_variation>("magnetic_variation", nmea::precision(1)),
          nmea::field<&rmc::mode>("mode", nmea::may_be_absent),
          nmea::field<&rmc::navigational_status>("navigational_status", nmea::may_be_absent))
          .talker_in<&rmc::talker>()
          .wire_fields_in<&rmc::wire_fields>();
};

}  // namespace seawire::standard

SEAWIRE_COMPILED_ENCODER(seawire::standard::rmc)
