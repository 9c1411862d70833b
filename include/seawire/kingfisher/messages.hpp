// SPDX-License-Identifier: BSL-1.0
#pragma once
// Clearpath Kingfisher USV payload interface (vehicle: TCP server, port 29500, any client may
// command): CP* sentences and relayed GPRMC/GPGGA from the vehicle, PY* commands to it. Payloads
// read with decode_from_vehicle (checksum required), vehicles with decode_to_vehicle (checksum
// optional, a wrong one never accepted); unknown addresses are nmea::unknown_sentence, not
// errors. PYDEP's yaw rate is rad/s in the spec but deg/s clockwise in Clearpath's vehicle code:
// carried as written. Encode refuses what the spec forbids (out_of_range, with the field).

#include <cstdint>
#include <optional>
#include <string_view>
#include <variant>

#include "seawire/bluefin/navigation.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/rmc.hpp"

namespace seawire::kingfisher {

// ---------------------------------------------------------------------------------------------
// from the vehicle

/// How the Clearpath vehicle prints its numbers (a C float format): unpadded positions ("22.2,W"
/// is 0 deg 22.2 min W), "nan" for no value, seconds rounded up to "60.000"
/// (docs/parse-policy.md). Every CP* sentence declares them; the relayed GPRMC/GPGGA do not.
inline constexpr nmea::number_forms vehicle_numbers{
    .unpadded_positions = true, .nan_as_blank = true, .rounded_seconds = true};

/// Navigation update. Real vehicles write unpadded longitude degrees ("7105.44878") and 0, not
/// blank, for altitude and depth; both are kept as sent. `effective_nav_timestamp()` applies
/// the spec's "blank field 12 means field 1". (The spec's example is a BFNVG line; under CPNVG
/// its checksum would be *58, not *5B.)
///   $CPNVG,081025.987,4221.81092,N,7106.84603,W,1,0,0,203.1,-3.4,4.5,081025.980*68
using cpnvg = bluefin::nav_update<"CPNVG", vehicle_numbers>;

/// Velocity and rate update (m/s east/north/down, deg/s pitch/roll/yaw).
///   $CPNVR,164959.063,0.02941,-0.068552,0,0.060938,0,-0.061132*59
using cpnvr = bluefin::velocity_update<"CPNVR", vehicle_numbers>;

/// Raw compass reading, repackaged by the vehicle. The real vehicle reports compass id 0 (the
/// spec numbers compasses from 1). Any field after the timestamp may be blank, "no data" (spec
/// 2.4), which reads as nullopt.
///   $CPRCM,164959.065,0,234.326694,-1.655603,-6.628557,164959.060*62
struct cprcm {
  nmea::time_of_day timestamp;  // 1 [Timestamp] when the sentence was made
  std::optional<nmea::integer<std::uint16_t>> compass_id = 0;  // 2 [ID_Compass] which compass
  // 3 [Heading] degrees clockwise from true north
  std::optional<nmea::decimal> heading_deg;
  std::optional<nmea::decimal> pitch_deg;  // 4 [Pitch] degrees, positive bow up
  std::optional<nmea::decimal> roll_deg;   // 5 [Roll] degrees; the spec's 2.8 says
                                           //   positive port side up, its Appendix B starboard
  std::optional<nmea::time_of_day> nav_timestamp;  // 6 [NavTimestamp] when the compass measured;
                                                   //   blank means "the same as field 1"

  /// Field 6, or field 1 when field 6 is blank, as the spec says to read it.
  [[nodiscard]] constexpr nmea::time_of_day effective_nav_timestamp() const noexcept {
    return nav_timestamp ? *nav_timestamp : timestamp;
  }

  friend constexpr bool operator==(const cprcm&, const cprcm&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"CPRCM">(
          nmea::field<&cprcm::timestamp>("timestamp"),
          nmea::field<&cprcm::compass_id>("compass_id"),
          nmea::field<&cprcm::heading_deg>("heading_deg", nmea::precision(2),
                                           nmea::in_range(0, 360)),
          nmea::field<&cprcm::pitch_deg>("pitch_deg", nmea::precision(2), nmea::in_range(-90, 90)),
          nmea::field<&cprcm::roll_deg>("roll_deg", nmea::precision(2), nmea::in_range(-180, 180)),
          nmea::field<&cprcm::nav_timestamp>("nav_timestamp"))
          .sender_writes<vehicle_numbers>();
};

/// Battery bank voltages, one sentence per bank. The spec has the battery id as field 2 (six
/// fields); the real vehicle leaves it out (five fields). The two forms are told apart by the
/// field count. Member comments number the spec's six fields; errors report the position on
/// the wire, so in the five-field form the stack voltage is field 2. A blank measurement is
/// "no data" (spec 2.4) and reads as nullopt.
///   $CPRBS,105707.24,1,15.2,15.1,15.3,0*67                  spec form, 6 fields
///   $CPRBS,172909.322,15.121597,15.121597,15.121597,0*76   real vehicle, 5 fields (no id)
struct cprbs {
  nmea::time_of_day timestamp;  // 1 [Timestamp] when the sentence was made
  // 2 [ID_Battery] banks numbered from 1; only in the six-field form, nullopt writes the
  // five-field one unless wire_fields says six
  std::optional<nmea::integer<std::uint16_t>> battery_id;
  std::optional<nmea::decimal> stack_voltage_v;     // 3 [V_Batt_Stack] volts, the whole bank
  std::optional<nmea::decimal> min_cell_voltage_v;  // 4 [V_Batt_Min] volts, lowest cell of the bank
  // 5 [V_Batt_Max] volts, highest cell of the bank
  std::optional<nmea::decimal> max_cell_voltage_v;
  std::optional<nmea::decimal> temperature_c;  // 6 [TemperatureC] degrees Celsius (real: 0)
  std::uint8_t wire_fields = 0;  // 6 when a six-field sentence's battery id came blank: written
                                 //   back in that form (0: nullopt writes the five-field one)

