// SPDX-License-Identifier: BSL-1.0
#pragma once
// Deterministic corpora of valid sentences, for the benchmarks, the allocation test and fuzz
// seeds. Same seed, same bytes, on every machine: a splitmix64 stream drives a simulated
// vehicle (moving position, course, speed, attitude, clock), each message is filled from it and
// written by seawire's own encoder, so every line ends in CR LF and carries a correct checksum,
// and is checked to decode back before it joins the corpus.
//
//   auto c = seawire::bench::rmc_gga_corpus(1000);             // GPS at 1 Hz: RMC, GGA, ...
//   auto k = seawire::bench::kingfisher_from_vehicle_corpus(1000);  // CP*, RMC, GGA
//   auto r = seawire::bench::corpus_of<standard::rmc>(1000);   // one type, with the messages
//   for (std::string_view line : c.lines) ...                  // each with its CR LF
//
// Families whose headers are not in the tree are left out (SEAWIRE_BENCH_HAS_<FAMILY> is 0).
// This is test equipment, not library code: it allocates (std::string, std::vector) freely and
// aborts on a generator bug rather than produce a corpus with a bad line in it.

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "seawire/anello/frame.hpp"
#include "seawire/anello/gpsctrl.hpp"
#include "seawire/anello/inputs.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/sandshark/messages.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/rmc.hpp"
#include "seawire/standard/rpm.hpp"
#include "seawire/standard/rsa.hpp"
#include "seawire/standard/vbw.hpp"
#include "seawire/standard/vhw.hpp"
#include "seawire/standard/vwr.hpp"

#if __has_include("seawire/kingfisher/messages.hpp")
#include "seawire/kingfisher/messages.hpp"
#define SEAWIRE_BENCH_HAS_KINGFISHER 1
#else
#define SEAWIRE_BENCH_HAS_KINGFISHER 0
#endif

namespace seawire::bench {

// ---------------------------------------------------------------------------------------------
// randomness and the simulated vehicle

/// splitmix64: tiny, fast, and the same sequence everywhere.
class rng {
 public:
  explicit rng(std::uint64_t seed) noexcept : state_(seed) {}
  std::uint64_t next() noexcept {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15U);
    z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9U;
    z = (z ^ (z >> 27U)) * 0x94D049BB133111EBU;
    return z ^ (z >> 31U);
  }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) noexcept {
    return lo + (hi - lo) * static_cast<double>(next() >> 11U) * 0x1.0p-53;
  }
  /// Uniform in [lo, hi], both ends included.
  int between(int lo, int hi) noexcept {
    return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  bool chance(double p) noexcept { return uniform(0, 1) < p; }
  template <class T, std::size_t N>
  const T& pick(const std::array<T, N>& a) noexcept {
    return a[next() % N];
  }

 private:
  std::uint64_t state_;
};

/// A small boat (or AUV at the surface) going about its work off Boston: position, course and
/// speed drift smoothly, attitude wobbles with the sea, the clock runs on (across midnight and
/// into the next day).
struct vehicle {
  double lat_deg = 42.361852;
  double lon_deg = -71.090813;
  double course_deg = 156.78;
  double heading_deg = 155.0;
  double speed_mps = 2.1;
  double roll_deg = 0;
  double pitch_deg = 0;
  double yaw_rate_dps = 0;
  double altitude_m = 46.6;
  double seconds = 16 * 3600 + 49 * 60 + 59.0;  ///< since midnight, UTC
  int year = 2014, month = 12, day = 31;

