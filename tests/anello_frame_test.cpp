// SPDX-License-Identifier: BSL-1.0
// The ANELLO 0xAB00 binary frame, its CRC-32 and the byte order helpers under it.

#include <array>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "seawire/anello/frame.hpp"
#include "seawire/detail/byte_order.hpp"
#include "seawire/detail/crc32.hpp"

#include "anello_seed.hpp"
#include "support.hpp"

namespace {

using namespace support;

using namespace seawire::anello;
using seawire::errc;

using support::infinity;
using support::not_a_number;
constexpr sensor_frame_raw seed_frame = decode_frame(seed).value;

constexpr time_ms utc(int y, unsigned mo, unsigned d, int h, int mi, int s, int ms) {
  using namespace std::chrono;
  return sys_days{year{y} / month{mo} / day{d}} + hours{h} + minutes{mi} + seconds{s} +
         milliseconds{ms};
}

}  // namespace

// --- compile time: the spec's example frame decodes, reads right, re-encodes to the same bytes
static_assert(seawire::crc32("123456789") == 0xCBF43926U);
static_assert(decode_frame(seed).ok());
static_assert(encode_frame(seed_frame) == seed);
static_assert(seed_frame.heading_deg() == 89.0);
static_assert(seed_frame.latitude_deg() == 32.828671);
static_assert(seed_frame.longitude_deg() == -117.229926);
static_assert(seed_frame.gps_time() == utc(2024, 7, 3, 15, 42, 58, 0));
static_assert(!seed_frame.air_temp_c().has_value());
static_assert(validate(seed_frame).ok());
static_assert(build_frame(sensor_values{}).value == sensor_frame_raw{});
static_assert([] {
  sensor_values v;
  v.heading_deg = 400;
  return build_frame(v).ec == errc::out_of_range;
}());

TEST_CASE("crc32 is zlib's CRC-32", "[anello][crc32]") {
  // Expected values from Python's zlib.crc32.
  CHECK(seawire::crc32("123456789") == 0xCBF43926U);
  CHECK(seawire::crc32("") == 0U);
  CHECK(seawire::crc32("The quick brown fox jumps over the lazy dog") == 0x414FA339U);
  std::array<std::uint8_t, 32> zeros{};
  CHECK(seawire::crc32(zeros) == 0x190A55ADU);
  std::array<std::uint8_t, 32> ones{};
  ones.fill(0xFF);
  CHECK(seawire::crc32(ones) == 0xFF6CAB0BU);
  std::array<std::uint8_t, 256> all{};
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::uint8_t>(i);
  CHECK(seawire::crc32(all) == 0x29058C73U);
  CHECK(seawire::crc32(std::span<const std::uint8_t>(seed).subspan(8)) == 0x8EF7F176U);

  SECTION("incremental over every split equals one pass") {
    const std::span<const std::uint8_t> bytes(all);
    for (std::size_t split = 0; split <= bytes.size(); ++split) {
      const auto first = seawire::crc32(bytes.first(split));
      CHECK(seawire::crc32_update(first, bytes.subspan(split)) == 0x29058C73U);
    }
    CHECK(seawire::crc32_update(seawire::crc32("1234"), "56789") == 0xCBF43926U);
  }
}

