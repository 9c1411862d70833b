// SPDX-License-Identifier: BSL-1.0
#pragma once
// Text logs of NMEA 2000 traffic, each read and written: candump -L (candump_log), candump's
// screen output, canboat PLAIN/FAST lines, Yacht Devices RAW (yd_raw), Actisense N2K ASCII
// (actisense_n2k_ascii); parse_log_line() tells them apart by their shape. A frame of 0 to 8 data
// bytes, or a whole message (canboat FAST, Actisense); '#' lines are comments, canboat's
// `# format=NAME` header included. Timestamps in microseconds: Unix time (UTC), or of the day for
// yd_raw and Actisense. Examples, the timestamp forms read and the canboat rules:
// docs/nmea2000.md.

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "seawire/detail/ascii.hpp"
#include "seawire/detail/calendar.hpp"
#include "seawire/detail/enum_names.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/text.hpp"
#include "seawire/nmea2000/can_id.hpp"
#include "seawire/nmea2000/fast_packet.hpp"

namespace seawire::nmea2000 {

enum class log_format : std::uint8_t {
  candump_log,          ///< candump -L: "(1502984866.953084) can0 09F50374#001200FFFF00FFFF"
  candump,              ///< candump's screen output: "  can0  09F8027F   [8]  00 FC FF ..."
  canboat,              ///< canboat PLAIN/FAST: "2016-04-09T16:41:39.628Z,2,127489,16,255,8,..."
  yd_raw,               ///< Yacht Devices RAW: "21:55:35.925 R 19F51323 20 0E FF FF"
  actisense_n2k_ascii,  ///< Actisense N2K ASCII: "A000057.086 13FF2 1F112 005679FF7FFF7FFD"
};
inline constexpr std::size_t log_format_count = 5;

// A template of nothing, so that only a caller reads the enumerators' names (at compile time).
template <int = 0>
[[nodiscard]] constexpr std::string_view name(log_format f) noexcept {
  return seawire::detail::enumerator_name_of<log_format_count>(f);
}

/// The format called `text` (as name() spells it), or nullopt. (A template of nothing, as name().)
template <int = 0>
[[nodiscard]] constexpr std::optional<log_format> log_format_named(std::string_view text) noexcept {
  for (std::size_t i = 0; i < log_format_count; ++i)
    if (name(static_cast<log_format>(i)) == text) return static_cast<log_format>(i);
  return std::nullopt;
}

/// canboat's names for the line formats of its logs: what a `# format=NAME` header line (which
/// canboat's loggers write first) and analyzer's -format option say the lines are.
enum class canboat_format : std::uint8_t {
  plain,           ///< PLAIN: every line is one CAN frame (at most 8 bytes)
  fast,            ///< FAST: every line is one whole message, whatever its length
  plain_or_fast,   ///< PLAIN_OR_FAST: frames until a line of more than 8 bytes, whole messages
                   ///< from that line on (what canboat assumes of a log without a header whose
                   ///< first line has at most 8 bytes; one whose first line is longer is FAST)
  plain_mix_fast,  ///< PLAIN_MIX_FAST: a line of at most 8 bytes is a frame, a longer one a
                   ///< whole message
  ydwg02,          ///< YDWG02: Yacht Devices RAW lines (log_format::yd_raw)
  // canboat formats seawire does not read:
  airmar,       ///< AIRMAR
  chetco,       ///< CHETCO ($PCDIN sentences)
  garmin_csv1,  ///< GARMIN_CSV1
  garmin_csv2,  ///< GARMIN_CSV2
  // read again:
  actisense_n2k_ascii,  ///< ACTISENSE_N2K_ASCII: Actisense's N2K ASCII lines, whole messages
};
inline constexpr std::size_t canboat_format_count = 10;

/// The name canboat gives `f` ("PLAIN_OR_FAST").
[[nodiscard]] constexpr std::string_view name(canboat_format f) noexcept {
  switch (f) {
    case canboat_format::plain: return "PLAIN";
    case canboat_format::fast: return "FAST";
    case canboat_format::plain_or_fast: return "PLAIN_OR_FAST";
    case canboat_format::plain_mix_fast: return "PLAIN_MIX_FAST";
    case canboat_format::ydwg02: return "YDWG02";
    case canboat_format::airmar: return "AIRMAR";
    case canboat_format::chetco: return "CHETCO";
    case canboat_format::garmin_csv1: return "GARMIN_CSV1";
    case canboat_format::garmin_csv2: return "GARMIN_CSV2";
    case canboat_format::actisense_n2k_ascii: return "ACTISENSE_N2K_ASCII";
  }
  return "PLAIN";
}

/// Whether seawire reads logs of canboat format `f` (the first five and ACTISENSE_N2K_ASCII).
[[nodiscard]] constexpr bool is_readable(canboat_format f) noexcept {
  return f <= canboat_format::ydwg02 || f == canboat_format::actisense_n2k_ascii;
}

/// The log_format of lines of canboat format `f` (canboat, yd_raw for YDWG02,
/// actisense_n2k_ascii); nullopt for a format seawire does not read.
[[nodiscard]] constexpr std::optional<log_format> log_format_of(canboat_format f) noexcept {
  if (!is_readable(f)) return std::nullopt;
  if (f == canboat_format::ydwg02) return log_format::yd_raw;
  if (f == canboat_format::actisense_n2k_ascii) return log_format::actisense_n2k_ascii;
  return log_format::canboat;
}

/// What every canboat log header starts with.
inline constexpr std::string_view format_header_prefix = "# format=";

/// Whether `line` is a comment of a log: its first character is '#'. canboat's programs skip
/// them; `# format=NAME` is one that says what the lines after it are (parse_format_header).
[[nodiscard]] constexpr bool is_log_comment(std::string_view line) noexcept {
  return !line.empty() && line.front() == '#';
}

/// The canboat format called `text` (in any case: "fast" is FAST), or nullopt.
[[nodiscard]] constexpr std::optional<canboat_format> canboat_format_named(
    std::string_view text) noexcept {
  for (std::size_t i = 0; i < canboat_format_count; ++i) {
    const auto f = static_cast<canboat_format>(i);
    const std::string_view n = name(f);
    bool same = n.size() == text.size();
    for (std::size_t k = 0; same && k < n.size(); ++k) {
      const char c = text[k];
      same = (c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c) == n[k];
    }
    if (same) return f;
  }
  return std::nullopt;
}

/// The format a header line `# format=NAME` names (NAME in any case; a trailing CR/LF ignored).
/// bad_log_line (field 0) for a line that is no such header; unknown_log_format, with `field` 1
/// and `column` 9 (where NAME starts), for a NAME canboat has no format of
/// (canboat_format_named() says so), and for a format of canboat's that seawire does not read
/// (value = that format; is_readable() says which).
[[nodiscard]] constexpr result<canboat_format> parse_format_header(std::string_view line) noexcept {
  while (!line.empty() &&
         (line.back() == '\n' || line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
    line.remove_suffix(1);
  result<canboat_format> r;
  if (!line.starts_with(format_header_prefix)) {
    r.ec = errc::bad_log_line;
    return r;
  }
  const auto f = canboat_format_named(line.substr(format_header_prefix.size()));
  if (f) r.value = *f;
  if (!f || !is_readable(*f)) {
    r.ec = errc::unknown_log_format;
    r.field = 1;
    r.column = static_cast<std::uint16_t>(format_header_prefix.size());
  }
  return r;
}

/// canboat's pseudo-PGNs: numbers from 0x40000 (262144) up, past every 18-bit PGN, that a gateway
/// or one of canboat's converters gives messages of its own that never crossed the bus: canboat
/// numbers them 0x40000-0x402FF (an Actisense NGT-1's operating mode and counters from 0x40000,
/// iKonvert's from 0x40100, its own tools' from 0x40200), and logs of its Actisense reader hold
/// others still (an empty "...,0,16057090,255,1,0"). canboat's loggers write them as canboat
/// lines among the bus's messages, always whole ("...,0,262386,0,0,33,01,0e,..."), and its
/// analyzer reads such a line without an error; an Actisense N2K ASCII line could name one of
/// canboat's range in its five hex digits ("40100"). No CAN identifier carries one, so no candump
/// or Yacht Devices line can. parse_log_line() reads them (a record no CAN identifier carries:
/// write_log_line() refuses it, bad_can_id): from a canboat line any number of 32 bits; from an
/// Actisense line canboat's range only (the format's own PGNs are 18-bit, and no gateway
/// writes another there). log_reader skips and counts them.
inline constexpr std::uint32_t first_pseudo_pgn = 0x40000;
/// The last of the numbers canboat reserves for them.
inline constexpr std::uint32_t last_canboat_pseudo_pgn = 0x402FF;

/// Whether `pgn` is past every 18-bit PGN: a pseudo-PGN (see first_pseudo_pgn).
[[nodiscard]] constexpr bool is_pseudo_pgn(std::uint32_t pgn) noexcept {
  return pgn >= first_pseudo_pgn;
}

/// One line of a log: a CAN frame, or (canboat FAST, Actisense) a whole fast-packet payload.
struct log_record {
  log_format format = log_format::candump_log;
  can_id id;
  std::optional<std::int64_t> time_us;  ///< see the top of this file for what it counts from
  nmea::text<15> interface;             ///< candump formats: the CAN interface ("can0")
  char direction = 'R';                 ///< yd_raw: 'R' received, 'T' transmitted
  /// data is a whole message (a canboat FAST line, every Actisense line), not a frame.
  /// parse_log_line() takes a canboat line of more than 8 bytes for one (PLAIN_MIX_FAST);
  /// log_reader also follows the log's format header and canboat's rule for a log without one
  /// (canboat_format).
  bool assembled = false;
  std::array<std::uint8_t, max_fast_packet_length> bytes{};
  std::uint8_t size = 0;

  [[nodiscard]] constexpr std::span<const std::uint8_t> data() const noexcept {
    return {bytes.data(), size};
  }
  /// Copies `d` (at most 223 bytes; false and nothing copied otherwise).
  constexpr bool assign(std::span<const std::uint8_t> d) noexcept {
    if (d.size() > bytes.size()) return false;
    for (std::size_t i = 0; i < d.size(); ++i) bytes[i] = d[i];
    size = static_cast<std::uint8_t>(d.size());
    return true;
  }
};

/// The name of token `field` of a line of format `f`, as parse errors number them.
[[nodiscard]] constexpr std::string_view log_field_name(log_format f,
                                                        std::uint16_t field) noexcept {
  constexpr std::string_view candump_log[] = {"line", "timestamp", "interface", "frame"};
  constexpr std::string_view candump[] = {"line", "interface", "identifier", "length", "data"};
  constexpr std::string_view canboat[] = {"line",   "timestamp",   "priority", "pgn",
                                          "source", "destination", "length",   "data"};
  constexpr std::string_view yd_raw[] = {"line", "time", "direction", "identifier", "data"};
  constexpr std::string_view actisense[] = {"line", "time", "address", "pgn", "data"};
  const auto pick = [&](std::span<const std::string_view> names) {
    return field < names.size() ? names[field] : names.back();
  };
  switch (f) {
    case log_format::candump_log: return pick(candump_log);
    case log_format::candump: return pick(candump);
    case log_format::canboat: return pick(canboat);
    case log_format::yd_raw: return pick(yd_raw);
    case log_format::actisense_n2k_ascii: return pick(actisense);
  }
  return "line";
}

namespace detail {

class log_cursor {
 public:
  constexpr explicit log_cursor(std::string_view line) noexcept : s_(line) {}
  [[nodiscard]] constexpr std::size_t pos() const noexcept { return i_; }
  [[nodiscard]] constexpr bool done() const noexcept { return i_ >= s_.size(); }
  [[nodiscard]] constexpr char peek() const noexcept { return done() ? '\0' : s_[i_]; }
  constexpr bool skip_spaces() noexcept {
    const std::size_t at = i_;
    while (!done() && (s_[i_] == ' ' || s_[i_] == '\t')) ++i_;
    return i_ != at;
  }
  constexpr bool eat(char c) noexcept {
    if (peek() != c || done()) return false;
    ++i_;
    return true;
  }
  /// Characters up to (not including) one of `stops` or the end.
  constexpr std::string_view until(std::string_view stops) noexcept {
    const std::size_t at = i_;
    while (!done() && stops.find(s_[i_]) == std::string_view::npos) ++i_;
    return s_.substr(at, i_ - at);
  }

 private:
  std::string_view s_;
  std::size_t i_ = 0;
};

/// An unsigned decimal of 1-18 digits.
[[nodiscard]] constexpr bool parse_uint(std::string_view t, std::uint64_t& out) noexcept {
  if (t.empty() || t.size() > 18) return false;
  std::uint64_t v = 0;
  for (const char c : t) {
    if (!seawire::detail::is_digit(c)) return false;
    v = v * 10 + static_cast<std::uint64_t>(c - '0');
  }
  out = v;
  return true;
}

/// Hex of 1-8 digits.
[[nodiscard]] constexpr bool parse_hex(std::string_view t, std::uint32_t& out) noexcept {
  if (t.empty() || t.size() > 8) return false;
  std::uint32_t v = 0;
  for (const char c : t) {
    const int h = seawire::detail::hex_value(c);
    if (h < 0) return false;
    v = v << 4 | static_cast<std::uint32_t>(h);
  }
  out = v;
  return true;
}

/// "sec[.frac]" as microseconds (fraction digits past 6 are cut).
[[nodiscard]] constexpr bool parse_seconds(std::string_view t, std::int64_t& us) noexcept {
  const std::size_t dot = t.find('.');
  std::uint64_t sec = 0;
  if (!parse_uint(t.substr(0, dot), sec) || sec > 9'000'000'000'000ULL) return false;
  std::uint64_t frac = 0;
  if (dot != std::string_view::npos) {
    const std::string_view f = t.substr(dot + 1);
    if (f.empty()) return false;
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (!seawire::detail::is_digit(f[i])) return false;
      if (i < 6) frac = frac * 10 + static_cast<std::uint64_t>(f[i] - '0');
    }
    for (std::size_t i = f.size(); i < 6; ++i) frac *= 10;
  }
  us = static_cast<std::int64_t>(sec * 1'000'000 + frac);
  return true;
}

/// Two-digit number at t[i].
[[nodiscard]] constexpr int two_digits(std::string_view t, std::size_t i) noexcept {
  if (i + 2 > t.size() || !seawire::detail::is_digit(t[i]) || !seawire::detail::is_digit(t[i + 1]))
    return -1;
  return (t[i] - '0') * 10 + (t[i + 1] - '0');
}

/// "hh:mm:ss[.f...]" at the start of t as microseconds of the day; the characters used.
[[nodiscard]] constexpr std::size_t parse_clock(std::string_view t, std::int64_t& us) noexcept {
  const int h = two_digits(t, 0);
  const int m = two_digits(t, 3);
  const int s = two_digits(t, 6);
  if (h < 0 || m < 0 || s < 0 || t[2] != ':' || t[5] != ':' || h > 23 || m > 59 || s > 60) return 0;
  std::size_t i = 8;
  std::int64_t frac = 0;
  if (i < t.size() && t[i] == '.') {
    ++i;
    std::size_t digits = 0;
    for (; i < t.size() && seawire::detail::is_digit(t[i]); ++i, ++digits)
      if (digits < 6) frac = frac * 10 + (t[i] - '0');
    if (digits == 0) return 0;
    for (; digits < 6; ++digits) frac *= 10;
  }
  us = ((std::int64_t{h} * 60 + m) * 60 + s) * 1'000'000 + frac;
  return i;
}

/// canboat's timestamps: YYYY-MM-DD[T or -]hh:mm:ss[.f...][Z | +hh:mm | -hh:mm | +hhmm].
[[nodiscard]] constexpr std::optional<std::int64_t> parse_canboat_time(
    std::string_view t) noexcept {
  seawire::detail::civil_date ymd;
  if (t.size() < 19 || (t[10] != 'T' && t[10] != '-' && t[10] != ' ') ||
      !seawire::detail::parse_iso_date(t, ymd) || !seawire::detail::valid_date(ymd))
    return std::nullopt;
  std::int64_t clock = 0;
  const std::size_t used = parse_clock(t.substr(11), clock);
  if (used == 0) return std::nullopt;
  std::size_t i = 11 + used;
  std::int64_t offset_us = 0;
  if (i < t.size()) {
    if (t[i] == 'Z' && i + 1 == t.size()) {
      ++i;
    } else if (t[i] == '+' || t[i] == '-') {
      const int sign = t[i] == '-' ? -1 : 1;
      const int oh = two_digits(t, i + 1);
      const std::size_t mi = i + 3 < t.size() && t[i + 3] == ':' ? i + 4 : i + 3;
      const int om = two_digits(t, mi);
      if (oh < 0 || om < 0 || oh > 23 || om > 59 || mi + 2 != t.size()) return std::nullopt;
      offset_us = sign * (std::int64_t{oh} * 60 + om) * 60 * 1'000'000;
      i = t.size();
    }
    if (i != t.size()) return std::nullopt;
  }
  const std::int64_t days = seawire::detail::days_from_civil(ymd);
  const std::int64_t us = days * 86'400'000'000 + clock - offset_us;
  // Unix time from 1970 to the end of year 9999: what the writers can write back.
  if (us < 0 || us >= 253'402'300'800'000'000) return std::nullopt;
  return us;
}

/// Up to `max` hex byte tokens separated by `sep` (' ' or ','); false on a bad token.
template <bool Spaced>
[[nodiscard]] constexpr bool parse_byte_tokens(log_cursor& c, log_record& r,
                                               std::size_t max) noexcept {
  r.size = 0;
  while (true) {
    if constexpr (Spaced) {
      c.skip_spaces();
      if (c.done()) return true;
    } else {
      if (c.done()) return true;
      if (!c.eat(',')) return false;
    }
    const std::string_view tok = c.until(Spaced ? " \t" : ",");
    std::uint32_t v = 0;
    // Two hex digits; canboat lines may have one (canboat writes and reads "0" for 00)
    const bool size_ok = tok.size() == 2 || (!Spaced && tok.size() == 1);
    if (!size_ok || !parse_hex(tok, v) || r.size >= max) return false;
    r.bytes[r.size++] = static_cast<std::uint8_t>(v);
  }
}

/// The CAN identifier text `t` (8 hex digits, a 29-bit identifier) into r.id.
[[nodiscard]] constexpr errc parse_identifier(std::string_view t, log_record& r) noexcept {
  std::uint32_t raw = 0;
  if (t.size() != 8 || !parse_hex(t, raw)) return errc::bad_can_id;
  const result<can_id> id = parse_can_id(raw);
  if (!id) return id.ec;
  r.id = id.value;
  return errc::ok;
}

constexpr std::string_view trim_line_end(std::string_view line) noexcept {
  while (!line.empty() &&
         (line.back() == '\n' || line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
    line.remove_suffix(1);
  return line;
}

[[nodiscard]] constexpr result<log_record> log_fail(const log_record& r, errc e,
                                                    std::uint16_t field,
                                                    std::size_t column) noexcept {
  return {r, e, field, static_cast<std::uint16_t>(column > 0xFFFF ? 0xFFFF : column)};
}

/// "(sec.usec)" at the cursor into r.time_us; false when it is not that.
[[nodiscard]] constexpr bool parse_paren_time(log_cursor& c, log_record& r) noexcept {
  if (!c.eat('(')) return false;
  const std::string_view ts = c.until(")");
  std::int64_t us = 0;
  if (!c.eat(')') || !parse_seconds(ts, us)) return false;
  r.time_us = us;
  return true;
}

constexpr result<log_record> parse_candump_log(std::string_view line) noexcept {
  log_record r;
  r.format = log_format::candump_log;
  log_cursor c(line);
  c.skip_spaces();
  std::size_t at = c.pos();
  if (c.peek() != '(') return log_fail(r, errc::bad_log_line, 1, at);
  if (!parse_paren_time(c, r)) return log_fail(r, errc::bad_time, 1, at);
  c.skip_spaces();
  at = c.pos();
  const std::string_view iface = c.until(" \t");
  if (iface.empty() || !r.interface.assign(iface)) return log_fail(r, errc::bad_log_line, 2, at);
  c.skip_spaces();
  at = c.pos();
  const std::string_view id = c.until("#");
  if (!c.eat('#')) return log_fail(r, errc::bad_log_line, 3, at);
  if (const errc e = parse_identifier(id, r); e != errc::ok) return log_fail(r, e, 3, at);
  const std::size_t data_at = c.pos();
  if (c.peek() == 'R' || c.peek() == '#')  // remote request or CAN FD: not NMEA 2000 data
    return log_fail(r, errc::bad_log_line, 3, data_at);
  const std::string_view hex = c.until(" \t");
  if (hex.size() % 2 != 0 || hex.size() > 16) return log_fail(r, errc::bad_length, 3, data_at);
  for (std::size_t i = 0; i < hex.size(); i += 2) {
    std::uint32_t v = 0;
    if (!parse_hex(hex.substr(i, 2), v)) return log_fail(r, errc::bad_number, 3, data_at + i);
    r.bytes[r.size++] = static_cast<std::uint8_t>(v);
  }
  c.skip_spaces();
  at = c.pos();
  if (!c.done()) {  // newer can-utils: " R" / " T"
    const std::string_view dir = c.until(" \t");
    c.skip_spaces();
    if ((dir != "R" && dir != "T") || !c.done()) return log_fail(r, errc::bad_log_line, 3, at);
    r.direction = dir[0];
  }
  return {r, errc::ok, 0, 0};
}

constexpr result<log_record> parse_candump(std::string_view line) noexcept {
  log_record r;
  r.format = log_format::candump;
  log_cursor c(line);
  c.skip_spaces();
  std::size_t at = c.pos();
  if (c.peek() == '(') {  // candump -t a: (1700000000.123456)
    if (!parse_paren_time(c, r)) return log_fail(r, errc::bad_time, 1, at);
    c.skip_spaces();
    at = c.pos();
  }
  const std::string_view iface = c.until(" \t");
  if (iface.empty() || !r.interface.assign(iface)) return log_fail(r, errc::bad_log_line, 1, at);
  c.skip_spaces();
  at = c.pos();
  if (const errc e = parse_identifier(c.until(" \t"), r); e != errc::ok)
    return log_fail(r, e, 2, at);
  c.skip_spaces();
  at = c.pos();
  std::uint64_t dlc = 0;
  if (!c.eat('[')) return log_fail(r, errc::bad_log_line, 3, at);
  if (!parse_uint(c.until("]"), dlc) || !c.eat(']') || dlc > 8)
    return log_fail(r, errc::bad_length, 3, at);
  at = c.pos();
  if (!parse_byte_tokens<true>(c, r, 8)) return log_fail(r, errc::bad_number, 4, at);
  if (r.size != dlc) return log_fail(r, errc::bad_length, 4, at);
  return {r, errc::ok, 0, 0};
}

constexpr result<log_record> parse_canboat(std::string_view line) noexcept {
  log_record r;
  r.format = log_format::canboat;
  log_cursor c(line);
  r.time_us = parse_canboat_time(c.until(","));
  std::uint64_t v[5] = {};
  for (std::uint16_t k = 0; k < 5; ++k) {
    const std::size_t at = c.pos();
    if (!c.eat(',')) return log_fail(r, errc::bad_log_line, static_cast<std::uint16_t>(k + 2), at);
    if (!parse_uint(c.until(","), v[k]))
      return log_fail(r, errc::bad_number, static_cast<std::uint16_t>(k + 2), at + 1);
  }
  const std::size_t at = c.pos();
  if (v[0] > 7) return log_fail(r, errc::bad_can_id, 2, at);
  if (v[1] > 0xFFFFFFFFU) return log_fail(r, errc::bad_can_id, 3, at);  // past 18: pseudo-PGN
  if (v[2] > 255) return log_fail(r, errc::bad_can_id, 4, at);
  if (v[3] > 255) return log_fail(r, errc::bad_can_id, 5, at);
  if (v[4] > max_fast_packet_length) return log_fail(r, errc::bad_length, 6, at);
  r.id.priority = static_cast<std::uint8_t>(v[0]);
  r.id.pgn = static_cast<std::uint32_t>(v[1]);
  r.id.source = static_cast<std::uint8_t>(v[2]);
  r.id.destination = is_addressed(r.id.pgn) || is_pseudo_pgn(r.id.pgn)
                         ? static_cast<std::uint8_t>(v[3])
                         : broadcast_address;
  if (!parse_byte_tokens<false>(c, r, max_fast_packet_length))
    return log_fail(r, errc::bad_number, 7, at);
  if (r.size != v[4]) return log_fail(r, errc::bad_length, 7, at);
  r.assembled = r.size > 8;
  return {r, errc::ok, 0, 0};
}

constexpr result<log_record> parse_yd_raw(std::string_view line) noexcept {
  log_record r;
  r.format = log_format::yd_raw;
  log_cursor c(line);
  c.skip_spaces();
  std::size_t at = c.pos();
  std::int64_t us = 0;
  const std::string_view clock = c.until(" \t");
  if (parse_clock(clock, us) != clock.size()) return log_fail(r, errc::bad_time, 1, at);
  r.time_us = us;
  c.skip_spaces();
  at = c.pos();
  const std::string_view dir = c.until(" \t");
  if (dir != "R" && dir != "T") return log_fail(r, errc::bad_log_line, 2, at);
  r.direction = dir[0];
  c.skip_spaces();
  at = c.pos();
  if (const errc e = parse_identifier(c.until(" \t"), r); e != errc::ok)
    return log_fail(r, e, 3, at);
  at = c.pos();
  if (!parse_byte_tokens<true>(c, r, 8)) return log_fail(r, errc::bad_number, 4, at);
  return {r, errc::ok, 0, 0};
}

/// "Ahhmmss[.f...]" (the A included) as microseconds of the day; false when it is not that.
[[nodiscard]] constexpr bool parse_actisense_time(std::string_view t, std::int64_t& us) noexcept {
  if (t.size() < 7 || t[0] != 'A') return false;
  const int h = two_digits(t, 1);
  const int m = two_digits(t, 3);
  const int s = two_digits(t, 5);
  if (h < 0 || m < 0 || s < 0 || h > 23 || m > 59 || s > 60) return false;
  std::int64_t frac = 0;
  if (t.size() > 7) {
    const std::string_view f = t.substr(8);
    if (t[7] != '.' || f.empty()) return false;
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (!seawire::detail::is_digit(f[i])) return false;
      if (i < 6) frac = frac * 10 + (f[i] - '0');
    }
    for (std::size_t i = f.size(); i < 6; ++i) frac *= 10;
  }
  us = ((std::int64_t{h} * 60 + m) * 60 + s) * 1'000'000 + frac;
  return true;
}

// Actisense N2K ASCII: "A<hhmmss.ddd> <SSDDP> <PGN> <data>", the address token five hex digits
// (source, destination, priority), the PGN in hex, the whole message's bytes as hex without
// spaces.
constexpr result<log_record> parse_actisense_n2k_ascii(std::string_view line) noexcept {
  log_record r;
  r.format = log_format::actisense_n2k_ascii;
  r.assembled = true;
  log_cursor c(line);
  c.skip_spaces();
  std::size_t at = c.pos();
  std::int64_t us = 0;
  if (!parse_actisense_time(c.until(" \t"), us)) return log_fail(r, errc::bad_time, 1, at);
  r.time_us = us;
  c.skip_spaces();
  at = c.pos();
  std::uint32_t address = 0;
  const std::string_view sdp = c.until(" \t");
  if (sdp.size() != 5 || !parse_hex(sdp, address)) return log_fail(r, errc::bad_can_id, 2, at);
  c.skip_spaces();
  at = c.pos();
  std::uint32_t pgn = 0;
  const std::string_view pgn_text = c.until(" \t");
  if (pgn_text.size() > 5 || !parse_hex(pgn_text, pgn)) return log_fail(r, errc::bad_can_id, 3, at);
  const auto priority = static_cast<std::uint8_t>(address & 0xF);
  if (priority > 7 || (pgn > max_pgn && pgn > last_canboat_pseudo_pgn))
    return log_fail(r, errc::bad_can_id, priority > 7 ? 2 : 3, at);
  r.id.priority = priority;
  r.id.pgn = pgn;
  r.id.source = static_cast<std::uint8_t>(address >> 12);
  r.id.destination = is_addressed(pgn) || is_pseudo_pgn(pgn)
                         ? static_cast<std::uint8_t>(address >> 4 & 0xFF)
                         : broadcast_address;
  c.skip_spaces();
  at = c.pos();
  const std::string_view hex = c.until(" \t");
  c.skip_spaces();
  if (!c.done()) return log_fail(r, errc::bad_log_line, 4, c.pos());
  if (hex.size() % 2 != 0 || hex.size() > 2 * max_fast_packet_length)
    return log_fail(r, errc::bad_length, 4, at);
  for (std::size_t i = 0; i < hex.size(); i += 2) {
    std::uint32_t v = 0;
    if (!parse_hex(hex.substr(i, 2), v)) return log_fail(r, errc::bad_number, 4, at + i);
    r.bytes[r.size++] = static_cast<std::uint8_t>(v);
  }
  return {r, errc::ok, 0, 0};
}

}  // namespace detail

/// One line of a log in format `f` (a trailing CR/LF is ignored).
[[nodiscard]] constexpr result<log_record> parse_log_line(std::string_view line,
                                                          log_format f) noexcept {
  line = detail::trim_line_end(line);
  switch (f) {
    case log_format::candump_log: return detail::parse_candump_log(line);
    case log_format::candump: return detail::parse_candump(line);
    case log_format::canboat: return detail::parse_canboat(line);
    case log_format::yd_raw: return detail::parse_yd_raw(line);
    case log_format::actisense_n2k_ascii: return detail::parse_actisense_n2k_ascii(line);
  }
  return {};
}

/// The format a line looks like, or nullopt for a line of none (see the top of this file).
[[nodiscard]] constexpr std::optional<log_format> detect_log_format(
    std::string_view line) noexcept {
  std::size_t i = 0;
  while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
  if (line.size() - i >= 2 && line[i] == 'A' && seawire::detail::is_digit(line[i + 1]))
    return log_format::actisense_n2k_ascii;
  if (line.find('#') != std::string_view::npos) return log_format::candump_log;
  if (line.find('[') != std::string_view::npos) return log_format::candump;
  if (line.find(',') != std::string_view::npos) return log_format::canboat;
  if (line.size() - i >= 8 && line[i + 2] == ':' && line[i + 5] == ':' &&
      seawire::detail::is_digit(line[i]))
    return log_format::yd_raw;
  return std::nullopt;
}

/// One line of a log of any format, detected per line. empty_input for a blank line,
/// bad_log_line (field 0) for a line of no known shape.
[[nodiscard]] constexpr result<log_record> parse_log_line(std::string_view line) noexcept {
  line = detail::trim_line_end(line);
  if (line.find_first_not_of(" \t") == std::string_view::npos) return {{}, errc::empty_input, 0, 0};
  const auto f = detect_log_format(line);
  if (!f) return {{}, errc::bad_log_line, 0, 0};
  return parse_log_line(line, *f);
}

// ---------------------------------------------------------------------------------------------
// writing

namespace detail {

template <class Sink>
constexpr void put_hex_byte(Sink& s, std::uint8_t b, bool upper) noexcept {
  constexpr std::string_view lower = "0123456789abcdef";
  constexpr std::string_view higher = "0123456789ABCDEF";
  const std::string_view digits = upper ? higher : lower;
  s.put(digits[b >> 4]);
  s.put(digits[b & 0xF]);
}

using seawire::detail::put_uint;

/// "(sec.usec)", as candump writes its times.
template <class Sink>
constexpr void put_paren_time(Sink& s, std::int64_t us) noexcept {
  s.put('(');
  put_uint(s, static_cast<std::uint64_t>(us / 1'000'000));
  s.put('.');
  put_uint(s, static_cast<std::uint64_t>(us % 1'000'000), 6);
  s.put(')');
}

template <class Sink>
constexpr void put_can_id(Sink& s, std::uint32_t id) noexcept {
  for (int shift = 24; shift >= 0; shift -= 8)
    put_hex_byte(s, static_cast<std::uint8_t>(id >> shift), true);
}

template <class Sink>
constexpr void put_clock(Sink& s, std::int64_t us_of_day, unsigned places) noexcept {
  const auto us = static_cast<std::uint64_t>(us_of_day);
  if (us >= 86'400'000'000) {  // a leap second: 23:59:60.xxx
    s.put("23:59:");
    put_uint(s, 60 + (us - 86'400'000'000) / 1'000'000 % 60, 2);
  } else {
    put_uint(s, us / 3'600'000'000, 2);
    s.put(':');
    put_uint(s, us / 60'000'000 % 60, 2);
    s.put(':');
    put_uint(s, us / 1'000'000 % 60, 2);
  }
  if (places > 0) {
    s.put('.');
    put_uint(s, us % 1'000'000 / seawire::detail::pow10_table[6 - places], places);
  }
}

}  // namespace detail

/// Writes `r` as one line of format `f`, ending in LF. A record holding more than 8 bytes (a
/// whole fast packet) can only be written as canboat (FAST) or Actisense; bad_length for the
/// other formats: split it into frames first (split_fast_packet). Every Actisense line is read
/// back as a whole message. bad_can_id when r.id cannot be an identifier.
/// candump writes the time first, as `candump -t a` does, when there is one. A missing time is
/// written as 0 (candump_log, yd_raw) or 1970-01-01 (canboat); yd_raw
/// and Actisense keep the time of day of a Unix time, and canboat writes a time of day as a time
/// on 1970-01-01. Milliseconds are written, or microseconds when the time has them, except by
/// yd_raw and Actisense (milliseconds, as the gateways write).
template <class Sink>
constexpr errc write_log_line(Sink& s, const log_record& r, log_format f) noexcept {
  if (r.size > 8 && f != log_format::canboat && f != log_format::actisense_n2k_ascii)
    return errc::bad_length;
  const result<std::uint32_t> id = make_can_id(r.id);
  if (!id) return id.ec;
  const std::int64_t time = r.time_us.value_or(0) < 0 ? 0 : r.time_us.value_or(0);
  const unsigned places = time % 1000 == 0 ? 3 : 6;
  const std::string_view iface =
      r.interface.size() == 0 ? std::string_view("can0") : r.interface.view();
  switch (f) {
    case log_format::candump_log:
      detail::put_paren_time(s, time);
      s.put(' ');
      s.put(iface);
      s.put(' ');
      detail::put_can_id(s, id.value);
      s.put('#');
      for (const std::uint8_t b : r.data()) detail::put_hex_byte(s, b, true);
      break;
    case log_format::candump:
      if (r.time_us) detail::put_paren_time(s, time);  // as candump -t a prints it
      s.put("  ");
      s.put(iface);
      s.put("  ");
      detail::put_can_id(s, id.value);
      s.put("   [");
      detail::put_uint(s, r.size);
      s.put("] ");
      for (const std::uint8_t b : r.data()) {
        s.put(' ');
        detail::put_hex_byte(s, b, true);
      }
      break;
    case log_format::canboat: {
      const auto days = std::chrono::sys_days(std::chrono::days(time / 86'400'000'000));
      const std::chrono::year_month_day ymd(days);
      detail::put_uint(s, static_cast<std::uint64_t>(static_cast<int>(ymd.year())), 4);
      s.put('-');
      detail::put_uint(s, static_cast<unsigned>(ymd.month()), 2);
      s.put('-');
      detail::put_uint(s, static_cast<unsigned>(ymd.day()), 2);
      s.put('T');
      detail::put_clock(s, time % 86'400'000'000, places);
      s.put("Z,");
      detail::put_uint(s, r.id.priority);
      s.put(',');
      detail::put_uint(s, r.id.pgn);
      s.put(',');
      detail::put_uint(s, r.id.source);
      s.put(',');
      detail::put_uint(s, r.id.destination);
      s.put(',');
      detail::put_uint(s, r.size);
      for (const std::uint8_t b : r.data()) {
        s.put(',');
        detail::put_hex_byte(s, b, false);
      }
      break;
    }
    case log_format::yd_raw:
      // A time of day (below 86 401 s, a leap second included) as it is; a Unix time's of day.
      detail::put_clock(s, time < 86'401'000'000 ? time : time % 86'400'000'000, 3);
      s.put(' ');
      s.put(r.direction == 'T' ? 'T' : 'R');
      s.put(' ');
      detail::put_can_id(s, id.value);
      for (const std::uint8_t b : r.data()) {
        s.put(' ');
        detail::put_hex_byte(s, b, true);
      }
      break;
    case log_format::actisense_n2k_ascii: {
      s.put('A');
      const std::int64_t of_day = time < 86'401'000'000 ? time : time % 86'400'000'000;
      const auto clock = static_cast<std::uint64_t>(of_day);
      if (clock >= 86'400'000'000) {  // a leap second
        s.put("235960");
      } else {
        detail::put_uint(s, clock / 3'600'000'000, 2);
        detail::put_uint(s, clock / 60'000'000 % 60, 2);
        detail::put_uint(s, clock / 1'000'000 % 60, 2);
      }
      s.put('.');
      detail::put_uint(s, clock % 1'000'000 / 1000, 3);
      s.put(' ');
      detail::put_hex_byte(s, r.id.source, true);
      detail::put_hex_byte(s, r.id.destination, true);
      s.put(seawire::detail::hex_digit_upper(r.id.priority));
      s.put(' ');
      s.put(seawire::detail::hex_digit_upper(r.id.pgn >> 16 & 0xF));
      detail::put_hex_byte(s, static_cast<std::uint8_t>(r.id.pgn >> 8), true);
      detail::put_hex_byte(s, static_cast<std::uint8_t>(r.id.pgn), true);
      s.put(' ');
      for (const std::uint8_t b : r.data()) detail::put_hex_byte(s, b, true);
      break;
    }
  }
  s.put('\n');
  return errc::ok;
}

}  // namespace seawire::nmea2000