  void step(rng& g, double dt) noexcept {
    yaw_rate_dps = 0.8 * yaw_rate_dps + g.uniform(-1.5, 1.5);
    course_deg = wrap360(course_deg + yaw_rate_dps * dt);
    heading_deg = wrap360(course_deg + g.uniform(-4, 4));
    speed_mps = std::fmin(7.5, std::fmax(0.05, speed_mps + g.uniform(-0.15, 0.15)));
    roll_deg = 0.7 * roll_deg + g.uniform(-3, 3);
    pitch_deg = 0.7 * pitch_deg + g.uniform(-1.5, 1.5);
    altitude_m = std::fmin(60, std::fmax(20, altitude_m + g.uniform(-0.3, 0.3)));
    const double rad = course_deg * 3.14159265358979323846 / 180.0;
    const double metres = speed_mps * dt;
    lat_deg += metres * std::cos(rad) / 111'320.0;
    lon_deg += metres * std::sin(rad) / (111'320.0 * std::cos(lat_deg * 3.14159265358979 / 180));
    seconds += dt;
    if (seconds >= 86'400) {
      seconds -= 86'400;
      next_day();
    }
  }
  [[nodiscard]] double speed_knots() const noexcept { return speed_mps * 3600.0 / 1852.0; }

 private:
  static double wrap360(double d) noexcept {
    d = std::fmod(d, 360.0);
    return d < 0 ? d + 360.0 : d;
  }
  void next_day() noexcept {
    const nmea::date d{static_cast<std::uint16_t>(year), static_cast<std::uint8_t>(month),
                       static_cast<std::uint8_t>(day)};
    const auto ymd = std::chrono::sys_days{d.ymd()} + std::chrono::days{1};
    const std::chrono::year_month_day n{ymd};
    year = static_cast<int>(n.year());
    month = static_cast<int>(static_cast<unsigned>(n.month()));
    day = static_cast<int>(static_cast<unsigned>(n.day()));
  }
};

// ---------------------------------------------------------------------------------------------
// value helpers (a failure here is a generator bug: stop)

[[noreturn]] inline void generator_bug(const char* what) noexcept {
  std::fprintf(stderr, "seawire bench corpus: %s\n", what);
  std::abort();
}

template <class T>
T must(const result<T>& r, const char* what) noexcept {
  if (!r) generator_bug(what);
  return r.value;
}

inline nmea::decimal dec(double v, unsigned places) noexcept {
  return must(nmea::decimal::from_double(v, places), "decimal");
}
inline nmea::time_of_day tod(double seconds_since_midnight, unsigned places) noexcept {
  const auto ns = static_cast<std::int64_t>(seconds_since_midnight * 1e9);
  return must(nmea::time_of_day::from_since_midnight(std::chrono::nanoseconds{ns}, places), "time");
}
inline nmea::date date_of(const vehicle& v) noexcept {
  return {static_cast<std::uint16_t>(v.year), static_cast<std::uint8_t>(v.month),
          static_cast<std::uint8_t>(v.day)};
}
inline nmea::latitude lat(double deg, unsigned places) noexcept {
  return must(nmea::latitude::from_degrees(deg, places), "latitude");
}
inline nmea::longitude lon(double deg, unsigned places) noexcept {
  return must(nmea::longitude::from_degrees(deg, places), "longitude");
}

// ---------------------------------------------------------------------------------------------
// one message of each type, from the vehicle's current state

/// Fills messages from a seeded stream and a vehicle that moves on between messages.
class generator {
 public:
  explicit generator(std::uint64_t seed) noexcept : g_(seed) {}

  rng& random() noexcept { return g_; }
  vehicle& state() noexcept { return v_; }
  /// Moves the vehicle on by `dt` seconds.
  void advance(double dt) noexcept { v_.step(g_, dt); }

