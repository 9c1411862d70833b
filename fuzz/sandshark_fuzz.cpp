// SPDX-License-Identifier: BSL-1.0
// Bluefin Sandshark SPI: every BF* and BP* sentence, as sent and with its checksum made right,
// under the from-vehicle and to-vehicle policies, the liberal and the strict one.
// Properties: fuzz_common.hpp (check_sentence_input).
#include <cstddef>
#include <cstdint>

#include "fuzz_common.hpp"
#include "seawire/registry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace registry = seawire::registry;
  seawire::fuzz::check_roles(data, size, registry::sandshark_from_vehicle,
                             registry::sandshark_to_vehicle);
  return 0;
}
