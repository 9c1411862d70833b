// SPDX-License-Identifier: BSL-1.0
#pragma once
// The TCP side of the simulators and servers: one thread, one asio event loop.
//
// line_server accepts any number of clients. Each client's bytes go through the library's stream
// reader (sentences only, fixed memory), so an overlong or garbled line from one client never
// corrupts the next sentence, and each sentence is handed to the program. What the program sends
// goes into each client's queue, bounded in lines: when a client does not read, its oldest
// unsent lines are dropped and counted, and once more than `max_drops` lines have been dropped
// it is disconnected. Bytes the reader gives up on are skipped, or handed to the program when it
// asks (on_drop). A client that ends its sending side (half close) gets what is already
// queued for it (within 10 s), then the connection is closed. One line per connection event is
// logged to stderr.
//
// serve() is the main of every server once its options are read: listen, log "listening on",
// start, hand SIGINT and SIGTERM to the program, run, and the exit status.
//
// Closing a client never removes it inside the call that closed it: the removal (and the
// program's on_close) runs as a posted handler, so code that is iterating clients or holding a
// reference to a client's state while it sends can never see it freed under its feet.

#include <asio.hpp>

#include <chrono>
#include <concepts>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <seawire/nmea/stream.hpp>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "log_limit.hpp"

namespace seawire::tools::net {

/// "ADDR:PORT", "[v6addr]:PORT" or ":PORT" (all interfaces). nullopt when malformed.
struct endpoint_text {
  std::string host;
  std::uint16_t port = 0;
};
inline std::optional<endpoint_text> parse_endpoint(std::string_view s) {
  const auto colon = s.rfind(':');
  if (colon == std::string_view::npos) return std::nullopt;
  std::string_view host = s.substr(0, colon);
  const std::string_view port = s.substr(colon + 1);
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']')
    host = host.substr(1, host.size() - 2);
  unsigned value = 0;
  if (port.empty() || port.size() > 5) return std::nullopt;
  for (const char c : port) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + static_cast<unsigned>(c - '0');
  }
  if (value > 65535) return std::nullopt;
  return endpoint_text{host.empty() ? std::string("0.0.0.0") : std::string(host),
                       static_cast<std::uint16_t>(value)};
}

inline std::string to_string(const asio::ip::tcp::endpoint& e) {
  const auto a = e.address();
  return (a.is_v6() ? "[" + a.to_string() + "]" : a.to_string()) + ":" + std::to_string(e.port());
}

/// Lines shared by every client they are sent to: one allocation per batch, not per client.
struct batch {
  std::string bytes;
  std::uint32_t lines = 0;
};
using batch_ptr = std::shared_ptr<const batch>;

struct server_limits {
  std::size_t max_queue_lines = 2000;  ///< unsent lines kept per client
  std::uint64_t max_drops = 10000;     ///< dropped lines after which a client is disconnected
  int send_buffer = 0;                 ///< SO_SNDBUF for clients' sockets; 0 = the system's
  std::size_t max_clients = 1000;      ///< further connections are refused (closed at once)
};

class line_server;

/// One connected client.
class client : public std::enable_shared_from_this<client> {
 public:
  client(line_server& server, asio::ip::tcp::socket socket, std::uint64_t id);

  [[nodiscard]] std::uint64_t id() const { return id_; }
  [[nodiscard]] const std::string& peer() const { return peer_; }
  [[nodiscard]] const asio::ip::address& address() const { return address_; }
  /// Queues `bytes` (whole lines) for this client alone.
  void send(std::string bytes, std::uint32_t lines) {
    auto b = std::make_shared<batch>();
    b->bytes = std::move(bytes);
    b->lines = lines;
    send(b);
  }
  /// Queues `b` for sending (dropping the oldest unsent lines when over the limit).
  void send(const batch_ptr& b);
  /// Closes the connection; `why` is logged once.
  void close(std::string_view why);

  std::uint64_t lines_sent = 0;
  std::uint64_t lines_dropped = 0;
  std::uint64_t sentences_in = 0;
  std::uint64_t rejected_in = 0;  ///< counted by the program (bad commands)
  std::uint64_t bytes_in = 0;

 private:
  friend class line_server;
  void start();
  void read();
  void write();
  template <class Item>
  void deliver(const Item& item);

