// SPDX-License-Identifier: BSL-1.0
// seawire-decode: NMEA-style sentences (and ANELLO 0xAB00 binary frames mixed in), or a CAN log
// of NMEA 2000 frames, on stdin -> one JSON object per message (or re-encoded messages, CSV tables,
// a GeoJSON or SVG track, or nothing but a verdict). A thin program over the library:
// anello::stream_reader cuts the stream into sentences and frames, message_set::visit decodes each
// sentence by its address; a CAN log goes through nmea2000::log_reader (lines, fast packets).
// The decoder finds the messages and counts them; every message, of every wire, goes to the
// writer of the format asked for (writers.hpp: one class per format, behind `sink`): the
// library's JSON and CSV writers, loops over the walk of its fields (walk.hpp), and track.hpp,
// which gathers positions from the same walk. See --help, and tools/decode/README.md for the
// manual.

#include <poll.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "io.hpp"
#include "messages.hpp"
#include "seawire/anello/frame.hpp"
#include "seawire/anello/frame_json.hpp"
#include "seawire/anello/stream.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/error_text.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/nmea2000/reader.hpp"
#include "seawire/version.hpp"
#include "writers.hpp"

namespace {

using namespace seawire;
using seawire::tools::all_messages;
using seawire::tools::format;
using seawire::tools::origin;
using seawire::tools::sink;

// What stdin holds: sentences and ANELLO frames, or a CAN log (NMEA 2000); auto: the first line
// that is not blank decides.
enum class input { automatic, nmea, n2k };

using seawire::tools::n2k_pgns;
// A CAN log line longer than this is no line of any log format (a canboat FAST line of 223
// bytes has about 700 characters).
constexpr std::size_t max_log_line = 4096;
// --input auto decides within this much input, or this many lines neither a sentence nor a CAN
// log line: it then reads sentences.
constexpr std::size_t max_undecided = 64 * 1024;
constexpr int max_undecided_lines = 16;

// Whether `line` is a CAN log line of a format seawire reads (and not a sentence).
bool is_can_log_line(std::string_view line) {
  const std::size_t at = line.find_first_not_of(" \t");
  if (at == std::string_view::npos || line[at] == '$' || line[at] == '!') return false;
  // canboat's "# format=NAME" header, of a format known or not, says this is a CAN log.
  if (nmea2000::parse_format_header(line).ec != errc::bad_log_line) return true;
  return static_cast<bool>(nmea2000::parse_log_line(line));
}

// The output's options (writers.hpp), and the input's.
struct options : tools::output_options {
  input in = input::automatic;
  // Sentences are read by the policy of the role that receives them (tools::receiving_policy);
  // these options change it for every role.
  bool strict = false;                            // the rules seawire sends by (CR LF too)
  std::optional<nmea::checksum_policy> checksum;  // this checksum rule
  bool stats = false;
  bool quiet = false;
  std::optional<nmea2000::log_format> log_format;  // CAN logs: every line in this format
};

// Rejected input shows at most this much of its line.
constexpr std::size_t max_input_shown = 256;

class decoder {
 public:
  // Every message, rejected line and dropped run of bytes, and the end of the input, goes to
  // `out`.
  decoder(const options& o, sink& out) : opt_(o), out_(out), in_(o.in) {
    // What the reader drops comes as items of its own, in order with the messages.
    reader_.report_drops(true);
  }

  void feed(std::string_view chunk) {
    if (in_ == input::automatic) {
      decide(chunk, false);
      return;
    }
    if (in_ == input::n2k) {
      can_log(chunk);
      return;
    }
    // Each item is the reader's own, handed over without a copy.
    reader_.feed(chunk, [this](const anello::stream_item& item) { handle(item); });
  }

  void finish() {
    if (in_ == input::automatic) decide({}, true);
    if (in_ == input::n2k) {
      if (!carry_.empty() && !skipping_) can_log_line(carry_);
      carry_.clear();
      n2k_.flush();
    }
    reader_.finish([this](const anello::stream_item& item) { handle(item); });
    out_.finish();
  }

  [[nodiscard]] std::uint64_t decoded() const { return decoded_; }
  [[nodiscard]] std::uint64_t rejected() const { return rejected_; }

  // The input went quiet: a sentence ended by a CR that may yet be followed by LF is decoded
  // now rather than when the next byte comes. Not when CR LF is required: there the LF decides.
  void quiet() {
    if (opt_.strict) return;
    reader_.flush([this](const anello::stream_item& item) { handle(item); });
  }

