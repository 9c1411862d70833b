// SPDX-License-Identifier: BSL-1.0
#pragma once
// The ANELLO Maritime INS custom binary sensor input frame: 56 bytes, every field big-endian:
// AB 00, payload length 48, zlib CRC-32 of bytes 8-55, then 19 payload fields. One table
// (sensor_fields) gives each field's offset, scale and range; decode_frame, encode_frame,
// build_frame, validate, to_values and the accessors are loops over it. "Not available" is each
// wire type's maximum. The rules (CRC, sentinels, rounding, ranges): docs/anello-frame.md.

#include <array>
#include <chrono>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

#include "seawire/detail/bit_layout.hpp"
#include "seawire/detail/byte_order.hpp"
#include "seawire/detail/crc32.hpp"
#include "seawire/detail/member.hpp"
#include "seawire/detail/rounding.hpp"
#include "seawire/detail/row_list.hpp"
#include "seawire/error.hpp"

namespace seawire::anello {

inline constexpr std::uint16_t frame_id = 0xAB00;  ///< the first two bytes of every frame
inline constexpr std::size_t header_size = 8;      ///< id, length, CRC
inline constexpr std::size_t payload_size = 48;    ///< the length field's only valid value
inline constexpr std::size_t frame_size = header_size + payload_size;  ///< 56
inline constexpr std::size_t sensor_field_count = 19;

using frame_bytes = std::array<std::uint8_t, frame_size>;

/// GPS time as the frame carries it: milliseconds of Unix time (UTC, no leap seconds), not the GPS
/// time scale.
using time_ms = std::chrono::sys_time<std::chrono::milliseconds>;

/// The payload in physical units, as a sender has it; nullopt = not available. Member names are
/// the table's field names (ranges: docs/messages.md).
struct sensor_values {
  std::optional<double> heading_deg;         ///<  1 IMU compass heading, degrees
  std::optional<double> latitude_deg;        ///<  2 degrees, north positive
  std::optional<double> longitude_deg;       ///<  3 degrees, east positive
  std::optional<double> sog_mps;             ///<  4 speed over ground, m/s
  std::optional<double> cog_deg;             ///<  5 course over ground, degrees
  std::optional<time_ms> gps_time;           ///<  6 time of the GPS fix
  std::optional<double> alt_msl_m;           ///<  7 altitude above mean sea level, m
  std::optional<double> geoid_sep_m;         ///<  8 geoid separation, m
  std::optional<double> hdop;                ///<  9 horizontal dilution of precision
  std::optional<int> fix_quality;            ///< 10 GGA quality indicator (0 = no fix)
  std::optional<double> motor_pct;           ///< 11 motor, %
  std::optional<double> rudder_pct;          ///< 12 rudder, %, +100 = full starboard
  std::optional<double> stw_mps;             ///< 13 speed through water, m/s
  std::optional<double> wind_speed_abs_mps;  ///< 14 true wind speed, m/s
  std::optional<double> wind_dir_abs_deg;    ///< 15 true wind direction, degrees
  std::optional<double> wind_speed_rel_mps;  ///< 16 apparent wind speed, m/s
  std::optional<double> wind_dir_rel_deg;    ///< 17 apparent wind angle, degrees
  std::optional<double> air_temp_c;          ///< 18 air temperature, degrees Celsius
  std::optional<double> pressure_hpa;        ///< 19 barometric pressure, hPa