  friend constexpr bool operator==(const cprbs&, const cprbs&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"CPRBS">(
          nmea::field<&cprbs::timestamp>("timestamp"),
          nmea::field<&cprbs::battery_id>("battery_id", nmea::only_with_field_count(6)),
          nmea::field<&cprbs::stack_voltage_v>("stack_voltage_v", nmea::precision(2)),
          nmea::field<&cprbs::min_cell_voltage_v>("min_cell_voltage_v", nmea::precision(2)),
          nmea::field<&cprbs::max_cell_voltage_v>("max_cell_voltage_v", nmea::precision(2)),
          nmea::field<&cprbs::temperature_c>("temperature_c", nmea::precision(1)))
          .wire_fields_in<&cprbs::wire_fields>()
          .sender_writes<vehicle_numbers>();
};

/// Raw IMU reading, repackaged by the vehicle. Axes follow the sea-vehicle convention (x bow,
/// y starboard, z down; rates by the right-hand rule). The real vehicle sends seven fields, no
/// nav timestamp; nullopt writes that form, and an eighth field that came blank is written back
/// blank (wire_fields). (The spec's sentence id is garbled; it is CPIMU.) A blank rate or
/// acceleration is "no data" (spec 2.4) and reads as nullopt.
///   $CPIMU,164958.858,-0.061035,-0.000097,-0.061035,-0.026916,0.104533,-0.932172*57
struct cpimu {
  nmea::time_of_day timestamp;                // 1 [Timestamp] when the sentence was made
  std::optional<nmea::decimal> rate_x_dps;    // 2 [AngularRate_X] deg/s about x (roll)
  std::optional<nmea::decimal> rate_y_dps;    // 3 [AngularRate_Y] deg/s about y (pitch)
  std::optional<nmea::decimal> rate_z_dps;    // 4 [AngularRate_Z] deg/s about z (yaw)
  std::optional<nmea::decimal> accel_x_mps2;  // 5 [Accel_X] m/s^2, positive forward
  std::optional<nmea::decimal> accel_y_mps2;  // 6 [Accel_Y] m/s^2, positive to starboard
  std::optional<nmea::decimal> accel_z_mps2;  // 7 [Accel_Z] m/s^2, positive down
  // 8 [NavTimestamp] when the IMU measured; blank or
  // absent means "the same as field 1"
  std::optional<nmea::time_of_day> nav_timestamp;
  std::uint8_t wire_fields = 0;  // 8 when field 8 came blank: written back blank (the spec's
                                 //   form); 0: left out when nav_timestamp has no value

  /// Field 8, or field 1 when field 8 is blank or absent.
  [[nodiscard]] constexpr nmea::time_of_day effective_nav_timestamp() const noexcept {
    return nav_timestamp ? *nav_timestamp : timestamp;
  }

  friend constexpr bool operator==(const cpimu&, const cpimu&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"CPIMU">(
          nmea::field<&cpimu::timestamp>("timestamp"),
          nmea::field<&cpimu::rate_x_dps>("rate_x_dps", nmea::precision(3)),
          nmea::field<&cpimu::rate_y_dps>("rate_y_dps", nmea::precision(3)),
          nmea::field<&cpimu::rate_z_dps>("rate_z_dps", nmea::precision(3)),
          nmea::field<&cpimu::accel_x_mps2>("accel_x_mps2", nmea::precision(3)),
          nmea::field<&cpimu::accel_y_mps2>("accel_y_mps2", nmea::precision(3)),
          nmea::field<&cpimu::accel_z_mps2>("accel_z_mps2", nmea::precision(3)),
          nmea::field<&cpimu::nav_timestamp>("nav_timestamp", nmea::may_be_absent))
          .wire_fields_in<&cpimu::wire_fields>()
          .sender_writes<vehicle_numbers>();
};

/// Lights state. Not in the spec; real vehicles send it (PYCLT switches the lights).
///   $CPALT,164959.100,1*62
struct cpalt {
  nmea::time_of_day timestamp;  // 1 when the sentence was made
  bool lights_on = false;       // 2 1 = lights on, 0 = off

