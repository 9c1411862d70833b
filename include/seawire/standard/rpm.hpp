// SPDX-License-Identifier: BSL-1.0
#pragma once
// $--RPM: revolutions of a shaft or engine, from any talker.
//
//   $IIRPM,S,1,1200.5,12.5,A*40
//
// Source and number say which shaft or engine the speed belongs to, so both are required: a
// speed that cannot be attributed is of no use to a twin-screw vessel's speed aiding. Speed,
// pitch and status may be blank ("no data"). The status is required by the spec, but senders
// without a valid reading leave it blank as often as they write V: blank decodes as nullopt and
// is written back blank.

#include <cstdint>
#include <optional>
#include <string_view>

#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"

namespace seawire::standard {

/// RPM field 1.
enum class rpm_source : char { shaft = 'S', engine = 'E' };

/// RPM field 5.
enum class rpm_status : char { valid = 'A', invalid = 'V' };

struct rpm {
  nmea::talker_id talker = "II";
  rpm_source source = rpm_source::shaft;   // 1 [Source] S shaft, E engine
  nmea::integer<std::uint8_t> number = 0;  // 2 [Engine or shaft number] 0 single or on the
                                           //   centreline, odd starboard, even port
  std::optional<nmea::decimal> speed_rpm;  // 3 [Speed] rev/min; negative = counter-clockwise
  // 4 [Propeller pitch] % of maximum, negative = astern
  std::optional<nmea::decimal> pitch_percent;
  std::optional<rpm_status> status;  // 5 [Status] A data valid, V invalid

  friend constexpr bool operator==(const rpm&, const rpm&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"--RPM">(nmea::field<&rpm::source>("source"),
                              nmea::field<&rpm::number>("number"),
                              nmea::field<&rpm::speed_rpm>("speed_rpm", nmea::precision(1)),
                              nmea::field<&rpm::pitch_percent>("pitch_percent", nmea::precision(1),
                                                               nmea::in_range(-100, 100)),
                              nmea::field<&rpm::status>("status"))
          .talker_in<&rpm::talker>();
};

}  // namespace seawire::standard

SEAWIRE_COMPILED_ENCODER(seawire::standard::rpm)
