// SPDX-License-Identifier: BSL-1.0
#pragma once
// The payload (backseat) side of a Sandshark SPI session, sans I/O: fed the vehicle's lines and
// steady time `now`, it hands back sentences and events; tick() when no input arrives,
// next_deadline() says when. Handshake, acks matched by name and timestamp, resends, heartbeat,
// BPRMB keep-alive and control: docs/sessions.md.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>

#include "seawire/detail/algorithm.hpp"
#include "seawire/detail/enum_names.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/writer.hpp"
#include "seawire/sandshark/messages.hpp"
#include "seawire/sandshark/session_common.hpp"

namespace seawire::sandshark {

/// Any message a payload sends.
using payload_message = std::variant<bplog, bpsts, bprmb, bpabt, bpver>;
/// One sentence to write to the vehicle (CR LF included). Every BP* sentence fits.
using payload_line = nmea::sentence_buffer<256>;

struct payload_config {
  nmea::text<32> version = "1.0";  ///< BPVER field 2
  bool want_acks = true;           ///< start() sends BPLOG,ACK,ON
  milliseconds resend_after = timing::resend_after;
  std::uint8_t max_resends = 3;  ///< resends after the first send
  milliseconds pending_timeout = timing::pending_timeout;
  milliseconds heartbeat_period{1000};                     ///< BPSTS period; zero: no heartbeat
  milliseconds request_timeout = timing::request_timeout;  ///< the vehicle's BPRMB timeout
  milliseconds keep_alive_margin{1000};  ///< BPRMB is resent this long before request_timeout
  bool sync_utc_from_vehicle = true;     ///< take UTC from each vehicle timestamp (SPI 2: the BAM
                                         ///< keeps the reference time)
  /// The most a stamp runs ahead of the UTC clock to stay after the previous one; a clock set
  /// back further is followed at once.
  milliseconds max_stamp_lead{1000};
};

/// Why a payload_event was raised.
enum class payload_event_kind : std::uint8_t {
  ack_ok,                        ///< the command was processed
  ack_failed,                    ///< processing failed (status 1)
  ack_invalid,                   ///< the vehicle did not understand it (status 0)
  ack_pending,                   ///< status 3: the final ack is to follow within 2 s
  ack_timeout,                   ///< a pending ack was not followed by the final one in time
  command_resent,                ///< no ack in time: sent again (count = sends so far)
  command_failed_after_retries,  ///< no ack after the last resend (count = sends)
  unmatched_ack,                 ///< an ack whose command name and timestamp match nothing sent
  control_gained,                ///< BFCTL 1: the payload drives
  control_lost,                  ///< BFCTL 0, or the mission left Running (detail says which)
  shutdown,                      ///< BFSHT: power goes in a minute or more
  outbox_overflow,               ///< a sentence did not fit the outbox; it is tried again later
  events_lost,                   ///< count events were dropped because the queue was full
};

/// The identifier of a payload_event_kind as text ("ack_ok"), for logs.
// (A template of nothing, so that only a caller reads the enumerators' names.)
template <int = 0>
[[nodiscard]] constexpr std::string_view name(payload_event_kind k) noexcept {
  return seawire::detail::enumerator_name_of<13>(k, "unknown_event");
}

/// What sent the message an event is about.
enum class message_origin : std::uint8_t {
  command,    ///< send(), subscribe(), abort(), start(): has a ticket
  request,    ///< set_request() and its keep-alive
  heartbeat,  ///< the BPSTS heartbeat
};

struct payload_event {
  payload_event_kind kind{};
  message_origin origin = message_origin::command;
  std::uint32_t ticket = 0;  ///< what send() returned for the command; 0 for the others
  nmea::text<16> command;    ///< "BPRMB"; for unmatched_ack the ack's own name for it ("RMB")
  std::optional<nmea::time_of_day> command_timestamp;  ///< as sent (unmatched_ack: as echoed)
  std::uint32_t count = 0;                             ///< sends so far, or events lost
  nmea::text<256> detail;  ///< the ack's description, or why control ended
  /// For a BPLOG command (BPLOG has no timestamp to tell two apart): which subscription, its
  /// code ("NVG", "ALL") and state (ON/OFF).
  std::optional<bplog> subscription;
};

/// The address of a payload message ("BPRMB").
// (This and timestamp_of are templates of nothing: a visit over the variant is compiled where one
// is called.)
template <int = 0>
[[nodiscard]] constexpr std::string_view address_of(const payload_message& m) noexcept {
  return std::visit([](const auto& x) { return decltype(x.nmea)::address; }, m);
}
/// Field 1 of a payload message; BPLOG has none.
template <int = 0>
[[nodiscard]] constexpr std::optional<nmea::time_of_day> timestamp_of(
    const payload_message& m) noexcept {
  return std::visit(
      [](const auto& x) -> std::optional<nmea::time_of_day> {
        if constexpr (requires { x.timestamp; }) {
          return x.timestamp;
        } else {
          return std::nullopt;
        }
      },
      m);
}

/// A message sent and not yet acknowledged.
struct payload_in_flight {
  payload_message message;  ///< as sent (stamped): a resend writes the same bytes
  std::uint32_t ticket = 0;
  message_origin origin = message_origin::command;
  bool queued = false;  ///< the head of the command queue (others wait behind it)
  std::uint8_t sends = 0;
  time_point first_sent{};
  time_point last_sent{};
  std::optional<time_point> pending_since;  ///< when a pending (3) ack came
  bool active = false;

