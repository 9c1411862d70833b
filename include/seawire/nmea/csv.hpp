// SPDX-License-Identifier: BSL-1.0
#pragma once
// CSV for messages: one table per message type, a header row of the field names
// (write_csv_header<T>) and one row per message (write_csv), RFC 4180 with LF line ends. Cells
// are the JSON values unquoted, empty when blank or not available (pandas NaN, R NA); a cell is
// quoted, inner quotes doubled, only when it holds a comma, a quote, CR or LF. Every wire's tables
// are loops over the walk (write_csv_columns, write_csv_cells). Details: tools/decode/README.md.

#include <cstddef>
#include <string_view>
#include <type_traits>

#include "seawire/nmea/description.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea/variation.hpp"

namespace seawire::nmea {

/// One CSV field holding `text`: as is, or quoted with inner quotes doubled when it holds a
/// comma, a quote, CR or LF.
template <json_sink Sink>
constexpr void write_csv_text(Sink& s, std::string_view text) noexcept {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) {
    s.put(text);
    return;
  }
  s.put('"');
  for (const char c : text) {
    if (c == '"') s.put('"');
    s.put(c);
  }
  s.put('"');
}

/// One value as a CSV field: its plain JSON text, quoted if need be.
template <json_sink Sink, class T>
constexpr void write_csv_value(Sink& s, const T& v) noexcept {
  if constexpr (detail::is_optional<T>::value) {
    if (v) write_csv_value(s, *v);
  } else if constexpr (std::is_same_v<T, magnetic_variation>) {
    if (v.value) write_json_value<json_style::plain>(s, v);
  } else if constexpr (detail::is_text<T>::value) {
    write_csv_text(s, v.view());
  } else if constexpr (std::is_arithmetic_v<T> || std::is_same_v<T, decimal> ||
                       is_ddmm_position<T> || is_degrees_position<T> ||
                       std::is_same_v<T, time_of_day> || std::is_same_v<T, date> ||
                       char_enum_like<T> || word_enum_like<T>) {
    write_json_value<json_style::plain>(s, v);  // digits, ':', '-', '.' and letters only
  } else {
    // Any other value with a codec (a RobotX light pattern): its wire text, quoted if need be.
    json_buffer<256> text;
    write_json_value<json_style::plain>(text, v);
    write_csv_text(s, text.view());
  }
}

/// A field as a CSV cell (the walk's per-wire value text: see seawire::write_csv_cells).
template <json_sink Sink, class Info>
requires(Info::kind ==
         wire_kind::nmea0183) constexpr void put_csv_value(Sink& s,
                                                           const field_view<Info>& f) noexcept {
  write_csv_value(s, f.value);
}

}  // namespace seawire::nmea

namespace seawire {

/// The JSON keys of M's fields as CSV header cells, in wire order, then LF; `first` false puts a
/// comma before the first (after columns of the caller's own).
template <walkable M, nmea::json_sink Sink>
constexpr void write_csv_columns(Sink& s, bool first = true) noexcept {
  visit_layout<M>([&](auto f) {
    if (!first) s.put(',');
    first = false;
    nmea::write_csv_text(s, f.key);
  });
  s.put('\n');
}

namespace detail {
/// A sink that passes text on and counts it.
template <class Sink>
struct counted_sink {
  Sink& out;
  std::size_t size = 0;
  constexpr void put(char c) noexcept {
    ++size;
    out.put(c);
  }
  constexpr void put(std::string_view v) noexcept {
    size += v.size();
    out.put(v);
  }
};
}  // namespace detail

/// Every field of `msg` as a CSV cell, in wire order, then LF (`first` as write_csv_columns'). A
/// cell's text is its wire's (put_csv_value, found with the field). A row that is one empty cell
/// is written `""`: as an empty line, CSV readers would skip it (pandas) or read no cell (Python).
template <nmea::json_sink Sink, walkable M>
constexpr void write_csv_cells(Sink& s, const M& msg, bool first = true) noexcept {
  const bool alone = first && field_count_of<M> == 1;
  visit_fields(msg, [&](const auto& f) {
    if (!first) s.put(',');
    first = false;
    if (alone) {
      detail::counted_sink<Sink> c{s};
      put_csv_value(c, f);
      if (c.size == 0) s.put("\"\"");
    } else {
      put_csv_value(s, f);
    }
  });
  s.put('\n');
}

}  // namespace seawire

namespace seawire::nmea {

/// The header row of T's table (with its LF): the field names in wire order.
template <message_like T, json_sink Sink>
constexpr void write_csv_header(Sink& s) noexcept {
  write_csv_columns<T>(s);
}

/// A message as one row of its type's table (with its LF): each field in wire order.
template <json_sink Sink, message_like T>
constexpr void write_csv(Sink& s, const T& msg) noexcept {
  write_csv_cells(s, msg);
}

}  // namespace seawire::nmea
