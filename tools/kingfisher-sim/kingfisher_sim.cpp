// SPDX-License-Identifier: BSL-1.0
// seawire-kingfisher-sim: a Clearpath Kingfisher for payloads to talk to. A TCP server (port
// 29500 unless told otherwise) that streams the vehicle's sentences to every client and obeys
// the PY* commands any client sends. Manual: tools/kingfisher-sim/README.md.

#include <CLI/CLI.hpp>
#include <asio.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <seawire/kingfisher/messages.hpp>
#include <seawire/nmea/build.hpp>
#include <seawire/nmea/error_text.hpp>
#include <seawire/nmea/heading.hpp>
#include <seawire/nmea/time.hpp>
#include <string>
#include <variant>

#include "cli.hpp"
#include "kingfisher_model.hpp"
#include "net.hpp"

namespace {

using namespace seawire;
namespace kf = seawire::kingfisher;
namespace net = seawire::tools::net;
using sys_ns = std::chrono::sys_time<std::chrono::nanoseconds>;

// A heading in [0, 360) for heading field M, at the field's places: -0.3 is 359.7, and 359.996
// for a field of two places is 0, not 360.00 (which the field refuses). The builder reads the
// decimal's double back as the same decimal. A heading the wrap refuses is given as it is, for
// the builder to refuse.
template <auto M>
double wrap_heading(double h) {
  const auto r = nmea::wrap_heading(h, static_cast<unsigned>(nmea::precision_of<M>()));
  return r ? r.value.to_double() : h;
}

struct options {
  std::string listen = "0.0.0.0:29500";
  std::string start = "42.358450,-71.087461";  // the Charles River basin
  std::uint64_t seed = 1;
  std::string time;  // ISO 8601 UTC; empty: now
  double nav_rate = 10;
  double status_rate = 1;
  double duration = 0;
  std::string pydep_units = "deg";
  net::server_limits limits;
  seawire::tools::vehicle_params vehicle;
};

class simulator {
 public:
  simulator(asio::io_context& io, const options& o, const asio::ip::tcp::endpoint& where,
            double lat, double lon, sys_ns start_time)
      : o_(o),
        server_(io, where, o.limits),
        model_(o.vehicle, lat, lon, o.seed),
        timer_(io),
        start_time_(start_time) {
    server_.on_sentence([this](net::client& c, const nmea::framed_line& s) { command(c, s.text); });
  }

  [[nodiscard]] asio::ip::tcp::endpoint local_endpoint() const { return server_.local_endpoint(); }

  void start() {
    server_.start();
    t0_ = std::chrono::steady_clock::now();
    schedule();
  }

  /// Called once the simulator has stopped (to cancel the signal wait).
  std::function<void()> on_stopped;
  void signalled(int signo) { stop(net::signal_name(signo)); }

  void stop(std::string_view why) {
    if (stopped_) return;
    stopped_ = true;
    timer_.cancel();
    server_.stop(why);
    if (on_stopped) on_stopped();
    net::line_server::flush_log(rejected_log_);
    net::line_server::flush_log(watchdog_log_);
    net::line_server::log(
        "stopped (%.*s) after %llu ticks: %llu connections, %llu commands applied, %llu "
        "rejected, %llu watchdog stops",
        static_cast<int>(why.size()), why.data(), static_cast<unsigned long long>(tick_),
        static_cast<unsigned long long>(server_.connections()),
        static_cast<unsigned long long>(applied_), static_cast<unsigned long long>(rejected_),
        static_cast<unsigned long long>(model_.watchdog_trips()));
  }

 private:
  [[nodiscard]] double dt() const { return 1.0 / o_.nav_rate; }
  [[nodiscard]] std::int64_t period_ns() const {
    return static_cast<std::int64_t>(std::llround(1e9 / o_.nav_rate));
  }

  void schedule() {
    const auto next =
        t0_ + std::chrono::nanoseconds(static_cast<std::int64_t>(tick_ + 1) * period_ns());
    timer_.expires_at(next);
    timer_.async_wait([this](const asio::error_code& ec) {
      if (ec || stopped_) return;
      ++tick_;
      const double now = static_cast<double>(tick_) * dt();
      model_.step(dt(), now);
      if (model_.watchdog_trips() != trips_seen_) {
        trips_seen_ = model_.watchdog_trips();
        net::line_server::log_limited(watchdog_log_,
                                      "watchdog: no command for %.3g s, thrusters stopped",
                                      o_.vehicle.watchdog_s);
      }
      emit(now);
      net::line_server::poll_log(rejected_log_);
      net::line_server::poll_log(watchdog_log_);
      if (o_.duration > 0 && now >= o_.duration) {
        stop("--duration reached");
        return;
      }
      schedule();
    });
  }

