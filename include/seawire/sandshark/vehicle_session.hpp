// SPDX-License-Identifier: BSL-1.0
#pragma once
// The vehicle (BAM) side of a Sandshark SPI session, sans I/O, for simulators and test doubles:
// fed each payload client's lines and steady time `now`, it hands back sentences per client and
// events. Subscriptions, acks (invalid, failed, ok, pending), BPRMB timeout and mission status:
// docs/sessions.md.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>

#include "seawire/detail/enum_names.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"
#include "seawire/sandshark/messages.hpp"
#include "seawire/sandshark/session_common.hpp"

namespace seawire::sandshark {

/// Which payload commands are acknowledged first with pending (3), then with the final status.
struct pending_commands {
  bool log = false;
  bool sts = false;
  bool rmb = false;
  bool abt = false;
  bool ver = false;

  [[nodiscard]] constexpr bool includes(std::string_view address) const noexcept {
    const std::string_view c = message_code(address);
    return (c == "LOG" && log) || (c == "STS" && sts) || (c == "RMB" && rmb) ||
           (c == "ABT" && abt) || (c == "VER" && ver);
  }
};

struct vehicle_config {
  nmea::text<32> version = "1.0";  ///< BFVER field 2, sent to each client on connect
  milliseconds request_timeout = timing::request_timeout;
  bool control_allowed = false;  ///< "allowDynamicRequests" at start (set_control() changes it)
  pending_commands pending{};
  /// When a pending command gets its final ack by itself; nullopt: only complete() sends it.
  std::optional<milliseconds> complete_pending_after = milliseconds{1000};
};

using client_id = std::uint8_t;

/// One sentence for one client (CR LF included).
struct vehicle_line {
  client_id client = 0;
  nmea::sentence_buffer<512> sentence;
  [[nodiscard]] constexpr std::string_view view() const noexcept { return sentence.view(); }
};

enum class vehicle_event_kind : std::uint8_t {
  request_started,    ///< a BPRMB was accepted while no request was active
  request_expired,    ///< no BPRMB for request_timeout: the vehicle resumes its behaviour
  request_cancelled,  ///< dynamic requests were disallowed while a request was active
  abort_requested,    ///< BPABT
  command_pending,    ///< a pending ack was sent; complete(ticket, ...) sends the final one
  invalid_command,    ///< a line that did not decode, or an unknown address (error, field)
  outbox_overflow,    ///< a sentence did not fit the outbox and was dropped
  events_lost,        ///< count events were dropped because the queue was full
};

/// The identifier of a vehicle_event_kind as text ("request_expired"), for logs.
// (A template of nothing, so that only a caller reads the enumerators' names.)
template <int = 0>
[[nodiscard]] constexpr std::string_view name(vehicle_event_kind k) noexcept {
  return seawire::detail::enumerator_name_of<8>(k, "unknown_event");
}

struct vehicle_event {
  vehicle_event_kind kind{};
  client_id client = 0;
  std::uint32_t ticket = 0;  ///< numbers every line received, for complete()
  nmea::text<16> command;    ///< the address the line carried ("BPRMB")
  std::optional<nmea::time_of_day> command_timestamp;
  errc error = errc::ok;  ///< invalid_command: why
  std::uint16_t field = 0;
  std::uint32_t count = 0;  ///< events_lost: how many
};

template <std::size_t MaxClients = 4, std::size_t OutboxCapacity = 32,
          std::size_t EventCapacity = 32>
class vehicle_session {
  // The payload's messages, named so that they depend on the class's parameters: a header that
  // merely defines the class does not compile their set.
  using payload_set = nmea::lazy<to_vehicle, static_cast<int>(MaxClients * 0)>;

 public:
  static constexpr std::size_t max_pending = 8;

  /// `utc` gives the timestamps' UTC time of day at each steady `now` (set_utc() re-anchors it).
  constexpr explicit vehicle_session(const utc_clock& utc,
                                     const vehicle_config& config = {}) noexcept
      : config_(config), utc_(utc), control_allowed_(config.control_allowed) {}

  // -- clients --------------------------------------------------------------------------------

