// SPDX-License-Identifier: BSL-1.0
#pragma once
// The NMEA 2000 PGNs seawire describes: those the ANELLO Maritime INS takes as sensor input, the
// vessel heading, and the navigation, steering, environment and power PGNs of a vessel's bus.
// Each struct is one PGN, its members in wire order, then its table (field.hpp). Values are SI
// as on the wire (Pa, K, m/s, rad, rad/s, V, A, L, plus degrees of latitude and longitude, rpm,
// L/h, %, Ah, s, min). Where ANELLO's field lists differ from what devices send (128259's speed
// direction, 130311's source lookups, 127489's reserved byte), these follow the wire:
// docs/nmea2000.md.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "seawire/detail/algorithm.hpp"
#include "seawire/nmea2000/device_names.hpp"
#include "seawire/nmea2000/field.hpp"

namespace seawire::nmea2000 {

// ---------------------------------------------------------------------------------------------
// lookups

/// The kind of sensor behind a speed through the water (128259).
enum class water_reference : std::uint8_t {
  paddle_wheel = 0,
  pitot_tube = 1,
  doppler = 2,
  correlation = 3,  ///< correlation (ultrasound)
  electro_magnetic = 4,
};
constexpr std::array<std::string_view, 5> lookup_names(water_reference) noexcept {
  return {"paddle_wheel", "pitot_tube", "doppler", "correlation", "electro_magnetic"};
}
constexpr std::array<std::string_view, 5> lookup_titles(water_reference) noexcept {
  return {"Paddle wheel", "Pitot tube", "Doppler", "Correlation (ultra sound)", "Electro Magnetic"};
}

/// Where a temperature is measured (130311).
enum class temperature_source : std::uint8_t {
  sea = 0,
  outside = 1,
  inside = 2,
  engine_room = 3,
  main_cabin = 4,
  live_well = 5,
  bait_well = 6,
  refrigeration = 7,
  heating_system = 8,
  dew_point = 9,
  apparent_wind_chill = 10,
  theoretical_wind_chill = 11,
  heat_index = 12,
  freezer = 13,
  exhaust_gas = 14,
  shaft_seal = 15,
};
constexpr std::array<std::string_view, 16> lookup_names(temperature_source) noexcept {
  return {"sea",
          "outside",
          "inside",
          "engine_room",
          "main_cabin",
          "live_well",
          "bait_well",
          "refrigeration",
          "heating_system",
          "dew_point",
          "apparent_wind_chill",
          "theoretical_wind_chill",
          "heat_index",
          "freezer",
          "exhaust_gas",
          "shaft_seal"};
}
constexpr std::array<std::string_view, 16> lookup_titles(temperature_source) noexcept {
  return {"Sea Temperature",
          "Outside Temperature",
          "Inside Temperature",
          "Engine Room Temperature",
          "Main Cabin Temperature",
          "Live Well Temperature",
          "Bait Well Temperature",
          "Refrigeration Temperature",
          "Heating System Temperature",
          "Dew Point Temperature",
          "Apparent Wind Chill Temperature",
          "Theoretical Wind Chill Temperature",
          "Heat Index Temperature",
          "Freezer Temperature",
          "Exhaust Gas Temperature",
          "Shaft Seal Temperature"};
}

/// Where a humidity is measured (130311).
enum class humidity_source : std::uint8_t { inside = 0, outside = 1 };
constexpr std::array<std::string_view, 2> lookup_names(humidity_source) noexcept {
  return {"inside", "outside"};
}
constexpr std::array<std::string_view, 2> lookup_titles(humidity_source) noexcept {
  return {"Inside", "Outside"};
}

/// Engine discrete status 1 (127489): bit numbers.
enum class engine_status_1 : std::uint8_t {
  check_engine = 0,
  over_temperature = 1,
  low_oil_pressure = 2,
  low_oil_level = 3,
  low_fuel_pressure = 4,
  low_system_voltage = 5,
  low_coolant_level = 6,
  water_flow = 7,
  water_in_fuel = 8,
  charge_indicator = 9,
  preheat_indicator = 10,
  high_boost_pressure = 11,
  rev_limit_exceeded = 12,
  egr_system = 13,
  throttle_position_sensor = 14,
  emergency_stop = 15,
};
constexpr std::array<std::string_view, 16> lookup_names(engine_status_1) noexcept {
  return {
      "check_engine",       "over_temperature",   "low_oil_pressure",         "low_oil_level",
      "low_fuel_pressure",  "low_system_voltage", "low_coolant_level",        "water_flow",
      "water_in_fuel",      "charge_indicator",   "preheat_indicator",        "high_boost_pressure",
      "rev_limit_exceeded", "egr_system",         "throttle_position_sensor", "emergency_stop"};
}
constexpr std::array<std::string_view, 16> lookup_titles(engine_status_1) noexcept {
  return {
      "Check Engine",       "Over Temperature",   "Low Oil Pressure",         "Low Oil Level",
      "Low Fuel Pressure",  "Low System Voltage", "Low Coolant Level",        "Water Flow",
      "Water In Fuel",      "Charge Indicator",   "Preheat Indicator",        "High Boost Pressure",
      "Rev Limit Exceeded", "EGR System",         "Throttle Position Sensor", "Emergency Stop"};
}

/// Engine discrete status 2 (127489): bit numbers. Bits 8-15 have no name and are kept as sent.
enum class engine_status_2 : std::uint8_t {
  warning_level_1 = 0,
  warning_level_2 = 1,
  power_reduction = 2,
  maintenance_needed = 3,
  engine_comm_error = 4,
  sub_or_secondary_throttle = 5,
  neutral_start_protect = 6,
  engine_shutting_down = 7,
};
constexpr std::array<std::string_view, 8> lookup_names(engine_status_2) noexcept {
  return {"warning_level_1",       "warning_level_2",     "power_reduction",
          "maintenance_needed",    "engine_comm_error",   "sub_or_secondary_throttle",
          "neutral_start_protect", "engine_shutting_down"};
}
constexpr std::array<std::string_view, 8> lookup_titles(engine_status_2) noexcept {
  return {"Warning Level 1",       "Warning Level 2",     "Power Reduction",
          "Maintenance Needed",    "Engine Comm Error",   "Sub or Secondary Throttle",
          "Neutral Start Protect", "Engine Shutting Down"};
}

/// What a heading is measured from (127250). Raw values 2 and 3 are not values: out of range
/// ("error") and not available.
enum class heading_reference : std::uint8_t {
  true_north = 0,  ///< true heading
  magnetic = 1,    ///< magnetic heading (add deviation and variation for true)
};
constexpr std::array<std::string_view, 2> lookup_names(heading_reference) noexcept {
  return {"true", "magnetic"};
}
/// Raw 2, "error" (out of range), is a value canboat names.
constexpr std::array<std::string_view, 3> lookup_titles(heading_reference) noexcept {
  return {"True", "Magnetic", "Error"};
}

/// Where a magnetic variation comes from (127258): entered by hand, from a chart or table,
/// computed, or a World Magnetic Model epoch.
enum class variation_source : std::uint8_t {
  manual = 0,
  automatic_chart = 1,
  automatic_table = 2,
  automatic_calculation = 3,
  wmm_2000 = 4,
  wmm_2005 = 5,
  wmm_2010 = 6,
  wmm_2015 = 7,
  wmm_2020 = 8,
  wmm_2025 = 9,
};
constexpr std::array<std::string_view, 10> lookup_names(variation_source) noexcept {
  return {"manual",   "automatic_chart", "automatic_table", "automatic_calculation",
          "wmm_2000", "wmm_2005",        "wmm_2010",        "wmm_2015",
          "wmm_2020", "wmm_2025"};
}
constexpr std::array<std::string_view, 10> lookup_titles(variation_source) noexcept {
  return {"Manual",   "Automatic Chart", "Automatic Table", "Automatic Calculation",
          "WMM 2000", "WMM 2005",        "WMM 2010",        "WMM 2015",
          "WMM 2020", "WMM 2025"};
}

/// Which way a rudder is ordered to move (127245).
enum class rudder_direction : std::uint8_t {
  no_order = 0,
  to_starboard = 1,
  to_port = 2,
};
constexpr std::array<std::string_view, 3> lookup_names(rudder_direction) noexcept {
  return {"no_order", "to_starboard", "to_port"};
}
constexpr std::array<std::string_view, 3> lookup_titles(rudder_direction) noexcept {
  return {"No Order", "Move to starboard", "Move to port"};
}

/// What a wind speed and angle are measured against (130306): true over the ground from north,
/// magnetic over the ground, apparent, true relative to the bow over the ground or through the
/// water.
enum class wind_reference : std::uint8_t {
  true_north = 0,
  magnetic = 1,
  apparent = 2,
  true_boat = 3,
  true_water = 4,
};
constexpr std::array<std::string_view, 5> lookup_names(wind_reference) noexcept {
  return {"true_north", "magnetic", "apparent", "true_boat", "true_water"};
}
constexpr std::array<std::string_view, 5> lookup_titles(wind_reference) noexcept {
  return {"True (ground referenced to North)", "Magnetic (ground referenced to Magnetic North)",
          "Apparent", "True (boat referenced)", "True (water referenced)"};
}

/// What a pressure is measured in (130314).
enum class pressure_source : std::uint8_t {
  atmospheric = 0,
  water = 1,
  steam = 2,
  compressed_air = 3,
  hydraulic = 4,
  filter = 5,
  altimeter_setting = 6,
  oil = 7,
  fuel = 8,
};
constexpr std::array<std::string_view, 9> lookup_names(pressure_source) noexcept {
  return {"atmospheric",       "water", "steam", "compressed_air", "hydraulic", "filter",
          "altimeter_setting", "oil",   "fuel"};
}
constexpr std::array<std::string_view, 9> lookup_titles(pressure_source) noexcept {
  return {"Atmospheric",      "Water", "Steam", "Compressed Air", "Hydraulic", "Filter",
          "AltimeterSetting", "Oil",   "Fuel"};
}

/// What a tank holds (127505).
enum class tank_type : std::uint8_t {
  fuel = 0,
  water = 1,
  gray_water = 2,
  live_well = 3,
  oil = 4,
  black_water = 5,
};
constexpr std::array<std::string_view, 6> lookup_names(tank_type) noexcept {
  return {"fuel", "water", "gray_water", "live_well", "oil", "black_water"};
}
constexpr std::array<std::string_view, 6> lookup_titles(tank_type) noexcept {
  return {"Fuel", "Water", "Gray water", "Live well", "Oil", "Black water"};
}

/// The kind of DC source (127506).
enum class dc_source : std::uint8_t {
  battery = 0,
  alternator = 1,
  converter = 2,
  solar_cell = 3,
  wind_generator = 4,
};
constexpr std::array<std::string_view, 5> lookup_names(dc_source) noexcept {
  return {"battery", "alternator", "converter", "solar_cell", "wind_generator"};
}
constexpr std::array<std::string_view, 5> lookup_titles(dc_source) noexcept {
  return {"Battery", "Alternator", "Convertor", "Solar cell", "Wind generator"};
}

/// How a navigation value was obtained (129283, 130577).
enum class residual_mode : std::uint8_t {
  autonomous = 0,
  differential = 1,
  estimated = 2,
  simulator = 3,
  manual = 4,
};
constexpr std::array<std::string_view, 5> lookup_names(residual_mode) noexcept {
  return {"autonomous", "differential", "estimated", "simulator", "manual"};
}
constexpr std::array<std::string_view, 5> lookup_titles(residual_mode) noexcept {
  return {"Autonomous", "Differential enhanced", "Estimated", "Simulator", "Manual"};
}

/// A two-bit yes or no (raw 2 is an error, 3 not available).
enum class yes_no : std::uint8_t {
  no = 0,
  yes = 1,
};
constexpr std::array<std::string_view, 2> lookup_names(yes_no) noexcept { return {"no", "yes"}; }

/// The clock a system time comes from (126992).
enum class time_source : std::uint8_t {
  gps = 0,
  glonass = 1,
  radio_station = 2,
  local_cesium_clock = 3,
  local_rubidium_clock = 4,
  local_crystal_clock = 5,
};
constexpr std::array<std::string_view, 6> lookup_names(time_source) noexcept {
  return {"gps",
          "glonass",
          "radio_station",
          "local_cesium_clock",
          "local_rubidium_clock",
          "local_crystal_clock"};
}
constexpr std::array<std::string_view, 6> lookup_titles(time_source) noexcept {
  return {"GPS",
          "GLONASS",
          "Radio Station",
          "Local Cesium clock",
          "Local Rubidium clock",
          "Local Crystal clock"};
}
constexpr std::array<std::string_view, 2> lookup_titles(yes_no) noexcept { return {"No", "Yes"}; }

/// A GNSS fix mode (129539): one, two or three dimensions, or chosen by the receiver.
enum class gnss_mode : std::uint8_t {
  fix_1d = 0,
  fix_2d = 1,
  fix_3d = 2,
  automatic = 3,
};
constexpr std::array<std::string_view, 4> lookup_names(gnss_mode) noexcept {
  return {"1d", "2d", "3d", "auto"};
}
constexpr std::array<std::string_view, 4> lookup_titles(gnss_mode) noexcept {
  return {"1D", "2D", "3D", "Auto"};
}

/// How a bearing to a waypoint is computed (129284).
enum class bearing_mode : std::uint8_t {
  great_circle = 0,
  rhumb_line = 1,
};
constexpr std::array<std::string_view, 2> lookup_names(bearing_mode) noexcept {
  return {"great_circle", "rhumb_line"};
}
constexpr std::array<std::string_view, 2> lookup_titles(bearing_mode) noexcept {
  return {"Great Circle", "Rhumbline"};
}

/// An ISO acknowledgement's answer (59392): acknowledged, refused, access denied, or busy.
enum class iso_control : std::uint8_t {
  ack = 0,
  nak = 1,
  access_denied = 2,
  address_busy = 3,
};
constexpr std::array<std::string_view, 4> lookup_names(iso_control) noexcept {
  return {"ack", "nak", "access_denied", "address_busy"};
}
constexpr std::array<std::string_view, 4> lookup_titles(iso_control) noexcept {
  return {"ACK", "NAK", "Access Denied", "Address Busy"};
}
/// Which engine an engine PGN is of (127488, 127489), as canboat names the first two instance
/// numbers. The field stays a number, written as one (an engine past the second has an instance
/// too): these are only its titles.
enum class engine_instance : std::uint8_t {
  single_or_port = 0,  ///< the only engine, or the port one of two
  starboard = 1,       ///< the starboard one of two
};
constexpr std::array<std::string_view, 2> lookup_titles(engine_instance) noexcept {
  return {"Single Engine or Dual Engine Port", "Dual Engine Starboard"};
}

// ---------------------------------------------------------------------------------------------
// the PGNs

namespace res {
inline constexpr resolution quarter{25, -2};       ///< 0.25
inline constexpr resolution hundred{1, 2};         ///< 100
inline constexpr resolution thousand{1, 3};        ///< 1000
inline constexpr resolution tenth{1, -1};          ///< 0.1
inline constexpr resolution hundredth{1, -2};      ///< 0.01
inline constexpr resolution thousandth{1, -3};     ///< 0.001
inline constexpr resolution humidity{4, -3};       ///< 0.004
inline constexpr resolution radian{1, -4};         ///< 0.0001 rad
inline constexpr resolution turn_rate{3125, -11};  ///< 3.125e-8 rad/s
inline constexpr resolution ten{1, 1};             ///< 10
inline constexpr resolution degree_e7{1, -7};      ///< 1e-7 degree
inline constexpr resolution minute{6, 1};          ///< 60 s
}  // namespace res

/// PGN 127488 Engine Parameters, Rapid Update: 8 bytes, single frame, priority 2, 10 Hz.
/// Instance 0 is the single engine or the port one of two, 1 the starboard one.
struct engine_parameters_rapid {
  unsigned_number<8> instance;
  unsigned_number<16, res::quarter> speed_rpm;
  unsigned_number<16, res::hundred> boost_pressure_pa;
  signed_number<8> tilt_trim_pct;  ///< negative = trimmed down

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{127488, "engine_parameters_rapid",
                                 "Engine Parameters, Rapid Update", 2, framing::single_frame, 100},
                        field<&P::instance, engine_instance>("instance", "Instance"),
                        field<&P::speed_rpm>("speed_rpm", "Speed"),
                        field<&P::boost_pressure_pa>("boost_pressure_pa", "Boost Pressure"),
                        field<&P::tilt_trim_pct>("tilt_trim_pct", "Tilt/Trim"), reserved<16>);
  }
  [[nodiscard]] constexpr bool operator==(const engine_parameters_rapid&) const noexcept = default;
};

