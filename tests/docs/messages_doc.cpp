// SPDX-License-Identifier: BSL-1.0
// Writes docs/messages.md, the reference of every message, from the messages' own descriptions:
// nothing in it is typed by hand, so it cannot disagree with what the library decodes. The
// test docs_messages_current fails when the committed copy differs from this program's output.
//
//   seawire_messages_doc > docs/messages.md

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "seawire/anello/frame_json.hpp"
#include "seawire/seawire.hpp"
#include "seawire/walk.hpp"

namespace {

using namespace seawire;

std::string number(const nmea::decimal& d) {
  char buf[48];
  const auto r = nmea::to_chars(buf, buf + sizeof buf, d);
  return std::string(buf, r.ptr);
}

std::string quoted(std::string_view s) { return "`" + std::string(s) + "`"; }

// The name of the member a field reads into, as the source spells it ("lat"), from the name the
// compiler gives the function template instantiated for its member pointer: C++20 has no
// reflection, and the description names the JSON key ("latitude"), which may differ.
template <auto Member>
std::string member_name() {
  const std::string_view f = __PRETTY_FUNCTION__;
  const std::size_t at = f.find("Member = ");
  const std::string_view with = f.substr(0, f.find_first_of(";]", at));
  const std::size_t colon = with.rfind("::");
  std::string name(with.substr(colon == std::string_view::npos ? with.size() : colon + 2));
  const bool identifier = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
  if (at == std::string_view::npos || !identifier) {
    std::fprintf(stderr, "messages_doc: no member name in %.*s\n", static_cast<int>(f.size()),
                 f.data());
    std::exit(1);
  }
  return name;
}

// What the wire field holds, told from the member's type.
template <class V>
std::string form_of(const nmea::field_options& o) {
  if constexpr (requires { nmea::codec<V>::form; }) {
    return std::string(nmea::codec<V>::form);
  } else if constexpr (std::is_same_v<V, nmea::decimal>) {
    return "number";
  } else if constexpr (std::is_same_v<V, bool>) {
    return "flag, `0` or `1`";
  } else if constexpr (std::is_integral_v<V> || nmea::is_integer_wrapper<V>) {
    std::string s = "whole number";
    if (o.zero_pad > 1) s += ", at least " + std::to_string(o.zero_pad) + " digits";
    return s;
  } else if constexpr (std::is_same_v<V, nmea::latitude>) {
    return "latitude `DDMM.m`, then `N`/`S`";
  } else if constexpr (std::is_same_v<V, nmea::longitude>) {
    return "longitude `DDDMM.m`, then `E`/`W`";
  } else if constexpr (std::is_same_v<V, nmea::decimal_latitude>) {
    return "latitude in decimal degrees, then `N`/`S`";
  } else if constexpr (std::is_same_v<V, nmea::decimal_longitude>) {
    return "longitude in decimal degrees, then `E`/`W`";
  } else if constexpr (std::is_same_v<V, nmea::magnetic_variation>) {
    return "degrees, then `E`/`W`";
  } else if constexpr (std::is_same_v<V, nmea::time_of_day>) {
    return "UTC time `hhmmss.s`";
  } else if constexpr (std::is_same_v<V, nmea::date>) {
    return "date `ddmmyy`";
  } else if constexpr (requires { V::capacity; }) {
    std::string s = o.code_chars ? "code (upper-case letters, digits)" : "text";
    if (o.min_length == o.max_length)
      s += ", " + std::to_string(o.min_length) + " characters";
    else if (o.max_length != 0xFFFF)
      s += ", " + std::to_string(o.min_length) + " to " + std::to_string(o.max_length) +
           " characters";
    else
      s += ", up to " + std::to_string(V::capacity) + " characters";
    return s;
  } else if constexpr (nmea::char_enum_like<V>) {
    std::string s = "one of ";
    const std::string_view letters = nmea::enum_letters<V>;
    for (std::size_t i = 0; i < letters.size(); ++i) {
      if (i != 0) s += " ";
      s += quoted(letters.substr(i, 1));
    }
    return s;
  } else if constexpr (nmea::word_enum_like<V>) {
    std::string s = "one of ";
    bool first = true;
    for (const std::string_view w : enum_words(V{})) {
      if (!first) s += " ";
      s += quoted(w);
      first = false;
    }
    return s;
  } else {
    static_assert(!sizeof(V), "messages_doc: say what this type's wire field holds");
  }
}

// The values the field allows beyond its form.
std::string allowed(const nmea::field_options& o) {
  std::string s;
  const auto add = [&s](const std::string& part) { s += (s.empty() ? "" : "; ") + part; };
  if (o.has_min && o.has_max)
    add(number(o.min) + (o.max_exclusive ? " to below " : " to ") + number(o.max));
  else if (o.has_min)
    add("at least " + number(o.min));
  else if (o.has_max)
    add((o.max_exclusive ? "below " : "at most ") + number(o.max));
  if (o.max_places >= 0) add("at most " + std::to_string(o.max_places) + " fraction digits");
  if (o.unit != 0) add("unit field " + quoted(std::string_view(&o.unit, 1)));
  return s;
}

// ---------------------------------------------------------------------------------------------
// One row of a message's table, from the walk's layout of the field (walk.hpp): the columns of
// its wire. A sentence's rows also extend the sentence's pattern ("$CPNVG,timestamp,...").

struct table_context {
  std::string pattern;  // a sentence's "$ADDR,field,N/S,..."
  bool hawaii = false;  // RobotX: dates and times on the Hawaii clock
};

template <class V>
std::string n2k_form(std::string& step, std::string& range);

template <class Raw>
std::string wire_type() {
  return std::string(std::is_signed_v<Raw> ? "int" : "uint") + std::to_string(8 * sizeof(Raw));
}

template <class F>
std::string sentence_row(F, table_context& c) {
  constexpr const auto& field = F::desc;
  using D = std::remove_cvref_t<decltype(field)>;
  using V = typename D::value_type;
  constexpr unsigned first = F::number;
  constexpr unsigned last = first + F::wire_fields - 1;
  const std::string numbers =
      first == last ? std::to_string(first) : std::to_string(first) + "-" + std::to_string(last);
  c.pattern += "," + std::string(F::name);
  if constexpr (nmea::codec<V>::width == 2) {
    c.pattern += F::axis == position_axis::latitude ? ",N/S" : ",E/W";
  }
  if (field.opts.unit != 0) c.pattern += "," + std::string(1, field.opts.unit);
  std::string when;
  if (field.opts.only_with_field_count != 0)
    when = "only in the " + std::to_string(field.opts.only_with_field_count) + "-field form";
  else if (field.opts.may_be_absent)
    when = "may be left out";
  std::string precision = field.opts.precision >= 0 ? std::to_string(field.opts.precision) : "";
  if (field.opts.precision >= 0 && nmea::is_ddmm_position<V>) precision += " (minutes)";
  std::string form = form_of<V>(field.opts);
  // RobotX dates and times are read on the Hawaii clock, not UTC.
  if (c.hawaii && form.starts_with("UTC time"))
    form = "HST time (Hawaii, UTC-10, no daylight saving)" + form.substr(8);
  if (c.hawaii && form.starts_with("date")) form = "HST date" + form.substr(4);
  return "| " + numbers + " | " + quoted(member_name<D::member>()) + " | " + quoted(F::key) +
         " | " + form + " | " + allowed(field.opts) + " | " + (D::is_optional ? "yes" : "no") +
         " | " + when + " | " + precision + " |\n";
}

template <class F>
std::string frame_row(F) {
  constexpr const auto& field = F::desc;
  using raw = typename std::remove_cvref_t<decltype(field)>::raw_type;
  std::string allowed;
  if (field.allowed)
    allowed = std::to_string(field.allowed->lo) + " to " + std::to_string(field.allowed->hi);
  if (field.also_not_available)
    allowed += std::string(allowed.empty() ? "" : "; ") +
               "also not available: " + std::to_string(*field.also_not_available);
  char line[256];
  std::snprintf(line, sizeof line, "| %u | `%s` | `%s` | %zu | %s | %lld | %s |\n",
                unsigned{F::number}, std::string(F::name).c_str(), std::string(F::key).c_str(),
                static_cast<std::size_t>(F::bit_offset / 8), wire_type<raw>().c_str(),
                static_cast<long long>(field.divisor), allowed.c_str());
  return line;
}

// The JSON name of a PGN struct's member.
template <auto Member>
std::string json_name() {
  using P = seawire::detail::member_class_t<Member>;
  std::string out;
  seawire::nmea2000::pgn_table<P>.for_each([&](const auto& f, unsigned, std::uint16_t) {
    using E = std::remove_cvref_t<decltype(f)>;
    if constexpr (!E::is_reserved) {
      if (seawire::detail::same_member<E::member, Member>) out = std::string(f.name);
    }
  });
  return out;
}

// The JSON name of the field a keyed row is named by.
template <class Row>
std::string key_name() {
  return json_name<Row::key_member>();
}

// The PGN struct of a walk row.
template <class Info>
struct pgn_of_row;
template <class P, std::size_t I>
struct pgn_of_row<nmea2000::walk_field<P, I>> {
  using type = P;
};

// A repeating group's row, then a row for each field of one repetition ("row.k", bit offsets
// from the repetition's start).
template <class F>
std::string group_rows() {
  using E = std::remove_cvref_t<decltype(F::desc)>;
  using G = typename F::value_type;
  using Item = typename G::item_type;
  std::string how = "to the end of the payload";
  if constexpr (E::counted) {
    using P = seawire::detail::member_class_t<E::member>;
    how = "as many as " +
          quoted(nmea2000::field_name<P>(nmea2000::detail::row_of<P, E::count>().first)) + " says";
  }
  std::string s = "| " + std::to_string(F::number) + " | " + quoted(F::name) + " | " +
                  std::string(F::desc.title) + " | " + std::to_string(F::bit_offset) + " | " +
                  std::to_string(E::item_bits) +
                  " each | repeating group (JSON array of objects): " + how + ", at most " +
                  std::to_string(G::capacity) + " | | |\n";
  Item::n2k_item.for_each([&](const auto& e, unsigned o, std::uint16_t k) {
    using R = std::remove_cvref_t<decltype(e)>;
    std::string holds = "reserved: sent as ones, ignored when received";
    std::string step;
    std::string values;
    if constexpr (requires { R::is_spare; }) {
      holds = "spare: sent as zeros, ignored when received";
    } else if constexpr (!R::is_reserved) {
      holds = n2k_form<typename R::value_type>(step, values);
    }
    s += "| " + std::to_string(F::number) + "." + std::to_string(k) + " | " +
         (R::is_reserved ? "" : quoted(e.name)) + " | " + std::string(e.title) + " | +" +
         std::to_string(o) + " | " + std::to_string(R::bits) + " | " + holds + " | " + step +
         " | " + values + " |\n";
  });
  return s;
}

template <class F>
constexpr bool is_group_row() {
  if constexpr (F::reserved) {
    return false;
  } else {
    return nmea2000::detail::is_group_value<typename F::value_type>;
  }
}

template <class F>
std::string field_row(F) {
  using P = typename pgn_of_row<typename F::info>::type;
  std::string holds = "reserved: sent as ones, ignored when received";
  if constexpr (requires { F::desc.is_spare; })
    holds = "spare: sent as zeros, ignored when received";
  std::string step;
  std::string values;
  if constexpr (!F::reserved && nmea2000::keyed_row<typename F::info::row_type>) {
    using row = typename F::info::row_type;
    holds = "lookup named by " + quoted(key_name<row>()) + " and its own value";
    values = std::to_string(row::value_type::table::entries.size()) + " named pairs";
  } else if constexpr (!F::reserved) {
    holds = n2k_form<typename F::value_type>(step, values);
  }
  // After a counted string a row starts where the string ends.
  const std::string offset = nmea2000::description_of<P>::fixed_layout || F::bit_offset == 0
                                 ? std::to_string(F::bit_offset)
                                 : "where the row before ends";
  std::string bits = std::to_string(F::bits);
  if constexpr (!F::reserved) {
    if constexpr (nmea2000::text_value<typename F::value_type>) {
      if constexpr (F::value_type::variable) bits = "16 to " + bits;
    } else if constexpr (nmea2000::detail::is_opaque_bytes<typename F::value_type>) {
      bits = "the rest";
      using row = std::remove_cvref_t<decltype(F::desc)>;
      if constexpr (requires { row::is_pairs; })
        holds = "parameter pairs: a field's number (8 bits) in the PGN `" +
                json_name<row::pgn_member>() +
                "` names, then its value in as many bytes as that field needs; kept as sent, "
                "JSON a string of hex digits, two a byte";
    }
  }
  return "| " + std::to_string(F::number) + " | " + (F::reserved ? "" : quoted(F::name)) + " | " +
         std::string(F::desc.title) + " | " + offset + " | " + bits + " | " + holds + " | " + step +
         " | " + values + " |\n";
}

template <class F>
std::string pgn_row(F f) {
  if constexpr (is_group_row<F>()) {
    return group_rows<F>();
  } else {
    return field_row(f);
  }
}

// The rows of M's table, whatever its wire: one loop over the walk's layout, reserved bits too.
template <class M>
std::string rows_of(table_context& c) {
  std::string rows;
  visit_rows<M>([&](auto f) {
    using F = decltype(f);
    if constexpr (F::kind == wire_kind::nmea0183) {
      rows += sentence_row(f, c);
    } else if constexpr (F::kind == wire_kind::nmea2000) {
      rows += pgn_row(f);
    } else {
      rows += frame_row(f);
    }
  });
  return rows;
}

template <class M>
void message(std::string_view section) {
  constexpr auto& d = M::nmea;
  table_context c{"$" + std::string(d.address), section.starts_with("RobotX")};
  const std::string rows = rows_of<M>(c);
  std::printf("### %s\n\n", std::string(d.address).c_str());
  std::printf("%s", std::string(section).c_str());
  if (d.any_talker) std::printf(" Any talker: `--` stands for GP, GN, II, ...");
  if constexpr (d.field_counts.size() != 0) {
    std::string forms;
    for (const auto count : d.field_counts)
      forms += (forms.empty() ? "" : " or ") + std::to_string(count);
    std::printf(" Standard forms: %s fields.", forms.c_str());
  }
  std::printf("\n\n```\n%s*hh\n```\n\n", c.pattern.c_str());
  std::printf(
      "| Field | C++ member | JSON key | Wire form | Allowed | Blank | Present | Precision |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n%s\n", rows.c_str());
}

std::set<std::string> written;

template <class... Ms>
void set(std::string_view title, std::string_view section, nmea::message_set<Ms...>*) {
  std::printf("## %s\n\n", std::string(title).c_str());
  (
      [&] {
        const std::string address(Ms::nmea.address);
        if (written.insert(address).second) {
          message<Ms>(section);
        } else {
          std::printf("### %s\n\n%s As described above.\n\n", address.c_str(),
                      std::string(section).c_str());
        }
      }(),
      ...);
}

// The 0xAB00 frame, from anello::sensor_fields.
void frame() {
  std::printf(
      "## ANELLO: the 0xAB00 binary sensor frame\n\n"
      "56 bytes, big-endian: `AB 00` (frame id), `00 30` (payload length 48), the CRC-32 of the\n"
      "payload, then the fields below. A field's highest value (`0xFFFF` for a uint16, `0x7FFF`\n"
      "for an int16, ...) means \"not available\" and reads as `std::nullopt`. Physical value =\n"
      "wire value / divisor.\n\n"
      "| Field | Name | JSON key | Offset | Wire type | Divisor | Allowed |\n"
      "|---|---|---|---|---|---|---|\n");
  table_context c;
  std::printf("%s\n", rows_of<anello::sensor_frame_raw>(c).c_str());
}

// ---------------------------------------------------------------------------------------------
// NMEA 2000, from the PGN tables

template <class T>
struct n2k_kind {
  static constexpr int value = 0;
};
template <unsigned B, bool S, nmea2000::resolution R, unsigned N>
struct n2k_kind<nmea2000::number<B, S, R, N>> {
  static constexpr int value = 1;
};
template <class E, unsigned B>
struct n2k_kind<nmea2000::lookup<E, B>> {
  static constexpr int value = 2;
  using enum_type = E;
};
template <class E, unsigned B>
struct n2k_kind<nmea2000::flags<E, B>> {
  static constexpr int value = 3;
  using enum_type = E;
};

template <class V>
std::string exact_text(std::int64_t raw) {
  return number(*V::from_raw(raw).exact());
}

// "0 `sea`, 1 `outside`, ..." for a lookup, "bit 0 `check_engine`, ..." for flags.
template <class E>
std::string names_of(bool bits) {
  std::string s;
  const auto names = lookup_names(E{});
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i].empty()) continue;
    s += (s.empty() ? "" : ", ") + std::string(bits ? "bit " : "") + std::to_string(i) + " " +
         quoted(names[i]);
  }
  return s;
}

