// SPDX-License-Identifier: BSL-1.0
#pragma once
// The 2018 Maritime RobotX Challenge reports a team's vehicle sends to the Technical Director's
// server: RXHRB (1 Hz heartbeat), RXGAT, RXCOD, RXDOK, RXDEL. Times are HST (hst.hpp), whole
// seconds. Date, time, team id and mode are required; the rest may be blank (std::optional).
// RXDOK spells the cross CRUC, RXDEL CRUCI: each has its own shape type accepting both and
// writing its own (docs/robotx.md).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>

#include "seawire/detail/fixed_string.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"

namespace seawire::robotx {

/// What the judges' server accepts. A checksum is required (the spec asks for one and the TD
/// verifies it). Lower-case hex and extra trailing fields are accepted: team code sends them,
/// and validator.hpp reports both as findings instead of losing the report.
inline constexpr nmea::parse_policy judge_policy{
    nmea::checksum_policy::required, true, true, false, false, 1024};

// ---------------------------------------------------------------------------------------------
// field values

/// RXHRB field 8. (The 2022 and 2024 editions add 3 = killed; 2018 has only these two.)
enum class system_mode : char { remote = '1', autonomous = '2' };

/// RXHRB field 9.
enum class auv_status : char {
  stowed = '1',     ///< secured to the AMS, not yet deployed
  deployed = '2',   ///< released from the AMS
  recovered = '3',  ///< back aboard after a deployment
  fault = '4',      ///< faulted while neither recovered nor stowed
  killed = '5',     ///< propulsion killed, safe to approach
};

/// RXGAT fields 4 and 5: the gate holding an active beacon.
enum class gate : char { one = '1', two = '2', three = '3' };

/// RXGAT field 6: Y = the light buoy is on (circle it), N = off (circle the black buoy).
enum class light_buoy : char { on = 'Y', off = 'N' };

/// Light and shape colours.
enum class color : char { red = 'R', blue = 'B', green = 'G' };

/// RXDOK field 5. Writes CRUC; reads CRUC or CRUCI.
enum class dock_shape : std::uint8_t { cruciform, triangle, circle };
constexpr std::array<std::string_view, 3> enum_words(dock_shape) noexcept {
  return {"CRUC", "TRIAN", "CIRCL"};
}
constexpr std::array<std::pair<std::string_view, dock_shape>, 1> enum_aliases(dock_shape) noexcept {
  return {{{"CRUCI", dock_shape::cruciform}}};
}

/// RXDEL field 5. Writes CRUCI; reads CRUCI or CRUC.
enum class deliver_shape : std::uint8_t { cruciform, triangle, circle };
constexpr std::array<std::string_view, 3> enum_words(deliver_shape) noexcept {
  return {"CRUCI", "TRIAN", "CIRCL"};
}
constexpr std::array<std::pair<std::string_view, deliver_shape>, 1> enum_aliases(
    deliver_shape) noexcept {
  return {{{"CRUC", deliver_shape::cruciform}}};
}

[[nodiscard]] constexpr deliver_shape as_deliver_shape(dock_shape s) noexcept {
  return static_cast<deliver_shape>(s);
}
[[nodiscard]] constexpr dock_shape as_dock_shape(deliver_shape s) noexcept {
  return static_cast<dock_shape>(s);
}

/// Three colours, first to last over time ("RGB"). Repeats are allowed: the spec does not
/// forbid them, and a judge must be able to read whatever a team reports.
struct light_pattern {
  std::array<color, 3> colors{};

  /// From text such as "RGB": bad_length unless three letters, bad_enum for any other than R/B/G.
  /// (A template of nothing: color's letters are read only where it is used.)
  template <int N = 0>
  [[nodiscard]] static constexpr result<light_pattern> from(std::string_view s) noexcept {
    result<light_pattern> r;
    if (s.size() != 3) {
      r.ec = errc::bad_length;
      return r;
    }
    for (std::size_t i = 0; i < 3; ++i) {
      if (!nmea::is_enum_letter<nmea::lazy<color, N>>(s[i])) {
        r.ec = errc::bad_enum;
        return r;
      }
      r.value.colors[i] = static_cast<color>(s[i]);
    }
    return r;
  }
  friend constexpr bool operator==(const light_pattern&, const light_pattern&) noexcept = default;
};

}  // namespace seawire::robotx