  // -- standard ---------------------------------------------------------------------------
  standard::rmc rmc() noexcept {
    standard::rmc m;
    m.talker = g_.chance(0.8) ? nmea::talker_id("GP") : nmea::talker_id("GN");
    m.time = tod(v_.seconds, 2);
    m.status = standard::rmc_status::active;
    m.lat = lat(v_.lat_deg, 5);
    m.lon = lon(v_.lon_deg, 5);
    m.speed_knots = dec(v_.speed_knots(), 3);
    m.course_true = dec(v_.course_deg, 2);
    m.date = date_of(v_);
    if (g_.chance(0.5)) m.magnetic_variation = variation(-14.2 + g_.uniform(-0.05, 0.05), 1);
    m.mode = g_.chance(0.9) ? standard::mode_indicator::autonomous
                            : standard::mode_indicator::differential;
    return m;
  }
  standard::gga gga() noexcept {
    standard::gga m;
    m.talker = g_.chance(0.8) ? nmea::talker_id("GP") : nmea::talker_id("GN");
    m.time = tod(v_.seconds, 2);
    m.lat = lat(v_.lat_deg, 5);
    m.lon = lon(v_.lon_deg, 5);
    const bool dgps = g_.chance(0.3);
    m.quality = dgps ? standard::gps_quality::dgps : standard::gps_quality::gps;
    m.satellites = static_cast<std::uint8_t>(g_.between(5, 14));
    m.hdop = dec(g_.uniform(0.6, 2.9), 2);
    m.altitude_m = dec(v_.altitude_m, 1);
    m.geoid_separation_m = dec(-33.2 + g_.uniform(-0.04, 0.04), 1);
    if (dgps) {
      m.dgps_age_s = dec(g_.uniform(0.5, 9.9), 1);
      m.dgps_station = static_cast<std::uint16_t>(g_.between(0, 1023));
    }
    return m;
  }
  standard::rpm rpm() noexcept {
    standard::rpm m;
    m.talker = "II";
    m.source = g_.chance(0.7) ? standard::rpm_source::shaft : standard::rpm_source::engine;
    m.number = static_cast<std::uint8_t>(g_.between(0, 2));
    m.speed_rpm = dec(600 + v_.speed_mps * 220 + g_.uniform(-15, 15), 1);
    m.pitch_percent = dec(g_.uniform(-20, 95), 1);
    m.status = standard::rpm_status::valid;
    return m;
  }
  standard::rsa rsa() noexcept {
    standard::rsa m;
    m.talker = "AG";
    m.starboard_angle = dec(std::fmax(-35, std::fmin(35, v_.yaw_rate_dps * 6)), 1);
    m.starboard_status = standard::rsa_status::valid;
    if (g_.chance(0.5)) {
      m.port_angle = dec(std::fmax(-35, std::fmin(35, v_.yaw_rate_dps * 6 + 0.4)), 1);
      m.port_status = standard::rsa_status::valid;
    }
    return m;
  }
  standard::vhw vhw() noexcept {
    standard::vhw m;
    m.talker = "VW";
    m.heading_true_deg = dec(v_.heading_deg, 1);
    m.heading_magnetic_deg = dec(std::fmod(v_.heading_deg + 14.2, 360), 1);
    m.speed_knots = dec(v_.speed_knots() * 0.97, 2);
    m.speed_kmh = dec(v_.speed_mps * 3.6 * 0.97, 2);
    return m;
  }
  standard::vbw vbw() noexcept {
    standard::vbw m;
    m.talker = "VD";
    const double knots = v_.speed_knots();
    m.longitudinal_water_knots = dec(knots * 0.97, 2);
    m.transverse_water_knots = dec(g_.uniform(-0.3, 0.3), 2);
    m.water_status = standard::vbw_status::valid;
    m.longitudinal_ground_knots = dec(knots, 2);
    m.transverse_ground_knots = dec(g_.uniform(-0.2, 0.2), 2);
    m.ground_status = standard::vbw_status::valid;
    return m;
  }
  standard::vwr vwr() noexcept {
    standard::vwr m;
    m.talker = "WI";
    const double angle = g_.uniform(0, 180);
    const double mps = g_.uniform(2, 14);
    m.angle_deg = dec(angle, 1);
    m.side = g_.chance(0.5) ? standard::bow_side::left : standard::bow_side::right;
    m.speed_knots = dec(mps * 3600 / 1852, 1);
    m.speed_mps = dec(mps, 1);
    m.speed_kmh = dec(mps * 3.6, 1);
    return m;
  }

  // -- ANELLO -----------------------------------------------------------------------------
  anello::papgpsctrl papgpsctrl() noexcept {
    anello::papgpsctrl m;
    m.control = g_.chance(0.8) ? anello::gps_control::use : anello::gps_control::ignore;
    return m;
  }
  /// The binary frame's payload, as a sender has it.
  anello::sensor_values sensor_values() noexcept {
    anello::sensor_values s;
    s.heading_deg = v_.heading_deg;
    s.latitude_deg = v_.lat_deg;
    s.longitude_deg = v_.lon_deg;
    s.sog_mps = v_.speed_mps;
    s.cog_deg = v_.course_deg;
    s.gps_time = anello::time_ms{std::chrono::milliseconds{
        1'719'000'000'000 + static_cast<std::int64_t>(v_.seconds * 1000)}};
    s.alt_msl_m = v_.altitude_m;
    s.geoid_sep_m = -33.2;
    s.hdop = g_.uniform(0.6, 2.9);
    s.fix_quality = 1;
    s.motor_pct = std::fmin(100, v_.speed_mps * 13);
    s.rudder_pct = std::fmax(-100, std::fmin(100, v_.yaw_rate_dps * 10));
    s.stw_mps = v_.speed_mps * 0.97;
    s.wind_speed_abs_mps = g_.uniform(2, 14);
    s.wind_dir_abs_deg = g_.uniform(0, 359);
    s.wind_speed_rel_mps = g_.uniform(2, 14);
    s.wind_dir_rel_deg = g_.uniform(0, 359);
    s.air_temp_c = 18.4 + g_.uniform(-0.5, 0.5);
    s.pressure_hpa = 1013;
    return s;
  }
  anello::sensor_frame_raw sensor_frame() noexcept {
    return must(anello::build_frame(sensor_values()), "sensor frame");
  }

