// SPDX-License-Identifier: BSL-1.0
// The binary layout shared by the NMEA 2000 PGN tables and the ANELLO 0xAB00 frame: fields read
// and written in either bit order, checked against a bit-at-a-time reference written from the
// orders' definitions and against the byte-order loads; rows walked with their offsets.

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <string_view>
#include <vector>

#include "seawire/anello/frame.hpp"
#include "seawire/detail/bit_layout.hpp"
#include "seawire/detail/byte_order.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "support.hpp"

namespace {

using seawire::detail::bit_order;
using seawire::detail::get_bits;
using seawire::detail::put_bits;

// Payload bit o, by the definition of each order: lsb_first counts from a byte's least
// significant bit, msb_first from its most significant.
bool payload_bit(const std::vector<std::uint8_t>& p, unsigned o, bit_order order) {
  const unsigned shift = order == bit_order::lsb_first ? o % 8 : 7 - o % 8;
  return ((static_cast<unsigned>(p[o / 8]) >> shift) & 1U) != 0;
}

// A field's value, one bit at a time: lsb_first takes its first bit as the least significant,
// msb_first as the most significant.
std::uint64_t reference_get(const std::vector<std::uint8_t>& p, unsigned offset, unsigned width,
                            bit_order order) {
  std::uint64_t v = 0;
  for (unsigned i = 0; i < width; ++i) {
    const std::uint64_t b = payload_bit(p, offset + i, order) ? 1 : 0;
    if (order == bit_order::lsb_first) {
      v |= b << i;
    } else {
      v = (v << 1) | b;
    }
  }
  return v;
}

template <bit_order Order>
void check_random_fields(std::uint64_t seed) {
  support::prng g{seed};
  for (int k = 0; k < 5000; ++k) {
    std::vector<std::uint8_t> p(1 + g.below(12));
    for (auto& b : p) b = static_cast<std::uint8_t>(g.next());
    const auto total = static_cast<unsigned>(8 * p.size());
    auto width = static_cast<unsigned>(1 + g.below(std::min(64U, total)));
    auto offset = static_cast<unsigned>(g.below(total - width + 1));
    if (k % 2 == 1) {  // whole bytes (get_bits reads those a byte at a time): 8 to 64 bits
      width = 8 * static_cast<unsigned>(1 + g.below(std::min<std::size_t>(8, p.size())));
      offset = 8 * static_cast<unsigned>(g.below((total - width) / 8 + 1));
    }
    INFO("seed " << seed << " case " << k << " offset " << offset << " width " << width);
    REQUIRE(get_bits<Order>(p, offset, width) == reference_get(p, offset, width, Order));

    // put_bits writes the field and nothing else.
    const std::vector<std::uint8_t> before = p;
    const std::uint64_t v = g.next();
    put_bits<Order>(p, offset, width, v);
    const std::uint64_t mask = width == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1;
    REQUIRE(reference_get(p, offset, width, Order) == (v & mask));
    for (unsigned o = 0; o < total; ++o) {
      if (o < offset || o >= offset + width)
        REQUIRE(payload_bit(p, o, Order) == payload_bit(before, o, Order));
    }
  }
}

// Whole-byte fields are the integers of the matching byte order.
template <class T>
void check_whole_bytes(support::prng& g) {
  std::array<std::uint8_t, 16> p{};
  for (auto& b : p) b = static_cast<std::uint8_t>(g.next());
  const auto at = static_cast<std::size_t>(g.below(p.size() - sizeof(T) + 1));
  const auto bit = static_cast<unsigned>(8 * at);
  constexpr unsigned width = 8 * sizeof(T);
  using seawire::detail::load_be;
  using seawire::detail::load_le;
  CHECK(static_cast<T>(get_bits<bit_order::msb_first>(p, bit, width)) == load_be<T>(p, at));
  CHECK(static_cast<T>(get_bits<bit_order::lsb_first>(p, bit, width)) == load_le<T>(p, at));
  const auto v = static_cast<T>(g.next());
  std::array<std::uint8_t, 16> a = p;
  std::array<std::uint8_t, 16> b = p;
  put_bits<bit_order::msb_first>(a, bit, width, static_cast<std::make_unsigned_t<T>>(v));
  seawire::detail::store_be(b, at, v);
  CHECK(a == b);
  put_bits<bit_order::lsb_first>(a, bit, width, static_cast<std::make_unsigned_t<T>>(v));
  seawire::detail::store_le(b, at, v);
  CHECK(a == b);
}

struct row3 {
  static constexpr unsigned bits = 3;
  std::string_view name;
};
struct row16 {
  static constexpr unsigned bits = 16;
  std::string_view name;
};

constexpr std::array<std::uint8_t, 2> sample{0b1011'0010, 0b0110'0000};
// Bits 3 to 8: "10010" then "0" reading from the most significant; "10110" then "0" reading from
// the least significant, the first bit lowest.
static_assert(get_bits<bit_order::msb_first>(sample, 3, 6) == 0b100100);
static_assert(get_bits<bit_order::lsb_first>(sample, 3, 6) == 0b010110);
static_assert(get_bits<bit_order::msb_first>(sample, 0, 16) == 0xB260);
static_assert(get_bits<bit_order::lsb_first>(sample, 0, 16) == 0x60B2);

}  // namespace

