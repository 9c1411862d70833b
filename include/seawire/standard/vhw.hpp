// SPDX-License-Identifier: BSL-1.0
#pragma once
// $--VHW: heading and speed through the water, from any talker.
//
//   $VWVHW,045.0,T,031.3,M,5.20,N,9.63,K*5F
//
// Four value + unit letter pairs, one declaration each. A speed log without a compass sends
// blank headings ("$IIVHW,,T,,M,5.2,N,9.6,K"); some senders blank the unit letters too. Every
// value may be blank and a blank unit letter is accepted. A letter that came blank beside a blank
// value is written back blank (blank_units); otherwise seawire writes the letters.
// Speed through water is a magnitude here: the signed, two-axis form is VBW.

#include <cstdint>
#include <optional>

#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"

namespace seawire::standard {

struct vhw {
  nmea::talker_id talker = "VW";
  std::optional<nmea::decimal> heading_true_deg;      // 1,2 [Degrees, T] heading, degrees true
  std::optional<nmea::decimal> heading_magnetic_deg;  // 3,4 [Degrees Magnetic, M] heading, degrees
  std::optional<nmea::decimal> speed_knots;           // 5,6 [Knots, N] speed through water, knots
  std::optional<nmea::decimal> speed_kmh;  // 7,8 [Kilometers, K] speed through water, km/h

  std::uint32_t blank_units = 0;  // bit n: wire field n, a unit letter that came blank beside
                                  //   a blank value, written back blank (blank_units_in)

  friend constexpr bool operator==(const vhw&, const vhw&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"--VHW">(
          nmea::field<&vhw::heading_true_deg>("heading_true_deg", nmea::precision(1),
                                              nmea::in_range(0, 360), nmea::unit('T')),
          nmea::field<&vhw::heading_magnetic_deg>("heading_magnetic_deg", nmea::precision(1),
                                                  nmea::in_range(0, 360), nmea::unit('M')),
          nmea::field<&vhw::speed_knots>("speed_knots", nmea::precision(2), nmea::at_least(0),
                                         nmea::unit('N')),
          nmea::field<&vhw::speed_kmh>("speed_kmh", nmea::precision(2), nmea::at_least(0),
                                       nmea::unit('K')))
          .talker_in<&vhw::talker>()
          .blank_units_in<&vhw::blank_units>();
};

}  // namespace seawire::standard

SEAWIRE_COMPILED_ENCODER(seawire::standard::vhw)