  // -- the Bluefin layout (Kingfisher CPNVG/CPNVR, Sandshark BFNVG/BFNVR) -------------------
  template <class M>  // a bluefin::nav_update
  M nav_update() noexcept {
    M m;
    m.timestamp = tod(v_.seconds, 3);
    m.lat = lat(v_.lat_deg, 5);
    m.lon = lon(v_.lon_deg, 5);
    m.lon.degree_digits = 2;  // real vehicles write "7106.84603"
    m.gps = true;
    m.altitude_m = nmea::decimal(0);
    m.depth_m = nmea::decimal(0);
    m.heading_deg = dec(v_.heading_deg, 1);
    m.roll_deg = dec(v_.roll_deg, 1);
    m.pitch_deg = dec(v_.pitch_deg, 1);
    m.nav_timestamp = tod(std::fmax(0, v_.seconds - 0.007), 3);
    return m;
  }
  template <class M>  // a bluefin::velocity_update
  M velocity_update() noexcept {
    M m;
    const double rad = v_.course_deg * 3.14159265358979323846 / 180.0;
    m.timestamp = tod(v_.seconds, 3);
    m.vel_east_mps = dec(v_.speed_mps * std::sin(rad), 6);
    m.vel_north_mps = dec(v_.speed_mps * std::cos(rad), 6);
    m.vel_down_mps = nmea::decimal(0);
    m.pitch_rate_dps = dec(g_.uniform(-0.1, 0.1), 6);
    m.roll_rate_dps = dec(g_.uniform(-0.2, 0.2), 6);
    m.yaw_rate_dps = dec(v_.yaw_rate_dps, 6);
    return m;
  }

  // -- Kingfisher -------------------------------------------------------------------------
#if SEAWIRE_BENCH_HAS_KINGFISHER
  kingfisher::cpnvg cpnvg() noexcept { return nav_update<kingfisher::cpnvg>(); }
  kingfisher::cpnvr cpnvr() noexcept { return velocity_update<kingfisher::cpnvr>(); }
  kingfisher::cprcm cprcm() noexcept {
    kingfisher::cprcm m;
    m.timestamp = tod(v_.seconds, 3);
    m.compass_id = 0;
    m.heading_deg = dec(v_.heading_deg, 6);
    m.pitch_deg = dec(v_.pitch_deg, 6);
    m.roll_deg = dec(v_.roll_deg, 6);
    m.nav_timestamp = tod(std::fmax(0, v_.seconds - 0.005), 3);
    return m;
  }
  kingfisher::cprbs cprbs() noexcept {
    kingfisher::cprbs m;
    m.timestamp = tod(v_.seconds, 3);
    const double stack = 15.2 - v_.seconds / 86'400;
    m.stack_voltage_v = dec(stack, 6);
    m.min_cell_voltage_v = dec(stack - g_.uniform(0, 0.02), 6);
    m.max_cell_voltage_v = dec(stack + g_.uniform(0, 0.02), 6);
    m.temperature_c = nmea::decimal(0);
    return m;
  }
  kingfisher::cpimu cpimu() noexcept {
    kingfisher::cpimu m;
    m.timestamp = tod(v_.seconds, 3);
    m.rate_x_dps = dec(g_.uniform(-0.2, 0.2), 6);
    m.rate_y_dps = dec(g_.uniform(-0.1, 0.1), 6);
    m.rate_z_dps = dec(v_.yaw_rate_dps, 6);
    m.accel_x_mps2 = dec(g_.uniform(-0.1, 0.1), 6);
    m.accel_y_mps2 = dec(g_.uniform(-0.1, 0.2), 6);
    m.accel_z_mps2 = dec(-0.93 + g_.uniform(-0.02, 0.02), 6);
    return m;
  }
  kingfisher::cpalt cpalt() noexcept {
    kingfisher::cpalt m;
    m.timestamp = tod(v_.seconds, 3);
    m.lights_on = g_.chance(0.5);
    return m;
  }
  kingfisher::pydep pydep() noexcept {
    return must(kingfisher::pydep::from_rate(g_.uniform(-10, 10), g_.uniform(0, 80), 2), "pydep");
  }
  kingfisher::pydev pydev() noexcept {
    return must(kingfisher::pydev::from_heading(v_.course_deg, v_.speed_mps, 1), "pydev");
  }
  kingfisher::pydir pydir() noexcept {
    const double turn = g_.uniform(-15, 15);
    return must(kingfisher::pydir::from_percent(55 + turn, 55 - turn, 1), "pydir");
  }
  kingfisher::pyclt pyclt() noexcept {
    kingfisher::pyclt m;
    m.lights_on = g_.chance(0.5);
    return m;
  }
#endif

