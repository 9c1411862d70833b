// SPDX-License-Identifier: BSL-1.0
// Clearpath Kingfisher: every CP* and PY* sentence (and the relayed RMC and GGA), as sent and
// with its checksum made right, under the payload and vehicle policies, the liberal and the
// strict one. Properties: fuzz_common.hpp (check_sentence_input).
#include <cstddef>
#include <cstdint>

#include "fuzz_common.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/registry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace kingfisher = seawire::kingfisher;
  namespace registry = seawire::registry;
  seawire::fuzz::check_roles(data, size, registry::kingfisher_from_vehicle,
                             registry::kingfisher_to_vehicle);
  // The role entry points are the same decoders; they must not disagree with the sets.
  const std::string_view line = seawire::fuzz::as_text(data, size);
  SEAWIRE_FUZZ_CHECK(kingfisher::decode_from_vehicle(line).ec ==
                         kingfisher::from_vehicle::decode(line, kingfisher::payload_policy()).ec,
                     line);
  SEAWIRE_FUZZ_CHECK(kingfisher::decode_to_vehicle(line).ec ==
                         kingfisher::to_vehicle::decode(line, kingfisher::vehicle_policy()).ec,
                     line);
  return 0;
}
