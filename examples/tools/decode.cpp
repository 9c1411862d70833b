// SPDX-License-Identifier: BSL-1.0
// seawire-decode: NMEA-style sentences (and ANELLO 0xAB00 binary frames mixed in) on stdin ->
// one JSON object per message (or re-encoded messages, or nothing but a verdict). A thin program
// over the library: anello::stream_reader cuts the stream into sentences and frames,
// message_set::visit decodes each sentence by its address, nmea/json.hpp and
// anello/frame_json.hpp write them. See --help, and the README's seawire-decode(1) for the manual.

#include <CLI/CLI.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "io.hpp"
#include "messages.hpp"
#include "seawire/anello/frame.hpp"
#include "seawire/anello/frame_json.hpp"
#include "seawire/anello/stream.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/describe.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"
#include "seawire/version.hpp"

namespace {

using namespace seawire;
using seawire::tools::all_messages;

enum class format { json, nmea, none };

struct options {
  format fmt = format::json;
  nmea::parse_policy policy;
  bool stats = false;
  bool line_buffered = false;
};

// Rejected input shows at most this much of its line.
constexpr std::size_t max_input_shown = 256;

class decoder {
 public:
  explicit decoder(const options& o) : opt_(o), policy_(o.policy), out_(stdout) {
    // The reader has taken the line ending off: it is checked here, from what the reader saw.
    policy_.require_crlf = false;
    // What the reader drops comes as items of its own, in order with the messages.
    reader_.report_drops(true);
  }

  void feed(std::string_view chunk) {
    reader_.feed(chunk);
    while (const std::optional<anello::stream_item> item = reader_.next()) handle(*item);
  }

  void finish() {
    while (const std::optional<anello::stream_item> item = reader_.finish()) handle(*item);
    out_.flush();
  }

  // The input went quiet: a sentence ended by a CR that may yet be followed by LF is decoded
  // now rather than when the next byte comes. Not when CR LF is required: there the LF decides.
  void quiet() {
    if (opt_.policy.require_crlf) return;
    if (const std::optional<anello::stream_item> item = reader_.flush()) handle(*item);
  }

  [[nodiscard]] bool all_good() const { return rejected_ == 0 && !out_.failed(); }
  [[nodiscard]] bool output_failed() const { return out_.failed(); }

  void print_stats() const {
    const anello::stream_stats& f = reader_.stats();
    std::fprintf(stderr, "seawire-decode: %llu messages decoded, %llu rejected\n",
                 static_cast<unsigned long long>(decoded_),
                 static_cast<unsigned long long>(rejected_));
    if (!by_type_.empty()) std::fprintf(stderr, "  by type:\n");
    for (const auto& [type, n] : by_type_)
      std::fprintf(stderr, "    %-20s %llu\n", type.c_str(), static_cast<unsigned long long>(n));
    bool any_error = false;
    for (std::size_t e = 0; e < by_error_.size(); ++e) {
      if (by_error_[e] == 0) continue;
      if (!any_error) std::fprintf(stderr, "  by error:\n");
      any_error = true;
      const std::string_view n = name(static_cast<errc>(e));
      std::fprintf(stderr, "    %-20.*s %llu\n", static_cast<int>(n.size()), n.data(),
                   static_cast<unsigned long long>(by_error_[e]));
    }
    if (reencode_failures_ > 0)
      std::fprintf(stderr, "    (%llu of them refused when re-encoded)\n",
                   static_cast<unsigned long long>(reencode_failures_));
    std::fprintf(
        stderr,
        "  input: %llu sentences, %llu frames; %llu noise bytes, %llu dropped bytes; "
        "%llu sentences interrupted, %llu overlong, %llu with invalid bytes; frames: "
        "%llu bad CRC, %llu bad length, %llu truncated\n",
        static_cast<unsigned long long>(f.sentences), static_cast<unsigned long long>(f.frames),
        static_cast<unsigned long long>(f.noise_bytes),
        static_cast<unsigned long long>(f.dropped_bytes),
        static_cast<unsigned long long>(f.interrupted), static_cast<unsigned long long>(f.overlong),
        static_cast<unsigned long long>(f.invalid_bytes),
        static_cast<unsigned long long>(f.bad_crc_frames),
        static_cast<unsigned long long>(f.bad_length_frames),
        static_cast<unsigned long long>(f.truncated_frames));
  }