  template <int = 0>
  [[nodiscard]] constexpr std::string_view address() const noexcept {
    return address_of(message);
  }
  template <int = 0>
  [[nodiscard]] constexpr std::optional<nmea::time_of_day> timestamp() const noexcept {
    return timestamp_of(message);
  }
};

template <std::size_t QueueCapacity = 16, std::size_t OutboxCapacity = 16,
          std::size_t EventCapacity = 32>
class payload_session {
  // The vehicle's messages, named so that they depend on the class's parameters: a header that
  // merely defines the class does not compile their set.
  using vehicle_set = nmea::lazy<from_vehicle, static_cast<int>(QueueCapacity * 0)>;

 public:
  /// Messages sent and awaiting an ack at the same time: the command, aborts, and the
  /// heartbeats and requests of the last resend_after.
  static constexpr std::size_t max_in_flight = 32;

  /// `utc` gives the timestamps' UTC time of day at each steady `now` (re-anchored from the
  /// vehicle's timestamps when config.sync_utc_from_vehicle, or by set_utc()).
  constexpr explicit payload_session(const utc_clock& utc,
                                     const payload_config& config = {}) noexcept
      : config_(config), utc_(utc) {}

  // -- what the application does --------------------------------------------------------------

  /// Begin: BPVER, then BPLOG,ACK,ON when acks are wanted, ahead of anything already queued,
  /// and the heartbeat. Calling it again starts over as on a new connection (the vehicle has
  /// turned every status message and the acks off, SPI 7.1): the handshake, then BPLOG requests
  /// that give back the subscriptions the old link had, then the commands still awaiting their
  /// ack there (same tickets, sent again), then the queue. Control ends (control_lost).
  constexpr void start(time_point now) noexcept {
    advance(now);
    if (started_) restart();
    if (config_.want_acks) {
      bplog ack;
      (void)ack.code.assign("ACK");
      ack.state = log_state::on;
      push_front_command(ack);
    }
    bpver ver;
    ver.version = config_.version;
    push_front_command(ver);
    started_ = true;
    next_heartbeat_ = now;
    pump(now);
  }

  /// Queue a command; nothing queued is sent before start(). Its timestamp (field 1) is set
  /// when it is sent. Returns its ticket; or the encoder's errc and field for a value the spec
  /// forbids; or buffer_too_small when the queue is full.
  [[nodiscard]] constexpr result<std::uint32_t> send(const payload_message& m,
                                                     time_point now) noexcept {
    advance(now);
    result<std::uint32_t> r = check(m, now);
    if (!r) return r;
    if (!queue_.push_back({m, next_ticket_})) {
      r.ec = errc::buffer_too_small;
      return r;
    }
    r.value = next_ticket_++;
    pump(now);
    return r;
  }

  /// Queue BPLOG,<code>,ON (or OFF). bad_text for a code that is not 3 letters/digits.
  [[nodiscard]] constexpr result<std::uint32_t> subscribe(
      std::string_view code, time_point now, log_state state = log_state::on) noexcept {
    bplog m;
    if (!valid_log_code(code) || !m.code.assign(code)) {
      result<std::uint32_t> r;
      r.ec = errc::bad_text;
      r.field = 1;
      return r;
    }
    m.state = state;
    return send(m, now);
  }

