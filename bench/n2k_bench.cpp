// SPDX-License-Identifier: BSL-1.0
// NMEA 2000 benchmarks: single-frame decode, fast-packet assembly and CAN log line parsing, each
// over 1,000 frames (or lines) beside a baseline that copies the same bytes and sums them, so
// the ratio says what the library adds to merely touching the data. Items are CAN frames (or log
// lines, one frame each), so items_per_second is frames per second.
//
//   n2k/baseline/<corpus>        each frame's (line's) bytes copied to a buffer and summed
//   n2k/decode/128259, /130311   decode<P> of an 8-byte payload, then every field read (numbers
//                                as doubles in their unit, lookups, sentinel states)
//   n2k/assemble/127489          fast_packet_assembler::feed of 250 packets of 4 frames each
//   n2k/parse_log_line/candump_log   parse_log_line (format detected) of `candump -L` lines
//   n2k/read_line+decode/candump_log log_reader::read_line of the same lines: parse, assemble
//                                the fast packets, decode every message and read its fields

#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "corpus.hpp"
#include "seawire/nmea2000/fast_packet.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/nmea2000/reader.hpp"
#include "support.hpp"

namespace {

using namespace seawire;
namespace n2k = seawire::nmea2000;
namespace sb = seawire::bench;

constexpr std::size_t frame_count = 1000;
using frame = std::array<std::uint8_t, 8>;

// ---------------------------------------------------------------------------------------------
// corpora: deterministic (splitmix64), written by the library's own encoders

/// A raw value for a field, mostly ordinary, sometimes a sentinel (senders leave fields out).
template <class V>
V some_value(sb::rng& r, std::int64_t lo, std::int64_t hi) {
  if (r.chance(0.1)) return V::from_raw(V::top_raw);  // not available
  return V::from_raw(lo +
                     static_cast<std::int64_t>(r.next() % static_cast<std::uint64_t>(hi - lo + 1)));
}

template <n2k::pgn_like P>
frame payload(const P& m) {
  const auto e = n2k::encode(m);
  if (!e) std::abort();  // a generator bug, not a measurement
  frame f{};
  std::memcpy(f.data(), e.value.data(), f.size());
  return f;
}

const std::vector<frame>& frames_128259() {
  static const std::vector<frame> out = [] {
    sb::rng r(128259);
    std::vector<frame> v;
    for (std::size_t i = 0; i < frame_count; ++i) {
      n2k::speed_water_referenced m;
      m.sid = decltype(m.sid)::from_raw(static_cast<std::int64_t>(i % 253));
      m.speed_water_mps = some_value<decltype(m.speed_water_mps)>(r, 0, 1500);  // up to 15 m/s
      m.speed_ground_mps = some_value<decltype(m.speed_ground_mps)>(r, 0, 1500);
      m.speed_type = decltype(m.speed_type)::from_raw(r.between(0, 4));
      v.push_back(payload(m));
    }
    return v;
  }();
  return out;
}

const std::vector<frame>& frames_130311() {
  static const std::vector<frame> out = [] {
    sb::rng r(130311);
    std::vector<frame> v;
    for (std::size_t i = 0; i < frame_count; ++i) {
      n2k::environmental_parameters m;
      m.sid = decltype(m.sid)::from_raw(static_cast<std::int64_t>(i % 253));
      m.temperature_source = decltype(m.temperature_source)::from_raw(r.between(0, 2));
      m.humidity_source = decltype(m.humidity_source)::from_raw(r.between(0, 1));
      m.temperature_k = some_value<decltype(m.temperature_k)>(r, 26315, 31315);  // -10..40 C
      m.humidity_pct = some_value<decltype(m.humidity_pct)>(r, 5000, 25000);     // 20..100 %
      m.atmospheric_pressure_pa =
          some_value<decltype(m.atmospheric_pressure_pa)>(r, 950, 1050);  // hPa
      v.push_back(payload(m));
    }
    return v;
  }();
  return out;
}

/// 250 packets of 127489 (26 bytes, 4 frames each), from one engine, as a sender sends them.
const std::vector<frame>& frames_127489() {
  static const std::vector<frame> out = [] {
    sb::rng r(127489);
    std::vector<frame> v;
    for (std::size_t i = 0; v.size() < frame_count; ++i) {
      n2k::engine_parameters_dynamic m;
      m.instance = decltype(m.instance)::from_raw(0);
      m.oil_pressure_pa = some_value<decltype(m.oil_pressure_pa)>(r, 2000, 5000);
      m.oil_temperature_k = some_value<decltype(m.oil_temperature_k)>(r, 3300, 3800);
      m.temperature_k = some_value<decltype(m.temperature_k)>(r, 33000, 36000);
      m.alternator_potential_v = some_value<decltype(m.alternator_potential_v)>(r, 1300, 1450);
      m.fuel_rate_lph = some_value<decltype(m.fuel_rate_lph)>(r, 0, 400);
      m.total_engine_hours_s =
          decltype(m.total_engine_hours_s)::from_raw(static_cast<std::int64_t>(3'600'000 + i));
      // No alarm: the flag words are sent, all clear (a field after a flag word that is not
      // available is refused).
      m.discrete_status_1 = decltype(m.discrete_status_1)::from_raw(0);
      m.discrete_status_2 = decltype(m.discrete_status_2)::from_raw(0);
      m.engine_load_pct = some_value<decltype(m.engine_load_pct)>(r, 0, 100);
      const auto e = n2k::encode(m);
      const auto split = n2k::split_fast_packet(e.value, static_cast<std::uint8_t>(i % 8));
      if (!e || !split) std::abort();
      for (const n2k::frame_data& f : split.value.view()) v.push_back(f.bytes);
    }
    return v;
  }();
  return out;
}

/// `candump -L` lines: the frames above interleaved as a bus carries them, in tens: eight frames
/// of 127489 (two packets, from source 0x01), one 128259 (0x23), one 130311 (0x24); 10 ms apart.
const std::string& candump_lines() {
  static const std::string out = [] {
    std::string text;
    struct string_sink {
      std::string* s;
      void put(char c) { s->push_back(c); }
      void put(std::string_view v) { s->append(v); }
    } put{&text};
    n2k::log_record rec;
    (void)rec.interface.assign("can0");
    const std::vector<frame>* sources[] = {&frames_128259(), &frames_130311(), &frames_127489()};
    const n2k::can_id ids[] = {
        {2, 128259, 0x23, 255}, {5, 130311, 0x24, 255}, {2, 127489, 0x01, 255}};
    std::array<std::size_t, 3> next{};
    for (std::size_t i = 0; i < frame_count; ++i) {
      const std::size_t k = i % 10 == 0 ? 0 : i % 10 == 5 ? 1 : 2;
      rec.id = ids[k];
      rec.time_us = 1'720'021'378'000'000 + static_cast<std::int64_t>(i) * 10'000;
      if (!rec.assign((*sources[k])[next[k]++]) ||
          n2k::write_log_line(put, rec, n2k::log_format::candump_log) != errc::ok)
        std::abort();
    }
    return text;
  }();
  return out;
}

// ---------------------------------------------------------------------------------------------
// reading every field, as a user would

template <class V>
void read_field(sb::sink& s, const V& v) noexcept {
  s.bits += static_cast<std::uint64_t>(v.raw()) + static_cast<std::uint64_t>(v.state());
  if constexpr (requires { v.exact(); }) s.sum += v.value().value_or(0.0);  // numbers
}

template <n2k::pgn_like P>
void read_all(sb::sink& s, const P& m) noexcept {
  n2k::pgn_table<P>.for_each([&](const auto& f, unsigned, std::uint16_t) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (!F::is_reserved) read_field(s, m.*F::member);
  });
}