TEST_CASE("byte order helpers", "[anello][byte_order]") {
  using namespace seawire::detail;
  constexpr std::array<std::uint8_t, 8> b{0x01, 0x23, 0x45, 0x67, 0x89, 0xAB, 0xCD, 0xEF};
  static_assert(load_be<std::uint8_t>(b, 1) == 0x23);
  static_assert(load_be<std::uint16_t>(b) == 0x0123);
  static_assert(load_be<std::uint32_t>(b, 4) == 0x89ABCDEFU);
  static_assert(load_be<std::uint64_t>(b) == 0x0123456789ABCDEFU);
  static_assert(load_le<std::uint16_t>(b) == 0x2301);
  static_assert(load_le<std::uint64_t>(b) == 0xEFCDAB8967452301U);
  static_assert(load_be<std::int8_t>(b, 4) == -119);
  static_assert(load_be<std::int16_t>(b, 6) == -12817);
  static_assert(load_be<std::int32_t>(b, 4) == -1985229329);
  static_assert(load_be<std::int64_t>(b) == 0x0123456789ABCDEF);
  static_assert(load_le<std::int32_t>(b, 4) == -271733879);

  std::array<std::uint8_t, 10> out{};
  store_be(out, 1, std::int32_t{-2});
  CHECK(out == std::array<std::uint8_t, 10>{0, 0xFF, 0xFF, 0xFF, 0xFE, 0, 0, 0, 0, 0});
  store_le(out, 5, std::uint32_t{0x11223344});
  CHECK(out == std::array<std::uint8_t, 10>{0, 0xFF, 0xFF, 0xFF, 0xFE, 0x44, 0x33, 0x22, 0x11, 0});

  // Round trip of edge values in every type and both orders.
  const auto check_all = [&out]<class T>(T) {
    for (const T v : {std::numeric_limits<T>::min(), T{0}, T{1}, static_cast<T>(-1),
                      std::numeric_limits<T>::max()}) {
      store_be(out, 1, v);
      CHECK(load_be<T>(out, 1) == v);
      store_le(out, 1, v);
      CHECK(load_le<T>(out, 1) == v);
    }
  };
  check_all(std::uint8_t{});
  check_all(std::int8_t{});
  check_all(std::uint16_t{});
  check_all(std::int16_t{});
  check_all(std::uint32_t{});
  check_all(std::int32_t{});
  check_all(std::uint64_t{});
  check_all(std::int64_t{});
}

TEST_CASE("the spec's example frame decodes to the spec's values", "[anello][frame]") {
  const auto r = decode_frame(seed);
  REQUIRE(r.ok());
  const sensor_frame_raw& f = r.value;
  CHECK(f.heading_deg() == 89.0);
  CHECK(f.latitude_deg() == 32.828671);
  CHECK(f.longitude_deg() == -117.229926);
  CHECK(f.sog_mps() == 0.0);
  CHECK_FALSE(f.cog_deg().has_value());
  CHECK(f.gps_time() == utc(2024, 7, 3, 15, 42, 58, 0));
  CHECK(f.alt_msl_m() == 48.0);
  CHECK_FALSE(f.geoid_sep_m().has_value());
  CHECK_FALSE(f.hdop().has_value());
  CHECK_FALSE(f.fix_quality().has_value());
  CHECK(f.motor_pct() == 0.0);
  CHECK(f.rudder_pct() == 0.0);
  CHECK(f.stw_mps() == 0.0);
  CHECK(f.wind_speed_abs_mps() == 0.2);
  CHECK(f.wind_dir_abs_deg() == 108.0);
  CHECK(f.wind_speed_rel_mps() == 0.3);
  CHECK(f.wind_dir_rel_deg() == 90.0);
  CHECK_FALSE(f.air_temp_c().has_value());
  CHECK_FALSE(f.pressure_hpa().has_value());

  // The integers as sent: nothing is lost, including the spec's 0xFFFF air temperature.
  CHECK(f.heading == 89);
  CHECK(f.lat == 32828671);
  CHECK(f.lon == -117229926);
  CHECK(f.cog == 0xFFFF);
  CHECK(f.gps_time_ms == 1720021378000U);
  CHECK(f.alt_msl == 480);
  CHECK(f.geoid_sep == 0x7FFFFFFF);
  CHECK(f.hdop_tenths == 0xFF);
  CHECK(f.gga_quality == 0xFF);
  CHECK(f.air_temp == -1);
  CHECK(f.pressure == 0xFFFF);

  CHECK(encode_frame(f) == seed);
  std::array<std::uint8_t, 80> big{};
  big.fill(0x5A);
  const auto n = encode_frame(f, big);
  REQUIRE(n.ok());
  CHECK(n.value == frame_size);
  CHECK(std::equal(seed.begin(), seed.end(), big.begin()));
  for (std::size_t i = frame_size; i < big.size(); ++i) CHECK(big[i] == 0x5A);
}

