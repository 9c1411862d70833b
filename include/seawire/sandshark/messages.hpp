// SPDX-License-Identifier: BSL-1.0
#pragma once
// Bluefin Sandshark Standard Payload Interface (SPI): BF* from the vehicle (the BAM), BP* from
// the payload, one NMEA-style sentence per line over TCP port 29500.
//
// Receive liberally (SPI 4.2): unknown addresses are unknown_sentence, extra trailing fields are
// ignored, every BP* field after the timestamp may be blank. The vehicle always sends a
// checksum, so from_vehicle_policy requires one; the payload may omit it, so to_vehicle_policy
// accepts a missing checksum but never a wrong one. Encoding follows the spec strictly.
//
// Field numbers below count as the spec does: 1 is the first field after the address.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>

#include "seawire/bluefin/navigation.hpp"
#include "seawire/detail/enum_names.hpp"
#include "seawire/detail/fixed_string.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"

namespace seawire::sandshark {

// ---------------------------------------------------------------------------------------------
// from the vehicle: commands (SPI 5), always sent

/// BFSHT: the payload loses power in one minute or more; clean up now.
///   $BFSHT,081025.987*hh
struct bfsht {
  nmea::time_of_day timestamp;  // 1 [hhmmss.ss] Timestamp

  friend constexpr bool operator==(const bfsht&, const bfsht&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<"BFSHT">(nmea::field<&bfsht::timestamp>("timestamp"));
};

/// BFVER and BPVER: the SPI version the sender speaks.
///   $BFVER,081025.987,1.0*hh
template <seawire::detail::fixed_string Address>
struct version_report {
  nmea::time_of_day timestamp;  // 1 [hhmmss.ss] Timestamp
  nmea::text<32> version;       // 2 [v-v] Version number

  friend constexpr bool operator==(const version_report&, const version_report&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<Address>(
      nmea::field<&version_report::timestamp>("timestamp"),
      nmea::field<&version_report::version>("version", nmea::length_between(1, 32)));
};

/// BFVER: the SPI version the vehicle speaks; sent at the start of communications.
using bfver = version_report<"BFVER">;

// ---------------------------------------------------------------------------------------------
// from the vehicle: status (SPI 6), sent only after BPLOG asks for them

/// Vehicles print their navigation numbers with a C float format, which writes "nan" for a value
/// the filter does not have: read as not available, with the rest of the sentence kept.
/// Positions keep NMEA's padded DDMM form (the SPI's own examples are padded).
inline constexpr nmea::number_forms vehicle_numbers{.nan_as_blank = true};

/// BFNVG: navigation update (the layout Kingfisher's CPNVG copies; the SPI's format line is
/// garbled, the example line is right).
using bfnvg = bluefin::nav_update<"BFNVG", vehicle_numbers>;
/// BFNVR: velocity and rate update.
using bfnvr = bluefin::velocity_update<"BFNVR", vehicle_numbers>;

/// Mission states the spec names for BFMIS field 3; the list is open ("include, but are not
/// limited to"), so the wire keeps the text and this is only an interpretation of it.
enum class mission_state : std::uint8_t {
  unknown,  ///< a status the spec does not name (or a blank one)
  offline,
  waiting,
  invalid_dive_file,
  invalid_wrapup_file,
  ready,
  running,  ///< "Running", possibly followed by the mission's log directory
  wrapping_up,
  aborting,
  completed,
  aborted,
  stopped,
};

/// BFMIS: mission status, sent when it changes.
///   $BFMIS,081025.987,dive1.xml,Running /var/log/mission_12,*hh
struct bfmis {
  nmea::time_of_day timestamp;  // 1 [hhmmss.ss] Timestamp
  // Variable-length text (SPI table 1): room for what real vehicles send, log paths included.
  nmea::text<256>
      dive_file;            // 2 [d--d] current dive file; blank when no mission plan asked for one
  nmea::text<256> status;   // 3 [t--t] Offline, Waiting, Ready, Running [log dir], Aborted ...
  nmea::text<512> details;  // 4 [a--a] human-readable details (abort reasons); not for parsing

