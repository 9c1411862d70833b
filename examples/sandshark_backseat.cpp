// SPDX-License-Identifier: BSL-1.0
// A Sandshark backseat (payload) session driven from stdin, with simulated time.
//
// Each input line is either a sentence from the vehicle ($BF...) or "@<seconds>", which moves
// the simulated clock. The program prints what the session wants to send ("send: ...") and what
// happened ("event: ..."). Once the vehicle hands over control (BFCTL 1) it asks for heading 90
// at 1.5 m/s and keeps that request alive. With no input it runs the startup and exits.
//
//   printf '@0.5\n$BFACK,000000.500,LOG,,,2,0,,*10\n$BFCTL,000001.000,1*71\n@9\n' |
//     ./seawire_sandshark_backseat

#include <charconv>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <string_view>
#include <variant>

#include "seawire/sandshark/messages.hpp"
#include "seawire/sandshark/session.hpp"

namespace ss = seawire::sandshark;
using namespace std::chrono_literals;

namespace {

template <class Session>
void flush(Session& s) {
  while (auto line = s.poll_send()) std::cout << "send: " << line->view();
  while (auto e = s.poll_event()) {
    std::cout << "event: " << ss::name(e->kind);
    if (!e->command.empty()) std::cout << ' ' << e->command.view();
    if (e->ticket != 0) std::cout << " ticket " << e->ticket;
    if (!e->detail.empty()) std::cout << " (" << e->detail.view() << ')';
    std::cout << '\n';
  }
}

ss::bprmb heading_and_speed() {
  ss::bprmb r;
  r.heading = seawire::nmea::decimal(90);
  r.horizontal_mode = ss::horizontal_mode::heading;
  r.speed = seawire::nmea::decimal::scaled(15, 1);
  r.speed_mode = ss::speed_mode::meters_per_second;
  return r;
}

}  // namespace

int main() {
  ss::payload_config config;
  config.heartbeat_period = 1s;
  ss::payload_session<> session(config);
  ss::time_point now{};

  session.start(now);
  for (std::string_view code : {"NVG", "MIS", "CTL"}) {
    if (!session.subscribe(code, now)) return 1;
  }
  flush(session);

  std::string line;
  while (std::getline(std::cin, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (line[0] == '@') {
      double seconds = 0;
      const auto [end, ec] = std::from_chars(line.data() + 1, line.data() + line.size(), seconds);
      if (ec != std::errc{} || seconds < 0) {
        std::cerr << "bad time: " << line << '\n';
        continue;
      }
      const auto t = ss::time_point{} + std::chrono::duration_cast<ss::time_point::duration>(
                                            std::chrono::duration<double>(seconds));
      // Step through the interval so every timer fires at its own time.
      for (int guard = 0; guard < 100000; ++guard) {
        const auto due = session.next_deadline();
        if (!due || *due > t) break;
        now = *due > now ? *due : now;
        session.tick(now);
        flush(session);
      }
      now = t > now ? t : now;
      session.tick(now);
      flush(session);
      continue;
    }
    const auto r = session.receive(line, now);
    if (!r) {
      std::cout << "bad line: " << seawire::name(r.ec) << " at field " << r.field << '\n';
    } else if (std::holds_alternative<ss::bfctl>(r.value) && session.has_control() &&
               !session.current_request()) {
      if (!session.set_request(heading_and_speed(), now)) return 1;
    }
    flush(session);
  }
  return 0;
}
