// SPDX-License-Identifier: BSL-1.0
// The Sandshark sessions take two clocks that cannot be confused: steady time for their timers,
// UTC (a system_clock time) for the timestamps they write. A steady_clock time where UTC is
// expected, a UTC time where steady time is, or a session without its UTC clock, does not
// compile. Each ctest case compiles this file with one CASE defined and expects the compiler's
// message; CASE ok must compile.
#include <chrono>

#include "seawire/sandshark/session.hpp"

namespace ss = seawire::sandshark;
using std::chrono::steady_clock;
using std::chrono::system_clock;

int main() {
#if defined(CASE_ok)
  using namespace std::chrono_literals;
  const ss::utc_clock live(steady_clock::now(), system_clock::now());
  const ss::utc_clock simulated(ss::time_point{}, std::chrono::sys_days{2026y / 11 / 26} + 23h);
  const ss::utc_clock from_the_wire(ss::time_point{}, seawire::nmea::time_of_day{23, 13, 0, 0, 0});
  ss::payload_session<> p(live);
  p.start(steady_clock::now());
  p.set_utc(steady_clock::now(), system_clock::now());
  p.set_utc(steady_clock::now(), std::chrono::sys_seconds{});
  ss::vehicle_session<> v(simulated);
  v.set_utc(steady_clock::now(), system_clock::now());
  ss::vehicle_session<> w(from_the_wire);
  (void)w.connect(steady_clock::now());
#elif defined(CASE_steady_as_utc)
  const ss::utc_clock clock(steady_clock::now(), steady_clock::now());
#elif defined(CASE_steady_ms_as_utc)
  const ss::utc_clock clock(
      steady_clock::now(),
      std::chrono::time_point_cast<std::chrono::milliseconds>(steady_clock::now()));
#elif defined(CASE_payload_set_utc_steady)
  ss::payload_session<> p(ss::utc_clock(steady_clock::now(), system_clock::now()));
  p.set_utc(steady_clock::now(), steady_clock::now());
#elif defined(CASE_vehicle_set_utc_steady)
  ss::vehicle_session<> v(ss::utc_clock(steady_clock::now(), system_clock::now()));
  v.set_utc(steady_clock::now(), steady_clock::now());
#elif defined(CASE_utc_as_steady)
  const ss::utc_clock clock(system_clock::now(), system_clock::now());
#elif defined(CASE_utc_as_now)
  ss::payload_session<> p(ss::utc_clock(steady_clock::now(), system_clock::now()));
  p.start(system_clock::now());
#elif defined(CASE_payload_without_utc)
  ss::payload_session<> p;
  p.start(steady_clock::now());
#elif defined(CASE_vehicle_without_utc)
  ss::vehicle_session<> v;
  (void)v.connect(steady_clock::now());
#endif
  return 0;
}
