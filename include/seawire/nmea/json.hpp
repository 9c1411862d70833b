// SPDX-License-Identifier: BSL-1.0
#pragma once
// JSON for messages: write_json writes any message as one JSON object ("type", then each field
// under its declared name, wire order); read_json<T> reads one back from values a JSON library
// has tokenised (kind + text). Nothing goes through double: numbers keep the wire's digits. Every
// wire's object is one loop over the walk (walk.hpp; PGNs: nmea2000/json.hpp, the 0xAB00 frame:
// anello/frame_json.hpp). The conventions, value type by value type (also fmt.hpp's):
// tools/decode/README.md (writing) and tools/encode/README.md (reading).

#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>

#include "seawire/detail/algorithm.hpp"
#include "seawire/detail/ascii.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/variation.hpp"
#include "seawire/nmea/writer.hpp"
#include "seawire/walk.hpp"

namespace seawire::nmea {

// ---------------------------------------------------------------------------------------------
// sinks

/// Where JSON text goes: put(char) and put(std::string_view); a sink that can fill up remembers
/// that it did (json_buffer::overflow()).
template <class S>
concept json_sink = requires(S& s, char c, std::string_view v) {
  s.put(c);
  s.put(v);
};

/// A sink of fixed capacity held by value. Text past the capacity is dropped and remembered.
template <std::size_t N>
class json_buffer {
 public:
  constexpr void put(char c) noexcept {
    if (size_ < N) {
      data_[size_++] = c;
    } else {
      overflow_ = true;
    }
  }
  constexpr void put(std::string_view s) noexcept {
    const std::size_t n = s.size() < N - size_ ? s.size() : N - size_;
    std::copy_n(s.data(), n, data_ + size_);
    size_ += n;
    if (n < s.size()) overflow_ = true;
  }
  /// Where `n` more bytes may be written, or nullptr when fewer are left; commit(k) keeps k of
  /// them. (Numbers are written there in place; see seawire::detail::sink_with_room.)
  [[nodiscard]] constexpr char* room(std::size_t n) noexcept {
    return N - size_ >= n ? data_ + size_ : nullptr;
  }
  constexpr void commit(std::size_t k) noexcept { size_ += k; }
  constexpr void clear() noexcept {
    size_ = 0;
    overflow_ = false;
  }
  [[nodiscard]] constexpr std::string_view view() const noexcept { return {data_, size_}; }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
  /// Some text did not fit: view() holds a truncated, invalid document.
  [[nodiscard]] constexpr bool overflow() const noexcept { return overflow_; }