/// PGN 127489 Engine Parameters, Dynamic: 26 bytes, fast packet, priority 2, 2 Hz.
struct engine_parameters_dynamic {
  unsigned_number<8> instance;
  unsigned_number<16, res::hundred> oil_pressure_pa;
  unsigned_number<16, res::tenth> oil_temperature_k;
  unsigned_number<16, res::hundredth> temperature_k;  ///< coolant
  signed_number<16, res::hundredth> alternator_potential_v;
  signed_number<16, res::tenth> fuel_rate_lph;  ///< litres per hour
  unsigned_number<32> total_engine_hours_s;     ///< in seconds, despite the name
  unsigned_number<16, res::hundred> coolant_pressure_pa;
  unsigned_number<16, res::thousand> fuel_pressure_pa;
  flags<engine_status_1, 16> discrete_status_1;
  flags<engine_status_2, 16> discrete_status_2;
  signed_number<8> engine_load_pct;
  signed_number<8> engine_torque_pct;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{127489, "engine_parameters_dynamic", "Engine Parameters, Dynamic", 2,
                 framing::fast_packet, 500},
        field<&P::instance, engine_instance>("instance", "Instance"),
        field<&P::oil_pressure_pa>("oil_pressure_pa", "Oil pressure"),
        field<&P::oil_temperature_k>("oil_temperature_k", "Oil temperature"),
        field<&P::temperature_k>("temperature_k", "Temperature"),
        field<&P::alternator_potential_v>("alternator_potential_v", "Alternator Potential"),
        field<&P::fuel_rate_lph>("fuel_rate_lph", "Fuel Rate"),
        field<&P::total_engine_hours_s>("total_engine_hours_s", "Total Engine hours"),
        field<&P::coolant_pressure_pa>("coolant_pressure_pa", "Coolant Pressure"),
        field<&P::fuel_pressure_pa>("fuel_pressure_pa", "Fuel Pressure"), reserved<8>,
        field<&P::discrete_status_1>("discrete_status_1", "Discrete Status 1"),
        field<&P::discrete_status_2>("discrete_status_2", "Discrete Status 2"),
        field<&P::engine_load_pct>("engine_load_pct", "Engine Load"),
        field<&P::engine_torque_pct>("engine_torque_pct", "Engine Torque"));
  }
  [[nodiscard]] constexpr bool operator==(const engine_parameters_dynamic&) const noexcept =
      default;
};

/// PGN 128259 Speed, Water Referenced: 8 bytes, single frame, priority 2, 1 Hz.
struct speed_water_referenced {
  unsigned_number<8> sid;  ///< ties readings of one moment together across PGNs
  unsigned_number<16, res::hundredth> speed_water_mps;
  unsigned_number<16, res::hundredth> speed_ground_mps;
  lookup<water_reference, 8> speed_type;
  unsigned_number<4> speed_direction;  ///< meaning not published; senders leave it at 15

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{128259, "speed_water_referenced", "Speed", 2, framing::single_frame, 1000},
        field<&P::sid>("sid", "SID"),
        field<&P::speed_water_mps>("speed_water_mps", "Speed Water Referenced"),
        field<&P::speed_ground_mps>("speed_ground_mps", "Speed Ground Referenced"),
        field<&P::speed_type>("speed_type", "Speed Water Referenced Type"),
        field<&P::speed_direction>("speed_direction", "Speed Direction"), reserved<12>);
  }
  [[nodiscard]] constexpr bool operator==(const speed_water_referenced&) const noexcept = default;
};

/// PGN 128275 Distance Log: 14 bytes, fast packet, priority 6, 1 Hz. Date and time are of the
/// measurement (UTC); most logs send them as not available and fill only the two distances.
struct distance_log {
  nmea2000::day_count date;
  nmea2000::time_since_midnight time;
  unsigned_number<32> log_m;       ///< total cumulative distance
  unsigned_number<32> trip_log_m;  ///< distance since last reset

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{128275, "distance_log", "Distance Log", 6, framing::fast_packet, 1000},
        field<&P::date>("date", "Date"), field<&P::time>("time", "Time"),
        field<&P::log_m>("log_m", "Log"), field<&P::trip_log_m>("trip_log_m", "Trip Log"));
  }
  [[nodiscard]] constexpr bool operator==(const distance_log&) const noexcept = default;
};

/// PGN 130311 Environmental Parameters: 8 bytes, single frame, priority 5, 2 Hz.
struct environmental_parameters {
  unsigned_number<8> sid;
  lookup<nmea2000::temperature_source, 6> temperature_source;
  lookup<nmea2000::humidity_source, 2> humidity_source;
  unsigned_number<16, res::hundredth> temperature_k;
  signed_number<16, res::humidity> humidity_pct;  ///< relative humidity
  unsigned_number<16, res::hundred> atmospheric_pressure_pa;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{130311, "environmental_parameters", "Environmental Parameters", 5,
                 framing::single_frame, 500},
        field<&P::sid>("sid", "SID"),
        field<&P::temperature_source>("temperature_source", "Temperature Source"),
        field<&P::humidity_source>("humidity_source", "Humidity Source"),
        field<&P::temperature_k>("temperature_k", "Temperature"),
        field<&P::humidity_pct>("humidity_pct", "Humidity"),
        field<&P::atmospheric_pressure_pa>("atmospheric_pressure_pa", "Atmospheric Pressure"));
  }
  [[nodiscard]] constexpr bool operator==(const environmental_parameters&) const noexcept = default;
};

/// PGN 130578 Vessel Speed Components: 12 bytes, fast packet, priority 2, 4 Hz. Longitudinal
/// positive = ahead, transverse positive = starboard; at most +-32.764 m/s.
struct vessel_speed_components {
  signed_number<16, res::thousandth> longitudinal_water_mps;
  signed_number<16, res::thousandth> transverse_water_mps;
  signed_number<16, res::thousandth> longitudinal_ground_mps;
  signed_number<16, res::thousandth> transverse_ground_mps;
  signed_number<16, res::thousandth> stern_water_mps;  ///< transverse speed at the stern
  signed_number<16, res::thousandth> stern_ground_mps;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{130578, "vessel_speed_components", "Vessel Speed Components", 2,
                 framing::fast_packet, 250},
        field<&P::longitudinal_water_mps>("longitudinal_water_mps",
                                          "Longitudinal Speed, Water-referenced"),
        field<&P::transverse_water_mps>("transverse_water_mps",
                                        "Transverse Speed, Water-referenced"),
        field<&P::longitudinal_ground_mps>("longitudinal_ground_mps",
                                           "Longitudinal Speed, Ground-referenced"),
        field<&P::transverse_ground_mps>("transverse_ground_mps",
                                         "Transverse Speed, Ground-referenced"),
        field<&P::stern_water_mps>("stern_water_mps", "Stern Speed, Water-referenced"),
        field<&P::stern_ground_mps>("stern_ground_mps", "Stern Speed, Ground-referenced"));
  }
  [[nodiscard]] constexpr bool operator==(const vessel_speed_components&) const noexcept = default;
};

/// PGN 127250 Vessel Heading: 8 bytes, single frame, priority 2, 10 Hz. Angles in radians:
/// the heading from the reference named, deviation and variation positive east (a magnetic
/// heading plus both is the true heading).
struct vessel_heading {
  unsigned_number<8> sid;
  unsigned_number<16, res::radian> heading_rad;
  signed_number<16, res::radian> deviation_rad;
  signed_number<16, res::radian> variation_rad;
  lookup<heading_reference, 2> reference;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{127250, "vessel_heading", "Vessel Heading", 2, framing::single_frame, 100},
        field<&P::sid>("sid", "SID"), field<&P::heading_rad>("heading_rad", "Heading"),
        field<&P::deviation_rad>("deviation_rad", "Deviation"),
        field<&P::variation_rad>("variation_rad", "Variation"),
        field<&P::reference>("reference", "Reference"), reserved<6>);
  }
  [[nodiscard]] constexpr bool operator==(const vessel_heading&) const noexcept = default;
};

/// PGN 127251 Rate of Turn: 8 bytes, single frame, priority 2, 10 Hz. Positive turning to
/// starboard, in rad/s at 3.125e-8 rad/s (1/32 of 1e-6).
struct rate_of_turn {
  unsigned_number<8> sid;
  signed_number<32, res::turn_rate> rate_radps;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{127251, "rate_of_turn", "Rate of Turn", 2, framing::single_frame, 100},
        field<&P::sid>("sid", "SID"), field<&P::rate_radps>("rate_radps", "Rate"), reserved<24>);
  }
  [[nodiscard]] constexpr bool operator==(const rate_of_turn&) const noexcept = default;
};

/// PGN 127257 Attitude: 8 bytes, single frame, priority 3, 1 Hz. Angles in radians: yaw (heading),
/// pitch positive bow up, roll positive starboard down.
struct attitude {
  unsigned_number<8> sid;
  signed_number<16, res::radian> yaw_rad;
  signed_number<16, res::radian> pitch_rad;
  signed_number<16, res::radian> roll_rad;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{127257, "attitude", "Attitude", 3, framing::single_frame, 1000},
                        field<&P::sid>("sid", "SID"), field<&P::yaw_rad>("yaw_rad", "Yaw"),
                        field<&P::pitch_rad>("pitch_rad", "Pitch"),
                        field<&P::roll_rad>("roll_rad", "Roll"), reserved<8>);
  }
  [[nodiscard]] constexpr bool operator==(const attitude&) const noexcept = default;
};

/// PGN 127258 Magnetic Variation: 8 bytes, single frame, priority 7, 1 Hz. The variation (positive
/// east) at the vessel, where it comes from and the date it is valid from.
struct magnetic_variation {
  unsigned_number<8> sid;
  lookup<nmea2000::variation_source, 4> source;
  nmea2000::day_count age_of_service;
  signed_number<16, res::radian> variation_rad;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{127258, "magnetic_variation", "Magnetic Variation", 7,
                                 framing::single_frame, 1000},
                        field<&P::sid>("sid", "SID"), field<&P::source>("source", "Source"),
                        reserved<4>, field<&P::age_of_service>("age_of_service", "Age of service"),
                        field<&P::variation_rad>("variation_rad", "Variation"), reserved<16>);
  }
  [[nodiscard]] constexpr bool operator==(const magnetic_variation&) const noexcept = default;
};

/// PGN 128267 Water Depth: 8 bytes, single frame, priority 3, 1 Hz. Depth below the transducer; the
/// offset from the transducer to the surface (positive) or the keel (negative), and the sounder's
/// range.
struct water_depth {
  unsigned_number<8> sid;
  unsigned_number<32, res::hundredth> depth_m;
  signed_number<16, res::thousandth> offset_m;
  unsigned_number<8, res::ten> range_m;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{128267, "water_depth", "Water Depth", 3, framing::single_frame, 1000},
        field<&P::sid>("sid", "SID"), field<&P::depth_m>("depth_m", "Depth"),
        field<&P::offset_m>("offset_m", "Offset"), field<&P::range_m>("range_m", "Range"));
  }
  [[nodiscard]] constexpr bool operator==(const water_depth&) const noexcept = default;
};

/// PGN 129025 Position, Rapid Update: 8 bytes, single frame, priority 2, 10 Hz. Latitude and
/// longitude in degrees (WGS 84) at 1e-7 degree, north and east positive.
struct position_rapid {
  signed_number<32, res::degree_e7> latitude_deg;
  signed_number<32, res::degree_e7> longitude_deg;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{129025, "position_rapid", "Position, Rapid Update", 2, framing::single_frame, 100},
        field<&P::latitude_deg>("latitude_deg", "Latitude"),
        field<&P::longitude_deg>("longitude_deg", "Longitude"));
  }
  [[nodiscard]] constexpr bool operator==(const position_rapid&) const noexcept = default;
};

/// PGN 129026 COG & SOG, Rapid Update: 8 bytes, single frame, priority 2, 4 Hz. Course and speed
/// over the ground; the course is from the reference named.
struct cog_sog_rapid {
  unsigned_number<8> sid;
  lookup<nmea2000::heading_reference, 2> cog_reference;
  unsigned_number<16, res::radian> cog_rad;
  unsigned_number<16, res::hundredth> sog_mps;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{129026, "cog_sog_rapid", "COG & SOG, Rapid Update", 2, framing::single_frame, 250},
        field<&P::sid>("sid", "SID"), field<&P::cog_reference>("cog_reference", "COG Reference"),
        reserved<6>, field<&P::cog_rad>("cog_rad", "COG"), field<&P::sog_mps>("sog_mps", "SOG"),
        reserved<16>);
  }
  [[nodiscard]] constexpr bool operator==(const cog_sog_rapid&) const noexcept = default;
};

