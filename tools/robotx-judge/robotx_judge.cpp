// SPDX-License-Identifier: BSL-1.0
// seawire-robotx-judge: the Technical Director's server of the 2018 Maritime RobotX Challenge,
// for rehearsing a team's reports. Every line a team sends is judged as it arrives by
// robotx::validator; each rule broken is printed at once, RXCOD, RXDOK and RXDEL are echoed back
// as the judges' system does, and a summary per team is printed at the end.
// Manual: tools/robotx-judge/README.md.

#include <CLI/CLI.hpp>
#include <asio.hpp>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <seawire/nmea/stream.hpp>
#include <seawire/nmea/writer.hpp>
#include <seawire/robotx/messages.hpp>
#include <seawire/robotx/validator.hpp>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "cli.hpp"
#include "log_limit.hpp"
#include "net.hpp"

namespace {

using namespace seawire;
namespace rx = seawire::robotx;
namespace net = seawire::tools::net;
using json = nlohmann::ordered_json;

struct options {
  std::string listen = "0.0.0.0:12345";
  std::string team;
  double clock_tolerance = 0;
  double gap_limit = 1.5;
  double jitter = 0.05;
  std::string report = "text";
  double duration = 0;
  net::server_limits limits;
};

std::string iso(rx::instant t) {
  using namespace std::chrono;
  const auto day = floor<days>(t);
  const year_month_day ymd(day);
  const hh_mm_ss hms(floor<milliseconds>(t - day));
  char buf[40];
  std::snprintf(buf, sizeof buf, "%04d-%02u-%02uT%02d:%02d:%02d.%03dZ", int(ymd.year()),
                unsigned(ymd.month()), unsigned(ymd.day()), int(hms.hours().count()),
                int(hms.minutes().count()), int(hms.seconds().count()),
                int(hms.subseconds().count()));
  return buf;
}

double seconds(std::chrono::nanoseconds d) { return std::chrono::duration<double>(d).count(); }

// What the stream reader gave up on, shown as text: bytes outside printable ASCII as \xHH.
std::string shown(std::string_view bytes) {
  std::string out;
  for (const char ch : bytes) {
    const auto b = static_cast<unsigned char>(ch);
    if (b >= 0x20 && b <= 0x7E && b != '\\') {
      out += ch;
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", unsigned{b});
      out += hex;
    }
  }
  return out;
}

// A report the stream reader dropped, as a framing finding: the decoder's reason and why.
struct dropped_report {
  errc ec = errc::ok;
  std::string why;
};
dropped_report judged(const nmea::stream_drop& d, std::size_t capacity) {
  const std::string_view b = d.bytes;
  switch (d.reason) {
    case nmea::drop_reason::invalid_byte: {
      std::size_t at = 0;
      while (at < b.size() && static_cast<unsigned char>(b[at]) >= 0x20 &&
             static_cast<unsigned char>(b[at]) <= 0x7E)
        ++at;
      char why[96];
      std::snprintf(why, sizeof why, "a byte outside printable ASCII (0x%02X at byte %zu)",
                    at < b.size() ? unsigned{static_cast<unsigned char>(b[at])} : 0U, at + 1);
      return {errc::bad_character, why};
    }
    case nmea::drop_reason::overlong:
      return {errc::too_long, "longer than " + std::to_string(capacity) + " bytes (" +
                                  std::to_string(d.size) + " bytes dropped)"};
    case nmea::drop_reason::interrupted:
      return {errc::truncated, "cut short: a '$' came before its checksum and line ending"};
    default: return {errc::missing_start, "not a sentence: no '$' first"};
  }
}

// One connection: its own validator (heartbeat gaps and rates are per link).
struct team_link {
  std::uint64_t id = 0;
  std::string peer;
  std::string team;  // the first team id it reported
  rx::validator validator;
  std::uint64_t dropped = 0;  // reports the stream reader dropped (framing findings)
};

// A team's totals over all its connections.
struct team_summary {
  std::vector<std::string> peers;  // the last max_peers connections' addresses
  std::uint64_t connections = 0;
  std::uint64_t lines = 0;
  std::uint64_t accepted = 0;
  std::array<std::uint64_t, rx::rule_count> findings{};
  std::map<std::string, std::uint64_t> reports;  // accepted reports by address
};

// The summary is bounded whatever the teams send: so many teams (ids first reported) by name,
// those after them summed as one, and the addresses of each team's last connections.
constexpr std::size_t max_teams = 100;
constexpr std::size_t max_peers = 10;
constexpr const char* other_teams = "(other teams)";
// Findings printed per rule: at most 20 a second, the rest counted ("... K more rate findings
// suppressed"); the summary counts them all.
constexpr std::uint32_t findings_per_second = 20;

class judge {
 public:
  judge(asio::io_context& io, const options& o, const asio::ip::tcp::endpoint& where)
      : o_(o), server_(io, where, o.limits), timer_(io) {
    for (std::size_t i = 0; i < rx::rule_count; ++i)
      limits_.emplace_back(std::string(name(static_cast<rx::rule>(i))) + " findings",
                           findings_per_second);
    config_.heartbeat_gap_limit = std::chrono::duration_cast<std::chrono::nanoseconds>(
        std::chrono::duration<double>(o.gap_limit));
    if (!o.team.empty()) config_.expected_team = rx::team(o.team);
    // Arrival times carry the network's jitter: reports sent exactly 1 s apart may arrive a
    // little less than 1 s apart, which is not the sender's fault.
    config_.min_interval = std::chrono::duration_cast<std::chrono::nanoseconds>(
        std::chrono::duration<double>(1.0 - o.jitter));
    if (o.clock_tolerance > 0)
      config_.clock_tolerance = std::chrono::duration_cast<std::chrono::nanoseconds>(
          std::chrono::duration<double>(o.clock_tolerance));
    server_.on_connect([this](net::client& c) {
      auto link =
          std::make_unique<team_link>(team_link{c.id(), c.peer(), {}, rx::validator(config_)});
      link->validator.start(now());
      links_.emplace(c.id(), std::move(link));
    });
    server_.on_sentence(
        [this](net::client& c, const nmea::framed_line& line) { received(c, line); });
    server_.on_drop([this](net::client& c, const nmea::stream_drop& d) { dropped(c, d); });
    server_.on_close([this](net::client& c, std::string_view) {
      const auto it = links_.find(c.id());
      if (it == links_.end()) return;
      print(*it->second, it->second->validator.finish(now()));
      add_to_summary(*it->second);
      links_.erase(it);
    });
  }