  friend constexpr bool operator==(const cpalt&, const cpalt&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<"CPALT">(nmea::field<&cpalt::timestamp>("timestamp"),
                                                       nmea::field<&cpalt::lights_on>("lights_on"))
                                   .sender_writes<vehicle_numbers>();
};

// ---------------------------------------------------------------------------------------------
// to the vehicle. The helpers below round doubles (decimal::from_double: not_finite names the
// field); the spec's ranges are checked by encode, once, from the description.

namespace detail {
template <class T>
[[nodiscard]] constexpr bool convert(result<T>& out, nmea::decimal T::*member, std::uint16_t field,
                                     double v, int places, int declared) noexcept {
  return seawire::detail::take(
      nmea::decimal::from_double(v, static_cast<unsigned>(places >= 0 ? places : declared)), field,
      out.value.*member, out);
}
}  // namespace detail

/// Desired yaw rate and thrust.
///   $PYDEP,-10,50*71
struct pydep {
  nmea::decimal
      yaw_rate;          // 1 [DesYawRate] desired rate of yaw. UNIT CONFLICT: the spec says rad/s;
                         //   the Clearpath vehicle reads deg/s, positive clockwise. Sent as given.
  nmea::decimal thrust;  // 2 [DesThrustPct] percent of thrust; 0 stopped, > 0 forward

  /// Both numbers rounded to `places` fraction digits, or (places < 0) to each field's
  /// declared precision: 2 for the yaw rate, 1 for the thrust.
  [[nodiscard]] static constexpr result<pydep> from_rate(double yaw_rate, double thrust_pct,
                                                         int places = -1) noexcept {
    result<pydep> r;
    (void)(detail::convert(r, &pydep::yaw_rate, 1, yaw_rate, places,
                           nmea::precision_of<&pydep::yaw_rate>()) &&
           detail::convert(r, &pydep::thrust, 2, thrust_pct, places,
                           nmea::precision_of<&pydep::thrust>()));
    return r;
  }

  friend constexpr bool operator==(const pydep&, const pydep&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<"PYDEP">(
      nmea::field<&pydep::yaw_rate>("yaw_rate", nmea::precision(2)),
      nmea::field<&pydep::thrust>("thrust", nmea::precision(1), nmea::in_range(-100, 100)));
};

/// Desired heading and speed; the vehicle's own controllers hold them.
///   $PYDEV,90,1.5*7D
struct pydev {
  nmea::decimal
      heading_deg;  // 1 [DesHeading] degrees clockwise from true north, [0, 360). The spec
                    //   says whole degrees 0..359; real senders send decimals: both accepted
  nmea::decimal speed_mps;  // 2 [DesSpeed] m/s over ground, >= 0 (the vehicle caps it at its max)

  /// Heading wrapped into [0, 360) after rounding (so -90 is 270 and 359.97 at one place is
  /// 0.0). Both rounded to `places` fraction digits (at most 15), or (places < 0) to each
  /// field's declared precision: 1 for the heading, 2 for the speed.
  [[nodiscard]] static constexpr result<pydev> from_heading(double heading_deg, double speed_mps,
                                                            int places = -1) noexcept {
    result<pydev> r;
    if (places > 15) {  // 360 * 10^places must fit the mantissa
      r.ec = errc::value_too_large;
      r.field = 1;
      return r;
    }
    if (!detail::convert(r, &pydev::heading_deg, 1, heading_deg, places,
                         nmea::precision_of<&pydev::heading_deg>()) ||
        !detail::convert(r, &pydev::speed_mps, 2, speed_mps, places,
                         nmea::precision_of<&pydev::speed_mps>()))
      return r;
    nmea::decimal& h = r.value.heading_deg;
    const std::uint64_t turn = 360 * seawire::detail::pow10_table[h.places];
    h.mantissa %= turn;
    if (h.negative && h.mantissa != 0) h.mantissa = turn - h.mantissa;
    h.negative = false;
    return r;
  }

  friend constexpr bool operator==(const pydev&, const pydev&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<"PYDEV">(
      nmea::field<&pydev::heading_deg>("heading_deg", nmea::precision(1),
                                       nmea::in_range_below(0, 360)),
      nmea::field<&pydev::speed_mps>("speed_mps", nmea::precision(2), nmea::at_least(0)));
};

/// Thrust for each motor of the differential drive.
///   $PYDIR,45,55*57
struct pydir {
  nmea::decimal thrust_left;   // 1 [DesThrustPct_L] percent of thrust, port motor
  nmea::decimal thrust_right;  // 2 [DesThrustPct_R] percent of thrust, starboard motor