  /// A new payload connection: sends it BFVER. nullopt when MaxClients are connected.
  [[nodiscard]] constexpr std::optional<client_id> connect(time_point now) noexcept {
    advance(now);
    for (std::size_t i = 0; i < MaxClients; ++i) {
      if (clients_[i].connected) continue;
      clients_[i] = {};
      clients_[i].connected = true;
      const auto id = static_cast<client_id>(i);
      bfver v;
      v.timestamp = utc_.at(now);
      v.version = config_.version;
      put(id, v);
      pump(now);
      return id;
    }
    return std::nullopt;
  }
  /// The client is gone: its subscriptions, and the pending acks owed to it (a client that
  /// connects later under the same id never gets an ack for a command it did not send).
  constexpr void disconnect(client_id c) noexcept {
    if (c >= MaxClients) return;
    clients_[c] = {};
    for (pending_ack& p : pending_)
      if (p.client == c) p.active = false;
  }
  [[nodiscard]] constexpr bool connected(client_id c) const noexcept {
    return c < MaxClients && clients_[c].connected;
  }

  // -- what the payloads say ------------------------------------------------------------------

  /// Decode one line from client `c` (to_vehicle_policy), act on it and acknowledge it. The
  /// result is the decode, for the caller's own use. A client that is not connected is ignored.
  [[nodiscard]] constexpr result<typename payload_set::variant> receive(client_id c,
                                                                        std::string_view line,
                                                                        time_point now) noexcept {
    advance(now);
    pump(now);  // a request that expired at `now` expires before this line is read
    // The decoder named through a template parameter: compiled where receive() is, not where
    // this header is read.
    result<typename payload_set::variant> r =
        decode_to_vehicle<static_cast<int>(MaxClients * 0)>(line);
    if (!connected(c)) return r;
    const std::uint32_t ticket = next_ticket_++;
    if (!r) {
      reject(c, line, r.ec, r.field, ticket, now);
      return r;
    }
    std::visit([&](const auto& m) { on_message(c, m, ticket, now); }, r.value);
    return r;
  }

  // -- what the vehicle does ------------------------------------------------------------------

  /// Allow or disallow dynamic requests ("allowDynamicRequests"), with BFCTL to subscribers.
  /// Disallowing ends an active request.
  constexpr void set_control(bool allowed, time_point now) noexcept {
    advance(now);
    pump(now);
    if (allowed == control_allowed_) return;
    control_allowed_ = allowed;
    if (!allowed && request_) {
      request_.reset();
      event(vehicle_event_kind::request_cancelled, request_client_);
    }
    (void)publish(bfctl{utc_.at(now), allowed}, now);
  }

  /// BFSHT to every client.
  constexpr void shutdown(time_point now) noexcept {
    advance(now);
    for (std::size_t i = 0; i < MaxClients; ++i)
      if (clients_[i].connected) put(static_cast<client_id>(i), bfsht{utc_.at(now)});
  }

  /// Send a status message (BFNVG, BFMIS ...) to every client that asked for it. Returns how
  /// many clients it was queued for, or the encoder's error. A timestamp left unset (a default
  /// time_of_day, 00:00:00, or an empty optional) is stamped with the vehicle's UTC clock at
  /// `now`, as connect() and set_control() stamp theirs. A BFMIS becomes the mission status the
  /// session knows (mission()).
  template <nmea::message_like M>
  [[nodiscard]] constexpr result<std::size_t> publish(const M& given, time_point now) noexcept {
    advance(now);
    M m = given;
    if constexpr (requires { m.timestamp; }) {
      using stamp_type = std::remove_cvref_t<decltype(m.timestamp)>;
      if constexpr (std::is_same_v<stamp_type, nmea::time_of_day>) {
        if (m.timestamp == nmea::time_of_day{}) m.timestamp = utc_.at(now);
      } else if constexpr (std::is_same_v<stamp_type, std::optional<nmea::time_of_day>>) {
        if (!m.timestamp) m.timestamp = utc_.at(now);
      }
    }
    if constexpr (std::is_same_v<M, bfmis>) mission_ = m;
    result<std::size_t> r;
    vehicle_line line;
    const result<std::size_t> e = nmea::encode_to(m, std::span<char>(line.sentence.data));
    if (!e) {
      r.ec = e.ec;
      r.field = e.field;
      return r;
    }
    line.sentence.size = e.value;
    for (std::size_t i = 0; i < MaxClients; ++i) {
      if (!should_send(static_cast<client_id>(i), M::nmea.address)) continue;
      line.client = static_cast<client_id>(i);
      if (push(line)) ++r.value;
    }
    return r;
  }

  /// Whether client `c` is to be sent the message with this code ("NVG") or address.
  [[nodiscard]] constexpr bool should_send(client_id c,
                                           std::string_view code_or_address) const noexcept {
    if (!connected(c)) return false;
    const std::string_view code = message_code(code_or_address);
    if (code == "SHT" || code == "VER") return true;  // commands (SPI 5) are always sent
    return clients_[c].subscriptions.includes(code);
  }

