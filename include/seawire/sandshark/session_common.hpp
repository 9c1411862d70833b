// SPDX-License-Identifier: BSL-1.0
#pragma once
// What the Sandshark sessions share: time passed in as steady_clock `now` (never read here, never
// running backwards), the SPI's timing rules, utc_clock (UTC time of day driven by steady time;
// a steady time given as UTC does not compile), the BPLOG subscription rules and the
// fixed-capacity queues. docs/sessions.md.

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>

#include "seawire/detail/ascii.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/sandshark/messages.hpp"

namespace seawire::sandshark {

/// The time every session call takes, for its timers: steady (monotonic), any epoch.
using time_point = std::chrono::steady_clock::time_point;
/// UTC as std::chrono::system_clock keeps it (no leap seconds): system_clock::now(), or any
/// sys_time (std::chrono::sys_days{...} + 23h), which converts implicitly.
using utc_time = std::chrono::system_clock::time_point;
using milliseconds = std::chrono::milliseconds;

namespace detail {
/// True for a time point of system_clock (UTC); the steady clock and the others are not UTC.
template <class T>
inline constexpr bool is_utc_time = false;
template <class Duration>
inline constexpr bool is_utc_time<std::chrono::time_point<std::chrono::system_clock, Duration>> =
    true;
/// Whether T is a time point, of a clock other than system_clock, passed where UTC is expected.
template <class T>
concept not_utc_time_point = requires {
  typename T::clock;
}
&&std::is_same_v<T, std::chrono::time_point<typename T::clock, typename T::duration>> &&
    !is_utc_time<T>;
}  // namespace detail

/// The SPI's timing rules; session configurations start from these.
namespace timing {
/// SPI 7.3: without a BPRMB for this long the vehicle resumes its own behaviour.
inline constexpr milliseconds request_timeout{5000};
/// SPI 4.4: a pending (3) acknowledgement is followed by the final one within this time.
inline constexpr milliseconds pending_timeout{2000};
/// No ack at all after this long: resend (what Goby, the reference backseat, does).
inline constexpr milliseconds resend_after{5000};
/// The least step of time_point: a limit "within t" is kept at t and broken at t + just_after,
/// which is when next_deadline() asks to be woken.
inline constexpr time_point::duration just_after{1};
}  // namespace timing

/// UTC time of day as a function of steady time, anchored once from both clocks
/// (utc_clock(steady_clock::now(), system_clock::now())) and advanced by the steady time passed
/// in; set() re-anchors it. ms_at() counts on past midnight so stamps stay ordered.
class utc_clock {
 public:
  static constexpr std::int64_t day_ms = 86'400'000;

  /// At the steady time `now` it is `utc`.
  constexpr utc_clock(time_point now, utc_time utc) noexcept
      : anchor_(now), anchor_ms_(ms_of(utc)) {}
  /// At the steady time `now` the UTC time of day is `t` (a timestamp off the wire, or a
  /// simulation's start: time_of_day{} is midnight).
  constexpr utc_clock(time_point now, const nmea::time_of_day& t) noexcept
      : anchor_(now), anchor_ms_(ms_of(t)) {}
  /// Refused: a time point of another clock than system_clock is not a UTC time.
  template <class T>
  requires detail::not_utc_time_point<T>
  constexpr utc_clock(time_point /*now*/, T /*utc*/) noexcept {
    static_assert(
        !detail::not_utc_time_point<T>,
        "a UTC time is a std::chrono::system_clock time (system_clock::now()): "
        "steady_clock counts from an arbitrary epoch (often boot), not from midnight UTC");
  }

  /// At `now` the UTC time of day is `t`. Re-anchoring picks the day nearest the running
  /// estimate, so a re-anchor just after midnight does not send the clock back a day.
  constexpr void set(time_point now, const nmea::time_of_day& t) noexcept {
    const std::int64_t tod = ms_of(t);
    const std::int64_t estimate = ms_at(now);
    std::int64_t candidate = estimate - floor_mod(estimate, day_ms) + tod;
    if (candidate - estimate > day_ms / 2) candidate -= day_ms;
    if (estimate - candidate > day_ms / 2) candidate += day_ms;
    anchor_ = now;
    anchor_ms_ = candidate;
  }
  /// At `now` it is `utc` (its time of day; the day nearest the running estimate, as above).
  constexpr void set(time_point now, utc_time utc) noexcept {
    set(now, to_time_of_day(ms_of(utc)));
  }
  /// Refused: a time point of another clock than system_clock is not a UTC time.
  template <class T>
  requires detail::not_utc_time_point<T>
  constexpr void set(time_point /*now*/, T /*utc*/) noexcept {
    static_assert(
        !detail::not_utc_time_point<T>,
        "a UTC time is a std::chrono::system_clock time (system_clock::now()): "
        "steady_clock counts from an arbitrary epoch (often boot), not from midnight UTC");
  }