  // The input cannot be written in the format asked for (a CAN log with --format nmea).
  [[nodiscard]] bool unusable() const { return unusable_; }
  void print_stats() const {
    const anello::stream_stats& f = reader_.stats();
    std::fprintf(stderr, "seawire-decode: %llu messages decoded, %llu rejected",
                 static_cast<unsigned long long>(decoded_),
                 static_cast<unsigned long long>(rejected_));
    if (in_ == input::n2k) print_pseudo_pgns(", ");
    std::fputc('\n', stderr);
    if (in_ == input::n2k) {
      print_by_pgn();
    } else {
      if (!by_type_.empty()) std::fprintf(stderr, "  by type:\n");
      for (const auto& [type, n] : by_type_)
        std::fprintf(stderr, "    %-20s %llu\n", type.c_str(), static_cast<unsigned long long>(n));
      if (other_types_ > 0)
        std::fprintf(stderr, "    %-20s %llu\n", "(other types)",
                     static_cast<unsigned long long>(other_types_));
    }
    bool any_error = false;
    for (std::size_t e = 0; e < by_error_.size(); ++e) {
      if (by_error_[e] == 0) continue;
      if (!any_error) std::fprintf(stderr, "  by error:\n");
      any_error = true;
      const std::string_view n = name(static_cast<errc>(e));
      std::fprintf(stderr, "    %-20.*s %llu\n", static_cast<int>(n.size()), n.data(),
                   static_cast<unsigned long long>(by_error_[e]));
    }
    if (refused_ > 0)
      std::fprintf(stderr, "    (%llu of them refused when re-encoded)\n",
                   static_cast<unsigned long long>(refused_));
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
    if (in_ != input::n2k) return;
    const auto& a = n2k_.assembler();
    std::fprintf(stderr,
                 "  CAN log: %llu lines; fast packets: %llu frames, %llu assembled into %llu "
                 "messages, %llu dropped",
                 static_cast<unsigned long long>(log_lines_),
                 static_cast<unsigned long long>(a.frames_in()),
                 static_cast<unsigned long long>(a.frames_assembled()),
                 static_cast<unsigned long long>(a.packets()),
                 static_cast<unsigned long long>(a.frames_dropped()));
    for (std::size_t i = 0; i < nmea2000::fast_packet_drop_count; ++i) {
      const auto why = static_cast<nmea2000::fast_packet_drop>(i);
      if (a.drops(why) == 0) continue;
      const std::string_view n = name(why);
      std::fprintf(stderr, "; %.*s %llu", static_cast<int>(n.size()), n.data(),
                   static_cast<unsigned long long>(a.drops(why)));
    }
    std::fputc('\n', stderr);
  }

  // Without --stats, the end of the run still says what was skipped of a CAN log.
  void print_summary() const {
    if (in_ != input::n2k || n2k_.pseudo_pgn_lines() == 0) return;
    std::fputs("seawire-decode: ", stderr);
    print_pseudo_pgns("");
    std::fputc('\n', stderr);
  }

 private:
  // "N lines of gateway pseudo-PGNs (262144 and up) skipped", when there were some.
  void print_pseudo_pgns(const char* before) const {
    const std::uint64_t n = n2k_.pseudo_pgn_lines();
    if (n == 0) return;
    std::fprintf(stderr, "%s%llu line%s of gateway pseudo-PGNs (%u and up) skipped", before,
                 static_cast<unsigned long long>(n), n == 1 ? "" : "s",
                 static_cast<unsigned>(nmea2000::first_pseudo_pgn));
  }

  // --stats of a CAN log: messages decoded per PGN, by number, with the name of the PGNs seawire
  // describes. Counted as types ("PGN128259"), so within the same bound.
  void print_by_pgn() const {
    std::vector<std::pair<std::uint32_t, std::uint64_t>> rows;
    rows.reserve(by_type_.size());
    for (const auto& [type, n] : by_type_) {
      std::uint32_t pgn = 0;
      for (const char c : std::string_view(type).substr(3))
        pgn = pgn * 10 + static_cast<std::uint32_t>(c - '0');
      rows.emplace_back(pgn, n);
    }
    std::sort(rows.begin(), rows.end());
    if (!rows.empty()) std::fprintf(stderr, "  by PGN:\n");
    for (const auto& [pgn, n] : rows) {
      // The struct's name; of a PGN with several layouts, what their names share
      // ("group_function").
      std::optional<std::string_view> named;
      const std::uint32_t number = pgn;  // (a lambda cannot capture a structured binding)
      n2k_pgns::for_each_type([&](const auto& tag) {
        using P = std::remove_cvref_t<decltype(tag)>;
        if (seawire::nmea2000::pgn_table<P>.info.pgn != number) return;
        const std::string_view name = seawire::nmea2000::pgn_table<P>.info.name;
        if (!named) {
          named = name;
          return;
        }
        std::size_t k = 0;
        while (k < named->size() && k < name.size() && (*named)[k] == name[k]) ++k;
        while (k > 0 && (*named)[k - 1] == '_') --k;
        named = named->substr(0, k);
      });
      if (!named) named = "(no description)";
      std::fprintf(stderr, "    %-7u %-32.*s %llu\n", static_cast<unsigned>(pgn),
                   static_cast<int>(named->size()), named->data(),
                   static_cast<unsigned long long>(n));
    }
    if (other_types_ > 0)
      std::fprintf(stderr, "    %-40s %llu\n", "(other PGNs)",
                   static_cast<unsigned long long>(other_types_));
  }