/// PGN 127245 Rudder: 8 bytes, single frame, priority 2, 10 Hz. The rudder's position and the order
/// given to it, in radians, positive to starboard.
struct rudder {
  unsigned_number<8> instance;
  lookup<nmea2000::rudder_direction, 3> direction_order;
  signed_number<16, res::radian> angle_order_rad;
  signed_number<16, res::radian> position_rad;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{127245, "rudder", "Rudder", 2, framing::single_frame, 100},
                        field<&P::instance>("instance", "Instance"),
                        field<&P::direction_order>("direction_order", "Direction Order"),
                        reserved<5>, field<&P::angle_order_rad>("angle_order_rad", "Angle Order"),
                        field<&P::position_rad>("position_rad", "Position"), reserved<16>);
  }
  [[nodiscard]] constexpr bool operator==(const rudder&) const noexcept = default;
};

/// PGN 130306 Wind Data: 8 bytes, single frame, priority 2, 10 Hz. Wind speed and the angle it
/// comes from, against the reference named.
struct wind_data {
  unsigned_number<8> sid;
  unsigned_number<16, res::hundredth> wind_speed_mps;
  unsigned_number<16, res::radian> wind_angle_rad;
  lookup<nmea2000::wind_reference, 3> reference;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{130306, "wind_data", "Wind Data", 2, framing::single_frame, 100},
                        field<&P::sid>("sid", "SID"),
                        field<&P::wind_speed_mps>("wind_speed_mps", "Wind Speed"),
                        field<&P::wind_angle_rad>("wind_angle_rad", "Wind Angle"),
                        field<&P::reference>("reference", "Reference"), reserved<21>);
  }
  [[nodiscard]] constexpr bool operator==(const wind_data&) const noexcept = default;
};

/// PGN 130312 Temperature: 8 bytes, single frame, priority 5, every 2 s. A measured temperature and
/// its set point, in K at 0.01 K.
struct temperature {
  unsigned_number<8> sid;
  unsigned_number<8> instance;
  lookup<nmea2000::temperature_source, 8> source;
  unsigned_number<16, res::hundredth> actual_temperature_k;
  unsigned_number<16, res::hundredth> set_temperature_k;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{130312, "temperature", "Temperature", 5, framing::single_frame, 2000},
        field<&P::sid>("sid", "SID"), field<&P::instance>("instance", "Instance"),
        field<&P::source>("source", "Source"),
        field<&P::actual_temperature_k>("actual_temperature_k", "Actual Temperature"),
        field<&P::set_temperature_k>("set_temperature_k", "Set Temperature"), reserved<8>);
  }
  [[nodiscard]] constexpr bool operator==(const temperature&) const noexcept = default;
};

/// PGN 130313 Humidity: 8 bytes, single frame, priority 5, every 2 s. A measured relative humidity
/// and its set point, in % at 0.004 %.
struct humidity {
  unsigned_number<8> sid;
  unsigned_number<8> instance;
  lookup<nmea2000::humidity_source, 8> source;
  signed_number<16, res::humidity> actual_humidity_pct;
  signed_number<16, res::humidity> set_humidity_pct;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{130313, "humidity", "Humidity", 5, framing::single_frame, 2000},
                        field<&P::sid>("sid", "SID"), field<&P::instance>("instance", "Instance"),
                        field<&P::source>("source", "Source"),
                        field<&P::actual_humidity_pct>("actual_humidity_pct", "Actual Humidity"),
                        field<&P::set_humidity_pct>("set_humidity_pct", "Set Humidity"),
                        reserved<8>);
  }
  [[nodiscard]] constexpr bool operator==(const humidity&) const noexcept = default;
};

/// PGN 130314 Actual Pressure: 8 bytes, single frame, priority 5, every 2 s. A measured pressure in
/// Pa at 0.1 Pa, signed (a gauge pressure may be negative).
struct actual_pressure {
  unsigned_number<8> sid;
  unsigned_number<8> instance;
  lookup<nmea2000::pressure_source, 8> source;
  signed_number<32, res::tenth> pressure_pa;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{130314, "actual_pressure", "Actual Pressure", 5, framing::single_frame, 2000},
        field<&P::sid>("sid", "SID"), field<&P::instance>("instance", "Instance"),
        field<&P::source>("source", "Source"), field<&P::pressure_pa>("pressure_pa", "Pressure"),
        reserved<8>);
  }
  [[nodiscard]] constexpr bool operator==(const actual_pressure&) const noexcept = default;
};

/// PGN 130316 Temperature Extended Range: 8 bytes, single frame, priority 5, every 2 s. A measured
/// temperature in K at 0.001 K (24 bits: up to 16 777 K) and its set point at 0.1 K.
struct temperature_extended {
  unsigned_number<8> sid;
  unsigned_number<8> instance;
  lookup<nmea2000::temperature_source, 8> source;
  unsigned_number<24, res::thousandth> temperature_k;
  unsigned_number<16, res::tenth> set_temperature_k;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{130316, "temperature_extended", "Temperature Extended Range", 5,
                                 framing::single_frame, 2000},
                        field<&P::sid>("sid", "SID"), field<&P::instance>("instance", "Instance"),
                        field<&P::source>("source", "Source"),
                        field<&P::temperature_k>("temperature_k", "Temperature"),
                        field<&P::set_temperature_k>("set_temperature_k", "Set Temperature"));
  }
  [[nodiscard]] constexpr bool operator==(const temperature_extended&) const noexcept = default;
};

/// PGN 127508 Battery Status: 8 bytes, single frame, priority 6, every 1.5 s. A battery's voltage,
/// current (positive charging) and temperature; the sequence ID comes last.
struct battery_status {
  unsigned_number<8> instance;
  signed_number<16, res::hundredth> voltage_v;
  signed_number<16, res::tenth> current_a;
  unsigned_number<16, res::hundredth> temperature_k;
  unsigned_number<8> sid;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{127508, "battery_status", "Battery Status", 6, framing::single_frame, 1500},
        field<&P::instance>("instance", "Instance"), field<&P::voltage_v>("voltage_v", "Voltage"),
        field<&P::current_a>("current_a", "Current"),
        field<&P::temperature_k>("temperature_k", "Temperature"), field<&P::sid>("sid", "SID"));
  }
  [[nodiscard]] constexpr bool operator==(const battery_status&) const noexcept = default;
};

/// PGN 127505 Fluid Level: 8 bytes, single frame, priority 6, every 2.5 s. A tank's level in % of
/// its capacity (litres at 0.1 L); instance and type share the first byte.
struct fluid_level {
  unsigned_number<4> instance;
  lookup<nmea2000::tank_type, 4> fluid_type;
  signed_number<16, res::humidity> level_pct;
  unsigned_number<32, res::tenth> capacity_l;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{127505, "fluid_level", "Fluid Level", 6, framing::single_frame, 2500},
        field<&P::instance>("instance", "Instance"), field<&P::fluid_type>("fluid_type", "Type"),
        field<&P::level_pct>("level_pct", "Level"), field<&P::capacity_l>("capacity_l", "Capacity"),
        reserved<8>);
  }
  [[nodiscard]] constexpr bool operator==(const fluid_level&) const noexcept = default;
};

/// PGN 127506 DC Detailed Status: 11 bytes, fast packet, priority 6, every 1.5 s. A DC source's
/// charge and health in %, the time left at the present rate (whole minutes, in s), the ripple
/// voltage and the capacity left in Ah.
struct dc_detailed_status {
  unsigned_number<8> sid;
  unsigned_number<8> instance;
  lookup<nmea2000::dc_source, 8> dc_type;
  unsigned_number<8> state_of_charge_pct;
  unsigned_number<8> state_of_health_pct;
  unsigned_number<16, res::minute> time_remaining_s;
  unsigned_number<16, res::thousandth> ripple_voltage_v;
  unsigned_number<16> remaining_capacity_ah;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{127506, "dc_detailed_status", "DC Detailed Status", 6, framing::fast_packet, 1500},
        field<&P::sid>("sid", "SID"), field<&P::instance>("instance", "Instance"),
        field<&P::dc_type>("dc_type", "DC Type"),
        field<&P::state_of_charge_pct>("state_of_charge_pct", "State of Charge"),
        field<&P::state_of_health_pct>("state_of_health_pct", "State of Health"),
        field<&P::time_remaining_s>("time_remaining_s", "Time Remaining"),
        field<&P::ripple_voltage_v>("ripple_voltage_v", "Ripple Voltage"),
        field<&P::remaining_capacity_ah>("remaining_capacity_ah", "Remaining capacity"));
  }
  [[nodiscard]] constexpr bool operator==(const dc_detailed_status&) const noexcept = default;
};

/// PGN 129283 Cross Track Error: 8 bytes, single frame, priority 3, 1 Hz. The distance off the
/// track in m at 0.01 m (signed: the side is the sign), how it was obtained, and whether navigation
/// has ended.
struct cross_track_error {
  unsigned_number<8> sid;
  lookup<nmea2000::residual_mode, 4> xte_mode;
  lookup<nmea2000::yes_no, 2> navigation_terminated;
  signed_number<32, res::hundredth> xte_m;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{129283, "cross_track_error", "Cross Track Error", 3, framing::single_frame, 1000},
        field<&P::sid>("sid", "SID"), field<&P::xte_mode>("xte_mode", "XTE mode"), reserved<2>,
        field<&P::navigation_terminated>("navigation_terminated", "Navigation Terminated"),
        field<&P::xte_m>("xte_m", "XTE"), reserved<16>);
  }
  [[nodiscard]] constexpr bool operator==(const cross_track_error&) const noexcept = default;
};

/// PGN 126992 System Time: 8 bytes, single frame, priority 3, 1 Hz. The date and time (UTC) and the
/// clock they come from.
struct system_time {
  unsigned_number<8> sid;
  lookup<nmea2000::time_source, 4> source;
  nmea2000::day_count date;
  nmea2000::time_since_midnight time;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{126992, "system_time", "System Time", 3, framing::single_frame, 1000},
        field<&P::sid>("sid", "SID"), field<&P::source>("source", "Source"), reserved<4>,
        field<&P::date>("date", "Date"), field<&P::time>("time", "Time"));
  }
  [[nodiscard]] constexpr bool operator==(const system_time&) const noexcept = default;
};

/// PGN 129033 Time & Date: 8 bytes, single frame, priority 3, 1 Hz. The date and time (UTC) and the
/// local time's offset from it (whole minutes, in s).
struct time_date {
  nmea2000::day_count date;
  nmea2000::time_since_midnight time;
  signed_number<16, res::minute> local_offset_s;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{129033, "time_date", "Time & Date", 3, framing::single_frame, 1000},
        field<&P::date>("date", "Date"), field<&P::time>("time", "Time"),
        field<&P::local_offset_s>("local_offset_s", "Local Offset"));
  }
  [[nodiscard]] constexpr bool operator==(const time_date&) const noexcept = default;
};

/// PGN 129539 GNSS DOPs: 8 bytes, single frame, priority 6, 1 Hz. Dilutions of precision
/// (horizontal, vertical, time) at 0.01, and the fix mode wanted and obtained.
struct gnss_dops {
  unsigned_number<8> sid;
  lookup<nmea2000::gnss_mode, 3> desired_mode;
  lookup<nmea2000::gnss_mode, 3> actual_mode;
  signed_number<16, res::hundredth> hdop;
  signed_number<16, res::hundredth> vdop;
  signed_number<16, res::hundredth> tdop;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{129539, "gnss_dops", "GNSS DOPs", 6, framing::single_frame, 1000},
                        field<&P::sid>("sid", "SID"),
                        field<&P::desired_mode>("desired_mode", "Desired Mode"),
                        field<&P::actual_mode>("actual_mode", "Actual Mode"), reserved<2>,
                        field<&P::hdop>("hdop", "HDOP"), field<&P::vdop>("vdop", "VDOP"),
                        field<&P::tdop>("tdop", "TDOP"));
  }
  [[nodiscard]] constexpr bool operator==(const gnss_dops&) const noexcept = default;
};

/// PGN 129284 Navigation Data: 34 bytes, fast packet, priority 3, 1 Hz. Progress toward the
/// destination waypoint: distance, bearings, the estimated arrival (UTC), the waypoints' numbers
/// and the destination's position.
struct navigation_data {
  unsigned_number<8> sid;
  unsigned_number<32, res::hundredth> distance_to_waypoint_m;
  lookup<nmea2000::heading_reference, 2> course_bearing_reference;
  lookup<nmea2000::yes_no, 2> perpendicular_crossed;
  lookup<nmea2000::yes_no, 2> arrival_circle_entered;
  lookup<nmea2000::bearing_mode, 2> calculation_type;
  nmea2000::time_since_midnight eta_time;
  nmea2000::day_count eta_date;
  unsigned_number<16, res::radian> bearing_origin_to_destination_rad;
  unsigned_number<16, res::radian> bearing_position_to_destination_rad;
  unsigned_number<32> origin_waypoint_number;
  unsigned_number<32> destination_waypoint_number;
  signed_number<32, res::degree_e7> destination_latitude_deg;
  signed_number<32, res::degree_e7> destination_longitude_deg;
  signed_number<16, res::hundredth> waypoint_closing_velocity_mps;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{129284, "navigation_data", "Navigation Data", 3, framing::fast_packet, 1000},
        field<&P::sid>("sid", "SID"),
        field<&P::distance_to_waypoint_m>("distance_to_waypoint_m", "Distance to Waypoint"),
        field<&P::course_bearing_reference>("course_bearing_reference", "Course/Bearing reference"),
        field<&P::perpendicular_crossed>("perpendicular_crossed", "Perpendicular Crossed"),
        field<&P::arrival_circle_entered>("arrival_circle_entered", "Arrival Circle Entered"),
        field<&P::calculation_type>("calculation_type", "Calculation Type"),
        field<&P::eta_time>("eta_time", "ETA Time"), field<&P::eta_date>("eta_date", "ETA Date"),
        field<&P::bearing_origin_to_destination_rad>("bearing_origin_to_destination_rad",
                                                     "Bearing, Origin to Destination Waypoint"),
        field<&P::bearing_position_to_destination_rad>("bearing_position_to_destination_rad",
                                                       "Bearing, Position to Destination Waypoint"),
        field<&P::origin_waypoint_number>("origin_waypoint_number", "Origin Waypoint Number"),
        field<&P::destination_waypoint_number>("destination_waypoint_number",
                                               "Destination Waypoint Number"),
        field<&P::destination_latitude_deg>("destination_latitude_deg", "Destination Latitude"),
        field<&P::destination_longitude_deg>("destination_longitude_deg", "Destination Longitude"),
        field<&P::waypoint_closing_velocity_mps>("waypoint_closing_velocity_mps",
                                                 "Waypoint Closing Velocity"));
  }
  [[nodiscard]] constexpr bool operator==(const navigation_data&) const noexcept = default;
};