// ---------------------------------------------------------------------------------------------
// the baseline

void baseline_frames(benchmark::State& state, const std::vector<frame>& frames) {
  frame copy{};
  std::uint64_t sum = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const frame& f : frames) {
      std::memcpy(copy.data(), f.data(), f.size());
      benchmark::DoNotOptimize(copy);
      for (const std::uint8_t b : copy) sum += b;
    }
    benchmark::DoNotOptimize(sum);
  }
  sb::report(state, frames.size(), frames.size() * sizeof(frame), sb::allocation_count() - before);
}

void baseline_lines(benchmark::State& state) {
  const std::string& text = candump_lines();
  std::array<char, 256> copy{};
  std::uint64_t sum = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    sb::for_each_line(text, [&](std::string_view line) {
      std::memcpy(copy.data(), line.data(), line.size());
      benchmark::DoNotOptimize(copy);
      for (std::size_t i = 0; i < line.size(); ++i) sum += static_cast<unsigned char>(copy[i]);
    });
    benchmark::DoNotOptimize(sum);
  }
  sb::report(state, frame_count, text.size(), sb::allocation_count() - before);
}

// ---------------------------------------------------------------------------------------------
// the library

template <n2k::pgn_like P>
void decode_frames(benchmark::State& state, const std::vector<frame>& frames) {
  sb::sink s;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const frame& f : frames) {
      const P m = n2k::decode<P>(f);
      read_all(s, m);
      benchmark::DoNotOptimize(s);
    }
  }
  sb::report(state, frames.size(), frames.size() * sizeof(frame), sb::allocation_count() - before);
}