  // ---- which input ----

  // Keeps what came until a line says what the input is: a CAN log line, or a sentence (or
  // anything else once max_undecided_lines lines or max_undecided bytes have said nothing either
  // way), and reads it so. Each byte is looked at once, however the input is cut: what was
  // scanned is not scanned again when more comes.
  void decide(std::string_view chunk, bool at_end) {
    pending_.append(chunk);
    std::string_view rest = std::string_view(pending_).substr(scanned_);
    std::optional<bool> can;
    // A sentence or a binary frame needs no whole line to be recognised (a live binary stream
    // may have no newline for a long time): the first byte that is not blank says so.
    if (!seen_text_) {
      if (const std::size_t at = rest.find_first_not_of(" \t\r\n"); at != std::string_view::npos) {
        const auto c = static_cast<unsigned char>(rest[at]);
        if (c == '$' || c == '!' || c == 0xAB) can = false;
        seen_text_ = true;
      }
    }
    while (!rest.empty() && !can) {
      const std::size_t nl = rest.find('\n');
      if (nl == std::string_view::npos && !at_end && rest.size() <= max_log_line) break;
      const std::string_view line = rest.substr(0, nl);
      const std::size_t used = nl == std::string_view::npos ? rest.size() : nl + 1;
      rest.remove_prefix(used);
      scanned_ += used;
      const std::size_t at = line.find_first_not_of(" \t\r");
      if (at == std::string_view::npos) continue;
      if (line[at] == '$' || line[at] == '!') {
        can = false;
      } else if (is_can_log_line(line)) {
        can = true;
      } else if (++undecided_lines_ >= max_undecided_lines) {
        can = false;
      }
    }
    // Noise without a line ending says nothing either way: past this much, the stream reader
    // takes it (it drops what is outside sentences and frames, and resyncs at '$', '!' and AB),
    // so what comes after the noise is read, and memory stays bounded.
    if (!can && pending_.size() >= max_undecided) can = false;
    if (!can && !at_end) return;
    in_ = can.value_or(out_.refuses_sentences() != nullptr) ? input::n2k : input::nmea;
    if (const char* why = in_ == input::n2k ? out_.refuses_can_log() : out_.refuses_sentences()) {
      std::fputs(why, stderr);
      unusable_ = true;
      in_ = input::nmea;
      pending_.clear();
      return;
    }
    std::string all = std::move(pending_);
    pending_.clear();
    if (!all.empty()) feed(all);
  }

  // ---- a CAN log ----

  void can_log(std::string_view chunk) {
    while (!chunk.empty()) {
      const std::size_t nl = chunk.find('\n');
      const std::string_view piece = chunk.substr(0, nl);
      if (!skipping_) {
        if (carry_.size() + piece.size() > max_log_line) {
          ++log_lines_;
          reject(log_lines_, errc::too_long, 0,
                 "a line longer than " + std::to_string(max_log_line) +
                     " characters is no CAN log line",
                 carry_.empty() ? piece : std::string_view(carry_));
          skipping_ = true;
          carry_.clear();
        } else if (nl != std::string_view::npos && carry_.empty()) {
          can_log_line(piece);
        } else {
          carry_.append(piece);
          if (nl != std::string_view::npos) {
            can_log_line(carry_);
            carry_.clear();
          }
        }
      }
      if (nl == std::string_view::npos) break;
      skipping_ = false;
      chunk.remove_prefix(nl + 1);
    }
  }