/// PGN 130577 Direction Data: 14 bytes, fast packet, priority 3, 1 Hz. Course and speed over the
/// ground, heading and speed through the water, and the current's set and drift.
struct direction_data {
  lookup<nmea2000::residual_mode, 4> data_mode;
  lookup<nmea2000::heading_reference, 2> cog_reference;
  unsigned_number<8> sid;
  unsigned_number<16, res::radian> cog_rad;
  unsigned_number<16, res::hundredth> sog_mps;
  unsigned_number<16, res::radian> heading_rad;
  unsigned_number<16, res::hundredth> speed_water_mps;
  unsigned_number<16, res::radian> set_rad;
  unsigned_number<16, res::hundredth> drift_mps;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{130577, "direction_data", "Direction Data", 3, framing::fast_packet, 1000},
        field<&P::data_mode>("data_mode", "Data Mode"),
        field<&P::cog_reference>("cog_reference", "COG Reference"), reserved<2>,
        field<&P::sid>("sid", "SID"), field<&P::cog_rad>("cog_rad", "COG"),
        field<&P::sog_mps>("sog_mps", "SOG"), field<&P::heading_rad>("heading_rad", "Heading"),
        field<&P::speed_water_mps>("speed_water_mps", "Speed through Water"),
        field<&P::set_rad>("set_rad", "Set"), field<&P::drift_mps>("drift_mps", "Drift"));
  }
  [[nodiscard]] constexpr bool operator==(const direction_data&) const noexcept = default;
};

/// PGN 59904 ISO Request: 3 bytes, single frame, priority 6, on demand. Asks the device addressed
/// (or every device, destination 255) to send the PGN named. An addressed (PDU1) PGN: the
/// destination is in the CAN identifier.
struct iso_request {
  unsigned_number<24> requested_pgn;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{59904, "iso_request", "ISO Request", 6, framing::single_frame, 0},
                        field<&P::requested_pgn>("requested_pgn", "PGN"));
  }
  [[nodiscard]] constexpr bool operator==(const iso_request&) const noexcept = default;
};

/// PGN 59392 ISO Acknowledgement: 8 bytes, single frame, priority 6, on demand. A device's answer
/// to a request or command for the PGN named. An addressed (PDU1) PGN.
struct iso_acknowledgement {
  lookup<nmea2000::iso_control, 8> control;
  unsigned_number<8> group_function;
  unsigned_number<24> acknowledged_pgn;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{59392, "iso_acknowledgement", "ISO Acknowledgement", 6, framing::single_frame, 0},
        field<&P::control>("control", "Control"),
        field<&P::group_function>("group_function", "Group Function"), reserved<24>,
        field<&P::acknowledged_pgn>("acknowledged_pgn", "PGN"));
  }
  [[nodiscard]] constexpr bool operator==(const iso_acknowledgement&) const noexcept = default;
};

// ---------------------------------------------------------------------------------------------
// ---- lookups: the ISO NAME, heartbeat, steering, transmission and AIS position reports ----
// Some of these name raw values a lookup otherwise keeps as sentinels (a 2-bit gear's reverse,
// a 3-bit steering mode's track control): a named raw value is a value (field.hpp, lookup).

/// A CAN controller's error state (126993), ISO 11898's: raw 2 (bus off) is named, so a value.
enum class controller_state : std::uint8_t {
  error_active = 0,
  error_passive = 1,
  bus_off = 2,
};
constexpr std::array<std::string_view, 3> lookup_names(controller_state) noexcept {
  return {"error_active", "error_passive", "bus_off"};
}
constexpr std::array<std::string_view, 3> lookup_titles(controller_state) noexcept {
  return {"Error Active", "Error Passive", "Bus Off"};
}

/// Whether a device works (126993).
enum class equipment_status : std::uint8_t {
  operational = 0,
  fault = 1,
};
constexpr std::array<std::string_view, 2> lookup_names(equipment_status) noexcept {
  return {"operational", "fault"};
}
constexpr std::array<std::string_view, 2> lookup_titles(equipment_status) noexcept {
  return {"Operational", "Fault"};
}

/// A transmission's gear (127493): raw 2 (reverse) is named, so a value.
enum class gear_status : std::uint8_t {
  forward = 0,
  neutral = 1,
  reverse = 2,
};
constexpr std::array<std::string_view, 3> lookup_names(gear_status) noexcept {
  return {"forward", "neutral", "reverse"};
}
constexpr std::array<std::string_view, 3> lookup_titles(gear_status) noexcept {
  return {"Forward", "Neutral", "Reverse"};
}

/// Who steers (127237): raw 5 (track control) is named, so a value.
enum class steering_mode : std::uint8_t {
  main_steering = 0,
  non_follow_up = 1,  ///< a non-follow-up device (a jog lever)
  follow_up = 2,      ///< a follow-up device (a helm that sets the rudder angle)
  heading_control_standalone = 3,
  heading_control = 4,
  track_control = 5,
};
constexpr std::array<std::string_view, 6> lookup_names(steering_mode) noexcept {
  return {"main_steering",   "non_follow_up", "follow_up", "heading_control_standalone",
          "heading_control", "track_control"};
}
constexpr std::array<std::string_view, 6> lookup_titles(steering_mode) noexcept {
  return {"Main Steering",    "Non-Follow-Up Device",
          "Follow-Up Device", "Heading Control Standalone",
          "Heading Control",  "Track Control"};
}

/// How a turn is controlled (127237).
enum class turn_mode : std::uint8_t {
  rudder_limit_controlled = 0,
  turn_rate_controlled = 1,
  radius_controlled = 2,
};
constexpr std::array<std::string_view, 3> lookup_names(turn_mode) noexcept {
  return {"rudder_limit_controlled", "turn_rate_controlled", "radius_controlled"};
}
constexpr std::array<std::string_view, 3> lookup_titles(turn_mode) noexcept {
  return {"Rudder limit controlled", "Turn rate controlled", "Radius controlled"};
}

/// Transmission discrete status 1 (127493): bit numbers.
enum class transmission_status : std::uint8_t {
  check_transmission = 0,
  over_temperature = 1,
  low_oil_pressure = 2,
  low_oil_level = 3,
  sail_drive = 4,
};
constexpr std::array<std::string_view, 5> lookup_names(transmission_status) noexcept {
  return {"check_transmission", "over_temperature", "low_oil_pressure", "low_oil_level",
          "sail_drive"};
}
constexpr std::array<std::string_view, 5> lookup_titles(transmission_status) noexcept {
  return {"Check Transmission", "Over Temperature", "Low Oil Pressure", "Low Oil Level",
          "Sail Drive"};
}

namespace detail {
/// A value of a lookup and its name.
struct named_value {
  std::size_t value = 0;
  std::string_view name;
};
/// The names of a lookup whose values have gaps, by value ("" where none).
template <std::size_t N, std::size_t M>
[[nodiscard]] constexpr std::array<std::string_view, N> names_by_value(
    const named_value (&values)[M]) noexcept {
  std::array<std::string_view, N> out{};
  for (const named_value& v : values) out[v.value] = v.name;
  return out;
}
}  // namespace detail

/// The AIS message an NMEA 2000 AIS PGN carries (6 bits, ITU-R M.1371 message numbers; 0 has no
/// name).
enum class ais_message_id : std::uint8_t {
  scheduled_class_a_position_report = 1,
  assigned_scheduled_class_a_position_report = 2,
  interrogated_class_a_position_report = 3,
  base_station_report = 4,
  static_and_voyage_related_data = 5,
  binary_addressed_message = 6,
  binary_acknowledgement = 7,
  binary_broadcast_message = 8,
  standard_sar_aircraft_position_report = 9,
  utc_date_inquiry = 10,
  utc_date_response = 11,
  safety_related_addressed_message = 12,
  safety_related_acknowledgement = 13,
  safety_related_broadcast_message = 14,
  interrogation = 15,
  assignment_mode_command = 16,
  dgnss_broadcast_binary_message = 17,
  standard_class_b_position_report = 18,
  extended_class_b_position_report = 19,
  data_link_management_message = 20,
  aton_report = 21,
  channel_management = 22,
  group_assignment_command = 23,
  static_data_report = 24,
  single_slot_binary_message = 25,
  multiple_slot_binary_message = 26,
  position_report_for_long_range_applications = 27,
};
constexpr std::array<std::string_view, 28> lookup_names(ais_message_id) noexcept {
  return detail::names_by_value<28>({{1, "scheduled_class_a_position_report"},
                                     {2, "assigned_scheduled_class_a_position_report"},
                                     {3, "interrogated_class_a_position_report"},
                                     {4, "base_station_report"},
                                     {5, "static_and_voyage_related_data"},
                                     {6, "binary_addressed_message"},
                                     {7, "binary_acknowledgement"},
                                     {8, "binary_broadcast_message"},
                                     {9, "standard_sar_aircraft_position_report"},
                                     {10, "utc_date_inquiry"},
                                     {11, "utc_date_response"},
                                     {12, "safety_related_addressed_message"},
                                     {13, "safety_related_acknowledgement"},
                                     {14, "safety_related_broadcast_message"},
                                     {15, "interrogation"},
                                     {16, "assignment_mode_command"},
                                     {17, "dgnss_broadcast_binary_message"},
                                     {18, "standard_class_b_position_report"},
                                     {19, "extended_class_b_position_report"},
                                     {20, "data_link_management_message"},
                                     {21, "aton_report"},
                                     {22, "channel_management"},
                                     {23, "group_assignment_command"},
                                     {24, "static_data_report"},
                                     {25, "single_slot_binary_message"},
                                     {26, "multiple_slot_binary_message"},
                                     {27, "position_report_for_long_range_applications"}});
}
/// canboat's texts for ais_message_id's values, in the same order.
constexpr std::array<std::string_view, 28> lookup_titles(ais_message_id) noexcept {
  return detail::names_by_value<28>({{1, "Scheduled Class A position report"},
                                     {2, "Assigned scheduled Class A position report"},
                                     {3, "Interrogated Class A position report"},
                                     {4, "Base station report"},
                                     {5, "Static and voyage related data"},
                                     {6, "Binary addressed message"},
                                     {7, "Binary acknowledgement"},
                                     {8, "Binary broadcast message"},
                                     {9, "Standard SAR aircraft position report"},
                                     {10, "UTC/date inquiry"},
                                     {11, "UTC/date response"},
                                     {12, "Safety related addressed message"},
                                     {13, "Safety related acknowledgement"},
                                     {14, "Satety related broadcast message"},
                                     {15, "Interrogation"},
                                     {16, "Assignment mode command"},
                                     {17, "DGNSS broadcast binary message"},
                                     {18, "Standard Class B position report"},
                                     {19, "Extended Class B position report"},
                                     {20, "Data link management message"},
                                     {21, "ATON report"},
                                     {22, "Channel management"},
                                     {23, "Group assignment command"},
                                     {24, "Static data report"},
                                     {25, "Single slot binary message"},
                                     {26, "Multiple slot binary message"},
                                     {27, "Position report for long range applications"}});
}

/// How many times an AIS message has been repeated (2 bits, every raw value named, so a value:
/// none is "not available").
enum class ais_repeat_indicator : std::uint8_t {
  initial = 0,
  first_retransmission = 1,
  second_retransmission = 2,
  final_retransmission = 3,
};
constexpr std::array<std::string_view, 4> lookup_names(ais_repeat_indicator) noexcept {
  return {"initial", "first_retransmission", "second_retransmission", "final_retransmission"};
}
/// canboat's texts for ais_repeat_indicator's values, in the same order.
constexpr std::array<std::string_view, 4> lookup_titles(ais_repeat_indicator) noexcept {
  return {"Initial", "First retransmission", "Second retransmission", "Final retransmission"};
}

/// An AIS position's accuracy (1 bit): high is better than 10 m.
enum class position_accuracy : std::uint8_t { low = 0, high = 1 };
constexpr std::array<std::string_view, 2> lookup_names(position_accuracy) noexcept {
  return {"low", "high"};
}
constexpr std::array<std::string_view, 2> lookup_titles(position_accuracy) noexcept {
  return {"Low", "High"};
}

/// Whether receiver autonomous integrity monitoring is in use (1 bit).
enum class raim_flag : std::uint8_t { not_in_use = 0, in_use = 1 };
constexpr std::array<std::string_view, 2> lookup_names(raim_flag) noexcept {
  return {"not_in_use", "in_use"};
}
constexpr std::array<std::string_view, 2> lookup_titles(raim_flag) noexcept {
  return {"not in use", "in use"};
}

/// An AIS report's time stamp (6 bits): 0-59 the UTC second of the report (unnamed numbers),
/// 60-63 why there is none. All four top values are named, so values: none is "not available".
enum class ais_time_stamp : std::uint8_t {
  unavailable = 60,
  manual_input = 61,
  dead_reckoning = 62,
  positioning_inoperative = 63,
};
constexpr std::array<std::string_view, 64> lookup_names(ais_time_stamp) noexcept {
  std::array<std::string_view, 64> a{};
  a[60] = "unavailable";
  a[61] = "manual_input";
  a[62] = "dead_reckoning";
  a[63] = "positioning_inoperative";
  return a;
}
constexpr std::array<std::string_view, 64> lookup_titles(ais_time_stamp) noexcept {
  std::array<std::string_view, 64> a{};
  a[60] = "Not available";
  a[61] = "Manual input mode";
  a[62] = "Dead reckoning mode";
  a[63] = "Positioning system is inoperative";
  return a;
}

/// Which AIS channel a message came from, or was sent on (5 bits).
enum class ais_transceiver : std::uint8_t {
  channel_a_vdl_reception = 0,
  channel_b_vdl_reception = 1,
  channel_a_vdl_transmission = 2,
  channel_b_vdl_transmission = 3,
  own_information_not_broadcast = 4,
  reserved_5 = 5,
};
constexpr std::array<std::string_view, 6> lookup_names(ais_transceiver) noexcept {
  return {"channel_a_vdl_reception",       "channel_b_vdl_reception",
          "channel_a_vdl_transmission",    "channel_b_vdl_transmission",
          "own_information_not_broadcast", "reserved_5"};
}
/// canboat's texts for ais_transceiver's values, in the same order.
constexpr std::array<std::string_view, 6> lookup_titles(ais_transceiver) noexcept {
  return {"Channel A VDL reception",       "Channel B VDL reception",
          "Channel A VDL transmission",    "Channel B VDL transmission",
          "Own information not broadcast", "Reserved"};
}

