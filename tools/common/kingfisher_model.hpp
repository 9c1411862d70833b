// SPDX-License-Identifier: BSL-1.0
#pragma once
// A small Kingfisher-sized surface vehicle for seawire-kingfisher-sim: two thrusters, a heading
// controller for PYDEV, first-order speed and yaw-rate responses, and the position integrated on
// the WGS84 ellipsoid. No I/O; the program steps it at its navigation rate.
//
// Dynamics (all documented in tools/kingfisher-sim/README.md):
// - Thrust t (-100..100 %) per side. Speed demand = max_speed * (left + right) / 200 (reverse is
//   capped at half the forward speed); yaw-rate demand = max_yaw_rate * (left - right) / 200,
//   positive clockwise (more port thrust turns to starboard).
// - PYDIR sets the two thrusts. PYDEP sets the yaw-rate demand (deg/s, as the Clearpath vehicle
//   reads it, or rad/s with --pydep-units rad) and the speed demand from one thrust percent.
//   PYDEV holds a heading: yaw-rate demand = heading_gain * heading error, clamped to
//   max_yaw_rate, and the speed demand is the commanded speed (clamped to max_speed).
// - Speed follows its demand with time constant speed_tau, yaw rate with yaw_tau.
// - With no command for `watchdog` seconds the demands drop to zero (thrusters stopped).
// - Roll and pitch are a small swell (sines with seeded phases) plus the roll of a turn.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace seawire::tools {

struct vehicle_params {
  double max_speed_mps = 1.7;          ///< forward, both thrusters at 100 %
  double max_yaw_rate_dps = 40;        ///< full differential thrust
  double speed_tau_s = 1.5;            ///< speed response time constant
  double yaw_tau_s = 0.5;              ///< yaw-rate response time constant
  double heading_gain = 1.0;           ///< deg/s of yaw rate per degree of heading error (PYDEV)
  double watchdog_s = 1.0;             ///< no command for this long: thrusters stop
  bool pydep_radians = false;          ///< PYDEP's yaw rate in rad/s (the spec) instead of deg/s
  double battery_full_v = 16.4;        ///< stack voltage at rest, full
  double battery_drain_v_per_h = 1.2;  ///< at full thrust on both sides
};

class vehicle_model {
 public:
  enum class mode : std::uint8_t { idle, thrust, rate, helm };

  vehicle_model(vehicle_params p, double lat_deg, double lon_deg, std::uint64_t seed)
      : p_(p), lat_(lat_deg), lon_(lon_deg), rng_(seed) {
    std::uniform_real_distribution<double> phase(0, 2 * std::numbers::pi);
    roll_phase_ = phase(rng_);
    pitch_phase_ = phase(rng_);
    heading_ = std::uniform_real_distribution<double>(0, 360)(rng_);
  }

  // Commands; `now` is the simulation time in seconds.
  void thrust(double left_pct, double right_pct, double now) {
    mode_ = mode::thrust;
    left_ = std::clamp(left_pct, -100.0, 100.0);
    right_ = std::clamp(right_pct, -100.0, 100.0);
    last_command_ = now;
  }
  void rate(double yaw_rate, double thrust_pct, double now) {
    mode_ = mode::rate;
    const double dps = p_.pydep_radians ? yaw_rate * 180 / std::numbers::pi : yaw_rate;
    rate_demand_ = std::clamp(dps, -p_.max_yaw_rate_dps, p_.max_yaw_rate_dps);
    left_ = right_ = std::clamp(thrust_pct, -100.0, 100.0);
    last_command_ = now;
  }
  void helm(double heading_deg, double speed_mps, double now) {
    mode_ = mode::helm;
    desired_heading_ = std::fmod(std::fmod(heading_deg, 360) + 360, 360);
    desired_speed_ = std::clamp(speed_mps, 0.0, p_.max_speed_mps);
    last_command_ = now;
  }
  void lights(bool on) { lights_ = on; }