  void can_log_line(std::string_view text) {
    ++log_lines_;
    const auto r = n2k_.read_line(
        text,
        [&](const nmea2000::message_header& h, std::span<const std::uint8_t> payload) {
          can_message(h, payload);
        },
        opt_.log_format);
    if (r.ec == errc::empty_input || r.ok()) return;
    std::string detail;
    if (r.ec == errc::unknown_log_format) {
      std::string_view named = text.substr(nmea2000::format_header_prefix.size());
      named = named.substr(0, named.find_last_not_of(" \t\r\n") + 1);
      detail = "the log's header names format \"" + std::string(named) + "\": " +
               (nmea2000::canboat_format_named(named) ? "a canboat format seawire does not read"
                                                      : "no canboat format has this name") +
               " (seawire reads PLAIN, FAST, PLAIN_OR_FAST, PLAIN_MIX_FAST and YDWG02); the lines "
               "after it are read as before";
      reject(log_lines_, r.ec, r.field, detail, text);
      return;
    }
    if (r.field != 0) {
      detail = std::string(name(r.value)) + " " +
               std::string(nmea2000::log_field_name(r.value, r.field)) + " at column " +
               std::to_string(r.column + 1) + ": ";
    }
    detail += r.ec == errc::bad_log_line && r.field == 0
                  ? "not a line of candump -L, candump, canboat or Yacht Devices RAW"
                  : std::string(message(r.ec));
    reject(log_lines_, r.ec, r.field, detail, text);
  }

  void can_message(const nmea2000::message_header& h, std::span<const std::uint8_t> payload) {
    char type_buf[16];
    const int n =
        std::snprintf(type_buf, sizeof type_buf, "PGN%u", static_cast<unsigned>(h.id.pgn));
    const std::string_view type(type_buf, static_cast<std::size_t>(n));
    if (!wanted(type)) return;
    const origin from{nullptr, {}, nullptr, &h, payload};
    const bool known = n2k_pgns::visit(h.id.pgn, payload,
                                       [&](const auto& msg) { deliver(type, type, msg, from); });
    if (!known) deliver(type, type, tools::raw_pgn{payload}, from);
  }

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
    if (!wanted(anello::frame_json_type)) return;
    deliver(anello::frame_json_type, anello::frame_json_type, item.frame, origin{});
  }

  // "AB00 field 1 (heading_deg) 361: value outside the range the spec allows", the value as
  // write_json would write it.
  static std::string frame_error(const anello::sensor_frame_raw& frame,
                                 const result<anello::sensor_frame_raw>& v) {
    std::array<char, 160> buf;
    return std::string(anello::error_text(buf, v, frame));
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
    if (opt_.strict && l.ending != nmea::line_ending::crlf) {
      const char* ends = l.ending == nmea::line_ending::lf   ? "it ends in LF alone"
                         : l.ending == nmea::line_ending::cr ? "it ends in CR alone"
                                                             : "it has no line ending";
      reject(l.line, errc::bad_line_ending, 0,
             std::string(message(errc::bad_line_ending)) + ": " + ends, l.text);
      return;
    }
    std::string_view address;
    const nmea::parse_policy& policy = policy_for(l.text, address);
    // A line in its plain form is read in one pass; any other is parsed first. The two give the
    // same message or the same error (column and field), which error_text tells alike.
    const result<bool> r = all_messages::visit(
        l.text, policy, [&](const auto& msg) { emit(l, address, policy, msg); });
    if (!r) {
      char why[512];
      reject(l.line, r.ec, r.field, nmea::error_text<all_messages>(why, r, l.text, policy), l.text);
    }
  }

  // The policy of the role that receives the sentence's address (tools::receiving_policy), or
  // the sending rules with --strict, with --checksum's rule. Kept per address in a small table:
  // a log repeats a few dozen addresses, and finding an address's role walks every role's set.
  // `address` is set to the text's address: what follows the start character up to the first
  // ',' or '*' (a sentence's address, when the text is one).
  const nmea::parse_policy& policy_for(std::string_view text, std::string_view& address) {
    // The address: up to the first ',' or '*' after the start character. One longer than a
    // table entry holds (no sentence has one) is looked up every time.
    const std::size_t most = policy_entry::address_capacity;
    const char* const a = text.data() + 1;
    const std::size_t limit = text.empty() ? 0 : std::min(text.size() - 1, most + 1);
    std::size_t n = 0;
    std::uint32_t hash = 0;
    for (; n < limit && a[n] != ',' && a[n] != '*'; ++n)
      hash = hash * 31U + static_cast<unsigned char>(a[n]);
    address = std::string_view(a, n);
    if (n > most) {
      address = text.substr(1);
      address = address.substr(0, address.find_first_of(",*"));
      policy_slow_ = policy_of(address);
      return policy_slow_;
    }
    // The hash's top bits (Fibonacci hashing) pick the first slot to look in; the next few are
    // tried after it. An address in none of them takes the first free one, or the first.
    const std::size_t first = (hash * 0x9E3779B1U) >> (32U - policy_slot_bits);
    policy_entry* free = nullptr;
    for (std::size_t k = 0; k < policy_probes; ++k) {
      policy_entry& e = policies_[(first + k) % policies_.size()];
      if (e.size == n && address == std::string_view(e.address.data(), e.size)) return e.policy;
      if (free == nullptr && e.size > most) free = &e;
    }
    policy_entry& e = free != nullptr ? *free : policies_[first];
    e.policy = policy_of(address);
    std::copy(address.begin(), address.end(), e.address.begin());
    e.size = n;
    return e.policy;
  }

