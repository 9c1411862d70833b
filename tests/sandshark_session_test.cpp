// SPDX-License-Identifier: BSL-1.0
// Sandshark SPI sessions under simulated time: the payload's startup, command queue, ack
// matching, resends, pending acks, heartbeat and BPRMB keep-alive; the vehicle's subscriptions,
// acks and request timeout; and the two talking to each other.

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "seawire/nmea/checksum.hpp"
#include "seawire/sandshark/session.hpp"

#include "support.hpp"

using namespace seawire;
using namespace seawire::sandshark;
using namespace seawire::nmea;
using namespace std::chrono_literals;

namespace {

using namespace support;

time_point at(std::chrono::milliseconds ms) { return time_point{} + ms; }
/// These tests' UTC: the steady time_point{} is midnight, so at(500ms) is 00:00:00.500.
const utc_clock midnight(time_point{}, time_of_day{});

template <class S>
std::vector<std::string> sent(S& s) {
  std::vector<std::string> out;
  while (auto l = s.poll_send()) out.emplace_back(l->view());
  return out;
}

template <class S>
auto events(S& s) {
  std::vector<std::remove_reference_t<decltype(*s.poll_event())>> out;
  while (auto e = s.poll_event()) out.push_back(*e);
  return out;
}

std::string address(std::string_view line) { return std::string(line.substr(1, 5)); }

/// Field 1 of a sent sentence ("" for BPLOG, which has no timestamp).
std::string stamp_of(std::string_view line) {
  if (address(line) == "BPLOG") return "";
  const auto s = nmea::parse(line);
  REQUIRE(s.ok());
  return std::string(s.value.field(1).text);
}

/// The vehicle's acknowledgement of `command` (a line the payload sent).
std::string ack_of(std::string_view command, char status, std::string_view description = "") {
  return sealed("BFACK,120000.000," + address(command).substr(2) + "," + stamp_of(command) + ",," +
                status + ",0," + std::string(description) + ",");
}

std::vector<std::string> with_address(const std::vector<std::string>& lines, std::string_view a) {
  std::vector<std::string> out;
  for (const auto& l : lines)
    if (address(l) == a) out.push_back(l);
  return out;
}

payload_config quiet() {
  payload_config c;
  c.heartbeat_period = 0ms;  // keep the outbox to what a test looks at
  c.sync_utc_from_vehicle = false;
  return c;
}

/// A payload that has started and had BPLOG,ACK,ON acknowledged: nothing in flight.
template <class S>
void started_with_acks(S& p, time_point now) {
  p.start(now);
  const auto lines = sent(p);
  REQUIRE(lines.size() == 2);
  REQUIRE(lines[1] == "$BPLOG,ACK,ON*1E\r\n");
  (void)p.receive(ack_of(lines[1], '2'), now);
  REQUIRE(p.awaiting() == nullptr);
  (void)events(p);
}

bprmb heading_request(int heading) {
  bprmb r;
  r.heading = decimal(heading);
  r.horizontal_mode = horizontal_mode::heading;
  return r;
}

}  // namespace

// =============================================================================================
// payload side

TEST_CASE("payload startup: BPVER, then BPLOG,ACK,ON before any other subscription") {
  payload_session<> p(midnight, quiet());
  // Asked for before start(): still sent after the handshake.
  REQUIRE(p.subscribe("NVG", at(0ms)).ok());
  p.start(at(0ms));
  auto lines = sent(p);
  REQUIRE(lines.size() == 2);
  CHECK(lines[0] == "$BPVER,000000.000,1.0*62\r\n");
  CHECK(lines[1] == "$BPLOG,ACK,ON*1E\r\n");
  CHECK(p.acks_enabled());
  REQUIRE(p.awaiting() != nullptr);
  CHECK(p.awaiting()->address() == "BPLOG");
  CHECK(p.queued() == 1);  // NVG waits for the ACK ON ack

  (void)p.receive(ack_of(lines[1], '2'), at(100ms));
  const auto ev = events(p);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == payload_event_kind::ack_ok);
  CHECK(ev[0].command == "BPLOG");
  // BPLOG has no timestamp: the event says which subscription was acknowledged.
  REQUIRE(ev[0].subscription);
  CHECK(ev[0].subscription->code == "ACK");
  CHECK(ev[0].subscription->state == log_state::on);
  lines = sent(p);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0] == sealed("BPLOG,NVG,ON"));
  CHECK(p.subscriptions().includes("NVG"));
  CHECK_FALSE(p.subscriptions().includes("NVR"));

  (void)p.receive(ack_of(lines[0], '2'), at(200ms));
  const auto nvg = events(p);
  REQUIRE(nvg.size() == 1);
  CHECK(nvg[0].kind == payload_event_kind::ack_ok);
  REQUIRE(nvg[0].subscription);
  CHECK(nvg[0].subscription->code == "NVG");
  CHECK(nvg[0].subscription->state == log_state::on);

  // Events about other commands carry none.
  REQUIRE(p.subscribe("NVG", at(300ms), log_state::off).ok());
  const auto off = sent(p);
  REQUIRE(off.size() == 1);
  CHECK(off[0] == sealed("BPLOG,NVG,OFF"));
  (void)p.receive(ack_of(off[0], '2'), at(400ms));
  const auto off_ev = events(p);
  REQUIRE(off_ev.size() == 1);
  REQUIRE(off_ev[0].subscription);
  CHECK(off_ev[0].subscription->state == log_state::off);
}

TEST_CASE("payload startup without acks: nothing waits") {
  payload_config c = quiet();
  c.want_acks = false;
  c.version = "2.1";
  payload_session<> p(midnight, c);
  p.start(at(0ms));
  REQUIRE(p.subscribe("ALL", at(0ms)).ok());
  REQUIRE(p.subscribe("NVG", at(0ms), log_state::off).ok());
  const auto lines = sent(p);
  REQUIRE(lines.size() == 3);
  CHECK(address(lines[0]) == "BPVER");
  CHECK(lines[0].find(",2.1*") != std::string::npos);
  CHECK(lines[1] == "$BPLOG,ALL,ON*16\r\n");
  CHECK(lines[2] == sealed("BPLOG,NVG,OFF"));
  CHECK_FALSE(p.acks_enabled());
  CHECK(p.awaiting() == nullptr);
  CHECK(p.in_flight() == 0);
  // ALL never includes ACK.
  CHECK(p.subscriptions().includes("NVR"));
  CHECK_FALSE(p.subscriptions().includes("NVG"));
  CHECK_FALSE(p.subscriptions().includes("ACK"));
}

TEST_CASE("payload: ack before the timeout completes the command, nothing is resent") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(0ms));
  const auto ticket = p.subscribe("MIS", at(1000ms));
  REQUIRE(ticket.ok());
  const auto lines = sent(p);
  REQUIRE(lines.size() == 1);
  (void)p.receive(ack_of(lines[0], '2', "done"), at(5999ms));
  const auto ev = events(p);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == payload_event_kind::ack_ok);
  CHECK(ev[0].ticket == ticket.value);
  CHECK(ev[0].detail == "done");
  CHECK(ev[0].origin == message_origin::command);
  p.tick(at(30000ms));
  CHECK(sent(p).empty());
  CHECK(events(p).empty());
  CHECK(p.in_flight() == 0);
}

TEST_CASE("payload: an ack that never comes: 3 resends, 5 s apart, then failure") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(0ms));
  bpabt cmd;
  (void)cmd.message.assign("test");
  const auto ticket = p.send(cmd, at(0ms));
  REQUIRE(ticket.ok());
  const auto first = sent(p);
  REQUIRE(first.size() == 1);
  CHECK(address(first[0]) == "BPABT");

  p.tick(at(4999ms));
  CHECK(sent(p).empty());
  CHECK(p.next_deadline() == at(5000ms));
  for (std::uint32_t n = 2; n <= 4; ++n) {
    p.tick(at(std::chrono::milliseconds(5000 * (n - 1))));
    const auto again = sent(p);
    REQUIRE(again.size() == 1);
    CHECK(again[0] == first[0]);  // the same bytes: an ack of any copy matches
    const auto ev = events(p);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0].kind == payload_event_kind::command_resent);
    CHECK(ev[0].count == n);
    CHECK(ev[0].ticket == ticket.value);
  }
  p.tick(at(19999ms));
  CHECK(events(p).empty());
  p.tick(at(20000ms));
  CHECK(sent(p).empty());
  const auto ev = events(p);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == payload_event_kind::command_failed_after_retries);
  CHECK(ev[0].count == 4);
  CHECK(ev[0].command == "BPABT");
  CHECK(p.awaiting() == nullptr);
}

