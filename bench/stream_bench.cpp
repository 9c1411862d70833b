// SPDX-License-Identifier: BSL-1.0
// Byte-level benchmarks: the framer over a stream read in 4 KiB chunks (alone and followed by a
// full decode), the NMEA checksum, CRC-32, and the ANELLO 0xAB00 binary frame.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "corpus.hpp"
#include "seawire/detail/crc32.hpp"
#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/framer.hpp"
#include "support.hpp"

namespace {

using namespace seawire;
namespace sb = seawire::bench;

constexpr std::size_t corpus_size = 1000;
constexpr std::size_t chunk_size = 4096;

const sb::family_corpus<sb::rmc_gga_set>& rmc_gga() {
  static const auto c = sb::rmc_gga_corpus(corpus_size);
  return c;
}

/// Every family's corpus, interleaved in blocks: a log of everything seawire reads.
const sb::corpus& mixed() {
  static const sb::corpus c = [] {
    std::vector<sb::corpus> parts;
    parts.push_back(sb::rmc_gga_corpus(corpus_size));
    parts.push_back(sb::anello_inputs_corpus(corpus_size));
    parts.push_back(sb::sandshark_from_vehicle_corpus(corpus_size));
    parts.push_back(sb::sandshark_to_vehicle_corpus(corpus_size));
    parts.push_back(sb::robotx_corpus(corpus_size));
#if SEAWIRE_BENCH_HAS_KINGFISHER
    parts.push_back(sb::kingfisher_from_vehicle_corpus(corpus_size));
    parts.push_back(sb::kingfisher_to_vehicle_corpus(corpus_size));
#endif
    sb::corpus out;
    for (std::size_t i = 0; i < corpus_size; i += 10) {
      for (const sb::corpus& p : parts) {
        for (std::size_t k = i; k < i + 10 && k < p.size(); ++k) out.append(p.lines[k]);
      }
    }
    return out;
  }();
  return c;
}

// ---------------------------------------------------------------------------------------------
// framer

template <class OnLine>
void run_framer(benchmark::State& state, const sb::corpus& c, OnLine on_line) {
  nmea::framer<1024> framer;
  std::size_t lines = 0;
  const std::string_view bytes = c.bytes;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (std::size_t at = 0; at < bytes.size(); at += chunk_size) {
      framer.feed(bytes.substr(at, chunk_size));
      while (const std::optional<nmea::framed_line> l = framer.next()) {
        ++lines;
        on_line(l->text);
      }
    }
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  if (lines != c.size() * static_cast<std::size_t>(state.iterations()))
    state.SkipWithError("framer: lost or invented lines");
  sb::report(state, c.size(), c.bytes.size(), allocations);
}

void framer_only(benchmark::State& state, const sb::corpus& c) {
  std::size_t total = 0;
  run_framer(state, c, [&](std::string_view text) {
    total += text.size();
    benchmark::DoNotOptimize(total);
  });
}

void framer_decode_rmc_gga(benchmark::State& state) {
  sb::sink s;
  std::size_t bad = 0;
  run_framer(state, rmc_gga(), [&](std::string_view text) {
    const auto r = sb::rmc_gga_set::decode(text);
    if (r && r.value.index() != 0) {
      std::visit([&s](const auto& m) { sb::read_all(s, m); }, r.value);
    } else {
      ++bad;
    }
    benchmark::DoNotOptimize(s);
  });
  if (bad != 0) state.SkipWithError("framer+decode: a line did not decode");
}

BENCHMARK_CAPTURE(framer_only, rmc_gga_4KiB, rmc_gga())->Name("framer/rmc_gga_4KiB");
BENCHMARK_CAPTURE(framer_only, mixed_4KiB, mixed())->Name("framer/mixed_4KiB");
BENCHMARK(framer_decode_rmc_gga)->Name("framer+decode/rmc_gga_4KiB");

// ---------------------------------------------------------------------------------------------
// checksum

/// The XOR of each sentence's checksummed span (between '$' and '*').
void checksum_rmc_gga(benchmark::State& state) {
  const auto& c = rmc_gga();
  std::vector<std::string_view> spans;
  std::size_t span_bytes = 0;
  for (const std::string_view line : c.lines) {
    spans.push_back(line.substr(1, line.find('*') - 1));
    span_bytes += spans.back().size();
  }
  unsigned x = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const std::string_view s : spans) {
      x += nmea::checksum(s);
      benchmark::DoNotOptimize(x);
    }
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  sb::report(state, spans.size(), span_bytes, allocations);
}
BENCHMARK(checksum_rmc_gga)->Name("checksum/rmc_gga");

