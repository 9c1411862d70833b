// SPDX-License-Identifier: BSL-1.0
// seawire-sandshark-sim: a Bluefin Sandshark's BAM (Bluefin Adapt Module) for backseat
// developers. A TCP server (port 29500) carrying the Standard Payload Interface through
// sandshark::vehicle_session: BFVER on connect, BPLOG subscriptions per client, acks (pending
// then final for the commands configured), a mission timeline with BFMIS and BFCTL handover,
// BPRMB requests that steer a small vehicle model and lapse after 5 s, BPABT, and BFSHT before
// shutting down. Manual: tools/sandshark-sim/README.md.

#include <CLI/CLI.hpp>
#include <asio.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <seawire/nmea/build.hpp>
#include <seawire/nmea/heading.hpp>
#include <seawire/nmea/time.hpp>
#include <seawire/nmea/writer.hpp>
#include <seawire/sandshark/messages.hpp>
#include <seawire/sandshark/vehicle_session.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "kingfisher_model.hpp"
#include "net.hpp"

namespace {

using namespace seawire;
namespace ss = seawire::sandshark;
namespace net = seawire::tools::net;
using steady = std::chrono::steady_clock;

constexpr std::size_t max_clients = 16;
using session_type = ss::vehicle_session<max_clients, 256, 64>;

// One step of the mission timeline.
struct mission_step {
  double at_s = 0;
  enum kind_t { mission, control } kind = mission;
  std::string status;  // mission: the BFMIS status word
  std::string dive_file;
  bool control_on = false;
};

std::vector<mission_step> default_timeline() {
  return {{0, mission_step::mission, "Waiting", "", false},
          {1, mission_step::mission, "Ready", "demo.dive", false},
          {2, mission_step::mission, "Running", "demo.dive", false},
          {3, mission_step::control, "", "", true},
          {3600, mission_step::mission, "Completed", "demo.dive", false}};
}

// What the vehicle publishes for a mission step: its BFMIS, with the longest details text the
// simulator or the session gives one (an abort), in the session's line buffer.
constexpr std::string_view longest_mission_details = "abort requested by the payload";
constexpr std::size_t mission_line_size = 512;

// Why a mission step's status or dive file cannot be sent in a BFMIS (empty when it can): a
// character a text field may not carry, or a line too long for the session.
std::string unsendable(const mission_step& s) {
  ss::bfmis m;
  m.timestamp = nmea::time_of_day{23, 59, 59, 999, 3};
  if (!m.status.assign(s.status) || !m.dive_file.assign(s.dive_file))
    return "BFMIS cannot carry this step: a status or dive file longer than 256 characters";
  (void)m.details.assign(longest_mission_details);
  const auto line = nmea::encode<mission_line_size>(m);
  if (line.ec == errc::ok) return {};
  return "BFMIS cannot carry this step: " + std::string(message(line.ec)) + " (field " +
         std::to_string(line.field) + ", " +
         (line.field == 2   ? "the dive file"
          : line.field == 3 ? "the status"
                            : "the line") +
         ")";
}

// "T mission STATUS [DIVE_FILE]" or "T control on|off"; '#' starts a comment.
std::optional<std::vector<mission_step>> read_timeline(const std::string& path,
                                                       std::string& error) {
  std::ifstream in(path);
  if (!in) {
    error = path + ": cannot be read";
    return std::nullopt;
  }
  std::vector<mission_step> steps;
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    mission_step s;
    std::string kind;
    if (!(words >> s.at_s)) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      error = path + ":" + std::to_string(n) + ": expected a time in seconds first";
      return std::nullopt;
    }
    words >> kind;
    if (kind == "mission" && (words >> s.status)) {
      s.kind = mission_step::mission;
      words >> s.dive_file;
    } else if (kind == "control") {
      std::string on;
      words >> on;
      if (on != "on" && on != "off") {
        error = path + ":" + std::to_string(n) + ": control takes on or off";
        return std::nullopt;
      }
      s.kind = mission_step::control;
      s.control_on = on == "on";
    } else {
      error =
          path + ":" + std::to_string(n) + ": expected 'mission STATUS [DIVE]' or 'control on|off'";
      return std::nullopt;
    }
    if (s.kind == mission_step::mission) {
      if (const std::string why = unsendable(s); !why.empty()) {
        error = path + ":" + std::to_string(n) + ": " + why;
        return std::nullopt;
      }
    }
    if (!steps.empty() && s.at_s < steps.back().at_s) {
      error = path + ":" + std::to_string(n) + ": times must not go backwards";
      return std::nullopt;
    }
    steps.push_back(s);
  }
  return steps;
}