  /// The status text starts with "Running" (it may carry the log directory after it).
  [[nodiscard]] constexpr bool running() const noexcept {
    return status.view().starts_with("Running");
  }
  /// What follows "Running" with leading blanks and ':' removed; empty when not running.
  [[nodiscard]] constexpr std::string_view log_directory() const noexcept {
    if (!running()) return {};
    std::string_view rest = status.view().substr(7);
    while (!rest.empty() && (rest.front() == ' ' || rest.front() == ':')) rest.remove_prefix(1);
    return rest;
  }
  /// The status as one of the states the spec names, or unknown.
  [[nodiscard]] constexpr mission_state state() const noexcept {
    if (running()) return mission_state::running;
    // Indexed by mission_state; unknown names no text, running is the prefix above.
    constexpr std::array<std::string_view, 12> names{
        "",        "Offline", "Waiting",    "Invalid Dive File", "Invalid Wrapup File",
        "Ready",   "",        "WrappingUp", "Aborting",          "Completed",
        "Aborted", "Stopped"};
    static_assert(static_cast<std::size_t>(mission_state::stopped) + 1 == names.size() &&
                  names[static_cast<std::size_t>(mission_state::wrapping_up)] == "WrappingUp");
    const std::optional<std::size_t> i = seawire::detail::index_of_name(names, status.view());
    return i ? static_cast<mission_state>(*i) : mission_state::unknown;
  }

  friend constexpr bool operator==(const bfmis&, const bfmis&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<"BFMIS">(
      nmea::field<&bfmis::timestamp>("timestamp"), nmea::field<&bfmis::dive_file>("dive_file"),
      nmea::field<&bfmis::status>("status"), nmea::field<&bfmis::details>("details"));
};

/// BFACK field 5: what became of the acknowledged command.
enum class ack_status : char {
  invalid = '0',  ///< unknown message, or improper parameters
  failed = '1',   ///< recognised, but processing failed
  ok = '2',       ///< processed successfully
  pending = '3',  ///< processing started; the final ack follows within 2 s
};

/// BFACK: acknowledgement of a payload message (only after BPLOG,ACK,ON).
///   $BFACK,081025.990,RMB,081025.950,,2,0,,*1E     the spec's form: 8 fields, field 8 empty
///   $BFACK,081025.990,RMB,081025.950,,2,0,*32      Goby's: 7 fields, no field 8
///   $BFACK,081025.990,RMB,081025.950,,2,0*1E       also seen: no description at all
///
/// Fields 7 and 8 may each be absent. Text keeps blank (empty text) apart from absent
/// (nullopt), so each form is written back as it came; a new bfack has the spec's form.
struct bfack {
  nmea::time_of_day timestamp;  // 1 [hhmmss.ss] Timestamp
  nmea::text<16> command;       // 2 [c-c] command acknowledged, by 3-letter id ("RMB") or address
  std::optional<nmea::time_of_day> command_timestamp;  // 3 [hhmmss.ss] the command's own field 1;
                                                       //   blank for commands without one (BPLOG)
  // 4 [iiii] payload-assigned id of a new behaviour
  std::optional<nmea::integer<std::int32_t>> behavior_id;
  ack_status status = ack_status::ok;                         // 5 [s] Acknowledgement Status Code
  std::optional<nmea::integer<std::int32_t>> future_use = 0;  // 6 [c] always 0 in this revision
  std::optional<nmea::text<256>> description =
      nmea::text<256>{};  // 7 [m-m] details, for people only
  std::optional<nmea::text<128>> trailing =
      nmea::text<128>{};  // 8 the spec's final field: empty in
                          //   this revision, kept if not

  /// Whether this acknowledges `address` ("BPRMB"): the vehicle names commands by their
  /// 3-letter id ("RMB"); the full address is accepted too.
  [[nodiscard]] constexpr bool names(std::string_view address) const noexcept {
    const std::string_view c = command.view();
    return c == address || (address.size() == 5 && c == address.substr(2));
  }

