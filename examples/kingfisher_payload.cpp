// SPDX-License-Identifier: BSL-1.0
// A Kingfisher payload loop: read what the vehicle sends (one sentence per line on stdin, as
// from `nc <vehicle> 29500`), decode it in the payload role, and answer each navigation update
// with a PYDEV command that steers to a fixed heading. The controller is a toy; the point is the
// API: decode_from_vehicle, the message variant, pydev::from_heading and encode.
//
//   echo '$CPNVG,105707.24,0000.00,N,00000.00,W,1,,,0,,,105707.24*64' | seawire_kingfisher_payload
//   $PYDEV,90.0,0.5*62        (heading 0, 90 degrees off course: slow while turning)

#include <seawire/kingfisher/messages.hpp>

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

void send(const kf::pydev& command) {
  const auto out = nmea::encode(command);
  if (!out) {
    std::fprintf(stderr, "PYDEV refused: field %u: %.*s\n", static_cast<unsigned>(out.field),
                 len(message(out.ec)), message(out.ec).data());
    return;
  }
  std::fwrite(out.view().data(), 1, out.view().size(), stdout);  // already ends in CR LF
  std::fflush(stdout);                                           // a command is worth nothing late
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

}  // namespace

int main() {
  std::string line;
  while (std::getline(std::cin, line)) {
    if (line.empty() || line == "\r") continue;
    const auto r = kf::decode_from_vehicle(line);
    if (!r) {
      report(line, r);
      continue;
    }
    std::visit(
        [](const auto& msg) {
          using T = std::decay_t<decltype(msg)>;
          if constexpr (std::is_same_v<T, kf::cpnvg>) {
            // Blank heading (no compass yet): hold still rather than guess.
            const double speed = msg.heading_deg ? speed_for(msg.heading_deg->to_double()) : 0.0;
            const auto command = kf::pydev::from_heading(target_heading_deg, speed);
            if (command) send(command.value);
          }
          // CPNVR, CPRBS, GPRMC, ... and unknown sentences: not needed by this controller.
        },
        r.value);
  }
  return 0;
}