  /// Send BPABT now, ahead of the queue and of any command awaiting its ack.
  [[nodiscard]] constexpr result<std::uint32_t> abort(
      std::string_view message, time_point now,
      abort_reason reason = abort_reason::with_errors) noexcept {
    advance(now);
    bpabt m;
    m.reason = reason;
    result<std::uint32_t> r;
    if (!m.message.assign(message)) {
      r.ec = errc::text_too_long;
      r.field = 2;
      return r;
    }
    r = check(m, now);
    if (!r) return r;
    const std::uint32_t ticket = next_ticket_++;
    if (!started_) {
      // Nothing goes out before BPVER (SPI 7.5): the abort waits at the head of the queue,
      // and start() puts only the handshake ahead of it.
      if (!queue_.push_front({m, ticket})) {
        r.ec = errc::buffer_too_small;
        return r;
      }
      r.value = ticket;
      return r;
    }
    if (!transmit(m, ticket, message_origin::command, false, now)) {
      r.ec = errc::buffer_too_small;
      return r;
    }
    r.value = ticket;
    pump(now);
    return r;
  }

  /// The behaviour to hold while in control. Sent now if control is held (else when it is
  /// gained), then kept alive. Its timestamp is set at each send.
  [[nodiscard]] constexpr result<bool> set_request(const bprmb& request, time_point now) noexcept {
    advance(now);
    const result<std::uint32_t> c = check(request, now);
    result<bool> r;
    r.ec = c.ec;
    r.field = c.field;
    if (!c) return r;
    request_ = request;
    request_due_ = true;
    r.value = true;
    pump(now);
    return r;
  }
  /// Stop sending BPRMB: the vehicle resumes its own behaviour request_timeout later.
  constexpr void clear_request() noexcept {
    request_.reset();
    request_due_ = false;
  }

  /// What the heartbeat says from now on. False (unchanged) if the text cannot be sent.
  [[nodiscard]] constexpr bool set_status(bool all_ok, std::string_view message) noexcept {
    nmea::text<128> t;
    if (!t.assign(message) || nmea::codec<nmea::text<128>>::check(t) != errc::ok) return false;
    status_.all_ok = all_ok;
    status_.message = t;
    return true;
  }

  /// The UTC time at `now`, for the timestamps the session writes: a time of day or a
  /// std::chrono::system_clock time, as utc_clock::set() takes (a steady time does not compile).
  template <class T>
  constexpr void set_utc(time_point now, const T& utc) noexcept {
    advance(now);
    utc_.set(now, utc);
  }

  // -- what the vehicle says ------------------------------------------------------------------

  /// Decode one line from the vehicle (from_vehicle_policy) and act on it. The result is the
  /// decoded message for the caller's own use (an unknown_sentence views into `line`).
  [[nodiscard]] constexpr result<typename vehicle_set::variant> receive(std::string_view line,
                                                                        time_point now) noexcept {
    // The decoder named through a template parameter: compiled where receive() is, not where
    // this header is read.
    result<typename vehicle_set::variant> r =
        decode_from_vehicle<static_cast<int>(QueueCapacity * 0)>(line);
    if (r) {
      handle(r.value, now);
    } else {
      tick(now);
    }
    return r;
  }

  /// Act on a decoded vehicle message.
  constexpr void handle(const typename vehicle_set::variant& v, time_point now) noexcept {
    std::visit([&](const auto& m) { handle(m, now); }, v);
  }

  template <class M>
  constexpr void handle(const M& m, time_point now) noexcept {
    advance(now);
    if constexpr (requires { m.timestamp; }) {
      if (config_.sync_utc_from_vehicle) utc_.set(now, m.timestamp);
    }
    if constexpr (std::is_same_v<M, bfack>) {
      on_ack(m, now);
    } else if constexpr (std::is_same_v<M, bfctl>) {
      if (m.control && !control_) {
        control_ = true;
        if (request_) request_due_ = true;
        event(payload_event_kind::control_gained);
      } else if (!m.control && control_) {
        lose_control("BFCTL 0");
      }
    } else if constexpr (std::is_same_v<M, bfmis>) {
      if (control_ && !m.running()) lose_control(m.status.view());
    } else if constexpr (std::is_same_v<M, bfsht>) {
      event(payload_event_kind::shutdown);
    } else if constexpr (std::is_same_v<M, bfver>) {
      vehicle_version_ = m.version;
    }
    pump(now);
  }