  /// Send the final ack of a command acknowledged as pending. False if `ticket` is not pending.
  constexpr bool complete(std::uint32_t ticket, ack_status status, std::string_view description,
                          time_point now) noexcept {
    advance(now);
    for (pending_ack& p : pending_) {
      if (!p.active || p.ticket != ticket) continue;
      p.active = false;
      ack(p.client, p.address.view(), p.timestamp, status, description, now);
      return true;
    }
    return false;
  }

  /// Let time pass: request timeout, automatic completion of pending acks.
  constexpr void tick(time_point now) noexcept {
    advance(now);
    pump(now);
  }

  /// The earliest time at which tick() has something to do, if any.
  [[nodiscard]] constexpr std::optional<time_point> next_deadline() const noexcept {
    std::optional<time_point> d;
    if (request_) d = last_request_ + config_.request_timeout + timing::just_after;
    if (config_.complete_pending_after) {
      for (const pending_ack& p : pending_) {
        if (!p.active) continue;
        const time_point t = p.since + *config_.complete_pending_after;
        if (!d || t < *d) d = t;
      }
    }
    return d;
  }

  // -- output ---------------------------------------------------------------------------------

  [[nodiscard]] constexpr std::optional<vehicle_line> poll_send() noexcept {
    return outbox_.pop_front();
  }
  [[nodiscard]] constexpr std::optional<vehicle_event> poll_event() noexcept {
    return events_.pop();
  }

  // -- state ----------------------------------------------------------------------------------

  [[nodiscard]] constexpr bool control_allowed() const noexcept { return control_allowed_; }
  /// Whether a BPRMB holds the vehicle's behaviour at `now`: one was accepted at most
  /// request_timeout ago (at exactly request_timeout it still holds).
  [[nodiscard]] constexpr bool request_active(time_point now) const noexcept {
    return request_.has_value() && now - last_request_ <= config_.request_timeout;
  }
  /// The request being followed (cleared when it expires, at the next call after expiry).
  [[nodiscard]] constexpr const std::optional<bprmb>& current_request() const noexcept {
    return request_;
  }
  /// What the client asked for (nothing for an id that is not connected).
  [[nodiscard]] constexpr const subscription_set<>& subscriptions(client_id c) const noexcept {
    return client(c).subscriptions;
  }
  /// The client's last BPSTS, if any (none for an id that is not connected).
  [[nodiscard]] constexpr const std::optional<bpsts>& payload_status(client_id c) const noexcept {
    return client(c).status;
  }
  /// The version the client reported in BPVER (empty until then, or for an id not connected).
  [[nodiscard]] constexpr std::string_view payload_version(client_id c) const noexcept {
    return client(c).version.view();
  }
  /// The mission status last published (BFMIS), or moved to Aborting by a BPABT; empty until a
  /// BFMIS was published.
  [[nodiscard]] constexpr const std::optional<bfmis>& mission() const noexcept { return mission_; }
  /// The vehicle's UTC clock, for the timestamps of what the caller publishes.
  [[nodiscard]] constexpr const utc_clock& utc() const noexcept { return utc_; }
  /// The UTC time at `now`, for the timestamps the session writes: a time of day or a
  /// std::chrono::system_clock time, as utc_clock::set() takes (a steady time does not compile).
  template <class T>
  constexpr void set_utc(time_point now, const T& utc) noexcept {
    advance(now);
    utc_.set(now, utc);
  }
  [[nodiscard]] constexpr std::uint64_t events_lost() const noexcept { return events_.lost(); }
  [[nodiscard]] constexpr std::uint64_t outbox_overflows() const noexcept { return overflows_; }

 private:
  struct client_state {
    bool connected = false;
    subscription_set<> subscriptions;
    nmea::text<32> version;
    std::optional<bpsts> status;
  };
  static constexpr client_state no_client{};
  struct pending_ack {
    bool active = false;
    client_id client = 0;
    std::uint32_t ticket = 0;
    nmea::text<16> address;
    std::optional<nmea::time_of_day> timestamp;
    ack_status final_status = ack_status::ok;
    time_point since{};
  };

  // The state of client c; an empty one for an id out of range (not some other client's).
  [[nodiscard]] constexpr const client_state& client(client_id c) const noexcept {
    return c < MaxClients ? clients_[c] : no_client;
  }

  constexpr void advance(time_point& now) noexcept {
    if (now < now_) now = now_;
    now_ = now;
  }

  [[nodiscard]] constexpr bool push(const vehicle_line& line) noexcept {
    if (outbox_.push_back(line)) return true;
    ++overflows_;
    event(vehicle_event_kind::outbox_overflow, line.client);
    return false;
  }
  template <class M>
  constexpr void put(client_id c, const M& m) noexcept {
    vehicle_line line;
    line.client = c;
    const result<std::size_t> e = nmea::encode_to(m, std::span<char>(line.sentence.data));
    if (!e) return;  // the session only writes messages it built within their fields' domains
    line.sentence.size = e.value;
    (void)push(line);
  }

