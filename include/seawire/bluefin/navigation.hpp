// SPDX-License-Identifier: BSL-1.0
#pragma once
// Navigation and velocity updates in the Bluefin SPI layout. Bluefin vehicles send them as
// BFNVG/BFNVR; the Clearpath Kingfisher copies the layout as CPNVG/CPNVR. Declared once here,
// instantiated by each family with its own address and the number forms its vehicle writes
// (nmea::number_forms).

#include <optional>

#include "seawire/detail/fixed_string.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"

namespace seawire::bluefin {

/// Navigation update: pose and position from the vehicle's filter.
///   $BFNVG,081025.987,4221.81092,N,07106.84603,W,1,45.3,20.1,203.1,-3.4,4.5,081025.980*4E
template <seawire::detail::fixed_string Address, nmea::number_forms Numbers = nmea::number_forms{}>
struct nav_update {
  nmea::time_of_day timestamp;  // 1  [Timestamp] when the sentence was made
  nmea::latitude lat;           // 2,3 [Lat_NMEA] [LatNS_NMEA]
  nmea::longitude lon;          // 4,5 [Lon_NMEA] [LonEW_NMEA] (unpadded degrees accepted)
  bool gps = false;             // 6  [PosQual] 1 = solution includes GPS, 0 = no GPS
  // 7  [AltBottom] metres above the bottom; blank (or 0) on
  // surface vehicles
  std::optional<nmea::decimal> altitude_m;
  std::optional<nmea::decimal> depth_m;      // 8  [DepthTop] metres below the surface; blank (or 0)
                                             //    on surface vehicles
  std::optional<nmea::decimal> heading_deg;  // 9  [Heading] degrees clockwise from true north
  std::optional<nmea::decimal> roll_deg;     // 10 [Roll] degrees, positive port side up
  std::optional<nmea::decimal> pitch_deg;    // 11 [Pitch] degrees, positive bow up
  // 12 [NavTimestamp] when the solution was computed;
  // blank means "the same as field 1"
  std::optional<nmea::time_of_day> nav_timestamp;

  /// Field 12, or field 1 when field 12 is blank, as the spec says to read it.
  [[nodiscard]] constexpr nmea::time_of_day effective_nav_timestamp() const noexcept {
    return nav_timestamp ? *nav_timestamp : timestamp;
  }

  friend constexpr bool operator==(const nav_update&, const nav_update&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<Address>(
          nmea::field<&nav_update::timestamp>("timestamp"),
          nmea::field<&nav_update::lat>("latitude", nmea::precision(5)),
          nmea::field<&nav_update::lon>("longitude", nmea::precision(5)),
          nmea::field<&nav_update::gps>("position_quality"),
          nmea::field<&nav_update::altitude_m>("altitude_m", nmea::precision(1)),
          nmea::field<&nav_update::depth_m>("depth_m", nmea::precision(1)),
          nmea::field<&nav_update::heading_deg>("heading_deg", nmea::precision(2),
                                                nmea::in_range(0, 360)),
          nmea::field<&nav_update::roll_deg>("roll_deg", nmea::precision(2),
                                             nmea::in_range(-180, 180)),
          nmea::field<&nav_update::pitch_deg>("pitch_deg", nmea::precision(2),
                                              nmea::in_range(-90, 90)),
          nmea::field<&nav_update::nav_timestamp>("nav_timestamp"))
          .template sender_writes<Numbers>();
};

/// Velocity and rate update.
///   $CPNVR,164959.063,0.02941,-0.068552,0,0.060938,0,-0.061132*59
template <seawire::detail::fixed_string Address, nmea::number_forms Numbers = nmea::number_forms{}>
struct velocity_update {
  nmea::time_of_day timestamp;                  // 1 [Timestamp]
  std::optional<nmea::decimal> vel_east_mps;    // 2 [Vel_East] m/s, negative = westward
  std::optional<nmea::decimal> vel_north_mps;   // 3 [Vel_North] m/s
  std::optional<nmea::decimal> vel_down_mps;    // 4 [Vel_Down] m/s, positive = sinking
  std::optional<nmea::decimal> pitch_rate_dps;  // 5 [Rate_Pitch] deg/s, positive nose rising
  std::optional<nmea::decimal> roll_rate_dps;   // 6 [Rate_Roll] deg/s
  std::optional<nmea::decimal> yaw_rate_dps;    // 7 [Rate_Yaw] deg/s, positive clockwise

  friend constexpr bool operator==(const velocity_update&,
                                   const velocity_update&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<Address>(
          nmea::field<&velocity_update::timestamp>("timestamp"),
          nmea::field<&velocity_update::vel_east_mps>("vel_east_mps", nmea::precision(3)),
          nmea::field<&velocity_update::vel_north_mps>("vel_north_mps", nmea::precision(3)),
          nmea::field<&velocity_update::vel_down_mps>("vel_down_mps", nmea::precision(3)),
          nmea::field<&velocity_update::pitch_rate_dps>("pitch_rate_dps", nmea::precision(3)),
          nmea::field<&velocity_update::roll_rate_dps>("roll_rate_dps", nmea::precision(3)),
          nmea::field<&velocity_update::yaw_rate_dps>("yaw_rate_dps", nmea::precision(3)))
          .template sender_writes<Numbers>();
};

}  // namespace seawire::bluefin