TEST_CASE("payload: the resend count is configurable") {
  payload_config c = quiet();
  c.max_resends = 1;
  c.resend_after = 2000ms;
  payload_session<> p(midnight, c);
  started_with_acks(p, at(0ms));
  REQUIRE(p.subscribe("NVG", at(0ms)).ok());
  CHECK(sent(p).size() == 1);
  p.tick(at(2000ms));
  CHECK(sent(p).size() == 1);
  p.tick(at(4000ms));
  CHECK(sent(p).empty());
  const auto ev = events(p);
  REQUIRE(ev.size() == 2);
  CHECK(ev[1].kind == payload_event_kind::command_failed_after_retries);
  CHECK(ev[1].count == 2);
}

TEST_CASE("payload: pending, then the final ack within 2 s") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(0ms));
  REQUIRE(p.send(bpver{{}, "1.0"}, at(0ms)).ok());
  const auto lines = sent(p);
  REQUIRE(lines.size() == 1);
  (void)p.receive(ack_of(lines[0], '3', "working"), at(4000ms));
  auto ev = events(p);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == payload_event_kind::ack_pending);
  CHECK(ev[0].detail == "working");
  // Pending: the vehicle has it, so the 5 s resend no longer applies.
  p.tick(at(5500ms));
  CHECK(sent(p).empty());
  CHECK(events(p).empty());
  (void)p.receive(ack_of(lines[0], '1', "no"), at(5999ms));
  ev = events(p);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == payload_event_kind::ack_failed);
  CHECK(ev[0].detail == "no");
  CHECK(p.awaiting() == nullptr);
}

TEST_CASE("payload: pending, then nothing: ack_timeout 2 s later and the queue moves on") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(0ms));
  REQUIRE(p.subscribe("NVG", at(0ms)).ok());
  REQUIRE(p.subscribe("NVR", at(0ms)).ok());
  const auto lines = sent(p);
  REQUIRE(lines.size() == 1);
  (void)p.receive(ack_of(lines[0], '3'), at(1000ms));
  (void)events(p);
  // "Within 2 seconds": at exactly 2 s the final ack is still in time; one tick later it is not.
  CHECK(p.next_deadline() == at(3000ms) + timing::just_after);
  p.tick(at(3000ms));
  CHECK(events(p).empty());
  CHECK(sent(p).empty());
  p.tick(at(3000ms) + timing::just_after);
  const auto ev = events(p);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == payload_event_kind::ack_timeout);
  CHECK(ev[0].command == "BPLOG");
  const auto next = sent(p);
  REQUIRE(next.size() == 1);
  CHECK(next[0] == sealed("BPLOG,NVR,ON"));
}

TEST_CASE("payload: a final ack exactly 2 s after the pending one, whatever the call order") {
  for (const bool tick_first : {false, true}) {
    INFO("tick at the deadline first: " << tick_first);
    payload_session<> p(midnight, quiet());
    started_with_acks(p, at(0ms));
    REQUIRE(p.subscribe("NVG", at(0ms)).ok());
    const auto lines = sent(p);
    REQUIRE(lines.size() == 1);
    (void)p.receive(ack_of(lines[0], '3'), at(1000ms));
    (void)events(p);
    if (tick_first) p.tick(at(3000ms));
    (void)p.receive(ack_of(lines[0], '2'), at(3000ms));
    const auto ev = events(p);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0].kind == payload_event_kind::ack_ok);
  }
}

TEST_CASE("payload: nothing goes out before start(), not an abort, not a request") {
  payload_session<> p(midnight, quiet());
  const auto ticket = p.abort("leak", at(0ms));
  REQUIRE(ticket.ok());
  (void)p.receive(sealed("BFCTL,000000.100,1"), at(100ms));
  REQUIRE(p.set_request(heading_request(90), at(200ms)).ok());
  p.tick(at(6000ms));
  CHECK(sent(p).empty());
  CHECK(p.next_deadline() == std::nullopt);

  // BPVER first (SPI 7.5), then the acks, then the abort that was waiting.
  p.start(at(7000ms));
  auto lines = sent(p);
  REQUIRE(lines.size() >= 2);
  CHECK(address(lines[0]) == "BPVER");
  CHECK(lines[1] == "$BPLOG,ACK,ON*1E\r\n");
  CHECK(with_address(lines, "BPABT").empty());  // behind ACK ON, which awaits its ack
  (void)p.receive(ack_of(lines[1], '2'), at(7100ms));
  lines = sent(p);
  REQUIRE(!with_address(lines, "BPABT").empty());
  CHECK(with_address(lines, "BPABT")[0].find(",leak,1*") != std::string::npos);
}

TEST_CASE("payload: start() again is a new connection: handshake, subscriptions, old commands") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(0ms));
  REQUIRE(p.subscribe("NVG", at(0ms)).ok());
  auto lines = sent(p);
  REQUIRE(lines.size() == 1);
  (void)p.receive(ack_of(lines[0], '2'), at(100ms));
  REQUIRE(p.subscribe("ALL", at(200ms)).ok());
  lines = sent(p);
  REQUIRE(lines.size() == 1);
  (void)p.receive(ack_of(lines[0], '2'), at(300ms));
  REQUIRE(p.subscribe("MIS", at(400ms), log_state::off).ok());
  lines = sent(p);
  REQUIRE(lines.size() == 1);
  (void)p.receive(ack_of(lines[0], '2'), at(500ms));
  const bpsts st{{}, false, "sonar fault"};
  const auto ticket = p.send(st, at(600ms));
  REQUIRE(ticket.ok());
  REQUIRE(sent(p).size() == 1);  // awaiting its ack when the link drops
  (void)events(p);

  p.start(at(2000ms));
  // The vehicle has turned the acks off: BPVER is not waited on, ACK ON follows at once.
  lines = sent(p);
  REQUIRE(lines.size() == 2);
  CHECK(address(lines[0]) == "BPVER");
  CHECK(lines[1] == "$BPLOG,ACK,ON*1E\r\n");
  // Then the subscriptions, as one request each, then the command, each after the last's ack.
  // (ALL ON replaced NVG's own request; MIS OFF is the exception under ALL.)
  const std::vector<std::string> expected = {sealed("BPLOG,ALL,ON"), sealed("BPLOG,MIS,OFF")};
  std::string last = lines[1];
  for (const std::string& want : expected) {
    (void)p.receive(ack_of(last, '2'), at(2100ms));
    lines = sent(p);
    REQUIRE(lines.size() == 1);
    CHECK(lines[0] == want);
    last = lines[0];
  }
  (void)p.receive(ack_of(last, '2'), at(2200ms));
  lines = sent(p);
  REQUIRE(lines.size() == 1);
  CHECK(address(lines[0]) == "BPSTS");
  (void)events(p);
  (void)p.receive(ack_of(lines[0], '2'), at(2300ms));
  const auto ev = events(p);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == payload_event_kind::ack_ok);
  CHECK(ev[0].ticket == ticket.value);
  CHECK(p.subscriptions().includes("NVR"));
  CHECK_FALSE(p.subscriptions().includes("MIS"));
}