TEST_CASE("tests/data holds the spec's example frame", "[anello][frame]") {
  CHECK(seed_hex_from_file() == seed_hex);
}

TEST_CASE("every single-bit error is detected", "[anello][frame]") {
  for (std::size_t byte = 0; byte < frame_size; ++byte) {
    for (unsigned bit = 0; bit < 8; ++bit) {
      frame_bytes bad = seed;
      bad[byte] = static_cast<std::uint8_t>(bad[byte] ^ (1U << bit));
      const auto r = decode_frame(bad);
      INFO("byte " << byte << " bit " << bit);
      if (byte < 2) {
        CHECK(r.ec == errc::bad_frame_id);
        CHECK(r.column == 0);
      } else if (byte < 4) {
        CHECK(r.ec == errc::bad_length);
        CHECK(r.column == 2);
      } else {
        CHECK(r.ec == errc::crc_mismatch);
        CHECK(r.column == 4);
      }
      CHECK(r.value == sensor_frame_raw{});
    }
  }
}

TEST_CASE("short input is truncated only while it can still become a frame", "[anello][frame]") {
  for (std::size_t n = 0; n < frame_size; ++n) {
    const auto r = decode_frame(std::span<const std::uint8_t>(seed).first(n));
    INFO("length " << n);
    CHECK(r.ec == errc::truncated);
    CHECK(r.column == n);
  }
  // A wrong byte is reported as soon as it is there, not after 56 bytes.
  CHECK(decode_frame(std::array<std::uint8_t, 1>{0x00}).ec == errc::bad_frame_id);
  CHECK(decode_frame(std::array<std::uint8_t, 2>{0xAB, 0xAB}).ec == errc::bad_frame_id);
  CHECK(decode_frame(std::array<std::uint8_t, 3>{0xAB, 0x00, 0x01}).ec == errc::bad_length);
  CHECK(decode_frame(std::array<std::uint8_t, 4>{0xAB, 0x00, 0x00, 0x31}).ec == errc::bad_length);

  // Bytes after the frame are none of its business.
  std::vector<std::uint8_t> longer(seed.begin(), seed.end());
  longer.insert(longer.end(), {0xAB, 0x00, 0x00});
  const auto r = decode_frame(longer);
  REQUIRE(r.ok());
  CHECK(r.value == seed_frame);
}

TEST_CASE("frame id and length field", "[anello][frame]") {
  for (const std::uint16_t length :
       std::array<std::uint16_t, 7>{0x0000, 0x0001, 0x002F, 0x0031, 0x0038, 0x3000, 0xFFFF}) {
    frame_bytes bad = seed;
    seawire::detail::store_be(bad, 2, length);
    INFO("length " << length);
    const auto r = decode_frame(bad);
    CHECK(r.ec == errc::bad_length);
    CHECK(r.column == 2);
    CHECK(r.field == 0);
  }
  for (const std::uint16_t id :
       std::array<std::uint16_t, 6>{0x0000, 0x00AB, 0xAB01, 0xAA00, 0xBA00, 0xFFFF}) {
    frame_bytes bad = seed;
    seawire::detail::store_be(bad, 0, id);
    INFO("id " << id);
    CHECK(decode_frame(bad).ec == errc::bad_frame_id);
  }
  CHECK(frame_id == 0xAB00);
  CHECK(payload_size == 48);
  CHECK(frame_size == 56);
}

TEST_CASE("encode_frame refuses a short buffer and writes nothing", "[anello][frame]") {
  for (std::size_t n = 0; n < frame_size; ++n) {
    std::vector<std::uint8_t> buffer(n, 0x5A);
    const auto r = encode_frame(seed_frame, buffer);
    CHECK(r.ec == errc::buffer_too_small);
    CHECK(r.value == 0);
    for (const auto b : buffer) CHECK(b == 0x5A);
  }
}