// What the vehicle can be asked. The SPI: a BPRMB "can not be used to command the vehicle beyond
// its safe operating parameters", and the payload only turns status messages on or off.
constexpr double rated_depth_m = 200;  // a Sandshark's rated depth
constexpr double max_speed_mps = 2.0;  // the vehicle model's top speed
constexpr double max_rpm = 2000;       // the model's thruster: 1000 RPM a metre a second
constexpr double max_angle_deg = 90;   // rudder, pitch and elevator, either way

// The status messages a BPLOG may turn on or off (BFSHT and BFVER are commands, always sent).
constexpr std::array<std::string_view, 6> log_codes{"NVG", "NVR", "MIS", "ACK", "CTL", "ALL"};

// A command the vehicle refuses although it decodes: acknowledged invalid (0, "improper
// parameters"), and not acted on.
struct refusal {
  std::string_view address;
  std::optional<nmea::time_of_day> command_timestamp;
  errc error = errc::ok;
  std::uint16_t field = 0;
  std::string_view field_name;
  std::string why;
};

std::string number(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.15g", v);
  return b;
}

// The BPRMB fields outside what the vehicle can do; nullopt when all are within.
std::optional<refusal> out_of_range(const ss::bprmb& m) {
  const auto check = [&](const std::optional<nmea::decimal>& v, std::uint16_t field,
                         std::string_view name, std::string_view what, double lo, double hi,
                         bool hi_open, std::string_view unit) -> std::optional<refusal> {
    if (!v) return std::nullopt;
    const double x = v->to_double();
    if (x >= lo && (hi_open ? x < hi : x <= hi)) return std::nullopt;
    return refusal{ss::bprmb::nmea.address,
                   m.timestamp,
                   errc::out_of_range,
                   field,
                   name,
                   std::string(what) + " " + number(x) + " " + std::string(unit) + " outside " +
                       number(lo) + " to " + number(hi) + (hi_open ? " (excluded)" : "") + " " +
                       std::string(unit)};
  };
  const bool rudder = m.horizontal_mode == ss::horizontal_mode::rudder;
  auto r =
      rudder ? check(m.heading, 2, "heading", "rudder", -max_angle_deg, max_angle_deg, false, "deg")
             : check(m.heading, 2, "heading", "heading", 0, 360, true, "deg");
  if (r) return r;
  switch (m.depth_mode.value_or(ss::depth_mode::depth)) {
    case ss::depth_mode::depth:
      r = check(m.depth, 3, "depth", "depth", 0, rated_depth_m, false, "m");
      break;
    case ss::depth_mode::altitude:
      r = check(m.depth, 3, "depth", "altitude", 0, rated_depth_m, false, "m");
      break;
    case ss::depth_mode::pitch:
      r = check(m.depth, 3, "depth", "pitch", -max_angle_deg, max_angle_deg, false, "deg");
      break;
    case ss::depth_mode::elevator:
      r = check(m.depth, 3, "depth", "elevator", -max_angle_deg, max_angle_deg, false, "deg");
      break;
  }
  if (r) return r;
  if (m.speed_mode == ss::speed_mode::rpm)
    return check(m.speed, 5, "speed", "thruster", 0, max_rpm, false, "RPM");
  return check(m.speed, 5, "speed", "speed", 0, max_speed_mps, false, "m/s");
}