  friend constexpr bool operator==(const bfack&, const bfack&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<"BFACK">(
      nmea::field<&bfack::timestamp>("timestamp"),
      nmea::field<&bfack::command>("command", nmea::length_between(1, 16)),
      nmea::field<&bfack::command_timestamp>("command_timestamp"),
      nmea::field<&bfack::behavior_id>("behavior_id"), nmea::field<&bfack::status>("status"),
      nmea::field<&bfack::future_use>("future_use"),
      nmea::field<&bfack::description>("description", nmea::may_be_absent),
      nmea::field<&bfack::trailing>("trailing", nmea::may_be_absent));
};

/// BFCTL: backseat control handed over (1) or taken back (0). The SPI prints its format line
/// with the BFVER address by mistake.
///   $BFCTL,081025.987,1*78
struct bfctl {
  nmea::time_of_day timestamp;  // 1 [hhmmss.ss] Timestamp
  bool control = false;         // 2 [c] 1 = the payload (backseat) has control, 0 = it has not

  friend constexpr bool operator==(const bfctl&, const bfctl&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<"BFCTL">(nmea::field<&bfctl::timestamp>("timestamp"),
                                                       nmea::field<&bfctl::control>("control"));
};

// ---------------------------------------------------------------------------------------------
// to the vehicle (SPI 7)

/// BPLOG field 2.
enum class log_state : std::uint8_t { on, off };
constexpr std::array<std::string_view, 2> enum_words(log_state) noexcept { return {"ON", "OFF"}; }

/// BPLOG: turn one status message (or ALL of them) on or off for this payload. No timestamp.
/// ALL never includes ACK, which must be asked for by name.
///   $BPLOG,ACK,ON*1E
struct bplog {
  nmea::text<3> code;               // 1 [rrr] 3-letter message id (NVG, NVR, MIS, CTL, ACK) or ALL
  log_state state = log_state::on;  // 2 [a-a] ON or OFF

  [[nodiscard]] constexpr bool is_all() const noexcept { return code == "ALL"; }

  friend constexpr bool operator==(const bplog&, const bplog&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<"BPLOG">(
      nmea::field<&bplog::code>("code", nmea::exact_length(3), nmea::code_chars),
      nmea::field<&bplog::state>("state"));
};

/// BPSTS: payload status (the payload's heartbeat).
///   $BPSTS,231133.12,1,BWSI Autonomy OK*46
struct bpsts {
  nmea::time_of_day timestamp;  // 1 [hhmmss.ss] Timestamp
  bool all_ok = true;           // 2 [f] Status flag: 1 = all OK, 0 = failed
  nmea::text<128> message;      // 3 [m--m] status text; spaces allowed ("Variable Text")

  friend constexpr bool operator==(const bpsts&, const bpsts&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<"BPSTS">(nmea::field<&bpsts::timestamp>("timestamp"),
                                                       nmea::field<&bpsts::all_ok>("all_ok"),
                                                       nmea::field<&bpsts::message>("message"));
};

/// BPRMB field 4: what field 3 holds.
enum class depth_mode : char { depth = '0', altitude = '1', pitch = '2', elevator = '3' };
/// BPRMB field 6: what field 5 holds.
enum class speed_mode : char { rpm = '0', meters_per_second = '1' };
/// BPRMB field 7: what field 2 holds.
enum class horizontal_mode : char { heading = '0', rudder = '1' };

/// BPRMB: modify the current behaviour. Blank fields leave that aspect as the mission has it.
/// Must be repeated at least every 5 s, or the vehicle takes control back. The meaning (and unit)
/// of fields 2, 3 and 5 comes from the mode fields, so no range is imposed on them here.
///   $BPRMB,231204.72,-15,,,750,0,1*54
struct bprmb {
  nmea::time_of_day timestamp;           // 1 [hhmmss.ss] Timestamp
  std::optional<nmea::decimal> heading;  // 2 [h.h] heading deg true, or rudder deg (field 7)
  std::optional<nmea::decimal> depth;    // 3 [d.d] depth/altitude m, pitch deg or elevator deg
  // 4 [dm] 0 depth, 1 altitude, 2 pitch, 3 elevator
  std::optional<sandshark::depth_mode> depth_mode;
  std::optional<nmea::decimal> speed;               // 5 [v.v] thruster RPM or m/s (field 6)
  std::optional<sandshark::speed_mode> speed_mode;  // 6 [vm] 0 RPM, 1 m/s
  std::optional<sandshark::horizontal_mode> horizontal_mode;  // 7 [hm] 0 heading, 1 rudder

