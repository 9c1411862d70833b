// SPDX-License-Identifier: BSL-1.0
// A field option that does not apply to its member's type must not compile. Each ctest case
// compiles this file with one CASE defined and expects the compiler's message; CASE ok must
// compile (so a failure is the option's, not a broken file).
#include <cstdint>
#include <optional>

#include "seawire/nmea/integer.hpp"
#include "seawire/nmea/message.hpp"

namespace n = seawire::nmea;

struct m {
  n::decimal speed;
  std::optional<n::decimal> heading;
  std::uint8_t count = 0;
  n::integer<std::int16_t> offset;
  n::text<8> name;
  n::latitude lat;
  bool flag = false;

#if defined(CASE_ok)
  static constexpr auto nmea = n::sentence<"XXMSG">(
      n::field<&m::speed>("speed", n::in_range(0, 10), n::precision(1), n::max_places(2)),
      n::field<&m::heading>("heading", n::may_be_absent),
      n::field<&m::count>("count", n::zero_pad(2)),
      n::field<&m::name>("name", n::code_chars, n::length_between(1, 8)),
      n::field<&m::lat>("lat", n::precision(5)), n::field<&m::flag>("flag"));
#elif defined(CASE_zero_pad_on_decimal)
  static constexpr auto nmea = n::sentence<"XXMSG">(n::field<&m::speed>("speed", n::zero_pad(2)));
#elif defined(CASE_zero_pad_on_signed)
  static constexpr auto nmea = n::sentence<"XXMSG">(n::field<&m::offset>("offset", n::zero_pad(3)));
#elif defined(CASE_may_be_absent_on_plain)
  static constexpr auto nmea = n::sentence<"XXMSG">(n::field<&m::speed>("speed", n::may_be_absent));
#elif defined(CASE_field_count_on_plain)
  static constexpr auto nmea =
      n::sentence<"XXMSG">(n::field<&m::speed>("speed", n::only_with_field_count(3)));
#elif defined(CASE_range_on_position)
  static constexpr auto nmea = n::sentence<"XXMSG">(n::field<&m::lat>("lat", n::in_range(0, 90)));
#elif defined(CASE_code_on_number)
  static constexpr auto nmea = n::sentence<"XXMSG">(n::field<&m::count>("count", n::code_chars));
#elif defined(CASE_precision_on_flag)
  static constexpr auto nmea = n::sentence<"XXMSG">(n::field<&m::flag>("flag", n::precision(1)));
#elif defined(CASE_places_on_text)
  static constexpr auto nmea = n::sentence<"XXMSG">(n::field<&m::name>("name", n::max_places(1)));
#endif
};

int main() { return m::nmea.fields.size == 0; }