  line_server& server_;
  asio::ip::tcp::socket socket_;
  asio::steady_timer linger_;  ///< after a half close: how long queued lines may take
  std::uint64_t id_;
  std::string peer_;
  asio::ip::address address_;
  nmea::stream_reader<512> reader_;
  std::array<char, 4096> in_{};
  std::deque<batch_ptr> queue_;
  std::size_t queued_lines_ = 0;
  bool writing_ = false;
  bool closed_ = false;
  bool read_ended_ = false;  ///< the peer half-closed: flush the queue, then close
};

/// Accepts clients on one endpoint and keeps them until they or the program close.
class line_server {
 public:
  /// A sentence as received: its text (without the line ending) and how it ended.
  using sentence_handler = std::function<void(client&, const nmea::framed_line& sentence)>;
  using client_handler = std::function<void(client&)>;
  using closed_handler = std::function<void(client&, std::string_view why)>;
  /// Bytes the stream reader gave up on (no '$' first, a byte outside printable ASCII, longer
  /// than the reader holds, cut short by the next '$'), as nmea::stream_reader reports them.
  using drop_handler = std::function<void(client&, const nmea::stream_drop& drop)>;

  line_server(asio::io_context& io, const asio::ip::tcp::endpoint& where, server_limits limits)
      : acceptor_(io), retry_(io), limits_(limits) {
    acceptor_.open(where.protocol());
    acceptor_.set_option(asio::ip::tcp::acceptor::reuse_address(true));
    acceptor_.bind(where);
    acceptor_.listen(asio::socket_base::max_listen_connections);
  }

  [[nodiscard]] asio::ip::tcp::endpoint local_endpoint() const {
    return acceptor_.local_endpoint();
  }
  [[nodiscard]] const server_limits& limits() const { return limits_; }

  void on_sentence(sentence_handler h) { on_sentence_ = std::move(h); }
  void on_connect(client_handler h) { on_connect_ = std::move(h); }
  void on_close(closed_handler h) { on_close_ = std::move(h); }
  /// With a handler, every client's dropped bytes are reported (without, they are only skipped).
  void on_drop(drop_handler h) { on_drop_ = std::move(h); }

  void start() { accept(); }

  /// Stops accepting and closes every client.
  void stop(std::string_view why) {
    asio::error_code ignored;
    acceptor_.close(ignored);
    retry_.cancel();
    auto all = clients_;
    for (auto& [id, c] : all) c->close(why);
  }

  /// Sends `b` to every client.
  void broadcast(const batch_ptr& b) {
    for (auto& [id, c] : clients_) c->send(b);
  }

  [[nodiscard]] std::size_t client_count() const { return clients_.size(); }
  [[nodiscard]] std::uint64_t connections() const { return next_id_ - 1; }

  /// A line on stderr, flushed: the programs' log.
  template <class... A>
  static void log(const char* format, A... args) {
    std::fprintf(stderr, format, args...);
    std::fputc('\n', stderr);
    std::fflush(stderr);
  }
  /// What writes `limit`'s note ("... K more <what> suppressed") to the log.
  static auto note(const log_limit& limit) {
    return [&limit](std::uint64_t n) { log("%s", limit.note_text(n).c_str()); };
  }
  /// log() for a line of `limit`'s category (one per event a client can repeat at line rate):
  /// written while the category is within its rate, else counted, and the count logged as
  /// "... K more <what> suppressed" when the next window opens.
  template <class... A>
  static void log_limited(log_limit& limit, const char* format, A... args) {
    if (limit.allow(note(limit))) log(format, args...);
  }
  /// From a timer: logs the count of a window that is over (a flood that stopped).
  static void poll_log(log_limit& limit) { limit.poll(note(limit)); }
  /// At exit: logs what is suppressed and not yet told.
  static void flush_log(log_limit& limit) { limit.flush(note(limit)); }

 private:
  friend class client;

