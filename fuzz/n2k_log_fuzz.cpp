// SPDX-License-Identifier: BSL-1.0
// NMEA 2000 CAN log lines (candump -L, candump, canboat PLAIN/FAST, Yacht Devices RAW, Actisense
// N2K ASCII). The input
// is text cut at each LF; every line goes to parse_log_line (format detected, then each format
// named), and through two log_readers (formats detected, and the one format the first byte picks).
// Properties:
//  - a line that does not parse gives an errc, a field that log_field_name names (0, the whole
//    line, when no format was recognised) and a column inside the line;
//  - a line that parses has the format detected or asked for and fields a frame can have, or
//    (canboat and Actisense lines) one of canboat's pseudo-PGNs, a gateway's own message;
//  - write_log_line in that format writes it (the refusals: a canboat or Actisense line may
//    name an addressed PGN with a low byte, or a pseudo-PGN, which no CAN identifier carries:
//    bad_can_id), and the
//    line written parses again, in the same format and through detection, to the same record as far
//    as the format keeps it: identifier, data, FAST or not, always; the interface (candump
//    formats) and direction (yd_raw); the time: exactly (candump -L and canboat, which write
//    ms or us as the time needs; candump, which writes it as `candump -t a` when there is one),
//    to the millisecond of the day (yd_raw, Actisense); a canboat line whose timestamp did not
//    parse is
//    written as 1970-01-01T00:00:00.000Z, which reads back as time 0;
//  - writing that record again gives the same line;
//  - log_reader::read_line reads a blank line as empty input whatever the format, a comment line
//    ('#' first) as parse_format_header says (empty input for a plain comment), and until a header
//    line was read returns what parse_log_line does (after one, an error still has a place); it
//    calls back at most once per line, with the line's key and a payload no longer than 223 bytes
//    (the line's own bytes, or a fast packet its frame completed: of a PGN the reader assembles,
//    declared or on the standard's list), which decodes and encodes, and never for a line of a
//    pseudo-PGN, which it counts; its
//    assembler balances (in == assembled + dropped + pending) after every line, and has nothing
//    pending after flush.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "fuzz_common.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/can_id.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/nmea2000/reader.hpp"
#include "seawire/registry.hpp"

