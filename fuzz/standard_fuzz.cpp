// SPDX-License-Identifier: BSL-1.0
// The talker-agnostic NMEA 0183 sentences (RMC, GGA, RPM, RSA, VHW, VBW, VWR): any line, as sent
// and with its checksum made right, under the liberal, strict and ANELLO input policies.
// Properties: fuzz_common.hpp (check_sentence_input).
#include <cstddef>
#include <cstdint>

#include "fuzz_common.hpp"
#include "seawire/anello/inputs.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/rmc.hpp"
#include "seawire/standard/rpm.hpp"
#include "seawire/standard/rsa.hpp"
#include "seawire/standard/vbw.hpp"
#include "seawire/standard/vhw.hpp"
#include "seawire/standard/vwr.hpp"

namespace {
namespace standard = seawire::standard;
using standard_set =
    seawire::nmea::message_set<standard::rmc, standard::gga, standard::rpm, standard::rsa,
                               standard::vhw, standard::vbw, standard::vwr>;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  seawire::fuzz::check_sentence_input<standard_set>(data, size, {seawire::anello::input_policy});
  return 0;
}