TEST_CASE("any payload survives decode -> encode bit for bit", "[anello][frame]") {
  // Also shows that the table covers each payload byte exactly once.
  prng rng{1};
  for (int round = 0; round < 2000; ++round) {
    frame_bytes bytes = seed;
    for (std::size_t i = header_size; i < frame_size; ++i) {
      bytes[i] = static_cast<std::uint8_t>(rng.next());
    }
    seal(bytes);
    const auto r = decode_frame(bytes);
    REQUIRE(r.ok());
    REQUIRE(encode_frame(r.value) == bytes);
  }
}

TEST_CASE("a default frame says nothing is available", "[anello][frame]") {
  const sensor_frame_raw none{};
  const auto bytes = encode_frame(none);
  // Unsigned fields are all FF; signed ones 7F FF..: lat, lon, alt, geoid, motor, rudder, air.
  for (const std::size_t signed_start : {10U, 14U, 30U, 34U, 40U, 41U, 52U}) {
    CHECK(bytes[signed_start] == 0x7F);
  }
  int available = 0;
  for_each_field(none, [&](std::string_view, const auto& value) { available += value ? 1 : 0; });
  CHECK(available == 0);
  CHECK(to_values(none) == sensor_values{});
  CHECK(validate(none).ok());
}

TEST_CASE("air temperature 0x7FFF and 0xFFFF are both not available", "[anello][frame]") {
  sensor_frame_raw f = seed_frame;
  for (const std::int16_t raw : {std::int16_t{0x7FFF}, std::int16_t{-1}}) {
    f.air_temp = raw;
    CHECK_FALSE(f.air_temp_c().has_value());
    CHECK(validate(f).ok());
  }
  f.air_temp = -2;
  CHECK(f.air_temp_c() == -0.2);
  f.air_temp = std::numeric_limits<std::int16_t>::min();
  CHECK(f.air_temp_c() == -3276.8);
  f.air_temp = 0x7FFE;
  CHECK(f.air_temp_c() == 3276.6);
  // Only air temperature: elsewhere -1 is a value.
  f.lat = -1;
  f.motor = -1;
  CHECK(f.latitude_deg() == -0.000001);
  CHECK(f.motor_pct() == -1.0);
}

TEST_CASE("gps time beyond what time_ms holds is not invented", "[anello][frame]") {
  sensor_frame_raw f{};
  f.gps_time_ms = 0;
  CHECK(f.gps_time() == time_ms{});
  f.gps_time_ms = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
  CHECK(f.gps_time().has_value());
  f.gps_time_ms = f.gps_time_ms + 1;
  CHECK_FALSE(f.gps_time().has_value());
  CHECK(validate(f).ec == errc::value_too_large);
  CHECK(validate(f).field == 6);
}

TEST_CASE("build_frame writes what the values say", "[anello][builder]") {
  sensor_values v;
  v.heading_deg = 89;
  v.latitude_deg = 32.828671;
  v.longitude_deg = -117.229926;
  v.sog_mps = 0;
  v.gps_time = utc(2024, 7, 3, 15, 42, 58, 0);
  v.alt_msl_m = 48;
  v.motor_pct = 0;
  v.rudder_pct = 0;
  v.stw_mps = 0;
  v.wind_speed_abs_mps = 0.2;
  v.wind_dir_abs_deg = 108;
  v.wind_speed_rel_mps = 0.3;
  v.wind_dir_rel_deg = 90;
  const auto r = build_frame(v);
  REQUIRE(r.ok());
  // The seed, except that "no air temperature" goes out as the spec's 0x7FFF.
  sensor_frame_raw expected = seed_frame;
  expected.air_temp = 0x7FFF;
  CHECK(r.value == expected);
  CHECK(to_values(r.value) == v);
  CHECK(to_values(seed_frame) == v);

  frame_bytes bytes = seed;
  bytes[52] = 0x7F;
  seal(bytes);
  CHECK(encode_frame(r.value) == bytes);
}

