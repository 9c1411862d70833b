// SPDX-License-Identifier: BSL-1.0
// The ANELLO INS's NMEA side: its inputs (RPM, RSA, VHW, VBW, VWR, PAPGPSCTRL) and its RMC
// output, as sent and with the checksum made right, under the INS's policies, the liberal and
// the strict one. Properties: fuzz_common.hpp (check_sentence_input).
#include <cstddef>
#include <cstdint>

#include "fuzz_common.hpp"
#include "seawire/registry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace registry = seawire::registry;
  seawire::fuzz::check_roles(data, size, registry::anello_inputs, registry::anello_outputs);
  return 0;
}
