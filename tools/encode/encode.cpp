// SPDX-License-Identifier: BSL-1.0
// seawire-encode: JSON Lines on stdin (the schema seawire-decode writes) -> sentences on stdout,
// and 56-byte ANELLO binary frames for "type":"AB00". nlohmann-json's SAX interface tokenises
// each line, handing over every number's text, so 203.10 is sent as 203.10 (a number in exponent
// form, as jq prints 0.00001, is first written out: 1e-05 is sent as 0.00001); the library reads
// the values (nmea::read_json, anello::read_frame_json) and encodes them strictly.
// See --help, and the README's seawire-encode(1) for the manual.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "io.hpp"
#include "log_limit.hpp"
#include "messages.hpp"
#include "seawire/anello/frame.hpp"
#include "seawire/anello/frame_json.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/writer.hpp"
#include "seawire/nmea2000/fast_packet.hpp"
#include "seawire/nmea2000/fast_packets.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/version.hpp"

namespace {

using namespace seawire;
using nmea::json_kind;
using nmea::json_value;
using seawire::tools::all_messages;
using seawire::tools::n2k_pgns;

// Exponent forms are written out only this far: 1e-40 .. 1e40, at most 48 digits in all.
constexpr int max_exponent = 40;
constexpr std::size_t max_plain_digits = 48;

/// The plain decimal text of a JSON number written with an exponent, by moving the decimal point
/// (never through double), so the digits are kept: 1e-05 -> 0.00001, -2.50E+2 -> -250,
/// 1.50e-1 -> 0.150, 1.5e1 -> 15. The fraction digits are the mantissa's minus the exponent, at
/// least 0. `text` is valid JSON number text. A number without an exponent is returned as it is.
/// Empty (and `why` set) when the exponent is beyond +-max_exponent or the result would have more
/// than max_plain_digits digits.
std::string plain_decimal(std::string_view text, std::string& why) {
  const std::size_t e_at = text.find_first_of("eE");
  if (e_at == std::string_view::npos) return std::string(text);
  std::string_view mantissa = text.substr(0, e_at);
  std::string_view exponent = text.substr(e_at + 1);
  const bool negative = mantissa.starts_with('-');
  if (negative) mantissa.remove_prefix(1);
  const bool exponent_negative = exponent.starts_with('-');
  if (exponent.starts_with('-') || exponent.starts_with('+')) exponent.remove_prefix(1);
  while (exponent.size() > 1 && exponent.front() == '0') exponent.remove_prefix(1);
  int e = 0;
  for (const char c : exponent) {
    e = e * 10 + (c - '0');
    if (e > max_exponent) {
      why = "an exponent beyond +-" + std::to_string(max_exponent) +
            " is not written out (write the number without an exponent)";
      return {};
    }
  }
  if (exponent_negative) e = -e;
  // The mantissa's digits without the point, and how many of them followed it.
  std::string digits;
  long fraction = 0;
  const std::size_t point = mantissa.find('.');
  if (point == std::string_view::npos) {
    digits = mantissa;
  } else {
    digits = mantissa.substr(0, point);
    digits += mantissa.substr(point + 1);
    fraction = static_cast<long>(mantissa.size() - point - 1);
  }
  fraction -= e;
  if (fraction < 0) {
    digits.append(static_cast<std::size_t>(-fraction), '0');
    fraction = 0;
  }
  const auto places = static_cast<std::size_t>(fraction);
  if (digits.size() <= places) digits.insert(0, places + 1 - digits.size(), '0');
  std::size_t lead = 0;  // zeros before the first integer digit: 05 -> 5, 00.1 -> 0.1
  while (lead + 1 < digits.size() - places && digits[lead] == '0') ++lead;
  digits.erase(0, lead);
  if (digits.size() > max_plain_digits) {
    why = "more than " + std::to_string(max_plain_digits) +
          " digits written out (write the number without an exponent)";
    return {};
  }
  std::string out = negative ? "-" : "";
  out.append(digits, 0, digits.size() - places);
  if (places > 0) {
    out += '.';
    out.append(digits, digits.size() - places, places);
  }
  return out;
}

// One JSON Lines object, flattened: its members, the members of its "precision" object, and its
// "fields" array (unknown sentences). Views point into `texts_`, which never moves its strings.
class json_object : public nlohmann::json_sax<nlohmann::json> {
 public:
  /// Parses one line; false (and error() says why) when it is not one JSON object, or holds a
  /// number that cannot be written out (see plain_decimal).
  bool parse(std::string_view line) {
    texts_.clear();
    members_.clear();
    precision_.clear();
    arrays_.clear();
    fields_.clear();
    has_fields_ = false;
    depth_ = 0;
    mode_ = mode::top;
    error_.clear();
    line_ = line;
    cursor_ = 0;
    if (!nlohmann::json::sax_parse(line, this) && error_.empty()) error_ = "invalid JSON: not JSON";
    return error_.empty();
  }
  [[nodiscard]] const std::string& error() const { return error_; }

