// SPDX-License-Identifier: BSL-1.0
#pragma once
// robotx::scheduler: when the vehicle may send what (RXHRB every heartbeat_period, each report
// type at most once per min_interval), without I/O or a clock: status() the heartbeat's content,
// submit() reports, poll(now) until nullopt. A heartbeat period runs from when the last one went
// out, so a late wake-up never sends two less than a second apart. Too-soon reports held (one
// slot per type, newest wins) or refused; order and stamping: docs/robotx.md.

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>

#include "seawire/error.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/writer.hpp"
#include "seawire/robotx/hst.hpp"
#include "seawire/robotx/messages.hpp"

namespace seawire::robotx {

/// What submit() does with a report that comes less than min_interval after the last one of its
/// type.
enum class too_soon : std::uint8_t {
  hold,    ///< keep it (newest per type) and release it when allowed
  refuse,  ///< give it back to the caller, with the time it would be allowed
};

struct scheduler_config {
  /// Heartbeat cadence. Raised to min_interval if set below it.
  std::chrono::nanoseconds heartbeat_period = std::chrono::seconds(1);
  /// Least time between two sentences of the same type (the spec: 1 Hz).
  std::chrono::nanoseconds min_interval = std::chrono::seconds(1);
  too_soon when_too_soon = too_soon::hold;
  /// Write the HST date and time of release into every sentence sent.
  bool stamp_reports = true;
};

enum class submit_status : std::uint8_t {
  ready,     ///< will go out at the next poll()
  held,      ///< too soon: will go out at `release_at`
  replaced,  ///< a waiting report of the same type was dropped for this one
  refused,   ///< too soon, and the policy is to refuse: it could go at `release_at`
  invalid,   ///< would not encode: `ec` and `field` say why; nothing changed
};

struct submit_result {
  submit_status status = submit_status::ready;
  instant release_at{};     ///< when it goes (ready/held/replaced) or could go (refused)
  errc ec = errc::ok;       ///< invalid only
  std::uint16_t field = 0;  ///< invalid only: the field whose value was refused

  /// The report was taken (ready, held or replaced).
  [[nodiscard]] constexpr bool accepted() const noexcept {
    return status == submit_status::ready || status == submit_status::held ||
           status == submit_status::replaced;
  }
};

/// One sentence to send now.
struct outgoing {
  report_type type = report_type::heartbeat;
  /// Sealed sentence with CR LF. Only if stamping failed (a `now` outside 1980..2079 HST) does
  /// it carry an error instead; its slot is used up either way, so poll() never loops on it.
  nmea::sentence_buffer<> sentence;
};

class scheduler {
 public:
  constexpr explicit scheduler(const scheduler_config& config = {}) noexcept : config_(config) {
    if (config_.heartbeat_period < config_.min_interval)
      config_.heartbeat_period = config_.min_interval;
  }

  /// Set what the heartbeat says (its date and time are overwritten when stamping). The first
  /// status() starts the heartbeat. A status that would not encode is refused: the error and
  /// field come back and the previous status stays.
  template <int N = 0>
  [[nodiscard]] constexpr result<bool> status(const rxhrb& hb) noexcept {
    result<bool> r;
    const auto check = trial_encode<nmea::lazy<rxhrb, N>>(hb);
    r.ec = check.ec;
    r.field = check.field;
    if (r.ec != errc::ok) return r;
    heartbeat_ = hb;
    r.value = true;
    return r;
  }
  /// The heartbeat content, once status() has been given.
  [[nodiscard]] constexpr const std::optional<rxhrb>& status() const noexcept { return heartbeat_; }

  // status(), submit() and poll() are templates of nothing, like the role decoders (nmea::lazy).
  /// One task report (rxgat, rxcod, rxdok or rxdel; the heartbeat is status()'s).
  template <int N = 0, class M>
  requires std::is_same_v<M, rxgat> || std::is_same_v<M, rxcod> || std::is_same_v<M, rxdok> ||
      std::is_same_v<M, rxdel>
  [[nodiscard]] constexpr submit_result submit(const M& m, instant now) noexcept {
    return submit_one<nmea::lazy<M, N>>(m, now);
  }

  /// The next sentence to send at `now`, or nullopt when nothing is due. Call until nullopt.
  template <int N = 0>
  [[nodiscard]] constexpr std::optional<outgoing> poll(instant now) noexcept {
    if (heartbeat_ && heartbeat_due(now)) {
      std::optional<outgoing> out = release<nmea::lazy<rxhrb, N>>(*heartbeat_, now);
      next_heartbeat_ = detail::later_by(now, config_.heartbeat_period);
      return out;
    }
    std::size_t best = report_type_count;
    for (std::size_t i = 1; i < report_type_count; ++i) {
      if (!slot_[i].waiting || slot_[i].release_at > now) continue;
      if (best == report_type_count || slot_[i].release_at < slot_[best].release_at ||
          (slot_[i].release_at == slot_[best].release_at && slot_[i].order < slot_[best].order))
        best = i;
    }
    if (best == report_type_count) return std::nullopt;
    slot_[best].waiting = false;
    switch (static_cast<report_type>(best)) {
      case report_type::gates: return release<nmea::lazy<rxgat, N>>(*held_.gates, now);
      case report_type::scan_code: return release<nmea::lazy<rxcod, N>>(*held_.scan_code, now);
      case report_type::dock: return release<nmea::lazy<rxdok, N>>(*held_.dock, now);
      case report_type::deliver: return release<nmea::lazy<rxdel, N>>(*held_.deliver, now);
      case report_type::heartbeat: break;
    }
    return std::nullopt;
  }

