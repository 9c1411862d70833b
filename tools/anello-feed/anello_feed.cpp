// SPDX-License-Identifier: BSL-1.0
// seawire-anello-feed: feeds an ANELLO Maritime INS its external inputs -- the 0xAB00 binary
// sensor frame and NMEA sentences -- on its RS-232 input (a serial device set up with termios,
// 115200 8N1 by default) or over UDP, paced at the frame rate, from a simulated boat or from a
// stream seawire-encode wrote. With --read-rmc it also reads the INS's RMC output back from the
// same device. Manual: tools/anello-feed/README.md.

#include <fcntl.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <asio.hpp>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <seawire/anello/frame.hpp>
#include <seawire/anello/inputs.hpp>
#include <seawire/anello/stream.hpp>
#include <string>
#include <vector>

#include "cli.hpp"
#include "io.hpp"
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
  // O_NONBLOCK for the open (it would wait for carrier detect) and the writes: a device that
  // takes nothing (a full line, a pty nobody reads) must not keep a signal or --seconds waiting.
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    error = path + ": " + std::strerror(errno);
    return -1;
  }
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

// A recorded stream (seawire-encode's output), read as it comes: cut into items by the stream
// reader; each frame starts a new period, the sentences after it go with it. Memory is bounded:
// input is read only when no period is ready, a chunk (64 KiB) at a time, and a run of
// sentences without a frame is cut into periods of max_items.
class stream_source {
 public:
  static constexpr std::size_t max_items = 64;

  explicit stream_source(int fd) : in_(fd) {}

  /// The next period; nullopt with ended() false when none is ready yet (input still to come).
  std::optional<period> next() {
    // A few chunks at most, and only those ready: the caller returns to its signals and timers.
    for (int i = 0; i < 16 && ready_.empty() && !ended_; ++i) {
      if (!in_.ready_within(0)) break;
      const std::string_view chunk = in_.next();
      if (chunk.empty()) {
        ended_ = true;
        reader_.finish([this](const auto& item) { take(item); });
        if (!current_.items.empty()) ready_.push_back(std::exchange(current_, period{}));
        break;
      }
      reader_.feed(chunk, [this](const auto& item) { take(item); });
    }
    if (ready_.empty()) return std::nullopt;
    period p = std::move(ready_.front());
    ready_.pop_front();
    return p;
  }
  [[nodiscard]] bool ended() const { return ended_ && ready_.empty(); }
  [[nodiscard]] int read_error() const { return in_.error(); }
  [[nodiscard]] std::uint64_t dropped() const {
    return reader_.stats().dropped_bytes + reader_.stats().noise_bytes;
  }

 private:
  template <class Item>
  void take(const Item& item) {
    if (item.is_frame()) {
      if (!current_.items.empty()) ready_.push_back(std::exchange(current_, period{}));
      current_.items.emplace_back(reinterpret_cast<const char*>(item.bytes.data()),
                                  item.bytes.size());
      ++current_.frames;
    } else if (item.is_sentence()) {
      current_.items.emplace_back(std::string(item.sentence.text) + "\r\n");
      ++current_.sentences;
      if (current_.items.size() >= max_items) ready_.push_back(std::exchange(current_, period{}));
    }
  }

  tools::chunk_reader in_;
  anello::stream_reader<> reader_;
  period current_;
  std::deque<period> ready_;
  bool ended_ = false;
};