namespace seawire::fuzz {
namespace {

namespace n2k = nmea2000;

constexpr std::array<n2k::log_format, n2k::log_format_count> formats = {
    n2k::log_format::candump_log, n2k::log_format::candump, n2k::log_format::canboat,
    n2k::log_format::yd_raw, n2k::log_format::actisense_n2k_ascii};

constexpr std::int64_t us_per_ms = 1000;

std::string describe(const n2k::log_record& r) {
  std::string out(name(r.format));
  out += " prio " + number(r.id.priority) + " pgn " + number(r.id.pgn) + " src " +
         number(r.id.source) + " dst " + number(r.id.destination);
  out += r.time_us ? " time_us " + std::to_string(*r.time_us) : std::string(" no time");
  out += " iface '" + std::string(r.interface.view()) + "' dir ";
  out += r.direction;
  out += r.assembled ? " FAST" : "";
  out += " data";
  for (const std::uint8_t b : r.data()) {
    out += ' ';
    out += "0123456789ABCDEF"[b >> 4U];
    out += "0123456789ABCDEF"[b & 15U];
  }
  return out;
}

/// The time a line of format `f` written from `r` must read back with.
std::optional<std::int64_t> time_kept(const n2k::log_record& r, n2k::log_format f) {
  switch (f) {
    case n2k::log_format::candump_log:
    case n2k::log_format::candump: return r.time_us;
    case n2k::log_format::canboat: return r.time_us.value_or(0);
    case n2k::log_format::yd_raw:
    case n2k::log_format::actisense_n2k_ascii: return *r.time_us / us_per_ms * us_per_ms;
  }
  return std::nullopt;
}

void check_same(const n2k::log_record& was, const n2k::log_record& now, n2k::log_format f,
                std::string_view line, std::string_view written) {
  const std::optional<std::int64_t> time = time_kept(was, f);
  const bool candump_family = f == n2k::log_format::candump_log || f == n2k::log_format::candump;
  SEAWIRE_FUZZ_CHECK(now.format == f && now.id == was.id && now.assembled == was.assembled &&
                         std::ranges::equal(now.data(), was.data()),
                     "write -> parse changed the frame", line, written, describe(was),
                     describe(now));
  SEAWIRE_FUZZ_CHECK(now.time_us == time, "write -> parse changed the time", line, written,
                     describe(was), describe(now));
  SEAWIRE_FUZZ_CHECK(!candump_family || now.interface == was.interface,
                     "write -> parse changed the interface", line, written, describe(was),
                     describe(now));
  SEAWIRE_FUZZ_CHECK(f != n2k::log_format::yd_raw || now.direction == was.direction,
                     "write -> parse changed the direction", line, written, describe(was),
                     describe(now));
}

/// A record parsed from `line` as format `f` (detected when `detected`).
void check_record(const n2k::log_record& rec, n2k::log_format f, bool detected,
                  std::string_view line) {
  SEAWIRE_FUZZ_CHECK(rec.format == f, "a record of another format", line, describe(rec));
  const bool whole_messages =
      f == n2k::log_format::canboat || f == n2k::log_format::actisense_n2k_ascii;
  const bool pseudo = whole_messages && n2k::is_pseudo_pgn(rec.id.pgn);
  SEAWIRE_FUZZ_CHECK(
      rec.id.priority <= 7 && (rec.id.pgn <= n2k::max_pgn || pseudo) &&
          (n2k::is_addressed(rec.id.pgn) || pseudo ||
           rec.id.destination == n2k::broadcast_address) &&
          rec.size <= (whole_messages ? 223U : 8U) &&
          rec.assembled == (f == n2k::log_format::actisense_n2k_ascii || rec.size > 8),
      "a record no frame can have", line, describe(rec));
  // Every format but canboat carries a time that parses, or none (candump without one).
  SEAWIRE_FUZZ_CHECK(
      f == n2k::log_format::canboat || f == n2k::log_format::candump || rec.time_us.has_value(),
      "a line read without its time", line, describe(rec));

  seawire::nmea::json_buffer<1024> out;
  const errc e = n2k::write_log_line(out, rec, f);
  const bool no_identifier =
      pseudo || (whole_messages && n2k::is_addressed(rec.id.pgn) && (rec.id.pgn & 0xFFU) != 0);
  if (no_identifier) {
    SEAWIRE_FUZZ_CHECK(e == errc::bad_can_id,
                       "wrote an addressed PGN with a low byte, or a pseudo-PGN", line,
                       describe(rec), name(e));
    return;
  }
  SEAWIRE_FUZZ_CHECK(e == errc::ok && !out.overflow(), "write_log_line refused a parsed record",
                     line, describe(rec), name(e));
  const std::string_view written = out.view();
  SEAWIRE_FUZZ_CHECK(
      !written.empty() && written.back() == '\n' && written.find('\n') == written.size() - 1,
      "not one line ending in LF", line, written);

  const seawire::result<n2k::log_record> again =
      detected ? n2k::parse_log_line(written) : n2k::parse_log_line(written, f);
  SEAWIRE_FUZZ_CHECK(again.ok(), "a written line does not parse", line, written, describe(rec),
                     name(again.ec), number(again.field), number(again.column));
  check_same(rec, again.value, f, line, written);

  seawire::nmea::json_buffer<1024> twice;
  SEAWIRE_FUZZ_CHECK(
      n2k::write_log_line(twice, again.value, f) == errc::ok && twice.view() == written,
      "writing the line read back gives another line", line, written, twice.view());
}

void check_line(std::string_view line) {
  const seawire::result<n2k::log_record> r = n2k::parse_log_line(line);
  if (!r) {
    SEAWIRE_FUZZ_CHECK(r.ec != errc::ok && r.column <= line.size() &&
                           !n2k::log_field_name(r.value.format, r.field).empty(),
                       "a parse error without a place", line, name(r.ec), number(r.field),
                       number(r.column));
    if (r.ec == errc::bad_log_line && r.field == 0) {
      SEAWIRE_FUZZ_CHECK(!n2k::detect_log_format(n2k::detail::trim_line_end(line)),
                         "a line of a known shape refused as of none", line);
    }
  } else {
    check_record(r.value, r.value.format, true, line);
  }
  for (const n2k::log_format f : formats) {
    const seawire::result<n2k::log_record> as = n2k::parse_log_line(line, f);
    if (!as) {
      SEAWIRE_FUZZ_CHECK(as.ec != errc::ok && as.column <= line.size() &&
                             !n2k::log_field_name(f, as.field).empty(),
                         "a parse error without a place", line, name(f), name(as.ec),
                         number(as.field), number(as.column));
      continue;
    }
    check_record(as.value, f, false, line);
  }
}

template <class Reader>
void read_through(Reader& reader, bool& headed, std::string_view line,
                  std::optional<n2k::log_format> format) {
  int calls = 0;
  const std::string_view trimmed = n2k::detail::trim_line_end(line);
  if (trimmed.find_first_not_of(" \t") == std::string_view::npos) {
    const seawire::result<n2k::log_format> b = reader.read_line(
        line, [&](const auto&, auto) { ++calls; }, format);
    SEAWIRE_FUZZ_CHECK(b.ec == errc::empty_input && calls == 0, "a blank line not empty input",
                       line, name(b.ec));
    return;
  }
  if (n2k::is_log_comment(trimmed)) {
    const seawire::result<n2k::log_format> c = reader.read_line(
        line, [&](const auto&, auto) { ++calls; }, format);
    const seawire::result<n2k::canboat_format> h = n2k::parse_format_header(trimmed);
    SEAWIRE_FUZZ_CHECK(calls == 0, "a comment line gave a message", line);
    SEAWIRE_FUZZ_CHECK(h.ec == errc::bad_log_line ? c.ec == errc::empty_input : c.ec == h.ec,
                       "a comment or header line not read as parse_format_header says", line,
                       name(c.ec), name(h.ec));
    headed = headed || h.ok();
    return;
  }
  // The format the line is read in: the one given, else the one the log's header fixed.
  const std::optional<n2k::log_format> as = format ? format : reader.header_format();
  const seawire::result<n2k::log_record> parsed =
      as ? n2k::parse_log_line(line, *as) : n2k::parse_log_line(line);
  const std::uint64_t pseudo_before = reader.pseudo_pgn_lines();
  const seawire::result<n2k::log_format> r = reader.read_line(
      line,
      [&](const n2k::message_header& h, std::span<const std::uint8_t> payload) {
        ++calls;
        const n2k::log_record& rec = parsed.value;
        SEAWIRE_FUZZ_CHECK(h.id.pgn == rec.id.pgn && h.id.source == rec.id.source &&
                               h.id.destination == rec.id.destination && h.time_us == rec.time_us,
                           "a message of another key than its line", line);
        SEAWIRE_FUZZ_CHECK(payload.size() <= n2k::max_fast_packet_length, line);
        // The line's own bytes, or a packet its frames completed (a canboat line is a frame
        // or a whole message as the log's header or first canboat line says).
        SEAWIRE_FUZZ_CHECK(std::ranges::equal(payload, rec.data()) ||
                               (Reader::is_fast(rec.id.pgn) && rec.size <= 8),
                           "a line's own payload not passed on as it is", line);
        (void)registry::pgns::visit(h.id.pgn, payload, [&](const auto& m) {
          SEAWIRE_FUZZ_CHECK(n2k::encode(m).ok(), "a message read from a log does not encode",
                             line);
        });
      },
      format);
  if (headed) {
    // A header fixed the format (or PLAIN refuses a line of more than 8 bytes): an error still
    // has a place.
    SEAWIRE_FUZZ_CHECK(
        r.ok() || (r.column <= line.size() && !n2k::log_field_name(r.value, r.field).empty()),
        "a read error without a place", line, name(r.ec));
    SEAWIRE_FUZZ_CHECK(calls <= 1 && (r.ok() || calls == 0), "called back more than once", line);
  } else {
    SEAWIRE_FUZZ_CHECK(r.ec == parsed.ec && r.field == parsed.field && r.column == parsed.column &&
                           (!r || r.value == parsed.value.format),
                       "read_line's result is not parse_log_line's", line, name(r.ec),
                       name(parsed.ec));
    SEAWIRE_FUZZ_CHECK(calls <= 1 && (parsed.ok() || calls == 0), "called back more than once",
                       line, number(static_cast<std::uint64_t>(calls)));
  }
  // A pseudo-PGN's line: read, never passed on, counted.
  const bool pseudo = parsed.ok() && n2k::is_pseudo_pgn(parsed.value.id.pgn);
  SEAWIRE_FUZZ_CHECK(reader.pseudo_pgn_lines() == pseudo_before + (pseudo && r.ok() ? 1U : 0U) &&
                         (!pseudo || calls == 0),
                     "a pseudo-PGN's line passed on, or not counted", line);
  const auto& a = reader.assembler();
  SEAWIRE_FUZZ_CHECK(
      a.frames_in() == a.frames_assembled() + a.frames_dropped() + a.frames_pending(),
      "the reader's assembler does not balance", line);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = as_text(data, size);
  // Two slots, so that a few sources interleaving fast packets evict each other.
  n2k::log_reader<registry::pgns, 2> detecting;
  n2k::log_reader<registry::pgns, 2> fixed;
  bool detecting_headed = false;
  bool fixed_headed = false;
  const n2k::log_format fixed_format = formats[size == 0 ? 0 : data[0] % formats.size()];
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t nl = std::min(text.find('\n', at), text.size());
    const std::string_view line = text.substr(at, nl - at);
    check_line(line);
    read_through(detecting, detecting_headed, line, std::nullopt);
    read_through(fixed, fixed_headed, line, fixed_format);
    at = nl + 1;
  }
  for (auto* reader : {&detecting, &fixed}) {
    reader->flush();
    SEAWIRE_FUZZ_CHECK(reader->assembler().frames_pending() == 0, "frames pending after flush");
  }
  return 0;
}

}  // namespace seawire::fuzz
