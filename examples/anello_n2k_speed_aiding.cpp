// SPDX-License-Identifier: BSL-1.0
// Speed aiding for the ANELLO Maritime INS over NMEA 2000: a USV computer sends 128259 Speed,
// Water Referenced at 1 Hz and 130578 Vessel Speed Components at 4 Hz (a fast packet of two
// frames) from the speeds its own software holds. Writes the frames as candump -L lines on stdout
// for can-utils, then reads the lines back through the library as a receiver would and prints
// what it decoded on stderr.
//
//   seawire_anello_n2k_speed_aiding [seconds] [source address]   (default 3 s, address 35)
//   seawire_anello_n2k_speed_aiding 10 | canplayer -I - vcan0=can0   # onto a (virtual) bus

#include <seawire/nmea2000/can_id.hpp>
#include <seawire/nmea2000/fast_packet.hpp>
#include <seawire/nmea2000/log.hpp>
#include <seawire/nmea2000/pgns.hpp>
#include <seawire/nmea2000/reader.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using namespace seawire;
namespace n2k = seawire::nmea2000;

// What the boat's software knows at time t: a slow turn at about 2.5 m/s through the water, with
// a current setting it to starboard.
struct boat_state {
  double water_ahead_mps;
  double water_starboard_mps;
  double ground_ahead_mps;
  double ground_starboard_mps;
};
boat_state simulate(double t) {
  const double surge = 2.5 + 0.3 * std::sin(t / 5);
  return {surge, 0.05 * std::cos(t / 3), surge + 0.1, 0.2 + 0.05 * std::cos(t / 3)};
}

// Collects the log lines (stdout gets them too).
struct lines_sink {
  std::string text;
  void put(char c) { text += c; }
  void put(std::string_view s) { text += s; }
};

bool fail(const char* what, errc e) {
  std::fprintf(stderr, "%s: %.*s\n", what, static_cast<int>(message(e).size()), message(e).data());
  return false;
}

// One message onto the log: its frame, or its fast packet's frames.
template <class P>
bool send(const P& msg, std::uint8_t source, std::int64_t time_us,
          n2k::fast_packet_sequencer<>& sequence, lines_sink& out) {
  const auto payload = n2k::encode(msg);
  if (!payload) return fail("encode", payload.ec);
  n2k::log_record rec;
  rec.id = {n2k::pgn_table<P>.info.priority, n2k::pgn_table<P>.info.pgn, source,
            n2k::broadcast_address};
  rec.time_us = time_us;
  (void)rec.interface.assign("can0");
  std::vector<n2k::frame_data> frames;
  if (n2k::pgn_table<P>.info.transport == n2k::framing::fast_packet) {
    const auto split = n2k::split_fast_packet(payload.value, sequence.next(rec.id.pgn, source));
    if (!split) return fail("split", split.ec);
    frames.assign(split.value.view().begin(), split.value.view().end());
  } else {
    n2k::frame_data f;
    for (std::size_t i = 0; i < payload.value.size(); ++i) f.bytes[i] = payload.value[i];
    f.size = static_cast<std::uint8_t>(payload.value.size());
    frames.push_back(f);
  }
  for (const auto& f : frames) {
    (void)rec.assign(f.view());
    if (const errc e = n2k::write_log_line(out, rec, n2k::log_format::candump_log); e != errc::ok)
      return fail("write", e);
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const int seconds = argc > 1 ? std::atoi(argv[1]) : 3;
  const int address = argc > 2 ? std::atoi(argv[2]) : 35;
  if (seconds < 1 || seconds > 3600 || address < 0 || address > 251) {
    std::fprintf(stderr, "usage: %s [seconds 1-3600] [source address 0-251]\n", argv[0]);
    return 2;
  }
  const auto source = static_cast<std::uint8_t>(address);
  const std::int64_t start_us = 1'720'021'378'000'000;  // 2024-07-03 15:42:58 UTC
  n2k::fast_packet_sequencer<> sequence;
  lines_sink out;
  std::uint8_t sid = 0;
  for (int tick = 0; tick < seconds * 4; ++tick) {  // 250 ms steps
    const double t = tick * 0.25;
    const std::int64_t now = start_us + tick * 250'000;
    const boat_state s = simulate(t);
    n2k::vessel_speed_components c;
    // assign() rounds to the field's 0.001 m/s and refuses what 16 bits cannot carry
    if (c.longitudinal_water_mps.assign(s.water_ahead_mps) != errc::ok ||
        c.transverse_water_mps.assign(s.water_starboard_mps) != errc::ok ||
        c.longitudinal_ground_mps.assign(s.ground_ahead_mps) != errc::ok ||
        c.transverse_ground_mps.assign(s.ground_starboard_mps) != errc::ok)
      return fail("130578 value", errc::out_of_range) ? 0 : 1;
    if (!send(c, source, now, sequence, out)) return 1;
    if (tick % 4 == 0) {  // 1 Hz
      n2k::speed_water_referenced w;
      (void)w.sid.assign(sid);
      sid = static_cast<std::uint8_t>((sid + 1) % 253);
      if (w.speed_water_mps.assign(s.water_ahead_mps) != errc::ok)
        return fail("128259 value", errc::out_of_range) ? 0 : 1;
      w.speed_type = n2k::water_reference::doppler;
      if (!send(w, source, now, sequence, out)) return 1;
    }
  }
  std::fwrite(out.text.data(), 1, out.text.size(), stdout);
  std::fflush(stdout);

  // Read back as a receiver: line by line, fast packets assembled.
  n2k::log_reader<> reader;
  std::size_t messages = 0;
  std::string_view rest = out.text;
  while (!rest.empty()) {
    const std::size_t nl = rest.find('\n');
    const auto r = reader.read_line(rest.substr(0, nl), [&](const n2k::message_header& h,
                                                            std::span<const std::uint8_t> p) {
      ++messages;
      n2k::ins_input_pgns::visit(h.id.pgn, p, [&](const auto& m) {
        using P = std::remove_cvref_t<decltype(m)>;
        if constexpr (std::is_same_v<P, n2k::speed_water_referenced>) {
          std::fprintf(stderr, "128259 sid %lld: %.2f m/s through the water (%.*s)\n",
                       static_cast<long long>(m.sid.raw()), *m.speed_water_mps.value(),
                       static_cast<int>(m.speed_type.name().size()), m.speed_type.name().data());
        } else if constexpr (std::is_same_v<P, n2k::vessel_speed_components>) {
          std::fprintf(stderr, "130578: water %.3f ahead %+.3f starboard, ground %.3f %+.3f m/s\n",
                       *m.longitudinal_water_mps.value(), *m.transverse_water_mps.value(),
                       *m.longitudinal_ground_mps.value(), *m.transverse_ground_mps.value());
        }
      });
    });
    if (!r) return fail("read back", r.ec) ? 0 : 1;
    if (nl == std::string_view::npos) break;
    rest.remove_prefix(nl + 1);
  }
  const auto& a = reader.assembler();
  std::fprintf(stderr, "%zu messages read back; %llu frames dropped\n", messages,
               static_cast<unsigned long long>(a.frames_dropped()));
  return a.frames_dropped() == 0 ? 0 : 1;
}