void assemble_127489(benchmark::State& state) {
  const std::vector<frame>& frames = frames_127489();
  const n2k::can_id id{2, 127489, 0x01, 255};
  n2k::fast_packet_assembler<> a;
  std::uint64_t bytes = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const frame& f : frames) {
      const auto done = a.feed(id, f);
      if (done) bytes += done->payload.size() + done->payload[0];
    }
    benchmark::DoNotOptimize(bytes);
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  if (a.frames_dropped() != 0 || a.frames_pending() != 0)
    state.SkipWithError("assemble: a frame was dropped");
  sb::report(state, frames.size(), frames.size() * sizeof(frame), allocations);
}

void parse_candump(benchmark::State& state) {
  const std::string& text = candump_lines();
  std::size_t bad = 0;
  std::uint64_t sum = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    sb::for_each_line(text, [&](std::string_view line) {
      const result<n2k::log_record> r = n2k::parse_log_line(line);
      if (!r) ++bad;
      sum +=
          r.value.id.pgn + r.value.size + static_cast<std::uint64_t>(r.value.time_us.value_or(0));
      benchmark::DoNotOptimize(r);
    });
    benchmark::DoNotOptimize(sum);
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  if (bad != 0) state.SkipWithError("parse_log_line: a line did not parse");
  sb::report(state, frame_count, text.size(), allocations);
}

void read_decode_candump(benchmark::State& state) {
  const std::string& text = candump_lines();
  n2k::log_reader<> reader;
  sb::sink s;
  std::size_t bad = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    sb::for_each_line(text, [&](std::string_view line) {
      const auto r = reader.read_line(line, [&](const n2k::message_header& h,
                                                std::span<const std::uint8_t> payload) {
        (void)n2k::ins_input_pgns::visit(h.id.pgn, payload, [&](const auto& m) { read_all(s, m); });
      });
      if (!r) ++bad;
      benchmark::DoNotOptimize(s);
    });
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  if (bad != 0 || reader.assembler().frames_dropped() != 0)
    state.SkipWithError("read_line: a line did not parse or a frame was dropped");
  sb::report(state, frame_count, text.size(), allocations);
}

void baseline_128259(benchmark::State& state) { baseline_frames(state, frames_128259()); }
void baseline_130311(benchmark::State& state) { baseline_frames(state, frames_130311()); }
void baseline_127489(benchmark::State& state) { baseline_frames(state, frames_127489()); }
void decode_128259(benchmark::State& state) {
  decode_frames<n2k::speed_water_referenced>(state, frames_128259());
}
void decode_130311(benchmark::State& state) {
  decode_frames<n2k::environmental_parameters>(state, frames_130311());
}

BENCHMARK(baseline_128259)->Name("n2k/baseline/128259");
BENCHMARK(decode_128259)->Name("n2k/decode/128259");
BENCHMARK(baseline_130311)->Name("n2k/baseline/130311");
BENCHMARK(decode_130311)->Name("n2k/decode/130311");
BENCHMARK(baseline_127489)->Name("n2k/baseline/127489");
BENCHMARK(assemble_127489)->Name("n2k/assemble/127489");
BENCHMARK(baseline_lines)->Name("n2k/baseline/candump_log");
BENCHMARK(parse_candump)->Name("n2k/parse_log_line/candump_log");
BENCHMARK(read_decode_candump)->Name("n2k/read_line+decode/candump_log");

}  // namespace