void checksum_block(benchmark::State& state) {
  const std::string_view block = std::string_view(rmc_gga().bytes).substr(0, chunk_size);
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    std::uint8_t x = nmea::checksum(block);
    benchmark::DoNotOptimize(x);
  }
  sb::report(state, 1, block.size(), sb::allocation_count() - before);
}
BENCHMARK(checksum_block)->Name("checksum/4KiB");

// ---------------------------------------------------------------------------------------------
// CRC-32

void crc32_bytes(benchmark::State& state, std::size_t size) {
  const std::vector<std::uint8_t> frames = sb::anello_frames(corpus_size);
  const auto data = std::span<const std::uint8_t>(frames).subspan(anello::header_size, size);
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    std::uint32_t crc = seawire::crc32(data);
    benchmark::DoNotOptimize(crc);
  }
  sb::report(state, 1, size, sb::allocation_count() - before);
}
BENCHMARK_CAPTURE(crc32_bytes, 48B_frame_payload, anello::payload_size)->Name("crc32/48B");
BENCHMARK_CAPTURE(crc32_bytes, 4KiB, chunk_size)->Name("crc32/4KiB");

// ---------------------------------------------------------------------------------------------
// the ANELLO binary frame

const std::vector<std::uint8_t>& frames() {
  static const std::vector<std::uint8_t> f = sb::anello_frames(corpus_size);
  return f;
}

// Decodes every frame of the corpus, each pass; `use` takes each result.
template <class Use>
void run_frame_decode(benchmark::State& state, Use&& use) {
  const std::span<const std::uint8_t> all = frames();
  std::size_t bad = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (std::size_t at = 0; at < all.size(); at += anello::frame_size) {
      const result<anello::sensor_frame_raw> r = anello::decode_frame(all.subspan(at));
      if (!r) ++bad;
      use(r);
    }
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  if (bad != 0) state.SkipWithError("frame: a frame did not decode");
  sb::report(state, corpus_size, all.size(), allocations);
}

void frame_decode(benchmark::State& state) {
  sb::sink s;
  run_frame_decode(state, [&s](const result<anello::sensor_frame_raw>& r) {
    anello::for_each_field(r.value, [&s](std::string_view, const auto& v) {
      if constexpr (std::is_same_v<std::remove_cvref_t<decltype(v)>, std::optional<double>>) {
        s.sum += v.value_or(0);
      } else {
        s.bits += v.has_value() ? 1U : 0U;
      }
    });
    benchmark::DoNotOptimize(s);
  });
}
BENCHMARK(frame_decode)->Name("frame/decode+values");

void frame_decode_raw(benchmark::State& state) {
  run_frame_decode(state,
                   [](const result<anello::sensor_frame_raw>& r) { benchmark::DoNotOptimize(r); });
}
BENCHMARK(frame_decode_raw)->Name("frame/decode");

void frame_encode(benchmark::State& state) {
  std::vector<anello::sensor_frame_raw> raws;
  const std::span<const std::uint8_t> all = frames();
  for (std::size_t at = 0; at < all.size(); at += anello::frame_size)
    raws.push_back(anello::decode_frame(all.subspan(at)).value);
  anello::frame_bytes out{};
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const anello::sensor_frame_raw& f : raws) {
      (void)anello::encode_frame(f, out);
      benchmark::DoNotOptimize(out);
    }
  }
  sb::report(state, raws.size(), all.size(), sb::allocation_count() - before);
}
BENCHMARK(frame_encode)->Name("frame/encode");

void frame_build_encode(benchmark::State& state) {
  std::vector<anello::sensor_values> values;
  const std::span<const std::uint8_t> all = frames();
  for (std::size_t at = 0; at < all.size(); at += anello::frame_size)
    values.push_back(anello::to_values(anello::decode_frame(all.subspan(at)).value));
  anello::frame_bytes out{};
  std::size_t bad = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const anello::sensor_values& v : values) {
      const result<anello::sensor_frame_raw> f = anello::build_frame(v);
      if (!f) ++bad;
      (void)anello::encode_frame(f.value, out);
      benchmark::DoNotOptimize(out);
    }
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  if (bad != 0) state.SkipWithError("frame: a frame was refused");
  sb::report(state, values.size(), all.size(), allocations);
}
BENCHMARK(frame_build_encode)->Name("frame/build+encode");

}  // namespace