  /// Milliseconds since the midnight the clock started from (may exceed one day).
  [[nodiscard]] constexpr std::int64_t ms_at(time_point now) const noexcept {
    return anchor_ms_ + std::chrono::floor<milliseconds>(now - anchor_).count();
  }
  /// The time of day at `now`, with 3 fraction digits (the SPI asks for milliseconds).
  [[nodiscard]] constexpr nmea::time_of_day at(time_point now) const noexcept {
    return to_time_of_day(ms_at(now));
  }
  [[nodiscard]] static constexpr nmea::time_of_day to_time_of_day(std::int64_t ms) noexcept {
    // Within [0, 24 h), and 3 places: from_since_midnight cannot fail.
    return nmea::time_of_day::from_since_midnight(milliseconds(floor_mod(ms, day_ms)), 3).value;
  }
  [[nodiscard]] static constexpr std::int64_t ms_of(const nmea::time_of_day& t) noexcept {
    return std::chrono::floor<milliseconds>(t.since_midnight()).count();
  }
  /// Milliseconds since the UTC midnight before `utc` (floor, before 1970 too).
  [[nodiscard]] static constexpr std::int64_t ms_of(utc_time utc) noexcept {
    const auto ms = std::chrono::floor<milliseconds>(utc);
    return (ms - std::chrono::floor<std::chrono::days>(ms)).count();
  }

 private:
  [[nodiscard]] static constexpr std::int64_t floor_mod(std::int64_t a, std::int64_t b) noexcept {
    const std::int64_t r = a % b;
    return r < 0 ? r + b : r;
  }
  time_point anchor_{};
  std::int64_t anchor_ms_ = 0;
};

/// Whether an acknowledgement's echo of a command timestamp names the command sent at `sent`.
/// The echo may carry fewer fraction digits than were sent ("081025.95" for "081025.950"),
/// so the two match when they differ by less than one unit of the echo's last digit.
[[nodiscard]] constexpr bool same_command_time(const nmea::time_of_day& sent,
                                               const nmea::time_of_day& echo) noexcept {
  const std::int64_t a = sent.since_midnight().count();
  const std::int64_t b = echo.since_midnight().count();
  const auto unit = static_cast<std::int64_t>(seawire::detail::pow10_table[9 - echo.places]);
  return a - b < unit && b - a < unit;
}

/// A BPLOG code: three upper-case letters or digits ("NVG", "ALL").
[[nodiscard]] constexpr bool valid_log_code(std::string_view code) noexcept {
  if (code.size() != 3) return false;
  for (char c : code)
    if (!seawire::detail::is_upper(c) && !seawire::detail::is_digit(c)) return false;
  return true;
}

/// Which status messages one payload asked for with BPLOG (SPI 7.1). A code's own request wins
/// over ALL; ALL ON/OFF clears the codes' own requests. ACK is never part of ALL: it is on only
/// after BPLOG,ACK,ON (and ALL OFF leaves it as it is).
template <std::size_t N = 16>
class subscription_set {
 public:
  /// Apply one BPLOG request. False (and unchanged) when the table of per-code requests is full.
  constexpr bool apply(std::string_view code, log_state state) noexcept {
    const bool on = state == log_state::on;
    if (code == "ACK") {
      acks_ = on;
      return true;
    }
    if (code == "ALL") {
      all_ = on;
      size_ = 0;
      return true;
    }
    for (std::size_t i = 0; i < size_; ++i) {
      if (codes_[i] == code) {
        on_[i] = on;
        return true;
      }
    }
    if (size_ == N || !codes_[size_].assign(code)) return false;
    on_[size_++] = on;
    return true;
  }
  constexpr bool apply(const bplog& m) noexcept { return apply(m.code.view(), m.state); }

