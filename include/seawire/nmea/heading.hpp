// SPDX-License-Identifier: BSL-1.0
#pragma once
// A heading from a double (often -180..180 or unwrapped) into [0, 360): a heading field
// refuses 360.

#include <cstdint>
#include <limits>

#include "seawire/error.hpp"
#include "seawire/nmea/decimal.hpp"

namespace seawire::nmea {

/// `deg` wrapped into [0, 360), rounded to `places` by decimal::from_double's rule: -0.3 is
/// 359.7, 725 is 5, 359.96 at one place 0.0, not 360.0. not_finite for NaN and infinities;
/// out_of_range beyond 1e12 degrees (the wrap would lose the fraction); value_too_large past 19
/// places.
[[nodiscard]] constexpr result<decimal> wrap_heading(double deg, unsigned places) noexcept {
  constexpr double max = std::numeric_limits<double>::max();
  if (!(deg == deg) || deg > 1e12 || deg < -1e12)
    return {decimal{},
            deg == deg && deg <= max && deg >= -max ? errc::out_of_range : errc::not_finite};
  double w = deg - 360.0 * static_cast<double>(static_cast<std::int64_t>(deg / 360.0));
  if (w < 0) w += 360.0;
  result<decimal> r = decimal::from_double(w, places);
  if (r && r.value.compare(decimal(360)) >= 0) r.value = decimal::scaled(0, r.value.places);
  return r;
}

}  // namespace seawire::nmea