  constexpr void event(vehicle_event_kind kind, client_id c) noexcept {
    vehicle_event e;
    e.kind = kind;
    e.client = c;
    events_.push(e);
  }

  constexpr void ack(client_id c, std::string_view address,
                     std::optional<nmea::time_of_day> timestamp, ack_status status,
                     std::string_view description, time_point now) noexcept {
    if (!connected(c) || !clients_[c].subscriptions.acks()) return;
    bfack a;
    a.timestamp = utc_.at(now);
    (void)a.command.assign(message_code(address));
    a.command_timestamp = timestamp;
    a.status = status;
    nmea::text<256> d;
    // Keep only what a text field may carry; the description is for people.
    std::size_t n = 0;
    char buf[256]{};
    for (char ch : description) {
      if (n == sizeof buf) break;
      if (seawire::detail::is_printable(ch) && !seawire::detail::is_reserved(ch)) buf[n++] = ch;
    }
    (void)d.assign(std::string_view(buf, n));
    a.description = d;
    put(c, a);
  }

  /// Acknowledge `address` now, or as pending when the configuration says so.
  constexpr void acknowledge(client_id c, std::string_view address,
                             std::optional<nmea::time_of_day> timestamp, ack_status status,
                             std::string_view description, std::uint32_t ticket,
                             time_point now) noexcept {
    if (status == ack_status::invalid || !config_.pending.includes(address) ||
        !clients_[c].subscriptions.acks()) {
      ack(c, address, timestamp, status, description, now);
      return;
    }
    pending_ack* slot = nullptr;
    for (pending_ack& p : pending_)
      if (!p.active) slot = &p;
    if (slot == nullptr) {  // too many at once: answer finally now rather than not at all
      ack(c, address, timestamp, status, description, now);
      return;
    }
    *slot = {true, c, ticket, {}, timestamp, status, now};
    (void)slot->address.assign(address);
    ack(c, address, timestamp, ack_status::pending, "pending", now);
    vehicle_event e;
    e.kind = vehicle_event_kind::command_pending;
    e.client = c;
    e.ticket = ticket;
    e.command = slot->address;
    e.command_timestamp = timestamp;
    events_.push(e);
  }

  /// "bad_enum in field 4 (depth_mode)": the description of an invalid ack.
  [[nodiscard]] static constexpr nmea::text<96> explain(errc error, std::uint16_t field,
                                                        std::string_view field_name) noexcept {
    char buf[96]{};
    std::size_t n = 0;
    const auto add = [&](std::string_view part) {
      for (char ch : part)
        if (n < sizeof buf) buf[n++] = ch;
    };
    add(seawire::name(error));
    if (field != 0) {
      add(" in field ");
      if (field >= 10) add(std::string_view(&"0123456789"[field / 10 % 10], 1));
      add(std::string_view(&"0123456789"[field % 10], 1));
      if (!field_name.empty()) {
        add(" (");
        add(field_name);
        add(")");
      }
    }
    nmea::text<96> t;
    (void)t.assign(std::string_view(buf, n));
    return t;
  }

  /// A line that did not decode: ack it invalid if its address can still be read.
  constexpr void reject(client_id c, std::string_view line, errc error, std::uint16_t field,
                        std::uint32_t ticket, time_point now) noexcept {
    vehicle_event e;
    e.kind = vehicle_event_kind::invalid_command;
    e.client = c;
    e.ticket = ticket;
    e.error = error;
    e.field = field;
    nmea::parse_policy lenient = to_vehicle_policy;
    lenient.checksum = nmea::checksum_policy::ignore;
    const result<nmea::sentence_view> s = nmea::parse(line, lenient);
    if (s) {
      (void)e.command.assign(s.value.address);
      // Echo field 1 when it is a time, so the payload can match the ack to its command.
      nmea::field_reader r(s.value, lenient);
      nmea::time_of_day t;
      if (r.peek().present && !r.peek().blank() &&
          nmea::codec<nmea::time_of_day>::read(r, t) == errc::ok)
        e.command_timestamp = t;
      const nmea::text<96> why =
          explain(error, field, payload_set::field_name(s.value.address, field));
      ack(c, s.value.address, e.command_timestamp, ack_status::invalid, why.view(), now);
    }
    events_.push(e);
  }

