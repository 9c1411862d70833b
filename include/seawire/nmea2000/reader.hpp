// SPDX-License-Identifier: BSL-1.0
#pragma once
// From CAN log lines to NMEA 2000 messages: each line parsed (log.hpp), fast-packet PGNs
// assembled, every complete message handed to a callback with its header and payload; canboat
// `# format=` headers followed, else canboat's own FAST detection (docs/nmea2000.md). A PGN's
// framing is the one `Pgns` declares for it, else the standard's (is_fast_packet_pgn,
// fast_packets.hpp), so a PGN without a description comes whole too. Lines of canboat's
// pseudo-PGNs (a gateway's own messages, log.hpp) are skipped and counted. Fixed memory: the
// assembler's slots and one parsed line.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "seawire/error.hpp"
#include "seawire/nmea2000/fast_packet.hpp"
#include "seawire/nmea2000/fast_packets.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/nmea2000/pgns.hpp"

namespace seawire::nmea2000 {

template <class Pgns = ins_input_pgns, std::size_t Slots = 16>
class log_reader {
 public:
  /// Reads one log line (of format `format`, else of the format the log's header fixed, else
  /// detected) and calls fn(const message_header&, std::span<const std::uint8_t> payload) when it
  /// completes a message. Returns the line's parse result: ok (a header line too), empty_input
  /// for a blank line or a comment, or the error and the token (`field`,
  /// log_field_name(value, field)) and byte column; value = the line's format. A header naming a
  /// format seawire does not read is unknown_log_format (the format in force is kept); a line
  /// of more than 8 bytes in a PLAIN log is bad_length (field 6, the length). A line of a
  /// pseudo-PGN is ok, fn not called: it is counted (pseudo_pgn_lines()) and says nothing of how
  /// the log's canboat lines are written (a gateway writes its own messages whole in any log).
  template <class Fn>
  constexpr result<log_format> read_line(std::string_view line, Fn&& fn,
                                         std::optional<log_format> format = std::nullopt) {
    const std::string_view text = detail::trim_line_end(line);
    if (text.find_first_not_of(" \t") == std::string_view::npos)
      return {format.value_or(fixed_.value_or(log_format::candump_log)), errc::empty_input, 0, 0};
    if (is_log_comment(text)) {
      const result<canboat_format> h = parse_format_header(text);
      if (h.ec == errc::bad_log_line) return {log_format::canboat, errc::empty_input, 0, 0};
      if (!h) return {log_format::canboat, h.ec, h.field, h.column};
      fixed_ = log_format_of(h.value);
      if (h.value != canboat_format::ydwg02) canboat_ = h.value;
      return {*fixed_, errc::ok, 0, 0};
    }
    if (!format) format = fixed_;
    record_ = format ? parse_log_line(text, *format) : parse_log_line(text);
    result<log_format> r{record_.value.format, record_.ec, record_.field, record_.column};
    if (!record_) return r;
    log_record& rec = record_.value;
    if (is_pseudo_pgn(rec.id.pgn)) {
      ++pseudo_pgn_lines_;
      return r;
    }
    if (rec.format == log_format::canboat) {
      if (!canboat_) canboat_ = rec.size > 8 ? canboat_format::fast : canboat_format::plain_or_fast;
      if (*canboat_ == canboat_format::plain_or_fast && rec.size > 8)
        canboat_ = canboat_format::fast;
      if (*canboat_ == canboat_format::plain && rec.size > 8) {
        std::size_t column = 0;  // of the length: after the fifth comma
        for (int commas = 0; column < text.size() && commas < 5; ++column)
          if (text[column] == ',') ++commas;
        r.ec = errc::bad_length;
        r.field = 6;
        r.column = static_cast<std::uint16_t>(column);
        return r;
      }
      rec.assembled =
          *canboat_ == canboat_format::fast || (*canboat_ != canboat_format::plain && rec.size > 8);
    }
    if (!rec.assembled && is_fast(rec.id.pgn)) {
      const auto done = assembler_.feed(rec.id, rec.data());
      if (done) {
        message_header h = header_of(rec);
        h.id = done->id;
        fn(static_cast<const message_header&>(h), done->payload);
      }
      return r;
    }
    fn(static_cast<const message_header&>(header_of(rec)), rec.data());
    return r;
  }

  /// The format the log's last readable header fixed for lines read without one given (canboat,
  /// or yd_raw for YDWG02); nullopt before any.
  [[nodiscard]] constexpr std::optional<log_format> header_format() const noexcept {
    return fixed_;
  }

  /// How canboat lines are read now: the log's header, or what its first canboat line made of a
  /// log without one; nullopt before either.
  [[nodiscard]] constexpr std::optional<canboat_format> canboat_lines() const noexcept {
    return canboat_;
  }

  /// Lines of canboat's pseudo-PGNs skipped so far.
  [[nodiscard]] constexpr std::uint64_t pseudo_pgn_lines() const noexcept {
    return pseudo_pgn_lines_;
  }

  /// Whether frames of `pgn` are assembled: as `Pgns` declares the PGN, else as the standard
  /// lists it (is_fast_packet_pgn).
  [[nodiscard]] static constexpr bool is_fast(std::uint32_t pgn) noexcept {
    const auto info = Pgns::info(pgn);
    return info ? info->transport == framing::fast_packet : is_fast_packet_pgn(pgn);
  }

  /// Drops unfinished fast packets (at the end of a log; counted as missing_frame).
  constexpr void flush() noexcept { assembler_.flush(); }
  [[nodiscard]] constexpr const fast_packet_assembler<Slots>& assembler() const noexcept {
    return assembler_;
  }

 private:
  result<log_record> record_;
  fast_packet_assembler<Slots> assembler_;
  std::optional<log_format> fixed_;        ///< the format the log's header fixed
  std::optional<canboat_format> canboat_;  ///< how canboat lines are read
  std::uint64_t pseudo_pgn_lines_ = 0;
};

}  // namespace seawire::nmea2000
