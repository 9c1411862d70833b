// SPDX-License-Identifier: BSL-1.0
// Bluefin Sandshark SPI: every BF* and BP* sentence, as sent and with its checksum made right,
// under the from-vehicle and to-vehicle policies, the liberal and the strict one.
// Properties: fuzz_common.hpp (check_sentence_input).
#include <cstddef>
#include <cstdint>

#include "fuzz_common.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/sandshark/messages.hpp"

namespace {
namespace sandshark = seawire::sandshark;
using both_ways = seawire::nmea::merge_sets<sandshark::from_vehicle, sandshark::to_vehicle>::type;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  seawire::fuzz::check_sentence_input<both_ways>(
      data, size, {sandshark::from_vehicle_policy, sandshark::to_vehicle_policy});
  return 0;
}
