// SPDX-License-Identifier: BSL-1.0
#pragma once
// The loops seawire_bench_instructions counts (instructions.cpp, families.cpp): each runs one
// kind of work `rounds` times over a corpus, reading every decoded field into a sink.

#include <span>
#include <string_view>
#include <type_traits>
#include <variant>

#include "../corpus.hpp"
#include "../support.hpp"

namespace seawire::bench::instructions {

namespace nmea = seawire::nmea;
namespace sb = seawire::bench;

// Each loop is a function of its own (SEAWIRE_BENCH_LOOP: never inlined into main), so that what
// the compiler inlines into it does not depend on what else main holds: inlined into main, the
// same loop counted up to ~40 instructions a sentence more or less as other modes were added.
// The policy is a template argument, a constant in the loop, as where a program decodes.
#define SEAWIRE_BENCH_LOOP [[gnu::noinline]]

namespace {

constexpr int rounds = 10;

SEAWIRE_BENCH_LOOP void baseline(const sb::corpus& c) {
  sb::split_sentence split;
  for (int r = 0; r < rounds; ++r) {
    sb::for_each_line(c.bytes, [&](std::string_view line) {
      (void)sb::baseline_split(line, split);
      benchmark::DoNotOptimize(split);
    });
  }
}

/// Set::decode of every line under `Policy`, a constant here as in a program that names its
/// policy where it decodes (the compiler folds the policy's tests).
template <class Set, nmea::parse_policy Policy = nmea::parse_policy{}>
SEAWIRE_BENCH_LOOP void decode(const sb::corpus& c, sb::sink& s) {
  for (int r = 0; r < rounds; ++r) {
    sb::for_each_line(c.bytes, [&](std::string_view line) {
      const auto d = Set::decode(line, Policy);
      if (d) std::visit([&s](const auto& m) { sb::read_all(s, m); }, d.value);
      benchmark::DoNotOptimize(s);
    });
  }
}

/// Set::visit of every line under `Policy`, likewise.
template <class Set, nmea::parse_policy Policy = nmea::parse_policy{}>
SEAWIRE_BENCH_LOOP void visit(const sb::corpus& c, sb::sink& s) {
  for (int r = 0; r < rounds; ++r) {
    sb::for_each_line(c.bytes, [&](std::string_view line) {
      (void)Set::visit(line, Policy, [&s](const auto& m) { sb::read_all(s, m); });
      benchmark::DoNotOptimize(s);
    });
  }
}

/// parse() of every line, then Set::decode of the sentence it gives, under `Policy`: the general
/// path, which reads a sentence already split (and any line the one-pass path leaves to it).
template <class Set, nmea::parse_policy Policy = nmea::parse_policy{}>
SEAWIRE_BENCH_LOOP void split_decode(const sb::corpus& c, sb::sink& s) {
  for (int r = 0; r < rounds; ++r) {
    sb::for_each_line(c.bytes, [&](std::string_view line) {
      const auto split = nmea::parse(line, Policy);
      if (split) {
        const auto d = Set::decode(split.value, Policy);
        if (d) std::visit([&s](const auto& m) { sb::read_all(s, m); }, d.value);
      }
      benchmark::DoNotOptimize(s);
    });
  }
}

/// `write(message, buffer)` for every message of the corpus, `rounds` times.
template <class Messages, class Write>
SEAWIRE_BENCH_LOOP void encode_with(const Messages& messages, Write write) {
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

/// The loop `what` names (baseline, decode, visit, split_decode or encode) over `c`, read by `Set`
/// under `Policy`; false, and nothing run, for another word.
template <class Set, nmea::parse_policy Policy = nmea::parse_policy{}>
bool run_loop(std::string_view what, const sb::family_corpus<Set>& c, sb::sink& s) {
  if (what == "baseline") {
    baseline(c);
  } else if (what == "decode") {
    decode<Set, Policy>(c, s);
  } else if (what == "visit") {
    visit<Set, Policy>(c, s);
  } else if (what == "split_decode") {
    split_decode<Set, Policy>(c, s);
  } else if (what == "encode") {
    encode(c.messages);
  } else {
    return false;
  }
  return true;
}

}  // namespace

/// A mode of another family's stream, counted in families.cpp (a file of its own: each of the
/// two compiles only its own sets): 0 when it ran, 2 for a word that is no such mode, -1 when
/// `mode` names none of its families.
int run_family_mode(std::string_view mode);

}  // namespace seawire::bench::instructions
