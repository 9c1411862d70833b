// SPDX-License-Identifier: BSL-1.0
#pragma once
// NMEA 2000 messages as JSON and CSV, and read back from a JSON object's tokenised values
// (nmea/json.hpp's json_value): "type":"PGN<n>", the log header ("time_s", "interface" or
// "direction", "prio", "src", "dst"), then the PGN's fields by name. Sentinel states are null,
// "out_of_range", "reserved"; a flag set is [] when sent clear, null when not sent. Reading also
// takes a lookup as its number and a flag set as its raw word. The whole schema:
// tools/decode/README.md and tools/encode/README.md (NMEA 2000).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>

#include "seawire/detail/ascii.hpp"
#include "seawire/detail/calendar.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/csv.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/log.hpp"

namespace seawire::nmea2000 {

using nmea::json_kind;
using nmea::json_sink;
using nmea::json_value;

/// How a message was carried: what the JSON object says besides the fields.
struct message_header {
  can_id id;
  std::optional<std::int64_t> time_us;
  nmea::text<15> interface;          ///< empty when the log has none
  char direction = 0;                ///< 'R' or 'T' for yd_raw, 0 otherwise
  std::optional<log_format> format;  ///< the log's format (what time_us counts from)
};

/// The header of the message the log record `r` carries (or completes).
[[nodiscard]] constexpr message_header header_of(const log_record& r) noexcept {
  message_header h;
  h.id = r.id;
  h.time_us = r.time_us;
  h.interface = r.interface;
  if (r.format == log_format::yd_raw) h.direction = r.direction;
  h.format = r.format;
  return h;
}

namespace detail {

template <nmea::json_style Style, json_sink Sink>
constexpr void json_state(Sink& s, field_state st) noexcept {
  if (st == field_state::not_available) {
    s.put("null");
  } else {
    if constexpr (Style == nmea::json_style::json) s.put('"');
    s.put(name(st));
    if constexpr (Style == nmea::json_style::json) s.put('"');
  }
}

template <class T>
struct is_number : std::false_type {};
template <unsigned B, bool S, resolution R, unsigned N>
struct is_number<number<B, S, R, N>> : std::true_type {};
template <class T>
struct is_lookup : std::false_type {};
template <class E, unsigned B>
struct is_lookup<lookup<E, B>> : std::true_type {};
template <class T>
struct is_flags : std::false_type {};
template <class E, unsigned B>
struct is_flags<flags<E, B>> : std::true_type {};

template <json_sink Sink>
constexpr void json_int(Sink& s, std::int64_t v) noexcept {
  seawire::detail::put_fixed(s, seawire::detail::magnitude(v), 0, v < 0);
}

/// Microseconds as seconds: 3 fraction digits, or 6 when the time has microseconds.
template <json_sink Sink>
constexpr void json_seconds(Sink& s, std::int64_t t) noexcept {
  const std::uint64_t m = seawire::detail::magnitude(t);
  if (m % 1000 == 0) {
    seawire::detail::put_fixed(s, m / 1000, 3, t < 0);
  } else {
    seawire::detail::put_fixed(s, m, 6, t < 0);
  }
}

template <nmea::json_style Style, json_sink Sink>
constexpr void quote(Sink& s) noexcept {
  if constexpr (Style == nmea::json_style::json) s.put('"');
}

/// The names of the flags set in `v` (a set bit without a name as "bit_N"), quoted in JSON,
/// `sep` between them. Returns whether any flag is set.
template <nmea::json_style Style, json_sink Sink, class T>
constexpr bool flag_names(Sink& s, const T& v, char sep) noexcept {
  bool any = false;
  for (unsigned bit = 0; bit < T::bits; ++bit) {
    if (!v.test_bit(bit)) continue;
    if (any) s.put(sep);
    any = true;
    quote<Style>(s);
    const std::string_view n = enum_name<value_enum_t<T>>(bit);
    if (n.empty()) {
      s.put("bit_");
      nmea::detail::json_uint(s, bit);
    } else {
      s.put(n);
    }
    quote<Style>(s);
  }
  return any;
}

/// A string's text as a JSON string's content (no quotes): printable ASCII as it is, '"' and '\'
/// escaped, every other character as \u00XX (a single-byte string's byte XX) or \uXXXX (a UTF-16
/// string's code unit, a pair for a character past U+FFFF), so any byte reads back exactly.
template <json_sink Sink, text_value T>
constexpr void json_text(Sink& s, const T& v) noexcept {
  const std::string_view t = v.text();
  if (!v.is_utf16()) {
    nmea::detail::json_escape(s, t);
    return;
  }
  for (std::size_t i = 0; i < t.size() / 2; ++i) {
    const std::uint32_t u = utf16_unit(t, i);
    if (u < 0x80) {
      const char c = static_cast<char>(u);
      nmea::detail::json_escape(s, std::string_view(&c, 1));
      continue;
    }
    s.put("\\u");
    for (unsigned shift = 16; shift > 0;) {
      shift -= 4;
      s.put(seawire::detail::hex_digit_upper(u >> shift));
    }
  }
}

/// A string's text as a CSV cell holds it: printable ASCII as it is (a quote, a backslash too),
/// every other character escaped as json_text escapes it, so the cell is the JSON string's value
/// but for those.
template <json_sink Sink, text_value T>
constexpr void csv_text(Sink& s, const T& v) noexcept {
  const std::string_view t = v.text();
  const std::size_t step = v.is_utf16() ? 2 : 1;
  for (std::size_t i = 0; i + step <= t.size(); i += step) {
    const std::uint32_t c = v.is_utf16() ? utf16_unit(t, i / 2) : static_cast<unsigned char>(t[i]);
    if (c >= 0x20 && c < 0x7F) {
      s.put(static_cast<char>(c));
    } else if (c < 0x80) {
      const char b = static_cast<char>(c);
      nmea::detail::json_escape(s, std::string_view(&b, 1));
    } else {
      s.put("\\u");
      for (unsigned shift = 16; shift > 0;) {
        shift -= 4;
        s.put(seawire::detail::hex_digit_upper(c >> shift));
      }
    }
  }
}

/// Passes text on with every '"' doubled (inside a quoted CSV field).
template <class Sink>
struct csv_quoted_sink {
  Sink& out;
  constexpr void put(char c) noexcept {
    if (c == '"') out.put('"');
    out.put(c);
  }
  constexpr void put(std::string_view v) noexcept {
    for (const char c : v) put(c);
  }
};

}  // namespace detail

/// One field value as JSON (or plain).
template <nmea::json_style Style = nmea::json_style::json, json_sink Sink, field_value T>
constexpr void write_json_value(Sink& s, const T& v) noexcept {
  using nmea::detail::json_uint;
  if constexpr (text_value<T>) {
    if (!v.has_value()) {  // an empty text: not available
      s.put("null");
      return;
    }
    s.put('"');  // quoted in plain text too, as a sentence's text is
    detail::json_text(s, v);
    s.put('"');
    return;
  } else if constexpr (detail::is_flags<T>::value) {
    if (!v.has_value()) {  // not sent: not the same as [] (sent, no flag set)
      s.put("null");
      return;
    }
    s.put('[');
    detail::flag_names<Style>(s, v, ',');
    s.put(']');
    return;
  } else {
    if (!v.has_value()) {
      detail::json_state<Style>(s, v.state());
      return;
    }
    if constexpr (detail::is_number<T>::value) {
      nmea::detail::json_decimal(s, *v.exact());
    } else if constexpr (detail::is_lookup<T>::value) {
      if (v.name().empty()) {
        json_uint(s, static_cast<std::uint64_t>(v.raw()));
      } else {
        detail::quote<Style>(s);
        s.put(v.name());
        detail::quote<Style>(s);
      }
    } else if constexpr (detail::is_keyed_lookup<T>) {
      json_uint(s, static_cast<std::uint64_t>(v.raw()));  // alone, without its key: no name
    } else if constexpr (std::is_same_v<T, day_count>) {
      const std::chrono::year_month_day ymd(*v.value());
      nmea::detail::json_joined<Style == nmea::json_style::json>(
          s,
          {{{static_cast<std::uint64_t>(static_cast<int>(ymd.year())), 4},
            {static_cast<unsigned>(ymd.month()), 2},
            {static_cast<unsigned>(ymd.day()), 2}}},
          '-');
    } else if constexpr (std::is_same_v<T, time_since_midnight>) {
      const auto ticks = static_cast<std::uint64_t>(v.raw());  // 0.1 ms
      nmea::detail::json_joined<Style == nmea::json_style::json>(
          s, {{{ticks / 36'000'000, 2}, {ticks / 600'000 % 60, 2}, {ticks / 10'000 % 60, 2}}}, ':',
          {ticks % 10'000, 4});
    }
  }
}

/// A keyed field's value beside its key: the pair's name, or the number when the table does not
/// name the pair (or the key is not available).
template <nmea::json_style Style = nmea::json_style::json, json_sink Sink, class L>
constexpr void write_json_value(Sink& s, const keyed_reading<L>& v) noexcept {
  if (!v.has_value()) {
    detail::json_state<Style>(s, v.state());
  } else if (v.name().empty()) {
    nmea::detail::json_uint(s, static_cast<std::uint64_t>(v.raw()));
  } else {
    detail::quote<Style>(s);
    s.put(v.name());
    detail::quote<Style>(s);
  }
}

/// A repeating group as JSON: an array with an object per repetition, its fields by name in wire
/// order (plain: `[{prn=30, elevation_rad=1.0646}, ...]`, fmt's form).
template <nmea::json_style Style = nmea::json_style::json, json_sink Sink, class G>
requires detail::is_group_value<G>
constexpr void write_json_value(Sink& s, const G& g) noexcept {
  using Item = typename G::item_type;
  s.put('[');
  bool first_item = true;
  for (const Item& item : g) {
    if (!first_item) s.put(Style == nmea::json_style::json ? "," : ", ");
    first_item = false;
    s.put('{');
    bool first = true;
    Item::n2k_item.for_each([&](const auto& f, unsigned, std::uint16_t) {
      using F = std::remove_cvref_t<decltype(f)>;
      if constexpr (!F::is_reserved) {
        if constexpr (Style == nmea::json_style::json) {
          s.put(first ? "\"" : ",\"");
          s.put(f.name);
          s.put("\":");
        } else {
          if (!first) s.put(", ");
          s.put(f.name);
          s.put('=');
        }
        first = false;
        write_json_value<Style>(s, item.*F::member);
      }
    });
    s.put('}');
  }
  s.put(']');
}

/// Opaque bytes as JSON: a string of hex digits, two a byte, upper case ("" for none).
template <nmea::json_style Style = nmea::json_style::json, json_sink Sink, class B>
requires detail::is_opaque_bytes<B>
constexpr void write_json_value(Sink& s, const B& b) noexcept {
  s.put('"');
  for (const std::uint8_t byte : b.bytes()) detail::put_hex_byte(s, byte, true);
  s.put('"');
}

/// `{"type":"PGN<n>"` and the header members, without the closing brace.
template <json_sink Sink>
constexpr void write_json_header(Sink& s, const message_header& h) noexcept {
  using nmea::detail::json_uint;
  s.put("{\"type\":\"PGN");
  json_uint(s, h.id.pgn);
  s.put('"');
  if (h.time_us) {
    s.put(",\"time_s\":");
    detail::json_seconds(s, *h.time_us);
  }
  if (h.interface.size() != 0) {
    s.put(",\"interface\":");
    nmea::detail::json_string<nmea::json_style::json>(s, h.interface.view());
  }
  if (h.direction != 0) {
    s.put(",\"direction\":\"");
    s.put(h.direction);
    s.put('"');
  }
  s.put(",\"prio\":");
  json_uint(s, h.id.priority);
  s.put(",\"src\":");
  json_uint(s, h.id.source);
  s.put(",\"dst\":");
  json_uint(s, h.id.destination);
}

/// A field's value (the walk's per-wire value text: see seawire::write_json_fields).
template <nmea::json_style Style, json_sink Sink, class Info>
requires(Info::kind ==
         wire_kind::nmea2000) constexpr void put_field_value(Sink& s,
                                                             const field_view<Info>& f) noexcept {
  write_json_value<Style>(s, f.value);
}

/// A field as a CSV cell: empty when not available, flags joined by ';' ("none" when the word
/// was sent with no flag set), else the value as plain text.
template <json_sink Sink, class Info>
requires(Info::kind ==
         wire_kind::nmea2000) constexpr void put_csv_value(Sink& s,
                                                           const field_view<Info>& f) noexcept {
  using V = typename Info::value_type;
  if constexpr (text_value<V>) {
    // The text (csv_text), quoted by CSV's rule when it holds a comma or a quote.
    if (!f.value.has_value()) return;
    if (f.value.text().find_first_of(",\"") == std::string_view::npos) {
      detail::csv_text(s, f.value);
    } else {
      s.put('"');
      detail::csv_quoted_sink<Sink> q{s};
      detail::csv_text(q, f.value);
      s.put('"');
    }
  } else if constexpr (detail::is_opaque_bytes<V>) {
    for (const std::uint8_t byte : f.value.bytes()) detail::put_hex_byte(s, byte, true);
  } else if constexpr (detail::is_group_value<V>) {
    // One cell: the repetitions separated by ';', a repetition's fields by '|' in wire order,
    // each as its own cell would be (empty when not available).
    bool first_item = true;
    for (const auto& item : f.value) {
      if (!first_item) s.put(';');
      first_item = false;
      bool first = true;
      std::remove_cvref_t<decltype(item)>::n2k_item.for_each(
          [&](const auto& e, unsigned, std::uint16_t) {
            using F = std::remove_cvref_t<decltype(e)>;
            if constexpr (!F::is_reserved) {
              if (!first) s.put('|');
              first = false;
              const auto& v = item.*F::member;
              if (v.state() != field_state::not_available)
                write_json_value<nmea::json_style::plain>(s, v);
            }
          });
    }
  } else if constexpr (detail::is_flags<V>::value) {
    if (f.value.has_value() && !detail::flag_names<nmea::json_style::plain>(s, f.value, ';'))
      s.put("none");
  } else if (f.state != field_state::not_available) {
    write_json_value<nmea::json_style::plain>(s, f.value);
  }
}

/// A message of a described PGN as one JSON object (no newline).
template <json_sink Sink, pgn_like P>
constexpr void write_json(Sink& s, const message_header& h, const P& msg) noexcept {
  write_json_object(s, msg, [&](Sink& out) { write_json_header(out, h); });
}

/// A message without its frame's header (built in code): `{"type":"PGN<n>"` and the fields.
template <json_sink Sink, pgn_like P>
constexpr void write_json(Sink& s, const P& msg) noexcept {
  write_json_object(s, msg, [](Sink& out) {
    out.put("{\"type\":\"PGN");
    nmea::detail::json_uint(out, pgn_table<P>.info.pgn);
    out.put('"');
  });
}

/// A message of a PGN without a description: its bytes in "data" (hex, upper case).
template <json_sink Sink>
constexpr void write_json_raw(Sink& s, const message_header& h,
                              std::span<const std::uint8_t> data) noexcept {
  write_json_header(s, h);
  s.put(",\"data\":\"");
  for (const std::uint8_t b : data) detail::put_hex_byte(s, b, true);
  s.put("\"}");
}

// ---------------------------------------------------------------------------------------------
// reading

namespace detail {

[[nodiscard]] constexpr std::optional<field_state> state_named(const json_value& v) noexcept {
  if (v.blank()) return field_state::not_available;
  if (v.kind != json_kind::string) return std::nullopt;
  if (v.text == "not_available") return field_state::not_available;
  if (v.text == "out_of_range") return field_state::out_of_range;
  if (v.text == "reserved") return field_state::reserved;
  return std::nullopt;
}

template <class T>
[[nodiscard]] constexpr std::optional<T> sentinel(field_state st) noexcept {
  constexpr std::int64_t top = T::top_raw;
  constexpr unsigned n = [] {
    if constexpr (requires { T::sentinels; }) {
      return T::sentinels;
    } else {
      return detail::sentinel_count(T::bits);
    }
  }();
  std::optional<T> out;
  if (st == field_state::not_available && n >= 1) out = T::from_raw(top);
  if (st == field_state::out_of_range && n >= 2) out = T::from_raw(top - 1);
  if (st == field_state::reserved && n >= 3) out = T::from_raw(top - 2);
  // A raw value a lookup names is that value, not the state (a 2-bit gear's 2 is reverse).
  if (out && out->state() != st) return std::nullopt;
  return out;
}

[[nodiscard]] constexpr bool parse_plain_uint(std::string_view t, std::int64_t& out) noexcept {
  std::uint64_t u = 0;
  if (!parse_uint(t, u)) return false;
  out = static_cast<std::int64_t>(u);
  return true;
}

[[nodiscard]] constexpr bool parse_date_text(std::string_view t,
                                             std::chrono::sys_days& out) noexcept {
  seawire::detail::civil_date c;
  if (t.size() != 10 || !seawire::detail::parse_iso_date(t, c) || !seawire::detail::valid_date(c))
    return false;
  out = std::chrono::sys_days(std::chrono::days(seawire::detail::days_from_civil(c)));
  return true;
}

/// A time field's text as written: hh:mm:ss, up to 4 fraction digits, hours of two or more
/// digits (24:00:00 and on: a leap second, a clock run past midnight; 23:59:60 reads as 24:00:00).
/// bad_time for another form, out_of_range past 119:18:16.7292.
[[nodiscard]] constexpr errc parse_time_of_day(std::string_view t, std::int64_t& ticks) noexcept {
  const std::size_t colon = t.find(':');
  if (colon < 2 || colon > 6 || t.size() < colon + 6 || t[colon + 3] != ':') return errc::bad_time;
  std::int64_t h = 0;
  if (!parse_plain_uint(t.substr(0, colon), h)) return errc::bad_time;
  const int m = two_digits(t, colon + 1);
  const int s = two_digits(t, colon + 4);
  if (m < 0 || s < 0 || m > 59 || s > 60 || (s == 60 && (h != 23 || m != 59)))
    return errc::bad_time;
  std::int64_t frac = 0;
  std::size_t i = colon + 6;
  if (i < t.size()) {
    if (t[i] != '.' || t.size() == i + 1 || t.size() > i + 5) return errc::bad_time;
    std::size_t digits = 0;
    for (++i; i < t.size(); ++i, ++digits) {
      if (!seawire::detail::is_digit(t[i])) return errc::bad_time;
      frac = frac * 10 + (t[i] - '0');
    }
    for (; digits < 4; ++digits) frac *= 10;
  }
  ticks = ((h * 60 + m) * 60 + s) * 10'000 + frac;
  return ticks > time_since_midnight::number_type::max_valid_raw ? errc::out_of_range : errc::ok;
}

}  // namespace detail

/// One field value from JSON; `lookup(name, index)` gives a flag array's elements ("0", "1", ...).
template <field_value T, class Lookup>
[[nodiscard]] constexpr errc read_json_value(const json_value& v, T& out, std::string_view name,
                                             Lookup&& lookup) noexcept {
  if constexpr (text_value<T>) {
    if (v.blank()) {
      out = T{};
      return errc::ok;
    }
    if (v.kind != json_kind::string) return errc::bad_text;
    const auto r = T::from_text(v.text);
    if (r) out = r.value;
    return r.ec;
  } else if constexpr (detail::is_flags<T>::value) {
    using E = value_enum_t<T>;
    if (v.kind == json_kind::number) {
      std::int64_t raw = 0;
      if (!detail::parse_plain_uint(v.text, raw) || raw > T::top_raw) return errc::out_of_range;
      out = T::from_raw(raw);
      return errc::ok;
    }
    if (v.blank()) {
      out = T{};
      return errc::ok;
    }
    if (v.kind != json_kind::other) return errc::bad_flag;
    std::int64_t raw = 0;
    constexpr std::string_view index[] = {"0",  "1",  "2",  "3",  "4",  "5",  "6",  "7",
                                          "8",  "9",  "10", "11", "12", "13", "14", "15",
                                          "16", "17", "18", "19", "20", "21", "22", "23",
                                          "24", "25", "26", "27", "28", "29", "30", "31"};
    for (const std::string_view i : index) {
      const json_value e = lookup(name, i);
      if (e.kind == json_kind::absent) break;
      if (e.kind != json_kind::string) return errc::bad_flag;
      std::optional<std::uint64_t> bit = nmea2000::detail::enum_value<E>(e.text);
      std::int64_t n = 0;
      if (!bit && e.text.starts_with("bit_") && detail::parse_plain_uint(e.text.substr(4), n))
        bit = static_cast<std::uint64_t>(n);
      if (!bit || *bit >= T::bits) return errc::bad_flag;
      raw |= std::int64_t{1} << *bit;
    }
    out = T::from_raw(raw);
    return errc::ok;
  } else {
    if (const auto st = detail::state_named(v)) {
      const auto s = detail::sentinel<T>(*st);
      // A state this field cannot carry; a field every raw value of which is a value (all
      // named, no sentinel) cannot be left out.
      if (!s) return *st == field_state::not_available ? errc::missing_field : errc::out_of_range;
      out = *s;
      return errc::ok;
    }
    if constexpr (detail::is_number<T>::value) {
      nmea::decimal d;
      if (nmea::detail::json_number(v, d) != errc::ok) return errc::bad_number;
      const auto r = T::from(d);
      if (r) out = r.value;
      return r.ec;
    } else if constexpr (detail::is_keyed_lookup<T>) {
      // Alone, without its key, a keyed field reads a number only (read_json gives names).
      std::int64_t raw = 0;
      if (v.kind != json_kind::number &&
          !(v.kind == json_kind::string && detail::parse_plain_uint(v.text, raw)))
        return errc::bad_enum;
      if (!detail::parse_plain_uint(v.text, raw) || raw > T::max_valid_raw)
        return errc::out_of_range;
      out = T::from_raw(raw);
      return errc::ok;
    } else if constexpr (detail::is_lookup<T>::value) {
      std::int64_t raw = 0;
      if (v.kind == json_kind::number ||
          (v.kind == json_kind::string && detail::parse_plain_uint(v.text, raw))) {
        if (!detail::parse_plain_uint(v.text, raw) || raw > T::top_raw || !T::is_value(raw))
          return errc::out_of_range;
        out = T::from_raw(raw);
        return errc::ok;
      }
      if (v.kind != json_kind::string) return errc::bad_enum;
      const auto r = T::from_name(v.text);
      if (r) out = r.value;
      return r.ec;
    } else if constexpr (std::is_same_v<T, day_count>) {
      std::chrono::sys_days day{};
      if (v.kind != json_kind::string || !detail::parse_date_text(v.text, day))
        return errc::bad_date;
      const auto r = day_count::from(day);
      if (r) out = r.value;
      return r.ec;
    } else if constexpr (std::is_same_v<T, time_since_midnight>) {
      if (v.kind != json_kind::string) return errc::bad_time;
      std::int64_t ticks = 0;
      const errc e = detail::parse_time_of_day(v.text, ticks);
      if (e == errc::ok) out = T::from_raw(ticks);
      return e;
    }
  }
}

namespace detail {

/// "<i>" or "<i>.<name>" in `buf`: the key of a group's element i, or of a member of it.
template <std::size_t N>
[[nodiscard]] constexpr std::string_view element_key(std::array<char, N>& buf, std::size_t i,
                                                     std::string_view name) noexcept {
  std::size_t n = 0;
  char digits[20] = {};
  std::size_t k = 0;
  do {
    digits[k++] = static_cast<char>('0' + i % 10);
    i /= 10;
  } while (i != 0);
  while (k > 0) buf[n++] = digits[--k];
  if (!name.empty() && n + 1 + name.size() <= N) {
    buf[n++] = '.';
    for (const char c : name) buf[n++] = c;
  }
  return {buf.data(), n};
}

/// Group row F from the JSON array `name`: `lookup(name, "<i>")` gives element i (an object),
/// `lookup(name, "<i>.<member>")` its members. Absent or null: no repetitions. Errors:
/// bad_length when the member is not an array of objects, too_many_fields past the capacity, or
/// a member's error (`column` set to the member's byte in the payload of that many repetitions).
template <class F, class G, class Lookup>
[[nodiscard]] constexpr errc read_json_group(G& out, std::string_view name, unsigned offset,
                                             std::uint16_t& column, Lookup& lookup) noexcept {
  using Item = typename G::item_type;
  out.clear();
  const json_value array = lookup(std::string_view{}, name);
  if (array.blank()) return errc::ok;
  if (array.kind != json_kind::other || array.text != "[") return errc::bad_length;
  std::array<char, 80> buf{};
  for (std::size_t i = 0;; ++i) {
    const json_value e = lookup(name, element_key(buf, i, {}));
    if (e.kind == json_kind::absent) return errc::ok;
    if (e.kind != json_kind::other || e.text != "{") return errc::bad_length;
    if (out.full()) return errc::too_many_fields;
    Item item{};
    errc ec = errc::ok;
    Item::n2k_item.for_each([&](const auto& f, unsigned o, std::uint16_t) {
      using R = std::remove_cvref_t<decltype(f)>;
      if constexpr (!R::is_reserved) {
        static_assert(!is_flags<typename R::value_type>::value,
                      "a group's repetition holds no flag set");
        if (ec != errc::ok) return;
        const std::string_view key = element_key(buf, i, f.name);
        const json_value v = lookup(name, key);
        ec = read_json_value(v, item.*R::member, key, lookup);
        if (ec != errc::ok)
          column = static_cast<std::uint16_t>(
              (offset + static_cast<unsigned>(i) * F::item_bits + o) / 8);
      }
    });
    if (ec != errc::ok) return ec;
    (void)out.push_back(item);
  }
}

}  // namespace detail

/// A message of PGN struct P from a JSON object: `lookup(object, key)` gives member `key` (object
/// == "") or element `key` of array member `object` ("0", "1", ...; a group's element's members
/// "0.prn", ...). Errors: `field` = the row of P's table. Unknown members are not looked at.
template <pgn_like P, class Lookup>
[[nodiscard]] constexpr result<P> read_json(Lookup&& lookup) noexcept {
  result<P> r;
  const auto fail = [&](errc e, std::uint16_t n, unsigned offset) {
    if (e == errc::ok || (r.ec != errc::ok && r.field < n)) return;
    r.ec = e;
    r.field = n;
    r.column = static_cast<std::uint16_t>(offset / 8);
  };
  pgn_table<P>.for_each([&](const auto& f, unsigned offset, std::uint16_t n) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (detail::group_row<F>) {
      if (r.ec != errc::ok) return;
      std::uint16_t column = static_cast<std::uint16_t>(offset / 8);
      const errc e = detail::read_json_group<F>(r.value.*F::member, f.name, offset, column, lookup);
      if (e != errc::ok) {
        r.ec = e;
        r.field = n;
        r.column = column;
      }
    } else if constexpr (detail::bytes_row<F>) {
      if (r.ec != errc::ok) return;
      const json_value v = lookup(std::string_view{}, f.name);
      if (v.kind == json_kind::absent) return;  // no bytes
      if (v.kind != json_kind::string) {
        fail(errc::bad_text, n, offset);
        return;
      }
      const auto b = F::value_type::from_hex(v.text);
      if (b) r.value.*F::member = b.value;
      fail(b.ec, n, offset);
    } else if constexpr (!F::is_reserved && !keyed_row<F>) {
      if (r.ec != errc::ok) return;
      const json_value v = lookup(std::string_view{}, f.name);
      // A match row left out is the struct's own layout (its member's initial value).
      if constexpr (detail::match_row<F>)
        if (v.kind == json_kind::absent) return;
      fail(read_json_value(v, r.value.*F::member, f.name, lookup), n, offset);
    }
  });
  // Keyed fields once their keys are read: a name counts for the key the message has. The
  // error reported is the first row's either way.
  pgn_table<P>.for_each([&](const auto& f, unsigned offset, std::uint16_t n) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (keyed_row<F>) {
      if (r.ec != errc::ok && r.field < n) return;
      using V = typename F::value_type;
      const json_value v = lookup(std::string_view{}, f.name);
      const auto& key = r.value.*F::key_member;
      errc e = errc::ok;
      std::int64_t number = 0;
      if (v.kind == json_kind::string && !detail::state_named(v) &&
          !detail::parse_plain_uint(v.text, number)) {
        const auto named =
            key.has_value() ? V::from_name(key.raw(), v.text) : result<V>{V{}, errc::bad_enum};
        if (named) r.value.*F::member = named.value;
        e = named.ec;
      } else {
        e = read_json_value(v, r.value.*F::member, f.name, lookup);
      }
      fail(e, n, offset);
    }
  });
  return r;
}

/// Whether P has a field called `name` (for reporting unknown members).
template <pgn_like P>
[[nodiscard]] constexpr bool has_field(std::string_view name) noexcept {
  bool found = false;
  pgn_table<P>.for_each([&](const auto& f, unsigned, std::uint16_t) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (!F::is_reserved) found = found || f.name == name;
  });
  return found;
}

