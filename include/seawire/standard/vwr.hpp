// SPDX-License-Identifier: BSL-1.0
#pragma once
// $--VWR: relative (apparent) wind speed and angle, from any talker.
//
//   $WIVWR,045.0,L,12.6,N,6.5,M,23.3,K*4C
//
// The angle is a magnitude, 0-180 degrees off the bow, and field 2 says to which side. The
// three speeds are value + unit letter pairs, one declaration each; senders often fill only
// one of them. Every field may be blank and a blank unit letter is accepted; one that came
// blank beside a blank value is written back blank (blank_units), the others are written.

#include <cstdint>
#include <optional>
#include <string_view>

#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"

namespace seawire::standard {

/// VWR field 2: which side of the bow the wind comes from.
enum class bow_side : char { left = 'L', right = 'R' };

struct vwr {
  nmea::talker_id talker = "WI";
  // 1 [Wind direction magnitude] degrees off the bow, 0-180
  std::optional<nmea::decimal> angle_deg;
  std::optional<bow_side> side;              // 2 [Left/Right of bow] L port, R starboard
  std::optional<nmea::decimal> speed_knots;  // 3,4 [Speed, N] knots
  std::optional<nmea::decimal> speed_mps;    // 5,6 [Speed, M] metres per second
  std::optional<nmea::decimal> speed_kmh;    // 7,8 [Speed, K] kilometres per hour

  /// The angle signed the usual way for relative bearings: negative to port (L). nullopt
  /// without an angle; an angle without a side is taken as given.
  [[nodiscard]] constexpr std::optional<double> signed_angle_deg() const noexcept {
    if (!angle_deg) return std::nullopt;
    const double a = angle_deg->to_double();
    return side == bow_side::left ? -a : a;
  }

  std::uint32_t blank_units = 0;  // bit n: wire field n, a unit letter that came blank beside
                                  //   a blank value, written back blank (blank_units_in)

  friend constexpr bool operator==(const vwr&, const vwr&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"--VWR">(
          nmea::field<&vwr::angle_deg>("angle_deg", nmea::precision(1), nmea::in_range(0, 180)),
          nmea::field<&vwr::side>("side"),
          nmea::field<&vwr::speed_knots>("speed_knots", nmea::precision(1), nmea::at_least(0),
                                         nmea::unit('N')),
          nmea::field<&vwr::speed_mps>("speed_mps", nmea::precision(1), nmea::at_least(0),
                                       nmea::unit('M')),
          nmea::field<&vwr::speed_kmh>("speed_kmh", nmea::precision(1), nmea::at_least(0),
                                       nmea::unit('K')))
          .talker_in<&vwr::talker>()
          .blank_units_in<&vwr::blank_units>();
};

}  // namespace seawire::standard

SEAWIRE_COMPILED_ENCODER(seawire::standard::vwr)
