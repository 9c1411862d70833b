// SPDX-License-Identifier: BSL-1.0
// What a sentence declares besides its fields is checked where it is declared (or, for a "--"
// address without its talker member, where the message is first used). Each ctest case compiles
// this file with one CASE defined and expects the compiler's message; CASE ok must compile.
#include <cstdint>
#include <optional>
#include <type_traits>

#include "seawire/nmea/message.hpp"

namespace n = seawire::nmea;

struct m {
  n::talker_id talker = "GP";
  n::text<3> code;
  std::optional<n::decimal> a;
  std::optional<n::decimal> b;
  std::uint8_t wire_fields = 0;
  std::uint32_t blank_units = 0;
  int count = 0;

#if defined(CASE_ok)
  static constexpr auto nmea = n::sentence<"--XYZ">(n::field<&m::a>("a", n::may_be_absent),
                                                    n::field<&m::b>("b", n::may_be_absent))
                                   .talker_in<&m::talker>()
                                   .standard_forms<1, 2>()
                                   .wire_fields_in<&m::wire_fields>()
                                   .blank_units_in<&m::blank_units>()
                                   .buffer_size_at_least<1000>();
#elif defined(CASE_any_talker_without_talker_in)
  static constexpr auto nmea = n::sentence<"--XYZ">(n::field<&m::a>("a"));
#elif defined(CASE_talker_in_on_fixed_address)
  static constexpr auto nmea = n::sentence<"GPXYZ">(n::field<&m::a>("a")).talker_in<&m::talker>();
#elif defined(CASE_talker_in_not_talker_id)
  static constexpr auto nmea = n::sentence<"--XYZ">(n::field<&m::a>("a")).talker_in<&m::code>();
#elif defined(CASE_wire_fields_in_not_uint8)
  static constexpr auto nmea =
      n::sentence<"GPXYZ">(n::field<&m::a>("a", n::may_be_absent)).wire_fields_in<&m::count>();
#elif defined(CASE_blank_units_in_not_uint32)
  static constexpr auto nmea =
      n::sentence<"GPXYZ">(n::field<&m::a>("a", n::unit('M'))).blank_units_in<&m::wire_fields>();
#elif defined(CASE_standard_forms_not_increasing)
  static constexpr auto nmea =
      n::sentence<"GPXYZ">(n::field<&m::a>("a"), n::field<&m::b>("b")).standard_forms<2, 1>();
#endif
};

int main() {
  m msg;
  const auto r = n::decode<m>("$GPXYZ,1,2*5A\r\n");
#if defined(CASE_ok)
  static_assert(std::is_same_v<decltype(n::encode(msg)), n::sentence_buffer<1000>>);
  static_assert(n::keeps_wire_fields<m> && n::lists_field_counts<m> && n::keeps_blank_units<m>);
#endif
  return r.ok() ? 0 : static_cast<int>(n::encode(msg).size);
}
