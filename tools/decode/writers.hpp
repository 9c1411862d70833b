// SPDX-License-Identifier: BSL-1.0
#pragma once
// seawire-decode's output formats, one class each (json, nmea, none, csv, geojson, svg, canboat),
// behind one sink: each is given every message decoded, every line rejected and run of bytes
// dropped, and the end of the input. And what they write on stderr by: the progress line, and the
// log of rejected input, rate limited.

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "canboat_json.hpp"
#include "io.hpp"
#include "messages.hpp"
#include "seawire/anello/frame.hpp"
#include "seawire/anello/frame_json.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/csv.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/stream.hpp"
#include "seawire/nmea/writer.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/walk.hpp"
#include "track.hpp"

namespace seawire::tools {

enum class format { json, nmea, none, csv, geojson, svg, canboat };

// What the command line tells the writers.
struct output_options {
  format fmt = format::json;
  bool line_buffered = false;
  std::vector<std::string> types;  // only these types (the JSON "type"); empty: every type
  std::string output_dir;          // --format csv: one <TYPE>.csv per type here
};

// A message of a PGN without a description: its payload, written as its bytes.
struct raw_pgn {
  std::span<const std::uint8_t> payload;
};

// The CSV table of a message type of any wire: its header row, and a message's row. A PGN's table
// begins with the columns of the CAN frame's header (nmea2000::write_csv_header); every other
// table is the message's fields alone.
template <class M>
void csv_header(tools::output& out) {
  if constexpr (nmea2000::pgn_like<M>) {
    nmea2000::write_csv_header<M>(out);
  } else {
    write_csv_columns<M>(out);
  }
}
template <class M>
void csv_row(tools::output& out, const M& msg, const nmea2000::message_header* head) {
  if constexpr (nmea2000::pgn_like<M>) {
    nmea2000::write_csv(out, *head, msg);
  } else {
    write_csv_cells(out, msg);
  }
}

// The CSV table of a message M of type `type`: the type's, and for a PGN whose layout a field
// picks (126208's function code), the layout's: "PGN126208_request".
template <class M>
std::string table_name(std::string_view type) {
  std::string out(type);
  if constexpr (nmea2000::pgn_like<M>) {
    seawire::nmea2000::pgn_table<M>.for_each([&](const auto& f, unsigned, std::uint16_t) {
      using F = std::remove_cvref_t<decltype(f)>;
      if constexpr (requires { F::is_match; }) {
        out += '_';
        out += F::value_type::from_raw(F::match_raw).name();
      }
    });
  }
  return out;
}
template <class M>
inline constexpr bool has_layouts = [] {
  if constexpr (nmea2000::pgn_like<M>) {
    return nmea2000::description_of<M>::has_match;
  } else {
    return false;
  }
}();

// Writes the CSV header of the type JSON calls `type` (GPRMC, CPNVG, AB00; of a PGN with several
// layouts, the first's, whose table name goes to `layout`); false when no message of the set,
// nor the frame, has that type.
template <class Set>
struct csv_headers;
template <class... Ms>
struct csv_headers<nmea::message_set<Ms...>> {
  static bool write(std::string_view type, tools::output& out, std::string& layout) {
    layout = type;
    if (type == anello::frame_json_type) {
      csv_header<anello::sensor_frame_raw>(out);
      return true;
    }
    if (const auto pgn = nmea2000::pgn_of_type(type)) {
      bool found = false;
      n2k_pgns::for_each_type([&](const auto& tag) {
        using P = std::remove_cvref_t<decltype(tag)>;
        if (seawire::nmea2000::pgn_table<P>.info.pgn != *pgn || found) return;
        csv_header<P>(out);
        layout = table_name<P>(type);
        found = true;
      });
      return found;
    }
    return ((Ms::nmea.matches(type) ? (csv_header<Ms>(out), true) : false) || ...);
  }
  static bool knows(std::string_view type) {
    if (const auto pgn = nmea2000::pgn_of_type(type)) return n2k_pgns::knows(*pgn);
    return type == anello::frame_json_type || (Ms::nmea.matches(type) || ...);
  }
};
using all_headers = csv_headers<all_messages>;

// One CSV table: a file of its own (--output-dir) with its header written once, or stdout.
struct csv_table {
  std::string name;  // for errors: the file's path, or "stdout"
  std::FILE* file = nullptr;
  std::unique_ptr<tools::output> out;  // while the table is open
  bool header = false;
  std::string layout;           // whose header it has: table_name of the first row's message
  bool created = false;         // the file was created (later opened to append)
  std::uint64_t last_used = 0;  // when a row last went to it, for closing the least recent
  csv_table() = default;
  csv_table(const csv_table&) = delete;
  csv_table& operator=(const csv_table&) = delete;
  ~csv_table() {
    out.reset();
    if (file != nullptr) std::fclose(file);
  }
};

// At most this many tables' files are open at once (and fewer when the process may open fewer
// files): the least recently used one is closed to open another, and opened again to append.
constexpr std::size_t max_open_tables = 32;

// The progress line: on stderr when it is a terminal, stdin a regular file (whose size is known)
// and stdout not a terminal (whose output would run into the line); at most ten times a second,
// erased at the end and before anything else is written to stderr.
class progress {
 public:
  explicit progress(bool wanted) {
    struct stat st {};
    if (wanted && ::isatty(2) == 1 && ::isatty(1) == 0 && ::fstat(0, &st) == 0 &&
        S_ISREG(st.st_mode)) {
      total_ = static_cast<std::uint64_t>(st.st_size);
      on_ = true;
    }
  }
  progress(const progress&) = delete;
  progress& operator=(const progress&) = delete;
  ~progress() { done(); }

