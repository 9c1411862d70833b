// SPDX-License-Identifier: BSL-1.0
// A RobotX vehicle's report loop on a simulated clock: three seconds of RXHRB at 1 Hz from a
// fixed UTC start, one Scan the Code report sent twice within a second (the second is held
// until its second is up), and every sentence checked the way the judges would.
//
//   seawire_robotx_heartbeat          start at 2018-12-11 02:12:29 UTC (the spec's HST stamp)
//   seawire_robotx_heartbeat --now    start at the system clock's now
//   seawire_robotx_heartbeat --connect HOST:PORT [COUNT]
//                                     the real thing: heartbeats at 1 Hz on the system clock to
//                                     the Technical Director's server (or seawire-robotx-judge),
//                                     reconnecting when it goes away; stops after COUNT sent
//
// A real vehicle calls poll(system_clock::now()) from its event loop, sleeps until next_due(),
// and writes each sentence to the Technical Director's TCP socket, as --connect does.

#if SEAWIRE_EXAMPLE_HAS_ASIO
#include <asio.hpp>
#endif
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <thread>

#include "seawire/robotx/heartbeat.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/robotx/validator.hpp"

namespace {

namespace rx = seawire::robotx;

rx::rxhrb our_status() {
  rx::rxhrb status;
  status.team_id = "AUVSI";
  status.lat = seawire::nmea::decimal_latitude::from_degrees(21.31198).value;
  status.lon = seawire::nmea::decimal_longitude::from_degrees(-157.88972).value;
  status.system_mode = rx::system_mode::autonomous;
  status.auv_status = rx::auv_status::stowed;
  return status;
}

// Heartbeats on the system clock to HOST:PORT until `count` are sent, reconnecting (after 0.5 s,
// doubling up to 4 s) whenever the connection fails or breaks.
int live(const std::string& host, const std::string& port, long count) {
#if SEAWIRE_EXAMPLE_HAS_ASIO
  using namespace std::chrono;
  std::signal(SIGPIPE, SIG_IGN);  // a vanished server is a failed write, not a dead process
  rx::scheduler scheduler;
  if (!scheduler.status(our_status())) return 1;
  long sent = 0;
  auto backoff = 500ms;
  while (sent < count) {
    asio::ip::tcp::iostream judge(host, port);
    if (!judge) {
      std::fprintf(stderr, "cannot connect to %s:%s (%s); again in %lld ms\n", host.c_str(),
                   port.c_str(), judge.error().message().c_str(),
                   static_cast<long long>(backoff.count()));
      std::this_thread::sleep_for(backoff);
      backoff = std::min(backoff * 2, milliseconds(4000));
      continue;
    }
    std::fprintf(stderr, "connected to %s:%s\n", host.c_str(), port.c_str());
    const auto connected_at = steady_clock::now();
    while (sent < count && judge) {
      while (const auto out = scheduler.poll(rx::instant(system_clock::now()))) {
        if (!out->sentence) return 1;
        judge << out->sentence.view() << std::flush;
        if (!judge) break;  // the server went away: this one is lost, the next goes anew
        ++sent;
        std::fwrite(out->sentence.view().data(), 1, out->sentence.view().size(), stdout);
        std::fflush(stdout);
      }
      std::this_thread::sleep_until(system_clock::time_point(
          duration_cast<system_clock::duration>(scheduler.next_due().time_since_epoch())));
    }
    if (sent < count) std::fprintf(stderr, "connection lost; reconnecting\n");
    // The wait starts again from the shortest only after a connection that lasted: a server
    // that accepts and closes at once is not hammered.
    if (steady_clock::now() - connected_at >= 2s) backoff = 500ms;
  }
  return 0;
#else
  (void)host, (void)port, (void)count;
  std::fprintf(stderr, "built without asio (libasio-dev): --connect is not available\n");
  return 2;
#endif
}

}  // namespace

int main(int argc, char** argv) {
  using namespace std::chrono;

  if (argc >= 3 && std::string_view(argv[1]) == "--connect") {
    const std::string where = argv[2];
    const auto colon = where.rfind(':');
    if (colon == std::string::npos) {
      std::fprintf(stderr, "--connect HOST:PORT [COUNT]\n");
      return 2;
    }
    const long count = argc > 3 ? std::strtol(argv[3], nullptr, 10) : 1L << 62;
    std::string host = where.substr(0, colon);
    if (host.size() > 2 && host.front() == '[' && host.back() == ']')
      host = host.substr(1, host.size() - 2);
    return live(host, where.substr(colon + 1), count);
  }

  const bool now = argc > 1 && std::string_view(argv[1]) == "--now";
  const rx::instant start =
      now ? rx::instant(system_clock::now()) : sys_days{2018y / 12 / 11} + 2h + 12min + 29s;

  rx::scheduler scheduler;  // 1 Hz heartbeat; too-soon reports held
  rx::validator judge({.expected_team = rx::team("AUVSI")});

  if (!scheduler.status(our_status())) return 1;

  rx::rxcod code;
  code.team_id = "AUVSI";
  code.light_pattern = rx::light_pattern::from("RGB").value;

  int findings = 0;
  for (auto t = 0ms; t < 3s; t += 10ms) {  // the vehicle's 100 Hz loop
    const rx::instant tick = start + t;
    if (t == 200ms || t == 500ms) {
      const auto r = scheduler.submit(code, tick);
      std::printf("%5lld ms  submit RXCOD: %s\n", static_cast<long long>(t.count()),
                  r.status == rx::submit_status::ready ? "ready" : "held for its second");
    }
    while (const auto out = scheduler.poll(tick)) {
      if (!out->sentence) return 1;
      std::printf("%5lld ms  %.*s", static_cast<long long>(t.count()),
                  static_cast<int>(out->sentence.view().size()), out->sentence.view().data());
      const auto verdict = judge.check(out->sentence.view(), tick);
      for (const auto& f : verdict.findings) {
        std::printf("          judge: %.*s field %u\n", static_cast<int>(name(f.broken).size()),
                    name(f.broken).data(), static_cast<unsigned>(f.field));
        ++findings;
      }
    }
  }
  std::printf("judges' findings: %d\n", findings);
  return findings == 0 ? 0 : 1;
}
