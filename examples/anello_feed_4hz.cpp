// SPDX-License-Identifier: BSL-1.0
// What a USV computer sends the ANELLO Maritime INS on its input link: the 0xAB00 binary sensor
// frame at 4 Hz (the spec's default rate) built from simulated vehicle values, with a $VWVBW
// speed sentence once a second on the same link. Writes the stream, then reads it back through
// anello::stream_reader in uneven chunks (as serial reads return them) and checks that every
// frame and sentence comes out, in order, bit for bit.
//
//   seawire_anello_feed_4hz                  5 s of simulated time, one line per item on stdout
//   seawire_anello_feed_4hz --seconds 20     more simulated time
//   seawire_anello_feed_4hz --raw            the raw bytes on stdout (for a serial port or file);
//                                            the report goes to stderr
//   seawire_anello_feed_4hz --real-time      wait 250 ms between frames, as a real sender does
//   seawire_anello_feed_4hz --read           read a raw stream from stdin and list its items:
//                                            seawire_anello_feed_4hz --raw | ... --read
//
// Exits 0 when the round trip (or the --read) went through.

#include <seawire/anello/frame.hpp>
#include <seawire/anello/inputs.hpp>
#include <seawire/anello/stream.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace {

using namespace seawire;

constexpr double pi = 3.14159265358979323846;
constexpr double metres_per_degree = 111'320.0;  // of latitude; good enough for a simulation
constexpr int frames_per_second = 4;

struct options {
  double seconds = 5.0;
  bool raw = false;
  bool real_time = false;
  bool read = false;
};

// What was put on the wire, to check the read-back against.
struct sent {
  std::vector<std::uint8_t> wire;
  std::vector<anello::frame_bytes> frames;
  std::vector<std::string> sentences;
};

// A boat circling off San Diego: 2 m/s through the water, turning 3 degrees a second, motor
// and rudder steady, a light westerly. GPS time starts at the spec example's.
anello::sensor_values simulate(double t, double& lat, double& lon) {
  const double heading = std::fmod(45.0 + 3.0 * t, 360.0);
  const double speed = 2.0 + 0.1 * std::sin(t / 3.0);
  const double dt = 1.0 / frames_per_second;
  if (t > 0) {
    lat += speed * std::cos(heading * pi / 180.0) * dt / metres_per_degree;
    lon += speed * std::sin(heading * pi / 180.0) * dt /
           (metres_per_degree * std::cos(lat * pi / 180.0));
  }
  anello::sensor_values v;
  v.heading_deg = heading;
  v.latitude_deg = lat;
  v.longitude_deg = lon;
  v.sog_mps = speed + 0.2;  // a little current from astern
  v.cog_deg = heading;
  v.gps_time = anello::time_ms{std::chrono::milliseconds{1'720'021'378'000}} +
               std::chrono::milliseconds{static_cast<std::int64_t>(std::lround(t * 1000.0))};
  v.alt_msl_m = 1.5;
  v.geoid_sep_m = -35.2;
  v.hdop = 0.9;
  v.fix_quality = 1;
  v.motor_pct = 40;
  v.rudder_pct = 15;
  v.stw_mps = speed;
  v.wind_speed_abs_mps = 4.3;
  v.wind_dir_abs_deg = 270;
  v.wind_speed_rel_mps = std::nullopt;  // no apparent-wind sensor on this boat
  v.wind_dir_rel_deg = std::nullopt;
  v.air_temp_c = 21.5;
  v.pressure_hpa = 1013;
  return v;
}

std::string hex(std::span<const std::uint8_t> bytes) {
  std::string out;
  for (const std::uint8_t b : bytes) {
    out += "0123456789ABCDEF"[b >> 4U];
    out += "0123456789ABCDEF"[b & 15U];
  }
  return out;
}

void write(const options& opt, std::span<const std::uint8_t> bytes) {
  if (opt.raw) {
    std::fwrite(bytes.data(), 1, bytes.size(), stdout);
    std::fflush(stdout);
  }
}

// Writes the stream and keeps a copy; false if a value could not be sent.
bool produce(const options& opt, sent& out) {
  std::FILE* report = opt.raw ? stderr : stdout;
  double lat = 32.7076;
  double lon = -117.2281;
  const int ticks = static_cast<int>(opt.seconds * frames_per_second);
  for (int tick = 0; tick < ticks; ++tick) {
    const double t = static_cast<double>(tick) / frames_per_second;
    const anello::sensor_values values = simulate(t, lat, lon);

    if (tick % frames_per_second == 0) {
      // Speed aiding once a second: along the hull, a little leeway to port.
      anello::vbw_si vbw_in;
      vbw_in.longitudinal_water_mps = *values.stw_mps;
      vbw_in.transverse_water_mps = -0.05;
      const auto vbw = anello::make_vbw(vbw_in);
      if (!vbw) {
        std::fprintf(stderr, "VBW refused: %s\n", std::string(message(vbw.ec)).c_str());
        return false;
      }
      const auto line = nmea::encode(vbw.value);
      if (!line) return false;
      const std::string_view text = line.view();
      const auto* p = reinterpret_cast<const std::uint8_t*>(text.data());
      std::fprintf(report, "%7.2f s  @%-6zu sentence %.*s\n", t, out.wire.size(),
                   static_cast<int>(text.size() - 2), text.data());
      out.wire.insert(out.wire.end(), p, p + text.size());
      out.sentences.emplace_back(text.substr(0, text.size() - 2));  // without CR LF
      write(opt, std::span(p, text.size()));
    }

    const auto built = anello::build_frame(values);
    if (!built) {
      std::fprintf(stderr, "frame refused: field %u: %s\n", static_cast<unsigned>(built.field),
                   std::string(message(built.ec)).c_str());
      return false;
    }
    const anello::frame_bytes bytes = anello::encode_frame(built.value);
    std::fprintf(report, "%7.2f s  @%-6zu frame    %s\n", t, out.wire.size(), hex(bytes).c_str());
    out.wire.insert(out.wire.end(), bytes.begin(), bytes.end());
    out.frames.push_back(bytes);
    write(opt, bytes);

    if (opt.real_time) std::this_thread::sleep_for(std::chrono::milliseconds{250});
  }
  return true;
}