  void update(std::uint64_t bytes, std::uint64_t decoded, std::uint64_t rejected) {
    if (!on_) return;
    read_ += bytes;
    const auto now = std::chrono::steady_clock::now();
    if (shown_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    shown_ = true;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    const double rate = seconds > 0 ? static_cast<double>(decoded) / seconds : 0;
    std::fprintf(
        stderr,
        "\rseawire-decode: %.1f of %.1f MB (%.0f%%), %llu messages, %.0f messages/s, "
        "%llu rejected\033[K",
        static_cast<double>(read_) / 1e6, static_cast<double>(total_) / 1e6,
        total_ > 0 ? 100.0 * static_cast<double>(read_) / static_cast<double>(total_) : 100.0,
        static_cast<unsigned long long>(decoded), rate, static_cast<unsigned long long>(rejected));
    std::fflush(stderr);
  }

  // Erases the line (shown again at the next update), so a message on stderr starts clean.
  void erase() {
    if (on_ && shown_) {
      std::fputs("\r\033[K", stderr);
      std::fflush(stderr);
    }
    shown_ = false;
  }

  // Erases the line for good.
  void done() {
    erase();
    on_ = false;
  }

 private:
  bool on_ = false;
  bool shown_ = false;
  std::uint64_t total_ = 0;
  std::uint64_t read_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_{};
};

// What seawire-decode says on stderr about the input, line by line (rejected lines with every
// format but json, tables that cannot be written, sentences left out of the tables): at most
// max_log_lines lines a second, so that a flood of bad input cannot flood stderr. The lines held
// back are counted, and their number said before the next line let out, and at the end.
class stderr_log {
 public:
  static constexpr std::uint64_t max_log_lines = 100;

  explicit stderr_log(progress& shown) : progress_(shown) {}
  stderr_log(const stderr_log&) = delete;
  stderr_log& operator=(const stderr_log&) = delete;
  ~stderr_log() { finish(); }

  // Whether a line may be written now (the caller writes it); false counts it as held back.
  [[nodiscard]] bool allow() {
    const auto now = std::chrono::steady_clock::now();
    if (written_ == 0 || now - since_ >= std::chrono::seconds(1)) {
      finish();
      since_ = now;
      written_ = 0;
    }
    if (written_ >= max_log_lines) {
      ++held_;
      return false;
    }
    ++written_;
    progress_.erase();
    return true;
  }

