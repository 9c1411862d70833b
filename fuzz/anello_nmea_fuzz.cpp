// SPDX-License-Identifier: BSL-1.0
// The ANELLO INS's NMEA side: its inputs (RPM, RSA, VHW, VBW, VWR, PAPGPSCTRL) and its RMC
// output, as sent and with the checksum made right, under the INS's policies, the liberal and
// the strict one. Properties: fuzz_common.hpp (check_sentence_input).
#include <cstddef>
#include <cstdint>

#include "fuzz_common.hpp"
#include "seawire/anello/inputs.hpp"
#include "seawire/nmea/dispatch.hpp"

namespace {
namespace anello = seawire::anello;
using both_ways = seawire::nmea::merge_sets<anello::nmea_inputs, anello::nmea_outputs>::type;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  seawire::fuzz::check_sentence_input<both_ways>(data, size,
                                                 {anello::input_policy, anello::output_policy});
  return 0;
}
