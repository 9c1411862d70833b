// SPDX-License-Identifier: BSL-1.0
// A 0xAB00-style table row that makes no sense is a compile error with the row's own message
// (describe_frame's bad_row names the fact).
#include <cstdint>
#include <limits>
#include <optional>
#include "seawire/detail/row_list.hpp"

#include "seawire/anello/frame.hpp"

namespace {
using namespace seawire::anello;
using namespace seawire::anello::frame_table;

struct raw {
  std::uint16_t heading;
  std::int16_t temp;
  std::uint8_t quality;
};
struct values {
  std::optional<double> heading_deg;
  std::optional<double> temp_c;
  std::optional<int> fix_quality;
};

// The ok case's quality row reaches 254, the last value below the wire type's maximum.
constexpr auto table =
    describe_frame(field<&raw::heading, &values::heading_deg>("heading_deg", in_range(0, 360)),
#if defined(CASE_not_a_fact)
                   field<&raw::temp, &values::temp_c>("temp_c", 10),
#elif defined(CASE_also_not_available_other_type)
                   field<&raw::temp, &values::temp_c>("temp_c", divisor(10),
                                                      also_not_available(-1)),
#elif defined(CASE_also_not_available_maximum)
                   field<&raw::temp, &values::temp_c>("temp_c", divisor(10),
                                                      also_not_available(std::int16_t{0x7FFF})),
#elif defined(CASE_empty_name)
                   field<&raw::temp, &values::temp_c>("", divisor(10)),
#elif defined(CASE_lo_above_hi)
                   field<&raw::temp, &values::temp_c>("temp_c", divisor(10), in_range(40, -40)),
#elif defined(CASE_divisor_not_power_of_ten)
                   field<&raw::temp, &values::temp_c>("temp_c", divisor(20)),
#elif defined(CASE_divisor_zero)
                   field<&raw::temp, &values::temp_c>("temp_c", divisor(0)),
#elif defined(CASE_divisor_negative)
                   field<&raw::temp, &values::temp_c>("temp_c", divisor(-10)),
#elif defined(CASE_range_past_wire_type)
                   // -4000.0 is -40000 tenths: not an int16.
                   field<&raw::temp, &values::temp_c>("temp_c", divisor(10), in_range(-4000, 40)),
#elif defined(CASE_range_overflows)
                   field<&raw::temp, &values::temp_c>(
                       "temp_c", divisor(10),
                       in_range(0, std::numeric_limits<std::int64_t>::max() / 2)),
#else
                   field<&raw::temp, &values::temp_c>("temp_c", divisor(10),
                                                      also_not_available(std::int16_t{-1})),
#endif
#if defined(CASE_range_at_not_available)
                   // 255 is the uint8's "not available": no sender can write it.
                   field<&raw::quality, &values::fix_quality>("fix_quality", in_range(0, 255)));
#elif defined(CASE_divisor_on_int)
                   field<&raw::quality, &values::fix_quality>("fix_quality", divisor(10)));
#else
                   field<&raw::quality, &values::fix_quality>("fix_quality", in_range(0, 254)));
#endif

// The ok case: offsets follow the header and the widths before.
static_assert(seawire::detail::row_at<0>(table).offset == header_size &&
              seawire::detail::row_at<1>(table).offset == 10 &&
              seawire::detail::row_at<2>(table).offset == 12);
static_assert(seawire::detail::row_at<1>(table).json_key == "temp_c" &&
              seawire::detail::row_at<1>(table).divisor == 10);
}  // namespace