  // Says how many lines were held back since the last it said, if any.
  void finish() {
    if (held_ == 0) return;
    progress_.erase();
    std::fprintf(stderr,
                 "seawire-decode: ... %llu more line%s like these not shown (at most %llu a "
                 "second are; --stats counts every rejected line by error)\n",
                 static_cast<unsigned long long>(held_), held_ == 1 ? "" : "s",
                 static_cast<unsigned long long>(max_log_lines));
    held_ = 0;
  }

 private:
  progress& progress_;
  std::chrono::steady_clock::time_point since_{};  // the start of this second's lines
  std::uint64_t written_ = 0;                      // lines written since then
  std::uint64_t held_ = 0;                         // lines held back, not said yet
};

// --stats counts messages by type, and --format csv sentences left out of the tables by
// address, for at most this many types each: garbage that parses as sentences of ever new
// addresses is counted as "other types" beyond, so memory stays bounded.
constexpr std::size_t max_counted_types = 4096;

// Adds one to `counts[key]`, or to `others` once `counts` holds max_counted_types keys.
inline void count_type(std::map<std::string, std::uint64_t, std::less<>>& counts,
                       std::uint64_t& others, std::string_view key) {
  if (const auto it = counts.find(key); it != counts.end()) {
    ++it->second;
  } else if (counts.size() < max_counted_types) {
    counts.emplace(std::string(key), 1);
  } else {
    ++others;
  }
}

// ---- the output formats ----
//
// Each format is a writer of its own: it is given every message decoded (message), every line
// rejected and every run of bytes the stream reader dropped (rejected), and the end of the input
// (finish). The decoder decides what is a message, and counts; the writer what goes out, where.

// Where a message came from, for the writers that need more than the message: a sentence's line,
// address and policy (--format nmea names it when it cannot re-encode it), a PGN's CAN frame header
// (JSON and CSV write it) and payload (--format canboat shows its reserved bits, and reads a
// short one as canboat does).
struct origin {
  const nmea::framed_line* line = nullptr;
  std::string_view address;
  const nmea::parse_policy* policy = nullptr;
  const nmea2000::message_header* head = nullptr;
  std::span<const std::uint8_t> payload;
};

// A line rejected, or a run of bytes dropped: where, why, and the input (as much of it as the
// decoder shows).
struct rejection {
  std::uint64_t line = 0;
  errc ec = errc::ok;
  std::uint16_t field = 0;
  std::string_view detail;
  std::string_view input;
};

// Why a writer could not write a message (a sentence --format nmea cannot re-encode): its line
// is rejected for it.
struct refusal {
  errc ec = errc::ok;
  std::uint16_t field = 0;
  std::string detail;
};

// What every format has: stdout, and the stderr log, where rejected input is said (at the log's
// rate, after stdout is written out, so that the two stay in order where they meet).
class stdio_writer {
 public:
  // Why a writer cannot write a CAN log, or sentences (nullptr: it can).
  static constexpr const char* refuses_can_log = nullptr;
  static constexpr const char* refuses_sentences = nullptr;

  stdio_writer(const output_options& o, progress& shown)
      : log_(shown), line_buffered_(o.line_buffered) {}
  stdio_writer(const stdio_writer&) = delete;
  stdio_writer& operator=(const stdio_writer&) = delete;

  void rejected(const rejection& r) {
    if (!log_.allow()) return;
    out_.flush();
    say(r);
  }

  void finish() {
    out_.flush();
    log_.finish();
  }

  [[nodiscard]] const tools::output& out() const { return out_; }
  // Whether every table was written (the formats without tables: true).
  [[nodiscard]] static bool tables_written() { return true; }

 protected:
  static void say(const rejection& r) {
    const std::string_view e = name(r.ec);
    std::fprintf(stderr, "seawire-decode: line %llu: %.*s: %.*s\n",
                 static_cast<unsigned long long>(r.line), static_cast<int>(e.size()), e.data(),
                 static_cast<int>(r.detail.size()), r.detail.data());
  }