 private:
  char data_[N]{};
  std::size_t size_ = 0;
  bool overflow_ = false;
};

/// As JSON, or plain for people (fmt.hpp): wire words unquoted, text still quoted and escaped.
enum class json_style : std::uint8_t { json, plain };

// ---------------------------------------------------------------------------------------------
// writing

namespace detail {

template <json_sink Sink>
constexpr void json_uint(Sink& s, std::uint64_t v, unsigned min_digits = 1) noexcept {
  seawire::detail::put_uint(s, v, min_digits);
}

/// json_escaped[c]: whether byte c is escaped in a JSON string.
inline constexpr std::array<bool, 256> json_escaped = [] {
  std::array<bool, 256> t{};
  for (std::size_t c = 0; c < t.size(); ++c) t[c] = c < 0x20 || c >= 0x7F || c == '"' || c == '\\';
  return t;
}();

/// A JSON string's content: '"' and '\' escaped, every byte outside printable ASCII as
/// \u00XX (so a stray byte >= 0x80 in rejected input still makes valid JSON, read as Latin-1).
template <json_sink Sink>
constexpr void json_escape(Sink& s, std::string_view text) noexcept {
  std::size_t run = 0;  // start of the current run of plain characters
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (!json_escaped[c]) continue;
    s.put(std::string_view(text.data() + run, i - run));
    run = i + 1;
    switch (c) {
      case '"': s.put("\\\""); break;
      case '\\': s.put("\\\\"); break;
      case '\n': s.put("\\n"); break;
      case '\r': s.put("\\r"); break;
      case '\t': s.put("\\t"); break;
      default:
        s.put("\\u00");
        s.put(seawire::detail::hex_digit_upper(c >> 4u));
        s.put(seawire::detail::hex_digit_upper(c));
    }
  }
  s.put(std::string_view(text.data() + run, text.size() - run));
}

template <json_style Style, json_sink Sink>
constexpr void json_string(Sink& s, std::string_view text) noexcept {
  if constexpr (Style == json_style::json) {
    s.put('"');
    json_escape(s, text);
    s.put('"');
  } else {
    s.put(text);
  }
}

/// A decimal as a JSON number: no padding, the wire's fraction digits; null past 19 fraction
/// digits (no decoder makes one), so the document stays valid.
template <json_sink Sink>
constexpr void json_decimal(Sink& s, const decimal& d) noexcept {
  if (d.places > seawire::detail::max_fraction_digits) {
    s.put("null");
    return;
  }
  seawire::detail::put_fixed(s, d.mantissa, d.places, d.negative);
}

// A number and the width it is zero-padded to.
struct padded {
  std::uint64_t value = 0;
  unsigned width = 0;
};

// A date ("2014-12-31") or time ("16:49:59.980"), written at once: three numbers joined by `sep`,
// then a point and `fraction` when its width is not 0, quoted when `Quoted`.
template <bool Quoted, json_sink Sink>
SEAWIRE_ALWAYS_INLINE constexpr void json_joined(Sink& s, const std::array<padded, 3>& parts,
                                                 char sep, padded fraction = {}) noexcept {
  constexpr std::size_t most = seawire::detail::max_padded_digits;
  seawire::detail::put_made<1 + 3 * (most + 1) + 1 + most + 1>(
      s, [&](char* out) SEAWIRE_INLINE_LAMBDA {
        std::size_t n = 0;
        if constexpr (Quoted) out[n++] = '"';
        n = seawire::detail::append_uint(out, n, parts[0].value, parts[0].width);
        out[n++] = sep;
        n = seawire::detail::append_uint(out, n, parts[1].value, parts[1].width);
        out[n++] = sep;
        n = seawire::detail::append_uint(out, n, parts[2].value, parts[2].width);
        if (fraction.width != 0) {
          out[n++] = '.';
          n = seawire::detail::append_uint(out, n, fraction.value, fraction.width);
        }
        if constexpr (Quoted) out[n++] = '"';
        return n;
      });
}

template <class T>
struct is_optional : std::false_type {};
template <class T>
struct is_optional<std::optional<T>> : std::true_type {};

template <class T>
struct is_text : std::false_type {};
template <std::size_t N>
struct is_text<text<N>> : std::true_type {};

}  // namespace detail

/// One value, by the JSON conventions (tools/decode/README.md).
template <json_style Style = json_style::json, json_sink Sink, class T>
constexpr void write_json_value(Sink& s, const T& v) noexcept {
  if constexpr (detail::is_optional<T>::value) {
    if (v) {
      write_json_value<Style>(s, *v);
    } else {
      s.put("null");
    }
  } else if constexpr (std::is_same_v<T, decimal>) {
    detail::json_decimal(s, v);
  } else if constexpr (std::is_same_v<T, bool>) {
    s.put(v ? std::string_view("true") : std::string_view("false"));
  } else if constexpr (whole_number<T>) {
    if constexpr (std::is_signed_v<T>) {
      seawire::detail::put_fixed(s, seawire::detail::magnitude(v), 0, v < 0);
    } else {
      detail::json_uint(s, static_cast<std::uint64_t>(v));
    }
  } else if constexpr (is_integer_wrapper<T>) {
    write_json_value<Style>(s, v.value());
  } else if constexpr (is_ddmm_position<T> || is_degrees_position<T>) {
    detail::json_decimal(s, to_decimal_degrees(v));
  } else if constexpr (std::is_same_v<T, magnetic_variation>) {
    // Signed degrees with the wire's digits, west negative; null for a letter without a value.
    if (!v.value) {
      s.put("null");
      return;
    }
    decimal d = *v.value;
    d.int_width = 0;
    d.negative = v.direction == hemisphere::west;
    detail::json_decimal(s, d);
  } else if constexpr (std::is_same_v<T, time_of_day>) {
    detail::json_joined<Style == json_style::json>(s, {{{v.hour, 2}, {v.minute, 2}, {v.second, 2}}},
                                                   ':', {v.fraction, v.places});
  } else if constexpr (std::is_same_v<T, date>) {
    detail::json_joined<Style == json_style::json>(s, {{{v.year, 4}, {v.month, 2}, {v.day, 2}}},
                                                   '-');
  } else if constexpr (detail::is_text<T>::value) {
    detail::json_string<json_style::json>(s, v.view());
  } else if constexpr (char_enum_like<T>) {
    // A digit or an ASCII letter (enum.hpp refuses a printable enumerator that is neither):
    // nothing to escape. Empty for a value that is no letter.
    const std::string_view letter = to_string(v);
    if constexpr (Style == json_style::json) {
      const char quoted[3] = {'"', letter.empty() ? '"' : letter[0], '"'};
      s.put(std::string_view(quoted, letter.empty() ? 2 : 3));
    } else {
      s.put(letter);
    }
  } else if constexpr (word_enum_like<T>) {
    detail::json_string<Style>(s, to_string(v));
  } else if constexpr (has_codec<T>) {
    // Any other value with a codec: its wire text, e.g. a RobotX light pattern "RGB".
    char buf[256];
    writer w(std::span<char>(buf, sizeof buf));
    codec<T>::write(w, v);
    detail::json_string<Style>(s, w.view());
  } else {
    static_assert(has_codec<T>, "write_json_value: no JSON form for this type");
  }
}