TEST_CASE("payload: unrelated traffic between a command and its ack") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(0ms));
  bpsts st{{}, false, "sonar fault"};
  const auto ticket = p.send(st, at(100ms));
  REQUIRE(ticket.ok());
  const auto lines = sent(p);
  REQUIRE(lines.size() == 1);
  for (const char* body :
       {"BFNVG,120000.100,4218.0,N,07106.0,W,1,,2.5,45.0,0.1,-0.2,",
        "BFNVR,120000.110,0.1,0.2,0,0,0,0", "BFMIS,120000.200,dive.xml,Running,",
        "BFACK,120000.250,LOG,,,2,0,,", "BFVER,120000.300,1.0", "BFXYZ,120000.310,future"}) {
    REQUIRE(p.receive(sealed(body), at(200ms)).ok());
  }
  CHECK(p.vehicle_version() == "1.0");
  // The LOG ack matched nothing in flight: reported, the STS command still awaits its own.
  auto ev = events(p);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == payload_event_kind::unmatched_ack);
  REQUIRE(p.awaiting() != nullptr);
  CHECK(p.awaiting()->ticket == ticket.value);
  (void)p.receive(ack_of(lines[0], '2'), at(300ms));
  ev = events(p);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == payload_event_kind::ack_ok);
  CHECK(ev[0].ticket == ticket.value);
  CHECK(ev[0].command == "BPSTS");
}

TEST_CASE("payload: an ack whose command timestamp matches nothing is reported, queue intact") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(0ms));
  REQUIRE(p.send(bpver{{}, "1.0"}, at(500ms)).ok());
  REQUIRE(p.subscribe("NVG", at(500ms)).ok());
  const auto lines = sent(p);
  REQUIRE(lines.size() == 1);
  CHECK(stamp_of(lines[0]) == "000000.500");

  // Right name, wrong timestamp; and right timestamp, wrong name.
  (void)p.receive(sealed("BFACK,000001.000,VER,000000.400,,2,0,,"), at(600ms));
  (void)p.receive(sealed("BFACK,000001.000,STS,000000.500,,2,0,,"), at(600ms));
  const auto ev = events(p);
  REQUIRE(ev.size() == 2);
  CHECK(ev[0].kind == payload_event_kind::unmatched_ack);
  CHECK(ev[0].command == "VER");
  CHECK(ev[0].command_timestamp == time_of_day{0, 0, 0, 400, 3});
  CHECK(ev[1].kind == payload_event_kind::unmatched_ack);
  CHECK(ev[1].command == "STS");
  REQUIRE(p.awaiting() != nullptr);
  CHECK(p.awaiting()->address() == "BPVER");
  CHECK(p.queued() == 1);
  CHECK(sent(p).empty());

  // The echo may carry fewer digits than were sent: 000000.50 names 000000.500.
  (void)p.receive(sealed("BFACK,000001.000,VER,000000.50,,2,0,,"), at(700ms));
  CHECK(events(p).at(0).kind == payload_event_kind::ack_ok);
  CHECK(sent(p) == std::vector<std::string>{sealed("BPLOG,NVG,ON")});
}

TEST_CASE("payload: commands wait behind the one awaiting its ack, in order") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(0ms));
  const auto a = p.subscribe("NVG", at(0ms));
  const auto b = p.subscribe("NVR", at(0ms));
  const auto c = p.send(bpsts{{}, true, "ready"}, at(0ms));
  REQUIRE((a.ok() && b.ok() && c.ok()));
  CHECK(a.value < b.value);
  CHECK(b.value < c.value);
  auto lines = sent(p);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0] == sealed("BPLOG,NVG,ON"));
  CHECK(p.queued() == 2);
  p.tick(at(4000ms));
  CHECK(sent(p).empty());

  (void)p.receive(ack_of(lines[0], '2'), at(4100ms));
  lines = sent(p);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0] == sealed("BPLOG,NVR,ON"));
  CHECK(p.queued() == 1);
  (void)p.receive(ack_of(lines[0], '0', "unknown code"), at(4200ms));
  lines = sent(p);
  REQUIRE(lines.size() == 1);
  CHECK(address(lines[0]) == "BPSTS");
  CHECK(stamp_of(lines[0]) == "000004.200");  // stamped when sent, not when queued
  CHECK(p.queued() == 0);

  const auto ev = events(p);
  REQUIRE(ev.size() == 2);
  CHECK(ev[0].kind == payload_event_kind::ack_ok);
  CHECK(ev[0].ticket == a.value);
  CHECK(ev[1].kind == payload_event_kind::ack_invalid);
  CHECK(ev[1].ticket == b.value);
  CHECK(ev[1].detail == "unknown code");
}

TEST_CASE("payload: abort goes out at once, ahead of a command awaiting its ack") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(0ms));
  REQUIRE(p.subscribe("NVG", at(0ms)).ok());
  REQUIRE(p.subscribe("NVR", at(0ms)).ok());
  (void)sent(p);
  const auto t = p.abort("leak", at(1000ms), abort_reason::with_errors);
  REQUIRE(t.ok());
  const auto lines = sent(p);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0] == sealed("BPABT,000001.000,leak,1"));
  CHECK(p.queued() == 1);
  (void)p.receive(ack_of(lines[0], '2'), at(1100ms));
  const auto ev = events(p);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].ticket == t.value);
  CHECK(ev[0].command == "BPABT");
  CHECK(p.awaiting()->address() == "BPLOG");  // the queue is where it was
}

TEST_CASE("payload: timestamps are distinct, so (name, timestamp) names one message") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(0ms));
  REQUIRE(p.abort("a", at(1000ms)).ok());
  REQUIRE(p.abort("b", at(1000ms)).ok());
  const auto lines = sent(p);
  REQUIRE(lines.size() == 2);
  CHECK(stamp_of(lines[0]) == "000001.000");
  CHECK(stamp_of(lines[1]) == "000001.001");
  (void)p.receive(ack_of(lines[1], '1'), at(1200ms));
  const auto ev = events(p);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == payload_event_kind::ack_failed);
  CHECK(ev[0].command_timestamp == time_of_day{0, 0, 1, 1, 3});
  CHECK(p.in_flight() == 1);
}

TEST_CASE("payload: the UTC clock follows the vehicle's timestamps") {
  payload_config c = quiet();
  c.sync_utc_from_vehicle = true;
  payload_session<> p(midnight, c);
  (void)p.receive(sealed("BFCTL,235959.500,0"), at(10000ms));
  p.start(at(10000ms));
  CHECK(stamp_of(sent(p).at(0)) == "235959.500");  // BPVER
  REQUIRE(p.abort("x", at(11000ms)).ok());
  CHECK(stamp_of(sent(p).at(0)) == "000000.500");  // past midnight
  p.set_utc(at(12000ms), time_of_day{8, 0, 0, 0, 0});
  REQUIRE(p.abort("y", at(12250ms)).ok());
  CHECK(stamp_of(sent(p).at(0)) == "080000.250");
}

namespace {
using std::chrono::days;
using std::chrono::January;
using std::chrono::milliseconds;
using std::chrono::November;
using std::chrono::seconds;
using std::chrono::sys_days;

/// "hhmmss.sss" for a UTC time, by std::chrono's own calendar arithmetic (not the library's).
std::string utc_text(utc_time t) {
  const auto ms = std::chrono::floor<std::chrono::milliseconds>(t);
  const std::chrono::hh_mm_ss<std::chrono::milliseconds> hms(
      ms - std::chrono::floor<std::chrono::days>(ms));
  char b[16];
  std::snprintf(b, sizeof b, "%02d%02d%02d.%03d", static_cast<int>(hms.hours().count()),
                static_cast<int>(hms.minutes().count()), static_cast<int>(hms.seconds().count()),
                static_cast<int>(hms.subseconds().count()));
  return b;
}
/// Steady epochs a machine may have: just booted, 36 s, the 36 min 14.581 s whose stamps once
/// read "003614.581", 400 days; and one before the epoch.
const std::vector<std::chrono::milliseconds> uptimes = {
    0ms, 36'000ms, 2'174'581ms, std::chrono::milliseconds(std::chrono::days(400)), -5'000ms};
}  // namespace