  [[nodiscard]] asio::ip::tcp::endpoint local_endpoint() const { return server_.local_endpoint(); }
  std::function<void()> on_stopped;
  void signalled(int signo) { stop(net::signal_name(signo)); }

  void start() {
    server_.start();
    started_ = now();
    tick();
  }

  void stop(std::string_view why) {
    if (stopped_) return;
    stopped_ = true;
    timer_.cancel();
    // Every link ends now: an open heartbeat gap is reported, and its totals summed.
    const auto t = now();
    for (auto& [id, link] : links_) {
      print(*link, link->validator.finish(t));
      add_to_summary(*link);
    }
    links_.clear();
    server_.stop(why);
    for (tools::log_limit& l : limits_) l.flush(note(l));
    net::line_server::log("stopped (%.*s): %llu connections", static_cast<int>(why.size()),
                          why.data(), static_cast<unsigned long long>(server_.connections()));
    summary();
    if (on_stopped) on_stopped();
  }

 private:
  static rx::instant now() {
    return std::chrono::time_point_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now());
  }

  // Heartbeat gaps are reported while they are open, not only when the next heartbeat comes.
  void tick() {
    timer_.expires_after(std::chrono::milliseconds(100));
    timer_.async_wait([this](const asio::error_code& ec) {
      if (ec || stopped_) return;
      const auto t = now();
      for (auto& [id, link] : links_) print(*link, link->validator.advance(t));
      for (tools::log_limit& l : limits_) l.poll(note(l));
      if (o_.duration > 0 && seconds(t - started_) >= o_.duration) {
        stop("--duration reached");
        return;
      }
      tick();
    });
  }

