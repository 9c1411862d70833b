// SPDX-License-Identifier: BSL-1.0
#pragma once
// $--VBW: dual ground/water speed along and across the hull, knots, from any talker.
//
//   $VDVBW,4.91,-0.12,A,5.02,0.08,A*7C
//
// Fields 1-6 are the sentence as the ANELLO spec (and NMEA 0183 before 3.0) has it. NMEA 3.0
// adds stern transverse speeds, water (7, status 8) and ground (9, status 10); a Doppler log
// may send them. Both forms are accepted, and each is written back in the form it came in: the
// four stern fields are written when one of them has a value or when they came blank
// (wire_fields); a message built in code without stern values is written in the six-field form.
// Under the strict policy a count between the two (7 to 9 fields) is too_few_fields.
//
// A sender with no ground track writes its water speeds and leaves 4-5 blank with status V.
// Every field may be blank; a blank status decodes as nullopt (senders leave it blank as often
// as they write V) and is written back blank.

#include <cstdint>
#include <optional>
#include <string_view>

#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"

namespace seawire::standard {

/// VBW fields 3, 6, 8 and 10.
enum class vbw_status : char { valid = 'A', invalid = 'V' };

struct vbw {
  nmea::talker_id talker = "VW";
  std::optional<nmea::decimal> longitudinal_water_knots;   // 1 [Longitudinal water speed] knots,
                                                           //   negative = astern
  std::optional<nmea::decimal> transverse_water_knots;     // 2 [Transverse water speed] knots,
                                                           //   negative = port
  std::optional<vbw_status> water_status;                  // 3 [Status] A data valid, V invalid
  std::optional<nmea::decimal> longitudinal_ground_knots;  // 4 [Longitudinal ground speed] knots,
                                                           //   negative = astern
  std::optional<nmea::decimal> transverse_ground_knots;    // 5 [Transverse ground speed] knots,
                                                           //   negative = port
  std::optional<vbw_status> ground_status;                 // 6 [Status] A data valid, V invalid
  std::optional<nmea::decimal> stern_transverse_water_knots;  // 7 NMEA 3.0+, knots, negative = port
  std::optional<vbw_status> stern_water_status;               // 8 NMEA 3.0+
  // 9 NMEA 3.0+, knots, negative = port
  std::optional<nmea::decimal> stern_transverse_ground_knots;
  std::optional<vbw_status> stern_ground_status;  // 10 NMEA 3.0+
  std::uint8_t wire_fields = 0;  // the sentence's field count when one of fields 7-10 came
                                 //   blank, to write back as it came (wire_fields_in)

  friend constexpr bool operator==(const vbw&, const vbw&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"--VBW">(
          nmea::field<&vbw::longitudinal_water_knots>("longitudinal_water_knots",
                                                      nmea::precision(2)),
          nmea::field<&vbw::transverse_water_knots>("transverse_water_knots", nmea::precision(2)),
          nmea::field<&vbw::water_status>("water_status"),
          nmea::field<&vbw::longitudinal_ground_knots>("longitudinal_ground_knots",
                                                       nmea::precision(2)),
          nmea::field<&vbw::transverse_ground_knots>("transverse_ground_knots", nmea::precision(2)),
          nmea::field<&vbw::ground_status>("ground_status"),
          nmea::field<&vbw::stern_transverse_water_knots>("stern_transverse_water_knots",
                                                          nmea::precision(2), nmea::may_be_absent),
          nmea::field<&vbw::stern_water_status>("stern_water_status", nmea::may_be_absent),
          nmea::field<&vbw::stern_transverse_ground_knots>("stern_transverse_ground_knots",
                                                           nmea::precision(2), nmea::may_be_absent),
          nmea::field<&vbw::stern_ground_status>("stern_ground_status", nmea::may_be_absent))
          .talker_in<&vbw::talker>()
          .standard_forms<6, 10>()  // before NMEA 3.0 and since: a stern field goes with all four
          .wire_fields_in<&vbw::wire_fields>();
};

}  // namespace seawire::standard

SEAWIRE_COMPILED_ENCODER(seawire::standard::vbw)