TEST_CASE("payload stamps: the UTC time of day it was built with, advanced by steady time") {
  // 23:59:59.900 UTC: the stamps cross midnight within the first 100 ms.
  const utc_time utc0 = sys_days{2026y / November / 26} + 23h + 59min + 59s + 900ms;
  const std::vector<milliseconds> later = {0ms,   2ms,     50ms,        99ms,        100ms,
                                           101ms, 1'234ms, 3'600'100ms, 86'400'000ms};
  for (const milliseconds uptime : uptimes) {
    CAPTURE(uptime.count());
    const time_point t0 = time_point{} + uptime;
    payload_config c = quiet();
    c.want_acks = false;  // nothing awaits an ack: every abort goes out at once
    payload_session<> p(utc_clock(t0, utc0), c);
    p.start(t0);
    CHECK(stamp_of(sent(p).at(0)) == "235959.900");  // BPVER
    for (const milliseconds d : later) {
      CAPTURE(d.count());
      REQUIRE(p.abort("x", t0 + d).ok());
      const auto lines = sent(p);
      REQUIRE(lines.size() == 1);
      CHECK(stamp_of(lines[0]) == utc_text(utc0 + d + (d == 0ms ? 1ms : 0ms)));
    }
  }
  // The values behind the list: BPVER and the first abort share 23:59:59.900 (the second is
  // one ms later), the abort 100 ms on is at midnight.
  CHECK(utc_text(utc0 + 100ms) == "000000.000");
  CHECK(utc_text(utc0 + 101ms) == "000000.001");
}

TEST_CASE("payload stamps: the heartbeat's stamps follow the steady clock, whatever its epoch") {
  const utc_time utc0 = sys_days{2026y / November / 26} + 23h + 13min + 0s + 250ms;
  for (const milliseconds uptime : uptimes) {
    CAPTURE(uptime.count());
    const time_point t0 = time_point{} + uptime;
    payload_config c = quiet();
    c.heartbeat_period = 1s;
    c.want_acks = false;
    payload_session<> p(utc_clock(t0, utc0), c);
    p.start(t0);
    (void)sent(p);
    std::vector<std::string> stamps;
    for (int s = 1; s <= 36; ++s) {
      p.tick(t0 + seconds(s));
      for (const auto& l : with_address(sent(p), "BPSTS")) stamps.push_back(stamp_of(l));
    }
    REQUIRE(stamps.size() == 36);
    for (int s = 1; s <= 36; ++s)
      CHECK(stamps[static_cast<std::size_t>(s - 1)] == utc_text(utc0 + seconds(s)));
  }
}

TEST_CASE("payload stamps: two in one millisecond are 1 ms apart, across midnight too") {
  const time_point t0 = time_point{} + days(400);
  payload_config c = quiet();
  c.want_acks = false;
  payload_session<> p(utc_clock(t0, sys_days{2026y / January / 1} - 1ms), c);
  p.start(t0);
  REQUIRE(p.abort("a", t0).ok());
  REQUIRE(p.abort("b", t0).ok());
  REQUIRE(p.abort("c", t0 + 1ms).ok());  // the clock is at 00:00:00.000, already taken
  REQUIRE(p.abort("d", t0 + 5ms).ok());
  std::vector<std::string> stamps;
  for (const auto& l : sent(p)) stamps.push_back(stamp_of(l));
  CHECK(stamps == std::vector<std::string>{"235959.999", "000000.000", "000000.001", "000000.002",
                                           "000000.004"});
}

TEST_CASE(
    "payload stamps: a vehicle clock far behind the payload's is followed, not counted up to") {
  // The payload's own UTC is off (00:36:14.581) and the vehicle says 23:13: stamps take the
  // vehicle's time at once and advance with the steady clock from there; they do not stay at
  // the payload's last stamp + 1 ms a sentence for the 1 h 23 min it would take to get there.
  payload_config c = quiet();
  c.sync_utc_from_vehicle = true;
  c.want_acks = false;
  const time_point t0 = time_point{} + 2'174'581ms;
  payload_session<> p(utc_clock(t0, time_of_day{0, 36, 14, 581, 3}), c);
  p.start(t0);
  CHECK(stamp_of(sent(p).at(0)) == "003614.581");
  (void)p.receive(sealed("BFCTL,231300.00,0"), t0 + 10ms);
  for (int i = 0; i < 5; ++i) {
    REQUIRE(p.abort("x", t0 + 20ms + std::chrono::milliseconds(100 * i)).ok());
    char want[16];
    std::snprintf(want, sizeof want, "231300.%03d", 10 + 100 * i);
    CHECK(stamp_of(sent(p).at(0)) == want);
  }
  // Ahead of the payload's clock: followed as well.
  (void)p.receive(sealed("BFCTL,235900.00,0"), t0 + 1000ms);
  REQUIRE(p.abort("y", t0 + 1500ms).ok());
  CHECK(stamp_of(sent(p).at(0)) == "235900.500");
}

TEST_CASE("payload stamps: a vehicle clock a little behind keeps the stamps increasing") {
  // Each vehicle sentence re-anchors the clock to a time taken before it travelled: a few tens
  // of ms behind. The stamps then run 1 ms a sentence ahead until the clock passes them.
  payload_config c = quiet();
  c.sync_utc_from_vehicle = true;
  c.want_acks = false;
  payload_session<> p(utc_clock(at(0ms), time_of_day{12, 0, 0, 0, 0}), c);
  p.start(at(0ms));
  REQUIRE(p.abort("a", at(100ms)).ok());
  (void)p.receive(sealed("BFCTL,120000.060,0"), at(100ms));  // 40 ms behind
  REQUIRE(p.abort("b", at(100ms)).ok());
  REQUIRE(p.abort("c", at(120ms)).ok());
  REQUIRE(p.abort("d", at(150ms)).ok());
  std::vector<std::string> stamps;
  for (const auto& l : sent(p)) stamps.push_back(stamp_of(l));
  CHECK(stamps == std::vector<std::string>{"120000.000", "120000.100", "120000.101", "120000.102",
                                           "120000.110"});
}

TEST_CASE("payload stamps: after the clock steps back, no stamp repeats one awaiting its ack") {
  payload_session<> p(utc_clock(at(0ms), time_of_day{12, 0, 0, 0, 0}), quiet());
  started_with_acks(p, at(0ms));
  const auto a = p.abort("a", at(2000ms));
  const auto b = p.abort("b", at(4000ms));
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  const auto first = sent(p);
  REQUIRE(first.size() == 2);
  CHECK(stamp_of(first[0]) == "120002.000");
  CHECK(stamp_of(first[1]) == "120004.000");
  // 12:00:05 set back to 12:00:02: the next stamp would be a's, still awaiting its ack.
  p.set_utc(at(5000ms), time_of_day{12, 0, 2, 0, 0});
  const auto c = p.abort("c", at(5000ms));
  REQUIRE(c.ok());
  const auto next = sent(p);
  REQUIRE(next.size() == 1);
  CHECK(stamp_of(next[0]) == "120002.001");
  // Each ack finds its own abort.
  (void)p.receive(ack_of(first[0], '2'), at(5100ms));
  (void)p.receive(ack_of(next[0], '2'), at(5100ms));
  const auto ev = events(p);
  REQUIRE(ev.size() == 2);
  CHECK(ev[0].ticket == a.value);
  CHECK(ev[1].ticket == c.value);
  CHECK(p.in_flight() == 1);  // b
}

TEST_CASE("payload: set_utc() from a system_clock time") {
  payload_session<> p(midnight, quiet());
  p.start(at(0ms));
  (void)sent(p);
  p.set_utc(at(1000ms), sys_days{2026y / November / 26} + 8h + 30min);
  REQUIRE(p.abort("x", at(1250ms)).ok());
  CHECK(stamp_of(sent(p).at(0)) == "083000.250");
}

TEST_CASE("payload: BPRMB keep-alive at request_timeout - margin, with a fresh timestamp") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(0ms));
  // Not in control: held, not sent.
  REQUIRE(p.set_request(heading_request(90), at(1000ms)).ok());
  CHECK(sent(p).empty());
  (void)p.receive(sealed("BFCTL,000002.000,1"), at(2000ms));
  CHECK(p.has_control());
  CHECK(events(p).at(0).kind == payload_event_kind::control_gained);
  auto lines = with_address(sent(p), "BPRMB");
  REQUIRE(lines.size() == 1);
  CHECK(lines[0] == sealed("BPRMB,000002.000,90,,,,,0"));

  CHECK(p.next_deadline() == at(6000ms));
  p.tick(at(5999ms));
  CHECK(sent(p).empty());
  p.tick(at(6000ms));
  lines = sent(p);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0] == sealed("BPRMB,000006.000,90,,,,,0"));
  p.tick(at(9999ms));
  CHECK(sent(p).empty());
  p.tick(at(10000ms));
  CHECK(sent(p).size() == 1);

  // A new request goes out at once and restarts the interval.
  REQUIRE(p.set_request(heading_request(180), at(11000ms)).ok());
  lines = sent(p);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0] == sealed("BPRMB,000011.000,180,,,,,0"));
  p.tick(at(14999ms));
  CHECK(sent(p).empty());
  p.tick(at(15000ms));
  CHECK(sent(p).size() == 1);

  // The keep-alive's own acks are matched quietly.
  (void)p.receive(ack_of(lines[0], '2'), at(15100ms));
  CHECK(events(p).empty());

  p.clear_request();
  p.tick(at(30000ms));
  CHECK(sent(p).empty());
}

