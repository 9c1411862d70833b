// SPDX-License-Identifier: BSL-1.0
#pragma once
// How canboat's analyzer shows a PGN field in its default units ("units":"std" in its JSON), by
// the field's unit: the unit a field's name ends with (walk.hpp's unit_of_name), declared once
// here for every PGN. canboat keeps most values as the wire's (m, m/s, V, A, %, rpm, L/h, Ah) and
// changes four: angles and turn rates in degrees, absolute temperatures in degrees Celsius,
// pressures in bar, and durations as hh:mm:ss text. Latitude and longitude have 7 decimals
// whatever their resolution. The texts of lookups and flags are lookup_titles (field.hpp).

#include <cstdint>
#include <string_view>

namespace seawire::nmea2000 {

/// How canboat shows a number field.
enum class canboat_display : std::uint8_t {
  number,      ///< the value at its resolution, as its unit has it
  degrees,     ///< radians, or radians per second, times 180 / pi
  celsius,     ///< kelvin minus 273.15 (an unsigned temperature; a signed one is a difference)
  bar,         ///< pascals divided by 100 000
  duration,    ///< seconds as text: [-]hh:mm:ss, and the resolution's fraction digits
  coordinate,  ///< degrees of latitude or longitude
};

/// A field's unit in canboat's std units: how it is shown, the unit's name there, and the
/// fraction digits canboat fixes for it (-1: as many as the shown resolution has, that is the
/// digits needed to write one step: 2 for 0.01, 0 for 1 or 60).
struct canboat_unit {
  canboat_display display = canboat_display::number;
  std::string_view unit;
  int precision = -1;

  [[nodiscard]] constexpr bool operator==(const canboat_unit&) const noexcept = default;
};

/// canboat's std unit for a field of seawire unit `unit` ("rad", "k", "pa": the end of its
/// name), signed or not. A unit canboat shows as it is comes back as number with an empty name.
[[nodiscard]] constexpr canboat_unit canboat_std_unit(std::string_view unit,
                                                      bool is_signed) noexcept {
  if (unit == "rad") return {canboat_display::degrees, "deg", 1};
  if (unit == "radps") return {canboat_display::degrees, "deg/s", -1};
  if (unit == "k" && !is_signed) return {canboat_display::celsius, "C", -1};
  if (unit == "pa") return {canboat_display::bar, "bar", 3};
  if (unit == "s") return {canboat_display::duration, "s", -1};
  if (unit == "deg") return {canboat_display::coordinate, "deg", 7};
  return {};
}

}  // namespace seawire::nmea2000