  /// The usual request: a heading (degrees true, [0, 360)), a depth below the surface (metres,
  /// >= 0) and a speed (m/s, >= 0), each rounded to its field's precision (one place) and each
  /// left blank when not given (the mission keeps that aspect); the mode fields say heading,
  /// depth and m/s for the values given. NaN, infinities and values outside those ranges are
  /// refused naming the field (not_finite, out_of_range).
  [[nodiscard]] static constexpr result<bprmb> request(nmea::time_of_day stamp,
                                                       std::optional<double> heading_deg,
                                                       std::optional<double> depth_m,
                                                       std::optional<double> speed_mps) noexcept {
    result<bprmb> r;
    r.value.timestamp = stamp;
    // Each value rounded to its field's precision, then 0 <= value (< below, when given).
    const auto put = [&r](std::optional<nmea::decimal> bprmb::*member, std::uint16_t field,
                          std::optional<double> v, int places, std::optional<nmea::decimal> below) {
      if (!v || r.ec != errc::ok) return;
      const result<nmea::decimal> d = nmea::decimal::from_double(*v, static_cast<unsigned>(places));
      r.ec = d.ec;
      if (d && (d.value.compare(nmea::decimal{0}) < 0 || (below && d.value.compare(*below) >= 0)))
        r.ec = errc::out_of_range;
      if (r.ec != errc::ok) {
        r.field = field;
        return;
      }
      r.value.*member = d.value;
    };
    put(&bprmb::heading, 2, heading_deg, nmea::precision_of<&bprmb::heading>(), nmea::decimal{360});
    put(&bprmb::depth, 3, depth_m, nmea::precision_of<&bprmb::depth>(), std::nullopt);
    put(&bprmb::speed, 5, speed_mps, nmea::precision_of<&bprmb::speed>(), std::nullopt);
    if (r.ec != errc::ok) {
      r.value = bprmb{};
      return r;
    }
    if (heading_deg) r.value.horizontal_mode = sandshark::horizontal_mode::heading;
    if (depth_m) r.value.depth_mode = sandshark::depth_mode::depth;
    if (speed_mps) r.value.speed_mode = sandshark::speed_mode::meters_per_second;
    return r;
  }

  friend constexpr bool operator==(const bprmb&, const bprmb&) noexcept = default;

  static constexpr auto nmea =
      nmea::sentence<"BPRMB">(nmea::field<&bprmb::timestamp>("timestamp"),
                              nmea::field<&bprmb::heading>("heading", nmea::precision(1)),
                              nmea::field<&bprmb::depth>("depth", nmea::precision(1)),
                              nmea::field<&bprmb::depth_mode>("depth_mode"),
                              nmea::field<&bprmb::speed>("speed", nmea::precision(1)),
                              nmea::field<&bprmb::speed_mode>("speed_mode"),
                              nmea::field<&bprmb::horizontal_mode>("horizontal_mode"));
};

/// BPABT field 3.
enum class abort_reason : char { success = '0', with_errors = '1' };

/// BPABT: end the mission and run its wrap-up (e.g. a powered ascent).
///   $BPABT,081025.987,leak detected,1*hh
struct bpabt {
  nmea::time_of_day timestamp;  // 1 [hhmmss.ss] Timestamp (when sent)
  nmea::text<128> message;      // 2 [c--c] shown to the operator to explain the abort
  std::optional<abort_reason> reason = abort_reason::with_errors;  // 3 [a] blank = with errors

  /// Field 3 as the vehicle reads it: blank means "with errors", the spec's default.
  [[nodiscard]] constexpr abort_reason effective_reason() const noexcept {
    return reason.value_or(abort_reason::with_errors);
  }

  friend constexpr bool operator==(const bpabt&, const bpabt&) noexcept = default;