TEST_CASE("payload: the keep-alive margin is configurable") {
  payload_config c = quiet();
  c.keep_alive_margin = 250ms;
  payload_session<> p(midnight, c);
  p.start(at(0ms));
  (void)sent(p);
  (void)p.receive(sealed("BFCTL,000000.000,1"), at(0ms));
  REQUIRE(p.set_request(heading_request(10), at(0ms)).ok());
  CHECK(sent(p).size() == 1);
  p.tick(at(4749ms));
  CHECK(sent(p).empty());
  p.tick(at(4750ms));
  CHECK(sent(p).size() == 1);
  CHECK(p.keep_alive_interval() == 4750ms);
}

TEST_CASE("payload: losing control stops the keep-alive and drops the request") {
  SECTION("BFCTL 0") {
    payload_session<> p(midnight, quiet());
    started_with_acks(p, at(0ms));
    (void)p.receive(sealed("BFCTL,000000.000,1"), at(0ms));
    REQUIRE(p.set_request(heading_request(90), at(0ms)).ok());
    CHECK(sent(p).size() == 1);
    (void)p.receive(sealed("BFCTL,000003.000,0"), at(3000ms));
    CHECK_FALSE(p.has_control());
    const auto ev = events(p);
    REQUIRE(ev.size() == 2);
    CHECK(ev[1].kind == payload_event_kind::control_lost);
    CHECK(ev[1].detail == "BFCTL 0");
    CHECK_FALSE(p.current_request().has_value());
    p.tick(at(4000ms));
    p.tick(at(60000ms));
    CHECK(sent(p).empty());
    // Control comes back: the old request is not revived.
    (void)p.receive(sealed("BFCTL,000100.000,1"), at(100000ms));
    p.tick(at(110000ms));
    CHECK(sent(p).empty());
  }
  SECTION("the mission leaves Running") {
    payload_session<> p(midnight, quiet());
    (void)p.receive(sealed("BFCTL,000000.000,1"), at(0ms));
    REQUIRE(p.set_request(heading_request(90), at(0ms)).ok());
    (void)sent(p);
    // A status starting with "Running" (with its log dir) keeps control.
    (void)p.receive(sealed("BFMIS,000001.000,d.xml,Running /log/7,"), at(1000ms));
    CHECK(p.has_control());
    (void)p.receive(sealed("BFMIS,000002.000,d.xml,Aborting,leak"), at(2000ms));
    CHECK_FALSE(p.has_control());
    const auto ev = events(p);
    REQUIRE(ev.size() == 2);
    CHECK(ev[1].kind == payload_event_kind::control_lost);
    CHECK(ev[1].detail == "Aborting");
    p.tick(at(4000ms));
    CHECK(sent(p).empty());
  }
}

TEST_CASE("payload: a refused keep-alive is reported; BFSHT is a shutdown event") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(0ms));
  (void)p.receive(sealed("BFCTL,000000.000,1"), at(0ms));
  REQUIRE(p.set_request(heading_request(90), at(0ms)).ok());
  const auto lines = sent(p);
  (void)p.receive(ack_of(lines.at(0), '1', "dynamic requests not allowed"), at(100ms));
  (void)p.receive(sealed("BFSHT,000000.200"), at(200ms));
  const auto ev = events(p);
  REQUIRE(ev.size() == 3);
  CHECK(ev[1].kind == payload_event_kind::ack_failed);
  CHECK(ev[1].origin == message_origin::request);
  CHECK(ev[1].ticket == 0);
  CHECK(ev[1].detail == "dynamic requests not allowed");
  CHECK(ev[2].kind == payload_event_kind::shutdown);
}

TEST_CASE("payload: BPSTS heartbeat at the configured period") {
  payload_config c = quiet();
  c.heartbeat_period = 2000ms;
  c.want_acks = false;
  payload_session<> p(midnight, c);
  REQUIRE(p.set_status(false, "sonar offline"));
  CHECK_FALSE(p.set_status(true, "bad, text"));
  p.start(at(0ms));
  auto lines = sent(p);
  REQUIRE(lines.size() == 2);
  CHECK(address(lines[0]) == "BPVER");
  CHECK(lines[1] == sealed("BPSTS,000000.001,0,sonar offline"));
  p.tick(at(1999ms));
  CHECK(sent(p).empty());
  p.tick(at(2000ms));
  lines = sent(p);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0] == sealed("BPSTS,000002.000,0,sonar offline"));
  REQUIRE(p.set_status(true, "all good"));
  p.tick(at(4100ms));
  lines = sent(p);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0] == sealed("BPSTS,000004.100,1,all good"));
  // Late: the next one is due on the original grid.
  CHECK(p.next_deadline() == at(6000ms));
}

TEST_CASE("payload: full queues are reported, never silent") {
  SECTION("the command queue refuses") {
    payload_session<2> p(midnight, quiet());
    started_with_acks(p, at(0ms));
    REQUIRE(p.subscribe("NVG", at(0ms)).ok());  // in flight
    REQUIRE(p.subscribe("NVR", at(0ms)).ok());
    REQUIRE(p.subscribe("MIS", at(0ms)).ok());
    const auto r = p.subscribe("CTL", at(0ms));
    CHECK(r.ec == errc::buffer_too_small);
  }
  SECTION("bad values are refused when handed in") {
    payload_session<> p(midnight, quiet());
    const auto r = p.send(bpsts{{}, true, "a*b"}, at(0ms));
    CHECK(r.ec == errc::bad_text);
    CHECK(r.field == 3);
    CHECK(p.subscribe("nvg", at(0ms)).ec == errc::bad_text);
    CHECK(p.subscribe("NVGS", at(0ms)).ec == errc::bad_text);
    bprmb bad = heading_request(1);
    bad.speed_mode = static_cast<speed_mode>('5');
    const auto s = p.set_request(bad, at(0ms));
    CHECK(s.ec == errc::bad_enum);
    CHECK(s.field == 6);
  }
  SECTION("the outbox overflows: reported, and sent once there is room") {
    payload_session<16, 2> p(midnight, quiet());
    p.start(at(0ms));  // BPVER + ACK ON fill the outbox
    (void)p.receive(sealed("BFACK,000000.000,LOG,,,2,0,,"), at(10ms));
    REQUIRE(p.subscribe("NVG", at(20ms)).ok());
    const auto ev = events(p);
    REQUIRE(ev.size() == 2);
    CHECK(ev[0].kind == payload_event_kind::ack_ok);
    CHECK(ev[1].kind == payload_event_kind::outbox_overflow);
    CHECK(ev[1].command == "BPLOG");
    CHECK(p.outbox_overflows() == 1);
    CHECK(sent(p).size() == 2);
    p.tick(at(30ms));
    CHECK(sent(p) == std::vector<std::string>{sealed("BPLOG,NVG,ON")});
  }
  SECTION("events beyond the queue are counted in one events_lost event") {
    payload_session<16, 16, 3> p(midnight, quiet());
    for (int i = 0; i < 6; ++i) (void)p.receive(sealed("BFSHT,000000.000"), at(0ms));
    const auto ev = events(p);
    REQUIRE(ev.size() == 3);
    CHECK(ev[0].kind == payload_event_kind::shutdown);
    CHECK(ev[1].kind == payload_event_kind::shutdown);
    CHECK(ev[2].kind == payload_event_kind::events_lost);
    CHECK(ev[2].count == 4);
    CHECK(p.events_lost() == 4);
  }
}

