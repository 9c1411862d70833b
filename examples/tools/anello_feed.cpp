// SPDX-License-Identifier: BSL-1.0
// seawire-anello-feed: feeds an ANELLO Maritime INS its external inputs -- the 0xAB00 binary
// sensor frame and NMEA sentences -- on its RS-232 input (a serial device set up with termios,
// 115200 8N1 by default) or over UDP, paced at the frame rate, from a simulated boat or from a
// stream seawire-encode wrote. With --read-rmc it also reads the INS's RMC output back from the
// same device. Manual: docs/seawire-anello-feed.md.

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <asio.hpp>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <optional>
#include <seawire/anello/frame.hpp>
#include <seawire/anello/inputs.hpp>
#include <seawire/anello/stream.hpp>
#include <string>
#include <vector>

#include "cli.hpp"
#include "kingfisher_model.hpp"
#include "net.hpp"

namespace {

using namespace seawire;
using steady = std::chrono::steady_clock;

struct options {
  std::string device;
  std::string udp;
  int baud = 115200;
  std::string input;
  double rate = 4;
  double seconds = 0;
  std::string start = "32.7076,-117.2281";
  std::uint64_t seed = 1;
  bool read_rmc = false;
  bool quiet = false;
};

// One period's bytes: a frame and the sentences that go with it.
struct period {
  std::vector<std::string> items;  // each a whole frame or sentence (CR LF included)
  std::uint64_t frames = 0;
  std::uint64_t sentences = 0;
};

// termios speed constants for the rates a serial port offers.
std::optional<speed_t> speed_of(int baud) {
  static const std::map<int, speed_t> speeds{
      {1200, B1200},     {2400, B2400},     {4800, B4800},    {9600, B9600},
      {19200, B19200},   {38400, B38400},   {57600, B57600},  {115200, B115200},
      {230400, B230400}, {460800, B460800}, {921600, B921600}};
  const auto it = speeds.find(baud);
  if (it == speeds.end()) return std::nullopt;
  return it->second;
}

// Opens a serial device raw at `baud`, 8N1, no flow control. -1 and `error` on failure.
int open_serial(const std::string& path, int baud, std::string& error) {
  // O_NONBLOCK only for the open itself (it would wait for carrier detect); writes block.
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    error = path + ": " + std::strerror(errno);
    return -1;
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  termios t{};
  if (::tcgetattr(fd, &t) != 0) {
    error = path + ": not a terminal (" + std::string(std::strerror(errno)) + ")";
    ::close(fd);
    return -1;
  }
  ::cfmakeraw(&t);
  t.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | PARENB | CRTSCTS | CSIZE);
  t.c_cflag |= CS8 | CLOCAL | CREAD;
  t.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  t.c_cc[VMIN] = 1;
  t.c_cc[VTIME] = 0;
  const speed_t speed = *speed_of(baud);
  ::cfsetispeed(&t, speed);
  ::cfsetospeed(&t, speed);
  if (::tcsetattr(fd, TCSANOW, &t) != 0) {
    error = path + ": cannot set " + std::to_string(baud) + " 8N1: " + std::strerror(errno);
    ::close(fd);
    return -1;
  }
  ::tcflush(fd, TCIOFLUSH);
  return fd;
}

// The built-in boat: circling at about 2 m/s, a VBW speed sentence once a second.
class simulated_boat {
 public:
  simulated_boat(const options& o, double lat, double lon)
      : rate_(o.rate), model_(params(), lat, lon, o.seed) {}