  [[nodiscard]] constexpr bool operator==(const sensor_values&) const noexcept = default;
};

struct sensor_frame_raw;

namespace detail {
template <class T>
inline constexpr T not_available = std::numeric_limits<T>::max();

template <auto ValueMember>
[[nodiscard]] constexpr seawire::detail::member_type_t<ValueMember> physical_of(
    const sensor_frame_raw& frame) noexcept;
}  // namespace detail

/// The payload as the wire carries it, in wire order. Each member: field number, spec name,
/// wire resolution. A default-constructed frame says "nothing available" in every field.
struct sensor_frame_raw {
  std::uint16_t heading = detail::not_available<std::uint16_t>;         //  1 IMU heading, 1 deg
  std::int32_t lat = detail::not_available<std::int32_t>;               //  2 latitude, 1e-6 deg
  std::int32_t lon = detail::not_available<std::int32_t>;               //  3 longitude, 1e-6 deg
  std::uint16_t sog = detail::not_available<std::uint16_t>;             //  4 SOG, 0.1 m/s
  std::uint16_t cog = detail::not_available<std::uint16_t>;             //  5 COG, 1 deg
  std::uint64_t gps_time_ms = detail::not_available<std::uint64_t>;     //  6 Unix time, 1 ms
  std::int32_t alt_msl = detail::not_available<std::int32_t>;           //  7 MSL alt, 0.1 m
  std::int32_t geoid_sep = detail::not_available<std::int32_t>;         //  8 geoid sep, 0.1 m
  std::uint8_t hdop_tenths = detail::not_available<std::uint8_t>;       //  9 HDOP, 0.1
  std::uint8_t gga_quality = detail::not_available<std::uint8_t>;       // 10 GGA fix quality
  std::int8_t motor = detail::not_available<std::int8_t>;               // 11 motor, 1 %
  std::int8_t rudder = detail::not_available<std::int8_t>;              // 12 rudder, 1 %
  std::uint16_t stw = detail::not_available<std::uint16_t>;             // 13 STW, 0.1 m/s
  std::uint16_t wind_speed_abs = detail::not_available<std::uint16_t>;  // 14 0.1 m/s
  std::uint16_t wind_dir_abs = detail::not_available<std::uint16_t>;    // 15 1 deg
  std::uint16_t wind_speed_rel = detail::not_available<std::uint16_t>;  // 16 0.1 m/s
  std::uint16_t wind_dir_rel = detail::not_available<std::uint16_t>;    // 17 1 deg
  std::int16_t air_temp = detail::not_available<std::int16_t>;          // 18 0.1 degC
  std::uint16_t pressure = detail::not_available<std::uint16_t>;        // 19 1 hPa