  constexpr void on_message(client_id c, const nmea::unknown_sentence& u, std::uint32_t ticket,
                            time_point now) noexcept {
    vehicle_event e;
    e.kind = vehicle_event_kind::invalid_command;
    e.client = c;
    e.ticket = ticket;
    e.error = errc::unknown_address;
    (void)e.command.assign(u.sentence.address);
    nmea::field_reader r(u.sentence, to_vehicle_policy);
    nmea::time_of_day t;
    if (r.peek().present && !r.peek().blank() &&
        nmea::codec<nmea::time_of_day>::read(r, t) == errc::ok)
      e.command_timestamp = t;
    events_.push(e);
    ack(c, u.sentence.address, e.command_timestamp, ack_status::invalid, "unknown message", now);
  }
  constexpr void on_message(client_id c, const bplog& m, std::uint32_t ticket,
                            time_point now) noexcept {
    // The code is 3 upper-case letters or digits: BPLOG's description refuses any other.
    const bool applied = clients_[c].subscriptions.apply(m);
    acknowledge(c, bplog::nmea.address, std::nullopt, applied ? ack_status::ok : ack_status::failed,
                applied ? "" : "too many subscriptions", ticket, now);
  }
  constexpr void on_message(client_id c, const bpsts& m, std::uint32_t ticket,
                            time_point now) noexcept {
    clients_[c].status = m;
    acknowledge(c, bpsts::nmea.address, m.timestamp, ack_status::ok, "", ticket, now);
  }
  constexpr void on_message(client_id c, const bprmb& m, std::uint32_t ticket,
                            time_point now) noexcept {
    if (!control_allowed_) {
      acknowledge(c, bprmb::nmea.address, m.timestamp, ack_status::failed,
                  "dynamic requests not allowed", ticket, now);
      return;
    }
    const bool started = !request_;
    request_ = m;
    request_client_ = c;
    last_request_ = now;
    if (started) event(vehicle_event_kind::request_started, c);
    acknowledge(c, bprmb::nmea.address, m.timestamp, ack_status::ok, "", ticket, now);
  }
  constexpr void on_message(client_id c, const bpabt& m, std::uint32_t ticket,
                            time_point now) noexcept {
    vehicle_event e;
    e.kind = vehicle_event_kind::abort_requested;
    e.client = c;
    e.ticket = ticket;
    (void)e.command.assign(bpabt::nmea.address);
    e.command_timestamp = m.timestamp;
    events_.push(e);
    acknowledge(c, bpabt::nmea.address, m.timestamp, ack_status::ok, "", ticket, now);
    // A mission under way starts aborting, and its subscribers hear it (SPI: BFMIS is sent
    // when the status changes). The caller publishes "Aborted" once the vehicle has stopped.
    if (mission_ && abortable(mission_->state())) {
      bfmis aborting = *mission_;
      aborting.timestamp = utc_.at(now);
      (void)aborting.status.assign("Aborting");
      (void)aborting.details.assign("abort requested by the payload");
      (void)publish(aborting, now);
    }
  }
  [[nodiscard]] static constexpr bool abortable(mission_state s) noexcept {
    return s == mission_state::waiting || s == mission_state::ready ||
           s == mission_state::running || s == mission_state::wrapping_up;
  }
  constexpr void on_message(client_id c, const bpver& m, std::uint32_t ticket,
                            time_point now) noexcept {
    clients_[c].version = m.version;
    acknowledge(c, bpver::nmea.address, m.timestamp, ack_status::ok, "", ticket, now);
  }

  constexpr void pump(time_point now) noexcept {
    if (request_ && !request_active(now)) {
      request_.reset();
      event(vehicle_event_kind::request_expired, request_client_);
    }
    if (config_.complete_pending_after) {
      for (pending_ack& p : pending_) {
        if (!p.active || now - p.since < *config_.complete_pending_after) continue;
        p.active = false;
        ack(p.client, p.address.view(), p.timestamp, p.final_status, "", now);
      }
    }
  }

  vehicle_config config_;
  utc_clock utc_;
  time_point now_ = time_point::min();  // any steady epoch: the first `now` is taken as it is
  bool control_allowed_ = false;
  std::uint32_t next_ticket_ = 1;
  std::array<client_state, MaxClients> clients_{};
  std::array<pending_ack, max_pending> pending_{};
  std::optional<bprmb> request_;
  std::optional<bfmis> mission_;
  client_id request_client_ = 0;
  time_point last_request_{};
  detail::ring<vehicle_line, OutboxCapacity> outbox_;
  detail::event_queue<vehicle_event, EventCapacity> events_;
  std::uint64_t overflows_ = 0;
};

}  // namespace seawire::sandshark
