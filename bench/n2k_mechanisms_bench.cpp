// SPDX-License-Identifier: BSL-1.0
// NMEA 2000: one row per field mechanism and per framing step, so that what each costs shows
// apart, beside a baseline that copies the same bytes and sums them. Items are CAN frames (8
// bytes each), so items_per_second is frames per second.
//
//   n2k/mechanism/baseline            each 8-byte payload copied to a buffer and summed
//   n2k/mechanism/numbers             decode of 8 bytes of four numbers (16 bits, signed and
//                                     unsigned, with resolutions), each read as a double
//   n2k/mechanism/lookups             decode of 2 bytes of four lookups (2, 3, 3 and 8 bits),
//                                     each read as its name
//   n2k/mechanism/flags               decode of 8 bytes of four 16-bit flag words, each bit
//                                     tested
//   n2k/mechanism/is_fast_packet_pgn  the standard's fast-packet list looked up (binary search)
//                                     for 1,000 PGNs of a bus
//   n2k/mechanism/fast_packet/undescribed  log_reader::read_line of `candump -L` lines of a
//                                     proprietary fast-packet PGN no PGN set declares (130842,
//                                     20 bytes in 3 frames): parsed, assembled by the list
//
// Adding a mechanism (strings, repeating groups, ...): a struct of four fields of that mechanism
// (`four_fields` below, or one of its own; a PGN number of the proprietary range, as no registry
// holds it), its corpus (`corpus_of`, from random raw values), a reader of its fields (`read`),
// and one BENCHMARK line naming the row `n2k/mechanism/<kind>`.

#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "corpus.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/fast_packet.hpp"
#include "seawire/nmea2000/fast_packets.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/nmea2000/reader.hpp"
#include "seawire/registry.hpp"
#include "support.hpp"

namespace {

using namespace seawire;
namespace n2k = seawire::nmea2000;
namespace sb = seawire::bench;

constexpr std::size_t frame_count = 1000;

// ---------------------------------------------------------------------------------------------
// one struct per mechanism (PGN numbers of the proprietary single-frame range: no registry
// holds them)

/// Four fields of types A-D (the payload as long as they are).
template <class A, class B, class C, class D, std::uint32_t Pgn>
struct four_fields {
  A a;
  B b;
  C c;
  D d;
  static constexpr auto n2k = n2k::describe_pgn(
      n2k::pgn_info{Pgn, "four_fields", "four fields", 6, n2k::framing::single_frame, 0},
      n2k::field<&four_fields::a>("a", "a"), n2k::field<&four_fields::b>("b", "b"),
      n2k::field<&four_fields::c>("c", "c"), n2k::field<&four_fields::d>("d", "d"));
  [[nodiscard]] constexpr bool operator==(const four_fields&) const noexcept = default;
};

using mechanism_numbers = four_fields<n2k::signed_number<16, n2k::res::radian>,
                                      n2k::unsigned_number<16, n2k::res::hundredth>,
                                      n2k::signed_number<16, n2k::res::thousandth>,
                                      n2k::unsigned_number<16, n2k::res::radian>, 65280>;
using mechanism_lookups =
    four_fields<n2k::lookup<n2k::heading_reference, 2>, n2k::lookup<n2k::rudder_direction, 3>,
                n2k::lookup<n2k::wind_reference, 3>, n2k::lookup<n2k::temperature_source, 8>,
                65281>;
using mechanism_flags =
    four_fields<n2k::flags<n2k::engine_status_1, 16>, n2k::flags<n2k::engine_status_2, 16>,
                n2k::flags<n2k::engine_status_1, 16>, n2k::flags<n2k::engine_status_2, 16>, 65282>;

// ---------------------------------------------------------------------------------------------
// corpora: random raw values of every field (10% not available), written by the library's
// encoder, deterministic (splitmix64)

template <n2k::pgn_like P>
std::vector<std::vector<std::uint8_t>> corpus_of(std::uint64_t seed) {
  sb::rng r(seed);
  std::vector<std::vector<std::uint8_t>> out;
  while (out.size() < frame_count) {
    P m{};
    P::n2k.for_each([&](const auto& f, unsigned, std::uint16_t) {
      using F = std::remove_cvref_t<decltype(f)>;
      if constexpr (!F::is_reserved) {
        using V = typename F::value_type;
        const auto top = static_cast<std::uint64_t>(V::top_raw);
        std::int64_t raw = static_cast<std::int64_t>(r.next() % (top + 1));
        if constexpr (requires { V::max_valid_raw; }) {
          raw = static_cast<std::int64_t>(r.next() %
                                          (static_cast<std::uint64_t>(V::max_valid_raw) + 1));
        }
        if constexpr (V::is_signed) raw -= static_cast<std::int64_t>((top + 1) / 2);
        m.*F::member = r.chance(0.1) ? V{} : V::from_raw(raw);
      }
    });
    const auto e = n2k::encode(m);
    if (!e) continue;  // a value the encoder refuses (a sentinel of a signed number): draw again
    out.emplace_back(e.value.begin(), e.value.end());
  }
  return out;
}

template <class V>
void read(sb::sink& s, const V& v) noexcept {
  if constexpr (requires { v.name(); }) {
    s.bits += v.name().size();  // a lookup: its name
  } else if constexpr (requires { v.test_bit(0U); }) {
    for (unsigned b = 0; b < V::bits; ++b) s.bits += v.test_bit(b) ? b : 0U;  // flags
  } else {
    s.sum += v.value().value_or(0.0);  // a number in its unit
  }
}

template <n2k::pgn_like P>
void decode_row(benchmark::State& state, std::uint64_t seed) {
  const std::vector<std::vector<std::uint8_t>> corpus = corpus_of<P>(seed);
  sb::sink s;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const std::vector<std::uint8_t>& payload : corpus) {
      const P m = n2k::decode<P>(payload);
      P::n2k.for_each([&](const auto& f, unsigned, std::uint16_t) {
        using F = std::remove_cvref_t<decltype(f)>;
        if constexpr (!F::is_reserved) read(s, m.*F::member);
      });
      benchmark::DoNotOptimize(s);
    }
  }
  std::size_t bytes = 0;
  for (const std::vector<std::uint8_t>& payload : corpus) bytes += payload.size();
  sb::report(state, corpus.size(), bytes, sb::allocation_count() - before);
}