  // Physical values, each read through its row of sensor_fields; nullopt when the field says
  // "not available". (Templates only so that they are compiled where called, after the table.)
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> heading_deg() const noexcept {
    return detail::physical_of<&sensor_values::heading_deg>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> latitude_deg() const noexcept {
    return detail::physical_of<&sensor_values::latitude_deg>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> longitude_deg() const noexcept {
    return detail::physical_of<&sensor_values::longitude_deg>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> sog_mps() const noexcept {
    return detail::physical_of<&sensor_values::sog_mps>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> cog_deg() const noexcept {
    return detail::physical_of<&sensor_values::cog_deg>(static_cast<const F&>(*this));
  }
  /// Also nullopt for a time past the year 292 million, which time_ms cannot hold.
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<time_ms> gps_time() const noexcept {
    return detail::physical_of<&sensor_values::gps_time>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> alt_msl_m() const noexcept {
    return detail::physical_of<&sensor_values::alt_msl_m>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> geoid_sep_m() const noexcept {
    return detail::physical_of<&sensor_values::geoid_sep_m>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> hdop() const noexcept {
    return detail::physical_of<&sensor_values::hdop>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<int> fix_quality() const noexcept {
    return detail::physical_of<&sensor_values::fix_quality>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> motor_pct() const noexcept {
    return detail::physical_of<&sensor_values::motor_pct>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> rudder_pct() const noexcept {
    return detail::physical_of<&sensor_values::rudder_pct>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> stw_mps() const noexcept {
    return detail::physical_of<&sensor_values::stw_mps>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> wind_speed_abs_mps() const noexcept {
    return detail::physical_of<&sensor_values::wind_speed_abs_mps>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> wind_dir_abs_deg() const noexcept {
    return detail::physical_of<&sensor_values::wind_dir_abs_deg>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> wind_speed_rel_mps() const noexcept {
    return detail::physical_of<&sensor_values::wind_speed_rel_mps>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> wind_dir_rel_deg() const noexcept {
    return detail::physical_of<&sensor_values::wind_dir_rel_deg>(static_cast<const F&>(*this));
  }
  /// Both 0x7FFF and 0xFFFF are "not available": see the air_temp_c row of sensor_fields.
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> air_temp_c() const noexcept {
    return detail::physical_of<&sensor_values::air_temp_c>(static_cast<const F&>(*this));
  }
  template <class F = sensor_frame_raw>
  [[nodiscard]] constexpr std::optional<double> pressure_hpa() const noexcept {
    return detail::physical_of<&sensor_values::pressure_hpa>(static_cast<const F&>(*this));
  }

  [[nodiscard]] constexpr bool operator==(const sensor_frame_raw&) const noexcept = default;
};

/// A closed range of physical values, in whole units of the field's physical value.
struct value_range {
  std::int64_t lo;
  std::int64_t hi;
};

namespace detail {

/// Fraction digits of a power-of-ten divisor (1 -> 0, 10 -> 1, 1'000'000 -> 6).
[[nodiscard]] constexpr unsigned divisor_places(std::int64_t divisor) noexcept {
  unsigned n = 0;
  while (divisor > 1) {
    divisor /= 10;
    ++n;
  }
  return n;
}

}  // namespace detail

/// One payload field: where it is, its scale and what a sender may put in it; the members'
/// types give the wire type and the physical type (double, int or time_ms).
template <auto RawMember, auto ValueMember>
struct sensor_field {
  using raw_type = seawire::detail::member_type_t<RawMember>;
  using value_type = typename seawire::detail::member_type_t<ValueMember>::value_type;
  /// The field's width on the wire: its wire type's.
  static constexpr unsigned bits = 8 * sizeof(raw_type);
  static constexpr auto raw_member = RawMember;
  static constexpr auto value_member = ValueMember;

  std::string_view name;  ///< snake_case; also the sensor_values member and the accessor
  /// The key in JSON; empty in a table row when it is the name (the table then fills it in).
  std::string_view json_key = {};
  std::int64_t divisor = 1;  ///< wire counts per physical unit, a power of ten: raw / divisor
  /// What the spec allows, in physical units; without it, whatever the wire type holds.
  std::optional<value_range> allowed = std::nullopt;
  /// A value read as "not available" besides the type's maximum.
  std::optional<raw_type> also_not_available = std::nullopt;
  /// Of the field's first byte in the frame, computed from the widths before it.
  std::size_t offset = 0;

  [[nodiscard]] constexpr bool not_available(raw_type raw) const noexcept {
    return raw == detail::not_available<raw_type> ||
           (also_not_available && raw == *also_not_available);
  }

  /// The lowest and highest wire value a sender may write.
  [[nodiscard]] constexpr value_range wire_limits() const noexcept {
    if (allowed) return {allowed->lo * divisor, allowed->hi * divisor};
    constexpr std::int64_t int64_max = std::numeric_limits<std::int64_t>::max();
    constexpr auto type_hi = detail::not_available<raw_type> - 1;  // the maximum is n/a
    return {static_cast<std::int64_t>(std::numeric_limits<raw_type>::min()),
            std::cmp_less(int64_max, type_hi) ? int64_max : static_cast<std::int64_t>(type_hi)};
  }

  /// The error for a value outside wire_limits(): out_of_range (the spec's), value_too_large.
  [[nodiscard]] constexpr errc refusal() const noexcept {
    return allowed ? errc::out_of_range : errc::value_too_large;
  }

  /// Whether a strict sender could have written `raw`: n/a or within wire_limits().
  [[nodiscard]] constexpr bool acceptable(raw_type raw) const noexcept {
    const auto [lo, hi] = wire_limits();
    return not_available(raw) || (!std::cmp_less(raw, lo) && !std::cmp_greater(raw, hi));
  }

  [[nodiscard]] constexpr std::optional<value_type> to_physical(raw_type raw) const noexcept {
    if (not_available(raw)) return std::nullopt;
    if constexpr (std::is_same_v<value_type, time_ms>) {
      using rep = time_ms::rep;
      if (std::cmp_greater(raw, std::numeric_limits<rep>::max())) return std::nullopt;
      return time_ms{time_ms::duration{static_cast<rep>(raw)}};
    } else if constexpr (std::is_same_v<value_type, double>) {
      // Divided by the exact divisor: the double nearest the wire's decimal (32.828671).
      return static_cast<double>(raw) / static_cast<double>(divisor);
    } else {
      return static_cast<value_type>(raw);
    }
  }

  /// Rounds `value` to the wire resolution into `out`; nullopt becomes "not available".
  /// On failure `out` is left alone.
  [[nodiscard]] constexpr errc to_wire(const std::optional<value_type>& value,
                                       raw_type& out) const noexcept {
    if (!value) {
      out = detail::not_available<raw_type>;
      return errc::ok;
    }
    std::int64_t wire = 0;
    if constexpr (std::is_same_v<value_type, time_ms>) {
      wire = value->time_since_epoch().count();
    } else if constexpr (std::is_same_v<value_type, double>) {
      // nmea::decimal::from_double's rule: 1.05 m/s is 11 tenths.
      seawire::detail::rounded_double m;
      const errc e = seawire::detail::round_double(
          *value, 1, static_cast<int>(detail::divisor_places(divisor)), 1, m);
      if (e == errc::not_finite) return e;
      if (e != errc::ok ||
          m.magnitude > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
        return refusal();
      const auto mag = static_cast<std::int64_t>(m.magnitude);
      wire = m.negative ? -mag : mag;
    } else {
      wire = static_cast<std::int64_t>(*value);
    }
    const auto [lo, hi] = wire_limits();
    if (wire < lo || wire > hi) return refusal();
    const auto raw = static_cast<raw_type>(wire);
    if (not_available(raw)) return refusal();  // would be read back as "not available"
    out = raw;
    return errc::ok;
  }
};

/// What describe_frame refuses in a row. Each is declared and never defined: describe_frame
/// calls one only for a row that makes no sense, and a call to a function that is not constexpr
/// stops the compile there, the function's name saying what is wrong.
namespace frame_table::bad_row {
void name_is_empty();
void in_range_has_lo_above_hi();
void divisor_is_not_a_positive_power_of_ten();
void divisor_on_a_field_whose_value_is_not_a_double();
void in_range_times_divisor_does_not_fit_the_wire_type_below_its_maximum();
void also_not_available_is_the_wire_type_maximum_already_not_available();
}  // namespace frame_table::bad_row

namespace detail {
// Whether lo * divisor and hi * divisor, both computed without overflow, are values of Raw
// other than its maximum (the maximum reads "not available", so a sender could not write it).
template <class Raw>
[[nodiscard]] consteval bool fits_wire_type(value_range r, std::int64_t divisor) {
  constexpr std::int64_t int64_max = std::numeric_limits<std::int64_t>::max();
  constexpr std::int64_t int64_min = std::numeric_limits<std::int64_t>::min();
  const auto fits = [&](std::int64_t v) {
    if (v > int64_max / divisor || v < int64_min / divisor) return false;
    const std::int64_t wire = v * divisor;
    return std::in_range<Raw>(wire) && std::cmp_less(wire, detail::not_available<Raw>);
  };
  return fits(r.lo) && fits(r.hi);
}

// Stops the compile at the first fact of the row that makes no sense (bad_row).
template <class F>
consteval void check_row(const F& f) {
  using raw_type = typename F::raw_type;
  if (f.name.empty()) frame_table::bad_row::name_is_empty();
  std::int64_t d = f.divisor;
  while (d >= 10 && d % 10 == 0) d /= 10;
  if (d != 1) frame_table::bad_row::divisor_is_not_a_positive_power_of_ten();
  if (!std::is_same_v<typename F::value_type, double> && f.divisor != 1)
    frame_table::bad_row::divisor_on_a_field_whose_value_is_not_a_double();
  if (f.allowed) {
    if (f.allowed->lo > f.allowed->hi) frame_table::bad_row::in_range_has_lo_above_hi();
    if (!fits_wire_type<raw_type>(*f.allowed, f.divisor))
      frame_table::bad_row::in_range_times_divisor_does_not_fit_the_wire_type_below_its_maximum();
  }
  if (f.also_not_available && *f.also_not_available == detail::not_available<raw_type>)
    frame_table::bad_row::also_not_available_is_the_wire_type_maximum_already_not_available();
}
}  // namespace detail

/// The vocabulary of the frame's table: rows `field<&raw, &value>("name", facts...)` given to
/// describe_frame. (A namespace of its own, so that `using namespace seawire::anello` does not
/// bring in names as common as `field`.)
namespace frame_table {

/// What a row can say besides its name.
namespace fact {
struct range {
  value_range r;
  template <class F>
  constexpr void apply(F& f) const noexcept {
    f.allowed = r;
  }
};
struct json_key {
  std::string_view key;
  template <class F>
  constexpr void apply(F& f) const noexcept {
    f.json_key = key;
  }
};
struct divisor {
  std::int64_t n;
  template <class F>
  constexpr void apply(F& f) const noexcept {
    f.divisor = n;
  }
};
template <class Raw>
struct also_not_available {
  Raw raw;
  template <class F>
  constexpr void apply(F& f) const noexcept {
    static_assert(std::is_same_v<Raw, typename F::raw_type>,
                  "a raw value of the field's wire type");
    f.also_not_available = raw;
  }
};
}  // namespace fact

/// What a sender may put in the field, in whole physical units, both ends allowed.
[[nodiscard]] constexpr fact::range in_range(std::int64_t lo, std::int64_t hi) noexcept {
  return {{lo, hi}};
}
/// The key in JSON, where it is not the field's name.
[[nodiscard]] constexpr fact::json_key json_key(std::string_view key) noexcept { return {key}; }
/// Wire counts per physical unit, a power of ten (10: tenths): physical = raw / n.
[[nodiscard]] constexpr fact::divisor divisor(std::int64_t n) noexcept { return {n}; }
/// A raw value read as "not available" besides the wire type's maximum.
template <std::integral Raw>
[[nodiscard]] constexpr fact::also_not_available<Raw> also_not_available(Raw raw) noexcept {
  return {raw};
}

/// A row of the frame's table: the raw member, the sensor_values member, the name, the facts.
template <auto RawMember, auto ValueMember, class... Facts>
[[nodiscard]] consteval sensor_field<RawMember, ValueMember> field(std::string_view name,
                                                                   Facts... facts) noexcept {
  static_assert((requires(sensor_field<RawMember, ValueMember> & f) { facts.apply(f); } && ...),
                "a frame row's facts are in_range, divisor, json_key and also_not_available");
  sensor_field<RawMember, ValueMember> f{.name = name};
  (facts.apply(f), ...);
  return f;
}

/// The frame's table from its rows in wire order: each field starts where the one before ends,
/// after the 8-byte header; the JSON key is the name unless a row says. A row that makes no
/// sense does not compile (bad_row names why): an empty name, a divisor that is not a positive
/// power of ten or is not 1 on a field whose value is not a double, an in_range whose lo is
/// above its hi or which, times the divisor, does not fit the wire type below its maximum (the
/// maximum is "not available"), an also_not_available that is that maximum.
template <class... Fields>
[[nodiscard]] consteval seawire::detail::row_list<Fields...> describe_frame(
    Fields... rows) noexcept {
  (detail::check_row(rows), ...);
  seawire::detail::row_list<Fields...> fields = seawire::detail::make_rows(rows...);
  seawire::detail::for_each_row(fields, 8 * header_size, [](auto& field, unsigned bit, auto) {
    field.offset = bit / 8;
    if (field.json_key.empty()) field.json_key = field.name;
  });
  return fields;
}

}  // namespace frame_table

/// The payload layout, one sensor_field per field in the spec's order (a row_list: `apply(f)`
/// calls f(fields...), `seawire::detail::row_at<I>` gives one); a row's
/// position (1-based) is the field number in errors.
inline constexpr auto sensor_fields = [] {
  using frame_table::also_not_available, frame_table::describe_frame, frame_table::divisor,
      frame_table::field, frame_table::in_range, frame_table::json_key;
  using r = sensor_frame_raw;
  using v = sensor_values;
  constexpr auto degrees = in_range(0, 360);  // "Degrees: 0-360" in the spec, both ends
  constexpr auto tenths = divisor(10);
  return describe_frame(
      field<&r::heading, &v::heading_deg>("heading_deg", degrees),
      // JSON "latitude" and "longitude", as every message.
      field<&r::lat, &v::latitude_deg>("latitude_deg", json_key("latitude"), divisor(1'000'000),
                                       in_range(-90, 90)),
      field<&r::lon, &v::longitude_deg>("longitude_deg", json_key("longitude"), divisor(1'000'000),
                                        in_range(-180, 180)),
      field<&r::sog, &v::sog_mps>("sog_mps", tenths),
      field<&r::cog, &v::cog_deg>("cog_deg", degrees),
      field<&r::gps_time_ms, &v::gps_time>("gps_time"),
      field<&r::alt_msl, &v::alt_msl_m>("alt_msl_m", tenths),
      field<&r::geoid_sep, &v::geoid_sep_m>("geoid_sep_m", tenths),
      // The spec's HDOP range 0-1 is not enforced: real fixes have more.
      field<&r::hdop_tenths, &v::hdop>("hdop", tenths),
      // "as defined by GPGGA": NMEA 0183 defines qualities 0 (invalid) to 8 (simulation).
      field<&r::gga_quality, &v::fix_quality>("fix_quality", in_range(0, 8)),
      field<&r::motor, &v::motor_pct>("motor_pct", in_range(-100, 100)),
      field<&r::rudder, &v::rudder_pct>("rudder_pct", in_range(-100, 100)),
      field<&r::stw, &v::stw_mps>("stw_mps", tenths),
      field<&r::wind_speed_abs, &v::wind_speed_abs_mps>("wind_speed_abs_mps", tenths),
      field<&r::wind_dir_abs, &v::wind_dir_abs_deg>("wind_dir_abs_deg", degrees),
      field<&r::wind_speed_rel, &v::wind_speed_rel_mps>("wind_speed_rel_mps", tenths),
      field<&r::wind_dir_rel, &v::wind_dir_rel_deg>("wind_dir_rel_deg", degrees),
      // 0xFFFF, the spec example's "not reported", is not available too; nullopt sent as 0x7FFF.
      field<&r::air_temp, &v::air_temp_c>("air_temp_c", tenths,
                                          also_not_available(std::int16_t{-1})),
      field<&r::pressure, &v::pressure_hpa>("pressure_hpa"));
}();

namespace detail {

// Calls fn(field_number, field) in table order, heading = 1, until fn returns false.
// Returns whether every call returned true.
template <class Fn>
constexpr bool visit_sensor_fields(Fn&& fn) {
  return seawire::detail::for_each_row(
      sensor_fields, 8 * header_size,
      [&](const auto& field, unsigned, std::uint16_t number) { return fn(number, field); });
}

inline constexpr auto frame_order = seawire::detail::bit_order::msb_first;

// The table against the spec: 19 fields filling bytes 8 to 56. (describe_frame checked each
// row's facts.)
consteval bool sensor_fields_match_spec() {
  std::size_t end = header_size;
  visit_sensor_fields([&](std::uint16_t, const auto& field) {
    end = field.offset + sizeof(typename std::remove_cvref_t<decltype(field)>::raw_type);
    return true;
  });
  return end == frame_size &&
         seawire::detail::layout_bits<decltype(sensor_fields)> == 8 * payload_size &&
         std::remove_cv_t<decltype(sensor_fields)>::size == sensor_field_count;
}
static_assert(sensor_fields_match_spec(), "sensor_fields disagrees with the spec's layout");

// The row of sensor_fields whose sensor_values member is ValueMember.
template <auto ValueMember>
consteval std::size_t row_of() noexcept {
  using table = std::remove_cv_t<decltype(sensor_fields)>;
  return []<std::size_t... I>(std::index_sequence<I...>) {
    std::size_t row = sensor_field_count;
    ((row =
          row == sensor_field_count &&
                  seawire::detail::same_member<seawire::detail::row_type_t<I, table>::value_member,
                                               ValueMember>
              ? I
              : row),
     ...);
    return row;
  }
  (std::make_index_sequence<sensor_field_count>{});
}

// One field of `frame` in physical units, read through its row alone (an accessor costs the
// compiler one row, not a walk over all 19).
template <auto ValueMember>
[[nodiscard]] constexpr seawire::detail::member_type_t<ValueMember> physical_of(
    const sensor_frame_raw& frame) noexcept {
  constexpr const auto& field = seawire::detail::row_at<row_of<ValueMember>()>(sensor_fields);
  using field_type = std::remove_cvref_t<decltype(field)>;
  return field.to_physical(frame.*field_type::raw_member);
}

}  // namespace detail

// decode_frame, encode_frame, build_frame, validate and to_values are templates of nothing, so
// that only a translation unit calling one compiles its walk over the 19 fields (as the role
// decoders: nmea::lazy); they are called as any function, decode_frame(bytes).

/// Decodes the frame at the start of `bytes`. Checks, in order: frame id (bad_frame_id, column
/// 0), length 48 (bad_length, column 2), 56 bytes (truncated, column = bytes.size(): every byte
/// so far is right), CRC (crc_mismatch, column 4). No range checks (validate()). On error `value`
/// is an all-n/a frame.
template <int = 0>
[[nodiscard]] constexpr result<sensor_frame_raw> decode_frame(
    std::span<const std::uint8_t> bytes) noexcept {
  result<sensor_frame_raw> out;
  const auto fail = [&out](errc ec, std::size_t column) {
    out.ec = ec;
    out.column = static_cast<std::uint16_t>(column);
    return out;
  };
  std::array<std::uint8_t, 4> expected{};
  seawire::detail::store_be(expected, 0, frame_id);
  seawire::detail::store_be(expected, 2, static_cast<std::uint16_t>(payload_size));
  for (std::size_t i = 0; i < expected.size() && i < bytes.size(); ++i) {
    if (bytes[i] != expected[i]) {
      return i < 2 ? fail(errc::bad_frame_id, 0) : fail(errc::bad_length, 2);
    }
  }
  if (bytes.size() < frame_size) return fail(errc::truncated, bytes.size());
  if (seawire::detail::load_be<std::uint32_t>(bytes, 4) !=
      crc32(bytes.subspan(header_size, payload_size))) {
    return fail(errc::crc_mismatch, 4);
  }
  detail::visit_sensor_fields([&](std::uint16_t, const auto& field) {
    using field_type = std::remove_cvref_t<decltype(field)>;
    // The conversion to a signed type is two's complement (modular since C++20).
    out.value.*field_type::raw_member =
        static_cast<typename field_type::raw_type>(seawire::detail::get_bits<detail::frame_order>(
            bytes, 8 * static_cast<unsigned>(field.offset), field_type::bits));
    return true;
  });
  return out;
}

/// Writes `frame`'s raw integers as 56 bytes, header and CRC included, and returns 56;
/// buffer_too_small (nothing written) if `out` is shorter.
template <int = 0>
[[nodiscard]] constexpr result<std::size_t> encode_frame(const sensor_frame_raw& frame,
                                                         std::span<std::uint8_t> out) noexcept {
  if (out.size() < frame_size) return {0, errc::buffer_too_small};
  seawire::detail::store_be(out, 0, frame_id);
  seawire::detail::store_be(out, 2, static_cast<std::uint16_t>(payload_size));
  detail::visit_sensor_fields([&](std::uint16_t, const auto& field) {
    using field_type = std::remove_cvref_t<decltype(field)>;
    using unsigned_type = std::make_unsigned_t<typename field_type::raw_type>;
    seawire::detail::put_bits<detail::frame_order>(
        out, 8 * static_cast<unsigned>(field.offset), field_type::bits,
        static_cast<unsigned_type>(frame.*field_type::raw_member));
    return true;
  });
  seawire::detail::store_be(out, 4, crc32(out.subspan(header_size, payload_size)));
  return {frame_size};
}

/// The 56 bytes of `frame`.
template <int = 0>
[[nodiscard]] constexpr frame_bytes encode_frame(const sensor_frame_raw& frame) noexcept {
  frame_bytes bytes{};
  (void)encode_frame(frame, bytes);  // cannot fail: the array is exactly a frame long
  return bytes;
}

/// The frame a strict sender writes for `values`: each rounded to its field's resolution
/// (decimal::from_double's rule), nullopt as not available. Refuses the first field that is
/// NaN or infinite (not_finite), outside the spec's range after rounding (out_of_range), or not
/// carried by the wire type (value_too_large); `field` 1-19, `column` its byte offset.
template <int = 0>
[[nodiscard]] constexpr result<sensor_frame_raw> build_frame(const sensor_values& values) noexcept {
  result<sensor_frame_raw> out;
  detail::visit_sensor_fields([&](std::uint16_t number, const auto& field) {
    using field_type = std::remove_cvref_t<decltype(field)>;
    const errc ec =
        field.to_wire(values.*field_type::value_member, out.value.*field_type::raw_member);
    if (ec == errc::ok) return true;
    out = {{}, ec, number, static_cast<std::uint16_t>(field.offset)};
    return false;
  });
  return out;
}

/// Whether every field of `frame` is not available or within what build_frame would send; the
/// first that is not gives build_frame's error.
template <int = 0>
[[nodiscard]] constexpr result<sensor_frame_raw> validate(const sensor_frame_raw& frame) noexcept {
  result<sensor_frame_raw> out{frame};
  detail::visit_sensor_fields([&](std::uint16_t number, const auto& field) {
    using field_type = std::remove_cvref_t<decltype(field)>;
    if (field.acceptable(frame.*field_type::raw_member)) return true;
    out.ec = field.refusal();
    out.field = number;
    out.column = static_cast<std::uint16_t>(field.offset);
    return false;
  });
  return out;
}

/// Every field in physical units. build_frame(to_values(f)) == f for every f that validates.
template <int = 0>
[[nodiscard]] constexpr sensor_values to_values(const sensor_frame_raw& frame) noexcept {
  sensor_values values;
  detail::visit_sensor_fields([&](std::uint16_t, const auto& field) {
    using field_type = std::remove_cvref_t<decltype(field)>;
    values.*field_type::value_member = field.to_physical(frame.*field_type::raw_member);
    return true;
  });
  return values;
}

/// Calls fn(name, value) for each field in table order: value a std::optional of double, int
/// (fix_quality) or time_ms (gps_time).
template <class Fn>
constexpr void for_each_field(const sensor_frame_raw& frame, Fn&& fn) {
  detail::visit_sensor_fields([&](std::uint16_t, const auto& field) {
    using field_type = std::remove_cvref_t<decltype(field)>;
    fn(field.name, field.to_physical(frame.*field_type::raw_member));
    return true;
  });
}

}  // namespace seawire::anello