  // After each message: out at once on a live stream.
  void written() {
    if (line_buffered_) out_.flush();
  }

  tools::output out_{stdout};
  stderr_log log_;
  bool line_buffered_;
};

// --format json: one JSON object a line per message, and per rejected line, on stdout in order.
class json_writer : public stdio_writer {
 public:
  using stdio_writer::stdio_writer;

  template <class M>
  std::optional<refusal> message(std::string_view /*type*/, const M& msg, const origin& from) {
    if constexpr (nmea2000::pgn_like<M>) {
      nmea2000::write_json(out_, *from.head, msg);
    } else if constexpr (std::is_same_v<M, raw_pgn>) {
      nmea2000::write_json_raw(out_, *from.head, msg.payload);
    } else if constexpr (std::is_same_v<M, anello::sensor_frame_raw>) {
      anello::write_json(out_, msg);
    } else {
      nmea::write_json(out_, msg);
    }
    out_.put('\n');
    written();
    return std::nullopt;
  }

  void rejected(const rejection& r) {
    nmea::write_json_error(out_, r.line, r.ec, r.field, r.detail, r.input);
    out_.put('\n');
    written();
  }
};

// --format nmea: each sentence re-encoded by the rules seawire sends by, each frame as its bytes.
class nmea_writer : public stdio_writer {
 public:
  static constexpr const char* refuses_can_log =
      "seawire-decode: the input is a CAN log (NMEA 2000), which has no sentences to re-encode: "
      "use --format json (and seawire-encode --output FORMAT to write a log again)\n";

  using stdio_writer::stdio_writer;

  template <class M>
  std::optional<refusal> message(std::string_view /*type*/, const M& msg, const origin& from) {
    if constexpr (std::is_same_v<M, anello::sensor_frame_raw>) {
      const anello::frame_bytes bytes = anello::encode_frame(msg);
      out_.put(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    } else if constexpr (!nmea2000::pgn_like<M> && !std::is_same_v<M, raw_pgn>) {
      if (std::optional<refusal> no = reencode(from, msg)) return no;
    }
    written();
    return std::nullopt;
  }

 private:
  template <class M>
  std::optional<refusal> reencode(const origin& from, const M& msg) {
    std::array<char, 1100> buf;
    result<std::size_t> r;
    if constexpr (std::is_same_v<M, nmea::unknown_sentence>) {
      // Not ours to interpret: the same start ('$' or '!') and fields, sealed the way seawire
      // seals.
      const nmea::sentence_view& s = msg.sentence;
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
      std::string detail = std::string(from.address) + " cannot be re-encoded";
      if (r.field != 0) {
        // The field named as the sentence has it (a message with a variable number of fields
        // names them by their count): the line split again, by the rules it was decoded by.
        const result<nmea::sentence_view> s = nmea::parse(from.line->text, *from.policy);
        const nmea::field_about a =
            all_messages::about_field(from.address, r.field, s ? s.value.field_count : 0);
        detail += ": field " + std::to_string(r.field) + " (" + std::string(a.name);
        if (!a.part.empty()) detail += "'s " + std::string(a.part);
        detail += ")";
      }
      detail += ": " + std::string(seawire::message(r.ec));
      return refusal{r.ec, r.field, std::move(detail)};
    }
    out_.put(std::string_view(buf.data(), r.value));
    return std::nullopt;
  }
};

// --format none: nothing on stdout (the verdict is the exit status, and --stats).
class none_writer : public stdio_writer {
 public:
  using stdio_writer::stdio_writer;

  template <class M>
  std::optional<refusal> message(std::string_view /*type*/, const M& /*msg*/,
                                 const origin& /*from*/) {
    written();
    return std::nullopt;
  }
};

// --format csv: a table per type, in a file of its own (--output-dir) or the one on stdout.
class csv_writer : public stdio_writer {
 public:
  csv_writer(const output_options& o, progress& shown)
      : stdio_writer(o, shown), dir_(o.output_dir) {
    // The one table on stdout has its header even when no message of its type comes.
    if (o.output_dir.empty() && o.types.size() == 1) {
      if (csv_table* t = table(o.types.front()))
        t->header = all_headers::write(o.types.front(), *t->out, t->layout);
    }
  }

