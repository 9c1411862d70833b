// SPDX-License-Identifier: BSL-1.0
#pragma once
// error_text(): an error from decoding a line told for people, in the caller's buffer, the same
// everywhere: which sentence, which field by number, name and part, the text it held, why (what
// in the text is wrong, where the codec can tell) and the range or form the field allows:
//   PYDIR field 1 (thrust_left) "150": value outside the range the spec allows: -100..100
// No allocation: the text is cut to the buffer and always NUL-terminated.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "seawire/detail/ascii.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"

namespace seawire::nmea {

namespace detail {

/// Appends to a caller's buffer, keeping one byte for the terminating NUL; cuts what does not
/// fit.
class text_out {
 public:
  constexpr explicit text_out(std::span<char> out) noexcept
      : out_(out), sink_(out.data(), out.empty() ? out.data() : out.data() + out.size() - 1) {}
  constexpr text_out& put(std::string_view s) noexcept {
    sink_.put(s);
    return *this;
  }
  constexpr text_out& put(std::uint64_t v) noexcept {
    json_uint(sink_, v);
    return *this;
  }
  constexpr text_out& put(const decimal& d) noexcept {
    json_decimal(sink_, d);
    return *this;
  }
  constexpr text_out& hex(std::uint8_t b) noexcept {
    sink_.put(seawire::detail::hex_digit_upper(b >> 4U));
    sink_.put(seawire::detail::hex_digit_upper(b & 0x0FU));
    return *this;
  }
  /// The text, NUL-terminated in the buffer.
  [[nodiscard]] constexpr std::string_view view() noexcept {
    if (out_.empty()) return {};
    *sink_.end() = '\0';
    return {out_.data(), static_cast<std::size_t>(sink_.end() - out_.data())};
  }

 private:
  std::span<char> out_;
  range_sink sink_;
};

/// The range or form a field allows, after an error about its value.
constexpr void put_allowed(text_out& t, errc e, const field_options& o) noexcept {
  if (e == errc::out_of_range) {
    if (o.has_min && o.has_max) {
      t.put(": ").put(o.min).put("..").put(o.max);
      if (o.max_exclusive) t.put(" (").put(o.max).put(" excluded)");
    } else if (o.has_min) {
      t.put(": at least ").put(o.min);
    } else if (o.has_max) {
      t.put(o.max_exclusive ? ": below " : ": at most ").put(o.max);
    }
    if (o.max_places >= 0)
      t.put(", at most ").put(static_cast<std::uint64_t>(o.max_places)).put(" fraction digits");
  } else if (e == errc::bad_length) {
    if (o.min_length == o.max_length) {
      t.put(": exactly ").put(std::uint64_t{o.min_length}).put(" characters");
    } else if (o.max_length != 0xFFFF) {
      t.put(": ").put(std::uint64_t{o.min_length}).put(" to ");
      t.put(std::uint64_t{o.max_length}).put(" characters");
    }
  } else if (e == errc::bad_unit && o.unit != 0) {
    t.put(": the unit is ").put(std::string_view(&o.unit, 1));
  }
}

/// " (sent 0a, computed 67)", the sent digits' case kept; ": written in decimal?" when they read
/// as the computed checksum in decimal.
constexpr void put_checksum(text_out& t, std::string_view line, const sentence_view& s) noexcept {
  const std::size_t star = line.find('*');
  std::string_view sent =
      star == std::string_view::npos ? std::string_view{} : line.substr(star + 1);
  if (sent.size() > 2) sent = sent.substr(0, 2);
  t.put(" (sent ");
  if (sent.size() == 2)
    t.put(sent);
  else
    t.hex(s.received_checksum);
  t.put(", computed ").hex(s.computed_checksum);
  if (written_in_decimal(sent, s.computed_checksum)) t.put(": written in decimal?");
  t.put(")");
}

template <class About>
constexpr std::string_view error_text_with(std::span<char> out, errc e, std::uint16_t field,
                                           std::uint16_t column, std::string_view line,
                                           const parse_policy& policy, About&& about) noexcept {
  text_out t(out);
  if (e == errc::ok) return t.put("ok").view();
  // The sentence as far as it splits, to name it and quote its field.
  parse_policy lax = policy;
  lax.checksum = checksum_policy::ignore;
  lax.max_length = 0xFFFF;
  const result<sentence_view> s = parse(line, lax);
  const bool framing =
      (e >= errc::empty_input && e <= errc::too_long) || e == errc::trailing_characters;
  if (!framing && s && field == 0) return t.put(s.value.address).put(": ").put(message(e)).view();
  if (field == 0 || !s) {
    t.put(message(e));
    if (e == errc::checksum_mismatch && s) put_checksum(t, line, s.value);
    if (e == errc::trailing_characters && column < line.size()) {
      // What stands after the checksum but the line ending; non-printable bytes as \xHH.
      std::string_view rest = line.substr(column);
      if (rest.ends_with("\r\n"))
        rest.remove_suffix(2);
      else if (rest.ends_with('\n') || rest.ends_with('\r'))
        rest.remove_suffix(1);
      t.put(" (\"");
      for (const char c : rest) {
        if (seawire::detail::is_printable(c) && c != '"' && c != '\\')
          t.put(std::string_view(&c, 1));
        else
          t.put("\\x").hex(static_cast<std::uint8_t>(c));
      }
      t.put("\")");
    }
    return t.put(" at column ").put(std::uint64_t{column}).view();
  }
  const field_about a = about(s.value.address, field, s.value.field_count);
  t.put(s.value.address).put(" field ").put(std::uint64_t{field});
  if (a.found) {
    t.put(" (").put(a.name);
    if (!a.part.empty()) t.put("'s ").put(a.part);
    t.put(")");
  }
  const field_token tok = s.value.field(field);
  if (tok.present) t.put(" \"").put(tok.text).put("\"");
  // What the text shows is wrong, where the field's codec can tell; else the error's words.
  const std::string_view why = a.explain != nullptr ? a.explain(a.part_index, e, tok.text) : "";
  if (!why.empty()) return t.put(": ").put(why).view();
  t.put(": ").put(message(e));
  if (a.found) put_allowed(t, e, a.opts);
  return t.view();
}

}  // namespace detail

/// An error from decoding `line` as T, for people, into `out` (cut to fit, NUL-terminated; the
/// view is into `out`). `policy`: the one the line was decoded with (it decides the split).
template <message_like T, class R>
constexpr std::string_view error_text(std::span<char> out, const result<R>& r,
                                      std::string_view line,
                                      const parse_policy& policy = {}) noexcept {
  return detail::error_text_with(
      out, r.ec, r.field, r.column, line, policy,
      [](std::string_view, std::size_t n, std::size_t count) { return about_field<T>(n, count); });
}

/// The same for a message set's decode: the field is named by the message the address selects.
template <class Set, class R>
requires requires { Set::size; }
constexpr std::string_view error_text(std::span<char> out, const result<R>& r,
                                      std::string_view line,
                                      const parse_policy& policy = {}) noexcept {
  return detail::error_text_with(out, r.ec, r.field, r.column, line, policy,
                                 [](std::string_view address, std::size_t n, std::size_t count) {
                                   return Set::about_field(address, n, count);
                                 });
}

}  // namespace seawire::nmea
