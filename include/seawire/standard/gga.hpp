// SPDX-License-Identifier: BSL-1.0
#pragma once
// $--GGA: GPS fix data, from any talker.
//
//   $GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,M,-33.2,M,,*5C
//
// Fields 9-10 and 11-12 are value + unit letter pairs ('M'): one declaration each.

#include <cstdint>
#include <optional>
#include <string_view>

#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"

namespace seawire::standard {

/// GGA field 6.
enum class gps_quality : char {
  invalid = '0',
  gps = '1',
  dgps = '2',
  pps = '3',
  rtk = '4',
  float_rtk = '5',
  estimated = '6',
  manual = '7',
  simulation = '8',
};

struct gga {
  nmea::talker_id talker = "GP";
  std::optional<nmea::time_of_day> time;  // 1  UTC time of the fix
  std::optional<nmea::latitude> lat;      // 2,3
  std::optional<nmea::longitude> lon;     // 4,5
  std::optional<gps_quality> quality;     // 6  blank: not available (the fix is kept)
  std::optional<nmea::integer<std::uint8_t>> satellites;  // 7  in use, written with two digits
  std::optional<nmea::decimal> hdop;                      // 8  horizontal dilution of precision
  std::optional<nmea::decimal> altitude_m;          // 9,10  antenna altitude above MSL, metres
  std::optional<nmea::decimal> geoid_separation_m;  // 11,12 geoid above the WGS84 ellipsoid, metres
  std::optional<nmea::decimal> dgps_age_s;          // 13 seconds since the last DGPS update
  std::optional<nmea::integer<std::uint16_t>> dgps_station;  // 14 station id 0000-1023

  std::uint32_t blank_units = 0;  // bit n: wire field n, a unit letter that came blank beside
                                  //   a blank value, written back blank (blank_units_in)

  friend constexpr bool operator==(const gga&, const gga&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"--GGA">(
          nmea::field<&gga::time>("time"), nmea::field<&gga::lat>("latitude", nmea::precision(5)),
          nmea::field<&gga::lon>("longitude", nmea::precision(5)),
          nmea::field<&gga::quality>("quality"),
          nmea::field<&gga::satellites>("satellites", nmea::zero_pad(2)),
          nmea::field<&gga::hdop>("hdop", nmea::precision(2), nmea::at_least(0)),
          nmea::field<&gga::altitude_m>("altitude_m", nmea::precision(1), nmea::unit('M')),
          nmea::field<&gga::geoid_separation_m>("geoid_separation_m", nmea::precision(1),
                                                nmea::unit('M')),
          nmea::field<&gga::dgps_age_s>("dgps_age_s", nmea::precision(1), nmea::at_least(0)),
          nmea::field<&gga::dgps_station>("dgps_station", nmea::in_range(0, 1023),
                                          nmea::zero_pad(4)))
          .talker_in<&gga::talker>()
          .blank_units_in<&gga::blank_units>();
};

}  // namespace seawire::standard

SEAWIRE_COMPILED_ENCODER(seawire::standard::gga)
