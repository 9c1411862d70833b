// SPDX-License-Identifier: BSL-1.0
#pragma once
// The one definition of what SEAWIRE_SEPARATE_COMPILATION leaves declared in the headers (the
// role decoders of every family). Include this header in exactly one translation unit of a
// program built with SEAWIRE_SEPARATE_COMPILATION defined everywhere, or link the CMake target
// seawire::compiled, which does both.

#if !defined(SEAWIRE_SEPARATE_COMPILATION)
#error \
    "<seawire/impl/src.hpp> defines what SEAWIRE_SEPARATE_COMPILATION declares: define it for every translation unit (or link seawire::compiled)"
#endif

#include <string_view>

#include "seawire/anello/inputs.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/sandshark/messages.hpp"

namespace seawire {

template result<kingfisher::from_vehicle::variant> kingfisher::decode_from_vehicle<0>(
    std::string_view, const nmea::parse_policy&) noexcept;
template result<kingfisher::to_vehicle::variant> kingfisher::decode_to_vehicle<0>(
    std::string_view, const nmea::parse_policy&) noexcept;

template result<sandshark::from_vehicle::variant> sandshark::decode_from_vehicle<0>(
    std::string_view) noexcept;
template result<sandshark::from_vehicle::variant> sandshark::decode_from_vehicle<0>(
    const nmea::sentence_view&) noexcept;
template result<sandshark::to_vehicle::variant> sandshark::decode_to_vehicle<0>(
    std::string_view) noexcept;
template result<sandshark::to_vehicle::variant> sandshark::decode_to_vehicle<0>(
    const nmea::sentence_view&) noexcept;

template result<anello::nmea_inputs::variant> anello::decode_input<0>(
    std::string_view, const nmea::parse_policy&) noexcept;
template result<anello::nmea_outputs::variant> anello::decode_output<0>(
    std::string_view, const nmea::parse_policy&) noexcept;

template result<robotx::reports::variant> robotx::decode_report<0>(
    std::string_view, const nmea::parse_policy&) noexcept;

}  // namespace seawire