  // -- time -----------------------------------------------------------------------------------

  /// Let time pass: resends, ack timeouts, heartbeat, keep-alive.
  constexpr void tick(time_point now) noexcept {
    advance(now);
    pump(now);
  }

  /// The earliest time at which tick() has something to do, if any.
  [[nodiscard]] constexpr std::optional<time_point> next_deadline() const noexcept {
    std::optional<time_point> d;
    const auto consider = [&](time_point t) {
      if (!d || t < *d) d = t;
    };
    for (const payload_in_flight& f : flights_) {
      if (!f.active) continue;
      consider(f.pending_since ? *f.pending_since + config_.pending_timeout + timing::just_after
                               : f.last_sent + config_.resend_after);
    }
    if (started_ && config_.heartbeat_period.count() > 0) consider(next_heartbeat_);
    if (started_ && control_ && request_)
      consider(request_due_ ? now_ : last_request_ + keep_alive_interval());
    if (started_ && !queue_.empty() && !awaiting()) consider(now_);
    return d;
  }

  // -- output ---------------------------------------------------------------------------------

  /// The next sentence to write to the vehicle.
  [[nodiscard]] constexpr std::optional<payload_line> poll_send() noexcept {
    return outbox_.pop_front();
  }
  /// The next event.
  [[nodiscard]] constexpr std::optional<payload_event> poll_event() noexcept {
    return events_.pop();
  }

  // -- state ----------------------------------------------------------------------------------

  [[nodiscard]] constexpr bool started() const noexcept { return started_; }
  /// BFCTL 1 was received and control has not ended since.
  [[nodiscard]] constexpr bool has_control() const noexcept { return control_; }
  /// BPLOG,ACK,ON has been sent (and not turned off): sent messages await acks.
  [[nodiscard]] constexpr bool acks_enabled() const noexcept { return subscriptions_.acks(); }
  /// What this payload has asked the vehicle to send (by the BPLOG requests sent so far).
  [[nodiscard]] constexpr const subscription_set<>& subscriptions() const noexcept {
    return subscriptions_;
  }
  /// The command at the head of the queue, sent and awaiting its ack.
  [[nodiscard]] constexpr const payload_in_flight* awaiting() const noexcept {
    for (const payload_in_flight& f : flights_)
      if (f.active && f.queued) return &f;
    return nullptr;
  }
  /// Commands waiting behind the one awaiting its ack.
  [[nodiscard]] constexpr std::size_t queued() const noexcept { return queue_.size(); }
  /// Messages sent and not yet acknowledged (commands, aborts, heartbeats, requests).
  [[nodiscard]] constexpr std::size_t in_flight() const noexcept {
    std::size_t n = 0;
    for (const payload_in_flight& f : flights_) n += f.active ? 1 : 0;
    return n;
  }
  [[nodiscard]] constexpr const std::optional<bprmb>& current_request() const noexcept {
    return request_;
  }
  /// The version the vehicle reported in BFVER (empty until then).
  [[nodiscard]] constexpr std::string_view vehicle_version() const noexcept {
    return vehicle_version_.view();
  }
  [[nodiscard]] constexpr const utc_clock& utc() const noexcept { return utc_; }
  [[nodiscard]] constexpr std::uint64_t events_lost() const noexcept { return events_.lost(); }
  /// Times a sentence did not fit the outbox.
  [[nodiscard]] constexpr std::uint64_t outbox_overflows() const noexcept { return overflows_; }
  [[nodiscard]] constexpr milliseconds keep_alive_interval() const noexcept {
    const milliseconds i = config_.request_timeout - config_.keep_alive_margin;
    return i.count() > 0 ? i : milliseconds{1};
  }

 private:
  struct queued_command {
    payload_message message;
    std::uint32_t ticket = 0;
  };

  constexpr void advance(time_point& now) noexcept {
    if (now < now_) now = now_;
    now_ = now;
  }

