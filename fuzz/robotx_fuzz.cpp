// SPDX-License-Identifier: BSL-1.0
// RobotX 2018 reports (RXHRB, RXGAT, RXCOD, RXDOK, RXDEL), as sent and with the checksum made
// right, under the judges' policy, the liberal and the strict one.
// Properties: fuzz_common.hpp (check_sentence_input).
#include <cstddef>
#include <cstdint>

#include "fuzz_common.hpp"
#include "seawire/registry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  seawire::fuzz::check_roles(data, size, seawire::registry::robotx_reports);
  return 0;
}