class feeder {
 public:
  feeder(asio::io_context& io, const options& o)
      : io_(io),
        o_(o),
        timer_(io),
        deadline_(io),
        device_in_(io),
        out_(io),
        rmc_out_(io),
        signals_(io, SIGINT, SIGTERM) {}

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
      return own_output(out_, fd_, error) && (!o_.read_rmc || own_stdout(rmc_out_, error));
    }
    if (!o_.udp.empty()) {
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
      return true;
    }
    return own_stdout(out_, error);
  }

  // Periods come from `next` until it returns nullopt with `later` false, --seconds is up or a
  // signal comes. nullopt with `later` true: none ready yet, asked again shortly.
  void run(std::function<std::optional<period>(std::string& error, bool& later)> next) {
    next_ = std::move(next);
    t0_ = steady::now();
    signals_.async_wait([this](const asio::error_code& ec, int) {
      if (!ec) finish();  // drain the line (for a while), print the summary, exit 0
    });
    if (o_.seconds > 0) {
      // By the clock, not by periods sent: input that stalls, or a line that takes nothing,
      // does not stretch the run.
      deadline_.expires_at(t0_ + std::chrono::duration_cast<steady::duration>(
                                     std::chrono::duration<double>(o_.seconds)));
      deadline_.async_wait([this](const asio::error_code& ec) {
        if (!ec) finish();
      });
    }
    if (o_.read_rmc) read();
    step();
    io_.run();
  }

  [[nodiscard]] int status() const { return status_; }

 private:
  void step() {
    if (done_) return;
    const double t = static_cast<double>(tick_) / o_.rate;
    if (o_.seconds > 0 && t >= o_.seconds) {
      finish();
      return;
    }
    std::string error;
    bool later = false;
    auto p = next_(error, later);
    if (!p) {
      if (later) {
        wait_for(steady::now() + std::chrono::milliseconds(10));  // input still to come
        return;
      }
      if (!error.empty()) {
        std::fprintf(stderr, "seawire-anello-feed: %s\n", error.c_str());
        status_ = 1;
      }
      finish();
      return;
    }
    if (udp_) {
      for (const std::string& item : p->items) {
        asio::error_code ec;
        udp_->send_to(asio::buffer(item), udp_to_, 0, ec);
        if (ec) {
          fail("--udp: " + ec.message());
          return;
        }
      }
      sent(*p);
      return;
    }
    for (const std::string& item : p->items) pending_ += item;
    sending_ = std::move(*p);
    write_pending();
  }

  // Writes pending_ without blocking; when the device or pipe takes no more, waits for it to
  // be writable in the event loop, where signals and --seconds are still heard.
  void write_pending() {
    while (written_ < pending_.size()) {
      const ssize_t n =
          ::write(out_.native_handle(), pending_.data() + written_, pending_.size() - written_);
      if (n > 0) {
        written_ += static_cast<std::size_t>(n);
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
        out_.async_wait(asio::posix::descriptor_base::wait_write,
                        [this](const asio::error_code& ec) {
                          if (!ec && !done_) write_pending();
                        });
        return;
      }
      fail(std::string(o_.device.empty() ? "writing stdout" : o_.device) + ": " +
           std::strerror(n < 0 ? errno : EIO));
      return;
    }
    pending_.clear();
    written_ = 0;
    sent(sending_);
  }

  // A period sent: the next one at its time.
  void sent(const period& p) {
    frames_ += p.frames;
    sentences_ += p.sentences;
    ++tick_;
    wait_for(t0_ + std::chrono::duration_cast<steady::duration>(
                       std::chrono::duration<double>(static_cast<double>(tick_) / o_.rate)));
  }

  void wait_for(steady::time_point at) {
    timer_.expires_at(at);
    timer_.async_wait([this](const asio::error_code& ec) {
      if (!ec) step();
    });
  }

  void fail(const std::string& why) {
    std::fprintf(stderr, "seawire-anello-feed: %s\n", why.c_str());
    status_ = 1;
    finish();
  }

  static bool own_output(asio::posix::stream_descriptor& d, int fd, std::string& error) {
    asio::error_code ec;
    d.assign(fd, ec);
    if (!ec) d.non_blocking(true, ec);
    if (ec) {
      error = "output: " + ec.message();
      return false;
    }
    return true;
  }

  // stdout, written without blocking: a pipe or terminal opened anew, so that making it
  // non-blocking leaves the caller's open file (shared with its shell) as it was; a file or
  // socket as it is.
  static bool own_stdout(asio::posix::stream_descriptor& d, std::string& error) {
    struct stat st {};
    int fd = -1;
    if (::fstat(1, &st) == 0 && (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)))
      fd = ::open("/proc/self/fd/1", O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) fd = ::dup(1);
    if (fd < 0) {
      error = std::string("stdout: ") + std::strerror(errno);
      return false;
    }
    return own_output(d, fd, error);
  }

  // The INS's output: RMC sentences, printed as received; anything else counted. Printed
  // without blocking: while 64 KiB wait for a stdout nobody reads, the device is not read.
  void read() {
    reading_ = true;
    device_in_.async_read_some(
        asio::buffer(in_), [this](const asio::error_code& ec, std::size_t n) {
          reading_ = false;
          if (ec || done_) return;
          reader_.feed(std::string_view(in_.data(), n), [this](const auto& item) {
            if (!item.is_sentence()) return;
            const auto r = anello::decode_output(item.sentence.text);
            if (r && std::holds_alternative<standard::rmc>(r.value)) {
              rmc_pending_ += item.sentence.text;
              rmc_pending_ += '\n';
              ++rmc_;
            } else {
              ++other_;
            }
          });
          write_rmc();
        });
  }

  void write_rmc() {
    while (!rmc_pending_.empty()) {
      const ssize_t n = ::write(rmc_out_.native_handle(), rmc_pending_.data(), rmc_pending_.size());
      if (n > 0) {
        rmc_pending_.erase(0, static_cast<std::size_t>(n));
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
        if (!rmc_waiting_) {
          rmc_waiting_ = true;
          rmc_out_.async_wait(asio::posix::descriptor_base::wait_write,
                              [this](const asio::error_code& ec) {
                                rmc_waiting_ = false;
                                if (!ec && !done_) write_rmc();
                              });
        }
        break;
      }
      fail(std::string("writing stdout: ") + std::strerror(n < 0 ? errno : EIO));
      return;
    }
    if (!reading_ && !done_ && rmc_pending_.size() < 64 * 1024) read();
  }

  void finish() {
    if (done_) return;
    done_ = true;
    if (fd_ >= 0) drain();
    timer_.cancel();
    deadline_.cancel();
    asio::error_code ignored;
    signals_.cancel(ignored);
    if (device_in_.is_open()) device_in_.close(ignored);
    if (out_.is_open()) out_.close(ignored);
    if (rmc_out_.is_open()) rmc_out_.close(ignored);
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

  // Lets the device send what it holds, for at most a second (tcdrain would wait for ever on
  // a line that takes nothing): its output queue polled until empty.
  void drain() const {
    const auto until = steady::now() + std::chrono::seconds(1);
    int queued = 0;
    while (::ioctl(fd_, TIOCOUTQ, &queued) == 0 && queued > 0 && steady::now() < until)
      ::usleep(10 * 1000);
  }

  asio::io_context& io_;
  const options& o_;
  asio::steady_timer timer_;
  asio::steady_timer deadline_;  // --seconds
  asio::posix::stream_descriptor device_in_;
  asio::posix::stream_descriptor out_;      // the device (a descriptor of its own) or stdout
  asio::posix::stream_descriptor rmc_out_;  // stdout, with --read-rmc
  std::string rmc_pending_;                 // RMC lines not yet written to stdout
  bool reading_ = false, rmc_waiting_ = false;
  asio::signal_set signals_;
  std::optional<asio::ip::udp::socket> udp_;
  asio::ip::udp::endpoint udp_to_;
  int fd_ = -1;
  std::function<std::optional<period>(std::string&, bool&)> next_;
  std::string pending_;  // the period being written
  std::size_t written_ = 0;
  period sending_;
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
  int input_fd = -1;
  if (!o.input.empty()) {
    input_fd = o.input == "-" ? 0 : ::open(o.input.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat st {};
    const bool directory = input_fd >= 0 && ::fstat(input_fd, &st) == 0 && S_ISDIR(st.st_mode);
    if (input_fd < 0 || directory) {
      std::fprintf(stderr, "seawire-anello-feed: --input %s: cannot be read: %s\n", o.input.c_str(),
                   std::strerror(directory ? EISDIR : errno));
      return 2;
    }
  }
  // A reader gone (EPIPE) is an error told like any other, not a silent death.
  std::signal(SIGPIPE, SIG_IGN);
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
      f.run([&](std::string& e, bool&) { return boat.next(e); });
    } else {
      stream_source source(input_fd);
      f.run([&](std::string& e, bool& later) {
        std::optional<period> p = source.next();
        later = !p && !source.ended();
        if (!p && source.read_error() != 0)
          e = "--input " + o.input + ": " + std::strerror(source.read_error());
        return p;
      });
      if (source.dropped() != 0)
        std::fprintf(stderr,
                     "seawire-anello-feed: --input: %llu bytes outside frames and sentences "
                     "skipped\n",
                     static_cast<unsigned long long>(source.dropped()));
    }
    return f.status();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "seawire-anello-feed: %s\n", e.what());
    return 1;
  }
}
