// SPDX-License-Identifier: BSL-1.0
#pragma once
// Optional: fmt::formatter for every message and value type of every wire. Needs {fmt} (8 or
// later); nothing else in seawire does. "{}" is TYPE{name=value, ...} with values as the JSON
// writers write them, only text quoted (CPNVG{timestamp=16:49:59.034, ...}, PGN128259{...},
// AB00{...}); "{:j}" is exactly write_json (a PGN without its frame header). Value types format
// on their own ("{}" of msg.lat is "42.36185237"; a PGN field not available is null).

#include <fmt/format.h>

#include <algorithm>
#include <string_view>

#include "seawire/anello/frame_json.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/json.hpp"

namespace seawire::detail {

/// A json_sink writing to a fmt output iterator.
template <class OutputIt>
struct fmt_sink {
  OutputIt out;
  constexpr void put(char c) { *out++ = c; }
  constexpr void put(std::string_view s) { out = std::copy(s.begin(), s.end(), out); }
};

/// Parses "" or "j" (and, where `json_only` is false, nothing else).
struct fmt_spec {
  bool json = false;

  template <class ParseContext>
  constexpr auto parse(ParseContext& ctx) {
    auto it = ctx.begin();
    if (it != ctx.end() && *it == 'j') {
      json = true;
      ++it;
    }
    if (it != ctx.end() && *it != '}') {
#if FMT_VERSION >= 110000
      fmt::report_error("seawire: the only format option is 'j' (JSON)");
#else
      ctx.on_error("seawire: the only format option is 'j' (JSON)");
#endif
    }
    return it;
  }
};

/// TYPE{name=value, ...} with plain values: the type as JSON's "type" has it, then the fields.
template <class Sink, nmea::message_like T>
constexpr void write_plain(Sink& s, const T& msg) {
  nmea::write_type(s, msg);
  write_plain_fields(s, msg);
}

/// PGN<n>{name=value, ...} with plain values, reserved bits left out.
template <class Sink, nmea2000::pgn_like P>
constexpr void write_plain(Sink& s, const P& msg) {
  s.put("PGN");
  nmea::detail::json_uint(s, nmea2000::pgn_table<P>.info.pgn);
  write_plain_fields(s, msg);
}

/// AB00{name=value, ...} with plain values (gps_time ISO 8601, unquoted).
template <class Sink>
constexpr void write_plain(Sink& s, const anello::sensor_frame_raw& frame) {
  s.put(anello::frame_json_type);
  write_plain_fields(s, frame);
}

/// Value types with a formatter of their own (messages and optionals are not among them).
template <class T>
concept fmt_value = std::is_same_v<T, nmea::decimal> || std::is_same_v<T, nmea::time_of_day> ||
    std::is_same_v<T, nmea::date> || nmea::char_enum_like<T> || nmea::word_enum_like<T> ||
    nmea::is_integer_wrapper<T> || nmea::is_ddmm_position<T> || nmea::is_degrees_position<T>;

}  // namespace seawire::detail

/// Messages of every wire (a sentence, a PGN, the 0xAB00 frame): "{}" is TYPE{field=value, ...};
/// "{:j}" one JSON object (a PGN's without the frame's header: nmea2000::write_json(sink, msg)).
template <seawire::walkable M>
struct fmt::formatter<M> : seawire::detail::fmt_spec {
  template <class FormatContext>
  auto format(const M& msg, FormatContext& ctx) const {
    seawire::detail::fmt_sink<decltype(ctx.out())> s{ctx.out()};
    if (!json) {
      seawire::detail::write_plain(s, msg);
    } else if constexpr (seawire::nmea::message_like<M>) {
      seawire::nmea::write_json(s, msg);
    } else if constexpr (seawire::nmea2000::pgn_like<M>) {
      seawire::nmea2000::write_json(s, msg);
    } else {
      seawire::anello::write_json(s, msg);
    }
    return s.out;
  }
};

/// A sentence no message of a set describes: its line, or "{:j}" JSON with its fields.
template <>
struct fmt::formatter<seawire::nmea::unknown_sentence> : seawire::detail::fmt_spec {
  template <class FormatContext>
  auto format(const seawire::nmea::unknown_sentence& u, FormatContext& ctx) const {
    seawire::detail::fmt_sink<decltype(ctx.out())> s{ctx.out()};
    if (json) {
      seawire::nmea::write_json(s, u);
    } else {
      s.put(u.sentence.line);
    }
    return s.out;
  }
};

/// Value types: decimals, positions, times, dates, enums. "{:j}" gives the JSON value (quoted
/// where JSON needs it).
template <seawire::detail::fmt_value T>
struct fmt::formatter<T> : seawire::detail::fmt_spec {
  template <class FormatContext>
  auto format(const T& v, FormatContext& ctx) const {
    seawire::detail::fmt_sink<decltype(ctx.out())> s{ctx.out()};
    if (json) {
      seawire::nmea::write_json_value(s, v);
    } else {
      seawire::nmea::write_json_value<seawire::nmea::json_style::plain>(s, v);
    }
    return s.out;
  }
};

/// text<N>: its characters ("{:j}": a JSON string).
template <std::size_t N>
struct fmt::formatter<seawire::nmea::text<N>> : seawire::detail::fmt_spec {
  template <class FormatContext>
  auto format(const seawire::nmea::text<N>& v, FormatContext& ctx) const {
    seawire::detail::fmt_sink<decltype(ctx.out())> s{ctx.out()};
    if (json) {
      seawire::nmea::write_json_value(s, v);
    } else {
      s.put(v.view());
    }
    return s.out;
  }
};

/// NMEA 2000 field values: numbers with the resolution's digits, lookups and flags by name,
/// dates and times; null when not available, the state's name when out of range or reserved.
template <seawire::nmea2000::field_value T>
struct fmt::formatter<T> : seawire::detail::fmt_spec {
  template <class FormatContext>
  auto format(const T& v, FormatContext& ctx) const {
    seawire::detail::fmt_sink<decltype(ctx.out())> s{ctx.out()};
    if (json) {
      seawire::nmea2000::write_json_value(s, v);
    } else {
      seawire::nmea2000::write_json_value<seawire::nmea::json_style::plain>(s, v);
    }
    return s.out;
  }
};