  void accept() {
    acceptor_.async_accept([this](const asio::error_code& ec, asio::ip::tcp::socket socket) {
      if (ec == asio::error::operation_aborted || !acceptor_.is_open()) return;
      if (ec) {
        // Out of descriptors (EMFILE) and the like: the connection stays in the backlog, so
        // accepting again at once would spin. Wait a little first.
        log("accept failed: %s; accepting again in 100 ms", ec.message().c_str());
        retry_.expires_after(std::chrono::milliseconds(100));
        retry_.async_wait([this](const asio::error_code& e) {
          if (!e && acceptor_.is_open()) accept();
        });
        return;
      }
      if (clients_.size() >= limits_.max_clients) {
        asio::error_code e;
        const auto peer = socket.remote_endpoint(e);
        log("refused %s: %zu clients already", e ? "?" : to_string(peer).c_str(), clients_.size());
        socket.close(e);
      } else {
        auto c = std::make_shared<client>(*this, std::move(socket), next_id_++);
        clients_.emplace(c->id(), c);
        log("client %llu %s connected (%zu connected)", static_cast<unsigned long long>(c->id()),
            c->peer().c_str(), clients_.size());
        c->start();
        if (on_connect_) on_connect_(*c);
      }
      accept();
    });
  }

  void closed(client& c, std::string_view why) {
    if (on_close_) on_close_(c, why);
    log("client %llu %s disconnected: %.*s; %llu lines sent, %llu dropped, %llu sentences in, "
        "%llu rejected",
        static_cast<unsigned long long>(c.id()), c.peer().c_str(), static_cast<int>(why.size()),
        why.data(), static_cast<unsigned long long>(c.lines_sent),
        static_cast<unsigned long long>(c.lines_dropped),
        static_cast<unsigned long long>(c.sentences_in),
        static_cast<unsigned long long>(c.rejected_in));
    clients_.erase(c.id());
  }

  asio::ip::tcp::acceptor acceptor_;
  asio::steady_timer retry_;
  server_limits limits_;
  std::map<std::uint64_t, std::shared_ptr<client>> clients_;
  std::uint64_t next_id_ = 1;
  sentence_handler on_sentence_;
  client_handler on_connect_;
  closed_handler on_close_;
  drop_handler on_drop_;
};

inline client::client(line_server& server, asio::ip::tcp::socket socket, std::uint64_t id)
    : server_(server), socket_(std::move(socket)), linger_(socket_.get_executor()), id_(id) {
  asio::error_code ec;
  const auto peer = socket_.remote_endpoint(ec);
  peer_ = ec ? std::string("?") : to_string(peer);
  if (!ec) address_ = peer.address();
  socket_.set_option(asio::ip::tcp::no_delay(true), ec);
  if (server_.limits_.send_buffer > 0)
    socket_.set_option(asio::socket_base::send_buffer_size(server_.limits_.send_buffer), ec);
}

inline void client::start() {
  reader_.report_drops(static_cast<bool>(server_.on_drop_));
  read();
}

template <class Item>
void client::deliver(const Item& item) {
  if (closed_) return;
  if (item.is_drop()) {
    if (server_.on_drop_) server_.on_drop_(*this, item.drop);
    return;
  }
  if (!item.is_sentence()) return;
  ++sentences_in;
  if (server_.on_sentence_) server_.on_sentence_(*this, item.sentence);
}

inline void client::read() {
  socket_.async_read_some(asio::buffer(in_),
                          [self = shared_from_this()](const asio::error_code& ec, std::size_t n) {
                            if (self->closed_) return;
                            if (ec) {
                              if (ec != asio::error::eof) {
                                self->close(ec.message());
                                return;
                              }
                              // The peer is done sending: what it sent last without a line ending
                              // still counts.
                              self->reader_.finish([&](const auto& item) { self->deliver(item); });
                              if (self->closed_) return;
                              self->read_ended_ = true;
                              if (self->queue_.empty()) {
                                self->close("end of stream");
                                return;
                              }
                              // What is queued has a while to leave; a peer that half-closed
                              // and does not read either is not kept for ever.
                              self->linger_.expires_after(std::chrono::seconds(10));
                              self->linger_.async_wait([self](const asio::error_code& e) {
                                if (!e) self->close("end of stream; queued lines not read in 10 s");
                              });
                              return;
                            }
                            self->bytes_in += n;
                            self->reader_.feed(std::string_view(self->in_.data(), n),
                                               [&](const auto& item) { self->deliver(item); });
                            // A sentence ended by a lone CR is held back to tell CR from CR LF: the
                            // read is over, so it is complete.
                            self->reader_.flush([&](const auto& item) { self->deliver(item); });
                            if (!self->closed_) self->read();
                          });
}