  /// The lookup nmea::read_json and nmea2000::read_json ask: member `key` of the object (""),
  /// of "precision", or element `key` ("0", "1", ...) of the array member `object`, or member m
  /// of an object element i of it (key "i.m", a PGN's repeating group).
  json_value operator()(std::string_view object, std::string_view key) const {
    if (!object.empty() && object != "precision") {
      for (auto it = arrays_.rbegin(); it != arrays_.rend(); ++it)
        if (it->array == object && it->index == key) return it->value;
      return {};
    }
    const auto& list = object.empty() ? members_ : precision_;
    for (auto it = list.rbegin(); it != list.rend(); ++it)  // the last of repeated keys wins
      if (it->first == key) return it->second;
    return {};
  }
  [[nodiscard]] const std::vector<std::pair<std::string_view, json_value>>& members() const {
    return members_;
  }
  /// The members of the "precision" object(s), in order.
  [[nodiscard]] const std::vector<std::pair<std::string_view, json_value>>& precision() const {
    return precision_;
  }
  [[nodiscard]] const std::vector<std::string_view>& fields() const { return fields_; }
  [[nodiscard]] bool has_fields() const { return has_fields_; }

  // ---- nlohmann::json_sax ----
  bool null() override { return value(json_kind::null, ""); }
  bool boolean(bool b) override { return value(json_kind::boolean, b ? "true" : "false"); }
  // The parser gives whole numbers as integers, and "-0" as 0: the sign of a zero, which the
  // vehicle writes and a decimal keeps, is read from the number's own text.
  bool number_integer(number_integer_t v) override {
    const std::string_view text = next_number_text();
    return value(json_kind::number, v == 0 && text == "-0" ? "-0" : std::to_string(v));
  }
  bool number_unsigned(number_unsigned_t v) override {
    (void)next_number_text();
    return value(json_kind::number, std::to_string(v));
  }
  bool number_float(number_float_t, const string_t& text) override {
    (void)next_number_text();
    // The number as written ("203.10"), or, with an exponent, written out ("1e-05": "0.00001"):
    // the library reads plain decimals only. Only values that are kept are converted.
    const bool kept = depth_ == 1 || (depth_ == 2 && mode_ == mode::precision) ||
                      (depth_ == 3 && mode_ == mode::element);
    if (!kept || text.find_first_of("eE") == std::string::npos)
      return value(json_kind::number, text);
    std::string why;
    const std::string plain = plain_decimal(text, why);
    if (plain.empty()) {
      const std::string where =
          depth_ == 1   ? "field \"" + tools::quote_prefix(key_) + "\""
          : depth_ == 3 ? "\"" + tools::quote_prefix(inner_key_) + "\" of an element of \"" +
                              tools::quote_prefix(key_) + "\""
                        : "\"precision\" of \"" + tools::quote_prefix(inner_key_) + "\"";
      return refuse(where + " " + tools::quote_prefix(text) + ": " + why);
    }
    return value(json_kind::number, plain);
  }
  bool string(string_t& s) override { return value(json_kind::string, s); }
  bool binary(binary_t&) override { return fail("binary values are not JSON text"); }
  bool key(string_t& k) override {
    if (depth_ == 1) {
      key_ = keep(k);
    } else if ((depth_ == 2 && mode_ == mode::precision) ||
               (depth_ == 3 && mode_ == mode::element)) {
      inner_key_ = keep(k);
    }
    return true;
  }
  bool start_object(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    // nlohmann-json's message quotes the input it stopped at ("last read: '...'", "number
    // overflow parsing '...'"), however long: a prefix of it.
    const std::string_view what = e.what();
    const std::size_t from = what.find('\'');
    const std::size_t to = what.rfind('\'');
    error_ = "invalid JSON: ";
    if (from == std::string_view::npos || to == from) {
      error_ += tools::quote_prefix(what, 256);
    } else {
      error_ += what.substr(0, from + 1);
      error_ += tools::quote_prefix(what.substr(from + 1, to - from - 1));
      error_ += tools::quote_prefix(what.substr(to), 64);
    }
    return false;
  }

