// SPDX-License-Identifier: BSL-1.0
// Sentence benchmarks: the baseline (frame + XOR checksum + field split), full typed decode and
// encode, over the RMC/GGA corpus, each family's corpus and each message type's corpus.
//
// Names are <what>/<corpus>: baseline/X, decode/X and encode/X run over the same sentences, so
// decode/X divided by baseline/X (bench/report.py prints it) is the ratio we quote.
//   decode/X         one call: parse + dispatch by address (the family's message_set) + decode
//                    into the typed message + read every field (numbers as doubles)
//   decode_visit/X   the same through message_set::visit (no variant)
//   decode_typed/X   nmea::decode<T> for one type, no dispatch
//   encode/X         nmea::encode_to into a stack buffer, checksum and CR LF included
//   reference_decode/rmc_gga, reference_encode/rmc_gga
//                    the hand-written one-pass RMC/GGA decoder and writer (bench/reference/):
//                    the floor a decoder generated from the descriptions is held to

#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "corpus.hpp"
#include "reference/one_pass_encode.hpp"
#include "support.hpp"

namespace {

using namespace seawire;
namespace sb = seawire::bench;

constexpr std::size_t corpus_size = 1000;

// ---------------------------------------------------------------------------------------------
// the measurements

/// Times `one` over every line of the corpus, with the allocations made meanwhile. `one` returns
/// false for a line it could not handle; the run is then marked failed with `error`.
template <class F>
void run_over_lines(benchmark::State& state, const sb::corpus& c, const char* error, F&& one) {
  std::size_t bad = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    sb::for_each_line(c.bytes, [&](std::string_view line) {
      if (!one(line)) ++bad;
    });
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  if (bad != 0) state.SkipWithError(error);
  sb::report(state, c.size(), c.bytes.size(), allocations);
}

void run_baseline(benchmark::State& state, const sb::corpus& c) {
  sb::split_sentence split;
  run_over_lines(state, c, "baseline: a corpus line did not check", [&](std::string_view line) {
    const bool ok = sb::baseline_split(line, split);
    benchmark::DoNotOptimize(split);
    return ok;
  });
}

template <class T>
void run_decode_typed(benchmark::State& state, const sb::corpus& c,
                      const nmea::parse_policy& policy) {
  sb::sink s;
  run_over_lines(state, c, "decode: a corpus line did not decode", [&](std::string_view line) {
    const result<T> r = nmea::decode<T>(line, policy);
    if (r) sb::read_all(s, r.value);
    benchmark::DoNotOptimize(s);
    return r.ok();
  });
}

template <class Set>
void run_decode_set(benchmark::State& state, const sb::corpus& c,
                    const nmea::parse_policy& policy) {
  sb::sink s;
  run_over_lines(state, c, "decode: a corpus line did not decode", [&](std::string_view line) {
    const auto r = Set::decode(line, policy);
    const bool ok = r && r.value.index() != 0;
    if (ok) std::visit([&s](const auto& m) { sb::read_all(s, m); }, r.value);
    benchmark::DoNotOptimize(s);
    return ok;
  });
}

template <class Set>
void run_decode_visit(benchmark::State& state, const sb::corpus& c,
                      const nmea::parse_policy& policy) {
  sb::sink s;
  run_over_lines(state, c, "decode: a corpus line did not decode", [&](std::string_view line) {
    const result<bool> r = Set::visit(line, policy, [&s](const auto& m) { sb::read_all(s, m); });
    benchmark::DoNotOptimize(s);
    return r && r.value;
  });
}

/// The hand-written one-pass decoder of RMC and GGA, and the same reading of every field.
void run_reference_decode(benchmark::State& state, const sb::corpus& c) {
  sb::sink s;
  hw::out o;
  run_over_lines(state, c, "reference: a corpus line did not decode", [&](std::string_view line) {
    const bool ok = hw::decode(line, o);
    if (ok && o.k == hw::out::rmc) sb::read_all(s, o.r);
    if (ok && o.k == hw::out::gga) sb::read_all(s, o.g);
    benchmark::DoNotOptimize(s);
    return ok;
  });
}

template <class T>
std::size_t encode_one(const T& m, std::span<char> out, std::size_t& bad) {
  if constexpr (nmea::message_like<T>) {
    const result<std::size_t> r = nmea::encode_to(m, out);
    if (!r) ++bad;
    return r.value;
  } else {
    ++bad;  // unknown_sentence: never in a generated corpus
    return 0;
  }
}

/// Times `encode(message, buffer, bad)` (bytes written) over every message of the corpus, with the
/// allocations made meanwhile; the run fails unless every message was written and the bytes add
/// up to the corpus.
template <class Messages, class Encode>
void run_encode_with(benchmark::State& state, const sb::corpus& c, const Messages& messages,
                     Encode encode) {
  std::array<char, 256> buffer{};
  std::size_t bad = 0;
  std::size_t written = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const auto& m : messages) {
      if constexpr (requires { m.index(); }) {
        written += std::visit([&](const auto& one) { return encode(one, buffer, bad); }, m);
      } else {
        written += encode(m, buffer, bad);
      }
      benchmark::DoNotOptimize(buffer);
    }
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  if (bad != 0 || written != c.bytes.size() * static_cast<std::size_t>(state.iterations()))
    state.SkipWithError("encode: a message was refused or written differently");
  sb::report(state, messages.size(), c.bytes.size(), allocations);
}