  template <class M>
  void put(std::string& out, std::uint32_t& lines, const result<M>& m) {
    if (!m) {
      ++encode_failures_;
      if (encode_failures_ <= 5)
        net::line_server::log("%s not sent: field %u: %s", std::string(M::nmea.address).c_str(),
                              unsigned{m.field}, std::string(message(m.ec)).c_str());
      return;
    }
    const auto e = nmea::encode(m.value);
    if (!e) {
      ++encode_failures_;
      return;
    }
    out += e.view();
    ++lines;
  }

  void emit(double now) {
    // Whole nanoseconds per tick, so 50 Hz stamps step by exactly 0.020 s.
    const sys_ns t =
        start_time_ + std::chrono::nanoseconds(static_cast<std::int64_t>(tick_) * period_ns());
    const auto stamp = nmea::time_of_day::from(t, 3).value;
    auto b = std::make_shared<net::batch>();
    const double heading = model_.heading() + model_.noise(0.02);
    kf::cpnvg nvg;
    nvg.timestamp = stamp;
    nvg.gps = true;
    nvg.altitude_m = nmea::decimal{0};  // the real vehicle sends 0, not blank, on the surface
    nvg.depth_m = nmea::decimal{0};
    nvg.nav_timestamp = stamp;
    kf::cpnvr nvr;
    nvr.timestamp = stamp;
    kf::cprcm rcm;
    rcm.timestamp = stamp;
    rcm.nav_timestamp = stamp;
    kf::cpimu imu;  // seven fields, as the real vehicle sends
    imu.timestamp = stamp;

    put(b->bytes, b->lines,
        nmea::builder<kf::cpnvg>{nvg}
            .set<&kf::cpnvg::lat>(model_.lat())
            .set<&kf::cpnvg::lon>(model_.lon())
            .set<&kf::cpnvg::heading_deg>(wrap_heading<&kf::cpnvg::heading_deg>(heading))
            .set<&kf::cpnvg::roll_deg>(model_.roll())
            .set<&kf::cpnvg::pitch_deg>(model_.pitch())
            .result());
    put(b->bytes, b->lines,
        nmea::builder<kf::cpnvr>{nvr}
            .set<&kf::cpnvr::vel_east_mps>(model_.vel_east())
            .set<&kf::cpnvr::vel_north_mps>(model_.vel_north())
            .set<&kf::cpnvr::vel_down_mps>(0)
            .set<&kf::cpnvr::pitch_rate_dps>(model_.pitch_rate())
            .set<&kf::cpnvr::roll_rate_dps>(model_.roll_rate())
            .set<&kf::cpnvr::yaw_rate_dps>(model_.yaw_rate())
            .result());
    put(b->bytes, b->lines,
        nmea::builder<kf::cprcm>{rcm}
            .set<&kf::cprcm::heading_deg>(
                wrap_heading<&kf::cprcm::heading_deg>(heading + model_.noise(0.3)))
            .set<&kf::cprcm::pitch_deg>(model_.pitch() + model_.noise(0.05))
            .set<&kf::cprcm::roll_deg>(model_.roll() + model_.noise(0.05))
            .result());
    const double turn = model_.yaw_rate() * std::numbers::pi / 180;
    put(b->bytes, b->lines,
        nmea::builder<kf::cpimu>{imu}
            .set<&kf::cpimu::rate_x_dps>(model_.roll_rate() + model_.noise(0.01))
            .set<&kf::cpimu::rate_y_dps>(model_.pitch_rate() + model_.noise(0.01))
            .set<&kf::cpimu::rate_z_dps>(model_.yaw_rate() + model_.noise(0.01))
            .set<&kf::cpimu::accel_x_mps2>(model_.accel_x() + model_.noise(0.02))
            .set<&kf::cpimu::accel_y_mps2>(model_.speed() * turn + model_.noise(0.02))
            .set<&kf::cpimu::accel_z_mps2>(-9.80665 + model_.noise(0.02))
            .result());

    // The once-a-second sentences, on the ticks where the status clock passes a whole period.
    const auto period = [&](double seconds) {
      return static_cast<std::int64_t>(std::floor(seconds * o_.status_rate + 1e-9));
    };
    if (tick_ == 1 || period(now) != period(now - dt())) {
      const double v = model_.battery_v();
      kf::cprbs rbs;  // five fields (no battery id), as the real vehicle sends
      rbs.timestamp = stamp;
      put(b->bytes, b->lines,
          nmea::builder<kf::cprbs>{rbs}
              .set<&kf::cprbs::stack_voltage_v>(v)
              .set<&kf::cprbs::min_cell_voltage_v>(v / 4 - 0.01)
              .set<&kf::cprbs::max_cell_voltage_v>(v / 4 + 0.01)
              .set<&kf::cprbs::temperature_c>(24.0)
              .result());
      kf::cpalt alt;
      alt.timestamp = stamp;
      alt.lights_on = model_.lights();
      put(b->bytes, b->lines, result<kf::cpalt>{alt});
      const auto fix = nmea::time_of_day::from(t, 2).value;
      const double course = wrap_heading<&standard::rmc::course_true>(
          model_.speed() >= 0 ? model_.heading() : model_.heading() + 180);
      standard::rmc rmc;
      rmc.time = fix;
      rmc.date = nmea::date::from(t);
      rmc.mode = standard::mode_indicator::autonomous;
      put(b->bytes, b->lines,
          nmea::builder<standard::rmc>{rmc}
              .set<&standard::rmc::lat>(model_.lat())
              .set<&standard::rmc::lon>(model_.lon())
              .set<&standard::rmc::speed_knots>(std::fabs(model_.speed()) * 3600 / 1852)
              .set<&standard::rmc::course_true>(course)
              .result());
      standard::gga gga;
      gga.time = fix;
      gga.quality = standard::gps_quality::gps;
      gga.satellites = 10;
      put(b->bytes, b->lines,
          nmea::builder<standard::gga>{gga}
              .set<&standard::gga::lat>(model_.lat())
              .set<&standard::gga::lon>(model_.lon())
              .set<&standard::gga::hdop>(0.9)
              .set<&standard::gga::altitude_m>(1.0)
              .set<&standard::gga::geoid_separation_m>(-33.2)
              .result());
    }
    server_.broadcast(b);
  }