void baseline(benchmark::State& state) {
  const std::vector<std::vector<std::uint8_t>> corpus = corpus_of<mechanism_numbers>(65280);
  std::array<std::uint8_t, 8> copy{};
  std::uint64_t sum = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const std::vector<std::uint8_t>& payload : corpus) {
      std::memcpy(copy.data(), payload.data(), copy.size());
      benchmark::DoNotOptimize(copy);
      for (const std::uint8_t b : copy) sum += b;
    }
    benchmark::DoNotOptimize(sum);
  }
  sb::report(state, corpus.size(), corpus.size() * 8, sb::allocation_count() - before);
}

void numbers(benchmark::State& state) { decode_row<mechanism_numbers>(state, 65280); }
void lookups(benchmark::State& state) { decode_row<mechanism_lookups>(state, 65281); }
void flag_words(benchmark::State& state) { decode_row<mechanism_flags>(state, 65282); }

// ---------------------------------------------------------------------------------------------
// framing

/// The PGNs of a bus as they come: the declared ones and the proprietary and standard ones
/// around them, single-frame and fast.
void is_fast(benchmark::State& state) {
  constexpr std::array<std::uint32_t, 16> bus = {127250, 127251, 127257, 129025, 129026, 127245,
                                                 65359,  126720, 129029, 129540, 130842, 128259,
                                                 130306, 59392,  127489, 126208};
  std::vector<std::uint32_t> pgns;
  sb::rng r(126720);
  for (std::size_t i = 0; i < frame_count; ++i) pgns.push_back(r.pick(bus));
  std::uint64_t fast = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const std::uint32_t pgn : pgns) {
      benchmark::DoNotOptimize(pgn);
      fast += n2k::is_fast_packet_pgn(pgn) ? 1U : 0U;
    }
    benchmark::DoNotOptimize(fast);
  }
  sb::report(state, pgns.size(), pgns.size() * 4, sb::allocation_count() - before);
}

/// `candump -L` lines of a proprietary fast-packet PGN (130842, 20 bytes: 3 frames), from two
/// sources interleaved, 10 ms apart.
std::string undescribed_lines() {
  std::string text;
  sb::rng r(130842);
  n2k::log_record rec;
  (void)rec.interface.assign("can0");
  std::size_t lines = 0;
  for (std::size_t packet = 0; lines < frame_count; ++packet) {
    std::array<std::uint8_t, 20> payload{};
    for (std::uint8_t& b : payload) b = static_cast<std::uint8_t>(r.next());
    const auto frames = n2k::split_fast_packet(payload, static_cast<std::uint8_t>(packet % 8));
    if (!frames) std::abort();
    for (const n2k::frame_data& f : frames.value.view()) {
      rec.id = {7, 130842, static_cast<std::uint8_t>(packet % 2 == 0 ? 0x0C : 0x0D), 255};
      rec.time_us = 1'720'021'378'000'000 + static_cast<std::int64_t>(lines) * 10'000;
      nmea::json_buffer<128> line;
      if (!rec.assign(f.view()) ||
          n2k::write_log_line(line, rec, n2k::log_format::candump_log) != errc::ok)
        std::abort();
      text += line.view();
      ++lines;
    }
  }
  return text;
}

void undescribed_fast(benchmark::State& state) {
  const std::string text = undescribed_lines();
  n2k::log_reader<registry::pgns> reader;
  std::uint64_t bytes = 0;
  std::size_t lines = 0;
  sb::for_each_line(text, [&](std::string_view) { ++lines; });
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    sb::for_each_line(text, [&](std::string_view line) {
      (void)reader.read_line(
          line, [&](const n2k::message_header&, std::span<const std::uint8_t> payload) {
            bytes += payload.size() + payload[0];
          });
    });
    benchmark::DoNotOptimize(bytes);
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  if (reader.assembler().frames_dropped() != 0 || reader.assembler().packets() == 0)
    state.SkipWithError("undescribed: a frame was dropped, or nothing assembled");
  sb::report(state, lines, text.size(), allocations);
}

BENCHMARK(baseline)->Name("n2k/mechanism/baseline");
BENCHMARK(numbers)->Name("n2k/mechanism/numbers");
BENCHMARK(lookups)->Name("n2k/mechanism/lookups");
BENCHMARK(flag_words)->Name("n2k/mechanism/flags");
BENCHMARK(is_fast)->Name("n2k/mechanism/is_fast_packet_pgn");
BENCHMARK(undescribed_fast)->Name("n2k/mechanism/fast_packet/undescribed");

}  // namespace
