// SPDX-License-Identifier: BSL-1.0
// seawire-tcp: a line-framed TCP client for the shell. Sentences from stdin go to the server,
// sentences from the server go to stdout, each cut out by seawire's stream reader (a garbled or
// overlong line from either side is dropped, never glued to the next), each ended with CR LF.
// Manual: tools/tcp/README.md.

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <asio.hpp>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <seawire/nmea/stream.hpp>
#include <string>

#include "cli.hpp"
#include "log_limit.hpp"
#include "net.hpp"

namespace {

using namespace seawire;
namespace net = seawire::tools::net;
using std::chrono::milliseconds;

struct options {
  std::string server;
  bool reconnect = false;
  double min_backoff = 0.1;
  double max_backoff = 5;
  double connect_timeout = 10;
  bool lf = false;
  bool quiet = false;
  bool close_on_eof = false;
};

class client {
 public:
  client(asio::io_context& io, const options& o, std::string host, std::string port)
      : io_(io),
        o_(o),
        host_(std::move(host)),
        port_(std::move(port)),
        resolver_(io),
        socket_(io),
        timer_(io),
        connect_timer_(io),
        signals_(io, SIGINT, SIGTERM),
        backoff_(o.min_backoff) {
    struct stat st {};
    stdin_is_file_ = ::fstat(0, &st) == 0 && !S_ISFIFO(st.st_mode) && !S_ISSOCK(st.st_mode) &&
                     !S_ISCHR(st.st_mode);
    if (!stdin_is_file_) {
      // asio makes the descriptor non-blocking. A terminal's stdin is usually the same open
      // file as stdout, and a dup() would share that flag with it (and leave the terminal
      // non-blocking afterwards): open the terminal anew instead.
      const int fd = ::isatty(0) != 0 ? ::open("/proc/self/fd/0", O_RDONLY | O_CLOEXEC) : ::dup(0);
      asio::error_code ec;
      if (fd >= 0) stdin_.assign(fd, ec);
      if (fd < 0 || ec) stdin_is_file_ = true;  // not pollable: read it as a file
    }
    signals_.async_wait([this](const asio::error_code& ec, int) {
      if (!ec) finish(0);
    });
  }

  void start() { connect(); }

  // A connection message on stderr (unless --quiet): at most 20 a second (a server that accepts
  // and closes at once, with --reconnect), then how many were not told.
  template <class... A>
  void note(const char* format, A... args) {
    if (o_.quiet || !log_.allow([this](std::uint64_t n) { told(n); })) return;
    std::fprintf(stderr, "seawire-tcp: ");
    std::fprintf(stderr, format, args...);
    std::fputc('\n', stderr);
  }
  void told(std::uint64_t suppressed) {
    std::fprintf(stderr, "seawire-tcp: %s\n", log_.note_text(suppressed).c_str());
  }
  [[nodiscard]] int status() const { return status_; }

 private:
  void connect() {
    resolver_.async_resolve(
        host_, port_,
        [this](const asio::error_code& ec, const asio::ip::tcp::resolver::results_type& r) {
          if (done_) return;
          if (ec) {
            lost("cannot resolve " + host_ + ": " + ec.message());
            return;
          }
          // A server that never answers (a full accept queue, a firewall dropping the SYN)
          // would leave the connect waiting for minutes: closed after --connect-timeout.
          timed_out_ = false;
          connect_timer_.expires_after(
              std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                  std::chrono::duration<double>(o_.connect_timeout)));
          connect_timer_.async_wait([this](const asio::error_code& t) {
            if (t || done_ || connected_) return;
            timed_out_ = true;
            asio::error_code ignored;
            socket_.close(ignored);
          });
          asio::async_connect(
              socket_, r, [this](const asio::error_code& e, const asio::ip::tcp::endpoint& to) {
                connect_timer_.cancel();
                if (done_) return;
                if (e) {
                  char why[64];
                  std::snprintf(why, sizeof why, "no answer within %g s", o_.connect_timeout);
                  lost("cannot connect to " + host_ + ":" + port_ + ": " +
                       (timed_out_ ? std::string(why) : e.message()));
                  return;
                }
                connected(to);
              });
        });
  }

  void connected(const asio::ip::tcp::endpoint& to) {
    asio::error_code ignored;
    socket_.set_option(asio::ip::tcp::no_delay(true), ignored);
    note("connected to %s", net::to_string(to).c_str());
    connected_ = true;
    connected_at_ = std::chrono::steady_clock::now();
    from_server_.reset();
    read_socket();
    if (!pending_.empty()) {
      send_pending();
    } else if (!stdin_done_ && !stdin_reading_) {
      read_stdin();
    }
  }