 private:
  void handle(const anello::stream_item& item) {
    switch (item.kind) {
      case anello::stream_item_kind::sentence: sentence(item.sentence); break;
      case anello::stream_item_kind::frame: frame(item); break;
      case anello::stream_item_kind::dropped: dropped(item); break;
    }
  }

  // ---- one binary frame ----

  void frame(const anello::stream_item& item) {
    // Values outside the spec's ranges are rejected, as in sentences (strict where it matters):
    // what is decoded here, seawire-encode sends back. "Not available" values pass.
    const result<anello::sensor_frame_raw> v = anello::validate(item.frame);
    if (!v) {
      reject(item.line, v.ec, v.field, frame_error(item.frame, v), hex(item.bytes));
      return;
    }
    switch (opt_.fmt) {
      case format::json:
        anello::write_json(out_, item.frame);
        out_.put('\n');
        break;
      case format::nmea: {
        const anello::frame_bytes bytes = anello::encode_frame(item.frame);
        out_.put(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        break;
      }
      case format::none: break;
    }
    ++decoded_;
    if (opt_.stats) ++by_type_[std::string(anello::frame_json_type)];
    if (opt_.line_buffered) out_.flush();
  }

  // "AB00 field 1 (heading_deg) 361: value outside the range the spec allows", the value as
  // write_json would write it.
  static std::string frame_error(const anello::sensor_frame_raw& frame,
                                 const result<anello::sensor_frame_raw>& v) {
    std::array<char, 160> buf;
    return std::string(anello::describe(buf, v, frame));
  }

  template <class Bytes>
  static std::string hex(const Bytes& bytes) {
    std::string h;
    for (const auto c : bytes) {
      const auto b = static_cast<std::uint8_t>(c);
      h += "0123456789ABCDEF"[b >> 4U];
      h += "0123456789ABCDEF"[b & 0x0FU];
    }
    return h;
  }

  // ---- one sentence ----

  void sentence(const nmea::framed_line& l) {
    if (opt_.policy.require_crlf && l.ending != nmea::line_ending::crlf) {
      reject(l.line, errc::bad_line_ending, 0,
             std::string(message(errc::bad_line_ending)) + ": the line does not end in CR LF",
             l.text);
      return;
    }
    const result<nmea::sentence_view> s = nmea::parse(l.text, policy_);
    if (!s) {
      parse_error(l, s);
      return;
    }
    const result<bool> r =
        all_messages::visit(s.value, policy_, [&](const auto& msg) { emit(l, s.value, msg); });
    if (!r) decode_error(l, r);
  }

  template <class M>
  void emit(const nmea::framed_line& l, const nmea::sentence_view& s, const M& msg) {
    switch (opt_.fmt) {
      case format::json:
        nmea::write_json(out_, msg);
        out_.put('\n');
        break;
      case format::nmea:
        if (!reencode(l, s, msg)) return;
        break;
      case format::none: break;
    }
    ++decoded_;
    if (opt_.stats) ++by_type_[std::string(s.address)];
    if (opt_.line_buffered) out_.flush();
  }

  template <class M>
  bool reencode(const nmea::framed_line& l, const nmea::sentence_view& s, const M& msg) {
    std::array<char, 1100> buf;
    result<std::size_t> r;
    if constexpr (std::is_same_v<M, nmea::unknown_sentence>) {
      // Not ours to interpret: the same start ('$' or '!') and fields, sealed the way seawire
      // seals.
      nmea::writer w(std::span<char>(buf.data(), buf.size()));
      w.begin(s.address, s.start);
      if (s.field_count > 0) {
        w.next_field();
        w.put(s.body);
      }
      r = w.seal();
    } else {
      r = nmea::encode_to(msg, std::span<char>(buf.data(), buf.size()));
    }
    if (!r) {
      ++reencode_failures_;
      std::string detail = std::string(s.address) + " cannot be re-encoded";
      if (r.field != 0) {
        detail += ": field " + std::to_string(r.field) + " (" +
                  std::string(all_messages::field_name(s.address, r.field, s.field_count)) + ")";
      }
      detail += ": " + std::string(message(r.ec));
      reject(l.line, r.ec, r.field, detail, l.text);
      return false;
    }
    out_.put(std::string_view(buf.data(), r.value));
    return true;
  }

  // ---- errors ----

  void parse_error(const nmea::framed_line& l, const result<nmea::sentence_view>& s) {
    char why[512];
    reject(l.line, s.ec, 0, nmea::describe<all_messages>(why, s, l.text, policy_), l.text);
  }

  void decode_error(const nmea::framed_line& l, const result<bool>& r) {
    char why[512];
    reject(l.line, r.ec, r.field, nmea::describe<all_messages>(why, r, l.text, policy_), l.text);
  }

  void reject(std::uint64_t line, errc e, std::uint16_t field, std::string_view detail,
              std::string_view input) {
    ++rejected_;
    ++by_error_[static_cast<std::size_t>(e)];
    if (input.size() > max_input_shown) input = input.substr(0, max_input_shown);
    if (opt_.fmt == format::json) {
      nmea::write_json_error(out_, line, e, field, detail, input);
      out_.put('\n');
      if (opt_.line_buffered) out_.flush();
    } else {
      // stdout keeps only good sentences; the reasons go to stderr, in order with them.
      out_.flush();
      std::fprintf(stderr, "seawire-decode: line %llu: %.*s: %.*s\n",
                   static_cast<unsigned long long>(line), static_cast<int>(name(e).size()),
                   name(e).data(), static_cast<int>(detail.size()), detail.data());
    }
  }

  // ---- what the reader dropped ----

  // One report per run of dropped bytes: where it began, why, and the bytes (frame candidates
  // in hex, since they are binary).
  void dropped(const anello::stream_item& item) {
    const anello::stream_drop& d = item.drop;
    if (d.of_frame()) {
      candidate_end_ = item.offset + d.bytes.size();
    } else if (d.reason == anello::drop_reason::noise && item.offset + d.size <= candidate_end_) {
      return;  // bytes of a rejected candidate read again, shown in its report: part of it
    }
    const std::string n = std::to_string(d.size) + (d.size == 1 ? " byte" : " bytes");
    errc e = errc::missing_start;
    std::string detail;
    switch (d.reason) {
      case anello::drop_reason::noise:
        detail = n + " outside any sentence or frame (no '$' or '!' before them); dropped";
        break;
      case anello::drop_reason::invalid_byte:
        e = errc::bad_character;
        detail =
            "a byte outside printable ASCII in a sentence; " + n + " dropped up to the line's end";
        break;
      case anello::drop_reason::overlong:
        e = errc::too_long;
        detail = "a sentence longer than " + std::to_string(decltype(reader_)::capacity) +
                 " bytes; " + n + " dropped up to the line's end";
        break;
      case anello::drop_reason::interrupted:
        e = errc::truncated;
        detail = "a sentence cut short by the next '$' or 0xAB; " + n + " dropped";
        break;
      case anello::drop_reason::bad_crc:
        e = errc::crc_mismatch;
        detail =
            "an AB00 frame whose CRC-32 does not match its payload; its 0xAB dropped, the "
            "bytes after it read again";
        break;
      case anello::drop_reason::bad_length:
        e = errc::bad_length;
        detail = "AB 00 followed by a length other than 00 30 (48); " + n + " dropped";
        break;
      case anello::drop_reason::truncated_frame:
        e = errc::truncated;
        detail =
            "an AB00 frame cut short by the end of the input; its 0xAB dropped, the bytes "
            "after it read again";
        break;
    }
    reject(item.line, e, 0, detail, d.of_frame() ? hex(d.bytes) : std::string(d.bytes));
  }

  const options& opt_;
  nmea::parse_policy policy_;  // opt_.policy, but for the line ending
  tools::output out_;
  anello::stream_reader<1024> reader_;
  std::uint64_t candidate_end_ = 0;  // stream offset just past the last rejected frame candidate
  std::uint64_t decoded_ = 0;
  std::uint64_t rejected_ = 0;
  std::uint64_t reencode_failures_ = 0;
  std::map<std::string, std::uint64_t> by_type_;
  std::array<std::uint64_t, 256> by_error_{};
};

int run(const options& o) {
  decoder d(o);
  tools::chunk_reader in(0);
  // Live streams: a line whose CR ended the input so far is let out after 50 ms without more.
  constexpr int quiet_ms = 50;
  for (;;) {
    if (o.line_buffered && !in.ready_within(quiet_ms)) d.quiet();
    const std::string_view chunk = in.next();
    if (chunk.empty()) break;
    d.feed(chunk);
  }
  d.finish();
  if (o.stats) d.print_stats();
  if (in.failed()) {
    std::perror("seawire-decode: reading stdin");
    return 1;
  }
  if (d.output_failed()) {
    std::perror("seawire-decode: writing stdout");
    return 1;
  }
  return d.all_good() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "seawire-decode: decode NMEA-style sentences (Kingfisher CP*/PY*, Sandshark BF*/BP*, "
      "RobotX RX*, ANELLO inputs, standard RMC/GGA/RPM/RSA/VHW/VBW/VWR) and ANELLO 0xAB00 "
      "binary frames (\"type\":\"AB00\") read from stdin.\n"
      "Writes one JSON object per message, one per line, in input order; a rejected line gives\n"
      "{\"line\":N,\"error\":\"<errc>\",\"field\":K,\"detail\":\"...\",\"input\":\"...\"}.\n\n"
      "Examples:\n"
      "  nc vehicle 29500 | seawire-decode --line-buffered | jq -c 'select(.type==\"CPNVG\")'\n"
      "  seawire-decode --format none --stats < mission.nmea      # check a log\n"
      "  seawire-decode --format nmea < raw.nmea > clean.nmea     # canonical sentences only\n"
      "Exit status: 0 every message decoded, 1 some input rejected, 2 usage error.",
      "seawire-decode"};
  std::string fmt = "json";
  std::string checksum = "verify";
  bool strict = false;
  options o;
  app.add_option("-f,--format", fmt,
                 "json: one JSON object per message (default); nmea: each message re-encoded "
                 "canonically (uppercase checksum, CR LF), rejected lines reported on stderr; "
                 "none: decode and validate only (e.g. --format none --stats)")
      ->check(CLI::IsMember({"json", "nmea", "none"}));
  CLI::Option* checksum_opt =
      app.add_option("-c,--checksum", checksum,
                     "required: a sentence without *hh is rejected; verify: checked when present "
                     "(default); ignore: not checked, in upper or lower case (e.g. --checksum "
                     "required)")
          ->check(CLI::IsMember({"required", "verify", "ignore"}));
  app.add_flag(
      "--strict", strict,
      "apply the rules seawire sends by to the input: checksum required, uppercase hex, "
      "no extra fields, CR LF endings, no '+' signs or spaces around numbers, no reserved "
      "characters in text "
      "(--checksum still overrides the checksum rule; with --checksum ignore the hex may be "
      "lowercase; e.g. --strict --format none < ours.nmea). Values outside the spec's ranges, "
      "in sentences and in frames, are rejected with or without --strict");
  app.add_flag("--stats", o.stats,
               "at the end, print counts by message type and by error, and the stream reader's "
               "dropped-byte counters, to stderr (e.g. --format none --stats)");
  app.add_flag("--line-buffered", o.line_buffered,
               "flush stdout after each message, for live streams (default: large buffers, "
               "for speed); a sentence ended by CR alone is let out once the input has been "
               "quiet for 50 ms (e.g. nc vehicle 29500 | seawire-decode --line-buffered)");
  app.set_version_flag("--version", "seawire-decode (seawire " SEAWIRE_VERSION_STRING ")");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    (void)app.exit(e);
    return 2;
  }
  o.fmt = fmt == "nmea" ? format::nmea : fmt == "none" ? format::none : format::json;
  if (strict) o.policy = nmea::parse_policy::strict();
  // Numbers with spaces around them (" -3.4"): Sandshark's SPI allows them, and a liberal reader
  // of every family at once takes them; --strict does not.
  o.policy.spaced_numbers = !strict;
  if (!strict || checksum_opt->count() > 0) {
    o.policy.checksum = checksum == "required" ? nmea::checksum_policy::required
                        : checksum == "ignore" ? nmea::checksum_policy::ignore
                                               : nmea::checksum_policy::verify_if_present;
  }
  // A checksum that is not checked has no case to check either (--strict asks for uppercase hex
  // only of a checksum it verifies). What is after '*' must still be two hex digits: the library
  // reads it as the sentence's end, and anything else there is no sentence.
  if (o.policy.checksum == nmea::checksum_policy::ignore) o.policy.lowercase_hex = true;
  return run(o);
}