/// A vessel's navigational status (4 bits); 14 (AIS-SART) is named, so a value, 13 is not.
enum class nav_status : std::uint8_t {
  under_way_using_engine = 0,
  at_anchor = 1,
  not_under_command = 2,
  restricted_maneuverability = 3,
  constrained_by_draught = 4,
  moored = 5,
  aground = 6,
  engaged_in_fishing = 7,
  under_way_sailing = 8,
  hazardous_material_high_speed = 9,
  hazardous_material_wing_in_ground = 10,
  towing_astern = 11,
  pushing_ahead_or_towing_alongside = 12,
  ais_sart = 14,
};
constexpr std::array<std::string_view, 15> lookup_names(nav_status) noexcept {
  return {"under_way_using_engine",
          "at_anchor",
          "not_under_command",
          "restricted_maneuverability",
          "constrained_by_draught",
          "moored",
          "aground",
          "engaged_in_fishing",
          "under_way_sailing",
          "hazardous_material_high_speed",
          "hazardous_material_wing_in_ground",
          "towing_astern",
          "pushing_ahead_or_towing_alongside",
          "",
          "ais_sart"};
}
constexpr std::array<std::string_view, 15> lookup_titles(nav_status) noexcept {
  return {"Under way using engine",
          "At anchor",
          "Not under command",
          "Restricted maneuverability",
          "Constrained by her draught",
          "Moored",
          "Aground",
          "Engaged in Fishing",
          "Under way sailing",
          "Hazardous material - High Speed",
          "Hazardous material - Wing in Ground",
          "Power-driven vessel towing astern",
          "Power-driven vessel pushing ahead or towing alongside",
          "",
          "AIS-SART"};
}

/// Whether a vessel is engaged in a special maneuver (2 bits, every raw value named).
enum class ais_special_maneuver : std::uint8_t {
  unavailable = 0,
  not_engaged = 1,
  engaged = 2,
  reserved_3 = 3,  ///< named "Reserved" by the standard
};
constexpr std::array<std::string_view, 4> lookup_names(ais_special_maneuver) noexcept {
  return {"unavailable", "not_engaged", "engaged", "reserved_3"};
}
constexpr std::array<std::string_view, 4> lookup_titles(ais_special_maneuver) noexcept {
  return {"Not available", "Not engaged in special maneuver", "Engaged in special maneuver",
          "Reserved"};
}

/// A class B unit's kind (1 bit): SOTDMA or carrier sense.
enum class ais_unit_type : std::uint8_t { sotdma = 0, cs = 1 };
constexpr std::array<std::string_view, 2> lookup_names(ais_unit_type) noexcept {
  return {"sotdma", "cs"};
}
constexpr std::array<std::string_view, 2> lookup_titles(ais_unit_type) noexcept {
  return {"SOTDMA", "CS"};
}

/// The band a class B unit can use (1 bit).
enum class ais_band : std::uint8_t { top_525_khz = 0, entire_marine_band = 1 };
constexpr std::array<std::string_view, 2> lookup_names(ais_band) noexcept {
  return {"top_525_khz", "entire_marine_band"};
}
constexpr std::array<std::string_view, 2> lookup_titles(ais_band) noexcept {
  return {"Top 525 kHz of marine band", "Entire marine band"};
}

/// A class B unit's mode (1 bit).
enum class ais_mode : std::uint8_t { autonomous = 0, assigned = 1 };
constexpr std::array<std::string_view, 2> lookup_names(ais_mode) noexcept {
  return {"autonomous", "assigned"};
}
constexpr std::array<std::string_view, 2> lookup_titles(ais_mode) noexcept {
  return {"Autonomous", "Assigned"};
}

/// The kind of communication state a class B report carries (1 bit).
enum class ais_communication_state : std::uint8_t { sotdma = 0, itdma = 1 };
constexpr std::array<std::string_view, 2> lookup_names(ais_communication_state) noexcept {
  return {"sotdma", "itdma"};
}
constexpr std::array<std::string_view, 2> lookup_titles(ais_communication_state) noexcept {
  return {"SOTDMA", "ITDMA"};
}

namespace res {
inline constexpr resolution rotation{3125, -8};  ///< 3.125e-5 rad/s
}  // namespace res

/// PGN 60928 ISO Address Claim: 8 bytes, single frame, priority 6, on demand. A device's 64-bit
/// ISO NAME, claiming the source address it is sent from. An addressed (PDU1) PGN, normally sent
/// to 255. The device function's name depends on the device class (device_functions); the
/// device instances are numbers every raw value of which is a value; bit 48 is spare (zero).
struct iso_address_claim {
  unsigned_number<21> unique_number;
  lookup<nmea2000::manufacturer_code, 11> manufacturer_code;
  unsigned_no_sentinel<3> device_instance_lower;
  unsigned_no_sentinel<5> device_instance_upper;
  keyed_lookup<device_functions, 8> device_function;
  lookup<nmea2000::device_class, 7> device_class;
  unsigned_number<4> system_instance;
  lookup<nmea2000::industry_group, 3> industry_group;
  lookup<yes_no, 1> arbitrary_address_capable;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{60928, "iso_address_claim", "ISO Address Claim", 6, framing::single_frame, 0},
        field<&P::unique_number>("unique_number", "Unique Number"),
        field<&P::manufacturer_code>("manufacturer_code", "Manufacturer Code"),
        field<&P::device_instance_lower>("device_instance_lower", "Device Instance Lower"),
        field<&P::device_instance_upper>("device_instance_upper", "Device Instance Upper"),
        keyed_field<&P::device_function, &P::device_class>("device_function", "Device Function"),
        spare<1>, field<&P::device_class>("device_class", "Device Class"),
        field<&P::system_instance>("system_instance", "System Instance"),
        field<&P::industry_group>("industry_group", "Industry Group"),
        field<&P::arbitrary_address_capable>("arbitrary_address_capable",
                                             "Arbitrary address capable"));
  }
  [[nodiscard]] constexpr bool operator==(const iso_address_claim&) const noexcept = default;
};

/// PGN 126993 Heartbeat: 8 bytes, single frame, priority 7, every 60 s. A device's sign of life:
/// its transmit offset (s, at 0.001 s), a counter, and its CAN controllers' and its own state.
struct heartbeat {
  unsigned_number<16, res::thousandth> data_transmit_offset_s;
  unsigned_number<8> sequence_counter;
  lookup<nmea2000::controller_state, 2> controller_1_state;
  lookup<nmea2000::controller_state, 2> controller_2_state;
  lookup<nmea2000::equipment_status, 2> equipment_status;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{126993, "heartbeat", "Heartbeat", 7, framing::single_frame, 60000},
        field<&P::data_transmit_offset_s>("data_transmit_offset_s", "Data transmit offset"),
        field<&P::sequence_counter>("sequence_counter", "Sequence Counter"),
        field<&P::controller_1_state>("controller_1_state", "Controller 1 State"),
        field<&P::controller_2_state>("controller_2_state", "Controller 2 State"),
        field<&P::equipment_status>("equipment_status", "Equipment Status"), reserved<34>);
  }
  [[nodiscard]] constexpr bool operator==(const heartbeat&) const noexcept = default;
};

/// PGN 127237 Heading/Track control: 21 bytes, fast packet, priority 2, 4 Hz. An autopilot's
/// mode, orders and limits: angles in rad (0.0001 rad), radius and off-track limit in m, rate
/// of turn in rad/s (3.125e-5 rad/s).
struct heading_track_control {
  lookup<yes_no, 2> rudder_limit_exceeded;
  lookup<yes_no, 2> off_heading_limit_exceeded;
  lookup<yes_no, 2> off_track_limit_exceeded;
  lookup<yes_no, 2> override;
  lookup<nmea2000::steering_mode, 3> steering_mode;
  lookup<nmea2000::turn_mode, 3> turn_mode;
  lookup<nmea2000::heading_reference, 2> heading_reference;
  lookup<rudder_direction, 3> commanded_rudder_direction;
  signed_number<16, res::radian> commanded_rudder_angle_rad;
  unsigned_number<16, res::radian> heading_to_steer_rad;
  unsigned_number<16, res::radian> track_rad;
  unsigned_number<16, res::radian> rudder_limit_rad;
  unsigned_number<16, res::radian> off_heading_limit_rad;
  signed_number<16> radius_of_turn_order_m;
  signed_number<16, res::rotation> rate_of_turn_order_radps;
  signed_number<16> off_track_limit_m;
  unsigned_number<16, res::radian> vessel_heading_rad;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{127237, "heading_track_control", "Heading/Track control", 2, framing::fast_packet,
                 250},
        field<&P::rudder_limit_exceeded>("rudder_limit_exceeded", "Rudder Limit Exceeded"),
        field<&P::off_heading_limit_exceeded>("off_heading_limit_exceeded",
                                              "Off-Heading Limit Exceeded"),
        field<&P::off_track_limit_exceeded>("off_track_limit_exceeded", "Off-Track Limit Exceeded"),
        field<&P::override>("override", "Override"),
        field<&P::steering_mode>("steering_mode", "Steering Mode"),
        field<&P::turn_mode>("turn_mode", "Turn Mode"),
        field<&P::heading_reference>("heading_reference", "Heading Reference"), reserved<5>,
        field<&P::commanded_rudder_direction>("commanded_rudder_direction",
                                              "Commanded Rudder Direction"),
        field<&P::commanded_rudder_angle_rad>("commanded_rudder_angle_rad",
                                              "Commanded Rudder Angle"),
        field<&P::heading_to_steer_rad>("heading_to_steer_rad", "Heading-To-Steer (Course)"),
        field<&P::track_rad>("track_rad", "Track"),
        field<&P::rudder_limit_rad>("rudder_limit_rad", "Rudder Limit"),
        field<&P::off_heading_limit_rad>("off_heading_limit_rad", "Off-Heading Limit"),
        field<&P::radius_of_turn_order_m>("radius_of_turn_order_m", "Radius of Turn Order"),
        field<&P::rate_of_turn_order_radps>("rate_of_turn_order_radps", "Rate of Turn Order"),
        field<&P::off_track_limit_m>("off_track_limit_m", "Off-Track Limit"),
        field<&P::vessel_heading_rad>("vessel_heading_rad", "Vessel Heading"));
  }
  [[nodiscard]] constexpr bool operator==(const heading_track_control&) const noexcept = default;
};

/// PGN 127252 Heave: 8 bytes, single frame, priority 3. The vessel's vertical displacement in m
/// (0.01 m, positive down as sent).
struct heave {
  unsigned_number<8> sid;
  signed_number<16, res::hundredth> heave_m;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{127252, "heave", "Heave", 3, framing::single_frame, 0},
                        field<&P::sid>("sid", "SID"), field<&P::heave_m>("heave_m", "Heave"),
                        reserved<40>);
  }
  [[nodiscard]] constexpr bool operator==(const heave&) const noexcept = default;
};

/// PGN 127493 Transmission Parameters, Dynamic: 8 bytes, single frame, priority 2, 10 Hz. A
/// transmission's gear, oil pressure (100 Pa) and temperature (0.1 K) and warnings.
struct transmission_parameters_dynamic {
  unsigned_number<8> instance;
  lookup<gear_status, 2> transmission_gear;
  unsigned_number<16, res::hundred> oil_pressure_pa;
  unsigned_number<16, res::tenth> oil_temperature_k;
  flags<transmission_status, 8> discrete_status_1;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{127493, "transmission_parameters_dynamic",
                                 "Transmission Parameters, Dynamic", 2, framing::single_frame, 100},
                        field<&P::instance, engine_instance>("instance", "Instance"),
                        field<&P::transmission_gear>("transmission_gear", "Transmission Gear"),
                        reserved<6>, field<&P::oil_pressure_pa>("oil_pressure_pa", "Oil pressure"),
                        field<&P::oil_temperature_k>("oil_temperature_k", "Oil temperature"),
                        field<&P::discrete_status_1>("discrete_status_1", "Discrete Status 1"),
                        reserved<8>);
  }
  [[nodiscard]] constexpr bool operator==(const transmission_parameters_dynamic&) const noexcept =
      default;
};

namespace detail {
/// The table of an AIS position report (129038, 129039) of struct P: the rows both start with
/// (AIS's message id, repeat indicator, MMSI, position, accuracy, RAIM, time stamp, course,
/// speed, communication state, transceiver, heading), then `rest`.
template <class P, class... Rest>
[[nodiscard]] constexpr auto ais_position_table(pgn_info info, Rest... rest) noexcept {
  return describe_pgn(
      info, field<&P::message_id>("message_id", "Message ID"),
      field<&P::repeat_indicator>("repeat_indicator", "Repeat Indicator"),
      field<&P::user_id, raw_display::identifier>("user_id", "User ID"),
      field<&P::longitude_deg>("longitude_deg", "Longitude"),
      field<&P::latitude_deg>("latitude_deg", "Latitude"),
      field<&P::position_accuracy>("position_accuracy", "Position Accuracy"),
      field<&P::raim>("raim", "RAIM"), field<&P::time_stamp>("time_stamp", "Time Stamp"),
      field<&P::cog_rad>("cog_rad", "COG"), field<&P::sog_mps>("sog_mps", "SOG"),
      field<&P::communication_state, raw_display::bits>("communication_state",
                                                        "Communication State"),
      field<&P::transceiver_information>("transceiver_information", "AIS Transceiver information"),
      field<&P::heading_rad>("heading_rad", "Heading"), rest...);
}
}  // namespace detail

/// PGN 129038 AIS Class A Position Report: 28 bytes, fast packet, priority 4, as received. A
/// class A vessel's AIS message 1, 2 or 3: its MMSI, position (1e-7 degree), course (rad) and
/// speed (m/s), heading, rate of turn (rad/s) and navigational status. The communication state
/// is the 19 bits of AIS's slot allocation as sent; bits 208-210 are spare (zero).
struct ais_class_a_position {
  lookup<ais_message_id, 6> message_id;
  lookup<nmea2000::ais_repeat_indicator, 2> repeat_indicator;
  unsigned_number<32> user_id;  ///< MMSI
  signed_number<32, res::degree_e7> longitude_deg;
  signed_number<32, res::degree_e7> latitude_deg;
  lookup<nmea2000::position_accuracy, 1> position_accuracy;
  lookup<raim_flag, 1> raim;
  lookup<ais_time_stamp, 6> time_stamp;
  unsigned_number<16, res::radian> cog_rad;
  unsigned_number<16, res::hundredth> sog_mps;
  unsigned_no_sentinel<19> communication_state;
  lookup<ais_transceiver, 5> transceiver_information;
  unsigned_number<16, res::radian> heading_rad;
  signed_number<16, res::rotation> rate_of_turn_radps;
  lookup<nmea2000::nav_status, 4> nav_status;
  lookup<ais_special_maneuver, 2> special_maneuver;
  unsigned_number<8> sid;

  template <class P>
  static constexpr auto n2k() {
    return detail::ais_position_table<P>(
        pgn_info{129038, "ais_class_a_position", "AIS Class A Position Report", 4,
                 framing::fast_packet, 0},
        field<&P::rate_of_turn_radps>("rate_of_turn_radps", "Rate of Turn"),
        field<&P::nav_status>("nav_status", "Nav Status"),
        field<&P::special_maneuver>("special_maneuver", "Special Maneuver Indicator"), reserved<2>,
        spare<3>, reserved<5>, field<&P::sid>("sid", "Sequence ID"));
  }
  [[nodiscard]] constexpr bool operator==(const ais_class_a_position&) const noexcept = default;
};