 private:
  // The text of the next number in the line: the parser calls back for the numbers in the order
  // they are written, and strings (keys and values) are the only other place a digit or '-'
  // can be.
  std::string_view next_number_text() {
    const auto number_char = [](char c) {
      return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
    };
    while (cursor_ < line_.size()) {
      const char c = line_[cursor_];
      if (c == '"') {
        for (++cursor_; cursor_ < line_.size() && line_[cursor_] != '"';)
          cursor_ += line_[cursor_] == '\\' ? std::size_t{2} : std::size_t{1};
        ++cursor_;
      } else if (c == '-' || (c >= '0' && c <= '9')) {
        const std::size_t begin = cursor_;
        while (cursor_ < line_.size() && number_char(line_[cursor_])) ++cursor_;
        return line_.substr(begin, cursor_ - begin);
      } else {
        ++cursor_;
      }
    }
    return {};
  }

  enum class mode { top, precision, fields, array, element, element_skip, skip };
  struct element {
    std::string_view array;
    std::string_view index;
    json_value value;
  };

  std::string_view keep(std::string_view s) { return texts_.emplace_back(s); }

  // Not the JSON this program reads.
  bool fail(const std::string& why) { return refuse("invalid JSON: " + why); }
  // JSON, but a value that cannot be sent.
  bool refuse(std::string why) {
    if (error_.empty()) error_ = std::move(why);
    return false;
  }

  bool value(json_kind kind, std::string_view text) {
    if (depth_ == 0) return fail("a line must hold one JSON object");
    if (depth_ == 1) {
      members_.emplace_back(key_, json_value{kind, keep(text)});
    } else if (depth_ == 2 && mode_ == mode::precision) {
      precision_.emplace_back(inner_key_, json_value{kind, keep(text)});
    } else if (depth_ == 2 && mode_ == mode::fields) {
      if (kind != json_kind::string) return fail("\"fields\" must be an array of strings");
      fields_.push_back(keep(text));
    } else if (depth_ == 2 && mode_ == mode::array) {
      arrays_.push_back({key_, keep(std::to_string(index_++)), json_value{kind, keep(text)}});
    } else if (depth_ == 3 && mode_ == mode::element) {
      // a member of an object in an array (a PGN's repeating group): "<index>.<member>"
      arrays_.push_back({key_, keep(std::to_string(index_ - 1) + "." + std::string(inner_key_)),
                         json_value{kind, keep(text)}});
    }
    return true;
  }

  bool open(bool array) {
    if (depth_ == 0) {
      if (array) return fail("a line must hold one JSON object");
    } else if (depth_ == 1) {
      // The text says which: "{" an object, "[" an array ("precision" must be an object).
      members_.emplace_back(key_, json_value{json_kind::other, array ? "[" : "{"});
      if (!array && key_ == "precision") {
        mode_ = mode::precision;
      } else if (array && key_ == "fields") {
        mode_ = mode::fields;
        has_fields_ = true;
      } else if (array) {
        mode_ = mode::array;  // e.g. a flag set of a PGN
        index_ = 0;
      } else {
        mode_ = mode::skip;
      }
    } else if (depth_ == 2 && mode_ == mode::array && !array) {
      // an object in an array (a PGN's repeating group): element "<index>", its members read
      arrays_.push_back({key_, keep(std::to_string(index_++)), json_value{json_kind::other, "{"}});
      mode_ = mode::element;
    } else if (depth_ == 2 && mode_ == mode::array) {
      mode_ = mode::skip;  // arrays of arrays: not read
    } else if (depth_ == 3 && mode_ == mode::element) {
      // a container inside a group's element: kept as "{" or "[", its content not read
      arrays_.push_back({key_, keep(std::to_string(index_ - 1) + "." + std::string(inner_key_)),
                         json_value{json_kind::other, array ? "[" : "{"}});
      mode_ = mode::element_skip;
    } else if (depth_ == 2 && mode_ != mode::skip) {
      return fail("\"precision\" and \"fields\" hold plain values only");
    }
    ++depth_;
    return true;
  }

  bool close() {
    if (--depth_ == 1) mode_ = mode::top;
    if (depth_ == 2 && mode_ == mode::element) mode_ = mode::array;
    if (depth_ == 3 && mode_ == mode::element_skip) mode_ = mode::element;
    return true;
  }

