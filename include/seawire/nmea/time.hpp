// SPDX-License-Identifier: BSL-1.0
#pragma once
// UTC time of day (hhmmss[.f], the fraction's digits kept as written) and date (ddmmyy,
// 1980-2079), their std::chrono conversions, and their codecs.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "seawire/detail/ascii.hpp"
#include "seawire/detail/calendar.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/codec.hpp"
#include "seawire/nmea/decimal.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"

namespace seawire::nmea {

/// Time of day hhmmss[.f], 0 to 9 fraction digits kept as written. Second 60 is accepted only
/// as 23:59:60, the one place a UTC leap second can stand, except in a message whose sender
/// prints seconds with a float format (number_forms::rounded_seconds): there "164960.000", what
/// "%06.3f" makes of hh:mm:59.9995 and later, is the first instant of the next minute, kept as
/// written (since_midnight() reads it as that time).
struct time_of_day {
  std::uint8_t hour = 0;
  std::uint8_t minute = 0;
  std::uint8_t second = 0;
  std::uint32_t fraction = 0;  ///< the fraction digits as an integer: ".980" -> 980
  std::uint8_t places = 0;     ///< number of fraction digits: ".980" -> 3

  constexpr time_of_day() noexcept = default;
  /// `time_of_day{16, 49, 59, 980, 3}` is 16:49:59.980.
  constexpr time_of_day(std::uint8_t h, std::uint8_t m, std::uint8_t s, std::uint32_t frac = 0,
                        std::uint8_t frac_places = 0) noexcept
      : hour(h), minute(m), second(s), fraction(frac), places(frac_places) {}
  /// Seconds as a double would lose their fraction: use from_since_midnight() or the parts.
  template <class... A>
  requires detail::any_floating<A...>
  explicit time_of_day(A...) = delete;  // use time_of_day::from_since_midnight(duration, places)

  [[nodiscard]] constexpr std::chrono::nanoseconds since_midnight() const noexcept {
    using namespace std::chrono;
    return hours(hour) + minutes(minute) + seconds(second) +
           nanoseconds(static_cast<std::int64_t>(fraction) *
                       static_cast<std::int64_t>(seawire::detail::pow10_table[9 - places]));
  }
  /// The fraction of the second in nanoseconds.
  [[nodiscard]] constexpr std::uint32_t fraction_ns() const noexcept {
    return static_cast<std::uint32_t>(fraction * seawire::detail::pow10_table[9 - places]);
  }
  /// From a duration since midnight (0 <= d < 24 h), truncated to `places` fraction digits
  /// (truncated, not rounded, so 23:59:59.9999 never becomes 24:00).
  [[nodiscard]] static constexpr result<time_of_day> from_since_midnight(
      std::chrono::nanoseconds d, unsigned places = 3) noexcept {
    result<time_of_day> r;
    const std::int64_t ns = d.count();
    if (ns < 0 || ns >= 86'400'000'000'000 || places > 9) {
      r.ec = errc::out_of_range;
      return r;
    }
    const std::int64_t s = ns / 1'000'000'000;
    r.value.hour = static_cast<std::uint8_t>(s / 3600);
    r.value.minute = static_cast<std::uint8_t>(s / 60 % 60);
    r.value.second = static_cast<std::uint8_t>(s % 60);
    r.value.fraction = static_cast<std::uint32_t>(static_cast<std::uint64_t>(ns % 1'000'000'000) /
                                                  seawire::detail::pow10_table[9 - places]);
    r.value.places = static_cast<std::uint8_t>(places);
    return r;
  }
  /// The UTC time of day of a system_clock time point (system_clock counts UTC without leap
  /// seconds), truncated to `places` fraction digits (0 to 9; out_of_range beyond). Any
  /// time point, before 1970 too.
  template <class Duration>
  [[nodiscard]] static constexpr result<time_of_day> from(std::chrono::sys_time<Duration> t,
                                                          unsigned places = 3) noexcept {
    using namespace std::chrono;
    const auto ns = time_point_cast<nanoseconds>(t);
    return from_since_midnight(ns - floor<days>(ns), places);
  }
  friend constexpr bool operator==(const time_of_day&, const time_of_day&) noexcept = default;
};

/// A ddmmyy date. Two-digit years are read as 1980..2079 (GPS time began in 1980).
struct date {
  std::uint16_t year = 2000;
  std::uint8_t month = 1;
  std::uint8_t day = 1;

  constexpr date() noexcept = default;
  /// `date{2014, 12, 31}`.
  constexpr date(std::uint16_t y, std::uint8_t m, std::uint8_t d) noexcept
      : year(y), month(m), day(d) {}
  template <class... A>
  requires detail::any_floating<A...>
  explicit date(A...) = delete;  // a date is whole numbers: date{year, month, day} or date::from()

