// SPDX-License-Identifier: BSL-1.0
#pragma once
// Hawaii Standard Time, the clock of every RobotX date and time: UTC-10 all year (no daylight
// saving), a fixed offset. The caller passes the time in; system_clock has no leap seconds, so
// a stamp never reads hh:mm:60.

#include <chrono>
#include <cstdint>
#include <limits>

#include "seawire/error.hpp"
#include "seawire/nmea/fields.hpp"

namespace seawire::robotx {

/// The time points this family takes: UTC, as std::chrono::system_clock keeps it. A
/// system_clock::time_point or any sys_time of a coarser duration converts implicitly.
using instant = std::chrono::sys_time<std::chrono::nanoseconds>;

namespace detail {
/// t + d, held at instant::max() (or min()) where the sum would overflow: a caller may pass
/// any instant, instant::max() included.
[[nodiscard]] constexpr instant later_by(instant t, instant::duration d) noexcept {
  if (d > instant::duration::zero() && t > instant::max() - d) return instant::max();
  if (d < instant::duration::zero() && t < instant::min() - d) return instant::min();
  return t + d;
}
/// a - b, held at the duration's limits where the difference would overflow.
[[nodiscard]] constexpr instant::duration elapsed(instant a, instant b) noexcept {
  using rep = instant::duration::rep;
  constexpr rep lo = std::numeric_limits<rep>::min();
  constexpr rep hi = std::numeric_limits<rep>::max();
  const rep x = a.time_since_epoch().count();
  const rep y = b.time_since_epoch().count();
  if (y < 0 && x > hi + y) return instant::duration::max();
  if (y > 0 && x < lo + y) return instant::duration::min();
  return instant::duration(x - y);
}
}  // namespace detail

/// HST = UTC + hst_offset.
inline constexpr std::chrono::hours hst_offset{-10};

/// A report's date and time fields.
struct hst_stamp {
  nmea::date date;
  nmea::time_of_day time;  ///< whole seconds (places == 0), as RobotX writes it
  friend constexpr bool operator==(const hst_stamp&, const hst_stamp&) noexcept = default;
};

/// The wall-clock reading in Hawaii at `utc`, truncated to the second (floor, also before 1970).
template <class Duration>
[[nodiscard]] constexpr std::chrono::local_seconds to_hst_local(
    std::chrono::sys_time<Duration> utc) noexcept {
  using namespace std::chrono;
  return local_seconds{(floor<seconds>(utc) + hst_offset).time_since_epoch()};
}

/// The HST date and time fields for `utc`. out_of_range when the HST year is outside the
/// 1980..2079 a two-digit year can name.
template <class Duration>
[[nodiscard]] constexpr result<hst_stamp> to_hst(std::chrono::sys_time<Duration> utc) noexcept {
  using namespace std::chrono;
  // The Hawaii wall clock, counted as system_clock counts UTC.
  const sys_seconds hst = floor<seconds>(utc) + hst_offset;
  result<hst_stamp> r;
  const nmea::date day = nmea::date::from(hst);
  if (day.year < 1980 || day.year > 2079) {
    r.ec = errc::out_of_range;
    return r;
  }
  r.value.date = day;
  r.value.time = nmea::time_of_day::from(hst, 0).value;  // whole seconds: never fails
  return r;
}

/// The UTC instant an HST date and time name (the time's fraction included). Refuses a date or
/// time the field codecs would refuse, with their errc.
[[nodiscard]] constexpr result<instant> from_hst(const nmea::date& d,
                                                 const nmea::time_of_day& t) noexcept {
  using namespace std::chrono;
  result<instant> r;
  r.ec = nmea::codec<nmea::date>::check(d);
  if (r.ec == errc::ok) r.ec = nmea::codec<nmea::time_of_day>::check(t);
  if (r.ec != errc::ok) return r;
  r.value = nmea::to_sys_time(d, t) - hst_offset;  // the wall clock's reading, less the offset
  return r;
}
[[nodiscard]] constexpr result<instant> from_hst(const hst_stamp& s) noexcept {
  return from_hst(s.date, s.time);
}

/// Write the HST date and time of `utc` into a report (any message with `date` and `time`).
/// Leaves the message unchanged and returns the error when `utc` cannot be stamped.
template <class M, class Duration>
requires requires(M m) {
  m.date = nmea::date{};
  m.time = nmea::time_of_day{};
}
[[nodiscard]] constexpr errc stamp(M& msg, std::chrono::sys_time<Duration> utc) noexcept {
  const result<hst_stamp> s = to_hst(utc);
  if (s) {
    msg.date = s.value.date;
    msg.time = s.value.time;
  }
  return s.ec;
}

}  // namespace seawire::robotx