  [[nodiscard]] nmea::parse_policy policy_of(std::string_view address) const {
    nmea::parse_policy p =
        opt_.strict ? nmea::parse_policy::strict() : tools::receiving_policy(address);
    if (opt_.checksum) p.checksum = *opt_.checksum;
    // A checksum that is not checked has no case to check either (--strict asks for uppercase
    // hex only of a checksum it verifies). What is after '*' must still be two hex digits: the
    // library reads it as the sentence's end, and anything else there is no sentence.
    if (p.checksum == nmea::checksum_policy::ignore) p.lowercase_hex = true;
    // The reader has taken the line ending off: it is checked from what the reader saw.
    p.require_crlf = false;
    return p;
  }

  // The JSON "type" of a message: talker + type for talker-agnostic ones, else its address.
  template <class M>
  static std::string_view type_of(std::string_view address, const M& msg,
                                  nmea::json_buffer<16>& buf) {
    if constexpr (nmea::message_like<M>) {
      nmea::write_type(buf, msg);
      return buf.view();
    } else {
      return address;
    }
  }

  // `address`: the line's, as policy_for found it; a sentence no message describes has its own,
  // as parse() split it.
  template <class M>
  void emit(const nmea::framed_line& l, std::string_view address, const nmea::parse_policy& policy,
            const M& msg) {
    if constexpr (std::is_same_v<M, nmea::unknown_sentence>) address = msg.sentence.address;
    nmea::json_buffer<16> type_buf;
    const std::string_view type = type_of(address, msg, type_buf);
    if (!wanted(type)) return;
    deliver(type, address, msg, origin{&l, address, &policy, nullptr, {}});
  }

  // ---- every message, of every wire ----

  // A message decoded (a sentence, known or not; a PGN, described or not; a frame), to the
  // writer. `type` is its JSON "type", `counted` what --stats counts it under. A sentence the
  // writer refuses (--format nmea cannot re-encode it) is rejected.
  template <class M>
  void deliver(std::string_view type, std::string_view counted, const M& msg, const origin& from) {
    if (const std::optional<tools::refusal> no = out_.message(type, msg, from)) {
      ++refused_;
      reject(from.line->line, no->ec, no->field, no->detail, from.line->text);
      return;
    }
    ++decoded_;
    if (opt_.stats) tools::count_type(by_type_, other_types_, counted);
  }

  // ---- types ----

  [[nodiscard]] bool wanted(std::string_view type) const {
    return opt_.types.empty() ||
           std::find(opt_.types.begin(), opt_.types.end(), type) != opt_.types.end();
  }

  // ---- errors ----