  void command(net::client& c, std::string_view sentence) {
    const auto r = kf::decode_to_vehicle(sentence);
    if (!r) {
      ++c.rejected_in;
      ++rejected_;
      char why[200];
      // Told with the policy it was read with: a command that ends "*" without a checksum
      // splits into its fields only under the vehicle's policy, and so has its field named.
      const auto text = nmea::error_text<kf::to_vehicle>(why, r, sentence, kf::vehicle_policy());
      net::line_server::log_limited(rejected_log_, "client %llu: rejected: %.*s",
                                    static_cast<unsigned long long>(c.id()),
                                    static_cast<int>(text.size()), text.data());
      return;
    }
    // Applied at once, stamped with the current tick's time: the model's clock (so runs with
    // the same --seed and --time given the same commands at the same ticks are the same).
    const double now = static_cast<double>(tick_) * dt();
    std::visit(
        [&](const auto& m) {
          using T = std::decay_t<decltype(m)>;
          if constexpr (std::is_same_v<T, kf::pydir>) {
            model_.thrust(m.thrust_left.to_double(), m.thrust_right.to_double(), now);
            ++applied_;
          } else if constexpr (std::is_same_v<T, kf::pydep>) {
            model_.rate(m.yaw_rate.to_double(), m.thrust.to_double(), now);
            ++applied_;
          } else if constexpr (std::is_same_v<T, kf::pydev>) {
            model_.helm(m.heading_deg.to_double(), m.speed_mps.to_double(), now);
            ++applied_;
          } else if constexpr (std::is_same_v<T, kf::pyclt>) {
            model_.lights(m.lights_on);
            ++applied_;
          }
          // Any other sentence: ignored, as the vehicle does.
        },
        r.value);
  }

  const options& o_;
  net::line_server server_;
  seawire::tools::vehicle_model model_;
  asio::steady_timer timer_;
  sys_ns start_time_;
  std::chrono::steady_clock::time_point t0_;
  std::uint64_t tick_ = 0;
  std::uint64_t trips_seen_ = 0;
  std::uint64_t applied_ = 0;
  std::uint64_t rejected_ = 0;
  std::uint64_t encode_failures_ = 0;
  bool stopped_ = false;
  // Lines clients can cause as fast as they send: at most 20 a second each.
  tools::log_limit rejected_log_{"rejected commands"};
  tools::log_limit watchdog_log_{"watchdog stops"};
};

// "2026-11-25T12:00:00Z" (seconds may have a fraction; the Z may be left out).
std::optional<sys_ns> parse_time(const std::string& s) {
  int y = 0, mo = 0, d = 0, h = 0, mi = 0;
  double sec = 0;
  char z = 0;
  const int n = std::sscanf(s.c_str(), "%d-%d-%dT%d:%d:%lf%c", &y, &mo, &d, &h, &mi, &sec, &z);
  if (n < 6 || (n == 7 && z != 'Z') || sec < 0 || sec >= 61 || h > 23 || mi > 59) return {};
  const std::chrono::year_month_day ymd{std::chrono::year{y},
                                        std::chrono::month{static_cast<unsigned>(mo)},
                                        std::chrono::day{static_cast<unsigned>(d)}};
  if (!ymd.ok()) return {};
  return sys_ns(std::chrono::sys_days(ymd)) + std::chrono::hours(h) + std::chrono::minutes(mi) +
         std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(sec));
}

}  // namespace

