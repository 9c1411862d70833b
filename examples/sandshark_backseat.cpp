// SPDX-License-Identifier: BSL-1.0
// A Sandshark backseat (payload) session driven from stdin, with simulated time.
//
// Each input line is either a sentence from the vehicle ($BF...) or "@<seconds>", which moves
// the simulated clock (0 s is midnight UTC: the vehicle's sentences below say so). The program
// prints what the session wants to send ("send: ...") and what happened ("event: ..."). Once the
// vehicle hands over control (BFCTL 1) it asks for heading 90 at 1.5 m/s and keeps that request
// alive. With no input it runs the startup and exits.
//
//   printf '@0.5\n$BFACK,000000.500,LOG,,,2,0,,*10\n$BFCTL,000001.000,1*71\n@9\n' |
//     ./seawire_sandshark_backseat
//
//   ./seawire_sandshark_backseat --connect 127.0.0.1:29500 [SECONDS]
//     the same session on the real clocks (steady for the timers, the system clock for the UTC
//     timestamps) against a vehicle (or seawire-sandshark-sim) over TCP, for SECONDS (default:
//     until the vehicle closes the connection)

#if SEAWIRE_EXAMPLE_HAS_ASIO
#include <asio.hpp>
#endif
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <string_view>
#include <variant>

#include "seawire/nmea/stream.hpp"
#include "seawire/sandshark/messages.hpp"
#include "seawire/sandshark/session.hpp"

namespace ss = seawire::sandshark;
using namespace std::chrono_literals;

namespace {

template <class Session, class Write>
void flush(Session& s, Write write) {
  while (auto line = s.poll_send()) {
    std::cout << "send: " << line->view();
    write(line->view());
  }
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

const auto no_write = [](std::string_view) {};

#if SEAWIRE_EXAMPLE_HAS_ASIO
// The session on the steady clock over TCP: lines from the socket through the stream reader,
// timers at the session's next deadline, what it sends written at once. Its timestamps start
// from the system clock's UTC, read once with the steady time, and follow the vehicle's.
int live(const std::string& host, const std::string& port, double seconds) {
  asio::io_context io;
  asio::ip::tcp::socket vehicle(io);
  asio::error_code ec;
  asio::connect(vehicle, asio::ip::tcp::resolver(io).resolve(host, port, ec), ec);
  if (ec) {
    std::cerr << "cannot connect to " << host << ':' << port << ": " << ec.message() << '\n';
    return 1;
  }
  const auto write = [&](std::string_view bytes) {
    asio::error_code e;
    asio::write(vehicle, asio::buffer(bytes.data(), bytes.size()), e);
  };
  const auto now = [] { return ss::time_point(std::chrono::steady_clock::now()); };
  ss::payload_config config;
  ss::payload_session<> session(ss::utc_clock(now(), std::chrono::system_clock::now()), config);
  session.start(now());
  for (std::string_view code : {"NVG", "MIS", "CTL"}) {
    if (!session.subscribe(code, now())) return 1;
  }
  flush(session, write);

  asio::steady_timer timer(io);
  std::function<void()> arm = [&] {
    const auto due = session.next_deadline();
    timer.expires_at(due ? *due : now() + 1s);
    timer.async_wait([&](const asio::error_code& e) {
      if (e) return;
      session.tick(now());
      flush(session, write);
      arm();
    });
  };
  seawire::nmea::stream_reader<> reader;
  std::array<char, 4096> buf{};
  std::function<void()> read = [&] {
    vehicle.async_read_some(asio::buffer(buf), [&](const asio::error_code& e, std::size_t n) {
      if (e) {
        std::cout << "vehicle closed the connection\n";
        io.stop();
        return;
      }
      reader.feed(std::string_view(buf.data(), n), [&](const auto& item) {
        if (!item.is_sentence()) return;
        const auto r = session.receive(item.sentence.text, now());
        if (r && std::holds_alternative<ss::bfctl>(r.value) && session.has_control() &&
            !session.current_request()) {
          if (!session.set_request(heading_and_speed(), now())) io.stop();
        }
      });
      flush(session, write);
      arm();  // a reply may have moved the next deadline
      read();
    });
  };
  asio::steady_timer end(io);
  if (seconds > 0) {
    end.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(seconds)));
    end.async_wait([&](const asio::error_code& e) {
      if (!e) io.stop();
    });
  }
  arm();
  read();
  io.run();
  return 0;
}
#endif

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 3 && std::string_view(argv[1]) == "--connect") {
    const std::string where = argv[2];
    const auto colon = where.rfind(':');
    if (colon == std::string::npos) {
      std::cerr << "--connect HOST:PORT [SECONDS]\n";
      return 2;
    }
#if SEAWIRE_EXAMPLE_HAS_ASIO
    std::string host = where.substr(0, colon);  // "[::1]" -> "::1"
    if (host.size() > 2 && host.front() == '[' && host.back() == ']')
      host = host.substr(1, host.size() - 2);
    return live(host, where.substr(colon + 1), argc > 3 ? std::strtod(argv[3], nullptr) : 0.0);
#else
    std::cerr << "built without asio (libasio-dev): --connect is not available\n";
    return 2;
#endif
  }
  ss::payload_config config;
  config.heartbeat_period = 1s;
  ss::time_point now{};
  ss::payload_session<> session(ss::utc_clock(now, seawire::nmea::time_of_day{}), config);

  session.start(now);
  for (std::string_view code : {"NVG", "MIS", "CTL"}) {
    if (!session.subscribe(code, now)) return 1;
  }
  flush(session, no_write);

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
        flush(session, no_write);
      }
      now = t > now ? t : now;
      session.tick(now);
      flush(session, no_write);
      continue;
    }
    const auto r = session.receive(line, now);
    if (!r) {
      std::cout << "bad line: " << seawire::name(r.ec) << " at field " << r.field << '\n';
    } else if (std::holds_alternative<ss::bfctl>(r.value) && session.has_control() &&
               !session.current_request()) {
      if (!session.set_request(heading_and_speed(), now)) return 1;
    }
    flush(session, no_write);
  }
  return 0;
}
