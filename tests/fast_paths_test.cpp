// SPDX-License-Identifier: BSL-1.0
// The fast paths of the hot code against plain references, over many generated inputs: the
// vectorized sentence scan, the word-at-a-time field search, digit counting, number writing, the
// checksum, and the fast decimal parser. Each fast path must give exactly what the simple code
// gives, byte for byte and error for error, at run time (where the fast paths run) and at
// compile time (where the simple ones do).

#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "seawire/anello/gpsctrl.hpp"
#include "seawire/detail/ascii.hpp"
#include "seawire/detail/byte_order.hpp"
#include "seawire/detail/copy.hpp"
#include "seawire/detail/crc32.hpp"
#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/time.hpp"
#include "seawire/nmea/writer.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/rmc.hpp"
#include "seawire/standard/vwr.hpp"

#include "support.hpp"

// Built twice: as is (SSE2 on x86-64, NEON on 64-bit ARM) and with SEAWIRE_NO_SIMD (the
// portable forms, which constant evaluation also runs).
#if defined(SEAWIRE_NO_SIMD)
static_assert(SEAWIRE_SIMD == 0, "SEAWIRE_NO_SIMD leaves only the portable forms");
#elif defined(__x86_64__)
static_assert(SEAWIRE_SSE2 == 1 && SEAWIRE_NEON == 0, "x86-64 takes the SSE2 paths");
#elif defined(__aarch64__)
static_assert(SEAWIRE_NEON == 1 && SEAWIRE_SSE2 == 0, "64-bit ARM takes the NEON paths");
#endif

using namespace seawire;
using namespace seawire::nmea;