TEST_CASE("fields are read and written in both bit orders, and only their own bits", "[layout]") {
  check_random_fields<bit_order::lsb_first>(1);
  check_random_fields<bit_order::msb_first>(2);
}

TEST_CASE("whole-byte fields are little-endian (lsb_first) or big-endian (msb_first) integers",
          "[layout]") {
  support::prng g{3};
  for (int k = 0; k < 200; ++k) {
    check_whole_bytes<std::uint8_t>(g);
    check_whole_bytes<std::int16_t>(g);
    check_whole_bytes<std::uint16_t>(g);
    check_whole_bytes<std::int32_t>(g);
    check_whole_bytes<std::uint64_t>(g);
    check_whole_bytes<std::int64_t>(g);
  }
}

TEST_CASE("a table's rows follow each other from its first bit", "[layout]") {
  const auto rows = seawire::detail::make_rows(row3{"a"}, row16{"b"}, row3{"c"});
  static_assert(decltype(rows)::size == 3);
  CHECK(seawire::detail::row_at<1>(rows).name == "b");
  static_assert(seawire::detail::layout_bits<decltype(rows)> == 22);
  std::vector<std::pair<unsigned, unsigned>> seen;  // (offset, number)
  CHECK(seawire::detail::for_each_row(
      rows, 5, [&](const auto&, unsigned at, std::uint16_t n) { seen.emplace_back(at, n); }));
  CHECK(seen == std::vector<std::pair<unsigned, unsigned>>{{5, 1}, {8, 2}, {24, 3}});
  // A walk that returns false stops there and says so.
  seen.clear();
  CHECK_FALSE(
      seawire::detail::for_each_row(rows, 0, [&](const auto& r, unsigned at, std::uint16_t n) {
        seen.emplace_back(at, n);
        return r.name != "b";
      }));
  CHECK(seen.size() == 2);
}

TEST_CASE("the 0xAB00 frame and the PGN tables are laid out by the same rows", "[layout]") {
  namespace anello = seawire::anello;
  namespace n2k = seawire::nmea2000;
  // 0xAB00: 19 whole-byte fields from byte 8, each where the one before ends, 48 bytes.
  static_assert(seawire::detail::layout_bits<decltype(anello::sensor_fields)> ==
                8 * anello::payload_size);
  std::size_t expected = anello::header_size;
  seawire::detail::for_each_row(anello::sensor_fields, 8 * anello::header_size,
                                [&](const auto& f, unsigned at, std::uint16_t) {
                                  CHECK(f.offset == expected);
                                  CHECK(at == 8 * expected);
                                  expected += f.bits / 8;
                                });
  CHECK(expected == anello::frame_size);
  // PGN 127488: instance (8 bits), speed (16), boost pressure (16), tilt/trim (8), reserved (16).
  std::vector<unsigned> offsets;
  seawire::nmea2000::pgn_table<n2k::engine_parameters_rapid>.for_each(
      [&](const auto&, unsigned at, std::uint16_t) { offsets.push_back(at); });
  CHECK(offsets == std::vector<unsigned>{0, 8, 24, 40, 48});
  // A frame's field is where the table puts it: heading (u16) at byte 8, big-endian.
  anello::sensor_frame_raw raw;
  raw.heading = 0x0102;
  const anello::frame_bytes bytes = anello::encode_frame(raw);
  CHECK(bytes[8] == 0x01);
  CHECK(bytes[9] == 0x02);
  CHECK(get_bits<bit_order::msb_first>(bytes, 64, 16) == 0x0102);
}