  std::deque<std::string> texts_;
  std::vector<std::pair<std::string_view, json_value>> members_;
  std::vector<std::pair<std::string_view, json_value>> precision_;
  std::vector<element> arrays_;
  std::size_t index_ = 0;
  std::vector<std::string_view> fields_;
  bool has_fields_ = false;
  std::string_view key_;
  std::string_view inner_key_;
  int depth_ = 0;
  mode mode_ = mode::top;
  std::string error_;
  std::string_view line_;  // the line being parsed, for the numbers' text
  std::size_t cursor_ = 0;
};

/// Calls f(std::type_identity<M>{}) for the first message of the set whose address matches.
template <class F, class... Ms>
bool with_type(std::string_view type, nmea::message_set<Ms...>*, F&& f) {
  return ((Ms::nmea.matches(type) ? (f(std::type_identity<Ms>{}), true) : false) || ...);
}

/// The "precision" a position field takes: fraction digits from lo to hi (what nmea::read_json
/// and nmea::from_decimal_degrees accept).
struct place_range {
  unsigned lo;
  unsigned hi;
  std::string_view what;
};

/// The precision range of M's field `key`; nullopt when it is no position field of M.
template <class M>
std::optional<place_range> position_places(std::string_view key) {
  std::optional<place_range> out;
  M::nmea.fields.apply([&](const auto&... d) {
    (
        [&](const auto& desc) {
          using V = typename std::remove_cvref_t<decltype(desc)>::value_type;
          if (desc.name != key) return;
          if constexpr (nmea::is_ddmm_position<V>) {
            out = place_range{nmea::min_minute_places, nmea::max_minute_places,
                              "minute places of a DDMM.mmm position"};
          } else if constexpr (nmea::is_degrees_position<V>) {
            out = place_range{0, nmea::max_degree_places,
                              "degree places of a decimal-degree position"};
          }
        }(d),
        ...);
  });
  return out;
}

/// M's position fields, for messages: "latitude, longitude"; empty when it has none.
template <class M>
std::string position_names() {
  std::string out;
  M::nmea.fields.apply([&](const auto&... d) {
    (
        [&](const auto& desc) {
          if (!position_places<M>(desc.name)) return;
          if (!out.empty()) out += ", ";
          out += desc.name;
        }(d),
        ...);
  });
  return out;
}

struct options {
  bool line_buffered = false;
  nmea2000::log_format log = nmea2000::log_format::candump_log;  // NMEA 2000 messages
};

class encoder {
 public:
  explicit encoder(const options& o) : opt_(o), out_(stdout) {}

  void line(std::string_view text) {
    ++line_;
    while (!text.empty() && (text.back() == '\r' || text.back() == ' ' || text.back() == '\t'))
      text.remove_suffix(1);
    if (text.find_first_not_of(" \t") == std::string_view::npos) return;  // blank line
    if (!obj_.parse(text)) {
      reject(obj_.error());
      return;
    }
    const json_value type = obj_({}, "type");
    if (type.kind != json_kind::string) {
      // seawire-decode's report of a line it rejected: nothing to send, already reported.
      if (type.blank() && !obj_({}, "error").blank()) return;
      reject("no \"type\" string");
      return;
    }
    const json_value start = obj_({}, "start");
    if (const auto pgn = nmea2000::pgn_of_type(type.text)) {
      can(*pgn, type.text);
    } else if (type.text == anello::frame_json_type) {
      frame();
    } else if (start.kind == json_kind::string && start.text == "!") {
      unknown(type.text);  // a '!' sentence is no message, whatever its type: sent as given
    } else if (!with_type(type.text, static_cast<all_messages*>(nullptr),
                          [&](auto tag) { send<typename decltype(tag)::type>(type.text); })) {
      unknown(type.text);
    }
    if (opt_.line_buffered) out_.flush();
  }

  // A line longer than tools::max_line: not read (its bytes are not kept), the next one is.
  void too_long(std::uint64_t bytes) {
    ++line_;
    reject(std::to_string(bytes) + " bytes, more than the " + std::to_string(tools::max_line) +
           " a line may have: not read");
  }

  void finish() {
    out_.flush();
    errors_.flush([&](std::uint64_t n) { note(errors_.note_text(n)); });
  }
  [[nodiscard]] std::uint64_t rejected() const { return rejected_; }
  [[nodiscard]] bool output_failed() const { return out_.failed(); }
  [[nodiscard]] int output_error() const { return out_.error(); }

 private:
  template <class M>
  void send(std::string_view type) {
    if (!known_keys(type, [](std::string_view k) { return nmea::has_field<M>(k); })) return;
    if (!known_precision(
            type, [](std::string_view k) { return position_places<M>(k); }, position_names<M>()))
      return;
    const result<M> m = nmea::read_json<M>(type, obj_);
    if (!m) {
      // Numbered in the form the object gives (a CPRBS without battery_id has five fields).
      field_error(type, m.ec, m.field,
                  nmea::field_name<M>(m.field, nmea::form_field_count(m.value)));
      return;
    }
    std::array<char, 1100> buf;
    const result<std::size_t> r = nmea::encode_to(m.value, std::span<char>(buf.data(), buf.size()));
    if (!r) {
      field_error(type, r.ec, r.field,
                  nmea::field_name<M>(r.field, nmea::form_field_count(m.value)));
      return;
    }
    out_.put(std::string_view(buf.data(), r.value));
  }