/// PGN 129039 AIS Class B Position Report: 27 bytes, fast packet, priority 4, as received. A
/// class B vessel's AIS message 18: as 129038 without rate of turn and status, plus what the
/// unit can do. The 10 bits of regional application are spare (zero).
struct ais_class_b_position {
  lookup<ais_message_id, 6> message_id;
  lookup<nmea2000::ais_repeat_indicator, 2> repeat_indicator;
  unsigned_number<32> user_id;  ///< MMSI
  signed_number<32, res::degree_e7> longitude_deg;
  signed_number<32, res::degree_e7> latitude_deg;
  lookup<nmea2000::position_accuracy, 1> position_accuracy;
  lookup<raim_flag, 1> raim;
  lookup<ais_time_stamp, 6> time_stamp;
  unsigned_number<16, res::radian> cog_rad;
  unsigned_number<16, res::hundredth> sog_mps;
  unsigned_no_sentinel<19> communication_state;
  lookup<ais_transceiver, 5> transceiver_information;
  unsigned_number<16, res::radian> heading_rad;
  lookup<ais_unit_type, 1> unit_type;
  lookup<yes_no, 1> integrated_display;
  lookup<yes_no, 1> dsc;
  lookup<ais_band, 1> band;
  lookup<yes_no, 1> can_handle_msg_22;
  lookup<nmea2000::ais_mode, 1> ais_mode;
  lookup<nmea2000::ais_communication_state, 1> ais_communication_state;
  unsigned_number<8> sid;

  template <class P>
  static constexpr auto n2k() {
    return detail::ais_position_table<P>(
        pgn_info{129039, "ais_class_b_position", "AIS Class B Position Report", 4,
                 framing::fast_packet, 0},
        spare_bits<8>{"regional_application", "Regional Application"},
        spare_bits<2>{"regional_application_b", "Regional Application B"},
        field<&P::unit_type>("unit_type", "Unit type"),
        field<&P::integrated_display>("integrated_display", "Integrated Display"),
        field<&P::dsc>("dsc", "DSC"), field<&P::band>("band", "Band"),
        field<&P::can_handle_msg_22>("can_handle_msg_22", "Can handle Msg 22"),
        field<&P::ais_mode>("ais_mode", "AIS mode"),
        field<&P::ais_communication_state>("ais_communication_state", "AIS communication state"),
        reserved<7>, field<&P::sid>("sid", "Sequence ID"));
  }
  [[nodiscard]] constexpr bool operator==(const ais_class_b_position&) const noexcept = default;
};

// ---------------------------------------------------------------------------------------------
// ---- groups: PGNs with a repeating field group or 64-bit fields ----

/// What a PGN list (126464) lists.
enum class pgn_list_function : std::uint8_t { transmit = 0, receive = 1 };
constexpr std::array<std::string_view, 2> lookup_names(pgn_list_function) noexcept {
  return {"transmit", "receive"};
}
constexpr std::array<std::string_view, 2> lookup_titles(pgn_list_function) noexcept {
  return {"Transmit PGN list", "Receive PGN list"};
}

/// How range residuals relate to the position (129540).
enum class range_residual_mode : std::uint8_t { used = 0, calculated_after = 1 };
constexpr std::array<std::string_view, 2> lookup_names(range_residual_mode) noexcept {
  return {"used", "calculated_after"};
}
constexpr std::array<std::string_view, 2> lookup_titles(range_residual_mode) noexcept {
  return {"Range residuals were used to calculate data",
          "Range residuals were calculated after the position"};
}

/// A satellite's part in the fix (129540).
enum class satellite_status : std::uint8_t {
  not_tracked = 0,
  tracked = 1,
  used = 2,
  not_tracked_diff = 3,
  tracked_diff = 4,
  used_diff = 5,
};
constexpr std::array<std::string_view, 6> lookup_names(satellite_status) noexcept {
  return {"not_tracked", "tracked", "used", "not_tracked_diff", "tracked_diff", "used_diff"};
}
constexpr std::array<std::string_view, 6> lookup_titles(satellite_status) noexcept {
  return {"Not tracked", "Tracked", "Used", "Not tracked+Diff", "Tracked+Diff", "Used+Diff"};
}

/// The constellation a satellite belongs to (129540).
enum class gnss_system : std::uint8_t { gps = 0, glonass = 1, galileo = 2, beidou = 3, qzss = 4 };
constexpr std::array<std::string_view, 5> lookup_names(gnss_system) noexcept {
  return {"gps", "glonass", "galileo", "beidou", "qzss"};
}
constexpr std::array<std::string_view, 5> lookup_titles(gnss_system) noexcept {
  return {"GPS", "GLONASS", "Galileo", "BeiDou", "QZSS"};
}

/// The kind of GNSS receiver or reference station (129029).
enum class gnss_type : std::uint8_t {
  gps = 0,
  glonass = 1,
  gps_glonass = 2,
  gps_sbas = 3,
  gps_sbas_glonass = 4,
  chayka = 5,
  integrated = 6,
  surveyed = 7,
  galileo = 8,
};
constexpr std::array<std::string_view, 9> lookup_names(gnss_type) noexcept {
  return {"gps",    "glonass",    "gps_glonass", "gps_sbas", "gps_sbas_glonass",
          "chayka", "integrated", "surveyed",    "galileo"};
}
constexpr std::array<std::string_view, 9> lookup_titles(gnss_type) noexcept {
  return {"GPS",    "GLONASS",    "GPS+GLONASS", "GPS+SBAS/WAAS", "GPS+SBAS/WAAS+GLONASS",
          "Chayka", "integrated", "surveyed",    "Galileo"};
}

/// How a position was fixed (129029).
enum class gnss_method : std::uint8_t {
  no_gnss = 0,
  gnss_fix = 1,
  dgnss_fix = 2,
  precise_gnss = 3,
  rtk_fixed = 4,
  rtk_float = 5,
  estimated = 6,
  manual = 7,
  simulated = 8,
};
constexpr std::array<std::string_view, 9> lookup_names(gnss_method) noexcept {
  return {"no_gnss",   "gnss_fix",  "dgnss_fix", "precise_gnss", "rtk_fixed",
          "rtk_float", "estimated", "manual",    "simulated"};
}
constexpr std::array<std::string_view, 9> lookup_titles(gnss_method) noexcept {
  return {"no GNSS",           "GNSS fix",  "DGNSS fix",           "Precise GNSS",
          "RTK Fixed Integer", "RTK float", "Estimated (DR) mode", "Manual Input",
          "Simulate mode"};
}

/// The receiver's integrity check of the position (129029; 2 bits, every raw value named, so a
/// value: none is "not available").
enum class gnss_integrity : std::uint8_t { none = 0, safe = 1, caution = 2, unsafe = 3 };
constexpr std::array<std::string_view, 4> lookup_names(gnss_integrity) noexcept {
  return {"none", "safe", "caution", "unsafe"};
}
constexpr std::array<std::string_view, 4> lookup_titles(gnss_integrity) noexcept {
  return {"No integrity checking", "Safe", "Caution", "Unsafe"};
}

/// PGN 126464 PGN List (Transmit and Receive): fast packet, priority 6, on demand. The PGNs a
/// device sends or receives: a function code, then 24-bit PGNs to the end of the payload (no
/// count field), at most 74. An addressed (PDU1) PGN.
struct pgn_list_message {
  /// One PGN of the list.
  struct entry {
    unsigned_number<24> pgn;

    static constexpr auto n2k_item = describe_item(field<&entry::pgn>("pgn", "PGN"));
    [[nodiscard]] constexpr bool operator==(const entry&) const noexcept = default;
  };

  lookup<nmea2000::pgn_list_function, 8> function_code;
  group<entry, group_capacity<entry>(1)> pgns;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{126464, "pgn_list_message", "PGN List (Transmit and Receive)", 6,
                                 framing::fast_packet, 0},
                        field<&P::function_code>("function_code", "Function Code"),
                        repeating_to_end<&P::pgns>("pgns", "PGN"));
  }
  [[nodiscard]] constexpr bool operator==(const pgn_list_message&) const noexcept = default;
};

/// PGN 129540 GNSS Sats in View: fast packet, priority 6, 1 Hz. The satellites a receiver sees:
/// a count, then 12 bytes per satellite (at most 18).
struct gnss_sats_in_view {
  /// One satellite.
  struct satellite {
    unsigned_number<8> prn;
    signed_number<16, res::radian> elevation_rad;
    unsigned_number<16, res::radian> azimuth_rad;
    signed_number<16, res::hundredth> snr_db;
    signed_number<32, resolution{1, -5}> range_residuals_m;
    lookup<nmea2000::satellite_status, 4> status;
    lookup<nmea2000::gnss_system, 4> gnss_system;

    static constexpr auto n2k_item =
        describe_item(field<&satellite::prn>("prn", "PRN"),
                      field<&satellite::elevation_rad>("elevation_rad", "Elevation"),
                      field<&satellite::azimuth_rad>("azimuth_rad", "Azimuth"),
                      field<&satellite::snr_db>("snr_db", "SNR"),
                      field<&satellite::range_residuals_m>("range_residuals_m", "Range residuals"),
                      field<&satellite::status>("status", "Status"),
                      field<&satellite::gnss_system>("gnss_system", "GNSS System"));
    [[nodiscard]] constexpr bool operator==(const satellite&) const noexcept = default;
  };

  unsigned_number<8> sid;
  lookup<nmea2000::range_residual_mode, 2> range_residual_mode;
  unsigned_number<8> sats_in_view;
  group<satellite, group_capacity<satellite>(3)> satellites;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{129540, "gnss_sats_in_view", "GNSS Sats in View", 6, framing::fast_packet, 1000},
        field<&P::sid>("sid", "SID"),
        field<&P::range_residual_mode>("range_residual_mode", "Range Residual Mode"), reserved<6>,
        field<&P::sats_in_view>("sats_in_view", "Sats in View"),
        repeating<&P::satellites, &P::sats_in_view>("satellites", "Satellites"));
  }
  [[nodiscard]] constexpr bool operator==(const gnss_sats_in_view&) const noexcept = default;
};

/// PGN 129029 GNSS Position Data: fast packet, priority 3, 1 Hz. A fix: date and time (UTC),
/// latitude and longitude (signed 64-bit, 1e-16 degree), altitude (signed 64-bit, 1e-6 m), how
/// it was fixed, DOPs, geoidal separation, then the reference stations used (a count, then 4
/// bytes each, at most 45).
struct gnss_position_data {
  /// One reference station.
  struct reference_station {
    lookup<nmea2000::gnss_type, 4> station_type;
    unsigned_number<12> station_id;
    unsigned_number<16, res::hundredth> age_of_corrections_s;

    static constexpr auto n2k_item = describe_item(
        field<&reference_station::station_type>("station_type", "Reference Station Type"),
        field<&reference_station::station_id>("station_id", "Reference Station ID"),
        field<&reference_station::age_of_corrections_s>("age_of_corrections_s",
                                                        "Age of DGNSS Corrections"));
    [[nodiscard]] constexpr bool operator==(const reference_station&) const noexcept = default;
  };

  unsigned_number<8> sid;
  nmea2000::day_count date;
  nmea2000::time_since_midnight time;
  signed_number<64, resolution{1, -16}> latitude_deg;
  signed_number<64, resolution{1, -16}> longitude_deg;
  signed_number<64, resolution{1, -6}> altitude_m;
  lookup<nmea2000::gnss_type, 4> gnss_type;
  lookup<nmea2000::gnss_method, 4> method;
  lookup<nmea2000::gnss_integrity, 2> integrity;
  unsigned_number<8> number_of_svs;
  signed_number<16, res::hundredth> hdop;
  signed_number<16, res::hundredth> pdop;
  signed_number<32, res::hundredth> geoidal_separation_m;
  unsigned_number<8> reference_stations;
  group<reference_station, group_capacity<reference_station>(43)> stations;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{129029, "gnss_position_data", "GNSS Position Data", 3, framing::fast_packet, 1000},
        field<&P::sid>("sid", "SID"), field<&P::date>("date", "Date"),
        field<&P::time>("time", "Time"), field<&P::latitude_deg>("latitude_deg", "Latitude"),
        field<&P::longitude_deg>("longitude_deg", "Longitude"),
        field<&P::altitude_m>("altitude_m", "Altitude"),
        field<&P::gnss_type>("gnss_type", "GNSS type"), field<&P::method>("method", "Method"),
        field<&P::integrity>("integrity", "Integrity"), reserved<6>,
        field<&P::number_of_svs>("number_of_svs", "Number of SVs"), field<&P::hdop>("hdop", "HDOP"),
        field<&P::pdop>("pdop", "PDOP"),
        field<&P::geoidal_separation_m>("geoidal_separation_m", "Geoidal Separation"),
        field<&P::reference_stations>("reference_stations", "Reference Stations"),
        repeating<&P::stations, &P::reference_stations>("stations", "Reference Station"));
  }
  [[nodiscard]] constexpr bool operator==(const gnss_position_data&) const noexcept = default;
};

// ---------------------------------------------------------------------------------------------
// ---- strings: product and configuration information, AIS static data ----

/// An NMEA 2000 certification level (126996).
enum class certification_level : std::uint8_t {
  level_a = 0,
  level_b = 1,
};
constexpr std::array<std::string_view, 2> lookup_names(certification_level) noexcept {
  return {"level_a", "level_b"};
}
/// canboat's texts for certification_level's values, in the same order.
constexpr std::array<std::string_view, 2> lookup_titles(certification_level) noexcept {
  return {"Level A", "Level B"};
}