  /// Encode `m` as it would be sent now, to refuse bad values when the caller hands them in.
  template <class M>
  [[nodiscard]] constexpr result<std::uint32_t> check(const M& m, time_point now) const noexcept {
    result<std::uint32_t> r;
    if constexpr (std::is_same_v<M, payload_message>) {
      return std::visit([&](const auto& x) { return check(x, now); }, m);
    } else {
      M stamped = m;
      if constexpr (requires { stamped.timestamp; }) stamped.timestamp = utc_.at(now);
      payload_line line;
      const result<std::size_t> e = nmea::encode_to(stamped, std::span<char>(line.data));
      r.ec = e.ec;
      r.field = e.field;
      return r;
    }
  }

  constexpr void push_front_command(const payload_message& m) noexcept {
    push_front_queued({m, next_ticket_++});
  }
  constexpr void push_front_queued(const queued_command& c) noexcept {
    if (!queue_.push_front(c)) {
      // Full queue: the handshake matters more than the newest command.
      const std::optional<queued_command> dropped = pop_back_command();
      payload_event e = about(payload_event_kind::outbox_overflow, dropped->message);
      e.ticket = dropped->ticket;
      (void)e.detail.assign("command queue full: newest command dropped");
      events_.push(e);
      (void)queue_.push_front(c);
    }
  }

  /// start() on a session already started: what the old link had is put back in the queue.
  /// Pushed to the front in reverse, so that the queue reads: subscriptions, old commands,
  /// what was queued (start() then puts the handshake ahead of all of it).
  constexpr void restart() noexcept {
    // Commands that were awaiting an ack, in the order they were first sent (BPLOGs are given
    // back by the subscriptions below, heartbeats and requests are not commands).
    std::array<const payload_in_flight*, max_in_flight> old{};
    std::size_t n = 0;
    for (const payload_in_flight& f : flights_)
      if (f.active && f.origin == message_origin::command &&
          !std::holds_alternative<bplog>(f.message))
        old[n++] = &f;
    std::sort(old.begin(), old.begin() + static_cast<std::ptrdiff_t>(n),
              [](const payload_in_flight* a, const payload_in_flight* b) {
                return a->first_sent < b->first_sent;
              });
    for (std::size_t i = n; i-- > 0;) push_front_queued({old[i]->message, old[i]->ticket});
    for (payload_in_flight& f : flights_) f = {};

    const subscription_set<> had = subscriptions_;
    subscriptions_.clear();
    std::array<bplog, subscription_set<>::capacity + 2> asks{};
    std::size_t k = 0;
    had.for_each_request([&](std::string_view code, log_state state) {
      if (code == "ACK" && config_.want_acks) return;  // start() asks for the acks itself
      bplog m;
      (void)m.code.assign(code);
      m.state = state;
      asks[k++] = m;
    });
    for (std::size_t i = k; i-- > 0;) push_front_command(asks[i]);

    if (control_) lose_control("restart: a new connection starts without control");
    request_due_ = false;
  }
  [[nodiscard]] constexpr std::optional<queued_command> pop_back_command() noexcept {
    // ring has no pop_back: rotate the rest to the front.
    const std::size_t n = queue_.size();
    std::optional<queued_command> last;
    for (std::size_t i = 0; i < n; ++i) {
      std::optional<queued_command> c = queue_.pop_front();
      if (i + 1 == n) {
        last = c;
      } else {
        (void)queue_.push_back(*c);
      }
    }
    return last;
  }

  /// A UTC timestamp that no message awaiting its ack has, so (name, timestamp) names one
  /// message: the clock's time, or 1 ms after the last stamp when the clock is at or behind it
  /// by less than max_stamp_lead (stamps increase); a clock set back further is followed.
  [[nodiscard]] constexpr nmea::time_of_day stamp(time_point now) noexcept {
    std::int64_t ms = utc_.ms_at(now);
    if (stamped_ && ms <= last_stamp_ && last_stamp_ - ms < config_.max_stamp_lead.count())
      ms = last_stamp_ + 1;
    // After a step back, stamps sent before it may lie ahead: pass the ones still in flight.
    for (std::size_t pass = 0; pass <= max_in_flight && stamp_in_flight(ms); ++pass) ++ms;
    stamped_ = true;
    last_stamp_ = ms;
    return utc_clock::to_time_of_day(ms);
  }
  [[nodiscard]] constexpr bool stamp_in_flight(std::int64_t ms) const noexcept {
    const nmea::time_of_day t = utc_clock::to_time_of_day(ms);
    for (const payload_in_flight& f : flights_)
      if (f.active && f.timestamp() == t) return true;
    return false;
  }