template <class V>
std::string n2k_form(std::string& step, std::string& range) {
  constexpr int kind = n2k_kind<V>::value;
  if constexpr (kind == 1) {
    step = exact_text<V>(1);
    range = exact_text<V>(V::min_raw) + " to " + exact_text<V>(V::max_valid_raw);
    return std::string(V::is_signed ? "signed" : "unsigned") + " number";
  } else if constexpr (kind == 2) {
    range = names_of<typename n2k_kind<V>::enum_type>(false);
    return "lookup";
  } else if constexpr (kind == 3) {
    range = names_of<typename n2k_kind<V>::enum_type>(true);
    return "flag set (`[]` when none is set, `null` when not sent)";
  } else if constexpr (nmea2000::text_value<V>) {
    if constexpr (V::variable) {
      range = "up to " + std::to_string(V::capacity) + " bytes";
      return "counted string: a length byte (itself, the next byte and the text), 1 ASCII or 0 "
             "UTF-16, the text; JSON a string, `null` when empty";
    } else {
      range = std::to_string(V::capacity) + " characters";
      return std::string("fixed string, one byte a character, padded with ") +
             (V::padding == '@' ? "'@'" : "0xFF") + "; JSON a string, `null` when empty";
    }
  } else if constexpr (std::is_same_v<V, nmea2000::day_count>) {
    step = "1 day";
    range = "1970-01-01 to 2149-06-03";
    return "date, days since 1970-01-01, JSON `\"YYYY-MM-DD\"`";
  } else if constexpr (std::is_same_v<V, nmea2000::time_since_midnight>) {
    step = "0.0001 s";
    range =
        "00:00:00.0000 to 24:00:01.0000 (a leap second); later times as sent, to "
        "119:18:16.7292";
    return "UTC time of day, JSON `\"hh:mm:ss.ffff\"`";
  } else if constexpr (nmea2000::detail::is_opaque_bytes<V>) {
    range = "up to " + std::to_string(V::capacity) + " bytes";
    return "bytes to the end of the payload, as sent; JSON a string of hex digits, two a byte";
  } else {
    static_assert(!sizeof(V), "messages_doc: say what this PGN field holds");
  }
}