  void received(net::client& c, const nmea::framed_line& line) {
    const auto it = links_.find(c.id());
    if (it == links_.end()) return;
    team_link& link = *it->second;
    // The validator judges the line ending too: give it the line as it came.
    std::string raw(line.text);
    switch (line.ending) {
      case nmea::line_ending::crlf: raw += "\r\n"; break;
      case nmea::line_ending::lf: raw += "\n"; break;
      case nmea::line_ending::cr: raw += "\r"; break;
      case nmea::line_ending::none: break;
    }
    const auto verdict = link.validator.check(raw, now());
    if (verdict.accepted) {
      std::visit(
          [&](const auto& m) {
            using T = std::decay_t<decltype(m)>;
            if constexpr (requires { m.team_id; }) {
              if (link.team.empty()) link.team = std::string(m.team_id.view());
              ++reports_seen_[link.id][std::string(T::nmea.address)];
            }
            // The judges' system echoes these three back to confirm their reception.
            if constexpr (std::is_same_v<T, rx::rxcod> || std::is_same_v<T, rx::rxdok> ||
                          std::is_same_v<T, rx::rxdel>) {
              c.send(std::string(line.text) + "\r\n", 1);
            }
          },
          verdict.message);
    } else {
      ++c.rejected_in;
    }
    print(link, verdict.findings, line.text);
  }

  // A report the stream reader dropped (a tab, a byte outside ASCII, a NUL, too long, no '$'):
  // the team sent it, so it is judged, as a framing finding, and counted in the summary.
  void dropped(net::client& c, const nmea::stream_drop& d) {
    // Line breaks alone (a blank line) are no report.
    if (d.size == d.bytes.size() && d.bytes.find_first_not_of("\r\n") == std::string_view::npos)
      return;
    const auto it = links_.find(c.id());
    if (it == links_.end()) return;
    team_link& link = *it->second;
    ++link.dropped;
    ++c.rejected_in;
    const dropped_report r = judged(d, reader_capacity);
    rx::finding f;
    f.broken = rx::rule::framing;
    f.ec = r.ec;
    f.at = now();
    // The address, when the bytes start as a sentence does ("$RXHRB,").
    if (d.bytes.size() > 1 && d.bytes[0] == '$') {
      const std::string_view rest = d.bytes.substr(1);
      const auto end = rest.find(',');
      if (end != std::string_view::npos && nmea::is_address(rest.substr(0, end)))
        (void)f.address.assign(rest.substr(0, end));
    }
    rx::finding_list one;
    one.push(f);
    std::string input = shown(d.bytes);
    if (d.size > d.bytes.size()) input += "...";
    print(link, one, {}, r.why, input);
  }
  static constexpr std::size_t reader_capacity = 512;  // net::client's stream reader

  // What writes a rule's "... K more X suppressed" among the findings.
  [[nodiscard]] std::function<void(std::uint64_t)> note(const tools::log_limit& l) const {
    return [this, &l](std::uint64_t n) {
      if (o_.report == "json") {
        json j;
        j["type"] = "suppressed";
        j["what"] = l.what();
        j["count"] = n;
        std::printf("%s\n", j.dump().c_str());
      } else {
        std::printf("%s\n", l.note_text(n).c_str());
      }
      std::fflush(stdout);
    };
  }

