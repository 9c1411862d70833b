// SPDX-License-Identifier: BSL-1.0
#pragma once
// JSON and CSV for the ANELLO 0xAB00 frame: {"type":"AB00", then the table's JSON keys}, values
// from the wire's integers (a 0.1 field has one fraction digit, latitude six), null for not
// available, gps_time ISO 8601 UTC with milliseconds (integer milliseconds outside years
// 1970..9999). read_frame_json is as strict as build_frame; fix_quality must be a whole number.
// Every frame validate() accepts reads back as the same frame, not available as each type's
// maximum. Schema: tools/decode/README.md, tools/encode/README.md; rules: docs/anello-frame.md.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include "seawire/anello/frame.hpp"
#include "seawire/detail/ascii.hpp"
#include "seawire/detail/calendar.hpp"
#include "seawire/detail/copy.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/csv.hpp"
#include "seawire/nmea/error_text.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/walk.hpp"

namespace seawire::anello {

/// The "type" of a frame in JSON.
inline constexpr std::string_view frame_json_type = "AB00";

namespace detail {

using civil = seawire::detail::civil_date;
using seawire::detail::civil_from_days;

// Milliseconds of 10000-01-01T00:00:00Z: ISO text is written below it.
inline constexpr std::uint64_t iso_limit_ms = 253402300800000ULL;

template <nmea::json_style Style = nmea::json_style::json, nmea::json_sink Sink>
constexpr void write_time_ms(Sink& s, std::uint64_t ms) noexcept {
  if (ms >= iso_limit_ms) {
    nmea::detail::json_uint(s, ms);
    return;
  }
  const auto days = static_cast<std::int64_t>(ms / 86'400'000);
  const std::uint64_t in_day = ms % 86'400'000;
  const civil c = civil_from_days(days);
  // Written into one buffer and handed to the sink at once: "2024-07-03T15:42:58.250Z".
  char tmp[26];
  std::size_t n = 0;
  if constexpr (Style == nmea::json_style::json) tmp[n++] = '"';
  using seawire::detail::append_uint;
  n = append_uint(tmp, n, static_cast<std::uint64_t>(c.year), 4);
  tmp[n++] = '-';
  n = append_uint(tmp, n, c.month, 2);
  tmp[n++] = '-';
  n = append_uint(tmp, n, c.day, 2);
  tmp[n++] = 'T';
  n = append_uint(tmp, n, in_day / 3'600'000, 2);
  tmp[n++] = ':';
  n = append_uint(tmp, n, in_day / 60'000 % 60, 2);
  tmp[n++] = ':';
  n = append_uint(tmp, n, in_day / 1000 % 60, 2);
  tmp[n++] = '.';
  n = append_uint(tmp, n, in_day % 1000, 3);
  tmp[n++] = 'Z';
  if constexpr (Style == nmea::json_style::json) tmp[n++] = '"';
  s.put(std::string_view(tmp, n));
}

/// "YYYY-MM-DDThh:mm:ss[.fff]Z" (0 to 3 fraction digits; "Z" or "+00:00" optional) or integer
/// milliseconds, to milliseconds since 1970.
[[nodiscard]] constexpr errc read_time_ms(const nmea::json_value& v, std::uint64_t& out) noexcept {
  if (v.kind == nmea::json_kind::number) {
    nmea::decimal d;
    const errc e = nmea::detail::parse_decimal(v.text, false, d);
    if (e != errc::ok || d.places != 0 || d.negative) return errc::bad_number;
    out = d.mantissa;
    return errc::ok;
  }
  if (v.kind != nmea::json_kind::string) return errc::bad_time;
  std::string_view s = v.text;
  if (s.ends_with('Z')) {
    s.remove_suffix(1);
  } else if (s.ends_with("+00:00")) {
    s.remove_suffix(6);
  }
  seawire::detail::civil_date date;
  if (s.size() < 19 || (s[10] != 'T' && s[10] != ' ') || !seawire::detail::parse_iso_date(s, date))
    return errc::bad_date;
  if (date.month < 1 || date.month > 12) return errc::month_out_of_range;
  if (date.year < 1970) return errc::out_of_range;  // before the epoch the frame counts from
  if (!seawire::detail::valid_date(date)) return errc::day_out_of_range;
  const result<nmea::time_of_day> t = nmea::parse_time_text(s.substr(11));
  if (!t) return t.ec;
  if (t.value.places > 3 || t.value.second > 59) return errc::bad_time;
  const std::uint64_t ms_of_day =
      ((t.value.hour * 60ULL + t.value.minute) * 60ULL + t.value.second) * 1000ULL +
      t.value.fraction * seawire::detail::pow10_table[3 - t.value.places];
  out = static_cast<std::uint64_t>(seawire::detail::days_from_civil(date)) * 86'400'000ULL +
        ms_of_day;
  return errc::ok;
}

/// round(value * 10^places), halves away from zero, exactly; value_too_large past 63 bits.
[[nodiscard]] constexpr errc scale_decimal(const nmea::decimal& d, unsigned places,
                                           std::int64_t& out) noexcept {
  std::uint64_t m = 0;
  if (!seawire::detail::round_scaled(d.mantissa,
                                     static_cast<int>(places) - static_cast<int>(d.places), 1, m) ||
      m > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
    return errc::value_too_large;
  out = d.negative ? -static_cast<std::int64_t>(m) : static_cast<std::int64_t>(m);
  return errc::ok;
}

}  // namespace detail

/// Whether `key` is a JSON key of the frame (for reporting unknown keys).
[[nodiscard]] constexpr bool has_json_field(std::string_view key) noexcept {
  bool found = false;
  detail::visit_sensor_fields([&](std::uint16_t, const auto& field) {
    found = found || field.json_key == key;
    return !found;
  });
  return found;
}

/// What the frame's table says of field `number` (1..19, heading = 1, as errors number them).
struct sensor_field_about {
  std::string_view name;      ///< the table's name: "heading_deg", "latitude_deg"
  std::string_view json_key;  ///< the JSON key: "heading_deg", "latitude"
  bool is_code = false;       ///< a code or count (fix_quality): a whole number, never rounded
  bool found = false;         ///< false for a number outside 1..19 (the rest is then empty)
};

[[nodiscard]] constexpr sensor_field_about about_sensor_field(std::uint16_t number) noexcept {
  sensor_field_about a;
  detail::visit_sensor_fields([&](std::uint16_t n, const auto& field) {
    if (n != number) return true;
    using value_type = typename std::remove_cvref_t<decltype(field)>::value_type;
    a = {field.name, field.json_key, std::is_integral_v<value_type>, true};
    return false;
  });
  return a;
}

/// An error from validate() or build_frame() for people, about `frame`: "AB00 field 1
/// (heading_deg) 361: value outside the range the spec allows". Into `out`, cut to fit,
/// NUL-terminated; the view is into `out`.
constexpr std::string_view error_text(std::span<char> out, const result<sensor_frame_raw>& r,
                                      const sensor_frame_raw& frame) noexcept {
  nmea::detail::text_out t(out);
  if (r) return t.put("ok").view();
  t.put(frame_json_type).put(" field ").put(std::uint64_t{r.field});
  visit_fields(frame, [&](const auto& f) {
    if (f.number != r.field) return;
    t.put(" (").put(f.key).put(") ");
    t.put(f.value.exact());
  });
  return t.put(": ").put(message(r.ec)).view();
}

/// The former name of error_text(), kept for one release.
[[deprecated("use anello::error_text")]] constexpr std::string_view describe(
    std::span<char> out, const result<sensor_frame_raw>& r,
    const sensor_frame_raw& frame) noexcept {
  return error_text(out, r, frame);
}

/// A field's value: null when not available, else the wire's integer with the row's fraction
/// digits, or the ISO time (an out-of-range value too: the frame has no other way to say it).
template <nmea::json_style Style, nmea::json_sink Sink, class Info>
requires(Info::kind == wire_kind::anello_frame) constexpr void put_field_value(
    Sink& s, const field_view<Info>& f) noexcept {
  if (f.state == field_state::not_available) {
    s.put("null");
  } else if constexpr (Info::value_type::is_time) {
    detail::write_time_ms<Style>(s, static_cast<std::uint64_t>(f.value.raw));
  } else {
    const nmea::decimal d = f.value.exact();  // a constant number of places per row
    seawire::detail::put_fixed(s, d.mantissa, d.places, d.negative);
  }
}

/// A field as a CSV cell: the value unquoted, empty when not available.
template <nmea::json_sink Sink, class Info>
requires(Info::kind ==
         wire_kind::anello_frame) constexpr void put_csv_value(Sink& s,
                                                               const field_view<Info>& f) noexcept {
  if (f.state != field_state::not_available) put_field_value<nmea::json_style::plain>(s, f);
}

namespace detail {
// The longest a frame's JSON can be: the head, every key, each value at its longest (a number as
// put_fixed writes it at most; a time, 26 characters, is shorter), the '}'.
inline constexpr std::size_t frame_json_max_size = [] {
  std::size_t n = 1 + 9 + frame_json_type.size() + 1;
  visit_layout<sensor_frame_raw>([&](auto f) {
    using info = typename decltype(f)::info;
    n += nmea::detail::static_text<seawire::detail::json_member_key_of<info>>.size() +
         seawire::detail::max_fixed_chars;
  });
  return n;
}();

// Where write_json puts the object together before the caller's sink gets it in one piece.
struct frame_text {
  char* out;
  std::size_t size = 0;
  constexpr void put(char c) noexcept { out[size++] = c; }
  constexpr void put(std::string_view v) noexcept {
    seawire::detail::copy_bytes(out + size, v.data(), v.size());
    size += v.size();
  }
};
}  // namespace detail

/// A frame as one JSON object (no newline): "type":"AB00", then the 19 fields in table order.
template <nmea::json_sink Sink>
constexpr void write_json(Sink& sink, const sensor_frame_raw& frame) noexcept {
  char text[detail::frame_json_max_size];
  detail::frame_text s{text};
  write_json_object(s, frame, [](detail::frame_text& out) {
    out.put("{\"type\":\"");
    out.put(frame_json_type);
    out.put('"');
  });
  sink.put(std::string_view(text, s.size));
}

/// The header row of the frame's CSV table (with its LF): the 19 JSON keys in table order.
template <nmea::json_sink Sink>
constexpr void write_csv_header(Sink& s) noexcept {
  write_csv_columns<sensor_frame_raw>(s);
}

/// A frame as one CSV row (with its LF): write_json's values unquoted, empty for not available.
template <nmea::json_sink Sink>
constexpr void write_csv(Sink& s, const sensor_frame_raw& frame) noexcept {
  write_csv_cells(s, frame);
}

/// Reads a frame from a JSON object: `lookup(object, key)` as for nmea::read_json (only
/// object == "" is asked for). Errors as build_frame's: field = 1..19, column = its offset.
template <class Lookup>
[[nodiscard]] constexpr result<sensor_frame_raw> read_frame_json(Lookup&& lookup) noexcept {
  result<sensor_frame_raw> out;
  detail::visit_sensor_fields([&](std::uint16_t number, const auto& field) {
    using field_type = std::remove_cvref_t<decltype(field)>;
    using raw_type = typename field_type::raw_type;
    raw_type& raw = out.value.*field_type::raw_member;
    const nmea::json_value v = lookup(std::string_view{}, field.json_key);
    errc e = errc::ok;
    if (v.blank()) {
      raw = detail::not_available<raw_type>;
      return true;
    }
    std::int64_t wire = 0;
    if constexpr (std::is_same_v<typename field_type::value_type, time_ms>) {
      std::uint64_t ms = 0;
      e = detail::read_time_ms(v, ms);
      if (e == errc::ok &&
          ms > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
        e = errc::value_too_large;
      wire = static_cast<std::int64_t>(ms);
    } else {
      nmea::decimal d;
      e = nmea::detail::json_number(v, d);
      // A code or count (an integer physical type) is never rounded: 7.5 is no fix quality.
      if constexpr (std::is_integral_v<typename field_type::value_type>) {
        if (e == errc::ok && d.places != 0) e = errc::bad_number;
      }
      if (e == errc::ok) e = detail::scale_decimal(d, detail::divisor_places(field.divisor), wire);
      if (e == errc::value_too_large) e = field.refusal();
    }
    if (e == errc::ok) {
      const auto [lo, hi] = field.wire_limits();
      if (wire < lo || wire > hi || field.not_available(static_cast<raw_type>(wire))) {
        e = field.refusal();
      } else {
        raw = static_cast<raw_type>(wire);
      }
    }
    if (e == errc::ok) return true;
    out.value = {};
    out.ec = e;
    out.field = number;
    out.column = static_cast<std::uint16_t>(field.offset);
    return false;
  });
  return out;
}

}  // namespace seawire::anello