  [[nodiscard]] constexpr std::chrono::year_month_day ymd() const noexcept {
    return std::chrono::year_month_day{std::chrono::year{year}, std::chrono::month{month},
                                       std::chrono::day{day}};
  }
  /// The day as a system_clock time point (its midnight, UTC).
  [[nodiscard]] constexpr std::chrono::sys_days sys_days() const noexcept {
    return std::chrono::sys_days{ymd()};
  }
  /// The UTC date of a system_clock time point. A ddmmyy field holds 1980..2079: a date
  /// outside is refused when written (out_of_range).
  template <class Duration>
  [[nodiscard]] static constexpr date from(std::chrono::sys_time<Duration> t) noexcept {
    return from(std::chrono::year_month_day{std::chrono::floor<std::chrono::days>(t)});
  }
  [[nodiscard]] static constexpr date from(std::chrono::year_month_day d) noexcept {
    return {static_cast<std::uint16_t>(static_cast<int>(d.year())),
            static_cast<std::uint8_t>(static_cast<unsigned>(d.month())),
            static_cast<std::uint8_t>(static_cast<unsigned>(d.day()))};
  }
  friend constexpr bool operator==(const date&, const date&) noexcept = default;
};

/// The system_clock time point of a UTC date and time of day (RMC's fields 9 and 1, RobotX's
/// date and time), to the nanosecond. system_clock has no leap seconds: 23:59:60 is the next
/// day's 00:00:00.
[[nodiscard]] constexpr std::chrono::sys_time<std::chrono::nanoseconds> to_sys_time(
    const date& d, const time_of_day& t) noexcept {
  return d.sys_days() + t.since_midnight();
}

namespace detail {

/// Parse an unsigned run of digits of exactly `len` characters at s[pos].
[[nodiscard]] constexpr bool parse_fixed_digits(std::string_view s, std::size_t pos,
                                                std::size_t len, unsigned& out) noexcept {
  if (pos + len > s.size()) return false;
  unsigned v = 0;
  for (std::size_t k = pos; k < pos + len; ++k) {
    if (!seawire::detail::is_digit(s[k])) return false;
    v = v * 10 + static_cast<unsigned>(s[k] - '0');
  }
  out = v;
  return true;
}

/// The first six characters of s (at least six) as three two-digit numbers ("hhmmss",
/// "ddmmyy"), with no branch per digit; false if any is not a digit.
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr bool parse_digit_pairs(std::string_view s,
                                                                     unsigned (&two)[3]) noexcept {
  const auto digit = [&s](std::size_t k) {  // a byte below '0' wraps to a large value
    return static_cast<unsigned>(static_cast<unsigned char>(s[k])) - unsigned{'0'};
  };
  const unsigned d0 = digit(0), d1 = digit(1), d2 = digit(2), d3 = digit(3), d4 = digit(4),
                 d5 = digit(5);
  two[0] = d0 * 10 + d1;
  two[1] = d2 * 10 + d3;
  two[2] = d4 * 10 + d5;
  return static_cast<bool>(static_cast<unsigned>(d0 < 10) & static_cast<unsigned>(d1 < 10) &
                           static_cast<unsigned>(d2 < 10) & static_cast<unsigned>(d3 < 10) &
                           static_cast<unsigned>(d4 < 10) & static_cast<unsigned>(d5 < 10));
}

/// parse_digit_pairs of the six bytes at `p`, read as one little-endian word: p[0, 8) must be
/// readable (six bytes of a framed sentence's body are: its "*hh" follows). Each byte made
/// 0..9, then each byte plus ten times the one before it: the pairs are bytes 0, 2 and 4.
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr bool scan_digit_pairs(const char* p,
                                                                    unsigned (&two)[3]) noexcept {
  const std::uint64_t w = seawire::detail::load_le64(p);
  if ((seawire::detail::non_digit_bytes(w) & 0x0000808080808080U) != 0) [[unlikely]]
    return false;
  const std::uint64_t x = w ^ 0x3030303030303030U;
  const std::uint64_t y = x * 10 + (x >> 8U);  // bytes 0 to 5 hold 0..99: no carry between them
  two[0] = static_cast<unsigned>(y & 0xFFU);
  two[1] = static_cast<unsigned>((y >> 16U) & 0xFFU);
  two[2] = static_cast<unsigned>((y >> 32U) & 0xFFU);
  return true;
}

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// codecs

template <>
struct codec<time_of_day> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = 16;  // hhmmss.fffffffff
  static constexpr bool allows_blank = false;
  /// scan() refuses a blank field at its first byte (one_pass.hpp: scans_no_blank).
  static constexpr bool scan_refuses_blank = true;