  // `why` and `input`, when given, stand for what the finding's error and line would show.
  void print(const team_link& link, const rx::finding_list& findings, std::string_view line = {},
             std::string_view given_why = {}, std::string_view input = {}) {
    if (input.empty()) input = line;
    for (const rx::finding& f : findings) {
      if (!limits_[static_cast<std::size_t>(f.broken)].allow(
              note(limits_[static_cast<std::size_t>(f.broken)])))
        continue;
      const std::string_view rule = name(f.broken);
      const std::string_view address = f.address.view();
      const nmea::field_about about =
          f.field != 0 ? rx::reports::about_field(address, f.field) : nmea::field_about{};
      const std::string_view field = about.name;
      std::string why = !given_why.empty() ? std::string(given_why)
                        : f.ec != errc::ok ? std::string(message(f.ec))
                                           : std::string();
      if (f.field != 0 && about.explain != nullptr && !line.empty()) {
        // What the field's text shows is wrong (a sign before a position, a blank letter).
        nmea::parse_policy lax;
        lax.checksum = nmea::checksum_policy::ignore;
        lax.max_length = 0xFFFF;
        const result<nmea::sentence_view> s = nmea::parse(line, lax);
        if (s) {
          const std::string_view explained =
              about.explain(about.part_index, f.ec, s.value.field(f.field).text);
          if (!explained.empty()) why = explained;
        }
      }
      const std::string team = link.team.empty() ? std::string("?") : link.team;
      if (o_.report == "json") {
        json j;
        j["type"] = "finding";
        j["time"] = iso(f.at);
        j["client"] = link.id;
        j["peer"] = link.peer;
        j["team"] = link.team.empty() ? json(nullptr) : json(link.team);
        j["rule"] = rule;
        j["address"] = address;
        j["field"] = f.field;
        if (!field.empty()) j["field_name"] = field;
        if (!about.part.empty()) j["field_part"] = about.part;
        if (!why.empty()) j["error"] = why;
        if (f.elapsed.count() != 0) j["elapsed_s"] = seconds(f.elapsed);
        if (!input.empty()) j["input"] = input;
        std::printf("%s\n", j.dump().c_str());
      } else {
        std::string text = iso(f.at) + " client " + std::to_string(link.id) + " " + link.peer +
                           " team " + team + ": " + std::string(rule);
        if (!address.empty()) text += " " + std::string(address);
        if (f.field != 0) {
          text += " field " + std::to_string(f.field);
          if (!field.empty()) {
            text += " (" + std::string(field);
            if (!about.part.empty()) text += "'s " + std::string(about.part);
            text += ")";
          }
        }
        if (!why.empty()) text += ": " + why;
        if (!given_why.empty() && !input.empty()) text += ": " + std::string(input);
        char secs[32];
        std::snprintf(secs, sizeof secs, "%.3f", seconds(f.elapsed));
        if (f.broken == rx::rule::rate) text += ": " + std::string(secs) + " s after the last";
        if (f.broken == rx::rule::heartbeat_gap)
          text += ": no heartbeat for " + std::string(secs) + " s";
        if (f.broken == rx::rule::clock_skew)
          text += ": report time " + std::string(secs) + " s from arrival";
        std::printf("%s\n", text.c_str());
      }
    }
    std::fflush(stdout);
  }

  void add_to_summary(const team_link& link) {
    std::string key = link.team.empty() ? "(no team id)" : link.team;
    if (!teams_.contains(key) && teams_.size() >= max_teams) key = other_teams;
    team_summary& s = teams_[key];
    s.peers.push_back(link.peer);
    if (s.peers.size() > max_peers) s.peers.erase(s.peers.begin());
    ++s.connections;
    const auto& t = link.validator.totals();
    s.lines += t.lines + link.dropped;
    s.accepted += t.accepted;
    for (std::size_t i = 0; i < rx::rule_count; ++i) s.findings[i] += t.findings[i];
    s.findings[static_cast<std::size_t>(rx::rule::framing)] += link.dropped;
    for (const auto& [address, n] : reports_seen_[link.id]) s.reports[address] += n;
    reports_seen_.erase(link.id);
  }