namespace {

using namespace support;

// Up to `max` characters drawn from `chars`.
std::string random_text(prng& g, std::string_view chars, std::size_t max) {
  std::string s;
  const std::size_t n = g.below(max + 1);
  for (std::size_t i = 0; i < n; ++i) s += chars[g.below(chars.size())];
  return s;
}

// A line that looks like a sentence most of the time: '$', an address, fields of digits and
// letters, sometimes a '*' and hex, sometimes a byte that does not belong.
std::string random_line(prng& g) {
  static constexpr std::string_view alphabet = "0123456789.,,,,-ABCNSEWMT*$ \x7f\x1f\x80\xff";
  std::string s = "$";
  const std::size_t address = 1 + g.below(8);
  for (std::size_t i = 0; i < address; ++i) s += static_cast<char>('A' + g.below(26));
  const std::size_t n = g.below(140);
  for (std::size_t i = 0; i < n; ++i) {
    // Mostly plain field text; the rare bytes appear often enough to sit in every lane.
    s += g.below(8) == 0 ? alphabet[g.below(alphabet.size())] : alphabet[g.below(16)];
  }
  if (g.below(2) == 0) {
    s += '*';
    s += "0123456789ABCDEF"[g.below(16)];
    s += "0123456789ABCDEF"[g.below(16)];
  }
  return s;
}

// The scan as parse() did it before it was vectorized: one byte at a time.
nmea::detail::body_scan reference_scan(std::string_view line) {
  nmea::detail::body_scan b;
  nmea::detail::scan_body_bytes(line, b);
  return b;
}

// Splitting at every comma, the obvious way.
std::vector<std::string_view> reference_fields(std::string_view body) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= body.size(); ++i) {
    if (i == body.size() || body[i] == ',') {
      out.push_back(body.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

}  // namespace

TEST_CASE("the vectorized sentence scan finds what the byte loop finds") {
  prng g{20261121};
  for (int k = 0; k < 200000; ++k) {
    const std::string line = random_line(g);
    INFO(line);
    const nmea::detail::body_scan fast = nmea::detail::scan_body(line);
    const nmea::detail::body_scan slow = reference_scan(line);
    REQUIRE(fast.bad == slow.bad);
    if (slow.bad != 0) continue;  // the rest is not defined once a bad byte stops the scan
    REQUIRE(fast.star == slow.star);
    REQUIRE(fast.commas == slow.commas);
    REQUIRE(fast.x == slow.x);
  }
}

TEST_CASE("the vectorized scan counts every comma of a long line") {
  // Its per-lane counters are bytes: 5,000 commas once came back as 904 fields.
  parse_policy p;
  p.max_length = 65535;
  for (const std::size_t commas : {255U, 256U, 4079U, 4080U, 4081U, 5000U, 65000U}) {
    std::string line = "$PXXX";
    line.append(commas, ',');
    INFO(commas);
    const nmea::detail::body_scan fast = nmea::detail::scan_body(line);
    CHECK(fast.commas == commas);
    CHECK(fast.x == reference_scan(line).x);
    const auto r = parse(line + "*" + std::string(1, "0123456789ABCDEF"[fast.x >> 4U]) +
                             std::string(1, "0123456789ABCDEF"[fast.x & 15U]),
                         p);
    REQUIRE(r);
    CHECK(r.value.field_count == commas);
  }
}

TEST_CASE("parse() names the byte that spoils an address, as a first-comma search would") {
  // The reference: the address is what stands before the first ',' (or the '*', or the end); it
  // must be 1 to 15 upper-case letters and digits, a letter first. A wrong length is reported
  // at column 1, a wrong character where it stands.
  const auto reference = [](std::string_view line) -> std::pair<bool, std::size_t> {
    std::size_t end = 1;
    while (end < line.size() && line[end] != ',' && line[end] != '*') ++end;
    if (end - 1 == 0 || end - 1 > 15) return {false, 1};
    for (std::size_t k = 1; k < end; ++k) {
      const char c = line[k];
      if (!((c >= 'A' && c <= 'Z') || (k > 1 && c >= '0' && c <= '9'))) return {false, k};
    }
    return {true, 0};
  };
  // Bytes after the '*' are not checked by the scan, and the address is read eight bytes at a
  // time: whatever stands there must not change the answer.
  CHECK(parse("$A*\xff\xff\xff\xff\xff\xff\xff").ec == errc::bad_checksum_format);
  CHECK(parse("$AB*\x80\x7f\x01\xfe\xff\xff\xff").ec == errc::bad_checksum_format);
  CHECK(parse("$GP\xffRMC,1,2,3,4,5,6").ec == errc::bad_character);
  const auto eight = parse("$ABCDEFGH,1,2,3*00", parse_policy{checksum_policy::ignore});
  REQUIRE(eight);
  CHECK(eight.value.address == "ABCDEFGH");
  const auto ten = parse("$PAPGPSCTRL,1*00", parse_policy{checksum_policy::ignore});
  REQUIRE(ten);
  CHECK(ten.value.address == "PAPGPSCTRL");
  CHECK(parse("$ABCDEFGHIJKLMNOP,1").column == 1);  // 16 characters
  CHECK(parse("$ABCDEFGHIJKLMNO,1").ok());          // 15

  prng g{4242};
  static constexpr std::string_view chars = "AAAAAAGPRMC0123456789,,*az-.";
  parse_policy p;
  p.checksum = checksum_policy::ignore;
  for (int k = 0; k < 100000; ++k) {
    std::string line = "$" + random_text(g, chars, 23);
    if (g.below(2) == 0) line += ",1,2,3.5,ABC,,,N*00";  // long enough for the vector scan
    INFO(line);
    const auto r = parse(line, p);
    const auto [ok, column] = reference(line);
    if (ok) {
      // Anything else wrong comes after the address.
      if (!r) CHECK(r.ec != errc::bad_address);
    } else {
      REQUIRE_FALSE(r);
      CHECK(r.ec == errc::bad_address);
      CHECK(r.column == column);
    }
  }
}

TEST_CASE("parse() gives the same answer at run time as at compile time") {
  // The compile-time answers come from the byte loop (constant evaluation never vectorizes).
  constexpr std::string_view line =
      "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70\r\n";
  constexpr auto ct = parse(line);
  static_assert(ct.ok() && ct.value.field_count == 12 && ct.value.computed_checksum == 0x70);
  const auto rt = parse(line);
  REQUIRE(rt);
  CHECK(rt.value.address == ct.value.address);
  CHECK(rt.value.body == ct.value.body);
  CHECK(rt.value.field_count == ct.value.field_count);
  CHECK(rt.value.computed_checksum == ct.value.computed_checksum);
}

TEST_CASE("field_reader hands out the fields a plain split finds, with their columns") {
  prng g{7};
  parse_policy p;
  p.checksum = checksum_policy::ignore;
  for (int k = 0; k < 50000; ++k) {
    const std::string line = random_line(g);
    const auto s = parse(line, p);
    if (!s) continue;
    INFO(line);
    const std::vector<std::string_view> want =
        s.value.field_count > 0 ? reference_fields(s.value.body) : std::vector<std::string_view>{};
    REQUIRE(want.size() == s.value.field_count);
    field_reader r(s.value, p);
    std::size_t column = s.value.body_column();
    for (std::size_t i = 0; i < want.size(); ++i) {
      REQUIRE(r.peek().text == want[i]);
      const field_token t = r.take();
      REQUIRE(t.present);
      REQUIRE(t.text == want[i]);
      REQUIRE(r.column() == column);
      REQUIRE(r.index() == i + 1);
      column += want[i].size() + 1;
    }
    REQUIRE(r.at_end());
    REQUIRE_FALSE(r.take().present);
  }
}

TEST_CASE("magnitude: |v| of every integer type, the most negative values included") {
  using seawire::detail::magnitude;
  STATIC_REQUIRE(magnitude(std::numeric_limits<std::int64_t>::min()) == 0x8000000000000000ULL);
  STATIC_REQUIRE(magnitude(std::numeric_limits<std::int64_t>::max()) == 0x7FFFFFFFFFFFFFFFULL);
  STATIC_REQUIRE(magnitude(std::int8_t{-128}) == 128);
  STATIC_REQUIRE(magnitude(std::int16_t{-32768}) == 32768);
  STATIC_REQUIRE(magnitude(-1) == 1);
  STATIC_REQUIRE(magnitude(0) == 0);
  STATIC_REQUIRE(magnitude(std::numeric_limits<std::uint64_t>::max()) == ~0ULL);
  for (std::int64_t v = -300; v <= 300; ++v)
    REQUIRE(magnitude(v) == static_cast<std::uint64_t>(v < 0 ? -v : v));
}

TEST_CASE("digit_count: exact at every power of ten and either side of it") {
  CHECK(seawire::detail::digit_count(0) == 1);
  CHECK(seawire::detail::digit_count(~std::uint64_t{0}) == 20);
  for (unsigned k = 1; k < 20; ++k) {
    const std::uint64_t p = seawire::detail::pow10_table[k];
    CHECK(seawire::detail::digit_count(p - 1) == k);
    CHECK(seawire::detail::digit_count(p) == k + 1);
    CHECK(seawire::detail::digit_count(p + 1) == k + 1);
  }
  static_assert(seawire::detail::digit_count(99) == 2 && seawire::detail::digit_count(100) == 3);
}

// v / 10^places as put_fixed writes it, built from std::to_string: the integer part zero-padded to
// `min` digits (at most 20), then a point and all `places` fraction digits.
namespace {
std::string fixed_text(std::uint64_t v, unsigned places, unsigned min) {
  const std::uint64_t p = seawire::detail::pow10_table[places];
  std::string whole = std::to_string(v / p);
  while (whole.size() < min && whole.size() < 20) whole.insert(whole.begin(), '0');
  std::string fraction = std::to_string(v % p);
  while (fraction.size() < places) fraction.insert(fraction.begin(), '0');
  return places == 0 ? whole : whole + "." + fraction;
}
}  // namespace

TEST_CASE("writer::put_uint and put_fixed write what std::to_string would") {
  prng g{99};
  for (int k = 0; k < 100000; ++k) {
    const unsigned digits = 1 + static_cast<unsigned>(g.below(20));
    const std::uint64_t v =
        digits == 20 ? g.next() : g.next() % seawire::detail::pow10_table[digits];
    const unsigned min = static_cast<unsigned>(g.below(22));
    const unsigned places = static_cast<unsigned>(g.below(20));

    std::string want = std::to_string(v);
    while (want.size() < min && want.size() < 20) want.insert(want.begin(), '0');
    char buf[64];
    writer w(buf);
    w.put_uint(v, min);
    INFO(v << " min " << min);
    REQUIRE(w.view() == want);

    // put_fixed: the integer part then the `places` fraction digits.
    const std::string fixed = fixed_text(v, places, min);
    writer f(buf);
    f.put_fixed(v, places, min);
    INFO("places " << places);
    REQUIRE(f.view() == fixed);

    // Out of room: nothing written, the writer failed.
    writer tight(std::span<char>(buf, fixed.size() - 1));
    tight.put_fixed(v, places, min);
    REQUIRE(tight.failed());
    REQUIRE(tight.size() == 0);
  }
}

// Numbers below 2^32 are written in 32-bit arithmetic, larger ones in 64-bit: at the edge, and
// where the integer part left after the fraction crosses it, with every fraction length and
// padding, by the checked writer and by encode's unchecked one, as std::to_string would.
TEST_CASE("put_fixed at the 32-bit edge: both arithmetics write the digits std::to_string does") {
  std::vector<std::uint64_t> values;
  for (const std::uint64_t edge : {std::uint64_t{0xFFFFFFFF}, std::uint64_t{0x100000000}}) {
    for (std::uint64_t p = 1; p <= 10'000'000'000ULL; p *= 10) {
      values.insert(values.end(), {edge - 1, edge, edge + 1, edge * p - 1, edge * p, edge * p + 1});
    }
  }
  for (const std::uint64_t v : values) {
    for (unsigned places = 0; places <= 19; ++places) {
      for (unsigned min = 0; min <= 21; ++min) {
        const std::string want = fixed_text(v, places, min);
        INFO(v << " places " << places << " min " << min);
        char buf[64];
        writer checked(buf);
        checked.put_fixed(v, places, min);
        REQUIRE(checked.view() == want);
        seawire::nmea::detail::basic_writer<false> unchecked(buf);
        unchecked.put_fixed(v, places, min);
        REQUIRE(unchecked.view() == want);
      }
    }
  }
}

// Times, dates and positions write small numbers padded to two digits by a shorter way: every
// such number, with the widths around it, as std::to_string would, and out of room at the margin.
TEST_CASE("small padded numbers: writer::put_uint and append_uint against std::to_string") {
  for (std::uint64_t v = 0; v < 1100; ++v) {
    for (unsigned min = 0; min <= 4; ++min) {
      std::string want = std::to_string(v);
      while (want.size() < min) want.insert(want.begin(), '0');
      INFO(v << " min " << min);
      char buf[32];
      writer w(buf);
      w.put_uint(v, min);
      REQUIRE(w.view() == want);
      REQUIRE_FALSE(w.failed());
      writer tight(std::span<char>(buf, want.size() - 1));
      tight.put_uint(v, min);
      REQUIRE(tight.failed());
      REQUIRE(tight.size() == 0);
      writer exact(std::span<char>(buf, want.size()));
      exact.put_uint(v, min);
      REQUIRE_FALSE(exact.failed());
      REQUIRE(exact.view() == want);
      char out[32] = {'x'};
      const std::size_t end = seawire::detail::append_uint(out, 1, v, min);
      REQUIRE(std::string_view(out + 1, end - 1) == want);
      REQUIRE(out[0] == 'x');
    }
  }
  static_assert([] {
    char out[4]{};
    return seawire::detail::append_uint(out, 0, 7, 2) == 2 && out[0] == '0' && out[1] == '7';
  }());
}

// Times and dates are written as three two-digit numbers at once: as put_uint(v, 2) three
// times, a number of 100 or more included, and out of room at the margin.
TEST_CASE("writer::put_pairs writes what put_uint(v, 2) writes three times") {
  const auto check = [](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
    INFO(a << " " << b << " " << c);
    char want_buf[80];
    writer want(want_buf);
    want.put_uint(a, 2);
    want.put_uint(b, 2);
    want.put_uint(c, 2);
    REQUIRE_FALSE(want.failed());
    char buf[80];
    writer w(buf);
    w.put('x');
    w.put_pairs(a, b, c);
    REQUIRE(w.view().substr(1) == want.view());
    writer exact(std::span<char>(buf, want.size()));
    exact.put_pairs(a, b, c);
    REQUIRE_FALSE(exact.failed());
    REQUIRE(exact.view() == want.view());
    writer tight(std::span<char>(buf, want.size() - 1));
    tight.put_pairs(a, b, c);
    REQUIRE(tight.failed());
    // The unchecked writer, given the room, writes the same bytes and nothing past them.
    char raw[80];
    std::fill(std::begin(raw), std::end(raw), '#');
    seawire::nmea::detail::basic_writer<false> u(std::span<char>(raw, want.size()));
    u.put_pairs(a, b, c);
    REQUIRE(std::string_view(raw, want.size()) == want.view());
    REQUIRE(raw[want.size()] == '#');
  };
  for (std::uint64_t v = 0; v < 100; ++v) {
    check(v, 0, 99);
    check(99, v, 0);
    check(0, 99, v);
  }
  for (const std::uint64_t big : {100ULL, 255ULL, 999ULL, 2026ULL, 18446744073709551615ULL}) {
    check(big, 7, 8);
    check(7, big, 8);
    check(7, 8, big);
  }
  static_assert([] {
    char out[6]{};
    writer w(out);
    w.put_pairs(23, 5, 60);
    return w.view() == "230560";
  }());
}

// A number that fits its width is written at that width with no digit count; one that does not
// fit, or a width past 19 digits, takes the counting way. Both against std::to_string padded to
// the width (at most max_padded_digits), at every width and around every power of ten, and
// nothing written past the digits.
TEST_CASE("append_uint at every width and around every power of ten against std::to_string") {
  constexpr unsigned most = seawire::detail::max_padded_digits;
  std::vector<std::uint64_t> values = {0, std::numeric_limits<std::uint64_t>::max()};
  for (std::uint64_t p = 1; p <= 10'000'000'000'000'000'000ULL; p *= 10) {
    values.insert(values.end(), {p - 1, p, p + 1});
    if (p > std::numeric_limits<std::uint64_t>::max() / 10) break;
  }
  prng g{20261128};
  for (int i = 0; i < 2000; ++i) values.push_back(g.next() >> g.below(64));
  for (const std::uint64_t v : values) {
    for (unsigned width = 0; width <= most + 2; ++width) {
      std::string want = std::to_string(v);
      while (want.size() < std::min(width, most)) want.insert(want.begin(), '0');
      INFO(v << " width " << width);
      char out[40];
      std::fill(std::begin(out), std::end(out), 'x');
      const std::size_t end = seawire::detail::append_uint(out, 3, v, width);
      REQUIRE(std::string_view(out + 3, end - 3) == want);
      REQUIRE(std::all_of(out, out + 3, [](char c) { return c == 'x'; }));
      REQUIRE(std::all_of(out + end, std::end(out), [](char c) { return c == 'x'; }));
    }
  }
  static_assert([] {
    char out[24]{};
    const std::size_t end = seawire::detail::append_uint(out, 0, 2026, 4);
    const std::size_t frac = seawire::detail::append_uint(out, end, 5, 3);
    return frac == 7 && std::string_view(out, frac) == "2026005";
  }());
}

#if SEAWIRE_SIMD
// The sixteen-lane operations the scans are written in, each against what it means for one
// byte: every byte value in every lane, with other lanes around it.
TEST_CASE("the vector operations give, lane by lane, what the byte rules give") {
  namespace simd = seawire::detail::simd;
  prng rng{0x5EA5EA5EA5EA5EA5ULL};
  for (unsigned value = 0; value < 256; ++value) {
    const auto b = static_cast<unsigned char>(value);
    for (std::size_t lane = 0; lane < 16; ++lane) {
      unsigned char bytes[16];
      for (auto& x : bytes) x = static_cast<unsigned char>(rng.next());
      bytes[lane] = b;
      const simd::bytes16 v = simd::load(bytes);
      unsigned not_printable = 0;
      unsigned equal = 0;
      unsigned char x = 0;
      for (std::size_t i = 0; i < 16; ++i) {
        if (bytes[i] < 0x20 || bytes[i] > 0x7E) not_printable |= 1U << i;
        if (bytes[i] == b) equal |= 1U << i;
        x = static_cast<unsigned char>(x ^ bytes[i]);
      }
      REQUIRE(simd::bits(simd::not_printable(v)) == not_printable);
      REQUIRE(simd::bits(simd::equal(v, b)) == equal);
      REQUIRE(simd::first(simd::equal(v, b)) == static_cast<std::size_t>(std::countr_zero(equal)));
      REQUIRE(simd::any(simd::equal(v, b)));
      REQUIRE(simd::xor_all(v) == x);
      // A mask with only this lane set, and masks that keep lanes from here on.
      unsigned char one[16] = {};
      one[lane] = 0xFF;
      REQUIRE(simd::first(simd::load(one)) == lane);
      REQUIRE(simd::bits(simd::lanes_from(lane)) == (0xFFFFU << lane & 0xFFFFU));
    }
  }
  unsigned char none[16] = {};
  CHECK(simd::first(simd::load(none)) == 16);
  CHECK_FALSE(simd::any(simd::load(none)));
  CHECK(simd::bits(simd::lanes_from(16)) == 0);
  // Counters up to 255 in each lane add up without loss.
  for (int round = 0; round < 1000; ++round) {
    simd::bytes16 counters = simd::zero();
    std::size_t expected = 0;
    const unsigned steps = static_cast<unsigned>(rng.next() % 256);
    for (unsigned step = 0; step < steps; ++step) {
      unsigned char mask[16];
      for (auto& m : mask) {
        m = (rng.next() & 1U) != 0 ? 0xFF : 0x00;
        expected += m != 0 ? 1 : 0;
      }
      counters = simd::count(counters, simd::load(mask));
    }
    REQUIRE(simd::sum(counters) == expected);
  }
}
#endif

TEST_CASE("the checksum of any span matches the byte-by-byte XOR") {
  prng g{3};
  std::string s;
  for (int k = 0; k < 300; ++k) {
    s += static_cast<char>(g.next());
    std::uint8_t x = 0;
    for (const char c : s) x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(c));
    for (std::size_t from = 0; from < 3 && from <= s.size(); ++from) {
      std::uint8_t y = 0;
      for (std::size_t i = from; i < s.size(); ++i)
        y = static_cast<std::uint8_t>(y ^ static_cast<std::uint8_t>(s[i]));
      REQUIRE(checksum(std::string_view(s).substr(from)) == y);
    }
    REQUIRE(checksum(s) == x);
  }
  static_assert(checksum("GPGLL,5057.970,N,00146.110,E,142451,A") == 0x27);
}

TEST_CASE("the fast decimal parser agrees with the general one") {
  prng g{11};
  static constexpr std::string_view chars = "0000123456789..-+x";
  for (int k = 0; k < 300000; ++k) {
    const std::string s = random_text(g, chars, 25);
    INFO(s);
    for (const bool plus : {false, true}) {
      decimal fast = decimal::scaled(123, 4);
      decimal slow = decimal::scaled(123, 4);
      const errc ef = nmea::detail::parse_decimal(s, plus, fast);
      std::size_t i = 0;
      bool neg = false;
      errc es = errc::ok;
      if (!s.empty() && (s[0] == '-' || s[0] == '+')) {
        if (s[0] == '+' && !plus) es = errc::bad_number;
        neg = s[0] == '-';
        i = 1;
      }
      if (es == errc::ok) es = nmea::detail::parse_decimal_long(s, i, neg, slow);
      REQUIRE(ef == es);
      if (ef == errc::ok) REQUIRE(fast == slow);
    }
  }
}

TEST_CASE("copy_bytes copies exactly n bytes, for every n around its word sizes") {
  check_copies_exactly(
      [](char* out, const char* in, std::size_t n) { seawire::detail::copy_bytes(out, in, n); },
      40);
  static_assert([] {
    char out[6] = {'.', '.', '.', '.', '.', '.'};
    seawire::detail::copy_bytes(out + 1, "abcd", 3);
    return out[0] == '.' && out[1] == 'a' && out[2] == 'b' && out[3] == 'c' && out[4] == '.';
  }());
}

TEST_CASE("a number read up to the comma after it is the number read to the end of its text") {
  // The codecs let the ',' that follows a field end its digit runs (field_end::comma, from
  // field_reader::end_of_field), so no digit needs a length test; the answer must be the
  // bounded read's.
  prng g{19};
  static constexpr std::string_view chars = "0001234567899..-+ x";
  for (int k = 0; k < 200000; ++k) {
    const std::string s = random_text(g, chars, 24);
    const std::string field = s + ",7";  // a digit after the comma: the run must stop at it
    INFO(s);
    for (const bool strict : {false, true}) {
      parse_policy p;
      p.strict_values = strict;
      p.spaced_numbers = true;
      decimal bounded = decimal::scaled(123, 4);
      decimal at_comma = decimal::scaled(123, 4);
      const std::string_view text(field.data(), s.size());
      const errc eb = nmea::detail::parse_decimal(text, p, bounded);
      const errc ec = nmea::detail::parse_decimal(text, p, at_comma, field_end::comma);
      REQUIRE(eb == ec);
      REQUIRE(bounded == at_comma);
    }
  }
}

TEST_CASE("field_reader::end_of_field: a comma follows every field but the last") {
  parse_policy p;
  p.checksum = checksum_policy::ignore;
  const auto s = parse("$GPXXX,1,,22,333*00", p);
  REQUIRE(s);
  field_reader r(s.value, p);
  for (const std::string_view want : {"1", "", "22", "333"}) {
    const std::string_view got = r.take().text;
    REQUIRE(got == want);
    CHECK((r.end_of_field() == field_end::comma) == (want != "333"));
    if (r.end_of_field() == field_end::comma) CHECK(got.data()[got.size()] == ',');
  }
  (void)r.take();  // past the end
  CHECK(r.end_of_field() == field_end::unknown);
}

TEST_CASE("a number or position that ends its sentence is read without a byte past it") {
  // The last field of a line without a checksum ends where the line's storage ends: read with
  // field_end::comma by mistake, its digit run would go on past it (the sanitizer build sees
  // that). Each line is copied to storage of exactly its size.
  struct case_ {
    std::string_view line;
    errc as_latitude;  // the digits read, then no hemisphere field, or a bad number
  };
  for (const auto& [line, as_latitude] :
       {case_{"$GPXXX,4807.038", errc::too_few_fields}, case_{"$GPXXX,12", errc::bad_latitude},
        case_{"$GPXXX,4807", errc::too_few_fields}, case_{"$GPXXX,4807.", errc::too_few_fields},
        case_{"$GPXXX,-3.25", errc::bad_latitude}}) {
    INFO(line);
    const auto exact = std::make_unique<char[]>(line.size());
    std::copy(line.begin(), line.end(), exact.get());
    const std::string_view copy(exact.get(), line.size());
    const auto s = parse(copy);
    REQUIRE(s);
    {
      field_reader r(s.value, parse_policy{});
      decimal d;
      const errc e = codec<decimal>::read(r, d);
      CHECK(r.end_of_field() == field_end::unknown);
      decimal want;
      CHECK(e == nmea::detail::parse_decimal(line.substr(7), parse_policy{}, want));
      if (e == errc::ok) CHECK(d == want);
    }
    {
      field_reader r(s.value, parse_policy{});
      latitude lat;
      CHECK(codec<latitude>::read(r, lat) == as_latitude);
    }
  }
}

TEST_CASE("a message's address test says what comparing the strings says") {
  // matches() compares the known letters one by one; the rule it must keep: same length, any
  // talker but a 'P' (proprietary) before a "--" address's letters, the rest equal.
  prng g{29};
  static constexpr std::string_view chars = "GPRMCNAVWZ";
  const auto reference = [](std::string_view a, std::string_view address) {
    if (address.starts_with("--"))
      return a.size() == address.size() && a[0] != 'P' && a.substr(2) == address.substr(2);
    return a == address;
  };
  for (int k = 0; k < 100000; ++k) {
    const std::string a = random_text(g, chars, 7);
    INFO(a);
    REQUIRE(standard::rmc::nmea.matches(a) == reference(a, standard::rmc::nmea.address));
    REQUIRE(standard::vwr::nmea.matches(a) == reference(a, standard::vwr::nmea.address));
  }
  CHECK(standard::rmc::nmea.matches("GPRMC"));
  CHECK(standard::rmc::nmea.matches("GNRMC"));
  CHECK_FALSE(standard::rmc::nmea.matches("PGRMC"));
  CHECK_FALSE(standard::rmc::nmea.matches("GPRMCX"));
  CHECK_FALSE(standard::rmc::nmea.matches("GPRM"));
  CHECK_FALSE(standard::rmc::nmea.matches(""));
  static_assert(standard::rmc::nmea.matches("IIRMC") && !standard::rmc::nmea.matches("IIRMD"));
  // A fixed address: every letter compared, from the first.
  constexpr auto& ctrl = anello::papgpsctrl::nmea;
  CHECK(ctrl.matches("PAPGPSCTRL"));
  for (const std::string_view a :
       {"PAPGPSCTRX", "XAPGPSCTRL", "PAPGPSCTR", "PAPGPSCTRLX", "", "QAPGPSCTRL", "PAPGPSCTRl"})
    CHECK_FALSE(ctrl.matches(a));
}

TEST_CASE("a number read under a policy is read as under the policy's two flags") {
  // The codecs read numbers with the field reader's policy, which the parser consults only for
  // a sign or a space; the answer must be the one the explicit flags give.
  prng g{12};
  static constexpr std::string_view chars = "0012345679.. -+x";
  for (int k = 0; k < 200000; ++k) {
    const std::string s = random_text(g, chars, 11);
    INFO(s);
    for (const bool strict : {false, true}) {
      for (const bool spaced : {false, true}) {
        parse_policy p;
        p.strict_values = strict;
        p.spaced_numbers = spaced;
        decimal by_policy = decimal::scaled(123, 4);
        decimal by_flags = decimal::scaled(123, 4);
        const errc ep = nmea::detail::parse_decimal(s, p, by_policy);
        const errc ef = nmea::detail::parse_decimal(s, !strict, by_flags, spaced);
        REQUIRE(ep == ef);
        REQUIRE(by_policy == by_flags);
      }
    }
  }
}

TEST_CASE("decimal::compare without division agrees with the value") {
  prng g{5};
  for (int k = 0; k < 200000; ++k) {
    decimal a;
    decimal b;
    a.places = static_cast<std::uint8_t>(g.below(20));
    b.places = static_cast<std::uint8_t>(g.below(20));
    a.mantissa = g.below(4) == 0 ? g.next() : g.next() % 100000;
    b.mantissa = g.below(4) == 0 ? g.next() : g.next() % 100000;
    a.negative = g.below(2) == 0;
    b.negative = g.below(2) == 0;
    // Reference: the magnitudes written out as text with 20 integer and 19 fraction digits,
    // which compare as the numbers do.
    const auto text = [](const decimal& d) {
      const std::uint64_t p = seawire::detail::pow10_table[d.places];
      std::string whole = std::to_string(d.mantissa / p);
      std::string fraction = d.places == 0 ? std::string() : std::to_string(d.mantissa % p);
      while (fraction.size() < d.places) fraction.insert(fraction.begin(), '0');
      while (whole.size() < 20) whole.insert(whole.begin(), '0');
      while (fraction.size() < 19) fraction += '0';
      return whole + fraction;
    };
    const bool na = a.negative && a.mantissa != 0;
    const bool nb = b.negative && b.mantissa != 0;
    int want = 0;
    if (na != nb) {
      want = na ? -1 : 1;
    } else {
      const std::string ta = text(a);
      const std::string tb = text(b);
      want = ta == tb ? 0 : (ta < tb ? -1 : 1);
      if (na) want = -want;
    }
    INFO(a.mantissa << "e-" << int(a.places) << " vs " << b.mantissa << "e-" << int(b.places));
    REQUIRE(a.compare(b) == want);
  }
}

namespace {

// Positions as the position codec read them before the one-pass reader: split at the point, degrees
// by parse_fixed_digits, minutes by parse_decimal.
template <class Axis>
errc reference_position(std::string_view s, nmea_coordinate<Axis>& v) {
  std::size_t point = s.find('.');
  if (point == std::string_view::npos) point = s.size();
  if (point < 3 || point - 2 > Axis::width) return Axis::error;
  unsigned deg = 0;
  if (!nmea::detail::parse_fixed_digits(s, 0, point - 2, deg)) return Axis::error;
  decimal minutes;
  if (nmea::detail::parse_decimal(s.substr(point - 2), false, minutes) != errc::ok ||
      minutes.negative || minutes.places > 12)
    return Axis::error;
  minutes.int_width = 0;
  if (minutes.places == 0) {  // no fraction: read as one zero fraction digit
    minutes.mantissa *= 10;
    minutes.places = 1;
  }
  if (minutes.mantissa >= 60 * seawire::detail::pow10_table[minutes.places])
    return errc::minute_out_of_range;
  if (deg > Axis::max_degrees || (deg == Axis::max_degrees && minutes.mantissa != 0))
    return Axis::error;
  v.whole_degrees = static_cast<std::uint16_t>(deg);
  v.minutes = minutes;
  v.degree_digits = static_cast<std::uint8_t>(point - 2);
  return errc::ok;
}

// Times by a plain reading of hhmmss[.f], one to nine fraction digits, that shares nothing with
// the codec's digit readers.
errc reference_time(std::string_view s, time_of_day& v) {
  const auto number = [s](std::size_t from, std::size_t n, unsigned& out) {
    out = 0;
    if (from + n > s.size()) return false;
    for (const char c : s.substr(from, n)) {
      if (c < '0' || c > '9') return false;
      out = out * 10 + static_cast<unsigned>(c - '0');
    }
    return true;
  };
  unsigned hms[3] = {};
  for (std::size_t k = 0; k < 3; ++k)
    if (!number(2 * k, 2, hms[k])) return errc::bad_time;
  unsigned frac = 0;
  const std::size_t places = s.size() > 7 ? s.size() - 7 : 0;
  const bool fraction_ok =
      s.size() == 6 || (s[6] == '.' && places >= 1 && places <= 9 && number(7, places, frac));
  if (!fraction_ok) return errc::bad_time;
  v = {static_cast<std::uint8_t>(hms[0]), static_cast<std::uint8_t>(hms[1]),
       static_cast<std::uint8_t>(hms[2]), frac, static_cast<std::uint8_t>(places)};
  return codec<time_of_day>::check(v);
}

// The codec's answer for `text` as the field before the hemisphere letter N.
template <class V>
errc through_codec(std::string_view text, V& v) {
  const std::string line = "$XXABC," + std::string(text) + ",N";
  parse_policy p;
  p.checksum = checksum_policy::ignore;
  const auto s = parse(line, p);
  if (!s) return errc::bad_character;  // not a field at all: the caller skips it
  field_reader r(s.value, p);
  return codec<V>::read(r, v);
}

}  // namespace

TEST_CASE("the one-pass position reader agrees with splitting at the point") {
  prng g{13};
  for (int k = 0; k < 300000; ++k) {
    const std::string s = random_text(g, "0123456789012345678959.x", 22);
    if (s.empty() || s.find(',') != std::string::npos) continue;
    INFO(s);
    latitude fast_lat;
    latitude slow_lat;
    const errc fl = through_codec(s, fast_lat);
    const errc sl = reference_position(s, slow_lat);
    REQUIRE(fl == sl);
    longitude fast_lon;
    longitude slow_lon;
    const errc fo = through_codec(s, fast_lon);
    const errc so = reference_position(s, slow_lon);
    // A longitude wants E/W: the field after it is N, so a good number ends in bad_hemisphere.
    REQUIRE(fo == (so == errc::ok ? errc::bad_hemisphere : so));
    if (sl == errc::ok) {
      REQUIRE(fast_lat.whole_degrees == slow_lat.whole_degrees);
      REQUIRE(fast_lat.minutes == slow_lat.minutes);
      REQUIRE(fast_lat.degree_digits == slow_lat.degree_digits);
    }
  }
}

TEST_CASE("the time reader agrees with three fixed-digit reads") {
  prng g{17};
  for (int k = 0; k < 300000; ++k) {
    const std::string s = random_text(g, "01234567890123456789.:", 17);
    if (s.empty()) continue;
    INFO(s);
    time_of_day fast;
    time_of_day slow;
    const errc ef = through_codec(s, fast);
    const errc es = reference_time(s, slow);
    REQUIRE(ef == es);
    if (es == errc::ok) REQUIRE(fast == slow);
  }
}

TEST_CASE("six digits as three pairs in one word: every byte at every place, as byte by byte") {
  // Bytes 6 and 7 are read with the six and must not matter; a byte below '0' or above '9' at
  // any of the six must refuse the whole.
  for (const std::string_view background :
       {"12345678", "00000000", "99999999", "235960*0", "010280,A"}) {
    for (std::size_t at = 0; at < 8; ++at) {
      for (unsigned b = 0; b < 256; ++b) {
        std::string word(background);
        word[at] = static_cast<char>(b);
        INFO(background << " with byte " << b << " at " << at);
        unsigned fast[3] = {};
        unsigned slow[3] = {};
        const bool f = nmea::detail::scan_digit_pairs(word.data(), fast);
        const bool s = nmea::detail::parse_digit_pairs(word, slow);
        REQUIRE(f == s);
        REQUIRE(f == (at >= 6 || (b >= '0' && b <= '9')));
        if (f) {
          for (std::size_t k = 0; k < 3; ++k) REQUIRE(fast[k] == slow[k]);
        }
      }
    }
  }
  static_assert([] {
    unsigned two[3] = {};
    return nmea::detail::scan_digit_pairs("235960*5", two) && two[0] == 23 && two[1] == 59 &&
           two[2] == 60 && !nmea::detail::scan_digit_pairs("2359 0*5", two);
  }());
}

namespace {
// What a one-pass scanner of V makes of `text` as the last field of a framed body: the value
// and the byte it stopped at, or nullptr. The line ends "*00", the only bytes past the body.
template <class V>
const char* scan_at_end(std::string& line, std::string_view text, V& v) {
  line = "$XXABC," + std::string(text) + "*00";
  const char* const body = line.data() + 7;
  return codec<V>::scan(body, body + text.size(), v);
}
}  // namespace

TEST_CASE("the one-pass time and date readers accept what read() accepts, to the same value") {
  prng g{19};
  std::string line;
  std::size_t accepted = 0;
  for (int k = 0; k < 300000; ++k) {
    const std::string s = random_text(g, "01234567890123456789012345.,:", 17);
    if (s.empty() || s.front() == ',' || s.find('*') != std::string::npos) continue;
    INFO(s);
    const std::string_view field = std::string_view(s).substr(0, s.find(','));
    time_of_day slow_time;
    time_of_day fast_time;
    const bool time_ok = through_codec(field, slow_time) == errc::ok;
    // The scan may stop inside the field ("123456" of "1234567"): the one-pass reader then
    // finds no ',' there and gives the line up. Stopped at the field's end, it has the value
    // read() gives; read() accepts nothing else.
    const char* q = scan_at_end(line, s, fast_time);
    const char* field_end = line.data() + 7 + field.size();
    REQUIRE((q == field_end) == time_ok);
    if (q == field_end) {
      REQUIRE(fast_time == slow_time);
      ++accepted;
    }
    date slow_date;
    date fast_date;
    const bool date_ok = through_codec(field, slow_date) == errc::ok;
    q = scan_at_end(line, s, fast_date);
    field_end = line.data() + 7 + field.size();  // a new line, perhaps elsewhere
    REQUIRE((q == field_end) == date_ok);
    if (q == field_end) {
      REQUIRE(fast_date == slow_date);
      ++accepted;
    }
  }
  CHECK(accepted > 1000);
}

TEST_CASE("CRC-32 eight bytes at a time equals the byte-at-a-time register") {
  prng g{23};
  std::vector<std::uint8_t> v;
  const auto bytewise = [](std::span<const std::uint8_t> b, std::uint32_t crc) {
    std::uint32_t reg = ~crc;
    for (const std::uint8_t x : b) reg = seawire::detail::crc32_step(reg, x);
    return ~reg;
  };
  for (int n = 0; n < 700; ++n) {
    v.push_back(static_cast<std::uint8_t>(g.next()));
    const std::span<const std::uint8_t> all(v);
    for (std::size_t cut = 0; cut < 9 && cut <= v.size(); ++cut) {
      REQUIRE(seawire::crc32(all.subspan(cut)) == bytewise(all.subspan(cut), 0));
      REQUIRE(seawire::crc32_update(seawire::crc32(all.first(cut)), all.subspan(cut)) ==
              bytewise(all, 0));
    }
  }
  static_assert(seawire::crc32("123456789") == 0xCBF43926U);
}

namespace {
// Three lengths of address, any-talker and fixed, and one longer than a key's eight bytes.
struct m8 {
  int x = 0;
  static constexpr auto nmea = sentence<"PABCDEFG">(field<&m8::x>("x"));
};
struct m10 {
  int x = 0;
  static constexpr auto nmea = sentence<"PAPGPSCTRL">(field<&m10::x>("x"));
};
struct m1 {
  int x = 0;
  static constexpr auto nmea = sentence<"Z">(field<&m1::x>("x"));
};
template <class... Ms>
bool by_string(nmea::message_set<Ms...>*, std::string_view a) {
  return (Ms::nmea.matches(a) || ...);
}
}  // namespace

TEST_CASE("dispatch by address key finds what string comparison finds") {
  using set = message_set<standard::rmc, standard::gga, standard::vwr, m8, m10, m1>;
  static constexpr std::string_view seeds[] = {
      "GPRMC", "GNGGA", "PGRMC", "IIVWR",  "PABCDEFG", "PAPGPSCTRL", "PAPGPSCTRX",
      "Z",     "ZZ",    "RMC",   "GPRMCX", "PABCDEF",  "PABCDEFGH"};
  prng g{29};
  for (int k = 0; k < 100000; ++k) {
    std::string a(seeds[g.below(std::size(seeds))]);
    if (!a.empty() && g.below(2) == 0) a[g.below(a.size())] = static_cast<char>('A' + g.below(26));
    INFO(a);
    REQUIRE(set::knows(a) == by_string(static_cast<set*>(nullptr), a));
  }
  static_assert(set::knows("GPRMC") && set::knows("PAPGPSCTRL") && !set::knows("PGRMC"));
}

TEST_CASE("the address key read in one load is the key read byte by byte") {
  prng g{99};
  for (int k = 0; k < 20000; ++k) {
    std::string line = "$";
    const std::size_t n = 1 + g.below(15);
    for (std::size_t i = 0; i < n; ++i) line += static_cast<char>('A' + g.below(26));
    if (g.below(3) != 0) line += ",1,2";
    const auto s = parse(line);
    REQUIRE(s);
    INFO(line);
    const nmea::detail::address_key fast = nmea::detail::key_of(s.value);
    const nmea::detail::address_key slow = nmea::detail::key_of(s.value.address);
    CHECK(fast.head == slow.head);
    CHECK(fast.size == slow.size);
  }
}

TEST_CASE("eight digits at a time: which bytes are digits, and the number the first k spell") {
  using seawire::detail::digits_value;
  using seawire::detail::load_le64;
  using seawire::detail::non_digit_bytes;
  // Every byte value at every position of a word of digits.
  for (unsigned at = 0; at < 8; ++at) {
    for (unsigned b = 0; b < 256; ++b) {
      char bytes[8] = {'1', '2', '3', '4', '5', '6', '7', '8'};
      bytes[at] = static_cast<char>(b);
      const std::uint64_t other = non_digit_bytes(load_le64(bytes));
      const bool digit = b >= '0' && b <= '9';
      INFO(at << " " << b);
      CHECK(other == (digit ? 0U : std::uint64_t{0x80} << (8U * at)));
    }
  }
  // The value of every prefix of words of varied digits, against a loop.
  std::uint64_t state = 0x9E3779B97F4A7C15U;
  for (int round = 0; round < 2000; ++round) {
    char bytes[8];
    for (char& c : bytes) {
      state = state * 6364136223846793005U + 1442695040888963407U;
      c = static_cast<char>('0' + (state >> 60U) % 10);
    }
    std::uint64_t want = 0;
    for (unsigned k = 1; k <= 8; ++k) {
      want = want * 10 + static_cast<unsigned>(bytes[k - 1] - '0');
      CHECK(digits_value(load_le64(bytes), k) == want);
    }
  }
  static_assert(digits_value(load_le64("99999999"), 8) == 99999999);
  static_assert(digits_value(load_le64("4807.038"), 4) == 4807);
}

TEST_CASE("eight_digits: numbers below 10^8 as their eight digits") {
  using seawire::detail::eight_digits;
  // Each half of the number is split in a lane of its own by the same arithmetic: every value of
  // each half, beside a few of the other, against std::to_string.
  const auto check = [](std::uint64_t v) {
    std::string want = std::to_string(v);
    want.insert(want.begin(), 8 - want.size(), '0');
    const std::uint64_t w = eight_digits(v);
    std::string got(8, ' ');
    for (unsigned i = 0; i < 8; ++i) got[i] = static_cast<char>((w >> (8U * i)) & 0xFFU);
    return got == want;
  };
  bool all = true;
  for (std::uint64_t a = 0; a < 10000; ++a) {
    for (const std::uint64_t b :
         {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{9}, std::uint64_t{10},
          std::uint64_t{99}, std::uint64_t{100}, std::uint64_t{4321}, std::uint64_t{9999}, a}) {
      all = all && check(a * 10000 + b) && check(b * 10000 + a);
    }
  }
  CHECK(all);
  static_assert(eight_digits(12345678) == 0x3837363534333231U);
  static_assert(eight_digits(0) == 0x3030303030303030U);
  static_assert(eight_digits(99999999) == 0x3939393939393939U);
}

// append_fixed_wide writes what append_fixed writes, for every count of digits, fraction places
// and zero padding, and nothing before where the number starts.
TEST_CASE("append_fixed_wide writes the digits append_fixed writes") {
  using seawire::detail::append_fixed;
  using seawire::detail::append_fixed_wide;
  using seawire::detail::fixed_word_room;
  using seawire::detail::integer_digits;
  prng g{20261129};
  const auto check = [](std::uint64_t v, unsigned places, unsigned int_digits) {
    char a[80];
    char b[80];
    std::fill(std::begin(a), std::end(a), 'x');
    std::fill(std::begin(b), std::end(b), 'x');
    const std::size_t end_a = append_fixed(a, 3, v, places, int_digits);
    const std::size_t end_b = append_fixed_wide(b, 3, v, places, int_digits);
    INFO(v << " places " << places << " integer digits " << int_digits);
    REQUIRE(end_b == end_a);
    REQUIRE(std::string_view(b, end_b) == std::string_view(a, end_a));
    // Nothing past the number and the room it may use, nothing before it.
    const std::size_t used = std::max(end_b, std::size_t{3} + fixed_word_room);
    REQUIRE(std::all_of(b + used, std::end(b), [](char c) { return c == 'x'; }));
    REQUIRE(std::string_view(b, 3) == "xxx");
  };
  for (int k = 0; k < 200000; ++k) {
    const unsigned digits = 1 + static_cast<unsigned>(g.below(20));
    const std::uint64_t v =
        digits == 20 ? g.next() : g.next() % seawire::detail::pow10_table[digits];
    const unsigned places = static_cast<unsigned>(g.below(20));
    const unsigned min = static_cast<unsigned>(g.below(22));
    check(v, places, integer_digits(v, places, min, seawire::detail::max_integer_digits));
  }
  // Around 16 digits, where the word path ends, and 8, where its second word begins.
  for (unsigned places = 0; places <= 17; ++places) {
    for (const std::uint64_t v :
         {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{99999999}, std::uint64_t{100000000},
          std::uint64_t{9999999999999999}, std::uint64_t{10000000000000000}, ~std::uint64_t{0}}) {
      for (unsigned min = 1; min <= 18; ++min) {
        check(v, places, integer_digits(v, places, min, seawire::detail::max_integer_digits));
      }
    }
  }
  // At compile time, the digit-pair path.
  static_assert([] {
    char out[40]{};
    const std::size_t end = append_fixed_wide(out, 0, 4807038, 3, 4);
    return std::string_view(out, end) == "4807.038";
  }());
}
