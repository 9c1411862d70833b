// SPDX-License-Identifier: BSL-1.0
#pragma once
// A rate limit for the programs' per-event log lines (an invalid sentence, a finding): a client
// that sends garbage as fast as the network carries it must not turn into megabytes of log a
// second. One log_limit per category of line: at most `per_window` lines in each window of
// `window` (steady clock); the lines past that are counted, not written, and one line
// "... K more <what> suppressed" says how many when the next window opens (the next event, or
// poll() from a timer) and at exit (flush()). Fixed memory: a count and a time per category.

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

namespace seawire::tools {

class log_limit {
 public:
  using clock = std::chrono::steady_clock;

  /// `what` names the lines in the note ("invalid sentences", "findings").
  explicit log_limit(std::string what, std::uint32_t per_window = 20,
                     clock::duration window = std::chrono::seconds(1))
      : what_(std::move(what)), per_window_(per_window), window_(window) {}

  /// Whether the line of an event happening at `now` may be written. When it opens a new window
  /// and the last one suppressed lines, `note(count)` is called first (see note_text).
  template <class Note>
  [[nodiscard]] bool allow(Note&& note, clock::time_point now = clock::now()) {
    poll(note, now);
    if (!started_) {
      started_ = true;
      opened_ = now;
    }
    if (written_ < per_window_) {
      ++written_;
      return true;
    }
    ++suppressed_;
    ++suppressed_total_;
    return false;
  }

  /// Opens a new window when the current one is over, calling `note(count)` if lines were
  /// suppressed in it: call from a timer so that the count shows when a flood stops.
  template <class Note>
  void poll(Note&& note, clock::time_point now = clock::now()) {
    if (!started_ || now - opened_ < window_) return;
    started_ = false;
    written_ = 0;
    flush(note);
  }

  /// Calls `note(count)` for the lines suppressed and not yet told (at exit).
  template <class Note>
  void flush(Note&& note) {
    if (suppressed_ == 0) return;
    const std::uint64_t n = std::exchange(suppressed_, 0);
    note(n);
  }

  /// "... K more <what> suppressed".
  [[nodiscard]] std::string note_text(std::uint64_t count) const {
    return "... " + std::to_string(count) + " more " + what_ + " suppressed";
  }
  [[nodiscard]] const std::string& what() const { return what_; }
  /// Lines suppressed since the start.
  [[nodiscard]] std::uint64_t suppressed_total() const { return suppressed_total_; }

 private:
  std::string what_;
  std::uint32_t per_window_;
  clock::duration window_;
  clock::time_point opened_{};
  std::uint32_t written_ = 0;
  std::uint64_t suppressed_ = 0;
  std::uint64_t suppressed_total_ = 0;
  bool started_ = false;
};

}  // namespace seawire::tools