template <>
struct seawire::nmea::codec<seawire::robotx::light_pattern> {
  using value_type = seawire::robotx::light_pattern;
  /// What the wire field holds, for generated references.
  static constexpr std::string_view form = "three colours `R` `G` `B`, first to last (`RGB`)";
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = 3;
  static constexpr bool allows_blank = false;
  // read() and check() are function templates of nothing, as light_pattern::from is.
  template <int N = 0>
  static constexpr errc read(nmea::field_reader& r, value_type& v) noexcept {
    const result<value_type> p = value_type::template from<N>(r.take().text);
    if (p) v = p.value;
    return p.ec;
  }
  template <int N = 0>
  static constexpr errc check(const value_type& v) noexcept {
    for (const auto c : v.colors)
      if (nmea::to_string(static_cast<nmea::lazy<seawire::robotx::color, N>>(c)).empty())
        return errc::bad_enum;
    return errc::ok;
  }
  template <nmea::sentence_writer W>
  static constexpr void write(W& w, const value_type& v) noexcept {
    for (const auto c : v.colors) w.put(static_cast<char>(c));
  }
};

namespace seawire::robotx {

// ---------------------------------------------------------------------------------------------
// messages

/// Heartbeat, 1 Hz, always.
///   $RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,2,1*06
struct rxhrb {
  nmea::date date;                             // 1   [HST Date] ddmmyy
  nmea::time_of_day time;                      // 2   [HST Time] hhmmss, 24 h
  std::optional<nmea::decimal_latitude> lat;   // 3,4 [Latitude] [N/S indicator] unsigned
                                               //     decimal degrees; sign from the letter
  std::optional<nmea::decimal_longitude> lon;  // 5,6 [Longitude] [E/W indicator] likewise
  nmea::text<5> team_id;                       // 7   [Team ID] 5 characters assigned by TD
  robotx::system_mode system_mode = robotx::system_mode::autonomous;  // 8 [System Mode]
  std::optional<robotx::auv_status> auv_status;                       // 9   [AUV Status]

  static constexpr auto nmea = nmea::sentence<"RXHRB">(
      nmea::field<&rxhrb::date>("date"), nmea::field<&rxhrb::time>("time", nmea::max_places(0)),
      nmea::field<&rxhrb::lat>("latitude", nmea::precision(5)),
      nmea::field<&rxhrb::lon>("longitude", nmea::precision(5)),
      nmea::field<&rxhrb::team_id>("team_id", nmea::exact_length(5)),
      nmea::field<&rxhrb::system_mode>("system_mode"),
      nmea::field<&rxhrb::auv_status>("auv_status"));

  friend constexpr bool operator==(const rxhrb&, const rxhrb&) noexcept = default;
};

/// Entrance and Exit Gates: the gates in which the AMS detected an active beacon.
///   $RXGAT,101218,161229,AUVSI,1,2,Y,RGB*25
struct rxgat {
  nmea::date date;                                     // 1 [HST date] ddmmyy
  nmea::time_of_day time;                              // 2 [HST time] hhmmss
  nmea::text<5> team_id;                               // 3 [Team ID]
  std::optional<gate> entrance_gate;                   // 4 [Active Entrance Gate]
  std::optional<gate> exit_gate;                       // 5 [Active Exit Gate]
  std::optional<light_buoy> light_buoy_active;         // 6 [Light Buoy Active] Y/N
  std::optional<robotx::light_pattern> light_pattern;  // 7 [Light Pattern] R/B/G x 3

  static constexpr auto nmea = nmea::sentence<"RXGAT">(
      nmea::field<&rxgat::date>("date"), nmea::field<&rxgat::time>("time", nmea::max_places(0)),
      nmea::field<&rxgat::team_id>("team_id", nmea::exact_length(5)),
      nmea::field<&rxgat::entrance_gate>("entrance_gate"),
      nmea::field<&rxgat::exit_gate>("exit_gate"),
      nmea::field<&rxgat::light_buoy_active>("light_buoy_active"),
      nmea::field<&rxgat::light_pattern>("light_pattern"));

  friend constexpr bool operator==(const rxgat&, const rxgat&) noexcept = default;
};

/// Scan the Code: the light bar's pattern. The TD echoes it back.
///   $RXCOD,101218,161229,AUVSI,RGB*49
struct rxcod {
  nmea::date date;                                     // 1 [HST date] ddmmyy
  nmea::time_of_day time;                              // 2 [HST time] hhmmss
  nmea::text<5> team_id;                               // 3 [Team ID]
  std::optional<robotx::light_pattern> light_pattern;  // 4 [Light Pattern] R/B/G x 3

  static constexpr auto nmea = nmea::sentence<"RXCOD">(
      nmea::field<&rxcod::date>("date"), nmea::field<&rxcod::time>("time", nmea::max_places(0)),
      nmea::field<&rxcod::team_id>("team_id", nmea::exact_length(5)),
      nmea::field<&rxcod::light_pattern>("light_pattern"));

