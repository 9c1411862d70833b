// SPDX-License-Identifier: BSL-1.0
#pragma once
// The one definition of what SEAWIRE_SEPARATE_COMPILATION leaves declared in the headers: the
// decoders of the library's message sets (which the role decoders call) and the encoders of its
// messages.
// Include this header in exactly one translation unit of a program built with
// SEAWIRE_SEPARATE_COMPILATION defined everywhere, or link the CMake target seawire::compiled,
// which does both.

#if !defined(SEAWIRE_SEPARATE_COMPILATION)
#error \
    "<seawire/impl/src.hpp> defines what SEAWIRE_SEPARATE_COMPILATION declares: define it for every translation unit (or link seawire::compiled)"
#endif

#include <cstddef>
#include <span>
#include <string_view>

#include "seawire/anello/gpsctrl.hpp"
#include "seawire/anello/inputs.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/registry.hpp"
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

// Each library message's encoder and each library set's decoder, as SEAWIRE_COMPILED_ENCODER and
// SEAWIRE_COMPILED_SET declared them.
#define SEAWIRE_DEFINE_ENCODER(M)                                                     \
  template seawire::result<std::size_t> seawire::nmea::detail::compiled_encode_to<M>( \
      const M&, std::span<char>) noexcept;
#define SEAWIRE_DEFINE_SET(Set)                                                                \
  template seawire::result<Set::variant> seawire::nmea::detail::compiled_set_decode<Set>(      \
      const seawire::nmea::sentence_view&, const seawire::nmea::parse_policy&) noexcept;       \
  template seawire::result<Set::variant> seawire::nmea::detail::compiled_set_decode_line<Set>( \
      std::string_view, const seawire::nmea::parse_policy&) noexcept;
SEAWIRE_DEFINE_ENCODER(seawire::standard::rmc)
SEAWIRE_DEFINE_ENCODER(seawire::standard::gga)
SEAWIRE_DEFINE_ENCODER(seawire::standard::rpm)
SEAWIRE_DEFINE_ENCODER(seawire::standard::rsa)
SEAWIRE_DEFINE_ENCODER(seawire::standard::vhw)
SEAWIRE_DEFINE_ENCODER(seawire::standard::vbw)
SEAWIRE_DEFINE_ENCODER(seawire::standard::vwr)
SEAWIRE_DEFINE_ENCODER(seawire::standard::hdt)
SEAWIRE_DEFINE_ENCODER(seawire::anello::papgpsctrl)
SEAWIRE_DEFINE_ENCODER(seawire::kingfisher::cpnvg)
SEAWIRE_DEFINE_ENCODER(seawire::kingfisher::cpnvr)
SEAWIRE_DEFINE_ENCODER(seawire::kingfisher::cprcm)
SEAWIRE_DEFINE_ENCODER(seawire::kingfisher::cprbs)
SEAWIRE_DEFINE_ENCODER(seawire::kingfisher::cpimu)
SEAWIRE_DEFINE_ENCODER(seawire::kingfisher::cpalt)
SEAWIRE_DEFINE_ENCODER(seawire::kingfisher::pydep)
SEAWIRE_DEFINE_ENCODER(seawire::kingfisher::pydev)
SEAWIRE_DEFINE_ENCODER(seawire::kingfisher::pydir)
SEAWIRE_DEFINE_ENCODER(seawire::kingfisher::pyclt)
SEAWIRE_DEFINE_ENCODER(seawire::sandshark::bfsht)
SEAWIRE_DEFINE_ENCODER(seawire::sandshark::bfver)
SEAWIRE_DEFINE_ENCODER(seawire::sandshark::bfnvg)
SEAWIRE_DEFINE_ENCODER(seawire::sandshark::bfnvr)
SEAWIRE_DEFINE_ENCODER(seawire::sandshark::bfmis)
SEAWIRE_DEFINE_ENCODER(seawire::sandshark::bfack)
SEAWIRE_DEFINE_ENCODER(seawire::sandshark::bfctl)
SEAWIRE_DEFINE_ENCODER(seawire::sandshark::bplog)
SEAWIRE_DEFINE_ENCODER(seawire::sandshark::bpsts)
SEAWIRE_DEFINE_ENCODER(seawire::sandshark::bprmb)
SEAWIRE_DEFINE_ENCODER(seawire::sandshark::bpabt)
SEAWIRE_DEFINE_ENCODER(seawire::sandshark::bpver)
SEAWIRE_DEFINE_ENCODER(seawire::robotx::rxhrb)
SEAWIRE_DEFINE_ENCODER(seawire::robotx::rxgat)
SEAWIRE_DEFINE_ENCODER(seawire::robotx::rxcod)
SEAWIRE_DEFINE_ENCODER(seawire::robotx::rxdok)
SEAWIRE_DEFINE_ENCODER(seawire::robotx::rxdel)
SEAWIRE_DEFINE_SET(seawire::anello::nmea_inputs)
SEAWIRE_DEFINE_SET(seawire::anello::nmea_outputs)
SEAWIRE_DEFINE_SET(seawire::kingfisher::from_vehicle)
SEAWIRE_DEFINE_SET(seawire::kingfisher::to_vehicle)
SEAWIRE_DEFINE_SET(seawire::sandshark::from_vehicle)
SEAWIRE_DEFINE_SET(seawire::sandshark::to_vehicle)
SEAWIRE_DEFINE_SET(seawire::robotx::reports)
SEAWIRE_DEFINE_SET(seawire::registry::standard_sentences)
#undef SEAWIRE_DEFINE_ENCODER
#undef SEAWIRE_DEFINE_SET