TEST_CASE("build_frame rounds to the wire resolution", "[anello][builder]") {
  const auto built = [](auto set) {
    sensor_values v;
    set(v);
    const auto r = build_frame(v);
    REQUIRE(r.ok());
    return r.value;
  };
  CHECK(built([](sensor_values& v) { v.heading_deg = 89.4; }).heading == 89);
  CHECK(built([](sensor_values& v) { v.heading_deg = 89.5; }).heading == 90);
  CHECK(built([](sensor_values& v) { v.heading_deg = 360.4; }).heading == 360);
  CHECK(built([](sensor_values& v) { v.heading_deg = -0.4; }).heading == 0);
  CHECK(built([](sensor_values& v) { v.sog_mps = 0.25; }).sog == 3);
  CHECK(built([](sensor_values& v) { v.sog_mps = 0.24999; }).sog == 2);
  CHECK(built([](sensor_values& v) { v.alt_msl_m = -0.05; }).alt_msl == -1);
  CHECK(built([](sensor_values& v) { v.alt_msl_m = -12.34; }).alt_msl == -123);
  CHECK(built([](sensor_values& v) { v.latitude_deg = -33.8688197; }).lat == -33868820);
  CHECK(built([](sensor_values& v) { v.longitude_deg = 151.2092955; }).lon == 151209296);
  CHECK(built([](sensor_values& v) { v.air_temp_c = -0.04; }).air_temp == 0);
  CHECK(built([](sensor_values& v) { v.air_temp_c = -0.15; }).air_temp == -2);
  CHECK(built([](sensor_values& v) { v.hdop = 0.94; }).hdop_tenths == 9);
  CHECK(built([](sensor_values& v) { v.hdop = 0.96; }).hdop_tenths == 10);
  CHECK(built([](sensor_values& v) { v.motor_pct = -99.5; }).motor == -100);
  CHECK(built([](sensor_values& v) { v.gps_time = time_ms{}; }).gps_time_ms == 0);
  CHECK(built([](sensor_values& v) { v.fix_quality = 4; }).gga_quality == 4);
}

TEST_CASE("build_frame accepts the edges of every range", "[anello][builder]") {
  struct edge {
    void (*set)(sensor_values&);
  };
  const edge edges[] = {
      {[](sensor_values& v) { v.heading_deg = 0; }},
      {[](sensor_values& v) { v.heading_deg = 360; }},
      {[](sensor_values& v) { v.latitude_deg = -90; }},
      {[](sensor_values& v) { v.latitude_deg = 90; }},
      {[](sensor_values& v) { v.longitude_deg = -180; }},
      {[](sensor_values& v) { v.longitude_deg = 180; }},
      {[](sensor_values& v) { v.sog_mps = 6553.4; }},
      {[](sensor_values& v) { v.cog_deg = 360; }},
      {[](sensor_values& v) { v.gps_time = utc(9999, 12, 31, 23, 59, 59, 999); }},
      {[](sensor_values& v) { v.alt_msl_m = -214748364.8; }},
      {[](sensor_values& v) { v.alt_msl_m = 214748364.6; }},
      {[](sensor_values& v) { v.geoid_sep_m = -214748364.8; }},
      {[](sensor_values& v) { v.hdop = 0; }},
      {[](sensor_values& v) { v.hdop = 25.4; }},
      {[](sensor_values& v) { v.fix_quality = 0; }},
      {[](sensor_values& v) { v.fix_quality = 8; }},
      {[](sensor_values& v) { v.motor_pct = -100; }},
      {[](sensor_values& v) { v.motor_pct = 100; }},
      {[](sensor_values& v) { v.rudder_pct = 100; }},
      {[](sensor_values& v) { v.stw_mps = 6553.4; }},
      {[](sensor_values& v) { v.wind_dir_abs_deg = 0; }},
      {[](sensor_values& v) { v.wind_dir_rel_deg = 360; }},
      {[](sensor_values& v) { v.air_temp_c = -3276.8; }},
      {[](sensor_values& v) { v.air_temp_c = 3276.6; }},
      {[](sensor_values& v) { v.air_temp_c = -0.2; }},
      {[](sensor_values& v) { v.air_temp_c = 0; }},
      {[](sensor_values& v) { v.pressure_hpa = 0; }},
      {[](sensor_values& v) { v.pressure_hpa = 65534; }},
  };
  int i = 0;
  for (const auto& e : edges) {
    sensor_values v;
    e.set(v);
    const auto r = build_frame(v);
    INFO("edge " << i++ << ": " << seawire::name(r.ec) << " field " << r.field);
    CHECK(r.ok());
    CHECK(validate(r.value).ok());
    CHECK(to_values(r.value) == v);
  }
}