// What the vehicle refuses of a line that decodes: a BPRMB beyond the vehicle, a BPLOG code of
// no status message.
std::optional<refusal> refused(std::string_view line) {
  const auto r = ss::decode_to_vehicle(line);
  if (!r) return std::nullopt;  // the session acknowledges it invalid
  if (const auto* rmb = std::get_if<ss::bprmb>(&r.value)) return out_of_range(*rmb);
  if (const auto* log = std::get_if<ss::bplog>(&r.value)) {
    for (const std::string_view code : log_codes)
      if (log->code.view() == code) return std::nullopt;
    return refusal{
        ss::bplog::nmea.address,
        std::nullopt,
        errc::bad_enum,
        1,
        "code",
        "no status message " + std::string(log->code.view()) + " (NVG NVR MIS ACK CTL or ALL)"};
  }
  return std::nullopt;
}

struct options {
  std::string listen = "0.0.0.0:29500";
  std::string start = "42.358450,-71.087461";
  std::uint64_t seed = 1;
  std::string mission_file;
  std::vector<std::string> clients;  // NAME=IP
  std::string pending = "ABT";
  double nav_rate = 5;
  double abort_time = 2;
  double shutdown_wait = 60;
  double duration = 0;
  std::string version = "1.0";
  net::server_limits limits;
};

class simulator {
 public:
  simulator(asio::io_context& io, const options& o, const asio::ip::tcp::endpoint& where,
            double lat, double lon, std::vector<mission_step> timeline,
            std::map<std::string, std::string> names)
      : o_(o),
        server_(io, where, o.limits),
        session_(ss::utc_clock(steady::now(), std::chrono::system_clock::now()), config(o)),
        model_(params(), lat, lon, o.seed),
        timer_(io),
        shutdown_timer_(io),
        timeline_(std::move(timeline)),
        names_(std::move(names)) {
    server_.on_connect([this](net::client& c) { connected(c); });
    server_.on_sentence(
        [this](net::client& c, const nmea::framed_line& s) { received(c, s.text); });
    server_.on_close([this](net::client& c, std::string_view) {
      const auto it = ids_.find(c.id());
      if (it == ids_.end()) return;
      session_.disconnect(it->second);
      clients_.erase(it->second);
      ids_.erase(it);
    });
  }

  [[nodiscard]] asio::ip::tcp::endpoint local_endpoint() const { return server_.local_endpoint(); }

  void start() {
    t0_ = steady::now();
    session_.set_utc(t0_, std::chrono::system_clock::now());
    server_.start();
    tick();
  }

  /// Called once the simulator has stopped (to cancel the signal wait).
  std::function<void()> on_stopped;

  // The first signal: BFSHT to every payload, closing after --shutdown-wait; a second one
  // closes at once.
  void signalled(int signo) {
    const char* name = net::signal_name(signo);
    if (shutting_down_) {
      stop(std::string(name) + " again");
      return;
    }
    shutting_down_ = true;
    session_.shutdown(steady::now());
    drain();
    net::line_server::log("%s: BFSHT sent to %zu client(s), closing in %.3g s", name,
                          server_.client_count(), o_.shutdown_wait);
    shutdown_timer_.expires_after(std::chrono::duration_cast<steady::duration>(
        std::chrono::duration<double>(o_.shutdown_wait)));
    shutdown_timer_.async_wait([this, name](const asio::error_code& e) {
      if (!e) stop(name);
    });
  }