int main(int argc, char** argv) {
  options o;
  CLI::App app{
      "A simulated Clearpath Kingfisher: a TCP server streaming CPNVG, CPNVR, CPRCM and CPIMU at\n"
      "the navigation rate and CPRBS, CPALT, GPRMC and GPGGA at the status rate to every client,\n"
      "and obeying PYDIR, PYDEP, PYDEV and PYCLT from any client.",
      "seawire-kingfisher-sim"};
  app.add_option("--listen", o.listen, "ADDR:PORT to listen on (port 0: any free port)")
      ->capture_default_str();
  app.add_option("--start", o.start, "LAT,LON where the vehicle starts, decimal degrees")
      ->capture_default_str();
  app.add_option("--seed", o.seed, "seed of the swell phases, start heading and sensor noise")
      ->capture_default_str();
  app.add_option("--time", o.time,
                 "UTC time of the first tick, 2026-11-25T12:00:00Z (default: now)");
  app.add_option("--nav-rate", o.nav_rate, "Hz of CPNVG, CPNVR, CPRCM, CPIMU")
      ->check(seawire::tools::finite_number)
      ->check(CLI::Range(0.1, 1000.0))
      ->capture_default_str();
  app.add_option("--status-rate", o.status_rate, "Hz of CPRBS, CPALT, GPRMC, GPGGA")
      ->check(seawire::tools::finite_number)
      ->check(CLI::Range(0.01, 1000.0))
      ->capture_default_str();
  app.add_option("--watchdog", o.vehicle.watchdog_s,
                 "seconds without a command after which the thrusters stop")
      ->check(seawire::tools::finite_number)
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--pydep-units", o.pydep_units,
                 "unit of PYDEP's yaw rate: deg (deg/s, as the Clearpath vehicle reads it) or rad "
                 "(rad/s, as the interface document says)")
      ->check(CLI::IsMember({"deg", "rad"}))
      ->capture_default_str();
  app.add_option("--max-speed", o.vehicle.max_speed_mps, "m/s at full thrust")
      ->check(seawire::tools::finite_number)
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--max-yaw-rate", o.vehicle.max_yaw_rate_dps, "deg/s at full differential thrust")
      ->check(seawire::tools::finite_number)
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--max-queue", o.limits.max_queue_lines,
                 "unsent lines kept per client; beyond it the oldest are dropped")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--max-drops", o.limits.max_drops,
                 "lines dropped for a client after which it is disconnected")
      ->capture_default_str();
  app.add_option("--max-clients", o.limits.max_clients, "connections beyond this are closed")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--send-buffer", o.limits.send_buffer,
                 "SO_SNDBUF of each client socket in bytes (0: the system's)")
      ->capture_default_str();
  app.add_option("--duration", o.duration, "stop after this many seconds (0: run until signalled)")
      ->check(seawire::tools::finite_number)
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  if (const auto status = seawire::tools::parse_command_line(app, argc, argv)) return *status;
  o.vehicle.pydep_radians = o.pydep_units == "rad";
  if (o.status_rate > o.nav_rate) {
    std::fprintf(stderr,
                 "seawire-kingfisher-sim: --status-rate %g is above --nav-rate %g: status "
                 "sentences go out on navigation ticks\n",
                 o.status_rate, o.nav_rate);
    return 2;
  }

  const auto where = net::listen_option("seawire-kingfisher-sim", o.listen);
  if (!where) return 2;
  double lat = 0, lon = 0;
  char tail = 0;
  if (std::sscanf(o.start.c_str(), "%lf,%lf%c", &lat, &lon, &tail) != 2 || !(lat >= -85) ||
      !(lat <= 85) || !(lon >= -180) || !(lon <= 180)) {
    std::fprintf(stderr,
                 "seawire-kingfisher-sim: --start %s: expected LAT,LON in decimal degrees "
                 "(latitude within 85 degrees of the equator)\n",
                 o.start.c_str());
    return 2;
  }
  sys_ns start_time =
      std::chrono::time_point_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now());
  if (!o.time.empty()) {
    const auto t = parse_time(o.time);
    if (!t) {
      std::fprintf(stderr, "seawire-kingfisher-sim: --time %s: expected 2026-11-25T12:00:00Z\n",
                   o.time.c_str());
      return 2;
    }
    start_time = *t;
  }

  return net::serve("seawire-kingfisher-sim", o.listen, *where,
                    [&](asio::io_context& io, const asio::ip::tcp::endpoint& at) {
                      return std::make_unique<simulator>(io, o, at, lat, lon, start_time);
                    });
}