TEST_CASE("build_frame refuses what a field cannot carry", "[anello][builder]") {
  using namespace std::chrono_literals;
  struct refusal {
    std::uint16_t field;
    errc ec;
    void (*set)(sensor_values&);
  };
  const refusal refusals[] = {
      {1, errc::out_of_range, [](sensor_values& v) { v.heading_deg = 400; }},
      {1, errc::out_of_range, [](sensor_values& v) { v.heading_deg = -1; }},
      {1, errc::out_of_range, [](sensor_values& v) { v.heading_deg = 360.5; }},
      {1, errc::out_of_range, [](sensor_values& v) { v.heading_deg = 1e300; }},
      {1, errc::not_finite, [](sensor_values& v) { v.heading_deg = not_a_number; }},
      {1, errc::not_finite, [](sensor_values& v) { v.heading_deg = infinity; }},
      {2, errc::out_of_range, [](sensor_values& v) { v.latitude_deg = 91; }},
      {2, errc::out_of_range, [](sensor_values& v) { v.latitude_deg = -90.0000006; }},
      {2, errc::not_finite, [](sensor_values& v) { v.latitude_deg = -not_a_number; }},
      {3, errc::out_of_range, [](sensor_values& v) { v.longitude_deg = 180.000001; }},
      {3, errc::out_of_range, [](sensor_values& v) { v.longitude_deg = -181; }},
      {4, errc::value_too_large, [](sensor_values& v) { v.sog_mps = 6553.5; }},
      {4, errc::value_too_large, [](sensor_values& v) { v.sog_mps = -0.1; }},
      {4, errc::value_too_large, [](sensor_values& v) { v.sog_mps = 1e20; }},
      {4, errc::not_finite, [](sensor_values& v) { v.sog_mps = -infinity; }},
      {5, errc::out_of_range, [](sensor_values& v) { v.cog_deg = 361; }},
      {5, errc::out_of_range, [](sensor_values& v) { v.cog_deg = -0.5; }},
      {6, errc::value_too_large, [](sensor_values& v) { v.gps_time = time_ms{} - 1ms; }},
      {6, errc::value_too_large,
       [](sensor_values& v) { v.gps_time = utc(1969, 12, 31, 0, 0, 0, 0); }},
      {7, errc::value_too_large, [](sensor_values& v) { v.alt_msl_m = 214748364.7; }},
      {7, errc::value_too_large, [](sensor_values& v) { v.alt_msl_m = 214748364.8; }},
      {7, errc::value_too_large, [](sensor_values& v) { v.alt_msl_m = -214748364.9; }},
      {8, errc::value_too_large, [](sensor_values& v) { v.geoid_sep_m = 1e12; }},
      {8, errc::not_finite, [](sensor_values& v) { v.geoid_sep_m = not_a_number; }},
      {9, errc::value_too_large, [](sensor_values& v) { v.hdop = 25.5; }},
      {9, errc::value_too_large, [](sensor_values& v) { v.hdop = -0.1; }},
      {10, errc::out_of_range, [](sensor_values& v) { v.fix_quality = 9; }},
      {10, errc::out_of_range, [](sensor_values& v) { v.fix_quality = -1; }},
      {10, errc::out_of_range, [](sensor_values& v) { v.fix_quality = 255; }},
      {11, errc::out_of_range, [](sensor_values& v) { v.motor_pct = 150; }},
      {11, errc::out_of_range, [](sensor_values& v) { v.motor_pct = -101; }},
      {11, errc::out_of_range, [](sensor_values& v) { v.motor_pct = 100.5; }},
      {11, errc::out_of_range, [](sensor_values& v) { v.motor_pct = 127; }},
      {12, errc::out_of_range, [](sensor_values& v) { v.rudder_pct = -150; }},
      {12, errc::not_finite, [](sensor_values& v) { v.rudder_pct = not_a_number; }},
      {13, errc::value_too_large, [](sensor_values& v) { v.stw_mps = 6553.5; }},
      {14, errc::value_too_large, [](sensor_values& v) { v.wind_speed_abs_mps = -1; }},
      {15, errc::out_of_range, [](sensor_values& v) { v.wind_dir_abs_deg = 720; }},
      {16, errc::value_too_large, [](sensor_values& v) { v.wind_speed_rel_mps = 7000; }},
      {17, errc::out_of_range, [](sensor_values& v) { v.wind_dir_rel_deg = -10; }},
      {18, errc::value_too_large, [](sensor_values& v) { v.air_temp_c = -0.1; }},
      {18, errc::value_too_large, [](sensor_values& v) { v.air_temp_c = -0.05; }},
      {18, errc::value_too_large, [](sensor_values& v) { v.air_temp_c = 3276.7; }},
      {18, errc::value_too_large, [](sensor_values& v) { v.air_temp_c = 3276.8; }},
      {18, errc::value_too_large, [](sensor_values& v) { v.air_temp_c = -3276.9; }},
      {19, errc::value_too_large, [](sensor_values& v) { v.pressure_hpa = 65535; }},
      {19, errc::value_too_large, [](sensor_values& v) { v.pressure_hpa = 70000; }},
      {19, errc::value_too_large, [](sensor_values& v) { v.pressure_hpa = -1; }},
  };
  // Field numbers follow the table; offsets come from it too.
  std::array<std::size_t, sensor_field_count + 1> offset_of{};
  sensor_fields.apply([&](const auto&... field) {
    std::size_t i = 1;
    ((offset_of[i++] = field.offset), ...);
  });
  int i = 0;
  for (const auto& bad : refusals) {
    sensor_values v;
    bad.set(v);
    const auto r = build_frame(v);
    INFO("refusal " << i++ << ": got " << seawire::name(r.ec) << " field " << r.field);
    CHECK(r.ec == bad.ec);
    CHECK(r.field == bad.field);
    CHECK(r.column == offset_of[bad.field]);
    CHECK(r.value == sensor_frame_raw{});
  }

  SECTION("the first bad field in table order is the one reported") {
    sensor_values v;
    v.pressure_hpa = -5;
    v.motor_pct = 101;
    v.latitude_deg = not_a_number;
    CHECK(build_frame(v).ec == errc::not_finite);
    CHECK(build_frame(v).field == 2);
    v.latitude_deg = 1;
    CHECK(build_frame(v).field == 11);
    v.motor_pct = 1;
    CHECK(build_frame(v).field == 19);
  }
}