 private:
  static ss::vehicle_config config(const options& o) {
    ss::vehicle_config c;
    (void)c.version.assign(o.version);
    c.pending.log = o.pending.find("LOG") != std::string::npos;
    c.pending.sts = o.pending.find("STS") != std::string::npos;
    c.pending.rmb = o.pending.find("RMB") != std::string::npos;
    c.pending.abt = o.pending.find("ABT") != std::string::npos;
    c.pending.ver = o.pending.find("VER") != std::string::npos;
    c.complete_pending_after = std::chrono::milliseconds(1000);
    return c;
  }
  static tools::vehicle_params params() {
    tools::vehicle_params p;
    p.max_speed_mps = 2.0;  // a small AUV
    p.max_yaw_rate_dps = 15;
    p.speed_tau_s = 3;
    p.yaw_tau_s = 1;
    p.watchdog_s = 1e9;  // commanded every tick
    return p;
  }

  [[nodiscard]] double seconds() const {
    return std::chrono::duration<double>(steady::now() - t0_).count();
  }

  std::string who(const net::client& c) const {
    const auto it = names_.find(c.address().to_string());
    return "client " + std::to_string(c.id()) +
           (it != names_.end() ? " (" + it->second + ")" : std::string());
  }

  void stop(const std::string& why) {
    if (stopped_) return;
    stopped_ = true;
    timer_.cancel();
    shutdown_timer_.cancel();
    server_.stop(why);
    net::line_server::flush_log(invalid_log_);
    net::line_server::flush_log(command_log_);
    net::line_server::log("stopped (%s): %llu connections", why.c_str(),
                          static_cast<unsigned long long>(server_.connections()));
    if (on_stopped) on_stopped();
  }

  void connected(net::client& c) {
    const auto id = session_.connect(steady::now());
    if (!id) {
      c.close("the vehicle serves " + std::to_string(max_clients) + " payloads at most");
      return;
    }
    ids_[c.id()] = *id;
    clients_[*id] = &c;
    const auto it = names_.find(c.address().to_string());
    if (it != names_.end())
      net::line_server::log("client %llu: named %s (%s)", static_cast<unsigned long long>(c.id()),
                            it->second.c_str(), it->first.c_str());
    drain();
  }

  void received(net::client& c, std::string_view line) {
    const auto it = ids_.find(c.id());
    if (it == ids_.end()) return;
    const auto now = steady::now();
    if (const auto no = refused(line)) {
      refuse(c, it->second, *no, now);
      return;
    }
    const auto r = session_.receive(it->second, line, now);
    bool tell_control = false;
    if (r) {
      std::visit(
          [&](const auto& m) {
            using T = std::decay_t<decltype(m)>;
            // A payload's timestamps are UTC: each logged with the vehicle's own UTC at receipt,
            // so a payload clock that is off shows.
            std::string at;
            if constexpr (requires { m.timestamp; }) at = " " + stamped(m.timestamp, now);
            if constexpr (std::is_same_v<T, ss::bplog>) {
              net::line_server::log_limited(command_log_, "%s: BPLOG %s %s", who(c).c_str(),
                                            std::string(m.code.view()).c_str(),
                                            m.state == ss::log_state::on ? "ON" : "OFF");
              tell_control = m.state == ss::log_state::on && (m.code == "CTL" || m.is_all());
            } else if constexpr (std::is_same_v<T, ss::bpver>) {
              net::line_server::log_limited(command_log_, "%s: BPVER %s%s", who(c).c_str(),
                                            std::string(m.version.view()).c_str(), at.c_str());
            } else if constexpr (std::is_same_v<T, ss::bpsts>) {
              net::line_server::log_limited(command_log_, "%s: BPSTS %s %s%s", who(c).c_str(),
                                            m.all_ok ? "OK" : "FAILED",
                                            std::string(m.message.view()).c_str(), at.c_str());
            } else if constexpr (std::is_same_v<T, ss::bpabt>) {
              net::line_server::log_limited(command_log_, "%s: BPABT %s%s", who(c).c_str(),
                                            std::string(m.message.view()).c_str(), at.c_str());
            }
          },
          r.value);
    }
    drain();
    // BFCTL is sent when control changes hands: a payload that subscribes to it (a payload
    // reconnecting in the middle of a mission) is told at once whether it has control.
    if (tell_control && session_.should_send(it->second, "CTL"))
      send_to(c, ss::bfctl{session_.utc().at(now), session_.control_allowed()});
  }