  static constexpr auto nmea = nmea::sentence<"BPABT">(nmea::field<&bpabt::timestamp>("timestamp"),
                                                       nmea::field<&bpabt::message>("message"),
                                                       nmea::field<&bpabt::reason>("reason"));
};

/// BPVER: the SPI version the payload speaks; the payload must send it first.
using bpver = version_report<"BPVER">;

// ---------------------------------------------------------------------------------------------
// roles

/// Everything the vehicle sends. Decode with from_vehicle_policy.
using from_vehicle = nmea::message_set<bfsht, bfver, bfnvg, bfnvr, bfmis, bfack, bfctl>;
/// Everything the payload sends. Decode with to_vehicle_policy.
using to_vehicle = nmea::message_set<bplog, bpsts, bprmb, bpabt, bpver>;

/// A payload receiving BF*: the vehicle always sends a checksum (SPI 4.2), so one is required.
/// Numbers may have spaces before the minus sign (SPI Table 1: "the first non-whitespace
/// character"), in both roles.
inline constexpr nmea::parse_policy from_vehicle_policy{.checksum = nmea::checksum_policy::required,
                                                        .spaced_numbers = true};
/// A vehicle receiving BP*: the payload may leave the checksum out; a wrong one never passes.
inline constexpr nmea::parse_policy to_vehicle_policy{
    .checksum = nmea::checksum_policy::verify_if_present, .spaced_numbers = true};

// The role decoders are templates of nothing so that only a caller compiles them (nmea::lazy).
/// Decode a line the vehicle sent; an address the set does not know is unknown_sentence.
template <int N = 0>
[[nodiscard]] constexpr result<typename nmea::lazy<from_vehicle, N>::variant> decode_from_vehicle(
    std::string_view line) noexcept {
  return nmea::lazy<from_vehicle, N>::decode(line, from_vehicle_policy);
}
template <int N = 0>
[[nodiscard]] constexpr result<typename nmea::lazy<from_vehicle, N>::variant> decode_from_vehicle(
    const nmea::sentence_view& s) noexcept {
  return nmea::lazy<from_vehicle, N>::decode(s, from_vehicle_policy);
}
/// Decode a line the payload sent.
template <int N = 0>
[[nodiscard]] constexpr result<typename nmea::lazy<to_vehicle, N>::variant> decode_to_vehicle(
    std::string_view line) noexcept {
  return nmea::lazy<to_vehicle, N>::decode(line, to_vehicle_policy);
}
template <int N = 0>
[[nodiscard]] constexpr result<typename nmea::lazy<to_vehicle, N>::variant> decode_to_vehicle(
    const nmea::sentence_view& s) noexcept {
  return nmea::lazy<to_vehicle, N>::decode(s, to_vehicle_policy);
}

/// The 3-letter id the SPI uses for a message in BPLOG and BFACK: "BFNVG" -> "NVG". Other
/// addresses are returned unchanged.
[[nodiscard]] constexpr std::string_view message_code(std::string_view address) noexcept {
  if (address.size() == 5 && (address.starts_with("BF") || address.starts_with("BP")))
    return address.substr(2);
  return address;
}

}  // namespace seawire::sandshark

SEAWIRE_COMPILED_ENCODER(seawire::sandshark::bfsht)
SEAWIRE_COMPILED_ENCODER(seawire::sandshark::bfver)
SEAWIRE_COMPILED_ENCODER(seawire::sandshark::bfnvg)
SEAWIRE_COMPILED_ENCODER(seawire::sandshark::bfnvr)
SEAWIRE_COMPILED_ENCODER(seawire::sandshark::bfmis)
SEAWIRE_COMPILED_ENCODER(seawire::sandshark::bfack)
SEAWIRE_COMPILED_ENCODER(seawire::sandshark::bfctl)
SEAWIRE_COMPILED_ENCODER(seawire::sandshark::bplog)
SEAWIRE_COMPILED_ENCODER(seawire::sandshark::bpsts)
SEAWIRE_COMPILED_ENCODER(seawire::sandshark::bprmb)
SEAWIRE_COMPILED_ENCODER(seawire::sandshark::bpabt)
SEAWIRE_COMPILED_ENCODER(seawire::sandshark::bpver)
SEAWIRE_COMPILED_SET(seawire::sandshark::from_vehicle)
SEAWIRE_COMPILED_SET(seawire::sandshark::to_vehicle)