TEST_CASE("payload: time never runs backwards") {
  payload_session<> p(midnight, quiet());
  started_with_acks(p, at(10000ms));
  REQUIRE(p.abort("x", at(5000ms)).ok());  // taken as 10 s (BPVER already has 10.000)
  CHECK(stamp_of(sent(p).at(0)) == "000010.001");
  p.tick(at(14999ms));
  CHECK(sent(p).empty());
  p.tick(at(15000ms));
  CHECK(sent(p).size() == 1);
}

// =============================================================================================
// vehicle side

namespace {
/// A vehicle with one client that asked for acks.
template <class V>
client_id connected_with_acks(V& v, time_point now) {
  const auto c = v.connect(now);
  REQUIRE(c.has_value());
  const auto hello = sent(v);
  REQUIRE(hello.size() == 1);
  CHECK(address(hello[0]) == "BFVER");
  REQUIRE(v.receive(*c, "$BPLOG,ACK,ON*1E\r\n", now).ok());
  const auto ack = sent(v);
  REQUIRE(ack.size() == 1);
  CHECK(ack[0].find(",LOG,,,2,0,,*") != std::string::npos);
  return *c;
}

bfack decoded_ack(const std::string& line) {
  const auto r = decode<bfack>(line, from_vehicle_policy);
  REQUIRE(r.ok());
  return r.value;
}
}  // namespace

TEST_CASE("vehicle: BFVER on connect; no acks until ACK ON; ACK OFF is not acked") {
  vehicle_session<2> v(midnight);
  const auto c = v.connect(at(1500ms));
  REQUIRE(c == client_id{0});
  CHECK(sent(v) == std::vector<std::string>{sealed("BFVER,000001.500,1.0")});
  REQUIRE(v.receive(*c, sealed("BPVER,000001.600,1.0"), at(1600ms)).ok());
  CHECK(v.payload_version(*c) == "1.0");
  CHECK(sent(v).empty());  // acks not asked for
  REQUIRE(v.receive(*c, "$BPLOG,ACK,ON*1e\r\n", at(1700ms)).ok());
  auto lines = sent(v);
  REQUIRE(lines.size() == 1);
  const bfack on = decoded_ack(lines[0]);
  CHECK(on.command == "LOG");
  CHECK_FALSE(on.command_timestamp.has_value());
  CHECK(on.status == ack_status::ok);
  REQUIRE(v.receive(*c, sealed("BPLOG,ACK,OFF"), at(1800ms)).ok());
  CHECK(sent(v).empty());
  // Two clients at most here.
  CHECK(v.connect(at(0ms)).has_value());
  CHECK_FALSE(v.connect(at(0ms)).has_value());
}

TEST_CASE("vehicle: stamps are the UTC it was built with, advanced by steady time") {
  const utc_time utc0 = sys_days{2026y / November / 26} + 23h + 59min + 59s + 950ms;
  for (const milliseconds uptime : uptimes) {
    CAPTURE(uptime.count());
    const time_point t0 = time_point{} + uptime;
    vehicle_session<> v(utc_clock(t0, utc0));
    const auto c = v.connect(t0);
    REQUIRE(c.has_value());
    CHECK(sent(v) == std::vector<std::string>{sealed("BFVER,235959.950,1.0")});
    REQUIRE(v.receive(*c, sealed("BPLOG,ALL,ON"), t0 + 10ms).ok());
    v.set_control(true, t0 + 100ms);
    CHECK(sent(v) == std::vector<std::string>{sealed("BFCTL,000000.050,1")});
    v.set_utc(t0 + 200ms, sys_days{2026y / November / 27} + 8h);
    REQUIRE(v.publish(bfsht{}, t0 + 300ms).ok());
    CHECK(sent(v) == std::vector<std::string>{sealed("BFSHT,080000.100")});
  }
}

TEST_CASE("vehicle: BPLOG subscriptions per client; ALL does not include ACK") {
  vehicle_session<> v(midnight);
  const client_id a = connected_with_acks(v, at(0ms));
  const client_id b = *v.connect(at(0ms));
  (void)sent(v);

  REQUIRE(v.receive(a, "$BPLOG,ALL,ON*16", at(0ms)).ok());
  CHECK(v.should_send(a, "NVG"));
  CHECK(v.should_send(a, "BFNVR"));
  CHECK(v.should_send(a, "MIS"));
  CHECK(v.should_send(a, "ACK"));  // asked for by name before
  CHECK_FALSE(v.should_send(b, "NVG"));
  CHECK(v.should_send(b, "SHT"));  // commands go to everyone
  CHECK(v.should_send(b, "VER"));
  CHECK_FALSE(v.should_send(b, "ACK"));

  REQUIRE(v.receive(b, "$BPLOG,ALL,ON*16", at(0ms)).ok());
  CHECK(v.should_send(b, "NVG"));
  CHECK_FALSE(v.should_send(b, "ACK"));  // ALL never includes ACK

  REQUIRE(v.receive(a, sealed("BPLOG,NVG,OFF"), at(0ms)).ok());
  CHECK_FALSE(v.should_send(a, "NVG"));
  CHECK(v.should_send(a, "NVR"));
  REQUIRE(v.receive(a, sealed("BPLOG,ALL,OFF"), at(0ms)).ok());
  CHECK_FALSE(v.should_send(a, "NVR"));
  CHECK(v.should_send(a, "ACK"));  // ALL OFF leaves ACK as it was
  REQUIRE(v.receive(a, sealed("BPLOG,CTL,ON"), at(0ms)).ok());
  CHECK(v.should_send(a, "CTL"));
  CHECK_FALSE(v.should_send(a, "NVG"));
  CHECK_FALSE(v.should_send(7, "NVG"));  // no such client

  (void)sent(v);
  bfnvg nav;
  nav.timestamp = time_of_day{1, 0, 0, 0, 3};
  nav.lat = latitude::from_degrees(42.5).value;
  nav.lon = longitude::from_degrees(-71.25).value;
  const auto n = v.publish(nav, at(0ms));
  REQUIRE(n.ok());
  CHECK(n.value == 1);  // b only: a turned NVG off
  const auto out = v.poll_send();
  REQUIRE(out.has_value());
  CHECK(out->client == b);
  CHECK(address(std::string(out->view())) == "BFNVG");
}