template <class P>
void pgn() {
  constexpr auto& d = seawire::nmea2000::pgn_table<P>;
  const auto& info = d.info;
  std::printf("### PGN %u %s\n\n", unsigned{info.pgn}, std::string(info.title).c_str());
  std::printf("`%s`: ", std::string(info.name).c_str());
  if (d.has_group || (d.fixed_layout && d.length != d.bit_length / 8)) {  // a group, or bytes
    std::printf("up to ");
  } else if (d.min_length != d.length) {
    std::printf("%zu to ", d.min_length);
  }
  std::printf("%zu bytes, %s, default priority %u", d.length,
              info.transport == nmea2000::framing::fast_packet ? "fast packet" : "single frame",
              unsigned{info.priority});
  if (info.interval_ms != 0) std::printf(", sent every %u ms", unsigned{info.interval_ms});
  std::printf(". JSON `\"type\":\"PGN%u\"`.\n\n", unsigned{info.pgn});
  d.for_each([](const auto& f, unsigned, std::uint16_t) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (requires { F::is_match; }) {
      std::printf(
          "This is the PGN's layout for the messages whose `%s` is `\"%s\"` (%lld): a "
          "receiver gives it those; encode refuses another value there.\n\n",
          std::string(f.name).c_str(),
          std::string(F::value_type::from_raw(F::match_raw).name()).c_str(),
          static_cast<long long>(F::match_raw));
    }
  });
  std::printf(
      "| Field | Name (JSON key) | Standard name | Bit offset | Bits | Holds | Step | Values |\n"
      "|---|---|---|---|---|---|---|---|\n");
  table_context c;
  std::printf("%s\n", rows_of<P>(c).c_str());
}