  void reject(std::uint64_t line, errc e, std::uint16_t field, std::string_view detail,
              std::string_view input) {
    ++rejected_;
    ++by_error_[static_cast<std::size_t>(e)];
    if (input.size() > max_input_shown) input = input.substr(0, max_input_shown);
    out_.rejected(tools::rejection{line, e, field, detail, input});
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
        // A sentence with a complete checksum before the '$' was yielded: this one has none,
        // or part of one, so it may have lost its tail.
        detail =
            "a sentence without a complete checksum, ended by the next '$' or 0xAB before its line "
            "ending (cut short, or sent without either); " +
            n + " dropped";
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
  // policy_for's table: an address's policy, in a slot near the address's hash.
  struct policy_entry {
    static constexpr std::size_t address_capacity = 16;
    std::array<char, address_capacity> address{};
    std::size_t size = address_capacity + 1;  // none yet
    nmea::parse_policy policy;
  };
  static constexpr unsigned policy_slot_bits = 7;
  static constexpr std::size_t policy_probes = 8;
  std::array<policy_entry, std::size_t{1} << policy_slot_bits> policies_{};
  nmea::parse_policy policy_slow_;  // policy_for's, for an address too long for the table
  sink& out_;
  anello::stream_reader<1024> reader_;
  std::uint64_t candidate_end_ = 0;  // stream offset just past the last rejected frame candidate
  input in_;
  std::string pending_;      // input kept until the first line says what it is
  std::size_t scanned_ = 0;  // pending_'s bytes already looked at (whole lines)
  bool seen_text_ = false;   // a byte not blank was looked at
  int undecided_lines_ = 0;  // lines that were neither a sentence nor a CAN log line
  bool unusable_ = false;
  nmea2000::log_reader<n2k_pgns> n2k_;
  std::string carry_;      // a CAN log line cut by the chunk boundary
  bool skipping_ = false;  // inside an overlong line, until its end
  std::uint64_t log_lines_ = 0;
  std::uint64_t decoded_ = 0;
  std::uint64_t rejected_ = 0;
  std::uint64_t refused_ = 0;
  std::map<std::string, std::uint64_t, std::less<>> by_type_;
  std::uint64_t other_types_ = 0;  // messages of types past max_counted_types
  std::array<std::uint64_t, 256> by_error_{};
};

// SIGINT or SIGTERM, once one came (0 before): reading stops, and what was read is decoded and
// written as at the end of the input.
volatile std::sig_atomic_t stop_signal = 0;
extern "C" void on_stop_signal(int sig) { stop_signal = sig; }

// SIGINT and SIGTERM are blocked but while waiting for input (ppoll lets them in atomically, so
// one that comes while a chunk is decoded is not lost, and none interrupts a write).
class stop_signals {
 public:
  stop_signals() {
    sigemptyset(&stop_);
    sigaddset(&stop_, SIGINT);
    sigaddset(&stop_, SIGTERM);
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
    sigprocmask(SIG_BLOCK, &stop_, &waiting_);
    sigdelset(&waiting_, SIGINT);
    sigdelset(&waiting_, SIGTERM);
  }
  stop_signals(const stop_signals&) = delete;
  stop_signals& operator=(const stop_signals&) = delete;
  // A second signal, while the output is written, ends the program at once. One that came while
  // the input ended (held back since) counts as the first.
  ~stop_signals() {
    const timespec now{0, 0};
    for (int sig = 0; (sig = sigtimedwait(&stop_, nullptr, &now)) > 0;) {
      if (stop_signal == 0) stop_signal = sig;
    }
    struct sigaction sa {};
    sa.sa_handler = SIG_DFL;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
    sigprocmask(SIG_UNBLOCK, &stop_, nullptr);
  }

  // Waits for input on `fd` (or its end, or an error), `ms` milliseconds at most (-1: no limit):
  // true when there is some, false after `ms` or when a stop signal came.
  [[nodiscard]] bool wait_input(int fd, int ms) const {
    pollfd p{fd, POLLIN, 0};
    for (;;) {
      if (stop_signal != 0) return false;
      timespec t{ms / 1000, static_cast<long>(ms % 1000) * 1000000L};
      const int n = ::ppoll(&p, 1, ms < 0 ? nullptr : &t, &waiting_);
      if (n < 0 && errno == EINTR) continue;
      return n != 0;  // a poll error too: the read says what it is
    }
  }

 private:
  sigset_t stop_{};
  sigset_t waiting_{};  // the mask while waiting: the one before, SIGINT and SIGTERM let in
};

int run(const options& o) {
  if (!o.output_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.output_dir, ec);
    if (ec) {
      std::fprintf(stderr, "seawire-decode: cannot create %s: %s\n", o.output_dir.c_str(),
                   ec.message().c_str());
      return 1;
    }
  }
  tools::progress shown(!o.quiet);
  sink out(o, shown);
  decoder d(o, out);
  tools::chunk_reader in(0);
  // Live streams: a line whose CR ended the input so far is let out after 50 ms without more.
  constexpr int quiet_ms = 50;
  {
    const stop_signals signals;
    for (;;) {
      if (o.line_buffered && !signals.wait_input(0, quiet_ms) && stop_signal == 0) d.quiet();
      // read() is called only once input is there, so it does not block with the signals
      // held back.
      if (!signals.wait_input(0, -1)) break;
      const std::string_view chunk = in.next();
      if (chunk.empty()) break;
      d.feed(chunk);
      shown.update(chunk.size(), d.decoded(), d.rejected());
    }
  }
  shown.done();
  d.finish();
  if (d.unusable()) return 2;
  if (o.stats) {
    d.print_stats();
  } else {
    d.print_summary();
  }
  if (in.failed()) {
    std::perror("seawire-decode: reading stdin");
    return 1;
  }
  if (out.out().failed()) {
    std::fprintf(stderr, "seawire-decode: writing stdout: %s\n", std::strerror(out.out().error()));
    return 1;
  }
  // Stopped by a signal: the shell's status for it (128 + its number), whatever was decoded.
  if (stop_signal != 0) return 128 + static_cast<int>(stop_signal);
  return d.rejected() == 0 && out.all_written() ? 0 : 1;
}