  // A command that decodes but that the vehicle will not carry out: acknowledged invalid (when
  // the payload asked for acks), logged, and not acted on.
  void refuse(net::client& c, ss::client_id id, const refusal& no, steady::time_point now) {
    ++c.rejected_in;
    net::line_server::log_limited(invalid_log_, "%s: invalid %s: %s (field %u): %s", who(c).c_str(),
                                  std::string(no.address).c_str(),
                                  std::string(message(no.error)).c_str(), unsigned{no.field},
                                  no.why.c_str());
    drain();  // what the session queued before this line goes first
    if (!session_.subscriptions(id).acks()) return;
    ss::bfack a;
    a.timestamp = session_.utc().at(now);
    (void)a.command.assign(ss::message_code(no.address));
    a.command_timestamp = no.command_timestamp;
    a.status = ss::ack_status::invalid;
    // As the session describes an invalid command: "out_of_range in field 3 (depth)".
    const std::string description = std::string(name(no.error)) + " in field " +
                                    std::to_string(no.field) + " (" + std::string(no.field_name) +
                                    ")";
    (void)a.description->assign(description);
    send_to(c, a);
  }

  template <class M>
  void send_to(net::client& c, const M& m) {
    const auto line = nmea::encode<512>(m);
    if (line.ec == errc::ok) c.send(std::string(line.view()), 1);
  }

  // "[stamped 231300.125, vehicle 231300.127]": a payload's timestamp and the vehicle's UTC.
  [[nodiscard]] std::string stamped(const nmea::time_of_day& t, steady::time_point now) const {
    const auto text = [](const nmea::time_of_day& x) {
      char b[24];
      std::snprintf(
          b, sizeof b, "%02u%02u%02u.%03u", unsigned{x.hour}, unsigned{x.minute},
          unsigned{x.second},
          static_cast<unsigned>(
              std::chrono::floor<std::chrono::milliseconds>(x.since_midnight()).count() % 1000));
      return std::string(b);
    };
    return "[stamped " + text(t) + ", vehicle " + text(session_.utc().at(now)) + "]";
  }

  // Everything the session has to say: lines to their clients, events to the log.
  void drain() {
    while (const auto e = session_.poll_event()) {
      const auto cl = clients_.find(e->client);
      const std::string name = cl != clients_.end() ? who(*cl->second) : "client ?";
      switch (e->kind) {
        case ss::vehicle_event_kind::request_expired:
          net::line_server::log("%s: no BPRMB for 5 s: the vehicle takes control back",
                                name.c_str());
          take_control_back_ = true;
          break;
        case ss::vehicle_event_kind::request_started:
          net::line_server::log("%s: BPRMB request started: the backseat steers", name.c_str());
          break;
        case ss::vehicle_event_kind::abort_requested: {
          // The session has moved a mission it could abort to Aborting (and published it); a
          // BPABT with nothing to abort, or a second one, changes nothing here.
          const auto& m = session_.mission();
          const bool aborting = m && m->status.view().starts_with("Aborting");
          if (aborting && !abort_at_ && !aborted_) {
            net::line_server::log("%s: abort requested; Aborted in %.3g s", name.c_str(),
                                  o_.abort_time);
            abort_at_ = seconds() + o_.abort_time;
            running_ = false;           // no longer Running: the mission wraps up
            take_control_back_ = true;  // and backseat control ends with it
          } else {
            net::line_server::log_limited(
                command_log_, "%s: abort requested with no mission to abort", name.c_str());
          }
          break;
        }
        case ss::vehicle_event_kind::invalid_command:
          // A line that does not decode or names no command: rejected (acknowledged invalid).
          if (cl != clients_.end()) ++cl->second->rejected_in;
          net::line_server::log_limited(invalid_log_, "%s: invalid %s: %s (field %u)", name.c_str(),
                                        std::string(e->command.view()).c_str(),
                                        std::string(message(e->error)).c_str(), unsigned{e->field});
          break;
        default:
          net::line_server::log_limited(command_log_, "%s: %s %s", name.c_str(),
                                        std::string(name_of(e->kind)).c_str(),
                                        std::string(e->command.view()).c_str());
      }
    }
    if (take_control_back_) {
      take_control_back_ = false;
      set_control(false);
    }
    while (const auto line = session_.poll_send()) {
      const auto cl = clients_.find(line->client);
      if (cl == clients_.end()) continue;
      cl->second->send(std::string(line->view()), 1);
    }
  }
  static std::string_view name_of(ss::vehicle_event_kind k) { return ss::name(k); }