template <class Messages>
void run_encode(benchmark::State& state, const sb::corpus& c, const Messages& messages) {
  run_encode_with(state, c, messages, [](const auto& m, std::span<char> out, std::size_t& bad) {
    return encode_one(m, out, bad);
  });
}

/// The hand-written writer of RMC and GGA.
template <class Messages>
void run_reference_encode(benchmark::State& state, const sb::corpus& c, const Messages& messages) {
  run_encode_with(state, c, messages,
                  [](const auto& m, std::span<char> out, std::size_t& bad) -> std::size_t {
                    using M = std::remove_cvref_t<decltype(m)>;
                    std::size_t n = 0;
                    if constexpr (std::is_same_v<M, standard::rmc>)
                      n = hw::encode_rmc(m, out.data());
                    if constexpr (std::is_same_v<M, standard::gga>)
                      n = hw::encode_gga(m, out.data());
                    if (n == 0) ++bad;
                    return n;
                  });
}

// ---------------------------------------------------------------------------------------------
// corpora, built once, on first use (outside any timed loop)

template <class T>
const sb::message_corpus<T>& type_corpus() {
  static const sb::message_corpus<T> c = sb::corpus_of<T>(corpus_size);
  return c;
}

// ---------------------------------------------------------------------------------------------
// registration

std::string type_name(std::string_view address) {
  return std::string(address.starts_with("--") ? address.substr(2) : address);
}

template <class T>
void register_type() {
  const std::string name = type_name(T::nmea.address);
  benchmark::RegisterBenchmark(("baseline/" + name).c_str(),
                               [](benchmark::State& s) { run_baseline(s, type_corpus<T>()); });
  benchmark::RegisterBenchmark(("decode_typed/" + name).c_str(), [](benchmark::State& s) {
    run_decode_typed<T>(s, type_corpus<T>(), nmea::parse_policy{});
  });
  benchmark::RegisterBenchmark(("encode/" + name).c_str(), [](benchmark::State& s) {
    run_encode(s, type_corpus<T>(), type_corpus<T>().messages);
  });
}

template <class... Ts>
void register_types() {
  (register_type<Ts>(), ...);
}

/// The corpus `make` builds, built once (each family's maker is a lambda of its own type).
template <class Make>
const auto& cached(Make make) {
  static const auto c = make(corpus_size);
  return c;
}

