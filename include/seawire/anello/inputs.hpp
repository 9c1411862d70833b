// SPDX-License-Identifier: BSL-1.0
#pragma once
// The NMEA 0183 side of the ANELLO Maritime INS: the sentences a USV computer sends it for speed
// aiding (RS-232-2, or UDP datagrams to port 19551 as ANELLO's scripts send them), make_vhw /
// make_vbw to build two of them from SI values, and the RMC it sends back (RS-232-1). The 0xAB00
// binary frame is in frame.hpp.

#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

#include "seawire/anello/gpsctrl.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/heading.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/standard/rmc.hpp"
#include "seawire/standard/rpm.hpp"
#include "seawire/standard/rsa.hpp"
#include "seawire/standard/vbw.hpp"
#include "seawire/standard/vhw.hpp"
#include "seawire/standard/vwr.hpp"

namespace seawire::anello {

/// Everything the INS takes on its NMEA input, from any talker.
using nmea_inputs = nmea::message_set<standard::rpm, standard::rsa, standard::vhw, standard::vbw,
                                      standard::vwr, papgpsctrl>;
/// What the INS sends on its NMEA output: RMC in its 11-field, NMEA 2.3 (mode) and 4.1
/// (navigational status) forms.
using nmea_outputs = nmea::message_set<standard::rmc>;

/// How the INS's NMEA input is read. Every format in the spec carries *hh and the link is bare
/// RS-232, with no error check below the sentence: a corrupted speed would go straight into the
/// navigation filter, so a checksum is required. Otherwise liberal: lower-case hex, any line
/// ending (UDP datagrams often have none), and extra trailing fields ignored (later NMEA
/// versions append fields).
inline constexpr nmea::parse_policy input_policy{
    .checksum = nmea::checksum_policy::required,
    .lowercase_hex = true,
    .extra_fields = true,
    .require_crlf = false,
    .strict_values = false,
};
/// How a USV computer reads the INS's RMC: the same rules, for the same reason (the position
/// feeds the vehicle's own navigation).
inline constexpr nmea::parse_policy output_policy = input_policy;

// The role decoders are templates of nothing so that only a caller compiles them (nmea::lazy).
/// Decode one line as the INS would. Sentences it does not take come back as unknown_sentence,
/// not as an error.
template <int N = 0>
[[nodiscard]] constexpr result<typename nmea::lazy<nmea_inputs, N>::variant> decode_input(
    std::string_view line, const nmea::parse_policy& policy = input_policy) noexcept {
  return nmea::lazy<nmea_inputs, N>::decode(line, policy);
}
/// Decode one line of the INS's output.
template <int N = 0>
[[nodiscard]] constexpr result<typename nmea::lazy<nmea_outputs, N>::variant> decode_output(
    std::string_view line, const nmea::parse_policy& policy = output_policy) noexcept {
  return nmea::lazy<nmea_outputs, N>::decode(line, policy);
}

// ---------------------------------------------------------------------------------------------
// SI values to the NMEA speed sentences
//
// NMEA speeds are knots and km/h; vehicle software works in m/s. Both wire speeds are computed
// from the m/s value (never km/h from rounded knots), each rounded to its own places.

/// Knots per metre per second: a knot is exactly 1852 m per hour.
inline constexpr double knots_per_mps = 3600.0 / 1852.0;
/// Kilometres per hour per metre per second.
inline constexpr double kmh_per_mps = 3.6;

/// Inputs of make_vhw. Unset values are sent blank.
struct vhw_si {
  std::optional<double> heading_true_deg;      ///< any angle; wrapped into [0, 360)
  std::optional<double> heading_magnetic_deg;  ///< any angle; wrapped into [0, 360)
  std::optional<double> speed_mps;             ///< speed through water, >= 0
  unsigned heading_places = 1;                 ///< fraction digits written for headings
  unsigned speed_places = 2;                   ///< fraction digits written for speeds
  nmea::talker_id talker = "VW";
};

/// Inputs of make_vbw: speeds along (+ ahead) and across (+ starboard) the hull. A pair with
/// neither value set is sent blank with status V; a pair with a value, with status A.
struct vbw_si {
  std::optional<double> longitudinal_water_mps;
  std::optional<double> transverse_water_mps;
  std::optional<double> longitudinal_ground_mps;
  std::optional<double> transverse_ground_mps;
  unsigned speed_places = 2;  ///< fraction digits written
  nmea::talker_id talker = "VW";
};

namespace detail {

/// `v` (a value in the unit the field holds) into `out`; on failure, the errc and field number.
template <class T>
[[nodiscard]] constexpr bool put_decimal(std::optional<nmea::decimal>& out, double v,
                                         unsigned places, std::uint16_t field,
                                         result<T>& r) noexcept {
  return seawire::detail::take(nmea::decimal::from_double(v, places), field, out, r);
}

/// A heading in [0, 360) (nmea::wrap_heading): headings from vehicle software are
/// often -180..180 or unwrapped.
template <class T>
[[nodiscard]] constexpr bool put_heading(std::optional<nmea::decimal>& out, double deg,
                                         unsigned places, std::uint16_t field,
                                         result<T>& r) noexcept {
  return seawire::detail::take(nmea::wrap_heading(deg, places), field, out, r);
}

/// A VHW speed (knots or km/h) from m/s. A speed that rounds to zero is zero, not "-0.00".
template <class T>
[[nodiscard]] constexpr bool put_speed(std::optional<nmea::decimal>& out, double mps,
                                       double per_mps, unsigned places, std::uint16_t field,
                                       result<T>& r) noexcept {
  if (!put_decimal(out, mps * per_mps, places, field, r)) return false;
  if (out->negative) {
    out.reset();
    r.ec = errc::out_of_range;
    r.field = field;
    return false;
  }
  return true;
}

}  // namespace detail

/// A VHW from a heading in degrees and a speed through water in m/s; knots (field 5) and km/h
/// (field 7) are both filled. Errors name the wire field: not_finite for NaN/inf,
/// out_of_range for a negative speed (VHW has no sign: use VBW), value_too_large past 19 digits.
[[nodiscard]] constexpr result<standard::vhw> make_vhw(const vhw_si& in) noexcept {
  result<standard::vhw> r;
  standard::vhw& m = r.value;
  m.talker = in.talker;
  if (in.heading_true_deg &&
      !detail::put_heading(m.heading_true_deg, *in.heading_true_deg, in.heading_places, 1, r))
    return r;
  if (in.heading_magnetic_deg &&
      !detail::put_heading(m.heading_magnetic_deg, *in.heading_magnetic_deg, in.heading_places, 3,
                           r))
    return r;
  if (in.speed_mps) {
    if (!detail::put_speed(m.speed_knots, *in.speed_mps, knots_per_mps, in.speed_places, 5, r) ||
        !detail::put_speed(m.speed_kmh, *in.speed_mps, kmh_per_mps, in.speed_places, 7, r))
      return r;
  }
  return r;
}

/// A VBW from body-frame speeds in m/s, written in knots. Errors name the wire field.
[[nodiscard]] constexpr result<standard::vbw> make_vbw(const vbw_si& in) noexcept {
  result<standard::vbw> r;
  standard::vbw& m = r.value;
  m.talker = in.talker;
  const auto put = [&](std::optional<nmea::decimal>& out, const std::optional<double>& v,
                       std::uint16_t field) {
    return !v || detail::put_decimal(out, *v * knots_per_mps, in.speed_places, field, r);
  };
  if (!put(m.longitudinal_water_knots, in.longitudinal_water_mps, 1) ||
      !put(m.transverse_water_knots, in.transverse_water_mps, 2) ||
      !put(m.longitudinal_ground_knots, in.longitudinal_ground_mps, 4) ||
      !put(m.transverse_ground_knots, in.transverse_ground_mps, 5))
    return r;
  const auto status = [](bool any) {
    return any ? standard::vbw_status::valid : standard::vbw_status::invalid;
  };
  m.water_status = status(in.longitudinal_water_mps || in.transverse_water_mps);
  m.ground_status = status(in.longitudinal_ground_mps || in.transverse_ground_mps);
  return r;
}

/// Speed through water of a VHW in m/s: from knots, or from km/h when knots is blank.
[[nodiscard]] constexpr std::optional<double> speed_through_water_mps(
    const standard::vhw& m) noexcept {
  if (m.speed_knots) return m.speed_knots->to_double() / knots_per_mps;
  if (m.speed_kmh) return m.speed_kmh->to_double() / kmh_per_mps;
  return std::nullopt;
}

}  // namespace seawire::anello

SEAWIRE_COMPILED_SET(seawire::anello::nmea_inputs)
SEAWIRE_COMPILED_SET(seawire::anello::nmea_outputs)