/// An AIS ship and cargo type (ITU-R M.1371); values without a name are kept as numbers.
enum class ship_type : std::uint8_t {
  unavailable = 0,
  wing_in_ground = 20,
  wing_in_ground_hazard_cat_x = 21,
  wing_in_ground_hazard_cat_y = 22,
  wing_in_ground_hazard_cat_z = 23,
  wing_in_ground_hazard_cat_os = 24,
  wing_in_ground_no_additional_information = 29,
  fishing = 30,
  towing = 31,
  towing_exceeds_200m_or_wider_than_25m = 32,
  engaged_in_dredging_or_underwater_operations = 33,
  engaged_in_diving_operations = 34,
  engaged_in_military_operations = 35,
  sailing = 36,
  pleasure = 37,
  high_speed_craft = 40,
  high_speed_craft_hazard_cat_x = 41,
  high_speed_craft_hazard_cat_y = 42,
  high_speed_craft_hazard_cat_z = 43,
  high_speed_craft_hazard_cat_os = 44,
  high_speed_craft_no_additional_information = 49,
  pilot_vessel = 50,
  sar = 51,
  tug = 52,
  port_tender = 53,
  anti_pollution = 54,
  law_enforcement = 55,
  spare = 56,
  spare_2 = 57,
  medical = 58,
  ships_and_aircraft_of_states_not_parties_to_an_armed_conflict = 59,
  passenger_ship = 60,
  passenger_ship_hazard_cat_x = 61,
  passenger_ship_hazard_cat_y = 62,
  passenger_ship_hazard_cat_z = 63,
  passenger_ship_hazard_cat_os = 64,
  passenger_ship_no_additional_information = 69,
  cargo_ship = 70,
  cargo_ship_hazard_cat_x = 71,
  cargo_ship_hazard_cat_y = 72,
  cargo_ship_hazard_cat_z = 73,
  cargo_ship_hazard_cat_os = 74,
  cargo_ship_no_additional_information = 79,
  tanker = 80,
  tanker_hazard_cat_x = 81,
  tanker_hazard_cat_y = 82,
  tanker_hazard_cat_z = 83,
  tanker_hazard_cat_os = 84,
  tanker_no_additional_information = 89,
  other = 90,
  other_hazard_cat_x = 91,
  other_hazard_cat_y = 92,
  other_hazard_cat_z = 93,
  other_hazard_cat_os = 94,
  other_no_additional_information = 99,
};
constexpr std::array<std::string_view, 100> lookup_names(ship_type) noexcept {
  return detail::names_by_value<100>(
      {{0, "unavailable"},
       {20, "wing_in_ground"},
       {21, "wing_in_ground_hazard_cat_x"},
       {22, "wing_in_ground_hazard_cat_y"},
       {23, "wing_in_ground_hazard_cat_z"},
       {24, "wing_in_ground_hazard_cat_os"},
       {29, "wing_in_ground_no_additional_information"},
       {30, "fishing"},
       {31, "towing"},
       {32, "towing_exceeds_200m_or_wider_than_25m"},
       {33, "engaged_in_dredging_or_underwater_operations"},
       {34, "engaged_in_diving_operations"},
       {35, "engaged_in_military_operations"},
       {36, "sailing"},
       {37, "pleasure"},
       {40, "high_speed_craft"},
       {41, "high_speed_craft_hazard_cat_x"},
       {42, "high_speed_craft_hazard_cat_y"},
       {43, "high_speed_craft_hazard_cat_z"},
       {44, "high_speed_craft_hazard_cat_os"},
       {49, "high_speed_craft_no_additional_information"},
       {50, "pilot_vessel"},
       {51, "sar"},
       {52, "tug"},
       {53, "port_tender"},
       {54, "anti_pollution"},
       {55, "law_enforcement"},
       {56, "spare"},
       {57, "spare_2"},
       {58, "medical"},
       {59, "ships_and_aircraft_of_states_not_parties_to_an_armed_conflict"},
       {60, "passenger_ship"},
       {61, "passenger_ship_hazard_cat_x"},
       {62, "passenger_ship_hazard_cat_y"},
       {63, "passenger_ship_hazard_cat_z"},
       {64, "passenger_ship_hazard_cat_os"},
       {69, "passenger_ship_no_additional_information"},
       {70, "cargo_ship"},
       {71, "cargo_ship_hazard_cat_x"},
       {72, "cargo_ship_hazard_cat_y"},
       {73, "cargo_ship_hazard_cat_z"},
       {74, "cargo_ship_hazard_cat_os"},
       {79, "cargo_ship_no_additional_information"},
       {80, "tanker"},
       {81, "tanker_hazard_cat_x"},
       {82, "tanker_hazard_cat_y"},
       {83, "tanker_hazard_cat_z"},
       {84, "tanker_hazard_cat_os"},
       {89, "tanker_no_additional_information"},
       {90, "other"},
       {91, "other_hazard_cat_x"},
       {92, "other_hazard_cat_y"},
       {93, "other_hazard_cat_z"},
       {94, "other_hazard_cat_os"},
       {99, "other_no_additional_information"}});
}
/// canboat's texts for ship_type's values, in the same order.
constexpr std::array<std::string_view, 100> lookup_titles(ship_type) noexcept {
  return detail::names_by_value<100>(
      {{0, "Unavailable"},
       {20, "Wing In Ground"},
       {21, "Wing In Ground (hazard cat X)"},
       {22, "Wing In Ground (hazard cat Y)"},
       {23, "Wing In Ground (hazard cat Z)"},
       {24, "Wing In Ground (hazard cat OS)"},
       {29, "Wing In Ground (no additional information)"},
       {30, "Fishing"},
       {31, "Towing"},
       {32, "Towing exceeds 200m or wider than 25m"},
       {33, "Engaged in dredging or underwater operations"},
       {34, "Engaged in diving operations"},
       {35, "Engaged in military operations"},
       {36, "Sailing"},
       {37, "Pleasure"},
       {40, "High speed craft"},
       {41, "High speed craft (hazard cat X)"},
       {42, "High speed craft (hazard cat Y)"},
       {43, "High speed craft (hazard cat Z)"},
       {44, "High speed craft (hazard cat OS)"},
       {49, "High speed craft (no additional information)"},
       {50, "Pilot vessel"},
       {51, "SAR"},
       {52, "Tug"},
       {53, "Port tender"},
       {54, "Anti-pollution"},
       {55, "Law enforcement"},
       {56, "Spare"},
       {57, "Spare #2"},
       {58, "Medical"},
       {59, "Ships and aircraft of States not parties to an armed conflict"},
       {60, "Passenger ship"},
       {61, "Passenger ship (hazard cat X)"},
       {62, "Passenger ship (hazard cat Y)"},
       {63, "Passenger ship (hazard cat Z)"},
       {64, "Passenger ship (hazard cat OS)"},
       {69, "Passenger ship (no additional information)"},
       {70, "Cargo ship"},
       {71, "Cargo ship (hazard cat X)"},
       {72, "Cargo ship (hazard cat Y)"},
       {73, "Cargo ship (hazard cat Z)"},
       {74, "Cargo ship (hazard cat OS)"},
       {79, "Cargo ship (no additional information)"},
       {80, "Tanker"},
       {81, "Tanker (hazard cat X)"},
       {82, "Tanker (hazard cat Y)"},
       {83, "Tanker (hazard cat Z)"},
       {84, "Tanker (hazard cat OS)"},
       {89, "Tanker (no additional information)"},
       {90, "Other"},
       {91, "Other (hazard cat X)"},
       {92, "Other (hazard cat Y)"},
       {93, "Other (hazard cat Z)"},
       {94, "Other (hazard cat OS)"},
       {99, "Other (no additional information)"}});
}

/// The ITU-R M.1371 edition an AIS station follows (2 bits, every raw value named, so a value:
/// none is "not available").
enum class ais_version : std::uint8_t {
  itu_r_m1371_1 = 0,
  itu_r_m1371_3 = 1,
  itu_r_m1371_5 = 2,
  itu_r_m1371_future = 3,
};
constexpr std::array<std::string_view, 4> lookup_names(ais_version) noexcept {
  return {"itu_r_m1371_1", "itu_r_m1371_3", "itu_r_m1371_5", "itu_r_m1371_future"};
}
/// canboat's texts for ais_version's values, in the same order.
constexpr std::array<std::string_view, 4> lookup_titles(ais_version) noexcept {
  return {"ITU-R M.1371-1", "ITU-R M.1371-3", "ITU-R M.1371-5", "ITU-R M.1371 future edition"};
}

/// The kind of position fixing device of an AIS station.
enum class position_fix_device : std::uint8_t {
  undefined = 0,
  gps = 1,
  glonass = 2,
  gps_glonass = 3,
  loran_c = 4,
  chayka = 5,
  integrated_navigation_system = 6,
  surveyed = 7,
  galileo = 8,
};
constexpr std::array<std::string_view, 9> lookup_names(position_fix_device) noexcept {
  return {"undefined",
          "gps",
          "glonass",
          "gps_glonass",
          "loran_c",
          "chayka",
          "integrated_navigation_system",
          "surveyed",
          "galileo"};
}
/// canboat's texts for position_fix_device's values, in the same order.
constexpr std::array<std::string_view, 9> lookup_titles(position_fix_device) noexcept {
  return {"Default: undefined",           "GPS",      "GLONASS",
          "Combined GPS/GLONASS",         "Loran-C",  "Chayka",
          "Integrated navigation system", "Surveyed", "Galileo"};
}

/// Whether an AIS station's data terminal is ready (DTE).
enum class dte_availability : std::uint8_t {
  available = 0,
  unavailable = 1,
};
constexpr std::array<std::string_view, 2> lookup_names(dte_availability) noexcept {
  return {"available", "unavailable"};
}
/// canboat's texts for dte_availability's values, in the same order.
constexpr std::array<std::string_view, 2> lookup_titles(dte_availability) noexcept {
  return {"Available", "Not available"};
}

/// PGN 126996 Product Information: 134 bytes, fast packet, priority 6, on request. The device's
/// NMEA 2000 version (0.001: 2.100 is 2100), product code, four 32-byte strings (model, software
/// version, model version, serial), certification level and load (LEN: 50 mA each).
struct product_information {
  unsigned_number<16, res::thousandth> nmea2000_version;
  unsigned_number<16> product_code;
  fixed_text<32> model_id;
  fixed_text<32> software_version_code;
  fixed_text<32> model_version;
  fixed_text<32> model_serial_code;
  lookup<nmea2000::certification_level, 8> certification_level;
  unsigned_number<8> load_equivalency;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{126996, "product_information", "Product Information", 6, framing::fast_packet, 0},
        field<&P::nmea2000_version>("nmea2000_version", "NMEA 2000 Version"),
        field<&P::product_code>("product_code", "Product Code"),
        field<&P::model_id>("model_id", "Model ID"),
        field<&P::software_version_code>("software_version_code", "Software Version Code"),
        field<&P::model_version>("model_version", "Model Version"),
        field<&P::model_serial_code>("model_serial_code", "Model Serial Code"),
        field<&P::certification_level>("certification_level", "Certification Level"),
        field<&P::load_equivalency>("load_equivalency", "Load Equivalency"));
  }
  [[nodiscard]] constexpr bool operator==(const product_information&) const noexcept = default;
};

/// The most text a counted string can carry: a fast packet less its length and encoding bytes.
inline constexpr std::size_t max_counted_text = max_fast_packet_length - 2;

/// PGN 126998 Configuration Information: 6 to 223 bytes, fast packet, priority 6, on request.
/// Three counted strings (installation notes and the manufacturer's), each where the one before
/// ends; together at most a fast packet.
struct configuration_information {
  counted_text<max_counted_text> installation_description_1;
  counted_text<max_counted_text> installation_description_2;
  counted_text<max_counted_text> manufacturer_information;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(pgn_info{126998, "configuration_information", "Configuration Information",
                                 6, framing::fast_packet, 0},
                        field<&P::installation_description_1>("installation_description_1",
                                                              "Installation Description #1"),
                        field<&P::installation_description_2>("installation_description_2",
                                                              "Installation Description #2"),
                        field<&P::manufacturer_information>("manufacturer_information",
                                                            "Manufacturer Information"));
  }
  [[nodiscard]] constexpr bool operator==(const configuration_information&) const noexcept =
      default;
};

/// An AIS string: 6-bit AIS text pads with '@' (docs/nmea2000.md).
template <std::size_t Bytes>
using ais_text = fixed_text<Bytes, '@'>;

/// PGN 129794 AIS Class A Static and Voyage Related Data: 76 bytes, fast packet, priority 6, as
/// received. AIS message 5: the station's MMSI, IMO number, call sign, name, ship type,
/// dimensions (0.1 m) and antenna position, ETA (UTC), draught (0.01 m) and destination.
struct ais_class_a_static_data {
  lookup<nmea2000::ais_message_id, 6> message_id;
  lookup<nmea2000::ais_repeat_indicator, 2> repeat_indicator;
  unsigned_number<32> user_id;
  unsigned_number<32> imo_number;
  ais_text<7> callsign;
  ais_text<20> name;
  lookup<nmea2000::ship_type, 8> type_of_ship;
  unsigned_number<16, res::tenth> length_m;
  unsigned_number<16, res::tenth> beam_m;
  unsigned_number<16, res::tenth> position_reference_from_starboard_m;
  unsigned_number<16, res::tenth> position_reference_from_bow_m;
  nmea2000::day_count eta_date;
  nmea2000::time_since_midnight eta_time;
  unsigned_number<16, res::hundredth> draft_m;
  ais_text<20> destination;
  lookup<nmea2000::ais_version, 2> ais_version_indicator;
  lookup<nmea2000::position_fix_device, 4> gnss_type;
  lookup<nmea2000::dte_availability, 1> dte;
  lookup<nmea2000::ais_transceiver, 5> ais_transceiver_information;
  unsigned_number<8> sequence_id;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{129794, "ais_class_a_static_data", "AIS Class A Static and Voyage Related Data", 6,
                 framing::fast_packet, 0},
        field<&P::message_id>("message_id", "Message ID"),
        field<&P::repeat_indicator>("repeat_indicator", "Repeat Indicator"),
        field<&P::user_id, raw_display::identifier>("user_id", "User ID"),
        field<&P::imo_number>("imo_number", "IMO number"),
        field<&P::callsign>("callsign", "Callsign"), field<&P::name>("name", "Name"),
        field<&P::type_of_ship>("type_of_ship", "Type of ship"),
        field<&P::length_m>("length_m", "Length"), field<&P::beam_m>("beam_m", "Beam"),
        field<&P::position_reference_from_starboard_m>("position_reference_from_starboard_m",
                                                       "Position reference from Starboard"),
        field<&P::position_reference_from_bow_m>("position_reference_from_bow_m",
                                                 "Position reference from Bow"),
        field<&P::eta_date>("eta_date", "ETA Date"), field<&P::eta_time>("eta_time", "ETA Time"),
        field<&P::draft_m>("draft_m", "Draft"),
        field<&P::destination>("destination", "Destination"),
        field<&P::ais_version_indicator>("ais_version_indicator", "AIS version indicator"),
        field<&P::gnss_type>("gnss_type", "GNSS type"), field<&P::dte>("dte", "DTE"), reserved<1>,
        field<&P::ais_transceiver_information>("ais_transceiver_information",
                                               "AIS Transceiver information"),
        reserved<3>, field<&P::sequence_id>("sequence_id", "Sequence ID"));
  }
  [[nodiscard]] constexpr bool operator==(const ais_class_a_static_data&) const noexcept = default;
};