  /// Both percentages rounded to `places` fraction digits, or (places < 0) to the declared
  /// precision: 1.
  [[nodiscard]] static constexpr result<pydir> from_percent(double left, double right,
                                                            int places = -1) noexcept {
    result<pydir> r;
    (void)(detail::convert(r, &pydir::thrust_left, 1, left, places,
                           nmea::precision_of<&pydir::thrust_left>()) &&
           detail::convert(r, &pydir::thrust_right, 2, right, places,
                           nmea::precision_of<&pydir::thrust_right>()));
    return r;
  }

  friend constexpr bool operator==(const pydir&, const pydir&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"PYDIR">(nmea::field<&pydir::thrust_left>("thrust_left", nmea::precision(1),
                                                               nmea::in_range(-100, 100)),
                              nmea::field<&pydir::thrust_right>("thrust_right", nmea::precision(1),
                                                                nmea::in_range(-100, 100)));
};

/// Lights control. Not in the spec; real vehicles accept it and report the state in CPALT.
///   $PYCLT,1*4F
struct pyclt {
  bool lights_on = false;  // 1 1 = switch the lights on, 0 = off

  friend constexpr bool operator==(const pyclt&, const pyclt&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<"PYCLT">(nmea::field<&pyclt::lights_on>("lights_on"));
};

// ---------------------------------------------------------------------------------------------
// roles

/// What a payload hears: the CP* sentences and the relayed GPS sentences (any talker).
using from_vehicle =
    nmea::message_set<cpnvg, cpnvr, cprcm, cprbs, cpimu, cpalt, standard::rmc, standard::gga>;
/// What a vehicle hears: the PY* commands.
using to_vehicle = nmea::message_set<pydep, pydev, pydir, pyclt>;

/// How a payload reads the vehicle: a checksum required (the vehicle always sends one) and every
/// field (a sentence that stops early is too_few_fields; a blank one is "no data", spec 2.4).
[[nodiscard]] constexpr nmea::parse_policy payload_policy() noexcept {
  nmea::parse_policy p;
  p.checksum = nmea::checksum_policy::required;
  p.absent_as_blank = false;
  return p;
}

/// How a vehicle reads payloads: a checksum is optional but must match; a bare '*' before CR LF
/// is no checksum, as the spec writes one.
[[nodiscard]] constexpr nmea::parse_policy vehicle_policy() noexcept {
  nmea::parse_policy p;
  p.checksum = nmea::checksum_policy::verify_if_present;
  p.empty_checksum = true;
  return p;
}

// The role decoders are templates of nothing so that only a caller compiles them (nmea::lazy).
/// Payload side: one line from the vehicle. Addresses outside `from_vehicle` (PY*, other
/// GPS sentences) give unknown_sentence, which views into `line`.
template <int N = 0>
[[nodiscard]] constexpr result<typename nmea::lazy<from_vehicle, N>::variant> decode_from_vehicle(
    std::string_view line, const nmea::parse_policy& policy = payload_policy()) noexcept {
  return nmea::lazy<from_vehicle, N>::decode(line, policy);
}

/// Vehicle side: one command line from a payload. Addresses outside `to_vehicle` give
/// unknown_sentence, which views into `line`.
template <int N = 0>
[[nodiscard]] constexpr result<typename nmea::lazy<to_vehicle, N>::variant> decode_to_vehicle(
    std::string_view line, const nmea::parse_policy& policy = vehicle_policy()) noexcept {
  return nmea::lazy<to_vehicle, N>::decode(line, policy);
}

}  // namespace seawire::kingfisher

SEAWIRE_COMPILED_ENCODER(seawire::kingfisher::cpnvg)
SEAWIRE_COMPILED_ENCODER(seawire::kingfisher::cpnvr)
SEAWIRE_COMPILED_ENCODER(seawire::kingfisher::cprcm)
SEAWIRE_COMPILED_ENCODER(seawire::kingfisher::cprbs)
SEAWIRE_COMPILED_ENCODER(seawire::kingfisher::cpimu)
SEAWIRE_COMPILED_ENCODER(seawire::kingfisher::cpalt)
SEAWIRE_COMPILED_ENCODER(seawire::kingfisher::pydep)
SEAWIRE_COMPILED_ENCODER(seawire::kingfisher::pydev)
SEAWIRE_COMPILED_ENCODER(seawire::kingfisher::pydir)
SEAWIRE_COMPILED_ENCODER(seawire::kingfisher::pyclt)
SEAWIRE_COMPILED_SET(seawire::kingfisher::from_vehicle)
SEAWIRE_COMPILED_SET(seawire::kingfisher::to_vehicle)