  /// Advances the model by dt seconds to simulation time `now`.
  void step(double dt, double now) {
    if (mode_ != mode::idle && now - last_command_ > p_.watchdog_s) {
      mode_ = mode::idle;
      left_ = right_ = 0;
      watchdog_trips_++;
    }
    double speed_demand = 0;
    double rate_demand = 0;
    switch (mode_) {
      case mode::idle: break;
      case mode::thrust:
        speed_demand = p_.max_speed_mps * (left_ + right_) / 200;
        rate_demand = p_.max_yaw_rate_dps * (left_ - right_) / 200;
        break;
      case mode::rate:
        speed_demand = p_.max_speed_mps * (left_ + right_) / 200;
        rate_demand = rate_demand_;
        break;
      case mode::helm: {
        const double error = std::remainder(desired_heading_ - heading_, 360.0);
        rate_demand =
            std::clamp(p_.heading_gain * error, -p_.max_yaw_rate_dps, p_.max_yaw_rate_dps);
        speed_demand = desired_speed_;
        break;
      }
    }
    speed_demand = std::max(speed_demand, -p_.max_speed_mps / 2);
    const double old_speed = speed_;
    speed_ += (speed_demand - speed_) * (1 - std::exp(-dt / p_.speed_tau_s));
    yaw_rate_ += (rate_demand - yaw_rate_) * (1 - std::exp(-dt / p_.yaw_tau_s));
    accel_x_ = (speed_ - old_speed) / dt;
    heading_ = std::fmod(heading_ + yaw_rate_ * dt + 360, 360);

    // Position on the ellipsoid: metres to degrees with the radii of curvature at this latitude.
    constexpr double a = 6378137.0;
    constexpr double f = 1 / 298.257223563;
    constexpr double e2 = f * (2 - f);
    const double phi = lat_ * std::numbers::pi / 180;
    const double s = std::sin(phi);
    const double w = std::sqrt(1 - e2 * s * s);
    const double meridian = a * (1 - e2) / (w * w * w);
    const double normal = a / w;
    const double h = heading_ * std::numbers::pi / 180;
    lat_ += speed_ * std::cos(h) * dt / meridian * 180 / std::numbers::pi;
    lon_ += speed_ * std::sin(h) * dt / (normal * std::cos(phi)) * 180 / std::numbers::pi;
    if (lon_ > 180) lon_ -= 360;
    if (lon_ < -180) lon_ += 360;

    // Swell and the heel of a turn; rates are their derivatives.
    const double old_roll = roll_;
    const double old_pitch = pitch_;
    roll_ = 1.5 * std::sin(2 * std::numbers::pi * now / 4.0 + roll_phase_) +
            0.3 * yaw_rate_ * speed_ / 10;
    pitch_ = 0.8 * std::sin(2 * std::numbers::pi * now / 3.0 + pitch_phase_);
    roll_rate_ = (roll_ - old_roll) / dt;
    pitch_rate_ = (pitch_ - old_pitch) / dt;

    const double load = (std::fabs(left_) + std::fabs(right_)) / 200;
    battery_v_ -= p_.battery_drain_v_per_h * load * dt / 3600;
  }

  /// A small seeded measurement noise (standard deviation `sd`).
  double noise(double sd) { return std::normal_distribution<double>(0, sd)(rng_); }

  [[nodiscard]] double lat() const { return lat_; }
  [[nodiscard]] double lon() const { return lon_; }
  [[nodiscard]] double heading() const { return heading_; }
  [[nodiscard]] double speed() const { return speed_; }
  [[nodiscard]] double yaw_rate() const { return yaw_rate_; }
  [[nodiscard]] double roll() const { return roll_; }
  [[nodiscard]] double pitch() const { return pitch_; }
  [[nodiscard]] double roll_rate() const { return roll_rate_; }
  [[nodiscard]] double pitch_rate() const { return pitch_rate_; }
  [[nodiscard]] double accel_x() const { return accel_x_; }
  [[nodiscard]] double vel_east() const {
    return speed_ * std::sin(heading_ * std::numbers::pi / 180);
  }
  [[nodiscard]] double vel_north() const {
    return speed_ * std::cos(heading_ * std::numbers::pi / 180);
  }
  [[nodiscard]] double battery_v() const { return battery_v_; }
  [[nodiscard]] bool lights() const { return lights_; }
  [[nodiscard]] mode current_mode() const { return mode_; }
  [[nodiscard]] std::uint64_t watchdog_trips() const { return watchdog_trips_; }

 private:
  vehicle_params p_;
  double lat_;
  double lon_;
  std::mt19937_64 rng_;
  double heading_ = 0;
  double speed_ = 0;
  double yaw_rate_ = 0;
  double accel_x_ = 0;
  double roll_ = 0, pitch_ = 0, roll_rate_ = 0, pitch_rate_ = 0;
  double roll_phase_ = 0, pitch_phase_ = 0;
  double left_ = 0, right_ = 0, rate_demand_ = 0;
  double desired_heading_ = 0, desired_speed_ = 0;
  double last_command_ = 0;
  double battery_v_ = p_.battery_full_v;
  bool lights_ = false;
  mode mode_ = mode::idle;
  std::uint64_t watchdog_trips_ = 0;
};

}  // namespace seawire::tools