void print_stats(std::FILE* to, const anello::stream_stats& s) {
  std::fprintf(to,
               "stats: %llu sentences, %llu frames, %llu noise bytes, %llu bad CRC, %llu bad "
               "length, %llu truncated, %llu dropped bytes\n",
               static_cast<unsigned long long>(s.sentences),
               static_cast<unsigned long long>(s.frames),
               static_cast<unsigned long long>(s.noise_bytes),
               static_cast<unsigned long long>(s.bad_crc_frames),
               static_cast<unsigned long long>(s.bad_length_frames),
               static_cast<unsigned long long>(s.truncated_frames),
               static_cast<unsigned long long>(s.dropped_bytes));
}

// Reads the wire back in chunks of 1, 2, ... 97 bytes and compares with what was sent.
bool read_back(const options& opt, const sent& in) {
  std::FILE* report = opt.raw ? stderr : stdout;
  anello::stream_reader<> reader;
  std::size_t frames = 0;
  std::size_t sentences = 0;
  bool ok = true;
  const auto check = [&](const anello::stream_item& item) {
    if (item.is_frame()) {
      const bool same = frames < in.frames.size() && item.bytes == in.frames[frames] &&
                        item.frame == anello::decode_frame(in.frames[frames]).value;
      if (!same) std::fprintf(stderr, "frame %zu differs\n", frames);
      ok = ok && same;
      ++frames;
      return;
    }
    const bool same =
        sentences < in.sentences.size() && item.sentence.text == in.sentences[sentences];
    if (!same) std::fprintf(stderr, "sentence %zu differs\n", sentences);
    ok = ok && same && anello::decode_input(item.sentence.text).ok();
    ++sentences;
  };
  const std::span<const std::uint8_t> wire(in.wire);
  std::size_t at = 0;
  for (std::size_t n = 1; at < wire.size(); n = n % 97 + 1) {
    const std::size_t take = std::min(n, wire.size() - at);
    reader.feed(wire.subspan(at, take), check);
    at += take;
  }
  reader.finish(check);
  ok = ok && frames == in.frames.size() && sentences == in.sentences.size() &&
       reader.stats().noise_bytes == 0 && reader.stats().dropped_bytes == 0;
  std::fprintf(report,
               "read back %zu frames and %zu sentences from %zu bytes in chunks of 1..97: %s\n",
               frames, sentences, wire.size(), ok ? "all in order, bit for bit" : "MISMATCH");
  print_stats(report, reader.stats());
  if (!in.frames.empty()) {
    const auto last = anello::decode_frame(in.frames.back()).value;
    std::fprintf(report,
                 "last frame: heading %.0f deg, %.6f %.6f, STW %.1f m/s, %.1f C, %.0f hPa\n",
                 last.heading_deg().value_or(-1), last.latitude_deg().value_or(0),
                 last.longitude_deg().value_or(0), last.stw_mps().value_or(-1),
                 last.air_temp_c().value_or(-273), last.pressure_hpa().value_or(-1));
  }
  return ok;
}

// --read: list the items of a raw stream on stdin.
bool list_stdin() {
  anello::stream_reader<> reader;
  const auto show = [](const anello::stream_item& item) {
    if (item.is_frame()) {
      const auto& f = item.frame;
      std::printf("@%-8llu frame    heading %.0f deg, lat %.6f, lon %.6f, STW %.1f m/s\n",
                  static_cast<unsigned long long>(item.offset), f.heading_deg().value_or(-1),
                  f.latitude_deg().value_or(0), f.longitude_deg().value_or(0),
                  f.stw_mps().value_or(-1));
    } else {
      std::printf("@%-8llu sentence %.*s\n", static_cast<unsigned long long>(item.offset),
                  static_cast<int>(item.sentence.text.size()), item.sentence.text.data());
    }
  };
  std::uint8_t buf[4096];
  for (;;) {
    const std::size_t n = std::fread(buf, 1, sizeof buf, stdin);
    if (n == 0) break;
    reader.feed(std::span<const std::uint8_t>(buf, n), show);
  }
  reader.finish(show);
  print_stats(stdout, reader.stats());
  return std::ferror(stdin) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  options opt;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--raw") {
      opt.raw = true;
    } else if (arg == "--real-time") {
      opt.real_time = true;
    } else if (arg == "--read") {
      opt.read = true;
    } else if (arg == "--seconds" && i + 1 < argc) {
      opt.seconds = std::strtod(argv[++i], nullptr);
      if (!(opt.seconds >= 0 && opt.seconds <= 86400)) {
        std::fprintf(stderr, "--seconds: 0..86400\n");
        return 2;
      }
    } else {
      std::fprintf(stderr, "usage: %s [--seconds S] [--raw] [--real-time] | --read\n", argv[0]);
      return 2;
    }
  }
  if (opt.read) return list_stdin() ? 0 : 1;
  sent out;
  if (!produce(opt, out)) return 1;
  return read_back(opt, out) ? 0 : 1;
}
