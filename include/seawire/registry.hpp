// SPDX-License-Identifier: BSL-1.0
#pragma once
// Every message seawire declares, listed once: each role's sentences with its parse policy, all
// sentences in one set, the NMEA 2000 PGNs and the 0xAB00 frame. The programs, docs generators,
// fuzz targets and round-trip tests iterate these lists (for_each_type); a message declared but
// missing here fails registry_complete (docs/adding-a-message.md).

#include <cstddef>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "seawire/anello/frame.hpp"
#include "seawire/anello/inputs.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/sandshark/messages.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/hdt.hpp"
#include "seawire/standard/rmc.hpp"
#include "seawire/standard/rpm.hpp"
#include "seawire/standard/rsa.hpp"
#include "seawire/standard/vbw.hpp"
#include "seawire/standard/vhw.hpp"
#include "seawire/standard/vwr.hpp"

namespace seawire::registry {

/// A list of types, for the messages that are not sentences or PGNs (the 0xAB00 frame).
template <class... T>
struct type_list {
  static constexpr std::size_t size = sizeof...(T);
};

namespace detail {
template <class List>
struct types_of;
template <class... T>
struct types_of<type_list<T...>> {
  using type = type_list<T...>;
};
template <nmea::message_like... M>
struct types_of<nmea::message_set<M...>> {
  using type = type_list<M...>;
};
template <nmea2000::pgn_like... P>
struct types_of<nmea2000::pgn_list<P...>> {
  using type = type_list<P...>;
};

template <class... T, class Fn>
constexpr void each(type_list<T...>*, Fn& fn) {
  (fn(std::type_identity<T>{}), ...);
}
template <class... T, class Fn>
constexpr bool one(type_list<T...>*, std::size_t index, Fn& fn) {
  std::size_t i = 0;
  return ((i++ == index ? (fn(std::type_identity<T>{}), true) : false) || ...);
}
}  // namespace detail

/// The types of a message_set, a pgn_list or a type_list, as a type_list.
template <class List>
using types = typename detail::types_of<List>::type;

/// fn(std::type_identity<T>{}) for every type T of the list, in order.
template <class List, class Fn>
constexpr void for_each_type(Fn&& fn) {
  detail::each(static_cast<types<List>*>(nullptr), fn);
}

/// fn(std::type_identity<T>{}) for the type at `index` of the list; false (fn not called) when
/// the list is shorter.
template <class List, class Fn>
constexpr bool visit_type(std::size_t index, Fn&& fn) {
  return detail::one(static_cast<types<List>*>(nullptr), index, fn);
}

/// A set of sentences, the role that receives them and that role's parse policy.
template <class Set>
struct role {
  using set = Set;
  std::string_view title;  ///< who sends to whom ("Kingfisher: vehicle to payload")
  std::string_view about;  ///< one sentence a message of the set is introduced with
  nmea::parse_policy policy;
};

/// The standard NMEA 0183 sentences, from any talker.
using standard_sentences =
    nmea::message_set<standard::rmc, standard::gga, standard::rpm, standard::rsa, standard::vhw,
                      standard::vbw, standard::vwr, standard::hdt>;

inline constexpr role<standard_sentences> standard_nmea{
    "Standard NMEA 0183 sentences", "Standard NMEA 0183 sentence.", nmea::parse_policy{}};
inline constexpr role<kingfisher::from_vehicle> kingfisher_from_vehicle{
    "Kingfisher: vehicle to payload", "Kingfisher, from the vehicle.",
    kingfisher::payload_policy()};
inline constexpr role<kingfisher::to_vehicle> kingfisher_to_vehicle{
    "Kingfisher: payload to vehicle", "Kingfisher, a command to the vehicle.",
    kingfisher::vehicle_policy()};
inline constexpr role<sandshark::from_vehicle> sandshark_from_vehicle{
    "Sandshark: vehicle to payload", "Sandshark SPI, from the vehicle.",
    sandshark::from_vehicle_policy};
inline constexpr role<sandshark::to_vehicle> sandshark_to_vehicle{
    "Sandshark: payload to vehicle", "Sandshark SPI, from the payload.",
    sandshark::to_vehicle_policy};
inline constexpr role<robotx::reports> robotx_reports{"RobotX: team to judges",
                                                      "RobotX 2018 report.", robotx::judge_policy};
inline constexpr role<anello::nmea_inputs> anello_inputs{
    "ANELLO: inputs to the INS", "ANELLO Maritime INS input.", anello::input_policy};
inline constexpr role<anello::nmea_outputs> anello_outputs{
    "ANELLO: output of the INS", "ANELLO Maritime INS output.", anello::output_policy};

/// Every role. A sentence is read by the policy of the first role whose set has its address
/// (receiving_policy): the standard sentences first (a GPRMC may come from any receiver: the
/// liberal default), then each family's as its receiver reads it.
inline constexpr std::tuple roles{
    standard_nmea,        kingfisher_from_vehicle, kingfisher_to_vehicle, sandshark_from_vehicle,
    sandshark_to_vehicle, robotx_reports,          anello_inputs,         anello_outputs};

/// fn(role) for every role, in the order of `roles`.
template <class Fn>
constexpr void for_each_role(Fn&& fn) {
  std::apply([&](const auto&... r) { (fn(r), ...); }, roles);
}

namespace detail {
template <class Roles>
struct sets_of;
template <class... R>
struct sets_of<std::tuple<R...>> {
  using type = typename nmea::merge_sets<typename R::set...>::type;
};
}  // namespace detail

/// Every sentence of every role, once (RMC is in several).
using sentences = detail::sets_of<std::remove_cvref_t<decltype(roles)>>::type;

namespace detail {
template <class List, class... More>
struct append_pgns;
template <class... P, class... More>
struct append_pgns<nmea2000::pgn_list<P...>, More...> {
  using type = nmea2000::pgn_list<P..., More...>;
};
}  // namespace detail

/// Every NMEA 2000 PGN declared: decoded and encoded by name ("type":"PGN128259"). The ANELLO
/// INS's inputs, then the others.
using pgns = detail::append_pgns<
    nmea2000::ins_input_pgns, nmea2000::vessel_heading, nmea2000::rate_of_turn, nmea2000::attitude,
    nmea2000::magnetic_variation, nmea2000::water_depth, nmea2000::position_rapid,
    nmea2000::cog_sog_rapid, nmea2000::rudder, nmea2000::wind_data, nmea2000::temperature,
    nmea2000::humidity, nmea2000::actual_pressure, nmea2000::temperature_extended,
    nmea2000::battery_status, nmea2000::fluid_level, nmea2000::dc_detailed_status,
    nmea2000::cross_track_error, nmea2000::system_time, nmea2000::time_date, nmea2000::gnss_dops,
    nmea2000::navigation_data, nmea2000::direction_data, nmea2000::iso_request,
    nmea2000::iso_acknowledgement,
    // lookups whose names sit in the sentinel range or depend on another field
    nmea2000::iso_address_claim, nmea2000::heartbeat, nmea2000::heading_track_control,
    nmea2000::heave, nmea2000::transmission_parameters_dynamic, nmea2000::ais_class_a_position,
    nmea2000::ais_class_b_position,
    // repeating groups, 64-bit fields
    nmea2000::pgn_list_message, nmea2000::gnss_sats_in_view, nmea2000::gnss_position_data,
    // ---- strings ----
    nmea2000::product_information, nmea2000::configuration_information,
    nmea2000::ais_class_a_static_data, nmea2000::ais_class_b_static_data_a,
    nmea2000::ais_class_b_static_data_b,
    // a layout per function code (the function code picks the struct)
    nmea2000::group_function_request, nmea2000::group_function_command,
    nmea2000::group_function_acknowledge>::type;

/// The ANELLO 0xAB00 binary sensor frame.
using frames = type_list<anello::sensor_frame_raw>;

/// The policy of the first role whose set has this address; the default policy for an address
/// that no set has. (A template of nothing: the walk over the roles is compiled where it is
/// called.)
template <int = 0>
[[nodiscard]] constexpr nmea::parse_policy receiving_policy(std::string_view address) noexcept {
  nmea::parse_policy p;
  std::apply(
      [&](const auto&... r) {
        (void)((std::remove_cvref_t<decltype(r)>::set::knows(address) ? (p = r.policy, true)
                                                                      : false) ||
               ...);
      },
      roles);
  return p;
}

}  // namespace seawire::registry

SEAWIRE_COMPILED_SET(seawire::registry::standard_sentences)
