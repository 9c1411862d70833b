// SPDX-License-Identifier: BSL-1.0
// Writes docs/enums.md: every public enum of the library, each enumerator with its value on the
// wire (a letter, a word, a number) or, for an enum that is not a wire field, its underlying
// value, and the comment its header gives it. The enumerators are read from the enums
// themselves (the compiler names an enumerator in a function template's signature, as
// nmea/enum.hpp does for letters), so a value added to an enum is a row added here; the
// docs_enums_current test fails until the file is regenerated, and docs_enums_listed fails when
// a header declares an enum this program does not list. The enums of the messages' fields are
// found by walking every field of every message of seawire/registry.hpp, which also gives the
// fields each is in: a message added to the registry brings its enums here.

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "seawire/detail/enum_names.hpp"
#include "seawire/seawire.hpp"

#ifndef SEAWIRE_SOURCE_DIR
#error "SEAWIRE_SOURCE_DIR: the source tree, to read the enumerators' comments from"
#endif

namespace {

using namespace seawire;

[[noreturn]] void fail(std::string_view what, std::string_view detail) {
  std::fprintf(stderr, "enums_doc: %.*s: %.*s\n", static_cast<int>(what.size()), what.data(),
               static_cast<int>(detail.size()), detail.data());
  std::exit(1);
}

// The template argument `parameter` stands for in a __PRETTY_FUNCTION__ ("V = ...;" or "V =
// ...]", as GCC and Clang write them).
std::string_view argument(std::string_view signature, std::string_view parameter) {
  const std::size_t at = signature.find(std::string(parameter) + " = ");
  if (at == std::string_view::npos) fail("no template argument in", signature);
  const std::string_view rest = signature.substr(at + parameter.size() + 3);
  return rest.substr(0, rest.find_first_of(";]"));
}

// E's name as the compiler writes it, for an error message.
template <class E>
std::string_view typeid_name() {
  return __PRETTY_FUNCTION__;
}

struct row {
  std::string name;
  unsigned value = 0;
  std::string meaning;  ///< when the header has no enumerator to take it from
};

// The names of the values V... of E, in order, empty for a value that is no enumerator: one
// listing of them all (the library's reading of the compiler's signature,
// detail/enum_names.hpp), not one instantiation per value. nullopt when the listing cannot be
// read.
template <class E, auto... V>
constexpr std::optional<std::array<std::string_view, sizeof...(V)>> names_of() {
  std::array<std::string_view, sizeof...(V)> names{};
  std::size_t i = 0;
  const std::size_t listed = seawire::detail::for_each_listed(
      seawire::detail::enum_listing<static_cast<E>(V)...>(), [&](std::string_view e) {
        if (i < names.size()) names[i] = seawire::detail::listed_name(e);
        ++i;
      });
  if (listed != sizeof...(V) || i != sizeof...(V)) return std::nullopt;
  return names;
}

template <class E, auto... V>
std::vector<row> rows_of(std::integer_sequence<std::underlying_type_t<E>, V...>) {
  static constexpr auto names = names_of<E, V...>();
  if (!names) fail("cannot read the compiler's listing of", typeid_name<E>());
  const std::underlying_type_t<E> values[] = {V...};
  std::vector<row> out;
  for (std::size_t i = 0; i < names->size(); ++i)
    if (!(*names)[i].empty())
      out.push_back({std::string((*names)[i]), static_cast<unsigned>(values[i]), {}});
  return out;
}

// Every enumerator of E: letters and digits for a letter enum, else the values 0..127 (every
// enum here counts from 0, and none has more).
template <class E>
std::vector<row> enumerators() {
  using U = std::underlying_type_t<E>;
  if constexpr (std::is_same_v<U, char>) {
    std::vector<row> out;
    const auto all = rows_of<E>(std::make_integer_sequence<char, 127>{});
    for (const row& r : all)
      if (r.value >= 0x20) out.push_back(r);
    return out;
  } else if constexpr (std::is_same_v<U, bool>) {
    return rows_of<E>(std::integer_sequence<bool, false, true>{});
  } else {
    return rows_of<E>(std::make_integer_sequence<U, 128>{});
  }
}

// The comment an enumerator has in its header: the "///<" text after it, with the lines that
// continue it.
std::string comment_of(const std::string& header, std::string_view type, std::string_view name) {
  std::ifstream in(std::string(SEAWIRE_SOURCE_DIR) + "/include/seawire/" + header);
  if (!in) fail("cannot read", header);
  std::stringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  const std::size_t decl = text.find("enum class " + std::string(type) + " ");
  if (decl == std::string::npos) fail("no declaration of", type);
  const std::size_t end = text.find("};", decl);
  std::size_t at = decl;
  for (;;) {
    at = text.find(name, at + 1);
    if (at == std::string::npos || at > end) return {};
    const char before = text[at - 1];
    const char after = text[at + name.size()];
    if ((before == ' ' || before == '{' || before == '\n') &&
        (after == ' ' || after == ',' || after == '\n' || after == '}'))
      break;
  }
  std::string out;
  std::size_t line_end = text.find('\n', at);
  std::size_t c = text.find("///<", at);
  // Only a comment on the enumerator's own line (or one the next lines continue).
  while (c != std::string::npos && c < line_end) {
    std::string piece = text.substr(c + 4, line_end - c - 4);
    while (!piece.empty() && piece.front() == ' ') piece.erase(0, 1);
    out += (out.empty() ? "" : " ") + piece;
    const std::size_t next_end = text.find('\n', line_end + 1);
    const std::string next = text.substr(line_end + 1, next_end - line_end - 1);
    const std::size_t first = next.find_first_not_of(' ');
    if (first == std::string::npos || next.compare(first, 4, "///<") != 0) break;
    c = line_end + 1 + first;
    line_end = next_end;
  }
  std::string escaped;
  for (const char ch : out) escaped += ch == '|' ? std::string("\\|") : std::string(1, ch);
  return escaped;
}

enum class kind { letter, word, lookup, text, value };

std::string code(std::string_view s) { return "`" + std::string(s) + "`"; }

template <class E>
void table(std::string_view qualified, const std::string& header, std::string_view about, kind k,
           std::vector<std::string> spelled = {}) {
  std::vector<row> rows = enumerators<E>();
  // A lookup that declares its values only (the manufacturer codes, up to 2047): its names by
  // value, the standard's texts as their meaning.
  if constexpr (nmea2000::named_enum<E> && requires { lookup_titles(E{}); }) {
    if (rows.empty()) {
      const auto names = lookup_names(E{});
      const auto titles = lookup_titles(E{});
      for (std::size_t i = 0; i < names.size(); ++i)
        if (!names[i].empty())
          rows.push_back({std::string(names[i]), static_cast<unsigned>(i), std::string(titles[i])});
    }
  }
  if (rows.empty()) fail("no enumerators found for", qualified);
  const std::string_view type = qualified.substr(qualified.rfind("::") + 2);
  std::printf("### `%.*s`\n\n`seawire/%s`. %.*s\n\n", static_cast<int>(qualified.size()),
              qualified.data(), header.c_str(), static_cast<int>(about.size()), about.data());
  const char* value_column = "Value";
  switch (k) {
    case kind::letter: value_column = "Wire letter"; break;
    case kind::word: value_column = "Wire word"; break;
    case kind::lookup: value_column = "Wire number | JSON name"; break;
    case kind::text: value_column = "Wire text"; break;
    case kind::value: value_column = "Value"; break;
  }
  std::printf("| Enumerator | %s | Meaning |\n|---|---|%s---|\n", value_column,
              k == kind::lookup ? "---|" : "");
  for (const row& r : rows) {
    std::string v;
    switch (k) {
      case kind::letter: v = code(std::string(1, static_cast<char>(r.value))); break;
      case kind::word:
        if constexpr (nmea::word_enum_like<E>) v = code(nmea::to_string(static_cast<E>(r.value)));
        break;
      case kind::lookup: {
        v = std::to_string(r.value) + " | ";
        if constexpr (nmea2000::named_enum<E>) {
          const auto names = lookup_names(E{});
          if (r.value < names.size()) v += code(names[r.value]);
        }
        break;
      }
      case kind::text:
        v = r.value < spelled.size() && !spelled[r.value].empty() ? code(spelled[r.value]) : "";
        break;
      case kind::value: v = std::to_string(r.value); break;
    }
    std::printf("| `%s` | %s | %s |\n", r.name.c_str(), v.c_str(),
                r.meaning.empty() ? comment_of(header, type, r.name).c_str() : r.meaning.c_str());
  }
  std::printf("\n");
}

// BFMIS's status texts, by the state bfmis::state() reads each as.
std::vector<std::string> mission_texts() {
  std::vector<std::string> out(32);
  for (const std::string_view t :
       {"Offline", "Waiting", "Invalid Dive File", "Invalid Wrapup File", "Ready", "Running",
        "WrappingUp", "Aborting", "Completed", "Aborted", "Stopped"}) {
    sandshark::bfmis m;
    if (!m.status.assign(t)) fail("mission text", t);
    const auto s = static_cast<std::size_t>(m.state());
    out[s] = std::string(t) + (t == "Running" ? " [log directory]" : "");
  }
  out[static_cast<std::size_t>(sandshark::mission_state::unknown)] = "";  // any other text
  return out;
}

template <class T>
std::string_view type_signature() {
  return __PRETTY_FUNCTION__;
}

// T's name with its namespaces ("seawire::standard::rmc_status"), as the compiler spells it.
template <class T>
std::string qualified_name() {
  return std::string(argument(type_signature<T>(), "T"));
}

// The header under include/seawire/<namespace>/ that declares `enum class <name>`.
std::string header_of(const std::string& qualified) {
  const std::size_t first = qualified.find("::");
  const std::size_t last = qualified.rfind("::");
  const std::string dir = qualified.substr(first + 2, last - first - 2);
  const std::string decl = "enum class " + qualified.substr(last + 2) + " ";
  const std::string root = std::string(SEAWIRE_SOURCE_DIR) + "/include/seawire/";
  for (const auto& entry : std::filesystem::directory_iterator(root + dir)) {
    std::ifstream in(entry.path());
    std::stringstream all;
    all << in.rdbuf();
    if (all.str().find(decl) != std::string::npos)
      return dir + "/" + entry.path().filename().string();
  }
  fail("no header declares", qualified);
}

// An enum some registry message has as a field, and where: each message with its field numbers
// ("RSA" 2 and 4, "PGN 128259" 4).
struct wire_enum {
  std::string qualified;
  std::vector<std::pair<std::string, std::vector<std::string>>> uses;
  std::function<void(const wire_enum&)> print;
};

// "RSA fields 2 and 4, ..."
std::string uses_text(const wire_enum& w) {
  std::string out;
  for (const auto& [message, fields] : w.uses) {
    out += (out.empty() ? "" : "; ") + message + (fields.size() == 1 ? " field " : " fields ");
    for (std::size_t i = 0; i < fields.size(); ++i)
      out += (i == 0 ? "" : i + 1 == fields.size() ? " and " : ", ") + fields[i];
  }
  return out + ".";
}

template <class E>
void add_use(std::vector<wire_enum>& out, const std::string& message, const std::string& field,
             kind k) {
  const std::string q = qualified_name<E>();
  for (wire_enum& w : out) {
    if (w.qualified != q) continue;
    if (w.uses.back().first == message) {
      w.uses.back().second.push_back(field);
    } else {
      w.uses.push_back({message, {field}});
    }
    return;
  }
  out.push_back({q, {{message, {field}}}, [k](const wire_enum& w) {
                   table<E>(w.qualified, header_of(w.qualified), uses_text(w), k);
                 }});
}

// Every enum the registry's sentences and PGNs have as a field, in registry order.
std::vector<wire_enum> wire_enums() {
  std::vector<wire_enum> out;
  registry::for_each_type<registry::sentences>([&](auto tag) {
    using M = typename decltype(tag)::type;
    const std::string address(M::nmea.address);
    unsigned first = 1;
    M::nmea.fields.apply([&](const auto&... d) {
      (
          [&](const auto& f) {
            using V = typename std::remove_cvref_t<decltype(f)>::value_type;
            const std::string message = address.substr(address.starts_with("--") ? 2 : 0);
            if constexpr (nmea::char_enum_like<V>) {
              add_use<V>(out, message, std::to_string(first), kind::letter);
            } else if constexpr (nmea::word_enum_like<V>) {
              add_use<V>(out, message, std::to_string(first), kind::word);
            } else if constexpr (std::is_same_v<V, robotx::light_pattern>) {
              // A light pattern is three colour letters in one field.
              add_use<robotx::color>(out, message, std::to_string(first) + " (three letters)",
                                     kind::letter);
            }
            first += f.width();
          }(d),
          ...);
    });
  });
  registry::for_each_type<registry::pgns>([&](auto tag) {
    using P = typename decltype(tag)::type;
    seawire::nmea2000::pgn_table<P>.for_each([&](const auto& f, unsigned, std::uint16_t row) {
      using F = std::remove_cvref_t<decltype(f)>;
      if constexpr (nmea2000::detail::group_row<F>) {
        // a repeating group's fields: numbered "row.k" as the messages' tables do
        using Item = typename F::value_type::item_type;
        Item::n2k_item.for_each([&](const auto& e, unsigned, std::uint16_t k) {
          using R = std::remove_cvref_t<decltype(e)>;
          if constexpr (!R::is_reserved) {
            using E = nmea2000::value_enum_t<typename R::value_type>;
            if constexpr (!std::is_void_v<E>) {
              add_use<E>(
                  out, "PGN " + std::to_string(seawire::nmea2000::pgn_table<P>.info.pgn),
                  std::to_string(row) + "." + std::to_string(k) + " (" + std::string(e.title) + ")",
                  kind::lookup);
            }
          }
        });
      } else if constexpr (!F::is_reserved) {
        using E = nmea2000::value_enum_t<typename F::value_type>;
        if constexpr (!std::is_void_v<E>) {
          add_use<E>(out, "PGN " + std::to_string(seawire::nmea2000::pgn_table<P>.info.pgn),
                     std::to_string(row) + " (" + std::string(f.title) + ")", kind::lookup);
        }
        // A number field whose values have titles (field<&P::m, E>).
        if constexpr (requires { typename F::titles; }) {
          add_use<typename F::titles>(
              out, "PGN " + std::to_string(seawire::nmea2000::pgn_table<P>.info.pgn),
              std::to_string(row) + " (" + std::string(f.title) + ")", kind::lookup);
        }
      }
    });
  });
  return out;
}

}  // namespace

