// SPDX-License-Identifier: BSL-1.0
// A RobotX vehicle's report loop on a simulated clock: three seconds of RXHRB at 1 Hz from a
// fixed UTC start, one Scan the Code report sent twice within a second (the second is held
// until its second is up), and every sentence checked the way the judges would.
//
//   seawire_robotx_heartbeat          start at 2018-12-11 02:12:29 UTC (the spec's HST stamp)
//   seawire_robotx_heartbeat --now    start at the system clock's now
//
// A real vehicle would call poll(system_clock::now()) from its event loop, sleep until
// next_due(), and write each sentence to the Technical Director's TCP socket.

#include <chrono>
#include <cstdio>
#include <string_view>

#include "seawire/robotx/heartbeat.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/robotx/validator.hpp"

int main(int argc, char** argv) {
  using namespace std::chrono;
  namespace rx = seawire::robotx;

  const bool now = argc > 1 && std::string_view(argv[1]) == "--now";
  const rx::instant start =
      now ? rx::instant(system_clock::now()) : sys_days{2018y / 12 / 11} + 2h + 12min + 29s;

  rx::scheduler scheduler;  // 1 Hz heartbeat; too-soon reports held
  rx::validator judge({.expected_team = rx::team("AUVSI")});

  rx::rxhrb status;
  status.team_id = "AUVSI";
  status.lat = seawire::nmea::decimal_latitude::from_degrees(21.31198).value;
  status.lon = seawire::nmea::decimal_longitude::from_degrees(-157.88972).value;
  status.system_mode = rx::system_mode::autonomous;
  status.auv_status = rx::auv_status::stowed;
  if (!scheduler.status(status)) return 1;

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