  void summary() {
    if (o_.report == "json") {
      json j;
      j["type"] = "summary";
      j["teams"] = json::array();
      for (const auto& [team, s] : teams_) {
        json t;
        t["team"] = team;
        t["connections"] = s.connections;
        t["peers"] = s.peers;
        t["lines"] = s.lines;
        t["accepted"] = s.accepted;
        t["reports"] = s.reports;
        json f = json::object();
        for (std::size_t i = 0; i < rx::rule_count; ++i)
          if (s.findings[i] != 0) f[std::string(name(static_cast<rx::rule>(i)))] = s.findings[i];
        t["findings"] = f;
        j["teams"].push_back(t);
      }
      std::printf("%s\n", j.dump().c_str());
    } else {
      std::printf("summary: %zu team(s)\n", teams_.size());
      for (const auto& [team, s] : teams_) {
        std::string reports, findings;
        for (const auto& [address, n] : s.reports)
          reports += (reports.empty() ? "" : ", ") + address + " " + std::to_string(n);
        for (std::size_t i = 0; i < rx::rule_count; ++i)
          if (s.findings[i] != 0)
            findings += (findings.empty() ? "" : ", ") +
                        std::string(name(static_cast<rx::rule>(i))) + " " +
                        std::to_string(s.findings[i]);
        std::printf("  %s: %llu connection(s), %llu lines, %llu accepted (%s); findings: %s\n",
                    team.c_str(), static_cast<unsigned long long>(s.connections),
                    static_cast<unsigned long long>(s.lines),
                    static_cast<unsigned long long>(s.accepted),
                    reports.empty() ? "no reports" : reports.c_str(),
                    findings.empty() ? "none" : findings.c_str());
      }
    }
    std::fflush(stdout);
  }

  const options& o_;
  rx::validator_config config_;
  net::line_server server_;
  asio::steady_timer timer_;
  rx::instant started_{};
  std::map<std::uint64_t, std::unique_ptr<team_link>> links_;
  std::map<std::uint64_t, std::map<std::string, std::uint64_t>> reports_seen_;
  std::map<std::string, team_summary> teams_;  // at most max_teams + 1 (other_teams)
  std::vector<tools::log_limit> limits_;       // per rule
  bool stopped_ = false;
};

}  // namespace

int main(int argc, char** argv) {
  options o;
  CLI::App app{
      "The RobotX Technical Director's server, for rehearsal: judges every report a team sends\n"
      "as it arrives (checksum, fields, team id, 1 Hz rate, heartbeat gaps, line endings),\n"
      "prints each rule broken at once on stdout, echoes RXCOD, RXDOK and RXDEL back, and\n"
      "prints a summary per team when stopped.",
      "seawire-robotx-judge"};
  app.add_option("--listen", o.listen, "ADDR:PORT to listen on (port 0: any free port)")
      ->capture_default_str();
  app.add_option("--team", o.team, "the team id every report must carry (5 characters)")
      ->check([](const std::string& t) {
        return t.size() == 5 ? std::string() : std::string("a team id has 5 characters");
      });
  app.add_option("--gap-limit", o.gap_limit,
                 "seconds without an accepted heartbeat that count as a gap")
      ->check(seawire::tools::finite_number)
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--jitter", o.jitter,
                 "seconds by which two reports of a type may arrive closer than 1 s apart without "
                 "breaking the rate rule (network jitter)")
      ->check(seawire::tools::finite_number)
      ->check(CLI::Range(0.0, 0.5))
      ->capture_default_str();
  app.add_option("--clock-tolerance", o.clock_tolerance,
                 "flag reports whose HST time is further than this many seconds from their "
                 "arrival (0: off)")
      ->check(seawire::tools::finite_number)
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--report", o.report,
                 "text: one line per finding and a summary; json: one JSON object per line")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  app.add_option("--duration", o.duration, "stop after this many seconds (0: at SIGINT/SIGTERM)")
      ->check(seawire::tools::finite_number)
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--max-clients", o.limits.max_clients, "connections beyond this are closed")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  if (const auto status = seawire::tools::parse_command_line(app, argc, argv)) return *status;

  const auto where = net::listen_option("seawire-robotx-judge", o.listen);
  if (!where) return 2;
  return net::serve("seawire-robotx-judge", o.listen, *where,
                    [&](asio::io_context& io, const asio::ip::tcp::endpoint& at) {
                      return std::make_unique<judge>(io, o, at);
                    });
}