  // The connection failed or ended: retry, or end.
  void lost(const std::string& why) {
    const bool was = connected_;
    connected_ = false;
    // A server that accepts and closes at once (full, or refusing us) must not be hammered:
    // the wait starts again from the shortest only after a connection that lasted.
    if (was && std::chrono::steady_clock::now() - connected_at_ >= std::chrono::seconds(2))
      backoff_ = o_.min_backoff;
    asio::error_code ignored;
    socket_.close(ignored);
    if (!o_.reconnect || (o_.close_on_eof && stdin_done_ && pending_.empty() && was)) {
      if (!was || why != "closed by the server") note("%s", why.c_str());
      finish(was ? 0 : 1);
      return;
    }
    note("%s; reconnecting in %.1f s", why.c_str(), backoff_);
    timer_.expires_after(milliseconds(static_cast<long>(backoff_ * 1000)));
    timer_.async_wait([this](const asio::error_code& ec) {
      if (!ec && !done_) connect();
    });
    backoff_ = std::min(backoff_ * 2, o_.max_backoff);
  }

  void read_socket() {
    socket_.async_read_some(asio::buffer(in_), [this](const asio::error_code& ec, std::size_t n) {
      if (done_ || !connected_) return;
      if (ec) {
        // What the server sent last without a line ending is still a sentence.
        from_server_.finish([this](const auto& item) { emit(item); });
        flush_stdout();
        lost(ec == asio::error::eof ? "closed by the server" : ec.message());
        return;
      }
      from_server_.feed(std::string_view(in_.data(), n), [this](const auto& item) { emit(item); });
      from_server_.flush([this](const auto& item) { emit(item); });
      flush_stdout();
      read_socket();
    });
  }

  template <class Item>
  void emit(const Item& item) {
    if (!item.is_sentence()) return;
    out_ += item.sentence.text;
    out_ += o_.lf ? "\n" : "\r\n";
  }

