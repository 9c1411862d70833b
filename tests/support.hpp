// SPDX-License-Identifier: BSL-1.0
#pragma once
// What many tests need: a sentence sealed with its right checksum, a deterministic random number
// generator, a stream cut into random chunks, and the check of a table of malformed sentences
// (each with the errc and the field number decode must report).

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hex_of.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/stream.hpp"

namespace support {

/// The doubles that no field may carry.
inline constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
inline constexpr double infinity = std::numeric_limits<double>::infinity();

/// A hand decode for checking binary payloads: `n` bytes at byte `at`, least significant first.
inline std::uint64_t le(const std::vector<std::uint8_t>& p, std::size_t at, std::size_t n) {
  std::uint64_t v = 0;
  for (std::size_t k = 0; k < n; ++k) v |= std::uint64_t{p[at + k]} << (8 * k);
  return v;
}

/// "$" body "*HH" CR LF with the right checksum, so that a table row can break one field only.
/// The XOR is computed here rather than by nmea::checksum, so that a checksum broken in the
/// library cannot agree with itself in the tests.
inline std::string sealed(std::string_view body) {
  std::uint8_t x = 0;
  for (const char c : body) x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(c));
  constexpr std::string_view hex = "0123456789ABCDEF";
  std::string s = "$";
  s += body;
  s += '*';
  s += hex[x >> 4U];
  s += hex[x & 15U];
  s += "\r\n";
  return s;
}

/// A line that starts with '$' or '!' (and may end in a checksum) with its checksum made right
/// and CR LF after it.
inline std::string resealed(std::string_view line) {
  const std::string_view data = line.substr(0, line.find('*'));
  std::string s = sealed(data.substr(1));
  s[0] = data[0];
  return s;
}

/// splitmix64: tiny and the same on every platform (std distributions are not), so a failure
/// names an input that can be replayed from its seed.
struct prng {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15U);
    z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9U;
    z = (z ^ (z >> 27U)) * 0x94D049BB133111EBU;
    return z ^ (z >> 31U);
  }
  /// 0 .. n-1 (n > 0); uniform enough for tests.
  std::uint64_t below(std::uint64_t n) { return next() % n; }
  bool chance(unsigned percent) { return below(100) < percent; }
  bool coin() { return (next() & 1U) != 0; }
  /// lo .. hi, both included.
  std::int64_t between(std::int64_t lo, std::int64_t hi) {
    const auto span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
    if (span == std::numeric_limits<std::uint64_t>::max()) return static_cast<std::int64_t>(next());
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) + next() % (span + 1));
  }
};

/// Splits `s` into chunks of 1..max_chunk bytes, as reads from a socket or a port may come.
inline std::vector<std::string_view> chop(std::string_view s, prng& r, std::size_t max_chunk) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const std::size_t n = std::min(s.size() - i, 1 + r.below(max_chunk));
    out.push_back(s.substr(i, n));
    i += n;
  }
  return out;
}

/// A maximum chunk size spread over 1..4096 roughly log-uniformly, so tiny chunks get their share.
inline std::size_t pick_max_chunk(prng& r) {
  const std::size_t bits = r.below(13);  // 2^0 .. 2^12
  const std::size_t base = std::size_t{1} << bits;
  return std::min<std::size_t>(4096, base + r.below(base));
}

/// `text` quoted for a failure message: printable ASCII as is, other bytes as \xNN, cut after 60
/// bytes (then its size).
inline std::ostream& quote_text(std::ostream& os, std::string_view text) {
  os << '"';
  for (const char c : text.substr(0, 60)) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7F) {
      os << c;
    } else {
      os << "\\x"
         << "0123456789abcdef"[u >> 4] << "0123456789abcdef"[u & 15];
    }
  }
  if (text.size() > 60) os << "...(" << text.size() << ")";
  return os << '"';
}

/// A line ending's name, for failure messages.
inline const char* ending_name(seawire::nmea::line_ending e) {
  switch (e) {
    case seawire::nmea::line_ending::none: return "none";
    case seawire::nmea::line_ending::lf: return "lf";
    case seawire::nmea::line_ending::cr: return "cr";
    case seawire::nmea::line_ending::crlf: return "crlf";
  }
  return "?";
}

/// A sink for the text writers (JSON, CSV): what they put, kept as a string.
struct string_sink {
  std::string s;
  void put(char c) { s += c; }
  void put(std::string_view v) { s += v; }
};

/// decode<T>(line), which must succeed (the test case stops here if not).
template <class T>
T must_decode(std::string_view line) {
  const auto r = seawire::nmea::decode<T>(line);
  REQUIRE(r);
  return r.value;
}

/// A malformed sentence and what decode must say of it.
struct bad_case {
  std::string body;  ///< between '$' and '*'; sealed with the right checksum
  seawire::errc ec;
  std::uint16_t field;
};

/// decode(sealed(c.body)) must fail with c.ec at field c.field.
template <class Decode>
void check_bad(const bad_case& c, Decode&& decode) {
  const std::string line = sealed(c.body);
  INFO(line);
  const auto r = decode(std::string_view(line));
  CHECK(seawire::name(r.ec) == seawire::name(c.ec));
  CHECK(r.field == c.field);
}

/// The same through nmea::decode<M> under `policy`.
template <class M>
void check_bad(const bad_case& c, const seawire::nmea::parse_policy& policy = {}) {
  check_bad(c, [&](std::string_view line) { return seawire::nmea::decode<M>(line, policy); });
}

/// copy(out, in, n) for every n in 0..most: it writes exactly in[0, n) at out, and nothing before
/// or after it (the short-piece copies of the library and of the programs' output).
template <class Copy>
void check_copies_exactly(Copy&& copy, std::size_t most) {
  prng g{41};
  std::string from(most + 8, '\0');
  for (char& c : from) c = static_cast<char>(g.next());
  for (std::size_t n = 0; n <= most; ++n) {
    INFO("n " << n);
    std::string to(most + 12, '.');
    copy(to.data() + 4, from.data() + 3, n);
    CHECK(to.substr(0, 4) == "....");
    CHECK(to.substr(4, n) == from.substr(3, n));
    CHECK(to.substr(4 + n) == std::string(most + 8 - n, '.'));
  }
}

}  // namespace support