namespace detail {
/// A sink over [first, last): what does not fit is remembered, not written.
class range_sink {
 public:
  constexpr range_sink(char* first, char* last) noexcept : at_(first), last_(last) {}
  constexpr void put(char c) noexcept {
    if (at_ != last_) {
      *at_++ = c;
    } else {
      full_ = true;
    }
  }
  constexpr void put(std::string_view v) noexcept {
    const auto room = static_cast<std::size_t>(last_ - at_);
    const std::size_t n = v.size() < room ? v.size() : room;
    at_ = std::copy_n(v.data(), n, at_);
    if (n < v.size()) full_ = true;
  }
  [[nodiscard]] constexpr char* end() const noexcept { return at_; }
  [[nodiscard]] constexpr bool full() const noexcept { return full_; }

 private:
  char* at_;
  char* last_;
  bool full_ = false;
};
}  // namespace detail

/// A value as fmt's "{}" writes it ("4.50", signed decimal degrees, "16:49:59.980"; a magnetic
/// variation east positive or "null"), with std::to_chars's contract: into [first, last), no
/// NUL; std::errc::value_too_large (ptr == last) when it does not fit.
template <class T>
requires(has_codec<T> && !std::is_arithmetic_v<T>) [[nodiscard]] constexpr std::to_chars_result
    to_chars(char* first, char* last, const T& value) noexcept {
  detail::range_sink s(first, last);
  if constexpr (detail::is_text<T>::value) {
    s.put(value.view());  // text needs no quotes outside JSON
  } else {
    write_json_value<json_style::plain>(s, value);
  }
  if (s.full()) return {last, std::errc::value_too_large};
  return {s.end(), std::errc{}};
}

/// The "type" value of a message: its address, or talker + type for talker-agnostic ones.
template <json_sink Sink, message_like T>
constexpr void write_type(Sink& s, const T& msg) noexcept {
  constexpr auto& desc = T::nmea;
  if constexpr (std::remove_cvref_t<decltype(desc)>::any_talker) {
    s.put(detail::talker_of(msg).view());
    s.put(desc.address.substr(2));
  } else {
    s.put(desc.address);
  }
}

namespace detail {
// Sinks for text made at compile time: one that counts, one that fills an array.
struct counting_sink {
  std::size_t size = 0;
  constexpr void put(char) noexcept { ++size; }
  constexpr void put(std::string_view v) noexcept { size += v.size(); }
};
template <std::size_t N>
struct array_sink {
  std::array<char, N> text{};
  std::size_t size = 0;
  constexpr void put(char c) noexcept { text[size++] = c; }
  constexpr void put(std::string_view v) noexcept {
    for (const char c : v) put(c);
  }
};

// The text Text::to(sink) writes, made once at compile time (counted, then written).
template <class Text>
inline constexpr auto static_text = [] {
  constexpr std::size_t size = [] {
    counting_sink n;
    Text::to(n);
    return n.size;
  }();
  array_sink<size> a;
  Text::to(a);
  return a.text;
}();

// `{"type":"ADDR"` for a message with a fixed address.
template <class T>
struct json_fixed_head {
  static constexpr void to(auto& s) noexcept {
    s.put("{\"type\":\"");
    s.put(T::nmea.address);
    s.put('"');
  }
};
template <class T>
inline constexpr const auto& json_head = static_text<json_fixed_head<T>>;

template <json_sink Sink, std::size_t N>
constexpr void put_array(Sink& s, const std::array<char, N>& a) noexcept {
  s.put(std::string_view(a.data(), N));
}
}  // namespace detail

}  // namespace seawire::nmea