template <class... P>
void pgns(nmea2000::pgn_list<P...>*) {
  std::printf(
      "## NMEA 2000 PGNs\n\n"
      "Fields are little-endian and packed least significant bit first from the bit offset. A\n"
      "number's physical value is its raw value times the step, in the unit its name ends with.\n"
      "The highest raw values of a field are not values: in a number of 8 bits or more the top\n"
      "one means \"not available\" (JSON `null`, an empty optional), the next \"out of range\"\n"
      "and the third \"reserved\" (JSON `\"out_of_range\"`, `\"reserved\"`); a number of 4 to 7\n"
      "bits has the first two, of 2 or 3 bits only \"not available\". A lookup has all three\n"
      "above 2 bits and the first two of 2 bits (3 and 2, as J1939 and canboat read a two-bit\n"
      "state). The Values column gives the range left for values. A lookup value without a name\n"
      "is written as its number. A flag set has no such value: all ones is every flag.\n"
      "A message may be shorter than its PGN (a sender leaves trailing fields out): a field it\n"
      "does not hold in full is not available, `null`, a flag set too (not `[]`, which says no\n"
      "flag is set); encoding leaves a flag set that is not available out, with every field\n"
      "after it, which must be not available too. A longer message (fields a newer sender\n"
      "appends) is read for the fields here, the rest ignored.\n\n");
  (pgn<P>(), ...);
}

}  // namespace

