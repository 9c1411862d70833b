// SPDX-License-Identifier: BSL-1.0
// A 0xAB00-style table row that makes no sense is a compile error with the row's own message.
#include <cstdint>
#include <optional>
#include "seawire/detail/row_list.hpp"

#include "seawire/anello/frame.hpp"

namespace {
using namespace seawire::anello;
using namespace seawire::anello::frame_table;

struct raw {
  std::uint16_t heading;
  std::int16_t temp;
};
struct values {
  std::optional<double> heading_deg;
  std::optional<double> temp_c;
};

constexpr auto table =
    describe_frame(field<&raw::heading, &values::heading_deg>("heading_deg", in_range(0, 360)),
#if defined(CASE_not_a_fact)
                   field<&raw::temp, &values::temp_c>("temp_c", 10));
#elif defined(CASE_also_not_available_other_type)
                   field<&raw::temp, &values::temp_c>("temp_c", divisor(10),
                                                      also_not_available(-1)));
#else
                   field<&raw::temp, &values::temp_c>("temp_c", divisor(10),
                                                      also_not_available(std::int16_t{-1})));
#endif

// The ok case: offsets follow the header and the widths before.
static_assert(seawire::detail::row_at<0>(table).offset == header_size &&
              seawire::detail::row_at<1>(table).offset == 10);
static_assert(seawire::detail::row_at<1>(table).json_key == "temp_c" &&
              seawire::detail::row_at<1>(table).divisor == 10);
}  // namespace