TEST_CASE("vehicle: ack status codes") {
  vehicle_session<> v(midnight);
  const client_id c = connected_with_acks(v, at(0ms));

  SECTION("ok, echoing the command's timestamp") {
    REQUIRE(v.receive(c, "$BPSTS,231133.12,1,BWSI Autonomy OK*46", at(10ms)).ok());
    const bfack a = decoded_ack(sent(v).at(0));
    CHECK(a.command == "STS");
    CHECK(a.command_timestamp == time_of_day{23, 11, 33, 12, 2});
    CHECK(a.status == ack_status::ok);
    REQUIRE(v.payload_status(c).has_value());
    CHECK(v.payload_status(c)->message == "BWSI Autonomy OK");
  }
  SECTION("failed: BPRMB while dynamic requests are not allowed") {
    REQUIRE(v.receive(c, "$BPRMB,231204.72,-15,,,750,0,1*54", at(10ms)).ok());
    const bfack a = decoded_ack(sent(v).at(0));
    CHECK(a.command == "RMB");
    CHECK(a.command_timestamp == time_of_day{23, 12, 4, 72, 2});
    CHECK(a.status == ack_status::failed);
    CHECK(a.description == text<256>("dynamic requests not allowed"));
    CHECK_FALSE(v.current_request().has_value());
  }
  SECTION("invalid: a field that does not decode, named in the description") {
    const auto r = v.receive(c, sealed("BPRMB,231204.72,-15,5,7,750,0,1"), at(10ms));
    CHECK(r.ec == errc::bad_enum);
    const bfack a = decoded_ack(sent(v).at(0));
    CHECK(a.command == "RMB");
    CHECK(a.command_timestamp == time_of_day{23, 12, 4, 72, 2});
    CHECK(a.status == ack_status::invalid);
    CHECK(a.description == text<256>("bad_enum in field 4 (depth_mode)"));
    const auto ev = events(v);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0].kind == vehicle_event_kind::invalid_command);
    CHECK(ev[0].error == errc::bad_enum);
    CHECK(ev[0].field == 4);
    CHECK(ev[0].command == "BPRMB");
  }
  SECTION("invalid: an unknown message") {
    REQUIRE(v.receive(c, sealed("BPRTK,120000.00,1,2,3"), at(10ms)).ok());
    const bfack a = decoded_ack(sent(v).at(0));
    CHECK(a.command == "RTK");
    CHECK(a.command_timestamp == time_of_day{12, 0, 0, 0, 2});
    CHECK(a.status == ack_status::invalid);
    CHECK(events(v).at(0).error == errc::unknown_address);
  }
  SECTION("invalid: a wrong checksum; a BPLOG code that is not letters") {
    CHECK(v.receive(c, "$BPLOG,NVG,ON*11", at(10ms)).ec == errc::checksum_mismatch);
    bfack a = decoded_ack(sent(v).at(0));
    CHECK(a.command == "LOG");
    CHECK(a.status == ack_status::invalid);
    CHECK(a.description == text<256>("checksum_mismatch"));
    CHECK_FALSE(v.should_send(c, "NVG"));
    // Now refused by the decoder itself (codes are upper-case letters and digits).
    CHECK(v.receive(c, sealed("BPLOG,n-g,ON"), at(10ms)).ec == errc::bad_text);
    a = decoded_ack(sent(v).at(0));
    CHECK(a.status == ack_status::invalid);
    CHECK(a.description == text<256>("bad_text in field 1 (code)"));
  }
  SECTION("a line without even an address is not acked, but reported") {
    CHECK(v.receive(c, "hello", at(10ms)).ec == errc::missing_start);
    CHECK(sent(v).empty());
    const auto ev = events(v);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0].kind == vehicle_event_kind::invalid_command);
    CHECK(ev[0].error == errc::missing_start);
  }
  SECTION("a command without a checksum is fine") {
    REQUIRE(v.receive(c, "$BPVER,120000.00,1.0\r\n", at(10ms)).ok());
    CHECK(decoded_ack(sent(v).at(0)).status == ack_status::ok);
  }
  SECTION("abort") {
    REQUIRE(v.receive(c, "$BPABT,081025.987,leak detected,1*6B", at(10ms)).ok());
    CHECK(decoded_ack(sent(v).at(0)).status == ack_status::ok);
    const auto ev = events(v);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0].kind == vehicle_event_kind::abort_requested);
    CHECK(ev[0].command_timestamp == time_of_day{8, 10, 25, 987, 3});
  }
}

TEST_CASE("vehicle: pending, then the final ack") {
  SECTION("completed automatically") {
    vehicle_config cfg;
    cfg.pending.abt = true;
    cfg.complete_pending_after = 1500ms;
    vehicle_session<> v(midnight, cfg);
    const client_id c = connected_with_acks(v, at(0ms));
    REQUIRE(v.receive(c, "$BPABT,081025.987,leak detected,1*6B", at(100ms)).ok());
    const bfack first = decoded_ack(sent(v).at(0));
    CHECK(first.status == ack_status::pending);
    CHECK(v.next_deadline() == at(1600ms));
    v.tick(at(1599ms));
    CHECK(sent(v).empty());
    v.tick(at(1600ms));
    const bfack final_ack = decoded_ack(sent(v).at(0));
    CHECK(final_ack.status == ack_status::ok);
    CHECK(final_ack.command == "ABT");
    CHECK(final_ack.command_timestamp == first.command_timestamp);
  }
  SECTION("completed by the caller") {
    vehicle_config cfg;
    cfg.pending.ver = true;
    cfg.complete_pending_after = std::nullopt;
    vehicle_session<> v(midnight, cfg);
    const client_id c = connected_with_acks(v, at(0ms));
    REQUIRE(v.receive(c, "$BPVER,081025.987,1.0*6A", at(100ms)).ok());
    CHECK(decoded_ack(sent(v).at(0)).status == ack_status::pending);
    const auto ev = events(v);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0].kind == vehicle_event_kind::command_pending);
    v.tick(at(60000ms));
    CHECK(sent(v).empty());
    CHECK_FALSE(v.complete(ev[0].ticket + 1, ack_status::ok, "", at(60000ms)));
    CHECK(v.complete(ev[0].ticket, ack_status::failed, "unsupported version", at(60000ms)));
    const bfack final_ack = decoded_ack(sent(v).at(0));
    CHECK(final_ack.status == ack_status::failed);
    CHECK(final_ack.description == text<256>("unsupported version"));
  }
}

TEST_CASE("vehicle: BPRMB holds for 5 s; 5.000 s keeps it, one tick more loses it") {
  vehicle_config cfg;
  cfg.control_allowed = true;
  vehicle_session<> v(midnight, cfg);
  const client_id c = *v.connect(at(0ms));
  REQUIRE(v.receive(c, "$BPRMB,000000.00,90,,,,,0", at(1000ms)).ok());
  CHECK(v.request_active(at(1000ms)));
  CHECK(v.current_request()->heading == decimal(90));
  CHECK(events(v).at(0).kind == vehicle_event_kind::request_started);

  // "At least every 5 seconds" (SPI 7.3): a BPRMB exactly 5 s later keeps the request going.
  CHECK(v.request_active(at(6000ms)));
  REQUIRE(v.receive(c, "$BPRMB,000006.00,95,,,,,0", at(6000ms)).ok());
  CHECK(events(v).empty());
  CHECK(v.current_request()->heading == decimal(95));
  CHECK(v.next_deadline() == at(11000ms) + timing::just_after);

  // Then nothing: at exactly 5 s the request still holds, one tick later it has expired.
  v.tick(at(11000ms));
  CHECK(events(v).empty());
  CHECK(v.request_active(at(11000ms)));
  CHECK_FALSE(v.request_active(at(11000ms) + timing::just_after));
  v.tick(at(11000ms) + timing::just_after);
  const auto ev = events(v);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == vehicle_event_kind::request_expired);
  CHECK_FALSE(v.current_request().has_value());

  // After the expiry a BPRMB is a new request; one every 5.000 s continues it.
  REQUIRE(v.receive(c, "$BPRMB,000012.00,95,,,,,0", at(12000ms)).ok());
  REQUIRE(v.receive(c, "$BPRMB,000017.00,95,,,,,0", at(17000ms)).ok());
  REQUIRE(v.receive(c, "$BPRMB,000023.00,95,,,,,0", at(23000ms)).ok());
  const auto again = events(v);
  REQUIRE(again.size() == 3);
  CHECK(again[0].kind == vehicle_event_kind::request_started);
  CHECK(again[1].kind == vehicle_event_kind::request_expired);
  CHECK(again[2].kind == vehicle_event_kind::request_started);
}

