// SPDX-License-Identifier: BSL-1.0
#pragma once
// From CAN log lines to NMEA 2000 messages: each line parsed (log.hpp), frames of fast-packet PGNs
// assembled (fast_packet.hpp), and every complete message handed to a callback with its header
// and payload. Which PGNs travel as fast packets, and how long their payloads may be, comes from
// the PGN set (`Pgns`, the ANELLO inputs by default); frames of any other PGN are passed on one by
// one as single-frame messages. A canboat FAST line is a whole payload and is passed on as it is.
// Fixed memory: the assembler's slots (Slots x 240 bytes) and one parsed line.

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "seawire/error.hpp"
#include "seawire/nmea2000/fast_packet.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/nmea2000/pgns.hpp"

namespace seawire::nmea2000 {

template <class Pgns = ins_input_pgns, std::size_t Slots = 16>
class log_reader {
 public:
  /// Reads one log line (of format `format`, or detected) and calls
  /// fn(const message_header&, std::span<const std::uint8_t> payload) when it completes a message.
  /// Returns the line's parse result: ok, empty_input for a blank line, or the error and the
  /// token (`field`, log_field_name(value, field)) and byte column; value = the line's format.
  template <class Fn>
  constexpr result<log_format> read_line(std::string_view line, Fn&& fn,
                                         std::optional<log_format> format = std::nullopt) {
    record_ = format ? parse_log_line(line, *format) : parse_log_line(line);
    result<log_format> r{record_.value.format, record_.ec, record_.field, record_.column};
    if (!record_) return r;
    const log_record& rec = record_.value;
    const auto info = Pgns::info(rec.id.pgn);
    if (!rec.assembled && info && info->transport == framing::fast_packet) {
      const auto done = assembler_.feed(rec.id, rec.data(), Pgns::length(rec.id.pgn));
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

  /// Drops unfinished fast packets (at the end of a log; counted as missing_frame).
  constexpr void flush() noexcept { assembler_.flush(); }
  [[nodiscard]] constexpr const fast_packet_assembler<Slots>& assembler() const noexcept {
    return assembler_;
  }

 private:
  result<log_record> record_;
  fast_packet_assembler<Slots> assembler_;
};

}  // namespace seawire::nmea2000