  /// Whether the heartbeat is due at `now` (false before the first status()).
  [[nodiscard]] constexpr bool heartbeat_due(instant now) const noexcept {
    // instant::max() is "never" (where the next second would be past the end of time).
    return heartbeat_ &&
           (!next_heartbeat_ || (now >= *next_heartbeat_ && *next_heartbeat_ != instant::max()));
  }

  /// When poll() next has something to send: instant::min() if it has now (or as soon as
  /// status() starts the heartbeat), instant::max() if nothing is scheduled.
  [[nodiscard]] constexpr instant next_due() const noexcept {
    instant t = instant::max();
    if (heartbeat_) t = next_heartbeat_ ? *next_heartbeat_ : instant::min();
    for (std::size_t i = 1; i < report_type_count; ++i)
      if (slot_[i].waiting && slot_[i].release_at < t) t = slot_[i].release_at;
    return t;
  }

  /// Whether a report of this type is waiting to go.
  [[nodiscard]] constexpr bool waiting(report_type t) const noexcept {
    const auto i = static_cast<std::size_t>(t);
    return i < report_type_count && slot_[i].waiting;
  }

  /// When the last sentence of this type went out, if one has.
  [[nodiscard]] constexpr std::optional<instant> last_sent(report_type t) const noexcept {
    const auto i = static_cast<std::size_t>(t);
    return i < report_type_count ? last_sent_[i] : std::nullopt;
  }

  [[nodiscard]] constexpr const scheduler_config& config() const noexcept { return config_; }

 private:
  struct slot {
    bool waiting = false;
    instant release_at{};
    std::uint64_t order = 0;
  };

  // The report of each type waiting to go: a struct rather than a std::tuple, whose constructors'
  // constraints every translation unit including this header would compile.
  struct held_reports {
    std::optional<rxgat> gates;
    std::optional<rxcod> scan_code;
    std::optional<rxdok> dock;
    std::optional<rxdel> deliver;

    template <class M>
    [[nodiscard]] constexpr std::optional<M>& of() noexcept {
      if constexpr (std::is_same_v<M, rxgat>) {
        return gates;
      } else if constexpr (std::is_same_v<M, rxcod>) {
        return scan_code;
      } else if constexpr (std::is_same_v<M, rxdok>) {
        return dock;
      } else {
        static_assert(std::is_same_v<M, rxdel>);
        return deliver;
      }
    }
  };

  template <class M>
  [[nodiscard]] static constexpr nmea::sentence_buffer<> trial_encode(const M& m) noexcept {
    return nmea::encode(m);
  }

  template <class M>
  constexpr submit_result submit_one(const M& m, instant now) noexcept {
    constexpr auto i = static_cast<std::size_t>(report_type_of<M>);
    submit_result r;
    const auto check = trial_encode(m);
    if (!check) {
      r.status = submit_status::invalid;
      r.ec = check.ec;
      r.field = check.field;
      return r;
    }
    slot& s = slot_[i];
    instant allowed = now;
    if (last_sent_[i] && detail::later_by(*last_sent_[i], config_.min_interval) > now)
      allowed = detail::later_by(*last_sent_[i], config_.min_interval);
    if (config_.when_too_soon == too_soon::refuse && (allowed > now || s.waiting)) {
      r.status = submit_status::refused;
      const instant after_waiting = detail::later_by(s.release_at, config_.min_interval);
      r.release_at = s.waiting && after_waiting > allowed ? after_waiting : allowed;
      return r;
    }
    r.status = s.waiting       ? submit_status::replaced
               : allowed > now ? submit_status::held
                               : submit_status::ready;
    held_.of<M>() = m;
    s.waiting = true;
    s.release_at = allowed;
    s.order = next_order_++;
    r.release_at = allowed;
    return r;
  }

  template <class M>
  constexpr std::optional<outgoing> release(M m, instant now) noexcept {
    outgoing out;
    out.type = report_type_of<M>;
    last_sent_[static_cast<std::size_t>(out.type)] = now;
    if (config_.stamp_reports) {
      const errc e = stamp(m, now);
      if (e != errc::ok) {
        out.sentence.ec = e;
        out.sentence.field = 1;
        return out;
      }
    }
    out.sentence = nmea::encode(m);
    return out;
  }

  scheduler_config config_;
  std::optional<rxhrb> heartbeat_;
  std::optional<instant> next_heartbeat_;
  held_reports held_;
  std::array<slot, report_type_count> slot_{};  // [0] (the heartbeat) unused
  std::array<std::optional<instant>, report_type_count> last_sent_{};
  std::uint64_t next_order_ = 0;
};

}  // namespace seawire::robotx
