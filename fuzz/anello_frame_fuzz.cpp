// SPDX-License-Identifier: BSL-1.0
// The ANELLO 0xAB00 binary frame: decode_frame on the bytes as sent, and again with the header
// made right and the CRC fixed up (so the payload reaches the field table); build_frame on
// values built from the same bytes.
// Properties:
//  - decode_frame's errc and column are the ones its contract gives for these bytes, checked
//    in its order (id, length, size, CRC) by an independent reading of the header;
//  - a decoded frame encodes back to the same 56 bytes (bit-exact), whatever the payload;
//  - to_values/accessors/for_each_field agree, and a frame that validates is rebuilt exactly
//    by build_frame(to_values(frame)); one that does not is refused by build_frame too;
//  - build_frame either refuses the first field (in table order) that cannot be sent, or gives
//    a frame that validates, whose values are the inputs to within half a wire step, and that
//    survives encode -> decode unchanged.
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>

#include "fuzz_common.hpp"
#include "seawire/anello/frame.hpp"
#include "seawire/detail/crc32.hpp"

namespace seawire::fuzz {
namespace {

// The errc and column decode_frame must give, read straight from the contract.
std::pair<errc, std::size_t> expected_error(std::span<const std::uint8_t> b) {
  constexpr std::array<std::uint8_t, 4> header = {0xAB, 0x00, 0x00, 0x30};
  for (std::size_t i = 0; i < header.size() && i < b.size(); ++i) {
    if (b[i] != header[i])
      return i < 2 ? std::pair{errc::bad_frame_id, 0} : std::pair{errc::bad_length, 2};
  }
  if (b.size() < 56) return {errc::truncated, b.size()};
  const std::uint32_t sent = (std::uint32_t{b[4]} << 24U) | (std::uint32_t{b[5]} << 16U) |
                             (std::uint32_t{b[6]} << 8U) | std::uint32_t{b[7]};
  if (sent != seawire::crc32(b.subspan(8, 48))) return {errc::crc_mismatch, 4};
  return {errc::ok, 0};
}

void check_decode(std::span<const std::uint8_t> bytes) {
  const seawire::result<anello::sensor_frame_raw> r = anello::decode_frame(bytes);
  const auto [ec, column] = expected_error(bytes);
  SEAWIRE_FUZZ_CHECK(r.ec == ec && (ec == errc::ok || r.column == column),
                     "decode_frame broke its contract", hex_of(bytes), name(r.ec), name(ec));
  if (!r) {
    SEAWIRE_FUZZ_CHECK(r.value == anello::sensor_frame_raw{}, "a failed decode left values");
    return;
  }
  const anello::frame_bytes again = anello::encode_frame(r.value);
  SEAWIRE_FUZZ_CHECK(std::equal(again.begin(), again.end(), bytes.begin()),
                     "decode -> encode is not bit-exact", hex_of(bytes));

  const anello::sensor_values values = anello::to_values(r.value);
  // Accessors and for_each_field read the same table.
  SEAWIRE_FUZZ_CHECK(values.heading_deg == r.value.heading_deg() &&
                         values.gps_time == r.value.gps_time() &&
                         values.fix_quality == r.value.fix_quality() &&
                         values.air_temp_c == r.value.air_temp_c() &&
                         values.pressure_hpa == r.value.pressure_hpa(),
                     hex_of(bytes));
  std::size_t fields = 0;
  anello::for_each_field(r.value, [&](std::string_view field_name, const auto&) {
    SEAWIRE_FUZZ_CHECK(!field_name.empty());
    ++fields;
  });
  SEAWIRE_FUZZ_CHECK(fields == anello::sensor_field_count);

  // A GPS time past what time_ms holds (year 292 million) reads as not available, documented:
  // to_values cannot carry it, so the rebuild is judged against the frame as to_values sees it.
  anello::sensor_frame_raw as_read = r.value;
  if (!values.gps_time) as_read.gps_time_ms = anello::sensor_frame_raw{}.gps_time_ms;
  const seawire::result<anello::sensor_frame_raw> valid = anello::validate(as_read);
  const seawire::result<anello::sensor_frame_raw> rebuilt = anello::build_frame(values);
  if (valid) {
    // The same frame, except that a "not available" written another way than the type's
    // maximum (air temperature 0xFFFF) comes back as the maximum.
    SEAWIRE_FUZZ_CHECK(rebuilt.ok(), "build_frame refused the values of a valid frame",
                       hex_of(bytes), name(rebuilt.ec), number(rebuilt.field));
    SEAWIRE_FUZZ_CHECK(anello::to_values(rebuilt.value) == values, hex_of(bytes));
    anello::detail::visit_sensor_fields([&](std::uint16_t n, const auto& field) {
      using field_type = std::remove_cvref_t<decltype(field)>;
      const auto was = as_read.*field_type::raw_member;
      const auto now = rebuilt.value.*field_type::raw_member;
      SEAWIRE_FUZZ_CHECK(was == now || (field.not_available(was) && field.not_available(now)),
                         "build_frame(to_values(f)) != f for a valid frame", hex_of(bytes),
                         number(n));
      return true;
    });
  } else {
    SEAWIRE_FUZZ_CHECK(valid.field >= 1 && valid.field <= anello::sensor_field_count &&
                           (valid.ec == errc::out_of_range || valid.ec == errc::value_too_large),
                       hex_of(bytes), name(valid.ec));
    SEAWIRE_FUZZ_CHECK(!rebuilt.ok() && rebuilt.field == valid.field && rebuilt.ec == valid.ec,
                       "build_frame sends a value validate refuses", hex_of(bytes),
                       name(rebuilt.ec), number(rebuilt.field), number(valid.field));
  }
}

// A double for a field: mostly values a sender has, sometimes the awkward ones.
double make_double(byte_source& src, std::int64_t divisor) {
  switch (src.byte() % 8) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1:
      return src.coin() ? std::numeric_limits<double>::infinity()
                        : -std::numeric_limits<double>::infinity();
    case 2: {  // any bit pattern
      const auto bits = src.integer<std::uint64_t>();
      double d = 0;
      std::memcpy(&d, &bits, sizeof d);
      return d;
    }
    case 3: return static_cast<double>(src.integer<std::int64_t>());
    default:  // a wire step count, maybe with half a step more (the rounding edge)
      return (static_cast<double>(src.integer<std::int32_t>()) + (src.coin() ? 0.5 : 0.0)) /
             static_cast<double>(divisor);
  }
}

// Fills sensor_values from the bytes, field by field over the frame's own table.
anello::sensor_values make_values(byte_source& src) {
  anello::sensor_values v;
  anello::sensor_fields.apply([&](const auto&... field) {
    const auto one = [&](const auto& f) {
      using field_type = std::remove_cvref_t<decltype(f)>;
      using value_type = typename field_type::value_type;
      auto& member = v.*field_type::value_member;
      if (src.coin()) return;  // not available
      if constexpr (std::is_same_v<value_type, double>) {
        member = make_double(src, f.divisor);
      } else if constexpr (std::is_same_v<value_type, anello::time_ms>) {
        member = anello::time_ms{anello::time_ms::duration{src.integer<std::int64_t>()}};
      } else {
        member = static_cast<value_type>(src.integer<std::int16_t>());
      }
    };
    (one(field), ...);
  });
  return v;
}

void check_build(byte_source& src) {
  const anello::sensor_values values = make_values(src);
  const seawire::result<anello::sensor_frame_raw> built = anello::build_frame(values);
  if (!built) {
    SEAWIRE_FUZZ_CHECK(built.field >= 1 && built.field <= anello::sensor_field_count,
                       number(built.field));
    // The first refusal in table order: without that field the rest goes further.
    anello::sensor_values without = values;
    std::uint16_t number_of_field = 0;
    anello::sensor_fields.apply([&](const auto&... field) {
      const auto one = [&](const auto& f) {
        using field_type = std::remove_cvref_t<decltype(f)>;
        if (++number_of_field == built.field) (without.*field_type::value_member).reset();
      };
      (one(field), ...);
    });
    const seawire::result<anello::sensor_frame_raw> further = anello::build_frame(without);
    SEAWIRE_FUZZ_CHECK(further.ok() || further.field > built.field,
                       "build_frame did not refuse the first bad field", number(built.field),
                       number(further.field));
    return;
  }
  const anello::sensor_frame_raw& frame = built.value;
  SEAWIRE_FUZZ_CHECK(anello::validate(frame).ok(), "build_frame made a frame validate refuses");
  const anello::frame_bytes bytes = anello::encode_frame(frame);
  const seawire::result<anello::sensor_frame_raw> back = anello::decode_frame(bytes);
  SEAWIRE_FUZZ_CHECK(back.ok() && back.value == frame, "encode -> decode changed a built frame");
  const anello::sensor_values read = anello::to_values(frame);
  anello::sensor_fields.apply([&](const auto&... field) {
    const auto one = [&](const auto& f) {
      using field_type = std::remove_cvref_t<decltype(f)>;
      using value_type = typename field_type::value_type;
      const auto& in = values.*field_type::value_member;
      const auto& out = read.*field_type::value_member;
      SEAWIRE_FUZZ_CHECK(in.has_value() == out.has_value(), "availability changed", f.name);
      if (!in) return;
      if constexpr (std::is_same_v<value_type, double>) {
        const double step = 1.0 / static_cast<double>(f.divisor);
        SEAWIRE_FUZZ_CHECK(std::fabs(*in - *out) <= step / 2 * (1 + 1e-9) + 1e-9 * std::fabs(*in),
                           "a value moved more than half a wire step", f.name);
      } else {
        SEAWIRE_FUZZ_CHECK(*in == *out, "a value changed", f.name);
      }
    };
    (one(field), ...);
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> input(data, size);
  check_decode(input);

  // The same bytes with a right header and CRC, so the payload is what gets exercised.
  std::array<std::uint8_t, 56> fixed{};
  std::copy_n(input.begin(), std::min(size, fixed.size()), fixed.begin());
  fixed[0] = 0xAB;
  fixed[1] = 0x00;
  fixed[2] = 0x00;
  fixed[3] = 0x30;
  fix_frame_crc(fixed);
  check_decode(fixed);

  byte_source src(input);
  check_build(src);
  return 0;
}

}  // namespace seawire::fuzz