  std::optional<period> next(std::string& error) {
    const double t = static_cast<double>(tick_) / rate_;
    model_.rate(3.0, 60, t);  // 3 deg/s to starboard, 60 % thrust
    model_.step(1.0 / rate_, t);
    period p;
    anello::sensor_values v;
    v.heading_deg = model_.heading();
    v.latitude_deg = model_.lat();
    v.longitude_deg = model_.lon();
    v.sog_mps = model_.speed() + 0.2;  // a little current from astern
    v.cog_deg = model_.heading();
    v.gps_time = anello::time_ms{std::chrono::duration_cast<std::chrono::milliseconds>(
        std::chrono::system_clock::now().time_since_epoch())};
    v.alt_msl_m = 1.5;
    v.geoid_sep_m = -35.2;
    v.hdop = 0.9;
    v.fix_quality = 1;
    v.motor_pct = 60;
    v.rudder_pct = 15;
    v.stw_mps = model_.speed();
    v.wind_speed_abs_mps = 4.3;
    v.wind_dir_abs_deg = 270;
    v.air_temp_c = 21.5;
    v.pressure_hpa = 1013;
    if (tick_ % static_cast<std::uint64_t>(std::max(1.0, std::round(rate_))) == 0) {
      anello::vbw_si vbw_in;
      vbw_in.longitudinal_water_mps = model_.speed();
      vbw_in.transverse_water_mps = -0.05;
      const auto vbw = anello::make_vbw(vbw_in);
      if (!vbw) {
        error = "VBW not built: " + std::string(message(vbw.ec));
        return std::nullopt;
      }
      const auto line = nmea::encode(vbw.value);
      if (!line) {
        error = "VBW not encoded: " + std::string(message(line.ec));
        return std::nullopt;
      }
      p.items.emplace_back(line.view());
      ++p.sentences;
    }
    const auto built = anello::build_frame(v);
    if (!built) {
      error = "frame not built: field " + std::to_string(built.field) + ": " +
              std::string(message(built.ec));
      return std::nullopt;
    }
    const anello::frame_bytes bytes = anello::encode_frame(built.value);
    p.items.emplace_back(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    ++p.frames;
    ++tick_;
    return p;
  }

 private:
  static tools::vehicle_params params() {
    tools::vehicle_params p;
    p.max_speed_mps = 3.5;
    p.watchdog_s = 1e9;
    return p;
  }
  double rate_;
  tools::vehicle_model model_;
  std::uint64_t tick_ = 0;
};

// A recorded stream (seawire-encode's output): cut into items by the stream reader; each frame
// starts a new period, the sentences after it go with it.
std::vector<period> read_stream(std::istream& in, std::uint64_t& dropped) {
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<period> out(1);
  anello::stream_reader<> reader;
  const auto take = [&](const auto& item) {
    if (item.is_frame()) {
      if (out.back().frames != 0 || out.back().sentences != 0) out.emplace_back();
      out.back().items.emplace_back(reinterpret_cast<const char*>(item.bytes.data()),
                                    item.bytes.size());
      ++out.back().frames;
    } else if (item.is_sentence()) {
      out.back().items.emplace_back(std::string(item.sentence.text) + "\r\n");
      ++out.back().sentences;
    }
  };
  reader.feed(std::string_view(bytes), take);
  while (const auto item = reader.finish()) take(*item);
  dropped = reader.stats().dropped_bytes + reader.stats().noise_bytes;
  if (out.back().items.empty()) out.pop_back();
  return out;
}

class feeder {
 public:
  feeder(asio::io_context& io, const options& o)
      : io_(io), o_(o), timer_(io), device_in_(io), signals_(io, SIGINT, SIGTERM) {}