// ---------------------------------------------------------------------------------------------
// every message of every wire, through the walk (walk.hpp)

namespace seawire {

namespace detail {
// `,"key":` of a field, escaped: made once at compile time.
template <class Info>
struct json_member_key_of {
  static constexpr void to(auto& s) noexcept {
    s.put(",\"");
    nmea::detail::json_escape(s, Info::key);
    s.put("\":");
  }
};
}  // namespace detail

namespace detail {
// write_json_fields' loop body (a function object: its call is inlined, as a lambda's may not be).
template <class Sink>
struct json_field_writer {
  Sink& s;
  template <class View>
  SEAWIRE_ALWAYS_INLINE constexpr void operator()(const View& f) const noexcept {
    nmea::detail::put_array(s, nmea::detail::static_text<json_member_key_of<typename View::info>>);
    put_field_value<nmea::json_style::json>(s, f);
  }
};
}  // namespace detail

/// `,"key":value` for every field of `msg` in wire order (values by the wire's put_field_value).
template <nmea::json_sink Sink, walkable M>
SEAWIRE_ALWAYS_INLINE constexpr void write_json_fields(Sink& s, const M& msg) noexcept {
  visit_fields(msg, detail::json_field_writer<Sink>{s});
}

/// A message of any wire as one JSON object (no newline): head(s) `{"type":...`, fields, '}'.
template <nmea::json_sink Sink, walkable M, class Head>
constexpr void write_json_object(Sink& s, const M& msg, Head&& head) noexcept {
  head(s);
  write_json_fields(s, msg);
  s.put('}');
}

/// `{name=value, ...}` with plain values: fmt's "{}" of a message of any wire, after its type.
template <nmea::json_sink Sink, walkable M>
constexpr void write_plain_fields(Sink& s, const M& msg) noexcept {
  s.put('{');
  bool first = true;
  visit_fields(msg, [&](const auto& f) {
    if (!first) s.put(", ");
    first = false;
    s.put(f.name);
    s.put('=');
    put_field_value<nmea::json_style::plain>(s, f);
  });
  s.put('}');
}

}  // namespace seawire

namespace seawire::nmea {

/// A field's value as JSON (or plain): the walk's value text for sentences.
template <json_style Style, json_sink Sink, class Info>
requires(Info::kind ==
         wire_kind::nmea0183) constexpr void put_field_value(Sink& s,
                                                             const field_view<Info>& f) noexcept {
  write_json_value<Style>(s, f.value);
}

/// A message as one JSON object (no newline): "type", then each field in wire order.
template <json_sink Sink, message_like T>
constexpr void write_json(Sink& s, const T& msg) noexcept {
  write_json_object(s, msg, [&](Sink& out) {
    if constexpr (std::remove_cvref_t<decltype(T::nmea)>::any_talker) {
      out.put("{\"type\":\"");
      write_type(out, msg);
      out.put('"');
    } else {
      detail::put_array(out, detail::json_head<T>);
    }
  });
}

/// A sentence no known message describes: {"type":"<address>","fields":["...", ...]}, with
/// "start":"!" after "type" for a '!' sentence (!AIVDM).
template <json_sink Sink>
constexpr void write_json(Sink& s, const unknown_sentence& u) noexcept {
  s.put("{\"type\":\"");
  detail::json_escape(s, u.sentence.address);
  if (u.sentence.start == '!') s.put("\",\"start\":\"!");
  s.put("\",\"fields\":[");
  const parse_policy policy;
  field_reader r(u.sentence, policy);
  for (bool first = true; !r.at_end(); first = false) {
    if (!first) s.put(',');
    s.put('"');
    detail::json_escape(s, r.take().text);
    s.put('"');
  }
  s.put("]}");
}

/// A rejected input: {"line":N,"error":"<errc name>","field":K,"detail":"...","input":"..."}.
/// `field` is the spec's field number (0: the sentence as a whole).
template <json_sink Sink>
constexpr void write_json_error(Sink& s, std::uint64_t line, errc e, std::uint16_t field,
                                std::string_view detail, std::string_view input) noexcept {
  s.put("{\"line\":");
  detail::json_uint(s, line);
  s.put(",\"error\":\"");
  s.put(name(e));
  s.put("\",\"field\":");
  detail::json_uint(s, field);
  s.put(",\"detail\":\"");
  detail::json_escape(s, detail);
  s.put("\",\"input\":\"");
  detail::json_escape(s, input);
  s.put("\"}");
}

// ---------------------------------------------------------------------------------------------
// reading

/// What a JSON reader found for a key.
enum class json_kind : std::uint8_t {
  absent,   ///< no such key
  null,     ///< null
  boolean,  ///< text is "true" or "false"
  number,   ///< text is the number as written ("203.10")
  string,   ///< text is the string's content, unescaped
  other,    ///< an object or array
};

/// One JSON value, tokenised by whatever JSON library the caller uses. Views the caller's text.
struct json_value {
  json_kind kind = json_kind::absent;
  std::string_view text;

