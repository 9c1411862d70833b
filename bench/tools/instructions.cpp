// SPDX-License-Identifier: BSL-1.0
// Instructions per sentence, the one figure a busy machine cannot disturb: runs one loop of
// bench/ ten times over the 1,000-sentence RMC/GGA corpus with callgrind collecting only there.
//
//   valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file=cg.out
//            build/bench/bench/seawire_bench_instructions decode    (one command line)
//   callgrind_annotate cg.out | grep 'PROGRAM TOTALS'     # divide by 10,000 sentences
//
// Modes: baseline (frame + checksum + split), decode (message_set -> variant, every field read),
// visit (message_set::visit of the line, every field read), typed (decode<T>(line) of the type
// the address names, every field read), encode (encode_to into a stack buffer),
// reference and reference_encode (the hand-written one-pass RMC/GGA decoder and writer of
// bench/reference/, every field read); kingfisher_baseline, kingfisher_decode and
// kingfisher_visit: the same over 1,000 sentences of the Kingfisher's CP* stream (with its RMC
// and GGA), under the payload's policy.

#include <valgrind/callgrind.h>

#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "../corpus.hpp"
#include "../reference/one_pass_encode.hpp"
#include "../support.hpp"

namespace {

using namespace seawire;
namespace sb = seawire::bench;

constexpr int rounds = 10;

void baseline(const sb::corpus& c) {
  sb::split_sentence split;
  for (int r = 0; r < rounds; ++r) {
    sb::for_each_line(c.bytes, [&](std::string_view line) {
      (void)sb::baseline_split(line, split);
      benchmark::DoNotOptimize(split);
    });
  }
}

template <class Set>
void decode(const sb::corpus& c, sb::sink& s, const nmea::parse_policy& policy = {}) {
  for (int r = 0; r < rounds; ++r) {
    sb::for_each_line(c.bytes, [&](std::string_view line) {
      const auto d = Set::decode(line, policy);
      if (d) std::visit([&s](const auto& m) { sb::read_all(s, m); }, d.value);
      benchmark::DoNotOptimize(s);
    });
  }
}

/// decode<T>(line) for the one type the line's address names (RMC or GGA).
void typed(const sb::corpus& c, sb::sink& s) {
  for (int r = 0; r < rounds; ++r) {
    sb::for_each_line(c.bytes, [&](std::string_view line) {
      if (line.substr(3, 3) == "RMC") {
        const auto d = nmea::decode<standard::rmc>(line);
        if (d) sb::read_all(s, d.value);
      } else {
        const auto d = nmea::decode<standard::gga>(line);
        if (d) sb::read_all(s, d.value);
      }
      benchmark::DoNotOptimize(s);
    });
  }
}

template <class Set>
void visit(const sb::corpus& c, sb::sink& s, const nmea::parse_policy& policy = {}) {
  for (int r = 0; r < rounds; ++r) {
    sb::for_each_line(c.bytes, [&](std::string_view line) {
      (void)Set::visit(line, policy, [&s](const auto& m) { sb::read_all(s, m); });
      benchmark::DoNotOptimize(s);
    });
  }
}

void reference(const sb::corpus& c, sb::sink& s) {
  hw::out o;
  for (int r = 0; r < rounds; ++r) {
    sb::for_each_line(c.bytes, [&](std::string_view line) {
      if (hw::decode(line, o)) {
        if (o.k == hw::out::rmc) sb::read_all(s, o.r);
        if (o.k == hw::out::gga) sb::read_all(s, o.g);
      }
      benchmark::DoNotOptimize(s);
    });
  }
}

/// `write(message, buffer)` for every message of the corpus, `rounds` times.
template <class Messages, class Write>
void encode_with(const Messages& messages, Write write) {
  char buffer[256];
  for (int r = 0; r < rounds; ++r) {
    for (const auto& m : messages) {
      std::visit([&](const auto& one) { write(one, buffer); }, m);
      benchmark::DoNotOptimize(buffer);
    }
  }
}

template <class Messages>
void encode(const Messages& messages) {
  encode_with(messages, [](const auto& one, char* buffer) {
    if constexpr (nmea::message_like<std::remove_cvref_t<decltype(one)>>)
      (void)nmea::encode_to(one, std::span<char>(buffer, 256));
  });
}

template <class Messages>
void reference_encode(const Messages& messages) {
  encode_with(messages, [](const auto& one, char* buffer) {
    using M = std::remove_cvref_t<decltype(one)>;
    if constexpr (std::is_same_v<M, standard::rmc>) (void)hw::encode_rmc(one, buffer);
    if constexpr (std::is_same_v<M, standard::gga>) (void)hw::encode_gga(one, buffer);
  });
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "decode";
  const auto c = sb::rmc_gga_corpus(1000);  // built before collection starts
  const auto k = sb::kingfisher_from_vehicle_corpus(1000);
  sb::sink s;
  CALLGRIND_TOGGLE_COLLECT;
  if (mode == "baseline") {
    baseline(c);
  } else if (mode == "decode") {
    decode<sb::rmc_gga_set>(c, s);
  } else if (mode == "visit") {
    visit<sb::rmc_gga_set>(c, s);
  } else if (mode == "typed") {
    typed(c, s);
  } else if (mode == "kingfisher_baseline") {
    baseline(k);
  } else if (mode == "kingfisher_decode") {
    decode<kingfisher::from_vehicle>(k, s, kingfisher::payload_policy());
  } else if (mode == "kingfisher_visit") {
    visit<kingfisher::from_vehicle>(k, s, kingfisher::payload_policy());
  } else if (mode == "encode") {
    encode(c.messages);
  } else if (mode == "reference") {
    reference(c, s);
  } else if (mode == "reference_encode") {
    reference_encode(c.messages);
  } else {
    CALLGRIND_TOGGLE_COLLECT;
    std::fprintf(stderr,
                 "usage: %s baseline|decode|visit|typed|encode|reference|reference_encode|"
                 "kingfisher_baseline|kingfisher_decode|kingfisher_visit\n",
                 argv[0]);
    return 2;
  }
  CALLGRIND_TOGGLE_COLLECT;
  std::printf("%s: %d sentences (%g)\n", mode.c_str(), rounds * 1000, s.sum);
  return 0;
}