int main() {
  std::printf(
      "# Enumerations\n\n"
      "Every public enum of the library with each of its values, generated from the enums "
      "themselves\n"
      "and the comments in their headers (`tests/docs/enums_doc.cpp`; the test "
      "`docs_enums_current`\n"
      "fails when this file is out of date, `docs_enums_listed` when a header declares an enum "
      "it\n"
      "does not list). Regenerate with `build/<dir>/tests/seawire_enums_doc > docs/enums.md`.\n\n"
      "A field's enum is written on the wire as its **wire letter** (an `enum class E : char`: "
      "the\n"
      "enumerator is the letter), its **wire word** (the enum's `enum_words`), or, in NMEA 2000, "
      "its\n"
      "**wire number** (the enumerator's value; JSON and fmt write the name). The other enums are "
      "not\n"
      "sent: their **value** is the enumerator's underlying value (stable for `errc`).\n\n");

  std::printf("## Fields of NMEA 0183 sentences\n\n");
  table<nmea::hemisphere>("seawire::nmea::hemisphere", "nmea/position.hpp",
                          "A position's or a magnetic variation's direction letter.", kind::letter);
  // The enums of the registry's messages' fields, with the fields they are in.
  const std::vector<wire_enum> fields = wire_enums();
  for (const wire_enum& w : fields)
    if (!w.uses.front().first.starts_with("PGN ")) w.print(w);
  table<sandshark::mission_state>(
      "seawire::sandshark::mission_state", "sandshark/messages.hpp",
      "BFMIS field 3 is text (the spec's list is open); `bfmis::state()` reads it as one of "
      "these.",
      kind::text, mission_texts());

  std::printf("## Fields of NMEA 2000 PGNs\n\n");
  for (const wire_enum& w : fields)
    if (w.uses.front().first.starts_with("PGN ")) w.print(w);

  std::printf("## Library enums (not on the wire)\n\n");
  table<errc>("seawire::errc", "error.hpp",
              "Why a decode or encode failed; `name(e)` gives the enumerator's name, "
              "`message(e)` a sentence.",
              kind::value);
  table<nmea::checksum_policy>("seawire::nmea::checksum_policy", "nmea/sentence.hpp",
                               "`parse_policy::checksum`.", kind::value);
  table<nmea::checksum_state>("seawire::nmea::checksum_state", "nmea/sentence.hpp",
                              "`sentence_view::checksum`.", kind::value);
  table<nmea::field_end>("seawire::nmea::field_end", "nmea/sentence.hpp",
                         "`field_reader::end_of_field()`.", kind::value);
  table<nmea::line_ending>("seawire::nmea::line_ending", "nmea/stream.hpp",
                           "`framed_line::ending`.", kind::value);
  table<nmea::stream_item_kind>("seawire::nmea::stream_item_kind", "nmea/stream.hpp",
                                "`stream_item::kind`.", kind::value);
  table<nmea::drop_reason>("seawire::nmea::drop_reason", "nmea/stream.hpp",
                           "`stream_drop::reason`; `name(r)` gives the enumerator's name.",
                           kind::value);
  table<nmea::json_style>("seawire::nmea::json_style", "nmea/json.hpp", "How `write_json` writes.",
                          kind::value);
  table<nmea::json_kind>("seawire::nmea::json_kind", "nmea/json.hpp",
                         "What a JSON reader found for a key.", kind::value);
  table<sandshark::payload_event_kind>("seawire::sandshark::payload_event_kind",
                                       "sandshark/payload_session.hpp", "`payload_event::kind`.",
                                       kind::value);
  table<sandshark::message_origin>(
      "seawire::sandshark::message_origin", "sandshark/payload_session.hpp",
      "Which part of the payload session wrote an outgoing message.", kind::value);
  table<sandshark::vehicle_event_kind>("seawire::sandshark::vehicle_event_kind",
                                       "sandshark/vehicle_session.hpp", "`vehicle_event::kind`.",
                                       kind::value);
  table<robotx::too_soon>("seawire::robotx::too_soon", "robotx/heartbeat.hpp",
                          "`scheduler_config::when_too_soon`.", kind::value);
  table<robotx::submit_status>("seawire::robotx::submit_status", "robotx/heartbeat.hpp",
                               "What `scheduler::submit` did.", kind::value);
  table<robotx::report_type>("seawire::robotx::report_type", "robotx/messages.hpp",
                             "The five RobotX report types.", kind::value);
  table<robotx::rule>("seawire::robotx::rule", "robotx/validator.hpp",
                      "What a validator finding broke; `name(r)` and `message(r)` tell it.",
                      kind::value);
  table<nmea2000::field_state>("seawire::nmea2000::field_state", "nmea2000/field.hpp",
                               "What a PGN field's raw value holds.", kind::value);
  table<nmea2000::framing>("seawire::nmea2000::framing", "nmea2000/field.hpp",
                           "How a PGN is carried: one CAN frame or a fast packet.", kind::value);
  table<nmea2000::raw_display>("seawire::nmea2000::raw_display", "nmea2000/field.hpp",
                               "How a number that is no quantity reads (canboat's JSON).",
                               kind::value);
  table<nmea2000::text_encoding>(
      "seawire::nmea2000::text_encoding", "nmea2000/field.hpp",
      "What a counted string's encoding byte says its characters are (`counted_text::control()`).",
      kind::value);
  table<nmea2000::fast_packet_drop>("seawire::nmea2000::fast_packet_drop",
                                    "nmea2000/fast_packet.hpp",
                                    "Why a fast-packet assembler dropped frames.", kind::value);
  table<nmea2000::log_format>("seawire::nmea2000::log_format", "nmea2000/log.hpp",
                              "The CAN log formats read and written.", kind::value);
  table<nmea2000::canboat_format>(
      "seawire::nmea2000::canboat_format", "nmea2000/log.hpp",
      "The formats a canboat log's `# format=` header names; the first five are read.",
      kind::value);
  table<nmea2000::canboat_display>(
      "seawire::nmea2000::canboat_display", "nmea2000/canboat.hpp",
      "How canboat's analyzer shows a number field in its std units, by the field's unit.",
      kind::value);
  table<wire_kind>("seawire::wire_kind", "walk.hpp", "Which wire a walked field is of.",
                   kind::value);
  table<byte_order>("seawire::byte_order", "walk.hpp", "How a walked field's bytes are laid out.",
                    kind::value);
  table<position_axis>("seawire::position_axis", "walk.hpp", "What a position-typed field holds.",
                       kind::value);
  return 0;
}