TEST_CASE("validate holds a decoded frame to build_frame's ranges", "[anello][frame]") {
  const auto check = [](auto set, errc ec, std::uint16_t field, std::uint16_t column) {
    sensor_frame_raw f = seed_frame;
    set(f);
    const auto r = validate(f);
    CHECK(r.ec == ec);
    CHECK(r.field == field);
    CHECK(r.column == column);
  };
  check([](sensor_frame_raw& f) { f.heading = 361; }, errc::out_of_range, 1, 8);
  check([](sensor_frame_raw& f) { f.lat = 90'000'001; }, errc::out_of_range, 2, 10);
  check([](sensor_frame_raw& f) { f.gga_quality = 9; }, errc::out_of_range, 10, 39);
  check([](sensor_frame_raw& f) { f.motor = 101; }, errc::out_of_range, 11, 40);
  check([](sensor_frame_raw& f) { f.wind_dir_rel = 0xFFFE; }, errc::out_of_range, 17, 50);
  check([](sensor_frame_raw& f) { f.motor = 127; }, errc::ok, 0, 0);  // not available
  check([](sensor_frame_raw& f) { f.sog = 0xFFFE; }, errc::ok, 0, 0);
  // Decoding itself stays liberal.
  sensor_frame_raw f = seed_frame;
  f.heading = 400;
  CHECK(f.heading_deg() == 400.0);
  const auto r = decode_frame(encode_frame(f));
  REQUIRE(r.ok());
  CHECK(r.value.heading == 400);
}