  // The templates come first: clang (14) cannot evaluate, in a constant expression, a member
  // template of this explicit specialization that is defined after the function calling it.

  /// check(), and with RoundedSeconds second 60 with a fraction of zeros at any minute.
  template <bool RoundedSeconds>
  SEAWIRE_ALWAYS_INLINE static constexpr errc check_form(const time_of_day& v) noexcept {
    if (v.hour > 23) [[unlikely]]
      return errc::hour_out_of_range;
    if (v.minute > 59) [[unlikely]]
      return errc::minute_out_of_range;
    if (v.second > 60 || (v.second == 60 && !(v.hour == 23 && v.minute == 59) &&
                          !(RoundedSeconds && v.fraction == 0)))
      return errc::second_out_of_range;
    if (v.places > 9 || v.fraction >= seawire::detail::pow10_table[v.places]) [[unlikely]]
      return errc::bad_time;
    return errc::ok;
  }
  template <bool RoundedSeconds>
  static constexpr errc read_form(field_reader& r, time_of_day& v) noexcept {
    const std::string_view s = r.take().text;
    if (s.size() < 6) [[unlikely]]
      return errc::bad_time;
    unsigned two[3];  // hh, mm, ss
    if (!detail::parse_digit_pairs(s, two)) [[unlikely]]
      return errc::bad_time;
    unsigned frac = 0;
    std::size_t places = 0;
    if (s.size() > 6) {
      places = s.size() - 7;
      // "hhmmss." with nothing after the point is malformed, not zero places.
      if (s[6] != '.' || places == 0 || places > 9 ||
          !detail::parse_fixed_digits(s, 7, places, frac))
        return errc::bad_time;
    }
    v = {static_cast<std::uint8_t>(two[0]), static_cast<std::uint8_t>(two[1]),
         static_cast<std::uint8_t>(two[2]), frac, static_cast<std::uint8_t>(places)};
    return check_form<RoundedSeconds>(v);
  }

  /// The one-pass reader (one_pass.hpp): hhmmss[.f] at `p`, up to the byte after it; nullptr
  /// for what read_form refuses. `end` is the body's end: six digits must fit before it.
  template <bool RoundedSeconds>
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan_form(const char* p, const char* end,
                                                               time_of_day& v) noexcept {
    if (end - p < 6) [[unlikely]]
      return nullptr;
    unsigned two[3];  // hh, mm, ss
    if (!detail::scan_digit_pairs(p, two)) [[unlikely]]
      return nullptr;
    p += 6;
    unsigned frac = 0;
    std::size_t places = 0;
    if (p != end && *p == '.') {
      // Up to the first byte no digit (there is one: the '*' at `end`); more than nine digits
      // wrap `frac` and are refused below.
      const char* const first = ++p;
      for (unsigned d = 0; (d = static_cast<unsigned char>(*p) - unsigned{'0'}) < 10; ++p)
        frac = frac * 10 + d;
      places = static_cast<std::size_t>(p - first);
      if (places - 1 >= 9) [[unlikely]]  // none, or more than nine
        return nullptr;
    }
    v = {static_cast<std::uint8_t>(two[0]), static_cast<std::uint8_t>(two[1]),
         static_cast<std::uint8_t>(two[2]), frac, static_cast<std::uint8_t>(places)};
    return check_form<RoundedSeconds>(v) == errc::ok ? p : nullptr;
  }

