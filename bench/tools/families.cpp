// SPDX-License-Identifier: BSL-1.0
// seawire_bench_instructions' modes for the families other than RMC/GGA and the Kingfisher's CP*
// stream (instructions.cpp says how to run them): 1,000 sentences of each, read by its role's set
// under its role's policy.

#include <valgrind/callgrind.h>

#include <cstdio>
#include <string>
#include <string_view>

#include "instruction_loops.hpp"

namespace seawire::bench::instructions {
namespace {

/// run_loop of `what`, collected by callgrind; 2 for a word that is no loop.
template <class Set, nmea::parse_policy Policy>
int run(std::string_view mode, std::string_view what, const sb::family_corpus<Set>& c) {
  sb::sink s;
  CALLGRIND_TOGGLE_COLLECT;
  const bool known = run_loop<Set, Policy>(what, c, s);
  CALLGRIND_TOGGLE_COLLECT;
  if (!known) return 2;
  std::printf("%.*s: %d sentences (%g)\n", static_cast<int>(mode.size()), mode.data(),
              rounds * 1000, s.sum);
  return 0;
}

}  // namespace

int run_family_mode(std::string_view mode) {
  // "sandshark_to_split_decode": family "sandshark_to", what "split_decode".
  std::string_view what;
  const auto is = [&](std::string_view family) {
    if (!mode.starts_with(family) || mode.size() <= family.size() + 1 || mode[family.size()] != '_')
      return false;
    what = mode.substr(family.size() + 1);
    return true;
  };
  // Each corpus is built before collection starts.
  if (is("kingfisher_to")) {
    return run<kingfisher::to_vehicle, kingfisher::vehicle_policy()>(
        mode, what, sb::kingfisher_to_vehicle_corpus(1000));
  }
  if (is("sandshark_from")) {
    return run<sandshark::from_vehicle, sandshark::from_vehicle_policy>(
        mode, what, sb::sandshark_from_vehicle_corpus(1000));
  }
  if (is("sandshark_to")) {
    return run<sandshark::to_vehicle, sandshark::to_vehicle_policy>(
        mode, what, sb::sandshark_to_vehicle_corpus(1000));
  }
  if (is("robotx")) {
    return run<robotx::reports, robotx::judge_policy>(mode, what, sb::robotx_corpus(1000));
  }
  if (is("anello")) {
    return run<anello::nmea_inputs, anello::input_policy>(mode, what,
                                                          sb::anello_inputs_corpus(1000));
  }
  return -1;
}

}  // namespace seawire::bench::instructions
