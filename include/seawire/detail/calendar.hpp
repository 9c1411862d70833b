// SPDX-License-Identifier: BSL-1.0
#pragma once
// The proleptic Gregorian calendar (internal): month lengths, days since 1970-01-01 and back,
// and the ISO "YYYY-MM-DD" dates of JSON, CSV and CAN logs.

#include <cstdint>
#include <string_view>

#include "seawire/detail/ascii.hpp"

namespace seawire::detail {

/// A calendar date; nothing checks it but valid_date().
struct civil_date {
  std::int64_t year = 1970;
  unsigned month = 1;
  unsigned day = 1;
};

/// Days in `month` (1..12) of `year`.
[[nodiscard]] constexpr unsigned days_in_month(unsigned month, std::int64_t year) noexcept {
  constexpr unsigned days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (month != 2) return days[month - 1];  // the leap year rule (divisions) only for February
  return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0 ? 29 : 28;
}

/// Whether the month is 1..12 and the day one of that month's.
[[nodiscard]] constexpr bool valid_date(const civil_date& c) noexcept {
  return c.month >= 1 && c.month <= 12 && c.day >= 1 && c.day <= days_in_month(c.month, c.year);
}

// Howard Hinnant's algorithms: 400-year eras of 146097 days, years counted from March.

/// The date `z` days after 1970-01-01 (before it when negative).
[[nodiscard]] constexpr civil_date civil_from_days(std::int64_t z) noexcept {
  z += 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const auto doe = static_cast<std::uint64_t>(z - era * 146097);
  const std::uint64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const std::int64_t y = static_cast<std::int64_t>(yoe) + era * 400;
  const std::uint64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const std::uint64_t mp = (5 * doy + 2) / 153;
  const auto d = static_cast<unsigned>(doy - (153 * mp + 2) / 5 + 1);
  const auto m = static_cast<unsigned>(mp < 10 ? mp + 3 : mp - 9);
  return {m <= 2 ? y + 1 : y, m, d};
}

/// Days from 1970-01-01 to a valid date (negative before it).
[[nodiscard]] constexpr std::int64_t days_from_civil(const civil_date& c) noexcept {
  const std::int64_t y = c.year - (c.month <= 2 ? 1 : 0);
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const auto yoe = static_cast<std::uint64_t>(y - era * 400);
  const std::uint64_t doy = (153 * (c.month > 2 ? c.month - 3 : c.month + 9) + 2) / 5 + c.day - 1;
  const std::uint64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<std::int64_t>(doe) - 719468;
}

/// The ISO date "YYYY-MM-DD" at the start of `s`; only the form is checked (valid_date()).
[[nodiscard]] constexpr bool parse_iso_date(std::string_view s, civil_date& out) noexcept {
  if (s.size() < 10 || s[4] != '-' || s[7] != '-') return false;
  unsigned v[3] = {0, 0, 0};
  constexpr std::size_t start[3] = {0, 5, 8};
  constexpr std::size_t len[3] = {4, 2, 2};
  for (std::size_t k = 0; k < 3; ++k) {
    for (std::size_t i = start[k]; i < start[k] + len[k]; ++i) {
      if (!is_digit(s[i])) return false;
      v[k] = v[k] * 10 + static_cast<unsigned>(s[i] - '0');
    }
  }
  out = {v[0], v[1], v[2]};
  return true;
}

}  // namespace seawire::detail
