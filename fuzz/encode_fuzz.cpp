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
#include <utility>

#include "fuzz_common.hpp"
#include "seawire/anello/inputs.hpp"
#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/sandshark/messages.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/rmc.hpp"
#include "seawire/standard/rpm.hpp"
#include "seawire/standard/rsa.hpp"
#include "seawire/standard/vbw.hpp"
#include "seawire/standard/vhw.hpp"
#include "seawire/standard/vwr.hpp"

// The one value type a family declares outside nmea/fields.hpp; found by argument-dependent
// lookup from make_message.
namespace seawire::robotx {
inline void fill(fuzz::byte_source& src, light_pattern& p) {
  constexpr std::string_view letters = "RBGX";
  for (color& c : p.colors) c = static_cast<color>(letters[src.below(letters.size())]);
}
}  // namespace seawire::robotx

namespace {
namespace nmea = seawire::nmea;
namespace standard = seawire::standard;
using standard_set = nmea::message_set<standard::rmc, standard::gga, standard::rpm, standard::rsa,
                                       standard::vhw, standard::vbw, standard::vwr>;
using every_message =
    nmea::merge_sets<standard_set, seawire::kingfisher::from_vehicle,
                     seawire::kingfisher::to_vehicle, seawire::sandshark::from_vehicle,
                     seawire::sandshark::to_vehicle, seawire::robotx::reports,
                     seawire::anello::nmea_inputs, seawire::anello::nmea_outputs>::type;

template <class Variant, std::size_t... I>
void check_one_of(std::size_t which, seawire::fuzz::byte_source& src, std::index_sequence<I...>) {
  // Alternative 0 is unknown_sentence; messages are 1..size.
  (void)((which == I
              ? (seawire::fuzz::check_encoder<every_message,
                                              std::variant_alternative_t<I + 1, Variant>>(src),
                 true)
              : false) ||
         ...);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  seawire::fuzz::byte_source src(std::span<const std::uint8_t>(data, size));
  const std::size_t which = src.below(every_message::size);
  check_one_of<every_message::variant>(which, src, std::make_index_sequence<every_message::size>{});
  return 0;
}