TEST_CASE("vehicle: pending acks go with the client; a new client under its id gets none") {
  vehicle_config cfg;
  cfg.control_allowed = true;
  cfg.pending.rmb = true;
  vehicle_session<> v(midnight, cfg);
  const client_id c = connected_with_acks(v, at(0ms));
  REQUIRE(v.receive(c, "$BPRMB,000000.10,90,,,,,0", at(100ms)).ok());
  CHECK(decoded_ack(sent(v).at(0)).status == ack_status::pending);
  REQUIRE(v.receive(c, "$BPSTS,000000.20,1,OK", at(200ms)).ok());
  (void)sent(v);
  v.disconnect(c);
  CHECK(v.next_deadline() != at(1100ms));  // the pending ack is gone

  const client_id again = connected_with_acks(v, at(500ms));
  CHECK(again == c);
  v.tick(at(5000ms));
  for (const std::string& l : sent(v)) CHECK(address(l) != "BFACK");
  // What the old client said is not the new one's.
  CHECK_FALSE(v.payload_status(again).has_value());
  // An id out of range has nothing, not client 0's state.
  REQUIRE(v.receive(again, "$BPSTS,000005.00,1,OK", at(5000ms)).ok());
  CHECK(v.payload_status(again).has_value());
  CHECK_FALSE(v.payload_status(200).has_value());
  CHECK(v.payload_version(200).empty());
  CHECK_FALSE(v.subscriptions(200).acks());
}

TEST_CASE("vehicle: control handed over and back with BFCTL; revoking ends the request") {
  vehicle_session<> v(midnight);
  const client_id c = *v.connect(at(0ms));
  const client_id quiet_client = *v.connect(at(0ms));
  REQUIRE(v.receive(c, sealed("BPLOG,CTL,ON"), at(0ms)).ok());
  (void)sent(v);
  v.set_control(true, at(1000ms));
  CHECK(v.control_allowed());
  auto lines = sent(v);
  REQUIRE(lines.size() == 1);  // only the client that asked for CTL
  CHECK(lines[0] == sealed("BFCTL,000001.000,1"));
  v.set_control(true, at(1100ms));
  CHECK(sent(v).empty());  // no change, nothing sent
  REQUIRE(v.receive(c, "$BPRMB,000001.20,90,,,,,0", at(1200ms)).ok());
  (void)events(v);
  v.set_control(false, at(2000ms));
  CHECK(sent(v) == std::vector<std::string>{sealed("BFCTL,000002.000,0")});
  CHECK(events(v).at(0).kind == vehicle_event_kind::request_cancelled);
  CHECK_FALSE(v.request_active(at(2000ms)));

  v.shutdown(at(3000ms));
  const auto down = sent(v);
  REQUIRE(down.size() == 2);  // commands reach every client
  CHECK(down[0] == sealed("BFSHT,000003.000"));
  (void)quiet_client;
}

// =============================================================================================
// both sides

TEST_CASE("a payload session driving a vehicle session for a minute") {
  vehicle_session<> v(midnight);
  payload_config pc;
  pc.heartbeat_period = 1000ms;
  payload_session<> p(midnight, pc);
  time_point now = at(0ms);
  const client_id c = *v.connect(now);
  p.start(now);
  REQUIRE(p.subscribe("ALL", now).ok());

  std::vector<payload_event> pev;
  std::vector<vehicle_event> vev;
  int rmb_seen = 0;
  int lost_requests = 0;
  const auto exchange = [&] {
    for (int round = 0; round < 3; ++round) {
      while (auto l = p.poll_send()) {
        if (address(std::string(l->view())) == "BPRMB") ++rmb_seen;
        REQUIRE(v.receive(c, l->view(), now).ok());
      }
      while (auto l = v.poll_send()) REQUIRE(p.receive(l->view(), now).ok());
    }
    while (auto e = p.poll_event()) pev.push_back(*e);
    while (auto e = v.poll_event()) {
      if (e->kind == vehicle_event_kind::request_expired) ++lost_requests;
      vev.push_back(*e);
    }
  };
  exchange();
  for (int step = 1; step <= 600; ++step) {
    now = at(std::chrono::milliseconds(step * 100));
    if (step == 50) v.set_control(true, now);
    if (step == 60) REQUIRE(p.set_request(heading_request(45), now).ok());
    if (step == 450) v.set_control(false, now);
    p.tick(now);
    v.tick(now);
    exchange();
  }
  // Every command and heartbeat was acknowledged: no unmatched acks, failures or timeouts.
  for (const auto& e : pev) {
    INFO(static_cast<int>(e.kind));
    CHECK((e.kind == payload_event_kind::ack_ok || e.kind == payload_event_kind::control_gained ||
           e.kind == payload_event_kind::control_lost));
  }
  CHECK(p.vehicle_version() == "1.0");
  CHECK(v.payload_version(c) == "1.0");
  CHECK(v.should_send(c, "NVG"));
  CHECK(v.should_send(c, "ACK"));
  CHECK_FALSE(p.has_control());
  // Control held from 6 s to 45 s: one BPRMB at once, then one every 4 s; never lost meanwhile.
  CHECK(rmb_seen == 1 + (45000 - 6000) / 4000);
  CHECK(lost_requests == 0);
  CHECK(vev.back().kind == vehicle_event_kind::request_cancelled);
}

TEST_CASE("vehicle: publish() stamps a timestamp left unset; BPABT moves the mission to Aborting") {
  vehicle_session<> v(midnight);
  v.set_utc(at(0ms), time_of_day{8, 10, 25, 0, 3});
  const client_id c = connected_with_acks(v, at(0ms));
  REQUIRE(v.receive(c, "$BPLOG,ALL,ON*16", at(0ms)).ok());
  (void)sent(v);

  bfnvg nav;  // timestamp left at its default
  nav.lat = latitude::from_degrees(42.5).value;
  nav.lon = longitude::from_degrees(-71.25).value;
  REQUIRE(v.publish(nav, at(1500ms)).ok());
  auto lines = sent(v);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].starts_with("$BFNVG,081026.500,"));
  nav.timestamp = time_of_day{1, 2, 3, 400, 3};  // one given is kept
  REQUIRE(v.publish(nav, at(1600ms)).ok());
  lines = sent(v);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].starts_with("$BFNVG,010203.400,"));

  CHECK_FALSE(v.mission().has_value());
  bfmis running;
  (void)running.dive_file.assign("dive1.xml");
  (void)running.status.assign("Running /var/log/mission_12");
  REQUIRE(v.publish(running, at(2000ms)).ok());
  (void)sent(v);
  REQUIRE(v.mission().has_value());
  CHECK(v.mission()->state() == mission_state::running);
  CHECK(v.mission()->timestamp == time_of_day{8, 10, 27, 0, 3});

  REQUIRE(v.receive(c, sealed("BPABT,081027.500,leak detected"), at(2500ms)).ok());
  lines = sent(v);
  REQUIRE(lines.size() == 2);
  const bfack ack = decoded_ack(lines[0]);
  CHECK(ack.command == "ABT");
  CHECK(ack.status == ack_status::ok);
  const auto mis = decode<bfmis>(lines[1], from_vehicle_policy);
  REQUIRE(mis.ok());
  CHECK(mis.value.state() == mission_state::aborting);
  CHECK(mis.value.dive_file == "dive1.xml");
  CHECK(mis.value.timestamp == time_of_day{8, 10, 27, 500, 3});
  REQUIRE(v.mission().has_value());
  CHECK(v.mission()->state() == mission_state::aborting);

  // A second abort changes nothing more; nor does one when no mission is under way.
  REQUIRE(v.receive(c, sealed("BPABT,081028.000,again"), at(3000ms)).ok());
  CHECK(sent(v).size() == 1);  // the ack only
  bfmis done = running;
  (void)done.status.assign("Completed");
  REQUIRE(v.publish(done, at(4000ms)).ok());
  (void)sent(v);
  REQUIRE(v.receive(c, sealed("BPABT,081029.000,late"), at(4500ms)).ok());
  CHECK(sent(v).size() == 1);
  CHECK(v.mission()->state() == mission_state::completed);
}
