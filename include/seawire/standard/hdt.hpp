// SPDX-License-Identifier: BSL-1.0
#pragma once
// $--HDT: heading, degrees true, from any talker (a gyrocompass is HE, a GNSS compass GP or GN).
//
//   $HEHDT,274.07,T*19
//          1      2
//
// One value + unit letter pair: the heading and the letter T. A compass without a heading (still
// settling, or failed) sends the value blank ("$HEHDT,,T"); some send the letter blank too. A
// blank value is accepted and a blank letter beside it is written back blank (blank_units);
// otherwise seawire writes the T. Any other letter is refused: a magnetic heading is HDG or HDM.

#include <cstdint>
#include <optional>

#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"

namespace seawire::standard {

struct hdt {
  nmea::talker_id talker = "HE";
  std::optional<nmea::decimal> heading_true_deg;  // 1,2 [Heading, T] degrees true

  std::uint32_t blank_units = 0;  // bit n: wire field n, a unit letter that came blank beside
                                  //   a blank value, written back blank (blank_units_in)

  friend constexpr bool operator==(const hdt&, const hdt&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<"--HDT">(nmea::field<&hdt::heading_true_deg>(
                                                           "heading_true_deg", nmea::precision(2),
                                                           nmea::in_range(0, 360), nmea::unit('T')))
                                   .talker_in<&hdt::talker>()
                                   .blank_units_in<&hdt::blank_units>();
};

}  // namespace seawire::standard

SEAWIRE_COMPILED_ENCODER(seawire::standard::hdt)