/// PGN 129809 AIS Class B static data (msg 24 Part A): 27 bytes, fast packet, priority 6, as
/// received. The station's MMSI and name.
struct ais_class_b_static_data_a {
  lookup<nmea2000::ais_message_id, 6> message_id;
  lookup<nmea2000::ais_repeat_indicator, 2> repeat_indicator;
  unsigned_number<32> user_id;
  ais_text<20> name;
  lookup<nmea2000::ais_transceiver, 5> ais_transceiver_information;
  unsigned_number<8> sequence_id;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{129809, "ais_class_b_static_data_a", "AIS Class B static data (msg 24 Part A)", 6,
                 framing::fast_packet, 0},
        field<&P::message_id>("message_id", "Message ID"),
        field<&P::repeat_indicator>("repeat_indicator", "Repeat Indicator"),
        field<&P::user_id, raw_display::identifier>("user_id", "User ID"),
        field<&P::name>("name", "Name"),
        field<&P::ais_transceiver_information>("ais_transceiver_information",
                                               "AIS Transceiver information"),
        reserved<3>, field<&P::sequence_id>("sequence_id", "Sequence ID"));
  }
  [[nodiscard]] constexpr bool operator==(const ais_class_b_static_data_a&) const noexcept =
      default;
};

/// PGN 129810 AIS Class B static data (msg 24 Part B): 35 bytes, fast packet, priority 6, as
/// received. The station's ship type, vendor ID, call sign, dimensions (0.1 m), antenna
/// position and, for an auxiliary craft, its mother ship's MMSI.
struct ais_class_b_static_data_b {
  lookup<nmea2000::ais_message_id, 6> message_id;
  lookup<nmea2000::ais_repeat_indicator, 2> repeat_indicator;
  unsigned_number<32> user_id;
  lookup<nmea2000::ship_type, 8> type_of_ship;
  ais_text<7> vendor_id;
  ais_text<7> callsign;
  unsigned_number<16, res::tenth> length_m;
  unsigned_number<16, res::tenth> beam_m;
  unsigned_number<16, res::tenth> position_reference_from_starboard_m;
  unsigned_number<16, res::tenth> position_reference_from_bow_m;
  unsigned_number<32> mothership_user_id;
  lookup<nmea2000::position_fix_device, 4> gnss_type;
  lookup<nmea2000::ais_transceiver, 5> ais_transceiver_information;
  unsigned_number<8> sequence_id;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{129810, "ais_class_b_static_data_b", "AIS Class B static data (msg 24 Part B)", 6,
                 framing::fast_packet, 0},
        field<&P::message_id>("message_id", "Message ID"),
        field<&P::repeat_indicator>("repeat_indicator", "Repeat Indicator"),
        field<&P::user_id, raw_display::identifier>("user_id", "User ID"),
        field<&P::type_of_ship>("type_of_ship", "Type of ship"),
        field<&P::vendor_id>("vendor_id", "Vendor ID"), field<&P::callsign>("callsign", "Callsign"),
        field<&P::length_m>("length_m", "Length"), field<&P::beam_m>("beam_m", "Beam"),
        field<&P::position_reference_from_starboard_m>("position_reference_from_starboard_m",
                                                       "Position reference from Starboard"),
        field<&P::position_reference_from_bow_m>("position_reference_from_bow_m",
                                                 "Position reference from Bow"),
        field<&P::mothership_user_id, raw_display::identifier>("mothership_user_id",
                                                               "Mothership User ID"),
        reserved<2>, spare<2>, field<&P::gnss_type>("gnss_type", "GNSS type"),
        field<&P::ais_transceiver_information>("ais_transceiver_information",
                                               "AIS Transceiver information"),
        reserved<3>, field<&P::sequence_id>("sequence_id", "Sequence ID"));
  }
  [[nodiscard]] constexpr bool operator==(const ais_class_b_static_data_b&) const noexcept =
      default;
};

// ---------------------------------------------------------------------------------------------
// ---- group function: one PGN, a layout per function code ----

/// What a group function message (126208) does; its first byte, which picks the layout.
enum class group_function : std::uint8_t {
  request = 0,
  command = 1,
  acknowledge = 2,
  read_fields = 3,
  read_fields_reply = 4,
  write_fields = 5,
  write_fields_reply = 6,
};
constexpr std::array<std::string_view, 7> lookup_names(group_function) noexcept {
  return {"request",           "command",      "acknowledge",       "read_fields",
          "read_fields_reply", "write_fields", "write_fields_reply"};
}
constexpr std::array<std::string_view, 7> lookup_titles(group_function) noexcept {
  return {"Request",           "Command",      "Acknowledge",       "Read Fields",
          "Read Fields Reply", "Write Fields", "Write Fields Reply"};
}

/// The priority a command sets for the PGN it names (126208): 0 (highest) to 7, or leave it.
enum class priority_setting : std::uint8_t {
  priority_0 = 0,
  priority_1 = 1,
  priority_2 = 2,
  priority_3 = 3,
  priority_4 = 4,
  priority_5 = 5,
  priority_6 = 6,
  priority_7 = 7,
  leave_unchanged = 8,
  reset_to_default = 9,
};
constexpr std::array<std::string_view, 10> lookup_names(priority_setting) noexcept {
  return {"priority_0", "priority_1", "priority_2", "priority_3",      "priority_4",
          "priority_5", "priority_6", "priority_7", "leave_unchanged", "reset_to_default"};
}
constexpr std::array<std::string_view, 10> lookup_titles(priority_setting) noexcept {
  return {"0", "1", "2", "3", "4", "5", "6", "7", "Leave unchanged", "Reset to default"};
}

/// How a device answers for the PGN a request or command named (126208's acknowledgement).
enum class pgn_error_code : std::uint8_t {
  acknowledge = 0,
  pgn_not_supported = 1,
  pgn_not_available = 2,
  access_denied = 3,
  not_supported = 4,
  tag_not_supported = 5,
  read_or_write_not_supported = 6,
};
constexpr std::array<std::string_view, 7> lookup_names(pgn_error_code) noexcept {
  return {"acknowledge",   "pgn_not_supported", "pgn_not_available",          "access_denied",
          "not_supported", "tag_not_supported", "read_or_write_not_supported"};
}
constexpr std::array<std::string_view, 7> lookup_titles(pgn_error_code) noexcept {
  return {"Acknowledge",   "PGN not supported", "PGN not available",          "Access denied",
          "Not supported", "Tag not supported", "Read or Write not supported"};
}

/// How a device answers for the transmission interval or priority asked of it (126208).
enum class interval_error_code : std::uint8_t {
  acknowledge = 0,
  not_supported_here = 1,
  interval_too_low = 2,
  access_denied = 3,
  not_supported = 4,
};
constexpr std::array<std::string_view, 5> lookup_names(interval_error_code) noexcept {
  return {"acknowledge", "not_supported_here", "interval_too_low", "access_denied",
          "not_supported"};
}
constexpr std::array<std::string_view, 5> lookup_titles(interval_error_code) noexcept {
  return {"Acknowledge", "Transmit Interval/Priority not supported", "Transmit Interval too low",
          "Access denied", "Not supported"};
}

/// How a device answers for one parameter of a command (126208's acknowledgement).
enum class parameter_error_code : std::uint8_t {
  acknowledge = 0,
  invalid_parameter_field = 1,
  temporary_error = 2,
  parameter_out_of_range = 3,
  access_denied = 4,
  not_supported = 5,
  read_or_write_not_supported = 6,
};
constexpr std::array<std::string_view, 7> lookup_names(parameter_error_code) noexcept {
  return {"acknowledge",
          "invalid_parameter_field",
          "temporary_error",
          "parameter_out_of_range",
          "access_denied",
          "not_supported",
          "read_or_write_not_supported"};
}
constexpr std::array<std::string_view, 7> lookup_titles(parameter_error_code) noexcept {
  return {"Acknowledge",
          "Invalid parameter field",
          "Temporary error",
          "Parameter out of range",
          "Access denied",
          "Not supported",
          "Read or Write not supported"};
}

/// PGN 126208 Group Function, function code 0 (Request): fast packet, priority 3, addressed. Asks
/// a device to send PGN `pgn` (now, or at an interval), optionally only messages whose fields
/// hold the given values. The parameter pairs (a field's number in the requested PGN, then its
/// value, as wide as that field) are kept as bytes: their layout is the requested PGN's. The
/// interval 4294967.295 s (all ones) with offset 655.35 s means "send now, change nothing";
/// seawire reads them as not available, as for any field.
struct group_function_request {
  lookup<nmea2000::group_function, 8> function_code = nmea2000::group_function::request;
  unsigned_number<24> pgn;
  unsigned_number<32, res::thousandth> transmission_interval_s;
  unsigned_number<16, res::hundredth> transmission_interval_offset_s;
  unsigned_number<8> number_of_parameters;
  opaque_bytes<212> parameters;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{126208, "group_function_request", "NMEA - Request group function", 3,
                 framing::fast_packet, 0},
        match<&P::function_code, nmea2000::group_function::request>("function_code",
                                                                    "Function Code"),
        field<&P::pgn>("pgn", "PGN"),
        field<&P::transmission_interval_s>("transmission_interval_s", "Transmission interval"),
        field<&P::transmission_interval_offset_s>("transmission_interval_offset_s",
                                                  "Transmission interval offset"),
        field<&P::number_of_parameters>("number_of_parameters", "Number of Parameters"),
        parameter_pairs<&P::parameters, &P::pgn, &P::number_of_parameters>("parameters",
                                                                           "Parameters"));
  }
  [[nodiscard]] constexpr bool operator==(const group_function_request&) const noexcept = default;
};

/// PGN 126208 Group Function, function code 1 (Command): fast packet, priority 3, addressed.
/// Tells a device to change PGN `pgn`: its priority, and the fields the parameter pairs name (a
/// field's number in that PGN, then its new value, as wide as that field; kept as bytes, as in a
/// request). The device answers with an acknowledgement.
struct group_function_command {
  lookup<nmea2000::group_function, 8> function_code = nmea2000::group_function::command;
  unsigned_number<24> pgn;
  lookup<nmea2000::priority_setting, 4> priority;
  unsigned_number<8> number_of_parameters;
  opaque_bytes<217> parameters;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{126208, "group_function_command", "NMEA - Command group function", 3,
                 framing::fast_packet, 0},
        match<&P::function_code, nmea2000::group_function::command>("function_code",
                                                                    "Function Code"),
        field<&P::pgn>("pgn", "PGN"), field<&P::priority>("priority", "Priority"), reserved<4>,
        field<&P::number_of_parameters>("number_of_parameters", "Number of Parameters"),
        parameter_pairs<&P::parameters, &P::pgn, &P::number_of_parameters>("parameters",
                                                                           "Parameters"));
  }
  [[nodiscard]] constexpr bool operator==(const group_function_command&) const noexcept = default;
};

/// PGN 126208 Group Function, function code 2 (Acknowledge): fast packet, priority 3, addressed.
/// A device's answer to a request or command for PGN `pgn`: a code for the PGN, one for the
/// interval or priority, and one per parameter of the command, in its order: 4 bits each, two to
/// a byte, the last byte's rest ones when the count is odd.
struct group_function_acknowledge {
  /// The answer for one parameter.
  struct parameter_answer {
    lookup<nmea2000::parameter_error_code, 4> parameter;

    static constexpr auto n2k_item =
        describe_item(field<&parameter_answer::parameter>("parameter", "Parameter"));
    [[nodiscard]] constexpr bool operator==(const parameter_answer&) const noexcept = default;
  };

  lookup<nmea2000::group_function, 8> function_code = nmea2000::group_function::acknowledge;
  unsigned_number<24> pgn;
  lookup<nmea2000::pgn_error_code, 4> pgn_error_code;
  lookup<nmea2000::interval_error_code, 4> transmission_interval_priority_error_code;
  unsigned_number<8> number_of_parameters;
  group<parameter_answer, group_capacity<parameter_answer>(6)> parameters;

  template <class P>
  static constexpr auto n2k() {
    return describe_pgn(
        pgn_info{126208, "group_function_acknowledge", "NMEA - Acknowledge group function", 3,
                 framing::fast_packet, 0},
        match<&P::function_code, nmea2000::group_function::acknowledge>("function_code",
                                                                        "Function Code"),
        field<&P::pgn>("pgn", "PGN"), field<&P::pgn_error_code>("pgn_error_code", "PGN error code"),
        field<&P::transmission_interval_priority_error_code>(
            "transmission_interval_priority_error_code",
            "Transmission interval/Priority error code"),
        field<&P::number_of_parameters>("number_of_parameters", "Number of Parameters"),
        repeating<&P::parameters, &P::number_of_parameters>("parameters", "Parameter"));
  }
  [[nodiscard]] constexpr bool operator==(const group_function_acknowledge&) const noexcept =
      default;
};

// ---------------------------------------------------------------------------------------------
// sets of PGNs

/// A set of PGN structs: what a receiver knows, looked up by PGN number.
template <class... P>
struct pgn_list {
  static_assert((pgn_like<P> && ...), "a pgn_list holds PGN structs");
  static constexpr std::size_t size = sizeof...(P);

  [[nodiscard]] static constexpr bool knows(std::uint32_t pgn) noexcept {
    return ((pgn_table<P>.info.pgn == pgn) || ...);
  }
  /// How many structs here have PGN `pgn`: more than one for a PGN whose layout a field picks
  /// (match<>, as 126208's function code does).
  [[nodiscard]] static constexpr std::size_t layouts(std::uint32_t pgn) noexcept {
    return (std::size_t{0} + ... + (pgn_table<P>.info.pgn == pgn ? 1U : 0U));
  }
  /// The description's facts for `pgn` (of the first of its layouts), or nullopt for a PGN of
  /// no struct here.
  [[nodiscard]] static constexpr std::optional<pgn_info> info(std::uint32_t pgn) noexcept {
    std::optional<pgn_info> out;
    (void)((pgn_table<P>.info.pgn == pgn ? (out = pgn_table<P>.info, true) : false) || ...);
    return out;
  }
  /// The payload length of `pgn` in bytes (of its longest layout); 0 when unknown.
  [[nodiscard]] static constexpr std::size_t length(std::uint32_t pgn) noexcept {
    std::size_t out = 0;
    ((out = pgn_table<P>.info.pgn == pgn ? std::max(out, description_of<P>::length) : out), ...);
    return out;
  }
  /// Decodes `payload` as the struct for `pgn` (of a PGN with several layouts, the one the
  /// payload matches: layout_matches) and calls fn with it; false (fn not called) when no struct
  /// here has that PGN and layout.
  template <class Fn>
  static constexpr bool visit(std::uint32_t pgn, std::span<const std::uint8_t> payload, Fn&& fn) {
    return ((pgn_table<P>.info.pgn == pgn && layout_matches<P>(payload)
                 ? (fn(decode<P>(payload)), true)
                 : false) ||
            ...);
  }
  /// fn(tag) for every struct, tag being a default-constructed P.
  template <class Fn>
  static constexpr void for_each_type(Fn&& fn) {
    (fn(P{}), ...);
  }
};

/// The six PGNs the ANELLO Maritime INS accepts as input.
using ins_input_pgns =
    pgn_list<engine_parameters_rapid, engine_parameters_dynamic, speed_water_referenced,
             distance_log, environmental_parameters, vessel_speed_components>;

}  // namespace seawire::nmea2000