// Reads the command line into `o`: the exit status when the program ends here (--help,
// --version, a usage error), nullopt when it is to run.
std::optional<int> parse_options(int argc, char** argv, options& o) {
  CLI::App app{
      "seawire-decode: decode NMEA-style sentences (Kingfisher CP*/PY*, Sandshark BF*/BP*, "
      "RobotX RX*, ANELLO inputs, standard RMC/GGA/RPM/RSA/VHW/VBW/VWR) and ANELLO 0xAB00 "
      "binary frames (\"type\":\"AB00\") read from stdin, or a CAN log of NMEA 2000 frames "
      "(\"type\":\"PGN128259\"; candump -L, candump, canboat, Yacht Devices RAW; fast "
      "packets assembled).\n"
      "Writes one JSON object per message, one per line, in input order; a rejected line gives\n"
      "{\"line\":N,\"error\":\"<errc>\",\"field\":K,\"detail\":\"...\",\"input\":\"...\"}.\n\n"
      "Examples:\n"
      "  nc vehicle 29500 | seawire-decode --line-buffered | jq -c 'select(.type==\"CPNVG\")'\n"
      "  seawire-decode --format csv --output-dir tables < mission.nmea   # tables/CPNVG.csv ...\n"
      "  seawire-decode --format geojson < mission.nmea > track.geojson\n"
      "  seawire-decode --format svg < mission.nmea > track.svg           # open in a browser\n"
      "  seawire-decode --format none --stats < mission.nmea      # check a log\n"
      "  seawire-decode --format nmea < raw.nmea > clean.nmea     # canonical sentences only\n"
      "  candump -L can0 | seawire-decode --line-buffered         # NMEA 2000 from a CAN bus\n"
      "Exit status: 0 every message decoded, 1 some input rejected, 2 usage error, 130/143 "
      "stopped by SIGINT/SIGTERM (what was read is decoded and written first).",
      "seawire-decode"};
  std::string fmt = "json";
  std::string checksum;
  bool strict = false;
  app.add_option("-f,--format", fmt,
                 "json: one JSON object per message (default); nmea: each message re-encoded "
                 "canonically (uppercase checksum, CR LF); none: decode and validate only (e.g. "
                 "--format none --stats); csv: a table per message type (with --type or "
                 "--output-dir); geojson: the tracks of every source of positions, and their "
                 "state changes as points; svg: a picture of the tracks; canboat: each NMEA 2000 "
                 "message as canboat's analyzer -json writes it (CAN logs only). With every "
                 "format but json, rejected lines are reported on stderr")
      ->check(CLI::IsMember({"json", "nmea", "none", "csv", "geojson", "svg", "canboat"}));
  CLI::Option* type_opt = app.add_option(
      "-t,--type", o.types,
      "only messages of this type, as JSON's \"type\" names it (CPNVG, GPRMC, AB00); may be "
      "given more than once (e.g. --format csv --type CPNVG)");
  CLI::Option* dir_opt = app.add_option(
      "-o,--output-dir", o.output_dir,
      "with --format csv: write each type's table to DIR/<TYPE>.csv (created, or replaced), "
      "stdout unused (e.g. --format csv --output-dir tables)");
  std::string in = "auto";
  std::string log_format;
  app.add_option("-i,--input", in,
                 "what stdin holds: nmea (sentences and ANELLO binary frames), n2k (a CAN log of "
                 "NMEA 2000 frames: candump -L, candump, canboat PLAIN/FAST, Yacht Devices RAW or "
                 "Actisense N2K ASCII, told apart line by line), or auto (default: the first "
                 "sentence or CAN log "
                 "line decides; e.g. --input n2k)")
      ->check(CLI::IsMember({"auto", "nmea", "n2k"}));
  app.add_option("--log-format", log_format,
                 "read every line of the CAN log in this format rather than telling them apart: "
                 "candump_log, candump, canboat, yd_raw or actisense_n2k_ascii (implies --input "
                 "n2k)")
      ->check(
          CLI::IsMember({"candump_log", "candump", "canboat", "yd_raw", "actisense_n2k_ascii"}));
  app.add_flag("-q,--quiet", o.quiet,
               "no progress line (shown on stderr when it is a terminal and stdin a file)");
  CLI::Option* checksum_opt =
      app.add_option("-c,--checksum", checksum,
                     "by default each sentence is read by the rules of the role that receives "
                     "it: a checksum is required of what a vehicle sends (CP*, BF*) and of "
                     "RobotX and ANELLO inputs, checked when present on commands to a vehicle "
                     "(PY*, where a bare '*' means none, and BP*) and on standard sentences. This "
                     "option sets one rule for all: required: a sentence without *hh is "
                     "rejected; verify: checked when present; ignore: not checked, in upper or "
                     "lower case (e.g. --checksum required)")
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
               "at the end, print counts by message type (by PGN for a CAN log) and by error, "
               "and the stream reader's dropped-byte counters, to stderr (e.g. --format none "
               "--stats)");
  app.add_flag("--line-buffered", o.line_buffered,
               "flush stdout after each message, for live streams (the default when stdin or "
               "stdout is a terminal; otherwise large buffers, for speed); a sentence ended by CR "
               "alone is let out once the input has been "
               "quiet for 50 ms (e.g. nc vehicle 29500 | seawire-decode --line-buffered)");
  app.set_version_flag("--version", "seawire-decode (seawire " SEAWIRE_VERSION_STRING ")");
  if (const auto status = seawire::tools::parse_command_line(app, argc, argv)) return *status;
  o.fmt = fmt == "nmea"      ? format::nmea
          : fmt == "none"    ? format::none
          : fmt == "csv"     ? format::csv
          : fmt == "geojson" ? format::geojson
          : fmt == "svg"     ? format::svg
          : fmt == "canboat" ? format::canboat
                             : format::json;
  o.in = in == "nmea" ? input::nmea : in == "n2k" ? input::n2k : input::automatic;
  if (!log_format.empty()) {
    o.log_format = nmea2000::log_format_named(log_format);
    if (o.in == input::automatic) o.in = input::n2k;
  }
  // Output a person watches, or input a person types (a terminal or pty), goes out line by line.
  if (::isatty(0) == 1 || ::isatty(1) == 1) o.line_buffered = true;
  if (o.in == input::n2k && o.fmt == format::nmea) {
    std::fprintf(stderr,
                 "seawire-decode: --format nmea re-encodes sentences; a CAN log has none (use "
                 "seawire-encode --output FORMAT to write a log again)\n");
    return 2;
  }
  if (o.in == input::nmea && o.fmt == format::canboat) {
    std::fprintf(stderr,
                 "seawire-decode: --format canboat writes NMEA 2000 messages as canboat's "
                 "analyzer does; sentences have none (use --input n2k or auto with a CAN log)\n");
    return 2;
  }
  if (dir_opt->count() > 0 && o.output_dir.empty()) {
    std::fprintf(stderr, "seawire-decode: --output-dir needs a directory (e.g. --output-dir .)\n");
    return 2;
  }
  if (dir_opt->count() > 0 && o.fmt != format::csv) {
    std::fprintf(stderr, "seawire-decode: --output-dir is for --format csv\n");
    return 2;
  }
  if (o.fmt == format::csv && dir_opt->count() == 0 && o.types.size() == 1 &&
      !tools::all_headers::knows(o.types.front())) {
    std::fprintf(stderr,
                 "seawire-decode: --type %s: no message seawire describes has this type, so it "
                 "has no table (types are as JSON names them: CPNVG, GPRMC, AB00)\n",
                 o.types.front().c_str());
    return 2;
  }
  if (o.fmt == format::csv && dir_opt->count() == 0 && type_opt->count() != 1) {
    std::fprintf(stderr,
                 "seawire-decode: --format csv writes one table to stdout: give one --type "
                 "(e.g. --type CPNVG), or --output-dir DIR for a table per type\n");
    return 2;
  }
  o.strict = strict;
  if (checksum_opt->count() > 0) {
    o.checksum = checksum == "required" ? nmea::checksum_policy::required
                 : checksum == "ignore" ? nmea::checksum_policy::ignore
                                        : nmea::checksum_policy::verify_if_present;
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  options o;
  if (const std::optional<int> status = parse_options(argc, argv, o)) return *status;
  return run(o);
}