  // Whether the object is a message of P: of a PGN with several layouts, whether it names P's
  // in P's match row (126208's "function_code"); `names` collects the layouts' names.
  template <class P>
  bool names_layout(std::string& names) const {
    if constexpr (!nmea2000::description_of<P>::has_match) {
      return true;
    } else {
      bool named = false;
      seawire::nmea2000::pgn_table<P>.for_each([&](const auto& f, unsigned, std::uint16_t) {
        using F = std::remove_cvref_t<decltype(f)>;
        if constexpr (requires { F::is_match; }) {
          typename F::value_type v;
          const json_value j = obj_({}, f.name);
          named = j.kind != json_kind::absent &&
                  nmea2000::read_json_value(j, v, f.name, obj_) == errc::ok &&
                  v.raw() == F::match_raw;
          names += names.empty() ? "\"" : ", \"";
          names += F::value_type::from_raw(F::match_raw).name();
          names += '"';
        }
      });
      return named;
    }
  }

  // An NMEA 2000 message: its CAN frames (a fast packet's several), as lines of the log format.
  void can(std::uint32_t pgn, std::string_view type) {
    const std::optional<nmea2000::pgn_info> info = n2k_pgns::info(pgn);
    constexpr std::string_view header_keys[] = {"time_s", "interface", "direction",
                                                "prio",   "src",       "dst"};
    // The struct that describes the object (its index in the list): the PGN's, or of a PGN
    // with several layouts the one the object names; none: its payload is given in "data".
    std::optional<std::size_t> chosen;
    std::string layouts;
    if (info) {
      std::size_t index = 0;
      n2k_pgns::for_each_type([&](const auto& tag) {
        using P = std::remove_cvref_t<decltype(tag)>;
        const std::size_t i = index++;
        if (seawire::nmea2000::pgn_table<P>.info.pgn == pgn && !chosen && names_layout<P>(layouts))
          chosen = i;
      });
      if (!chosen && obj_({}, "data").kind == json_kind::absent) {
        reject(std::string(type) + ": \"function_code\" must name one of its layouts seawire " +
               "describes (" + layouts + "), or \"data\" give the payload in hex");
        return;
      }
    }
    // fn(tag) for the chosen struct.
    const auto with_chosen = [&](auto&& fn) {
      std::size_t index = 0;
      n2k_pgns::for_each_type([&](const auto& tag) {
        if (chosen && index++ == *chosen) fn(tag);
      });
    };
    const auto known = [&](std::string_view k) {
      for (const std::string_view h : header_keys)
        if (k == h) return true;
      if (!chosen) return k == "data";
      bool found = false;
      with_chosen([&](const auto& tag) {
        found = nmea2000::has_field<std::remove_cvref_t<decltype(tag)>>(k);
      });
      return found;
    };
    if (!known_keys(type, known, false)) return;
    const result<nmea2000::message_header> h =
        nmea2000::read_json_header(pgn, info ? info->priority : 6, obj_);
    if (!h) {
      field_error(type, h.ec, 0, {},
                  std::string(" (in \"") + std::string(header_keys[h.field - 1]) + "\")");
      return;
    }
    nmea2000::log_record rec;
    rec.id = h.value.id;
    rec.time_us = h.value.time_us;
    rec.interface = h.value.interface;
    rec.direction = h.value.direction == 0 ? 'R' : h.value.direction;
    std::vector<std::uint8_t> payload;
    if (chosen) {
      bool ok = true;
      with_chosen([&](const auto& tag) {
        using P = std::remove_cvref_t<decltype(tag)>;
        const result<P> m = nmea2000::read_json<P>(obj_);
        if (!m) {
          field_error(type, m.ec, m.field, nmea2000::field_name<P>(m.field));
          ok = false;
          return;
        }
        const auto bytes = nmea2000::encode(m.value);
        if (!bytes) {
          field_error(type, bytes.ec, bytes.field, nmea2000::field_name<P>(bytes.field),
                      bytes.ec == errc::missing_field
                          ? " (a flag set has no \"not available\" value: it can be left out "
                            "only with every field after it; [] sends it with no flag set)"
                          : "");
          ok = false;
          return;
        }
        payload.assign(bytes.value.begin(), bytes.value.end());
      });
      if (!ok) return;
    } else {
      using payload_bytes = nmea2000::opaque_bytes<nmea2000::max_fast_packet_length>;
      const json_value d = obj_({}, "data");
      const result<payload_bytes> bytes = d.kind == json_kind::string
                                              ? payload_bytes::from_hex(d.text)
                                              : result<payload_bytes>{{}, errc::bad_text};
      if (!bytes) {
        reject(std::string(type) + ": \"data\" must be the payload's bytes in hex, at most " +
               std::to_string(nmea2000::max_fast_packet_length) +
               " bytes (a PGN seawire does not describe is sent as given)");
        return;
      }
      payload.assign(bytes.value.bytes().begin(), bytes.value.bytes().end());
    }
    // A PGN seawire does not describe travels as the standard's list says, as seawire-decode
    // reads it back. A single-frame PGN longer than a frame would need ISO transport (a
    // multi-packet session seawire does not write): refused, unless the log's line holds a whole
    // message (canboat, Actisense), where it is read back as written.
    const bool fast = info ? info->transport == nmea2000::framing::fast_packet
                           : nmea2000::is_fast_packet_pgn(pgn);
    const bool whole_lines = opt_.log == nmea2000::log_format::canboat ||
                             opt_.log == nmea2000::log_format::actisense_n2k_ascii;
    if (!fast && !whole_lines && payload.size() > 8) {
      reject(std::string(type) + ": " + std::to_string(payload.size()) +
             " bytes in a single-frame PGN (not a fast packet by the standard's list): a CAN "
             "frame holds 8; more needs ISO transport, which seawire-encode does not write (a "
             "canboat or Actisense log holds the whole message in one line)");
      return;
    }
    if (!fast || whole_lines) {
      // One frame, or a line holding the whole payload (canboat FAST, Actisense).
      (void)rec.assign(payload);
      put_record(type, rec);
      return;
    }
    const auto frames = nmea2000::split_fast_packet(payload, sequence_.next(pgn, rec.id.source));
    for (const nmea2000::frame_data& f : frames.value.view()) {
      (void)rec.assign(f.view());
      if (!put_record(type, rec)) return;
    }
  }

