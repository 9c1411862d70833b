// SPDX-License-Identifier: BSL-1.0
// Instructions per sentence, the one figure a busy machine cannot disturb: runs one loop of
// bench/ ten times over the 1,000-sentence RMC/GGA corpus with callgrind collecting only there.
//
//   valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file=cg.out
//            build/bench/bench/seawire_bench_instructions decode    (one command line)
//   callgrind_annotate cg.out | grep 'PROGRAM TOTALS'     # divide by 10,000 sentences
//
// Modes: baseline (frame + checksum + split), decode (message_set -> variant, every field read),
// visit (message_set::visit of the line, every field read), split_decode (parse() of the line,
// then message_set::decode of the sentence_view: the general path, every field read), typed
// (decode<T>(line) of the type the address names, every field read), encode (encode_to into a stack
// buffer), reference and reference_encode (the hand-written one-pass RMC/GGA decoder and writer of
// bench/reference/, every field read); kingfisher_baseline, kingfisher_decode, kingfisher_visit,
// kingfisher_split_decode and kingfisher_encode: the same over 1,000 sentences of the Kingfisher's
// CP* stream (with its RMC and GGA), under the payload's policy. The other families' modes
// (families.cpp): FAMILY_baseline, FAMILY_decode, FAMILY_visit, FAMILY_split_decode and
// FAMILY_encode for FAMILY kingfisher_to (PY* commands), sandshark_from (BF*), sandshark_to (BP*),
// robotx (RobotX reports) and anello (the ANELLO INS's NMEA inputs), each read by its role's set
// under its role's policy, as seawire_bench's family rows are.

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
#include "instruction_loops.hpp"

namespace {

using namespace seawire;
namespace sb = seawire::bench;
using namespace seawire::bench::instructions;

/// decode<T>(line) for the one type the line's address names (RMC or GGA).
SEAWIRE_BENCH_LOOP void typed(const sb::corpus& c, sb::sink& s) {
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

SEAWIRE_BENCH_LOOP void reference(const sb::corpus& c, sb::sink& s) {
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

template <class Messages>
void reference_encode(const Messages& messages) {
  encode_with(messages, [](const auto& one, char* buffer) {
    using M = std::remove_cvref_t<decltype(one)>;
    if constexpr (std::is_same_v<M, standard::rmc>) (void)hw::encode_rmc(one, buffer);
    if constexpr (std::is_same_v<M, standard::gga>) (void)hw::encode_gga(one, buffer);
  });
}

int usage(const char* program) {
  std::fprintf(stderr,
               "usage: %s baseline|decode|visit|split_decode|typed|encode|reference|"
               "reference_encode|kingfisher_{baseline,decode,visit,split_decode,encode}|"
               "FAMILY_{baseline,decode,visit,split_decode,encode}\n"
               "  FAMILY: kingfisher_to, sandshark_from, sandshark_to, robotx or anello\n",
               program);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "decode";
  const int family_status = run_family_mode(mode);
  if (family_status == 0) return 0;
  if (family_status == 2) return usage(argv[0]);
  const auto c = sb::rmc_gga_corpus(1000);  // built before collection starts
  const auto k = sb::kingfisher_from_vehicle_corpus(1000);
  sb::sink s;
  bool known = true;
  CALLGRIND_TOGGLE_COLLECT;
  if (mode == "typed") {
    typed(c, s);
  } else if (mode == "reference") {
    reference(c, s);
  } else if (mode == "reference_encode") {
    reference_encode(c.messages);
  } else if (mode.starts_with("kingfisher_")) {
    known = run_loop<kingfisher::from_vehicle, kingfisher::payload_policy()>(
        std::string_view(mode).substr(11), k, s);
  } else {
    known = run_loop<sb::rmc_gga_set>(mode, c, s);
  }
  CALLGRIND_TOGGLE_COLLECT;
  if (!known) return usage(argv[0]);
  std::printf("%s: %d sentences (%g)\n", mode.c_str(), rounds * 1000, s.sum);
  return 0;
}