  void set_control(bool on) {
    if (session_.control_allowed() == on) return;
    session_.set_control(on, steady::now());
    net::line_server::log(
        "BFCTL %d: %s", on ? 1 : 0,
        on ? "the backseat may steer (dynamic requests allowed)" : "the vehicle has control");
  }

  void publish_mission(const std::string& status, const std::string& dive,
                       const std::string& details = "") {
    ss::bfmis m;
    (void)m.status.assign(status);
    (void)m.dive_file.assign(dive);
    (void)m.details.assign(details);
    (void)session_.publish(m, steady::now());
    running_ = status.starts_with("Running");
    dive_ = dive;
    net::line_server::log("BFMIS %s%s%s", status.c_str(), dive.empty() ? "" : " ", dive.c_str());
    if (!running_) set_control(false);  // leaving Running ends backseat control
  }

  void tick() {
    ++ticks_;
    const auto period = std::chrono::nanoseconds(std::llround(1e9 / o_.nav_rate));
    timer_.expires_at(t0_ + period * ticks_);
    timer_.async_wait([this](const asio::error_code& ec) {
      if (ec || stopped_) return;
      const double now = seconds();
      // The timeline; an abort ends it.
      while (!aborted_ && next_step_ < timeline_.size() && timeline_[next_step_].at_s <= now) {
        const mission_step& s = timeline_[next_step_++];
        if (s.kind == mission_step::mission) {
          publish_mission(s.status, s.dive_file);
        } else {
          set_control(s.control_on && running_);
        }
      }
      if (abort_at_ && now >= *abort_at_) {
        abort_at_.reset();
        aborted_ = true;
        publish_mission("Aborted", dive_, "aborted by the payload");
      }
      net::line_server::poll_log(invalid_log_);
      net::line_server::poll_log(command_log_);
      steer(now);
      session_.tick(steady::now());
      publish_navigation();
      drain();
      if (o_.duration > 0 && now >= o_.duration) {
        stop("--duration reached");
        return;
      }
      tick();
    });
  }

  // The vehicle's behaviour: the payload's request while one holds, else the mission's own
  // (heading 45 at 1 m/s, 2 m deep while running; stopped and surfacing otherwise).
  void steer(double now) {
    const double dt = 1.0 / o_.nav_rate;
    double heading = 45, speed = running_ ? 1.0 : 0.0, depth = running_ ? 2.0 : 0.0;
    const auto& req = session_.current_request();
    if (req && session_.request_active(steady::now())) {
      const bool rudder = req->horizontal_mode == ss::horizontal_mode::rudder;
      if (req->heading && !rudder) heading = req->heading->to_double();
      if (req->speed)
        speed = req->speed_mode == ss::speed_mode::rpm ? req->speed->to_double() / 1000
                                                       : req->speed->to_double();
      if (req->depth && (!req->depth_mode || req->depth_mode == ss::depth_mode::depth))
        depth = req->depth->to_double();
      if (req->depth && req->depth_mode == ss::depth_mode::altitude)
        depth = std::max(0.0, water_depth_m - req->depth->to_double());
      if (rudder && req->heading) {
        model_.rate(req->heading->to_double(), speed / params().max_speed_mps * 100, now);
      } else {
        model_.helm(heading, speed, now);
      }
    } else {
      model_.helm(heading, speed, now);
    }
    depth_ += (depth - depth_) * (1 - std::exp(-dt / 5.0));
    model_.step(dt, now);
  }

