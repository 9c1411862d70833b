// SPDX-License-Identifier: BSL-1.0
// Every NMEA-style encoder, fed values the fuzzer chooses: the first byte picks the message type
// (any of every family), the rest fill its fields one by one over each C++ type's whole domain
// (out-of-range numbers, bad letters, unprintable text included). Property: encode refuses the
// value, or writes a sealed, printable sentence that the strict decoder reads back, through the
// dispatch of all families at once, to the same message type and value, and that encodes again
// to the same bytes (fuzz_common.hpp, check_encoder).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "fuzz_common.hpp"
#include "seawire/registry.hpp"

// The one value type a family declares outside nmea/fields.hpp; found by argument-dependent
// lookup from make_message.
namespace seawire::robotx {
inline void fill(fuzz::byte_source& src, light_pattern& p) {
  constexpr std::string_view letters = "RBGX";
  for (color& c : p.colors) c = static_cast<color>(letters[src.below(letters.size())]);
}
}  // namespace seawire::robotx

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using every_message = seawire::registry::sentences;
  seawire::fuzz::byte_source src(std::span<const std::uint8_t>(data, size));
  seawire::registry::visit_type<every_message>(src.below(every_message::size), [&](auto tag) {
    seawire::fuzz::check_encoder<every_message, typename decltype(tag)::type>(src);
  });
  return 0;
}