  template <class M>
  std::optional<refusal> message(std::string_view type, const M& msg, const origin& from) {
    if constexpr (walkable<M>) {
      // A table per layout of a PGN with several (a file each); on stdout, the first layout's
      // rows, the others counted and left out.
      std::string layout;
      if constexpr (has_layouts<M>) layout = table_name<M>(type);
      const std::string_view name = layout.empty() ? type : std::string_view(layout);
      if (csv_table* t = table(dir_.empty() ? type : name)) {
        if (!t->header) {
          csv_header<M>(*t->out);
          t->layout = name;
        }
        t->header = true;
        if (t->layout == name) {
          csv_row(*t->out, msg, from.head);
          if (line_buffered_) t->out->flush();
        } else {
          count_type(other_layout_, other_not_tabled_, name);
        }
      }
    } else {
      count_type(not_tabled_, other_not_tabled_, type);
    }
    written();
    return std::nullopt;
  }

  void rejected(const rejection& r) {
    if (!log_.allow()) return;
    out_.flush();
    if (stdout_table_ != nullptr) stdout_table_->out->flush();
    say(r);
  }

  void finish() {
    for (auto& [type, t] : tables_) {
      // Not created, or closed: reported then.
      if (t == nullptr || t->out == nullptr) continue;
      if (t->file != nullptr) {
        close_table(*t);
        continue;
      }
      t->out->flush();
      if (t->out->failed()) {
        if (log_.allow())
          std::fprintf(stderr, "seawire-decode: writing %s: %s\n", t->name.c_str(),
                       std::strerror(t->out->error()));
        ++table_failures_;
      }
    }
    for (const auto& [type, n] : not_tabled_) {
      if (!log_.allow()) continue;
      std::fprintf(stderr,
                   "seawire-decode: %llu %s message%s left out of the CSV output: no "
                   "description says their fields\n",
                   static_cast<unsigned long long>(n), type.c_str(), n == 1 ? "" : "s");
    }
    for (const auto& [layout, n] : other_layout_) {
      if (!log_.allow() || stdout_table_ == nullptr) continue;
      std::fprintf(stderr,
                   "seawire-decode: %llu %s message%s left out of the CSV output: the table on "
                   "stdout is %s's (--output-dir writes a table per layout)\n",
                   static_cast<unsigned long long>(n), layout.c_str(), n == 1 ? "" : "s",
                   stdout_table_->layout.c_str());
    }
    if (other_not_tabled_ > 0 && log_.allow()) {
      std::fprintf(stderr,
                   "seawire-decode: %llu more messages of other types left out of the CSV "
                   "output\n",
                   static_cast<unsigned long long>(other_not_tabled_));
    }
    stdio_writer::finish();
  }

  [[nodiscard]] bool tables_written() const { return table_failures_ == 0; }

 private:
  [[nodiscard]] std::string table_path(const std::string& type) const {
    return (std::filesystem::path(dir_) / (type + ".csv")).string();
  }

  // The table of a type, open: stdout when there is no output directory (one type only), else
  // the type's file, created when its first message comes. nullptr when it cannot be created
  // (or opened again, or was not written).
  csv_table* table(std::string_view type) {
    ++table_clock_;
    auto it = tables_.find(type);
    if (it != tables_.end()) {
      csv_table* t = it->second.get();
      if (t != nullptr && t->out == nullptr && !open_table(*t)) {
        it->second.reset();
        return nullptr;
      }
      if (t != nullptr) t->last_used = table_clock_;
      return t;
    }
    auto t = std::make_unique<csv_table>();
    if (dir_.empty()) {
      t->name = "stdout";
      t->out = std::make_unique<tools::output>(stdout);
      stdout_table_ = t.get();
    } else {
      t->name = table_path(std::string(type));
      if (!open_table(*t)) {
        tables_.emplace(std::string(type), nullptr);
        return nullptr;
      }
    }
    t->last_used = table_clock_;
    return tables_.emplace(std::string(type), std::move(t)).first->second.get();
  }