  // -- Sandshark --------------------------------------------------------------------------
  sandshark::bfsht bfsht() noexcept { return {tod(v_.seconds, 3)}; }
  sandshark::bfver bfver() noexcept { return {tod(v_.seconds, 3), "1.0"}; }
  sandshark::bfnvg bfnvg() noexcept {
    auto m = nav_update<sandshark::bfnvg>();
    m.lon.degree_digits = 3;
    m.altitude_m = dec(g_.uniform(5, 45), 1);
    m.depth_m = dec(g_.uniform(0, 20), 1);
    return m;
  }
  sandshark::bfnvr bfnvr() noexcept { return velocity_update<sandshark::bfnvr>(); }
  sandshark::bfmis bfmis() noexcept {
    sandshark::bfmis m;
    m.timestamp = tod(v_.seconds, 3);
    (void)m.dive_file.assign("dive1.xml");
    (void)m.status.assign(g_.chance(0.8) ? "Running /var/log/mission_12" : "Waiting");
    return m;
  }
  sandshark::bfack bfack() noexcept {
    sandshark::bfack m;
    m.timestamp = tod(v_.seconds, 3);
    (void)m.command.assign("RMB");
    m.command_timestamp = tod(std::fmax(0, v_.seconds - 0.04), 3);
    m.status = sandshark::ack_status::ok;
    return m;
  }
  sandshark::bfctl bfctl() noexcept { return {tod(v_.seconds, 3), true}; }
  sandshark::bplog bplog() noexcept {
    static constexpr std::array<std::string_view, 5> codes{"NVG", "NVR", "MIS", "CTL", "ACK"};
    sandshark::bplog m;
    (void)m.code.assign(g_.pick(codes));
    m.state = g_.chance(0.8) ? sandshark::log_state::on : sandshark::log_state::off;
    return m;
  }
  sandshark::bpsts bpsts() noexcept {
    sandshark::bpsts m;
    m.timestamp = tod(v_.seconds, 2);
    m.all_ok = true;
    (void)m.message.assign("BWSI Autonomy OK");
    return m;
  }
  sandshark::bprmb bprmb() noexcept {
    sandshark::bprmb m;
    m.timestamp = tod(v_.seconds, 2);
    m.heading = dec(v_.course_deg, 1);
    m.depth = dec(g_.uniform(0, 20), 1);
    m.depth_mode = sandshark::depth_mode::depth;
    m.speed = dec(g_.uniform(500, 1200), 0);
    m.speed_mode = sandshark::speed_mode::rpm;
    m.horizontal_mode = sandshark::horizontal_mode::heading;
    return m;
  }
  sandshark::bpabt bpabt() noexcept {
    sandshark::bpabt m;
    m.timestamp = tod(v_.seconds, 3);
    (void)m.message.assign("leak detected");
    m.reason = sandshark::abort_reason::with_errors;
    return m;
  }
  sandshark::bpver bpver() noexcept { return {tod(v_.seconds, 3), "1.0"}; }

  // -- RobotX -----------------------------------------------------------------------------
  robotx::rxhrb rxhrb() noexcept {
    robotx::rxhrb m;
    m.date = date_of(v_);
    m.time = tod(std::floor(v_.seconds), 0);
    m.lat = decimal_lat(21.31198 + (v_.lat_deg - 42.361852), 5);
    m.lon = decimal_lon(-157.88972 + (v_.lon_deg + 71.090813), 5);
    m.team_id = "AUVSI";
    m.system_mode = robotx::system_mode::autonomous;
    m.auv_status = robotx::auv_status::stowed;
    return m;
  }
  robotx::rxgat rxgat() noexcept {
    robotx::rxgat m;
    stamp(m);
    m.entrance_gate = robotx::gate::one;
    m.exit_gate = robotx::gate::two;
    m.light_buoy_active = robotx::light_buoy::on;
    m.light_pattern = pattern();
    return m;
  }
  robotx::rxcod rxcod() noexcept {
    robotx::rxcod m;
    stamp(m);
    m.light_pattern = pattern();
    return m;
  }
  robotx::rxdok rxdok() noexcept {
    return shape_report<robotx::rxdok>(robotx::color::red, robotx::dock_shape::triangle);
  }
  robotx::rxdel rxdel() noexcept {
    return shape_report<robotx::rxdel>(robotx::color::blue, robotx::deliver_shape::circle);
  }