  /// Whether the message with this code ("NVG") or address ("BFNVG") is to be sent.
  [[nodiscard]] constexpr bool includes(std::string_view code_or_address) const noexcept {
    const std::string_view code = message_code(code_or_address);
    if (code == "ACK") return acks_;
    for (std::size_t i = 0; i < size_; ++i)
      if (codes_[i] == code) return on_[i];
    return all_;
  }
  [[nodiscard]] constexpr bool acks() const noexcept { return acks_; }
  [[nodiscard]] constexpr bool all() const noexcept { return all_; }
  constexpr void clear() noexcept { *this = subscription_set{}; }

  /// Most per-code requests held (besides ALL and ACK).
  static constexpr std::size_t capacity = N;

  /// The BPLOG requests that build this set from an empty one, in order: ACK ON if the acks are
  /// on, ALL ON if it is, then each code's own request (f(code, state) for each).
  template <class F>
  constexpr void for_each_request(F&& f) const {
    if (acks_) f(std::string_view("ACK"), log_state::on);
    if (all_) f(std::string_view("ALL"), log_state::on);
    for (std::size_t i = 0; i < size_; ++i) {
      // Under ALL OFF (the start), a code's OFF changes nothing: only its ON is asked for.
      if (!all_ && !on_[i]) continue;
      f(codes_[i].view(), on_[i] ? log_state::on : log_state::off);
    }
  }

 private:
  std::array<nmea::text<3>, N> codes_{};
  std::array<bool, N> on_{};
  std::size_t size_ = 0;
  bool all_ = false;
  bool acks_ = false;
};

namespace detail {

/// A fixed-capacity double-ended queue.
template <class T, std::size_t N>
class ring {
  static_assert(N > 0);

 public:
  [[nodiscard]] constexpr bool push_back(const T& v) noexcept {
    if (size_ == N) return false;
    items_[(head_ + size_) % N] = v;
    ++size_;
    return true;
  }
  [[nodiscard]] constexpr bool push_front(const T& v) noexcept {
    if (size_ == N) return false;
    head_ = (head_ + N - 1) % N;
    items_[head_] = v;
    ++size_;
    return true;
  }
  [[nodiscard]] constexpr std::optional<T> pop_front() noexcept {
    if (size_ == 0) return std::nullopt;
    std::optional<T> v = items_[head_];
    head_ = (head_ + 1) % N;
    --size_;
    return v;
  }
  [[nodiscard]] constexpr T& operator[](std::size_t i) noexcept { return items_[(head_ + i) % N]; }
  [[nodiscard]] constexpr const T& operator[](std::size_t i) const noexcept {
    return items_[(head_ + i) % N];
  }
  [[nodiscard]] constexpr T& front() noexcept { return (*this)[0]; }
  [[nodiscard]] constexpr T& back() noexcept { return (*this)[size_ - 1]; }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0; }
  [[nodiscard]] constexpr bool full() const noexcept { return size_ == N; }
  [[nodiscard]] static constexpr std::size_t capacity() noexcept { return N; }

 private:
  std::array<T, N> items_{};
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

/// Events waiting for the caller. When only one slot is left, an event that arrives is
/// replaced by an `events_lost` event in that slot, whose count grows with each event lost
/// after it: the caller always learns that (and how many) events were dropped.
template <class Event, std::size_t N>
class event_queue {
  static_assert(N >= 2, "one slot is kept for the events_lost marker");

 public:
  constexpr void push(const Event& e) noexcept {
    if (q_.size() + 1 < N) {
      (void)q_.push_back(e);
      return;
    }
    ++lost_;
    if (q_.size() + 1 == N) {
      Event marker{};
      marker.kind = decltype(marker.kind)::events_lost;
      marker.count = 1;
      (void)q_.push_back(marker);
    } else {
      ++q_.back().count;
    }
  }
  [[nodiscard]] constexpr std::optional<Event> pop() noexcept { return q_.pop_front(); }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return q_.size(); }
  [[nodiscard]] constexpr const Event& operator[](std::size_t i) const noexcept { return q_[i]; }
  /// Events dropped since the session began.
  [[nodiscard]] constexpr std::uint64_t lost() const noexcept { return lost_; }

 private:
  ring<Event, N> q_;
  std::uint64_t lost_ = 0;
};

}  // namespace detail
}  // namespace seawire::sandshark