  // Opens a table's file: created (replacing a file of its name) the first time, appended to
  // after. The least recently used table is closed first when max_open_tables are open, or when
  // the process may open no more files. False, reported, when it cannot be opened.
  bool open_table(csv_table& t) {
    if (open_tables_ >= max_open_tables) close_least_used();
    for (;;) {
      t.file = std::fopen(t.name.c_str(), t.created ? "a" : "w");
      if (t.file != nullptr) break;
      const int e = errno;
      if ((e == EMFILE || e == ENFILE) && close_least_used()) continue;
      if (log_.allow())
        std::fprintf(stderr, "seawire-decode: cannot %s %s: %s\n", t.created ? "reopen" : "create",
                     t.name.c_str(), std::strerror(e));
      ++table_failures_;
      return false;
    }
    t.created = true;
    ++open_tables_;
    // Small buffers: a log may hold many types (one per talker of RMC, GGA, ...).
    t.out = std::make_unique<tools::output>(t.file, 16 * 1024);
    return true;
  }

  // Writes out a table and closes its file; false, reported, when the writing failed (the
  // table is then written no more). The table stays, to be opened again.
  bool close_table(csv_table& t) {
    t.out->flush();
    const bool ok = !t.out->failed();
    if (!ok) {
      if (log_.allow())
        std::fprintf(stderr, "seawire-decode: writing %s: %s\n", t.name.c_str(),
                     std::strerror(t.out->error()));
      ++table_failures_;
    }
    t.out.reset();
    std::fclose(t.file);
    t.file = nullptr;
    --open_tables_;
    return ok;
  }

  // Closes the open file table used least recently; false when none is open.
  bool close_least_used() {
    std::unique_ptr<csv_table>* least = nullptr;
    for (auto& [type, t] : tables_) {
      if (t == nullptr || t->file == nullptr) continue;
      if (least == nullptr || t->last_used < (*least)->last_used) least = &t;
    }
    if (least == nullptr) return false;
    if (!close_table(**least)) least->reset();
    return true;
  }

  std::string dir_;  // --output-dir; empty: the one table goes to stdout
  std::map<std::string, std::unique_ptr<csv_table>, std::less<>> tables_;
  std::size_t open_tables_ = 0;                                   // tables whose file is open
  std::uint64_t table_clock_ = 0;                                 // counts the rows, for last_used
  std::map<std::string, std::uint64_t, std::less<>> not_tabled_;  // unknown sentences, by address
  std::map<std::string, std::uint64_t, std::less<>> other_layout_;  // not the stdout table's
  std::uint64_t other_not_tabled_ = 0;  // those of addresses past max_counted_types
  std::uint64_t table_failures_ = 0;
  csv_table* stdout_table_ = nullptr;  // the one table written to stdout, once it exists
};

// --format geojson and svg: the tracks of every source of positions (track.hpp), written at the
// end.
class track_writer : public stdio_writer {
 public:
  using stdio_writer::stdio_writer;

  template <class M>
  std::optional<refusal> message(std::string_view type, const M& msg, const origin& /*from*/) {
    if constexpr (walkable<M>) tracks_.add(type, msg);
    written();
    return std::nullopt;
  }

 protected:
  tools::tracks tracks_;
};

class geojson_writer : public track_writer {
 public:
  using track_writer::track_writer;
  void finish() {
    tracks_.write_geojson(out_);
    stdio_writer::finish();
  }
};

class svg_writer : public track_writer {
 public:
  using track_writer::track_writer;
  void finish() {
    tracks_.write_svg(out_);
    stdio_writer::finish();
  }
};

// --format canboat: each PGN as canboat's `analyzer -json` writes it (canboat_json.hpp), one a
// line; rejected lines on stderr, as analyzer reports them.
class canboat_writer : public stdio_writer {
 public:
  static constexpr const char* refuses_sentences =
      "seawire-decode: --format canboat writes NMEA 2000 messages as canboat's analyzer does; the "
      "input is sentences (NMEA 0183 or ANELLO frames), which it has none of: use --format json\n";