inline void client::send(const batch_ptr& b) {
  if (closed_ || read_ended_) return;  // a half-closed client gets what was queued, no more
  queue_.push_back(b);
  queued_lines_ += b->lines;
  // Drop the oldest batches that are not being written until the queue fits again.
  while (queued_lines_ > server_.limits_.max_queue_lines && queue_.size() > (writing_ ? 2U : 1U)) {
    auto victim = queue_.begin() + (writing_ ? 1 : 0);
    queued_lines_ -= (*victim)->lines;
    lines_dropped += (*victim)->lines;
    queue_.erase(victim);
  }
  if (lines_dropped > server_.limits_.max_drops) {
    close("not reading: " + std::to_string(lines_dropped) + " lines dropped");
    return;
  }
  if (!writing_) write();
}

inline void client::write() {
  if (closed_) return;
  if (queue_.empty()) {
    if (read_ended_) close("end of stream");
    return;
  }
  writing_ = true;
  const batch_ptr front = queue_.front();
  asio::async_write(socket_, asio::buffer(front->bytes),
                    [self = shared_from_this(), front](const asio::error_code& ec, std::size_t) {
                      self->writing_ = false;
                      if (self->closed_) return;
                      if (ec) {
                        self->close(ec.message());
                        return;
                      }
                      self->lines_sent += front->lines;
                      self->queued_lines_ -= front->lines;
                      self->queue_.pop_front();
                      self->write();
                    });
}

inline void client::close(std::string_view why) {
  if (closed_) return;
  closed_ = true;
  asio::error_code ignored;
  socket_.shutdown(asio::ip::tcp::socket::shutdown_both, ignored);
  socket_.close(ignored);
  linger_.cancel();
  queue_.clear();
  // Removed later, never inside the caller's loop or handler (see the top of this file).
  asio::post(socket_.get_executor(), [self = shared_from_this(), reason = std::string(why)] {
    self->server_.closed(*self, reason);
  });
}

/// "SIGINT" or "SIGTERM": how the servers name the signal that stops them.
inline const char* signal_name(int signo) { return signo == SIGINT ? "SIGINT" : "SIGTERM"; }

/// --listen's ADDR:PORT, or nullopt after saying "PROGRAM: --listen TEXT: expected ADDR:PORT".
inline std::optional<endpoint_text> listen_option(const char* program, const std::string& listen) {
  auto where = parse_endpoint(listen);
  if (!where)
    std::fprintf(stderr, "%s: --listen %s: expected ADDR:PORT\n", program, listen.c_str());
  return where;
}

/// What serve() runs: a server program built on line_server.
template <class S>
concept server_program = requires(S& s, int signo) {
  { s.local_endpoint() } -> std::convertible_to<asio::ip::tcp::endpoint>;
  s.start();
  s.signalled(signo);  ///< SIGINT or SIGTERM (each one, until the program has stopped)
  s.on_stopped = std::function<void()>();  ///< called once the program has stopped
};

/// The main of every server, once its options are read: `make(io, endpoint)` builds the program
/// (a std::unique_ptr to a server_program) listening on `where`; "listening on ADDR:PORT" is
/// the first line of the log; SIGINT and SIGTERM go to its signalled() until it calls
/// on_stopped; the event loop runs until nothing is left to do. The exit status: 0, 2 for an
/// address that is none (`listen` is the option's text, for the message), 1 when the address
/// cannot be listened on (or anything else fails).
template <class Make>
int serve(const char* program, const std::string& listen, const endpoint_text& where, Make make) {
  try {
    asio::io_context io;
    asio::error_code ec;
    const auto address = asio::ip::make_address(where.host, ec);
    if (ec) {
      std::fprintf(stderr, "%s: --listen %s: %s\n", program, listen.c_str(), ec.message().c_str());
      return 2;
    }
    const auto server = make(io, asio::ip::tcp::endpoint(address, where.port));
    static_assert(server_program<std::remove_reference_t<decltype(*server)>>);
    line_server::log("listening on %s", to_string(server->local_endpoint()).c_str());
    asio::signal_set signals(io, SIGINT, SIGTERM);
    std::function<void()> wait = [&] {
      signals.async_wait([&](const asio::error_code& e, int signo) {
        if (e) return;
        wait();  // a second signal may mean more (the Sandshark closes at once)
        server->signalled(signo);
      });
    };
    wait();
    server->on_stopped = [&] {
      asio::error_code ignored;
      signals.cancel(ignored);
    };
    server->start();
    io.run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", program, e.what());
    return 1;
  }
  return 0;
}

}  // namespace seawire::tools::net