  bool open(std::string& error) {
    if (!o_.device.empty()) {
      fd_ = open_serial(o_.device, o_.baud, error);
      if (fd_ < 0) return false;
      if (o_.read_rmc) {
        // A descriptor of its own for reading: asio makes it non-blocking, and a dup() would
        // share that flag with the blocking writes.
        const int in = ::open(o_.device.c_str(), O_RDONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
        if (in < 0) {
          error = o_.device + ": " + std::strerror(errno);
          return false;
        }
        asio::error_code ec;
        device_in_.assign(in, ec);
        if (ec) {
          error = o_.device + ": " + ec.message();
          return false;
        }
      }
    } else if (!o_.udp.empty()) {
      const auto where = tools::net::parse_endpoint(o_.udp);
      if (!where || where->port == 0) {
        error = "--udp " + o_.udp + ": expected HOST:PORT";
        return false;
      }
      asio::error_code ec;
      asio::ip::udp::resolver resolver(io_);
      const auto r = resolver.resolve(where->host, std::to_string(where->port), ec);
      if (ec || r.empty()) {
        error = "--udp " + o_.udp + ": " + ec.message();
        return false;
      }
      udp_to_ = *r.begin();
      udp_.emplace(io_);
      udp_->open(udp_to_.protocol(), ec);
      if (ec) {
        error = "--udp: " + ec.message();
        return false;
      }
    }
    return true;
  }

  // Periods come from `next` until it returns nullopt (or --seconds is up).
  void run(std::function<std::optional<period>(std::string&)> next) {
    next_ = std::move(next);
    t0_ = steady::now();
    signals_.async_wait([this](const asio::error_code& ec, int) {
      if (!ec) finish();  // drain the line, print the summary, exit 0
    });
    if (o_.read_rmc) read();
    step();
    io_.run();
  }

  [[nodiscard]] int status() const { return status_; }

 private:
  void step() {
    const double t = static_cast<double>(tick_) / o_.rate;
    if (o_.seconds > 0 && t >= o_.seconds) {
      finish();
      return;
    }
    std::string error;
    auto p = next_(error);
    if (!p) {
      if (!error.empty()) {
        std::fprintf(stderr, "seawire-anello-feed: %s\n", error.c_str());
        status_ = 1;
      }
      finish();
      return;
    }
    for (const std::string& item : p->items) {
      if (!send(item)) {
        finish();
        return;
      }
    }
    frames_ += p->frames;
    sentences_ += p->sentences;
    ++tick_;
    timer_.expires_at(t0_ +
                      std::chrono::duration_cast<steady::duration>(
                          std::chrono::duration<double>(static_cast<double>(tick_) / o_.rate)));
    timer_.async_wait([this](const asio::error_code& ec) {
      if (!ec) step();
    });
  }

  bool send(const std::string& item) {
    if (udp_) {
      asio::error_code ec;
      udp_->send_to(asio::buffer(item), udp_to_, 0, ec);
      if (ec) {
        std::fprintf(stderr, "seawire-anello-feed: --udp: %s\n", ec.message().c_str());
        status_ = 1;
        return false;
      }
      return true;
    }
    const int fd = fd_ >= 0 ? fd_ : 1;
    std::size_t done = 0;
    while (done < item.size()) {
      const ssize_t n = ::write(fd, item.data() + done, item.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        std::fprintf(stderr, "seawire-anello-feed: write: %s\n", std::strerror(errno));
        status_ = 1;
        return false;
      }
      done += static_cast<std::size_t>(n);
    }
    return true;
  }

  // The INS's output: RMC sentences, printed as received; anything else counted.
  void read() {
    device_in_.async_read_some(
        asio::buffer(in_), [this](const asio::error_code& ec, std::size_t n) {
          if (ec) return;
          reader_.feed(std::string_view(in_.data(), n), [this](const auto& item) {
            if (!item.is_sentence()) return;
            const auto r = anello::decode_output(item.sentence.text);
            if (r && std::holds_alternative<standard::rmc>(r.value)) {
              std::printf("%.*s\n", static_cast<int>(item.sentence.text.size()),
                          item.sentence.text.data());
              std::fflush(stdout);
              ++rmc_;
            } else {
              ++other_;
            }
          });
          read();
        });
  }

  void finish() {
    if (done_) return;
    done_ = true;
    if (fd_ >= 0) ::tcdrain(fd_);
    timer_.cancel();
    asio::error_code ignored;
    signals_.cancel(ignored);
    if (device_in_.is_open()) device_in_.close(ignored);
    if (!o_.quiet)
      std::fprintf(stderr, "seawire-anello-feed: %llu frames, %llu sentences sent in %.2f s%s\n",
                   static_cast<unsigned long long>(frames_),
                   static_cast<unsigned long long>(sentences_),
                   std::chrono::duration<double>(steady::now() - t0_).count(),
                   o_.read_rmc ? (", " + std::to_string(rmc_) + " RMC read, " +
                                  std::to_string(other_) + " other lines")
                                     .c_str()
                               : "");
  }

  asio::io_context& io_;
  const options& o_;
  asio::steady_timer timer_;
  asio::posix::stream_descriptor device_in_;
  asio::signal_set signals_;
  std::optional<asio::ip::udp::socket> udp_;
  asio::ip::udp::endpoint udp_to_;
  int fd_ = -1;
  std::function<std::optional<period>(std::string&)> next_;
  steady::time_point t0_;
  std::uint64_t tick_ = 0, frames_ = 0, sentences_ = 0, rmc_ = 0, other_ = 0;
  std::array<char, 4096> in_{};
  nmea::stream_reader<> reader_;
  bool done_ = false;
  int status_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  options o;
  CLI::App app{
      "Feeds an ANELLO Maritime INS its external inputs: the 0xAB00 binary sensor frame and\n"
      "NMEA sentences, on a serial device (115200 8N1 by default), over UDP, or to stdout,\n"
      "paced at the frame rate; from a simulated boat or a stream seawire-encode wrote.",
      "seawire-anello-feed"};
  auto* dev = app.add_option("--device", o.device, "serial device to write to (and read RMC from)");
  app.add_option("--udp", o.udp, "HOST:PORT to send each frame and sentence to as a datagram")
      ->excludes(dev);
  app.add_option("--baud", o.baud, "serial speed, 8N1")
      ->check([](const std::string& s) {
        try {
          return speed_of(std::stoi(s)) ? std::string() : std::string("not a serial speed");
        } catch (...) {
          return std::string("not a number");
        }
      })
      ->capture_default_str();
  app.add_option("--input", o.input,
                 "a stream of frames and sentences (seawire-encode's output; - for stdin) "
                 "instead of the simulated boat");
  app.add_option("--rate", o.rate, "frames per second (the INS takes up to 10; 4 by default)")
      ->check(seawire::tools::finite_number)
      ->check(CLI::Range(0.1, 10.0))
      ->capture_default_str();
  app.add_option("--seconds", o.seconds, "stop after this long (0: the input's end or never)")
      ->check(seawire::tools::finite_number)
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--start", o.start, "LAT,LON where the simulated boat starts")
      ->capture_default_str();
  app.add_option("--seed", o.seed, "seed of the simulated boat")->capture_default_str();
  app.add_flag("--read-rmc", o.read_rmc,
               "print the RMC sentences the INS sends back on --device to stdout")
      ->needs(dev);
  app.add_flag("-q,--quiet", o.quiet, "no summary on stderr");
  if (const auto status = seawire::tools::parse_command_line(app, argc, argv)) return *status;

  double lat = 0, lon = 0;
  char tail = 0;
  if (std::sscanf(o.start.c_str(), "%lf,%lf%c", &lat, &lon, &tail) != 2 || !(lat >= -85) ||
      !(lat <= 85) || !(lon >= -180) || !(lon <= 180)) {
    std::fprintf(stderr, "seawire-anello-feed: --start %s: expected LAT,LON\n", o.start.c_str());
    return 2;
  }
  std::vector<period> recorded;
  if (!o.input.empty()) {
    std::ifstream file;
    if (o.input != "-") {
      file.open(o.input, std::ios::binary);
      if (!file) {
        std::fprintf(stderr, "seawire-anello-feed: --input %s: cannot be read\n", o.input.c_str());
        return 2;
      }
    }
    std::uint64_t dropped = 0;
    recorded = read_stream(o.input == "-" ? std::cin : file, dropped);
    if (dropped != 0)
      std::fprintf(stderr,
                   "seawire-anello-feed: --input: %llu bytes outside frames and sentences "
                   "skipped\n",
                   static_cast<unsigned long long>(dropped));
  }
  try {
    asio::io_context io;
    feeder f(io, o);
    std::string error;
    if (!f.open(error)) {
      std::fprintf(stderr, "seawire-anello-feed: %s\n", error.c_str());
      return 1;
    }
    if (o.input.empty()) {
      simulated_boat boat(o, lat, lon);
      f.run([&](std::string& e) { return boat.next(e); });
    } else {
      std::size_t i = 0;
      f.run([&](std::string&) -> std::optional<period> {
        if (i == recorded.size()) return std::nullopt;
        return recorded[i++];
      });
    }
    return f.status();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "seawire-anello-feed: %s\n", e.what());
    return 1;
  }
}
