// SPDX-License-Identifier: BSL-1.0
// A Kingfisher payload loop: read what the vehicle sends, decode it in the payload role, and
// answer each navigation update with a PYDEV command that steers to a fixed heading. The
// controller is a toy; the point is the API: decode_from_vehicle, the message variant,
// pydev::from_heading and encode.
//
//   seawire_kingfisher_payload --connect 127.0.0.1:29500   talk to a vehicle (or
//                                                           seawire-kingfisher-sim) over TCP
//   echo '$CPNVG,105707.24,0000.00,N,00000.00,W,1,,,0,,,105707.24*64' | seawire_kingfisher_payload
//   $PYDEV,90.0,0.5*62        (heading 0, 90 degrees off course: slow while turning)
//
// Over TCP it runs until the vehicle closes the connection.

#include <seawire/kingfisher/messages.hpp>

#if SEAWIRE_EXAMPLE_HAS_ASIO
#include <asio.hpp>
#endif
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

namespace {

using namespace seawire;
namespace kf = seawire::kingfisher;

constexpr double target_heading_deg = 90.0;  // due east
constexpr double cruise_mps = 1.5;

int len(std::string_view s) { return static_cast<int>(s.size()); }

// Slow down while turning: full speed on course, a crawl when more than 45 degrees off.
double speed_for(double heading_deg) {
  const double error = std::remainder(target_heading_deg - heading_deg, 360.0);
  return std::fabs(error) > 45.0 ? 0.5 : cruise_mps;
}

void send(std::ostream& to_vehicle, const kf::pydev& command) {
  const auto out = nmea::encode(command);
  if (!out) {
    std::fprintf(stderr, "PYDEV refused: field %u: %.*s\n", static_cast<unsigned>(out.field),
                 len(message(out.ec)), message(out.ec).data());
    return;
  }
  to_vehicle.write(out.view().data(), len(out.view()));  // already ends in CR LF
  to_vehicle.flush();                                    // a command is worth nothing late
}

// Which field of which sentence, and why: "CPNVG field 2 (latitude): minutes out of range".
void report(std::string_view line, const result<kf::from_vehicle::variant>& r) {
  nmea::parse_policy lax;
  lax.checksum = nmea::checksum_policy::ignore;  // only to learn the address
  const auto s = nmea::parse(line, lax);
  const std::string_view address = s ? s.value.address : std::string_view("line");
  const std::string_view why = message(r.ec);
  if (r.field == 0) {
    std::fprintf(stderr, "%.*s: %.*s\n", len(address), address.data(), len(why), why.data());
    return;
  }
  const std::string_view name = kf::from_vehicle::field_name(address, r.field);
  std::fprintf(stderr, "%.*s field %u (%.*s): %.*s\n", len(address), address.data(),
               static_cast<unsigned>(r.field), len(name), name.data(), len(why), why.data());
}

// One line at a time from the vehicle, commands back on the same link.
int run(std::istream& from_vehicle, std::ostream& to_vehicle) {
  std::string line;
  while (std::getline(from_vehicle, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // TCP lines end in CR LF
    if (line.empty()) continue;
    const auto r = kf::decode_from_vehicle(line);
    if (!r) {
      report(line, r);
      continue;
    }
    std::visit(
        [&](const auto& msg) {
          using T = std::decay_t<decltype(msg)>;
          if constexpr (std::is_same_v<T, kf::cpnvg>) {
            // Blank heading (no compass yet): hold still rather than guess.
            const double speed = msg.heading_deg ? speed_for(msg.heading_deg->to_double()) : 0.0;
            const auto command = kf::pydev::from_heading(target_heading_deg, speed);
            if (command) send(to_vehicle, command.value);
          }
          // CPNVR, CPRBS, GPRMC, ... and unknown sentences: not needed by this controller.
        },
        r.value);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string_view(argv[1]) == "--connect") {
    const std::string_view where = argv[2];
    const auto colon = where.rfind(':');
    if (colon == std::string_view::npos) {
      std::fprintf(stderr, "--connect HOST:PORT\n");
      return 2;
    }
#if SEAWIRE_EXAMPLE_HAS_ASIO
    std::string_view host = where.substr(0, colon);  // "[::1]" -> "::1"
    if (host.size() > 2 && host.front() == '[' && host.back() == ']')
      host = host.substr(1, host.size() - 2);
    asio::ip::tcp::iostream vehicle(std::string(host), std::string(where.substr(colon + 1)));
    if (!vehicle) {
      std::fprintf(stderr, "cannot connect to %s: %s\n", argv[2],
                   vehicle.error().message().c_str());
      return 1;
    }
    return run(vehicle, vehicle);
#else
    std::fprintf(stderr, "built without asio (libasio-dev): only stdin and stdout\n");
    return 2;
#endif
  }
  return run(std::cin, std::cout);
}