/// The PGN a "type" names ("PGN128259"), or nullopt.
[[nodiscard]] constexpr std::optional<std::uint32_t> pgn_of_type(std::string_view type) noexcept {
  std::uint64_t n = 0;
  if (!type.starts_with("PGN") || !detail::parse_uint(type.substr(3), n) || n > max_pgn)
    return std::nullopt;
  return static_cast<std::uint32_t>(n);
}

/// The header members of a JSON object for a message of `pgn`: "prio" defaults to
/// `default_priority`, "src" to 0, "dst" to 255, no "time_s" to no time. On failure `field` is 1
/// time_s, 2 interface, 3 direction, 4 prio, 5 src, 6 dst.
template <class Lookup>
[[nodiscard]] constexpr result<message_header> read_json_header(std::uint32_t pgn,
                                                                std::uint8_t default_priority,
                                                                Lookup&& lookup) noexcept {
  result<message_header> r;
  r.value.id.pgn = pgn;
  r.value.id.priority = default_priority;
  r.value.id.source = 0;
  const auto fail = [&](errc e, std::uint16_t field) {
    r.ec = e;
    r.field = field;
    return r;
  };
  if (const json_value t = lookup(std::string_view{}, "time_s"); !t.blank()) {
    std::int64_t us = 0;
    if (t.kind != json_kind::number || !detail::parse_seconds(t.text, us))
      return fail(errc::bad_time, 1);
    r.value.time_us = us;
  }
  if (const json_value i = lookup(std::string_view{}, "interface"); !i.blank()) {
    if (i.kind != json_kind::string || i.text.empty() ||
        i.text.find_first_of(" \t#(") != std::string_view::npos)
      return fail(errc::bad_text, 2);
    if (!r.value.interface.assign(i.text)) return fail(errc::text_too_long, 2);
  }
  if (const json_value d = lookup(std::string_view{}, "direction"); !d.blank()) {
    if (d.kind != json_kind::string || (d.text != "R" && d.text != "T"))
      return fail(errc::bad_enum, 3);
    r.value.direction = d.text[0];
  }
  const auto small = [&](std::string_view key, std::uint64_t max, std::uint8_t& out,
                         std::uint16_t field) {
    const json_value v = lookup(std::string_view{}, key);
    if (v.blank()) return true;
    std::uint64_t n = 0;
    if (v.kind != json_kind::number || !detail::parse_uint(v.text, n) || n > max) {
      r.ec = errc::out_of_range;
      r.field = field;
      return false;
    }
    out = static_cast<std::uint8_t>(n);
    return true;
  };
  if (!small("prio", 7, r.value.id.priority, 4) || !small("src", 255, r.value.id.source, 5) ||
      !small("dst", 255, r.value.id.destination, 6))
    return r;
  if (!is_addressed(pgn) && r.value.id.destination != broadcast_address)
    return fail(errc::bad_can_id, 6);
  return r;
}

// ---------------------------------------------------------------------------------------------
// CSV: one table per PGN, columns time_s, prio, src, dst, then the fields (put_csv_value).

/// The header row of P's table, ending in LF.
template <pgn_like P, json_sink Sink>
constexpr void write_csv_header(Sink& s) noexcept {
  s.put("time_s,prio,src,dst");
  write_csv_columns<P>(s, false);
}

/// One row of P's table, ending in LF.
template <json_sink Sink, pgn_like P>
constexpr void write_csv(Sink& s, const message_header& h, const P& msg) noexcept {
  using nmea::detail::json_uint;
  if (h.time_us) detail::json_seconds(s, *h.time_us);
  s.put(',');
  json_uint(s, h.id.priority);
  s.put(',');
  json_uint(s, h.id.source);
  s.put(',');
  json_uint(s, h.id.destination);
  write_csv_cells(s, msg, false);
}

}  // namespace seawire::nmea2000