 private:
  nmea::magnetic_variation variation(double deg, unsigned places) noexcept {
    return must(nmea::magnetic_variation::from_degrees(deg, places), "magnetic variation");
  }
  nmea::decimal_longitude decimal_lon(double deg, unsigned places) noexcept {
    return must(nmea::decimal_longitude::from_degrees(deg, places), "decimal longitude");
  }
  nmea::decimal_latitude decimal_lat(double deg, unsigned places) noexcept {
    return must(nmea::decimal_latitude::from_degrees(deg, places), "decimal latitude");
  }
  template <class M>
  void stamp(M& m) noexcept {
    m.date = date_of(v_);
    m.time = tod(std::floor(v_.seconds), 0);
    m.team_id = "AUVSI";
  }
  /// An RXDOK or RXDEL: stamped, the shape's colour and the shape.
  template <class M, class Shape>
  M shape_report(robotx::color color, Shape shape) noexcept {
    M m;
    stamp(m);
    m.shape_color = color;
    m.shape = shape;
    return m;
  }
  robotx::light_pattern pattern() noexcept {
    static constexpr std::array<std::string_view, 6> p{"RGB", "RBG", "GRB", "GBR", "BRG", "BGR"};
    return must(robotx::light_pattern::from(g_.pick(p)), "light pattern");
  }

  rng g_;
  vehicle v_;
};

/// make<T>(g): one T from the generator.
template <class T>
T make(generator& g) noexcept {
  namespace st = standard;
  namespace ss = sandshark;
  namespace rx = robotx;
  // clang-format off
  if constexpr (std::is_same_v<T, st::rmc>) return g.rmc();
  else if constexpr (std::is_same_v<T, st::gga>) return g.gga();
  else if constexpr (std::is_same_v<T, st::rpm>) return g.rpm();
  else if constexpr (std::is_same_v<T, st::rsa>) return g.rsa();
  else if constexpr (std::is_same_v<T, st::vhw>) return g.vhw();
  else if constexpr (std::is_same_v<T, st::vbw>) return g.vbw();
  else if constexpr (std::is_same_v<T, st::vwr>) return g.vwr();
  else if constexpr (std::is_same_v<T, anello::papgpsctrl>) return g.papgpsctrl();
#if SEAWIRE_BENCH_HAS_KINGFISHER
  else if constexpr (std::is_same_v<T, kingfisher::cpnvg>) return g.cpnvg();
  else if constexpr (std::is_same_v<T, kingfisher::cpnvr>) return g.cpnvr();
  else if constexpr (std::is_same_v<T, kingfisher::cprcm>) return g.cprcm();
  else if constexpr (std::is_same_v<T, kingfisher::cprbs>) return g.cprbs();
  else if constexpr (std::is_same_v<T, kingfisher::cpimu>) return g.cpimu();
  else if constexpr (std::is_same_v<T, kingfisher::cpalt>) return g.cpalt();
  else if constexpr (std::is_same_v<T, kingfisher::pydep>) return g.pydep();
  else if constexpr (std::is_same_v<T, kingfisher::pydev>) return g.pydev();
  else if constexpr (std::is_same_v<T, kingfisher::pydir>) return g.pydir();
  else if constexpr (std::is_same_v<T, kingfisher::pyclt>) return g.pyclt();
#endif
  else if constexpr (std::is_same_v<T, ss::bfsht>) return g.bfsht();
  else if constexpr (std::is_same_v<T, ss::bfver>) return g.bfver();
  else if constexpr (std::is_same_v<T, ss::bfnvg>) return g.bfnvg();
  else if constexpr (std::is_same_v<T, ss::bfnvr>) return g.bfnvr();
  else if constexpr (std::is_same_v<T, ss::bfmis>) return g.bfmis();
  else if constexpr (std::is_same_v<T, ss::bfack>) return g.bfack();
  else if constexpr (std::is_same_v<T, ss::bfctl>) return g.bfctl();
  else if constexpr (std::is_same_v<T, ss::bplog>) return g.bplog();
  else if constexpr (std::is_same_v<T, ss::bpsts>) return g.bpsts();
  else if constexpr (std::is_same_v<T, ss::bprmb>) return g.bprmb();
  else if constexpr (std::is_same_v<T, ss::bpabt>) return g.bpabt();
  else if constexpr (std::is_same_v<T, ss::bpver>) return g.bpver();
  else if constexpr (std::is_same_v<T, rx::rxhrb>) return g.rxhrb();
  else if constexpr (std::is_same_v<T, rx::rxgat>) return g.rxgat();
  else if constexpr (std::is_same_v<T, rx::rxcod>) return g.rxcod();
  else if constexpr (std::is_same_v<T, rx::rxdok>) return g.rxdok();
  else if constexpr (std::is_same_v<T, rx::rxdel>) return g.rxdel();
  else static_assert(sizeof(T) == 0, "no generator for this message type");
  // clang-format on
}

// ---------------------------------------------------------------------------------------------
// corpora

/// Sentences back to back in one buffer, each ending CR LF, and a view of each.
struct corpus {
  std::string bytes;
  std::vector<std::string_view> lines;  ///< into `bytes`, each with its CR LF