TEST_CASE("build_frame(to_values(f)) == f for every valid frame", "[anello][builder]") {
  prng rng{42};
  for (int round = 0; round < 5000; ++round) {
    sensor_frame_raw f;
    sensor_fields.apply([&](const auto&... field) {
      (
          [&](const auto& fd) {
            using field_type = std::remove_cvref_t<decltype(fd)>;
            using raw_type = typename field_type::raw_type;
            raw_type& raw = f.*field_type::raw_member;
            if (rng.next() % 8 == 0) return;  // leave "not available"
            const auto [lo, hi] = fd.wire_limits();
            raw = static_cast<raw_type>(rng.between(lo, hi));
            if (fd.not_available(raw)) raw = static_cast<raw_type>(lo);
          }(field),
          ...);
    });
    REQUIRE(validate(f).ok());
    const auto r = build_frame(to_values(f));
    INFO("round " << round);
    REQUIRE(r.ok());
    REQUIRE(r.value == f);
  }
}

TEST_CASE("the table's offsets, computed from the wire types, are the spec's", "[anello][frame]") {
  // Spec 002 section 2.2, "Offset" column: heading at 8 ... pressure at 54.
  const std::array<std::size_t, sensor_field_count> spec = {8,  10, 14, 18, 20, 22, 30, 34, 38, 39,
                                                            40, 41, 42, 44, 46, 48, 50, 52, 54};
  std::vector<std::size_t> offsets;
  std::vector<std::string> keys;
  sensor_fields.apply([&](const auto&... field) {
    (offsets.push_back(field.offset), ...);
    (keys.emplace_back(field.json_key), ...);
  });
  CHECK(offsets == std::vector<std::size_t>(spec.begin(), spec.end()));
  // JSON keys are the names, but the position's, which are those of every other message.
  CHECK(keys[0] == "heading_deg");
  CHECK(keys[1] == "latitude");
  CHECK(keys[2] == "longitude");
  CHECK(keys[18] == "pressure_hpa");
}

TEST_CASE("for_each_field names every field once, in spec order", "[anello][frame]") {
  std::vector<std::string> names;
  std::vector<std::optional<double>> numbers;
  std::optional<time_ms> time;
  std::optional<int> quality = 3;
  for_each_field(seed_frame, [&](std::string_view name, const auto& value) {
    names.emplace_back(name);
    using value_type = typename std::remove_cvref_t<decltype(value)>::value_type;
    if constexpr (std::is_same_v<value_type, double>) {
      numbers.push_back(value);
    } else if constexpr (std::is_same_v<value_type, time_ms>) {
      time = value;
      numbers.emplace_back();
    } else {
      static_assert(std::is_same_v<value_type, int>);
      quality = value;
      numbers.emplace_back();
    }
  });
  const std::vector<std::string> expected = {"heading_deg",
                                             "latitude_deg",
                                             "longitude_deg",
                                             "sog_mps",
                                             "cog_deg",
                                             "gps_time",
                                             "alt_msl_m",
                                             "geoid_sep_m",
                                             "hdop",
                                             "fix_quality",
                                             "motor_pct",
                                             "rudder_pct",
                                             "stw_mps",
                                             "wind_speed_abs_mps",
                                             "wind_dir_abs_deg",
                                             "wind_speed_rel_mps",
                                             "wind_dir_rel_deg",
                                             "air_temp_c",
                                             "pressure_hpa"};
  CHECK(names == expected);
  CHECK(names.size() == sensor_field_count);
  CHECK(std::set<std::string>(names.begin(), names.end()).size() == names.size());
  for (const auto& name : names) {
    for (const char c : name) CHECK(((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'));
  }
  CHECK(time == utc(2024, 7, 3, 15, 42, 58, 0));
  CHECK_FALSE(quality.has_value());
  const std::vector<std::optional<double>> values = {
      89.0, 32.828671, -117.229926, 0.0, {},    {},  48.0, {}, {}, {},
      0.0,  0.0,       0.0,         0.2, 108.0, 0.3, 90.0, {}, {}};
  CHECK(numbers == values);
}