int main() {
  std::printf(
      "# Messages\n\n"
      "Every message seawire decodes and encodes, generated from the descriptions in the headers\n"
      "(`tests/docs/messages_doc.cpp`; the test `docs_messages_current` fails when this file\n"
      "is out of date). Regenerate with `build/<dir>/tests/seawire_messages_doc > "
      "docs/messages.md`.\n\n"
      "Columns: **Field** is the wire field number after the address (errors name the same\n"
      "numbers; a field that spans two wire fields, such as a position and its hemisphere, has\n"
      "both). **C++ member** is the struct member the field reads into, **JSON key** the key\n"
      "seawire-decode and `nmea::write_json` write it under, and the name errors and\n"
      "`field_name` give; they differ where a short member has a spelled-out key (a\n"
      "position: `lat` is written as `latitude`, in signed decimal degrees).\n"
      "**Blank** says whether an empty field is accepted (it reads as `std::nullopt`).\n"
      "**Present** says when a field may be missing from the sentence altogether.\n"
      "**Precision** is the number of fraction digits `nmea::builder` rounds a\n"
      "double to by default (its shortest decimal, halves away from zero: 1.005 at 2 is\n"
      "1.01).\n\n");
  registry::for_each_role([](const auto& role) {
    set(role.title, role.about,
        static_cast<typename std::remove_cvref_t<decltype(role)>::set*>(nullptr));
  });
  frame();
  pgns(static_cast<registry::pgns*>(nullptr));
  return 0;
}