  bool put_record(std::string_view type, const nmea2000::log_record& rec) {
    if (opt_.log == nmea2000::log_format::canboat && !canboat_header_) {
      // Every canboat line written is a whole message: say so, as canboat's loggers do, so a
      // reader takes a fast-packet PGN's message of 8 bytes or fewer whole, not as a frame.
      out_.put(nmea2000::format_header_prefix);
      out_.put(nmea2000::name(nmea2000::canboat_format::fast));
      out_.put('\n');
      canboat_header_ = true;
    }
    const errc e = nmea2000::write_log_line(out_, rec, opt_.log);
    if (e != errc::ok) {
      field_error(type, e, 0, {});
      return false;
    }
    return true;
  }

  void frame() {
    // A frame's positions always have 6 fraction digits: no "precision" (an unknown key).
    if (!known_keys(anello::frame_json_type, anello::has_json_field, false)) return;
    const result<anello::sensor_frame_raw> f = anello::read_frame_json(obj_);
    if (!f) {
      const anello::sensor_field_about about = anello::about_sensor_field(f.field);
      field_error(anello::frame_json_type, f.ec, f.field, about.json_key,
                  about.is_code && f.ec == errc::bad_number
                      ? " (a code: a whole number, not rounded)"
                      : "");
      return;
    }
    const anello::frame_bytes bytes = anello::encode_frame(f.value);
    out_.put(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  }

  // {"type":"XXABC","fields":["1","2"]}: a sentence no message describes, sent as given;
  // {"type":"AIVDM","start":"!","fields":[...]} starts it with '!' (an encapsulation sentence).
  void unknown(std::string_view type) {
    if (!obj_.has_fields()) {
      reject(std::string(name(errc::unknown_address)) + ": no known message is \"" +
             tools::quote_prefix(type) + "\" (and there is no \"fields\" array to send it as is)");
      return;
    }
    for (const auto& [key, value] : obj_.members()) {
      if (key == "type" || key == "fields" || key == "start") continue;
      reject(tools::quote_prefix(type) + ": unknown key \"" + tools::quote_prefix(key) +
             "\" (a sentence no message describes takes only \"type\", \"fields\" and "
             "\"start\")");
      return;
    }
    char start = '$';
    if (const json_value s = obj_({}, "start"); s.kind != json_kind::absent) {
      if (s.kind != json_kind::string || (s.text != "$" && s.text != "!")) {
        reject(tools::quote_prefix(type) + ": \"start\" must be \"$\" or \"!\"");
        return;
      }
      start = s.text[0];
    }
    if (!nmea::is_address(type)) {
      reject(std::string(name(errc::bad_address)) + ": \"" + tools::quote_prefix(type) +
             "\" is not 1-15 upper-case letters and digits");
      return;
    }
    std::array<char, 1100> buf;
    nmea::writer w(std::span<char>(buf.data(), buf.size()));
    w.begin(type, start);
    std::uint16_t n = 0;
    for (const std::string_view f : obj_.fields()) {
      ++n;
      if (!nmea::is_field_text(f)) {
        field_error(type, errc::bad_text, n, "fields");
        return;
      }
      w.next_field();
      w.put(f);
    }
    const result<std::size_t> r = w.seal();
    if (!r) {
      field_error(type, r.ec, 0, {});
      return;
    }
    out_.put(w.view());
  }

  // Keys that are no field of the message are refused: a misspelt key would otherwise be a
  // silently blank field.
  template <class Known>
  bool known_keys(std::string_view type, Known&& known, bool precision_allowed = true) {
    for (const auto& [key, value] : obj_.members()) {
      if (key == "type" || (precision_allowed && key == "precision") || known(key)) continue;
      reject(std::string(type) + ": unknown key \"" + tools::quote_prefix(key) +
             "\" (not a field of " + std::string(type) + ")");
      return false;
    }
    return true;
  }

  // "precision" must be an object whose keys are position fields of the message and whose values
  // are whole numbers of fraction digits in the field's range: a misspelt key would otherwise
  // silently send the default precision. places(key) gives the range, nullopt for a key that is
  // no position field; `names` lists the position fields for the error message.
  template <class Places>
  bool known_precision(std::string_view type, Places&& places, std::string_view names) {
    const json_value p = obj_({}, "precision");
    if (p.blank()) return true;
    const std::string t(type);
    if (p.kind != json_kind::other || p.text != "{") {
      reject(t + ": \"precision\" must be an object giving position fields their fraction digits" +
             " (e.g. \"precision\":{\"latitude\":5})");
      return false;
    }
    for (const auto& [key, value] : obj_.precision()) {
      const std::optional<place_range> range = places(key);
      if (!range) {
        reject(t + ": unknown key \"" + tools::quote_prefix(key) + "\" in \"precision\" (" +
               (names.empty() ? t + " has no position fields"
                              : "allowed: the position fields " + std::string(names)) +
               ")");
        return false;
      }
      if (value.blank()) continue;  // null: the default precision
      unsigned n = 0;
      const char* const end = value.text.data() + value.text.size();
      const auto [stop, ec] = std::from_chars(value.text.data(), end, n);
      const bool whole = (value.kind == json_kind::number || value.kind == json_kind::string) &&
                         !value.text.empty() && value.text.size() <= 3 && ec == std::errc{} &&
                         stop == end;
      if (!whole || n < range->lo || n > range->hi) {
        const std::string_view quote = value.kind == json_kind::string ? "\"" : "";
        std::string why = t;
        why += ": \"precision\" of \"";
        why += tools::quote_prefix(key);
        why += "\" is ";
        why += quote;
        why += tools::quote_prefix(value.text);
        why += quote;
        why += ": must be a whole number from " + std::to_string(range->lo) + " to " +
               std::to_string(range->hi) + " (" + std::string(range->what) + ")";
        reject(why);
        return false;
      }
    }
    return true;
  }

  void field_error(std::string_view type, errc e, std::uint16_t field, std::string_view field_name,
                   std::string_view note = {}) {
    std::string what(type);
    if (field != 0) {
      what += " field " + std::to_string(field);
      if (!field_name.empty()) {
        what += " (" + std::string(field_name) + ")";
        const json_value v = obj_({}, field_name);
        if (v.kind == json_kind::string) {
          what += " \"" + tools::quote_prefix(v.text) + "\"";
        } else if (v.kind == json_kind::number || v.kind == json_kind::boolean) {
          what += " " + tools::quote_prefix(v.text);
        }
      }
    }
    reject(what + ": " + std::string(name(e)) + ": " + std::string(message(e)) + std::string(note));
  }

  void reject(const std::string& why) {
    ++rejected_;
    // A flood of bad lines is told in part: 20 a second, then how many were not.
    if (!errors_.allow([&](std::uint64_t n) { note(errors_.note_text(n)); })) return;
    out_.flush();  // keep stdout and stderr in input order for a reader of both
    // The reason quotes the input, which JSON lets hold any byte: NUL and control bytes escaped.
    std::fprintf(stderr, "seawire-encode: line %llu: %s\n", static_cast<unsigned long long>(line_),
                 tools::printable(why).c_str());
  }

  void note(const std::string& text) {
    out_.flush();
    std::fprintf(stderr, "seawire-encode: %s\n", text.c_str());
  }

  const options& opt_;
  tools::output out_;
  json_object obj_;
  nmea2000::fast_packet_sequencer<> sequence_;
  bool canboat_header_ = false;  // "# format=FAST" written
  std::uint64_t line_ = 0;
  std::uint64_t rejected_ = 0;
  tools::log_limit errors_{"rejected lines"};
};

int run(const options& o) {
  encoder e(o);
  tools::chunk_reader in(0);
  tools::for_each_bounded_line(
      in, tools::max_line, [&](std::string_view l) { e.line(l); },
      [&](std::uint64_t bytes) { e.too_long(bytes); });
  e.finish();
  // The errno saved when the read or write failed: errno itself has been set again since.
  if (in.failed()) {
    std::fprintf(stderr, "seawire-encode: reading stdin: %s\n", std::strerror(in.error()));
    return 1;
  }
  if (e.output_failed()) {
    std::fprintf(stderr, "seawire-encode: writing stdout: %s\n", std::strerror(e.output_error()));
    return 1;
  }
  return e.rejected() == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "seawire-encode: JSON Lines on stdin -> sentences on stdout (CR LF, uppercase checksum),\n"
      "in the schema seawire-decode writes: \"type\" (the address as on the wire: \"PYDIR\",\n"
      "\"GPRMC\"; \"AB00\" for an ANELLO binary frame) plus the message's fields by name.\n"
      "Numbers are sent with the digits written (1.50 stays 1.50; 1e-05, as jq prints 0.00001,\n"
      "is sent as 0.00001). Positions are signed decimal degrees; a DDMM.mmm field gets\n"
      "(fraction digits - 2) minute places, 4 when the number has fewer than 3; override per\n"
      "field with \"precision\": {\"latitude\": 5} (1-12 minute places; 0-18 degree places for\n"
      "decimal-degree fields). Blank or absent fields: null or left out; unknown keys are\n"
      "refused. {\"type\":\"XXABC\",\"fields\":[\"1\",\"2\"]} sends any other\n"
      "sentence as given. Error objects from seawire-decode are passed over. A line that cannot\n"
      "be sent is reported on stderr (line number, field, reason) and the next line is read.\n"
      "NMEA 2000 messages (\"type\":\"PGN128259\", as seawire-decode writes them from a CAN\n"
      "log) become CAN log lines (--output), fast packets split into their frames.\n\n"
      "Examples:\n"
      "  echo '{\"type\":\"PYDIR\",\"thrust_left\":45,\"thrust_right\":55}' | seawire-encode\n"
      "  seawire-encode --line-buffered < cmds.jsonl | nc vehicle 29500\n"
      "  seawire-decode < log.nmea | jq -c 'select(.type==\"CPNVG\")' | seawire-encode\n"
      "  seawire-encode < speed.jsonl | canplayer -I - vcan0=can0     # NMEA 2000 to a bus\n"
      "Exit status: 0 every line sent, 1 some line rejected, 2 usage error.",
      "seawire-encode"};
  options o;
  app.add_flag("--line-buffered", o.line_buffered,
               "flush stdout after each sentence, for live links (e.g. ... | seawire-encode "
               "--line-buffered | nc vehicle 29500); default: large buffers, for speed");
  std::string log = "candump_log";
  app.add_option("-o,--output", log,
                 "how NMEA 2000 messages (\"type\":\"PGN128259\") are written: candump_log "
                 "(default: candump -L lines, what canplayer reads), candump, canboat (FAST: a "
                 "\"# format=FAST\" header, then one line per whole message), yd_raw or "
                 "actisense_n2k_ascii (one line per whole message); other than canboat and "
                 "Actisense, fast packets are split into frames "
                 "with a sequence counter per PGN and source (e.g. seawire-encode < speed.jsonl | "
                 "canplayer -I - vcan0=can0)")
      ->check(
          CLI::IsMember({"candump_log", "candump", "canboat", "yd_raw", "actisense_n2k_ascii"}));
  app.set_version_flag("--version", "seawire-encode (seawire " SEAWIRE_VERSION_STRING ")");
  if (const auto status = tools::parse_command_line(app, argc, argv)) return *status;
  o.log = *nmea2000::log_format_named(log);
  return run(o);
}