  static constexpr errc read(field_reader& r, time_of_day& v) noexcept {
    return read_form<false>(r, v);
  }
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan(const char* p, const char* end,
                                                          time_of_day& v) noexcept {
    return scan_form<false>(p, end, v);
  }
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan_rounded_seconds(const char* p,
                                                                          const char* end,
                                                                          time_of_day& v) noexcept {
    return scan_form<true>(p, end, v);
  }
  /// read(), and second 60 with a fraction of zeros at any minute (number_forms::rounded_seconds).
  static constexpr errc read_rounded_seconds(field_reader& r, time_of_day& v) noexcept {
    return read_form<true>(r, v);
  }
  SEAWIRE_ALWAYS_INLINE static constexpr errc check(const time_of_day& v) noexcept {
    return check_form<false>(v);
  }
  template <sentence_writer W>
  static constexpr void write(W& w, const time_of_day& v) noexcept {
    w.put_pairs(v.hour, v.minute, v.second);
    if (v.places > 0) {
      w.put('.');
      w.put_uint(v.fraction, v.places);
    }
  }
};

template <>
struct codec<date> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = 6;
  static constexpr bool allows_blank = false;
  /// scan() refuses a blank field at its first byte (one_pass.hpp: scans_no_blank).
  static constexpr bool scan_refuses_blank = true;
  static constexpr errc read(field_reader& r, date& v) noexcept {
    const std::string_view s = r.take().text;
    if (s.size() != 6) [[unlikely]]
      return errc::bad_date;
    unsigned two[3];  // dd, mm, yy
    if (!detail::parse_digit_pairs(s, two)) [[unlikely]]
      return errc::bad_date;
    v = {static_cast<std::uint16_t>(two[2] < 80 ? 2000 + two[2] : 1900 + two[2]),
         static_cast<std::uint8_t>(two[1]), static_cast<std::uint8_t>(two[0])};
    return check(v);
  }
  /// The one-pass reader: ddmmyy at `p`, six digits before `end`.
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan(const char* p, const char* end,
                                                          date& v) noexcept {
    unsigned two[3];  // dd, mm, yy
    if (end - p < 6 || !detail::scan_digit_pairs(p, two)) [[unlikely]]
      return nullptr;
    v = {static_cast<std::uint16_t>(two[2] < 80 ? 2000 + two[2] : 1900 + two[2]),
         static_cast<std::uint8_t>(two[1]), static_cast<std::uint8_t>(two[0])};
    return check(v) == errc::ok ? p + 6 : nullptr;
  }
  SEAWIRE_ALWAYS_INLINE static constexpr errc check(const date& v) noexcept {
    if (v.year < 1980 || v.year > 2079) [[unlikely]]
      return errc::out_of_range;
    if (v.month < 1 || v.month > 12) [[unlikely]]
      return errc::month_out_of_range;
    if (v.day < 1 || v.day > seawire::detail::days_in_month(v.month, v.year)) [[unlikely]]
      return errc::day_out_of_range;
    return errc::ok;
  }
  template <sentence_writer W>
  static constexpr void write(W& w, const date& v) noexcept {
    w.put_pairs(v.day, v.month, v.year % 100U);
  }
};

// ---------------------------------------------------------------------------------------------
// from text people write (JSON and the command line take these)

/// A time of day from "hh:mm:ss[.f]" (1 to 9 fraction digits after a point, kept) or the wire's
/// "hhmmss[.f]". bad_time for other shapes, *_out_of_range for impossible values (second 60
/// with a fraction of zeros is possible at any minute with `rounded_seconds`, for a message
/// that declares number_forms::rounded_seconds).
[[nodiscard]] constexpr result<time_of_day> parse_time_text(std::string_view s,
                                                            bool rounded_seconds = false) noexcept {
  result<time_of_day> r;
  const bool colons = s.size() >= 8 && s[2] == ':' && s[5] == ':';
  const std::size_t step = colons ? 3 : 2;
  const std::size_t end = colons ? 8 : 6;
  unsigned h = 0, m = 0, sec = 0, frac = 0;
  std::size_t places = 0;
  bool ok = detail::parse_fixed_digits(s, 0, 2, h) && detail::parse_fixed_digits(s, step, 2, m) &&
            detail::parse_fixed_digits(s, 2 * step, 2, sec);
  if (ok && s.size() > end) {
    places = s.size() - end - 1;
    ok = s[end] == '.' && places >= 1 && places <= 9 &&
         detail::parse_fixed_digits(s, end + 1, places, frac);
  }
  if (!ok) {
    r.ec = errc::bad_time;
    return r;
  }
  r.value = {static_cast<std::uint8_t>(h), static_cast<std::uint8_t>(m),
             static_cast<std::uint8_t>(sec), frac, static_cast<std::uint8_t>(places)};
  r.ec = rounded_seconds ? codec<time_of_day>::check_form<true>(r.value)
                         : codec<time_of_day>::check(r.value);
  return r;
}

/// A date from ISO "YYYY-MM-DD" or the wire's "ddmmyy"; years 1980..2079, as the wire's.
[[nodiscard]] constexpr result<date> parse_date_text(std::string_view s) noexcept {
  result<date> r;
  seawire::detail::civil_date iso;
  unsigned y = 0, m = 0, d = 0;
  if (s.size() == 10 && seawire::detail::parse_iso_date(s, iso)) {
    r.value = {static_cast<std::uint16_t>(iso.year), static_cast<std::uint8_t>(iso.month),
               static_cast<std::uint8_t>(iso.day)};
  } else if (s.size() == 6 && detail::parse_fixed_digits(s, 0, 2, d) &&
             detail::parse_fixed_digits(s, 2, 2, m) && detail::parse_fixed_digits(s, 4, 2, y)) {
    r.value = {static_cast<std::uint16_t>(y < 80 ? 2000 + y : 1900 + y),
               static_cast<std::uint8_t>(m), static_cast<std::uint8_t>(d)};
  } else {
    r.ec = errc::bad_date;
    return r;
  }
  r.ec = codec<date>::check(r.value);
  return r;
}

}  // namespace seawire::nmea