  void publish_navigation() {
    const auto now = steady::now();
    const auto stamp = session_.utc().at(now);
    ss::bfnvg nvg;
    nvg.timestamp = stamp;
    nvg.gps = depth_ < 0.3;  // GPS only at the surface
    nvg.nav_timestamp = stamp;
    // A heading that the builder would round up to 360.0 (which the field refuses) is north.
    const double h = model_.heading();
    const auto wrapped =
        nmea::wrap_heading(h, static_cast<unsigned>(nmea::precision_of<&ss::bfnvg::heading_deg>()));
    (void)session_.publish(
        nmea::builder<ss::bfnvg>{nvg}
            .set<&ss::bfnvg::lat>(model_.lat())
            .set<&ss::bfnvg::lon>(model_.lon())
            .set<&ss::bfnvg::altitude_m>(std::max(0.0, water_depth_m - depth_))
            .set<&ss::bfnvg::depth_m>(depth_)
            .set<&ss::bfnvg::heading_deg>(wrapped ? wrapped.value.to_double() : h)
            .set<&ss::bfnvg::roll_deg>(model_.roll())
            .set<&ss::bfnvg::pitch_deg>(model_.pitch())
            .message(),
        now);
    ss::bfnvr nvr;
    nvr.timestamp = stamp;
    (void)session_.publish(nmea::builder<ss::bfnvr>{nvr}
                               .set<&ss::bfnvr::vel_east_mps>(model_.vel_east())
                               .set<&ss::bfnvr::vel_north_mps>(model_.vel_north())
                               .set<&ss::bfnvr::vel_down_mps>(0)
                               .set<&ss::bfnvr::pitch_rate_dps>(model_.pitch_rate())
                               .set<&ss::bfnvr::roll_rate_dps>(model_.roll_rate())
                               .set<&ss::bfnvr::yaw_rate_dps>(model_.yaw_rate())
                               .message(),
                           now);
  }

  static constexpr double water_depth_m = 50;

  const options& o_;
  net::line_server server_;
  session_type session_;
  tools::vehicle_model model_;
  asio::steady_timer timer_;
  asio::steady_timer shutdown_timer_;
  std::vector<mission_step> timeline_;
  std::map<std::string, std::string> names_;
  std::map<std::uint64_t, ss::client_id> ids_;
  std::map<ss::client_id, net::client*> clients_;
  steady::time_point t0_;
  std::int64_t ticks_ = 0;
  std::size_t next_step_ = 0;
  std::optional<double> abort_at_;
  std::string dive_;
  double depth_ = 0;
  bool running_ = false;
  bool aborted_ = false;
  bool take_control_back_ = false;
  bool shutting_down_ = false;
  bool stopped_ = false;
  // Lines a payload can cause at its line rate, each category at most 20 a second.
  tools::log_limit invalid_log_{"invalid commands"};
  tools::log_limit command_log_{"command lines"};
};

}  // namespace