  friend constexpr bool operator==(const rxcod&, const rxcod&) noexcept = default;
};

/// Identify Symbols and Dock (RXDOK) and Detect and Deliver (RXDEL): colour and shape of the
/// bay the AMS will dock in, or of the face it will deliver into. Echoed.
///   $RXDOK,101218,161229,AUVSI,R,TRIAN*28
template <seawire::detail::fixed_string Address, class Shape>
struct shape_report {
  nmea::date date;                   // 1 [HST date] ddmmyy
  nmea::time_of_day time;            // 2 [HST time] hhmmss
  nmea::text<5> team_id;             // 3 [Team ID]
  std::optional<color> shape_color;  // 4 [Shape Color] R/B/G
  std::optional<Shape> shape;        // 5 [Shape] dock_shape or deliver_shape words

  static constexpr auto nmea =
      nmea::sentence<Address>(nmea::field<&shape_report::date>("date"),
                              nmea::field<&shape_report::time>("time", nmea::max_places(0)),
                              nmea::field<&shape_report::team_id>("team_id", nmea::exact_length(5)),
                              nmea::field<&shape_report::shape_color>("shape_color"),
                              nmea::field<&shape_report::shape>("shape"));

  friend constexpr bool operator==(const shape_report&, const shape_report&) noexcept = default;
};

/// RXDOK: the shape is CRUC/TRIAN/CIRCL (CRUCI accepted).
using rxdok = shape_report<"RXDOK", dock_shape>;
/// RXDEL: the shape is CRUCI/TRIAN/CIRCL (CRUC accepted).
using rxdel = shape_report<"RXDEL", deliver_shape>;

// ---------------------------------------------------------------------------------------------
// the set

/// Every report, for decoding whatever arrives on the judges' socket.
using reports = nmea::message_set<rxhrb, rxgat, rxcod, rxdok, rxdel>;

/// The five reports by kind; the per-type rate limit and the scheduler count by this.
enum class report_type : std::uint8_t { heartbeat, gates, scan_code, dock, deliver };
inline constexpr std::size_t report_type_count = 5;

/// Which report a message type is; defined only for the five reports.
template <class M>
struct report_traits;
template <>
struct report_traits<rxhrb> {
  static constexpr report_type type = report_type::heartbeat;
};
template <>
struct report_traits<rxgat> {
  static constexpr report_type type = report_type::gates;
};
template <>
struct report_traits<rxcod> {
  static constexpr report_type type = report_type::scan_code;
};
template <>
struct report_traits<rxdok> {
  static constexpr report_type type = report_type::dock;
};
template <>
struct report_traits<rxdel> {
  static constexpr report_type type = report_type::deliver;
};
template <class M>
inline constexpr report_type report_type_of = report_traits<M>::type;

/// "RXHRB", "RXGAT", ...
[[nodiscard]] constexpr std::string_view address(report_type t) noexcept {
  constexpr std::array<std::string_view, report_type_count> a = {
      rxhrb::nmea.address, rxgat::nmea.address, rxcod::nmea.address, rxdok::nmea.address,
      rxdel::nmea.address};
  const auto i = static_cast<std::size_t>(t);
  return i < a.size() ? a[i] : std::string_view{};
}

/// The report an address names, or nullopt.
[[nodiscard]] constexpr std::optional<report_type> report_type_for(std::string_view a) noexcept {
  for (std::size_t i = 0; i < report_type_count; ++i)
    if (address(static_cast<report_type>(i)) == a) return static_cast<report_type>(i);
  return std::nullopt;
}

// The role decoders are templates of nothing so that only a caller compiles them (nmea::lazy).
/// Decode one line into whichever report it is, under the judges' policy by default. A
/// well-formed sentence with another address gives unknown_sentence (not an error).
template <int N = 0>
[[nodiscard]] constexpr result<typename nmea::lazy<reports, N>::variant> decode_report(
    std::string_view line, const nmea::parse_policy& policy = judge_policy) noexcept {
  return nmea::lazy<reports, N>::decode(line, policy);
}

/// Decode one line and call `on_report(const M&)` for it (or `(const unknown_sentence&)`).
/// Returns the error, without calling the visitor, when the line does not decode.
template <class F>
constexpr result<bool> visit_report(std::string_view line, F&& on_report,
                                    const nmea::parse_policy& policy = judge_policy) {
  const result<nmea::sentence_view> s = nmea::parse(line, policy);
  if (!s) return nmea::detail::parse_failure<bool>(s);
  return reports::visit(s.value, policy, on_report);
}

}  // namespace seawire::robotx

SEAWIRE_COMPILED_ENCODER(seawire::robotx::rxhrb)
SEAWIRE_COMPILED_ENCODER(seawire::robotx::rxgat)
SEAWIRE_COMPILED_ENCODER(seawire::robotx::rxcod)
SEAWIRE_COMPILED_ENCODER(seawire::robotx::rxdok)
SEAWIRE_COMPILED_ENCODER(seawire::robotx::rxdel)
SEAWIRE_COMPILED_SET(seawire::robotx::reports)