  corpus() = default;
  corpus(const corpus& o) : bytes(o.bytes), ends_(o.ends_) { reindex(); }
  corpus(corpus&& o) noexcept : bytes(std::move(o.bytes)), ends_(std::move(o.ends_)) { reindex(); }
  corpus& operator=(corpus o) noexcept {
    bytes = std::move(o.bytes);
    ends_ = std::move(o.ends_);
    reindex();
    return *this;
  }
  ~corpus() = default;

  void append(std::string_view line) {
    const char* const before = bytes.data();
    bytes.append(line);
    ends_.push_back(bytes.size());
    if (bytes.data() == before) {
      lines.emplace_back(bytes.data() + bytes.size() - line.size(), line.size());
    } else {
      reindex();  // the buffer moved: every view must follow it
    }
  }
  [[nodiscard]] std::size_t size() const noexcept { return lines.size(); }
  [[nodiscard]] double mean_length() const noexcept {
    return lines.empty() ? 0 : static_cast<double>(bytes.size()) / static_cast<double>(size());
  }

 private:
  void reindex() {
    lines.clear();
    std::size_t begin = 0;
    for (const std::size_t end : ends_) {
      lines.emplace_back(bytes.data() + begin, end - begin);
      begin = end;
    }
  }
  std::vector<std::size_t> ends_;
};

/// Writes `m` and checks that the line decodes back to `m`'s own encoding.
template <class T>
void append_message(corpus& c, const T& m) {
  const auto s = nmea::encode(m);
  if (!s) {
    std::fprintf(stderr, "seawire bench corpus: %.*s refused, %.*s at field %u\n",
                 static_cast<int>(T::nmea.address.size()), T::nmea.address.data(),
                 static_cast<int>(name(s.ec).size()), name(s.ec).data(), s.field);
    std::abort();
  }
  const auto back = nmea::decode<T>(s.view());
  if (!back || nmea::encode(back.value).view() != s.view()) generator_bug("round trip");
  c.append(s.view());
}

/// A corpus of one message type, with the messages it was written from.
template <class T>
struct message_corpus : corpus {
  std::vector<T> messages;
};

/// `n` messages of type T from a vehicle moving on 0.1 s between them.
template <class T>
message_corpus<T> corpus_of(std::size_t n, std::uint64_t seed = 1) {
  message_corpus<T> c;
  generator g(seed);
  for (std::size_t i = 0; i < n; ++i) {
    g.advance(0.1);
    c.messages.push_back(make<T>(g));
    append_message(c, c.messages.back());
  }
  return c;
}

/// A corpus of a family's message set, with the messages (as the set's variant).
template <class Set>
struct family_corpus : corpus {
  std::vector<typename Set::variant> messages;
};

namespace detail {
template <class... Ms, class F>
void with_message(nmea::message_set<Ms...>*, std::size_t index, F&& f) {
  std::size_t k = 0;
  (void)((k++ == index ? (f(static_cast<Ms*>(nullptr)), true) : false) || ...);
}
}  // namespace detail

/// `n` sentences of `Set`, sending the set's messages in the order `cycle` gives, over and
/// over; the vehicle moves on `dt` seconds between sentences.
template <class Set>
family_corpus<Set> family_corpus_from(std::size_t n, const std::vector<std::size_t>& cycle,
                                      double dt, std::uint64_t seed) {
  family_corpus<Set> c;
  generator g(seed);
  for (std::size_t i = 0; i < n; ++i) {
    g.advance(dt);
    detail::with_message(static_cast<Set*>(nullptr), cycle[i % cycle.size()], [&](auto* tag) {
      using M = std::remove_pointer_t<decltype(tag)>;
      const M m = make<M>(g);
      append_message(c, m);
      c.messages.emplace_back(m);
    });
  }
  return c;
}

/// GPS at 1 Hz as a receiver sends it: RMC then GGA, every second.
using rmc_gga_set = nmea::message_set<standard::rmc, standard::gga>;
inline family_corpus<rmc_gga_set> rmc_gga_corpus(std::size_t n, std::uint64_t seed = 1) {
  return family_corpus_from<rmc_gga_set>(n, {0, 1}, 0.5, seed);
}

/// Every family's sets at once: the decoder of a receiver that takes anything seawire knows.
using every_message = nmea::merge_sets<
#if SEAWIRE_BENCH_HAS_KINGFISHER
    kingfisher::from_vehicle, kingfisher::to_vehicle,
#endif
    sandshark::from_vehicle, sandshark::to_vehicle, robotx::reports, anello::nmea_inputs,
    anello::nmea_outputs, rmc_gga_set>::type;

/// The sentences the ANELLO INS takes for speed aiding: the rates a USV computer sends them.
inline family_corpus<anello::nmea_inputs> anello_inputs_corpus(std::size_t n,
                                                               std::uint64_t seed = 1) {
  // rpm rsa vhw vbw vwr papgpsctrl
  return family_corpus_from<anello::nmea_inputs>(n, {2, 3, 0, 1, 2, 3, 0, 4, 2, 3, 0, 1, 5}, 0.1,
                                                 seed);
}

/// Sandshark: what the vehicle sends (navigation at 10 Hz, the rest now and then) ...
inline family_corpus<sandshark::from_vehicle> sandshark_from_vehicle_corpus(
    std::size_t n, std::uint64_t seed = 1) {
  // bfsht bfver bfnvg bfnvr bfmis bfack bfctl
  return family_corpus_from<sandshark::from_vehicle>(
      n, {2, 3, 2, 3, 2, 3, 5, 2, 3, 2, 3, 4, 2, 3, 6, 2, 3, 1, 2, 3, 0}, 0.05, seed);
}
/// ... and what the payload sends (BPRMB keep-alive, heartbeat, the odd command).
inline family_corpus<sandshark::to_vehicle> sandshark_to_vehicle_corpus(std::size_t n,
                                                                        std::uint64_t seed = 1) {
  // bplog bpsts bprmb bpabt bpver
  return family_corpus_from<sandshark::to_vehicle>(n, {2, 1, 2, 2, 0, 2, 1, 2, 4, 2, 3}, 0.5, seed);
}

/// RobotX: the 1 Hz heartbeat and a task report now and then.
inline family_corpus<robotx::reports> robotx_corpus(std::size_t n, std::uint64_t seed = 1) {
  // rxhrb rxgat rxcod rxdok rxdel
  return family_corpus_from<robotx::reports>(n, {0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4}, 1.0, seed);
}

#if SEAWIRE_BENCH_HAS_KINGFISHER
/// Kingfisher: the vehicle's 10 Hz navigation, IMU and compass, 1 Hz battery, lights and GPS ...
inline family_corpus<kingfisher::from_vehicle> kingfisher_from_vehicle_corpus(
    std::size_t n, std::uint64_t seed = 1) {
  // cpnvg cpnvr cprcm cprbs cpimu cpalt rmc gga
  std::vector<std::size_t> cycle;
  for (int k = 0; k < 10; ++k) cycle.insert(cycle.end(), {0, 1, 4, 2});
  cycle.insert(cycle.end(), {3, 5, 6, 7});
  return family_corpus_from<kingfisher::from_vehicle>(n, cycle, 0.025, seed);
}
/// ... and the payload's commands.
inline family_corpus<kingfisher::to_vehicle> kingfisher_to_vehicle_corpus(std::size_t n,
                                                                          std::uint64_t seed = 1) {
  // pydep pydev pydir pyclt
  return family_corpus_from<kingfisher::to_vehicle>(n, {2, 2, 2, 0, 2, 2, 1, 2, 2, 3}, 0.1, seed);
}
#endif

/// `n` binary frames (56 bytes each) back to back, as the ANELLO input port would see them.
inline std::vector<std::uint8_t> anello_frames(std::size_t n, std::uint64_t seed = 1) {
  std::vector<std::uint8_t> out;
  generator g(seed);
  for (std::size_t i = 0; i < n; ++i) {
    g.advance(0.1);
    const anello::frame_bytes f = anello::encode_frame(g.sensor_frame());
    out.insert(out.end(), f.begin(), f.end());
  }
  return out;
}

}  // namespace seawire::bench