int main(int argc, char** argv) {
  options o;
  CLI::App app{
      "A simulated Bluefin Sandshark (its BAM): a TCP server speaking the Standard Payload\n"
      "Interface. BFVER on connect, BPLOG subscriptions per client, BFACK for every command,\n"
      "a mission timeline (BFMIS) that hands control to the backseat (BFCTL), BPRMB requests\n"
      "that steer the vehicle and lapse after 5 s, BPABT, and BFSHT before shutting down.",
      "seawire-sandshark-sim"};
  app.add_option("--listen", o.listen, "ADDR:PORT to listen on (port 0: any free port)")
      ->capture_default_str();
  app.add_option("--start", o.start, "LAT,LON where the vehicle starts")->capture_default_str();
  app.add_option("--seed", o.seed, "seed of the swell and start heading")->capture_default_str();
  app.add_option("--mission", o.mission_file,
                 "timeline file: lines 'SECONDS mission STATUS [DIVE_FILE]' or 'SECONDS control "
                 "on|off' (default: Waiting 0, Ready 1, Running 2, control on 3, Completed 3600)");
  app.add_option("--client", o.clients,
                 "NAME=IP: the payload connecting from IP is called NAME in the log (repeatable)");
  app.add_option("--pending", o.pending,
                 "commands acknowledged pending (3) first and finally 1 s later: any of LOG STS "
                 "RMB ABT VER, comma-separated, or 'none'")
      ->capture_default_str();
  app.add_option("--nav-rate", o.nav_rate, "Hz of BFNVG and BFNVR (to subscribers)")
      ->check(seawire::tools::finite_number)
      ->check(CLI::Range(0.1, 100.0))
      ->capture_default_str();
  app.add_option("--abort-time", o.abort_time, "seconds from BPABT to BFMIS Aborted")
      ->check(seawire::tools::finite_number)
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--shutdown-wait", o.shutdown_wait,
                 "seconds between BFSHT (on SIGINT/SIGTERM) and closing; a second signal closes "
                 "at once")
      ->check(seawire::tools::finite_number)
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--version-text", o.version, "the interface version sent in BFVER")
      ->capture_default_str();
  app.add_option("--duration", o.duration, "stop after this many seconds (0: at a signal)")
      ->check(seawire::tools::finite_number)
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  if (const auto status = seawire::tools::parse_command_line(app, argc, argv)) return *status;

  const auto fail = [](const std::string& what) {
    std::fprintf(stderr, "seawire-sandshark-sim: %s\n", what.c_str());
    return 2;
  };
  const auto where = net::listen_option("seawire-sandshark-sim", o.listen);
  if (!where) return 2;
  double lat = 0, lon = 0;
  char tail = 0;
  if (std::sscanf(o.start.c_str(), "%lf,%lf%c", &lat, &lon, &tail) != 2 || !(lat >= -85) ||
      !(lat <= 85) || !(lon >= -180) || !(lon <= 180))
    return fail("--start " + o.start + ": expected LAT,LON in decimal degrees");
  std::map<std::string, std::string> names;
  for (const std::string& c : o.clients) {
    const auto eq = c.find('=');
    asio::error_code ec;
    if (eq == std::string::npos || eq == 0) return fail("--client " + c + ": expected NAME=IP");
    const auto ip = asio::ip::make_address(c.substr(eq + 1), ec);
    if (ec) return fail("--client " + c + ": " + c.substr(eq + 1) + " is not an IP address");
    names[ip.to_string()] = c.substr(0, eq);
  }
  std::vector<mission_step> timeline = default_timeline();
  if (!o.mission_file.empty()) {
    std::string error;
    auto t = read_timeline(o.mission_file, error);
    if (!t) return fail("--mission " + error);
    timeline = std::move(*t);
  }
  if (o.version.size() > 32 || !nmea::is_field_text(o.version))
    return fail("--version-text " + o.version +
                ": at most 32 printable characters, none of $ , * ! \\ ^ ~");
  {
    std::istringstream list(o.pending);
    std::string code;
    while (std::getline(list, code, ',')) {
      if (code != "LOG" && code != "STS" && code != "RMB" && code != "ABT" && code != "VER" &&
          code != "none")
        return fail("--pending " + o.pending + ": " + code + " is none of LOG STS RMB ABT VER");
    }
  }
  o.limits.max_clients = max_clients;

  return net::serve("seawire-sandshark-sim", o.listen, *where,
                    [&](asio::io_context& io, const asio::ip::tcp::endpoint& at) {
                      return std::make_unique<simulator>(io, o, at, lat, lon, std::move(timeline),
                                                         std::move(names));
                    });
}