  void flush_stdout() {
    std::size_t done = 0;
    while (done < out_.size()) {
      const ssize_t n = ::write(1, out_.data() + done, out_.size() - done);
      if (n > 0) {
        done += static_cast<std::size_t>(n);
      } else if (n < 0 && errno == EINTR) {
        continue;
      } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
        pollfd p{1, POLLOUT, 0};  // stdout is non-blocking (someone else set it): wait
        (void)::poll(&p, 1, 1000);
      } else {
        // A closed pipe (EPIPE: SIGPIPE is ignored), a full disk: told, and the end.
        const int e = n < 0 ? errno : EIO;
        std::fprintf(stderr, "seawire-tcp: writing stdout: %s\n", std::strerror(e));
        finish(1);
        return;
      }
    }
    out_.clear();
  }

  // stdin -> pending_ (framed sentences with CR LF) -> the socket.
  void read_stdin() {
    if (stdin_done_ || done_) return;
    stdin_reading_ = true;
    if (stdin_is_file_) {
      asio::post(io_, [this] {
        const ssize_t n = ::read(0, stdin_buf_.data(), stdin_buf_.size());
        got_stdin(n > 0 ? asio::error_code{} : asio::error::eof,
                  n > 0 ? static_cast<std::size_t>(n) : 0);
      });
      return;
    }
    stdin_.async_read_some(asio::buffer(stdin_buf_),
                           [this](const asio::error_code& ec, std::size_t n) { got_stdin(ec, n); });
  }

  void got_stdin(const asio::error_code& ec, std::size_t n) {
    stdin_reading_ = false;
    if (done_) return;
    const auto take = [this](const auto& item) {
      if (!item.is_sentence()) return;
      pending_ += item.sentence.text;
      pending_ += "\r\n";
    };
    if (ec) {
      stdin_done_ = true;
      // A last line without its line ending was cut off (the writer died, a truncated file):
      // not sent as if whole.
      bool cut = false;
      from_stdin_.finish([&cut](const auto&) { cut = true; });
      if (cut)
        std::fprintf(stderr,
                     "seawire-tcp: stdin ended in the middle of a line (no line ending after "
                     "it): that line is not sent\n");
    } else {
      from_stdin_.feed(std::string_view(stdin_buf_.data(), n), take);
      from_stdin_.flush(take);
    }
    if (connected_) send_pending();
  }

  void send_pending() {
    if (pending_.empty()) {
      after_send();
      return;
    }
    sending_.swap(pending_);
    pending_.clear();
    asio::async_write(
        socket_, asio::buffer(sending_), [this](const asio::error_code& ec, std::size_t n) {
          if (done_) return;
          if (ec) {
            // Sent again after a reconnect, from the first line not wholly
            // written: a line the kernel took in full is not repeated.
            const std::size_t written = std::min(n, sending_.size());
            const std::size_t cut =
                written == 0 ? std::string::npos : sending_.rfind('\n', written - 1);
            pending_.insert(0, cut == std::string::npos ? sending_ : sending_.substr(cut + 1));
            sending_.clear();
            if (connected_) lost(ec.message());
            return;
          }
          sending_.clear();
          after_send();
        });
  }

  void after_send() {
    if (!stdin_done_) {
      if (!stdin_reading_) read_stdin();
      return;
    }
    // All of stdin is sent. With --close-on-eof, tell the server (half close) and read until it
    // closes; otherwise go on reading what it sends.
    if (!o_.close_on_eof) return;
    asio::error_code ignored;
    socket_.shutdown(asio::ip::tcp::socket::shutdown_send, ignored);
  }

  void finish(int status) {
    if (done_) return;
    done_ = true;
    log_.flush([this](std::uint64_t n) { told(n); });
    status_ = status;
    asio::error_code ignored;
    signals_.cancel(ignored);
    timer_.cancel();
    connect_timer_.cancel();
    resolver_.cancel();
    socket_.close(ignored);
    if (stdin_.is_open()) stdin_.close(ignored);
  }

  asio::io_context& io_;
  const options& o_;
  std::string host_, port_;
  asio::ip::tcp::resolver resolver_;
  asio::ip::tcp::socket socket_;
  asio::steady_timer timer_;
  asio::steady_timer connect_timer_;
  bool timed_out_ = false;
  tools::log_limit log_{"connection messages"};  // the connect was closed by connect_timer_
  asio::signal_set signals_;
  asio::posix::stream_descriptor stdin_{io_};
  bool stdin_is_file_ = false;
  double backoff_;
  std::chrono::steady_clock::time_point connected_at_{};
  bool connected_ = false;
  bool stdin_reading_ = false;
  bool stdin_done_ = false;
  bool done_ = false;
  int status_ = 0;
  std::array<char, 64 * 1024> in_{};
  std::array<char, 64 * 1024> stdin_buf_{};
  nmea::stream_reader<1024> from_server_;
  nmea::stream_reader<1024> from_stdin_;
  std::string out_, pending_, sending_;
};

}  // namespace

int main(int argc, char** argv) {
  options o;
  CLI::App app{
      "A line-framed TCP client: NMEA sentences from stdin to HOST:PORT, and from HOST:PORT to\n"
      "stdout, each cut out by seawire's stream reader and ended with CR LF. Output is flushed\n"
      "after every read from the server.",
      "seawire-tcp"};
  app.add_option("server", o.server, "HOST:PORT of the server (a vehicle: port 29500)")->required();
  app.add_flag("--reconnect", o.reconnect,
               "when the connection fails or ends, connect again (backoff doubling from "
               "--min-backoff to --max-backoff)");
  app.add_option("--min-backoff", o.min_backoff, "first wait before reconnecting, seconds")
      ->check(seawire::tools::finite_number)
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--max-backoff", o.max_backoff, "longest wait before reconnecting, seconds")
      ->check(seawire::tools::finite_number)
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--connect-timeout", o.connect_timeout,
                 "seconds to wait for the server to accept a connection")
      ->check(seawire::tools::finite_number)
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_flag("--lf", o.lf, "end lines written to stdout with LF alone");
  app.add_flag("-N,--close-on-eof", o.close_on_eof,
               "once stdin has ended and been sent, shut down the sending side and exit when the "
               "server closes (default: keep printing what the server sends)");
  app.add_flag("-q,--quiet", o.quiet, "no connection messages on stderr");
  if (const auto status = seawire::tools::parse_command_line(app, argc, argv)) return *status;
  const auto where = net::parse_endpoint(o.server);
  if (!where || where->port == 0 || o.server.front() == ':') {
    std::fprintf(stderr, "seawire-tcp: %s: expected HOST:PORT\n", o.server.c_str());
    return 2;
  }
  std::signal(SIGPIPE, SIG_IGN);
  try {
    asio::io_context io;
    client c(io, o, where->host, std::to_string(where->port));
    c.start();
    io.run();
    return c.status();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "seawire-tcp: %s\n", e.what());
    return 1;
  }
}