  using stdio_writer::stdio_writer;

  template <class M>
  std::optional<refusal> message(std::string_view /*type*/, const M& msg, const origin& from) {
    line_.clear();
    bool shown = true;
    if constexpr (nmea2000::pgn_like<M>) {
      shown = canboat::put_message(line_, *from.head, msg, from.payload,
                                   canboat::timestamp(*from.head));
    } else if constexpr (std::is_same_v<M, raw_pgn>) {
      canboat::put_raw_message(line_, *from.head, msg.payload, canboat::timestamp(*from.head));
    } else {
      return std::nullopt;  // a sentence: the input was refused before any was read
    }
    if (shown) {
      line_ += '\n';
      out_.put(line_);
    } else if (log_.allow()) {
      out_.flush();
      std::fprintf(stderr,
                   "seawire-decode: PGN %u from %u: a field canboat's analyzer cannot read (a "
                   "date cut to one byte, a group function's parameter that is no field of the "
                   "PGN it names); not written, as analyzer writes nothing of such a message\n",
                   static_cast<unsigned>(from.head->id.pgn),
                   static_cast<unsigned>(from.head->id.source));
    }
    written();
    return std::nullopt;
  }

 private:
  std::string line_;  // the message's line, built whole: analyzer writes all of it or nothing
};

// The writer of the format asked for: the one place the formats are told apart.
class sink {
 public:
  sink(const output_options& o, progress& shown) : w_(make(o, shown)) {}

  // A message decoded (a sentence, known or not; a PGN, described or not; a frame), of JSON type
  // `type`; a refusal when it cannot be written.
  template <class M>
  [[nodiscard]] std::optional<refusal> message(std::string_view type, const M& msg,
                                               const origin& from) {
    return std::visit([&](auto& w) { return w.message(type, msg, from); }, w_);
  }
  void rejected(const rejection& r) {
    std::visit([&](auto& w) { w.rejected(r); }, w_);
  }
  void finish() {
    std::visit([](auto& w) { w.finish(); }, w_);
  }

  // Why the format cannot be written of a CAN log, or of sentences (nullptr: it can).
  [[nodiscard]] const char* refuses_can_log() const {
    return std::visit(
        [](const auto& w) { return std::remove_cvref_t<decltype(w)>::refuses_can_log; }, w_);
  }
  [[nodiscard]] const char* refuses_sentences() const {
    return std::visit(
        [](const auto& w) { return std::remove_cvref_t<decltype(w)>::refuses_sentences; }, w_);
  }
  // stdout failed (the tables' failures are reported as they are found).
  [[nodiscard]] const tools::output& out() const {
    return std::visit([](const stdio_writer& w) -> const tools::output& { return w.out(); }, w_);
  }
  // Everything written: stdout and every table.
  [[nodiscard]] bool all_written() const {
    return !out().failed() && std::visit([](const auto& w) { return w.tables_written(); }, w_);
  }

 private:
  using writers = std::variant<json_writer, nmea_writer, none_writer, csv_writer, geojson_writer,
                               svg_writer, canboat_writer>;

  static writers make(const output_options& o, progress& shown) {
    switch (o.fmt) {
      case format::nmea: return writers(std::in_place_type<nmea_writer>, o, shown);
      case format::none: return writers(std::in_place_type<none_writer>, o, shown);
      case format::csv: return writers(std::in_place_type<csv_writer>, o, shown);
      case format::geojson: return writers(std::in_place_type<geojson_writer>, o, shown);
      case format::svg: return writers(std::in_place_type<svg_writer>, o, shown);
      case format::canboat: return writers(std::in_place_type<canboat_writer>, o, shown);
      case format::json: break;
    }
    return writers(std::in_place_type<json_writer>, o, shown);
  }

  writers w_;
};

}  // namespace seawire::tools