  /// Stamp, encode and place in the outbox; track the ack if acks are on. False if the outbox
  /// is full (reported) or no slot is free to track it.
  template <class M>
  [[nodiscard]] constexpr bool transmit(M m, std::uint32_t ticket, message_origin origin,
                                        bool queued, time_point now) noexcept {
    const bool had_stamp = stamped_;
    const std::int64_t last = last_stamp_;
    if constexpr (requires { m.timestamp; }) m.timestamp = stamp(now);
    if (!put(m, ticket, origin)) {
      stamped_ = had_stamp;  // nothing went out: the stamp was not used
      last_stamp_ = last;
      return false;
    }
    // BPLOG takes effect before its own ack: ACK ON is acknowledged, ACK OFF is not.
    if constexpr (std::is_same_v<M, bplog>) (void)subscriptions_.apply(m);
    if (subscriptions_.acks()) track(m, ticket, origin, queued, now);
    return true;
  }

  template <class M>
  [[nodiscard]] constexpr bool put(const M& m, std::uint32_t ticket,
                                   message_origin origin) noexcept {
    payload_line line;
    const result<std::size_t> r = nmea::encode_to(m, std::span<char>(line.data));
    line.ec = r.ec;
    line.field = r.field;
    line.size = r ? r.value : 0;
    if (r && outbox_.push_back(line)) return true;
    ++overflows_;
    payload_event e = about(payload_event_kind::outbox_overflow, payload_message{m});
    e.origin = origin;
    e.ticket = ticket;
    events_.push(e);
    return false;
  }

  template <class M>
  constexpr void track(const M& m, std::uint32_t ticket, message_origin origin, bool queued,
                       time_point now) noexcept {
    payload_in_flight* slot = nullptr;
    for (payload_in_flight& f : flights_) {
      if (!f.active) {
        slot = &f;
        break;
      }
    }
    if (slot == nullptr) {
      // Full: forget the oldest heartbeat or request; its ack, if it comes, is reported as
      // unmatched.
      for (payload_in_flight& f : flights_) {
        if (f.origin != message_origin::command &&
            (slot == nullptr || f.first_sent < slot->first_sent))
          slot = &f;
      }
      if (slot == nullptr) return;
    }
    *slot = {payload_message{m}, ticket, origin, queued, 1, now, now, std::nullopt, true};
  }

  [[nodiscard]] static constexpr payload_event about(payload_event_kind kind,
                                                     const payload_message& m) noexcept {
    payload_event e;
    e.kind = kind;
    (void)e.command.assign(address_of(m));
    e.command_timestamp = timestamp_of(m);
    if (const bplog* log = std::get_if<bplog>(&m)) e.subscription = *log;
    return e;
  }
  [[nodiscard]] static constexpr payload_event about(payload_event_kind kind,
                                                     const payload_in_flight& f) noexcept {
    payload_event e;
    e.kind = kind;
    e.origin = f.origin;
    e.ticket = f.ticket;
    (void)e.command.assign(f.address());
    e.command_timestamp = f.timestamp();
    e.count = f.sends;
    if (const bplog* log = std::get_if<bplog>(&f.message)) e.subscription = *log;
    return e;
  }
  constexpr void event(payload_event_kind kind, std::string_view detail = {}) noexcept {
    payload_event e;
    e.kind = kind;
    (void)e.detail.assign(detail.substr(0, decltype(e.detail)::capacity));
    events_.push(e);
  }

