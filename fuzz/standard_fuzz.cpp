// SPDX-License-Identifier: BSL-1.0
// The talker-agnostic NMEA 0183 sentences (registry::standard_sentences: RMC, GGA, RPM, RSA, VHW,
// VBW, VWR), any line, as sent and with its checksum made right, under the liberal, strict and
// ANELLO input policies (with the ANELLO inputs: the INS reads these sentences).
// Properties: fuzz_common.hpp (check_sentence_input).
#include <cstddef>
#include <cstdint>

#include "fuzz_common.hpp"
#include "seawire/registry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace registry = seawire::registry;
  seawire::fuzz::check_roles(data, size, registry::standard_nmea, registry::anello_inputs);
  return 0;
}
