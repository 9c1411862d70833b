// SPDX-License-Identifier: BSL-1.0
// examples/tools/log_limit.hpp, the programs' rate limit for log lines, on a clock given here.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "../../examples/tools/log_limit.hpp"

using seawire::tools::log_limit;
using namespace std::chrono_literals;

TEST_CASE("at most N lines a window, then one note with the count when the next window opens") {
  log_limit limit("invalid sentences", 3, 1s);
  std::vector<std::uint64_t> notes;
  const auto note = [&](std::uint64_t n) { notes.push_back(n); };
  const log_limit::clock::time_point t0{};
  int written = 0;
  for (int i = 0; i < 1000; ++i) written += limit.allow(note, t0 + i * 1ms) ? 1 : 0;
  CHECK(written == 3);
  CHECK(notes.empty());
  CHECK(limit.suppressed_total() == 997);
  // The next window: the note first, then lines again.
  CHECK(limit.allow(note, t0 + 1001ms));
  REQUIRE(notes.size() == 1);
  CHECK(notes[0] == 997);
  CHECK(limit.note_text(notes[0]) == "... 997 more invalid sentences suppressed");
  CHECK(limit.allow(note, t0 + 1002ms));
  CHECK(limit.allow(note, t0 + 1003ms));
  CHECK_FALSE(limit.allow(note, t0 + 1004ms));
  // A flood that stops: poll() from a timer tells the count once the window is over, not before.
  limit.poll(note, t0 + 1500ms);
  CHECK(notes.size() == 1);
  limit.poll(note, t0 + 2100ms);
  REQUIRE(notes.size() == 2);
  CHECK(notes[1] == 1);
  limit.poll(note, t0 + 9s);
  limit.flush(note);
  CHECK(notes.size() == 2);  // nothing more to tell
  CHECK(limit.suppressed_total() == 998);
}

TEST_CASE("flush tells what is suppressed and not yet told, once") {
  log_limit limit("findings", 1, 10s);
  std::vector<std::uint64_t> notes;
  const auto note = [&](std::uint64_t n) { notes.push_back(n); };
  const log_limit::clock::time_point t0{};
  CHECK(limit.allow(note, t0));
  CHECK_FALSE(limit.allow(note, t0 + 1s));
  CHECK_FALSE(limit.allow(note, t0 + 2s));
  limit.flush(note);
  limit.flush(note);
  REQUIRE(notes.size() == 1);
  CHECK(notes[0] == 2);
}

TEST_CASE("events slower than the limit are all written and nothing is noted") {
  log_limit limit("lines", 2, 1s);
  int notes = 0;
  const auto note = [&](std::uint64_t) { ++notes; };
  const log_limit::clock::time_point t0{};
  for (int i = 0; i < 100; ++i) CHECK(limit.allow(note, t0 + i * 600ms));
  limit.flush(note);
  CHECK(notes == 0);
  CHECK(limit.suppressed_total() == 0);
}
