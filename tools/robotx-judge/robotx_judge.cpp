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
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <seawire/robotx/messages.hpp>
#include <seawire/robotx/validator.hpp>
#include <string>
#include <variant>

#include "cli.hpp"
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

// One connection: its own validator (heartbeat gaps and rates are per link).
struct team_link {
  std::uint64_t id = 0;
  std::string peer;
  std::string team;  // the first team id it reported
  rx::validator validator;
};

// A team's totals over all its connections.
struct team_summary {
  std::vector<std::string> peers;
  std::uint64_t connections = 0;
  std::uint64_t lines = 0;
  std::uint64_t accepted = 0;
  std::array<std::uint64_t, rx::rule_count> findings{};
  std::map<std::string, std::uint64_t> reports;  // accepted reports by address
};

class judge {
 public:
  judge(asio::io_context& io, const options& o, const asio::ip::tcp::endpoint& where)
      : o_(o), server_(io, where, o.limits), timer_(io) {
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

  void print(const team_link& link, const rx::finding_list& findings, std::string_view line = {}) {
    for (const rx::finding& f : findings) {
      const std::string_view rule = name(f.broken);
      const std::string_view address = f.address.view();
      const nmea::field_about about =
          f.field != 0 ? rx::reports::about_field(address, f.field) : nmea::field_about{};
      const std::string_view field = about.name;
      std::string why = f.ec != errc::ok ? std::string(message(f.ec)) : std::string();
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
        if (!line.empty()) j["input"] = line;
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
    const std::string key = link.team.empty() ? "(no team id)" : link.team;
    team_summary& s = teams_[key];
    s.peers.push_back(link.peer);
    ++s.connections;
    const auto& t = link.validator.totals();
    s.lines += t.lines;
    s.accepted += t.accepted;
    for (std::size_t i = 0; i < rx::rule_count; ++i) s.findings[i] += t.findings[i];
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
  std::map<std::string, team_summary> teams_;
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

  const auto where = net::parse_endpoint(o.listen);
  if (!where) {
    std::fprintf(stderr, "seawire-robotx-judge: --listen %s: expected ADDR:PORT\n",
                 o.listen.c_str());
    return 2;
  }
  try {
    asio::io_context io;
    asio::error_code ec;
    const auto address = asio::ip::make_address(where->host, ec);
    if (ec) {
      std::fprintf(stderr, "seawire-robotx-judge: --listen %s: %s\n", o.listen.c_str(),
                   ec.message().c_str());
      return 2;
    }
    judge j(io, o, asio::ip::tcp::endpoint(address, where->port));
    net::line_server::log("listening on %s", net::to_string(j.local_endpoint()).c_str());
    net::stop_signals signals(io,
                              [&](int signo) { j.stop(signo == SIGINT ? "SIGINT" : "SIGTERM"); });
    j.on_stopped = [&] { signals.cancel(); };
    j.start();
    io.run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "seawire-robotx-judge: %s\n", e.what());
    return 1;
  }
  return 0;
}