  [[nodiscard]] constexpr bool blank() const noexcept {
    return kind == json_kind::absent || kind == json_kind::null;
  }
};

namespace detail {

/// A decimal from a JSON number or a string holding one; exponents are refused (bad_number).
[[nodiscard]] constexpr errc json_number(const json_value& v, decimal& out) noexcept {
  if (v.kind != json_kind::number && v.kind != json_kind::string) return errc::bad_number;
  return parse_decimal(v.text, false, out);
}

[[nodiscard]] constexpr bool is_scalar_text(const json_value& v) noexcept {
  return v.kind == json_kind::string || v.kind == json_kind::number;
}

/// A value of a codec without a JSON form of its own: its wire text, read by the codec.
template <class T>
[[nodiscard]] constexpr errc read_wire_text(std::string_view text, T& out) noexcept {
  sentence_view s;
  s.body = text;
  s.field_count = 1;
  for (const char c : text)
    if (c == ',') ++s.field_count;
  const parse_policy policy;
  field_reader r(s, policy);
  if (text.empty() && !codec<T>::allows_blank) return errc::missing_field;
  const errc e = codec<T>::read(r, out);
  if (e != errc::ok) return e;
  return r.at_end() ? errc::ok : errc::bad_text;
}

}  // namespace detail

/// One value from JSON, not blank (callers handle null and absent). `precision`: a position's
/// wire fraction digits (minutes for DDMM.mmm, degrees for decimal degrees); < 0 = default.
template <class T>
[[nodiscard]] constexpr errc read_json_value(const json_value& v, T& out,
                                             int precision = -1) noexcept {
  if constexpr (std::is_same_v<T, decimal>) {
    return detail::json_number(v, out);
  } else if constexpr (std::is_same_v<T, bool>) {
    if (v.kind == json_kind::boolean ||
        ((v.kind == json_kind::number || v.kind == json_kind::string) &&
         (v.text == "0" || v.text == "1"))) {
      out = v.text == "true" || v.text == "1";
      return errc::ok;
    }
    if (v.kind == json_kind::string && (v.text == "true" || v.text == "false")) {
      out = v.text == "true";
      return errc::ok;
    }
    return errc::bad_flag;
  } else if constexpr (detail::is_integer_field<T>) {
    if (!detail::is_scalar_text(v)) return errc::bad_number;
    sentence_view s;
    s.body = v.text;
    s.field_count = 1;
    const parse_policy strict{.checksum = checksum_policy::ignore, .strict_values = true};
    field_reader r(s, strict);
    if (v.text.empty()) return errc::bad_number;
    return codec<T>::read(r, out);
  } else if constexpr (is_ddmm_position<T> || is_degrees_position<T>) {
    decimal d;
    const errc e = detail::json_number(v, d);
    if (e != errc::ok) return e == errc::bad_number ? detail::coordinate_traits<T>::axis::error : e;
    const result<T> c = from_decimal_degrees<T>(d, precision);
    if (c) out = c.value;
    return c.ec;
  } else if constexpr (std::is_same_v<T, magnetic_variation>) {
    decimal d;
    const errc e = detail::json_number(v, d);
    if (e != errc::ok) return e == errc::bad_number ? errc::bad_variation : e;
    out.direction = d.negative ? hemisphere::west : hemisphere::east;
    d.negative = false;
    out.value = d;
    return errc::ok;
  } else if constexpr (std::is_same_v<T, time_of_day>) {
    if (v.kind != json_kind::string && v.kind != json_kind::number) return errc::bad_time;
    const result<time_of_day> t = parse_time_text(v.text);
    if (t) out = t.value;
    return t.ec;
  } else if constexpr (std::is_same_v<T, date>) {
    if (v.kind != json_kind::string && v.kind != json_kind::number) return errc::bad_date;
    const result<date> d = parse_date_text(v.text);
    if (d) out = d.value;
    return d.ec;
  } else if constexpr (detail::is_text<T>::value) {
    if (!detail::is_scalar_text(v)) return errc::bad_text;
    return out.assign(v.text) ? errc::ok : errc::text_too_long;
  } else if constexpr (char_enum_like<T> || word_enum_like<T>) {
    if (!detail::is_scalar_text(v) || v.text.empty()) return errc::bad_enum;
    return detail::read_wire_text(v.text, out);
  } else if constexpr (has_codec<T>) {
    if (!detail::is_scalar_text(v)) return errc::bad_text;
    return detail::read_wire_text(v.text, out);
  } else {
    static_assert(has_codec<T>, "read_json_value: no JSON form for this type");
    return errc::bad_text;
  }
}

/// Whether messages of type T have a field called `name` (for reporting unknown keys).
template <message_like T>
[[nodiscard]] constexpr bool has_field(std::string_view name) noexcept {
  return T::nmea.fields.apply([&](const auto&... d) { return ((d.name == name) || ...); });
}

namespace detail {
/// read_json_value, with the forms message T's sender writes (number_forms).
template <message_like T, class V>
[[nodiscard]] constexpr errc read_json_field(const json_value& v, V& out, int precision) noexcept {
  if constexpr (std::is_same_v<V, time_of_day> &&
                std::remove_cvref_t<decltype(T::nmea)>::numbers.rounded_seconds) {
    if (v.kind != json_kind::string && v.kind != json_kind::number) return errc::bad_time;
    const result<time_of_day> t = parse_time_text(v.text, true);
    if (t) out = t.value;
    return t.ec;
  } else {
    return read_json_value(v, out, precision);
  }
}
}  // namespace detail

/// Reads a message from a JSON object whose "type" is `type` (the talker comes from it).
/// `lookup(object, key)` gives member `key` of the object (object == "") or of its "precision"
/// object. Errors: the errc and the wire field number as encode_to numbers it; wrong_address for
/// another type. Ranges are checked by encode, not here.
template <message_like T, class Lookup>
[[nodiscard]] constexpr result<T> read_json(std::string_view type, Lookup&& lookup) noexcept {
  result<T> out;
  constexpr auto& desc = T::nmea;
  if (!desc.matches(type)) {
    out.ec = errc::wrong_address;
    return out;
  }
  if constexpr (std::remove_cvref_t<decltype(desc)>::any_talker) {
    (void)detail::talker_of(out.value).assign(type.substr(0, 2));
  }
  std::uint16_t wire_field = 1;
  const auto one = [&](const auto& d) -> bool {
    using F = std::remove_cvref_t<decltype(d)>;
    using V = typename F::value_type;
    auto& member = out.value.*F::member;
    const json_value v = lookup(std::string_view{}, d.name);
    int precision = -1;
    errc e = errc::ok;
    if constexpr (is_ddmm_position<V> || is_degrees_position<V>) {
      const json_value p = lookup(std::string_view("precision"), d.name);
      if (!p.blank()) {
        std::uint8_t n = 0;
        e = read_json_value(p, n);
        if (e == errc::ok && n > max_degree_places) e = errc::out_of_range;
        precision = n;
      }
    }
    if (e == errc::ok) {
      if constexpr (F::is_optional) {
        if (v.blank()) {
          detail::clear_optional(member);
        } else {
          V value{};
          e = detail::read_json_field<T>(v, value, precision);
          if (e == errc::ok) member = value;
        }
      } else if (v.blank()) {
        if constexpr (detail::is_text<V>::value) {
          member = V{};
        } else {
          e = errc::missing_field;
        }
      } else {
        e = detail::read_json_field<T>(v, member, precision);
      }
    }
    if (e != errc::ok) {
      out.ec = e;
      out.field = wire_field;
      return false;
    }
    // Numbered as encode_to numbers: a field of the longer form left out takes no number.
    if (d.opts.only_with_field_count == 0 || !detail::skipped(d, out.value))
      wire_field = static_cast<std::uint16_t>(wire_field + d.width());
    return true;
  };
  desc.fields.apply([&](const auto&... d) { (void)(one(d) && ...); });
  return out;
}

}  // namespace seawire::nmea