  constexpr void on_ack(const bfack& ack, time_point now) noexcept {
    payload_in_flight* match = nullptr;
    for (payload_in_flight& f : flights_) {
      if (!f.active || !ack.names(f.address())) continue;
      const std::optional<nmea::time_of_day> sent = f.timestamp();
      if (sent && !(ack.command_timestamp && same_command_time(*sent, *ack.command_timestamp)))
        continue;
      if (match == nullptr || f.first_sent < match->first_sent) match = &f;
    }
    if (match == nullptr) {
      payload_event e;
      e.kind = payload_event_kind::unmatched_ack;
      e.command = ack.command;
      e.command_timestamp = ack.command_timestamp;
      if (ack.description) e.detail = *ack.description;
      events_.push(e);
      return;
    }
    payload_event e = about(payload_event_kind::ack_ok, *match);
    if (ack.description) e.detail = *ack.description;
    const bool report_all = match->origin == message_origin::command;
    switch (ack.status) {
      case ack_status::pending:
        if (!match->pending_since) match->pending_since = now;
        e.kind = payload_event_kind::ack_pending;
        if (report_all) events_.push(e);
        return;
      case ack_status::ok:
        if (report_all) events_.push(e);
        break;
      case ack_status::failed:
        e.kind = payload_event_kind::ack_failed;
        events_.push(e);
        break;
      case ack_status::invalid:
        e.kind = payload_event_kind::ack_invalid;
        events_.push(e);
        break;
    }
    match->active = false;
  }

  constexpr void lose_control(std::string_view why) noexcept {
    control_ = false;
    request_.reset();
    request_due_ = false;
    event(payload_event_kind::control_lost, why);
  }

  /// Everything that is due at `now`, in order: acks overdue, the queue, heartbeat, keep-alive.
  constexpr void pump(time_point now) noexcept {
    for (payload_in_flight& f : flights_) {
      if (!f.active) continue;
      if (f.pending_since) {
        // "Within 2 seconds": a final ack at exactly pending_timeout is still in time.
        if (now - *f.pending_since > config_.pending_timeout) {
          events_.push(about(payload_event_kind::ack_timeout, f));
          f.active = false;
        }
        continue;
      }
      if (now - f.last_sent < config_.resend_after) continue;
      if (f.origin != message_origin::command) {
        f.active = false;  // the next heartbeat or keep-alive supersedes it
        continue;
      }
      if (f.sends > config_.max_resends) {
        events_.push(about(payload_event_kind::command_failed_after_retries, f));
        f.active = false;
        continue;
      }
      const bool sent =
          std::visit([&](const auto& m) { return put(m, f.ticket, f.origin); }, f.message);
      if (!sent) continue;
      ++f.sends;
      f.last_sent = now;
      events_.push(about(payload_event_kind::command_resent, f));
    }

    // Nothing queued goes out before start(): BPVER must be the first message (SPI 7.5).
    while (started_ && !queue_.empty() && awaiting() == nullptr) {
      const queued_command c = queue_.front();
      const bool sent = std::visit(
          [&](const auto& m) { return transmit(m, c.ticket, message_origin::command, true, now); },
          c.message);
      if (!sent) break;
      (void)queue_.pop_front();
    }

    if (started_ && config_.heartbeat_period.count() > 0 && now >= next_heartbeat_) {
      if (transmit(status_, 0, message_origin::heartbeat, false, now)) {
        next_heartbeat_ += config_.heartbeat_period;
        if (next_heartbeat_ <= now) next_heartbeat_ = now + config_.heartbeat_period;
      }
    }

    if (started_ && control_ && request_ &&
        (request_due_ || now - last_request_ >= keep_alive_interval())) {
      if (transmit(*request_, 0, message_origin::request, false, now)) {
        request_due_ = false;
        last_request_ = now;
      }
    }
  }

  payload_config config_;
  utc_clock utc_;
  time_point now_ = time_point::min();  // any steady epoch: the first `now` is taken as it is
  bool started_ = false;
  bool control_ = false;
  std::uint32_t next_ticket_ = 1;
  bool stamped_ = false;
  std::int64_t last_stamp_ = 0;
  detail::ring<queued_command, QueueCapacity> queue_;
  std::array<payload_in_flight, max_in_flight> flights_{};
  detail::ring<payload_line, OutboxCapacity> outbox_;
  detail::event_queue<payload_event, EventCapacity> events_;
  std::uint64_t overflows_ = 0;
  subscription_set<> subscriptions_;
  bpsts status_{{}, true, "OK"};
  time_point next_heartbeat_{};
  std::optional<bprmb> request_;
  bool request_due_ = false;
  time_point last_request_{};
  nmea::text<32> vehicle_version_;
};

}  // namespace seawire::sandshark