/// baseline, decode (set -> variant), decode_visit and encode over one family corpus.
template <class Set, class Make>
void register_family(const std::string& name, Make make, nmea::parse_policy policy) {
  benchmark::RegisterBenchmark(("baseline/" + name).c_str(),
                               [make](benchmark::State& s) { run_baseline(s, cached(make)); });
  benchmark::RegisterBenchmark(("decode/" + name).c_str(), [make, policy](benchmark::State& s) {
    run_decode_set<Set>(s, cached(make), policy);
  });
  benchmark::RegisterBenchmark(
      ("decode_visit/" + name).c_str(),
      [make, policy](benchmark::State& s) { run_decode_visit<Set>(s, cached(make), policy); });
  benchmark::RegisterBenchmark(("encode/" + name).c_str(), [make](benchmark::State& s) {
    run_encode(s, cached(make), cached(make).messages);
  });
}

const bool registered = [] {
  // The headline: GPS at 1 Hz, RMC and GGA, under the default (liberal) policy.
  const auto rmc_gga = [](std::size_t n) { return sb::rmc_gga_corpus(n); };
  register_family<sb::rmc_gga_set>("rmc_gga", rmc_gga, nmea::parse_policy{});
  // The same sentences through a set that knows every message of every family.
  benchmark::RegisterBenchmark("decode_all_sets/rmc_gga", [rmc_gga](benchmark::State& s) {
    run_decode_set<sb::every_message>(s, cached(rmc_gga), nmea::parse_policy{});
  });
  benchmark::RegisterBenchmark("reference_decode/rmc_gga", [rmc_gga](benchmark::State& s) {
    run_reference_decode(s, cached(rmc_gga));
  });
  benchmark::RegisterBenchmark("reference_encode/rmc_gga", [rmc_gga](benchmark::State& s) {
    run_reference_encode(s, cached(rmc_gga), cached(rmc_gga).messages);
  });

  // Each family, read by its role's set under its role's policy.
  register_family<anello::nmea_inputs>(
      "anello_inputs", [](std::size_t n) { return sb::anello_inputs_corpus(n); },
      anello::input_policy);
#if SEAWIRE_BENCH_HAS_KINGFISHER
  register_family<kingfisher::from_vehicle>(
      "kingfisher_from_vehicle",
      [](std::size_t n) { return sb::kingfisher_from_vehicle_corpus(n); },
      kingfisher::payload_policy());
  register_family<kingfisher::to_vehicle>(
      "kingfisher_to_vehicle", [](std::size_t n) { return sb::kingfisher_to_vehicle_corpus(n); },
      kingfisher::vehicle_policy());
#endif
  register_family<sandshark::from_vehicle>(
      "sandshark_from_vehicle", [](std::size_t n) { return sb::sandshark_from_vehicle_corpus(n); },
      sandshark::from_vehicle_policy);
  register_family<sandshark::to_vehicle>(
      "sandshark_to_vehicle", [](std::size_t n) { return sb::sandshark_to_vehicle_corpus(n); },
      sandshark::to_vehicle_policy);
  register_family<robotx::reports>(
      "robotx_reports", [](std::size_t n) { return sb::robotx_corpus(n); }, robotx::judge_policy);

  // Each message type on its own.
  register_types<standard::rmc, standard::gga, standard::rpm, standard::rsa, standard::vhw,
                 standard::vbw, standard::vwr, anello::papgpsctrl>();
#if SEAWIRE_BENCH_HAS_KINGFISHER
  register_types<kingfisher::cpnvg, kingfisher::cpnvr, kingfisher::cprcm, kingfisher::cprbs,
                 kingfisher::cpimu, kingfisher::cpalt, kingfisher::pydep, kingfisher::pydev,
                 kingfisher::pydir, kingfisher::pyclt>();
#endif
  register_types<sandshark::bfsht, sandshark::bfver, sandshark::bfnvg, sandshark::bfnvr,
                 sandshark::bfmis, sandshark::bfack, sandshark::bfctl, sandshark::bplog,
                 sandshark::bpsts, sandshark::bprmb, sandshark::bpabt, sandshark::bpver>();
  register_types<robotx::rxhrb, robotx::rxgat, robotx::rxcod, robotx::rxdok, robotx::rxdel>();
  return true;
}();

}  // namespace
