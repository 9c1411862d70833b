// SPDX-License-Identifier: BSL-1.0
#pragma once
// Buffered stdin/stdout for the command-line programs: read() in 64 KiB chunks, one large output
// buffer written with fwrite(). No iostreams, no per-line system calls.

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace seawire::tools {

inline constexpr std::size_t read_chunk = 64 * 1024;

/// Reads a file descriptor in chunks of up to read_chunk bytes. Empty view at end of input.
class chunk_reader {
 public:
  explicit chunk_reader(int fd = 0) : fd_(fd), buf_(read_chunk) {}

  /// The next chunk, empty at end of input. Sets failed() on a read error.
  std::string_view next() {
    for (;;) {
      const ssize_t n = ::read(fd_, buf_.data(), buf_.size());
      if (n > 0) return {buf_.data(), static_cast<std::size_t>(n)};
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        failed_ = true;
        error_ = errno;
      }
      return {};
    }
  }
  [[nodiscard]] bool failed() const { return failed_; }
  /// The errno of the failed read (0 if none).
  [[nodiscard]] int error() const { return error_; }

  /// Whether input (or its end) arrives within `ms` milliseconds; true too when the descriptor
  /// cannot be polled, so the caller just reads on.
  [[nodiscard]] bool ready_within(int ms) const {
    pollfd p{fd_, POLLIN, 0};
    for (;;) {
      const int n = ::poll(&p, 1, ms);
      if (n < 0 && errno == EINTR) continue;
      return n != 0;
    }
  }

 private:
  int fd_;
  std::vector<char> buf_;
  bool failed_ = false;
  int error_ = 0;
};

/// Calls f(line) for each line of `in` to its end, without its '\n' (a CR before it is kept), a
/// line cut by a chunk boundary joined first; the last line too if it has no '\n' (and is not
/// empty).
template <class F>
void for_each_line(chunk_reader& in, F&& f) {
  std::string carry;  // a line cut by the chunk boundary
  for (std::string_view chunk = in.next(); !chunk.empty(); chunk = in.next()) {
    while (!chunk.empty()) {
      const void* nl = std::memchr(chunk.data(), '\n', chunk.size());
      if (nl == nullptr) {
        carry.append(chunk);
        break;
      }
      const auto n = static_cast<std::size_t>(static_cast<const char*>(nl) - chunk.data());
      if (carry.empty()) {
        f(chunk.substr(0, n));
      } else {
        carry.append(chunk.substr(0, n));
        f(std::string_view(carry));
        carry.clear();
      }
      chunk.remove_prefix(n + 1);
    }
  }
  if (!carry.empty()) f(std::string_view(carry));
}

/// The longest line for_each_bounded_line hands over (without its '\n'), a documented bound of
/// seawire-encode: a JSON Lines object of any message is a few hundred bytes.
inline constexpr std::size_t max_line = 64 * 1024;

/// Like for_each_line, with memory bounded: a line longer than `max` bytes (without its '\n') is
/// not kept but skipped to its end, and too_long(length) is called in its place (length: its
/// bytes, counted, however many they are); the lines after it are read as usual.
template <class F, class G>
void for_each_bounded_line(chunk_reader& in, std::size_t max, F&& f, G&& too_long) {
  std::string carry;          // a line cut by the chunk boundary, at most `max` bytes
  std::uint64_t skipped = 0;  // bytes of the over-long line being skipped
  bool skipping = false;
  for (std::string_view chunk = in.next(); !chunk.empty(); chunk = in.next()) {
    while (!chunk.empty()) {
      const void* nl = std::memchr(chunk.data(), '\n', chunk.size());
      const std::size_t n =
          nl == nullptr ? chunk.size()
                        : static_cast<std::size_t>(static_cast<const char*>(nl) - chunk.data());
      if (!skipping && carry.size() + n > max) {
        skipping = true;
        skipped = carry.size();
        carry.clear();
      }
      if (skipping) {
        skipped += n;
      } else if (nl != nullptr && carry.empty()) {
        f(chunk.substr(0, n));
      } else {
        carry.append(chunk.substr(0, n));
        if (nl != nullptr) f(std::string_view(carry));
      }
      if (nl == nullptr) break;
      if (skipping) too_long(skipped);
      skipping = false;
      carry.clear();
      chunk.remove_prefix(n + 1);
    }
  }
  if (skipping) {
    too_long(skipped);
  } else if (!carry.empty()) {
    f(std::string_view(carry));
  }
}

/// `s` made safe for a terminal: control bytes (NUL included) and DEL as \xNN, the rest as is.
inline std::string printable(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7F) {
      out += "\\x";
      out += "0123456789abcdef"[u >> 4];
      out += "0123456789abcdef"[u & 15];
    } else {
      out += c;
    }
  }
  return out;
}

/// At most `n` bytes of `s` made printable, "..." after them when `s` is longer: what a message
/// quotes of a value, however long the value.
inline std::string quote_prefix(std::string_view s, std::size_t n = 64) {
  if (s.size() <= n) return printable(s);
  return printable(s.substr(0, n)) + "...";
}

/// A large output buffer in front of a FILE*. put() never fails; flush() reports write errors.
/// It keeps where the next byte goes and where the buffer ends as pointers, and each put reads
/// them once: a short piece costs a comparison and its copy.
class output {
 public:
  explicit output(std::FILE* f, std::size_t capacity = 1 << 20)
      : f_(f), buf_(capacity), at_(buf_.data()), end_(buf_.data() + buf_.size()) {}
  output(const output&) = delete;
  output& operator=(const output&) = delete;
  ~output() { flush(); }

  [[gnu::always_inline]] void put(char c) {
    char* const at = at_;
    if (at == end_) [[unlikely]] {
      put_long(std::string_view(&c, 1));
      return;
    }
    *at = c;
    at_ = at + 1;
  }
  // Inline for the short pieces JSON is made of (at most 32 bytes, while 32 are free; memcpy of
  // them measured as fast as a hand-made copy); the rest, and every piece near the end of the
  // buffer, goes out of line.
  [[gnu::always_inline]] void put(std::string_view s) {
    char* const at = at_;
    if (s.size() <= 32 && end_ - at >= 32) [[likely]] {
      std::memcpy(at, s.data(), s.size());
      at_ = at + s.size();
      return;
    }
    put_long(s);
  }
  /// Where `n` more bytes may be written (flushed first if need be; nullptr past the capacity),
  /// and commit(k) to keep k of them: the JSON and CSV writers write numbers there in place.
  [[gnu::always_inline]] char* room(std::size_t n) {
    if (static_cast<std::size_t>(end_ - at_) < n) [[unlikely]] {
      flush();
      if (buf_.size() < n) return nullptr;
    }
    return at_;
  }
  [[gnu::always_inline]] void commit(std::size_t k) { at_ += k; }
  void flush() {
    if (at_ != buf_.data()) write(buf_.data(), static_cast<std::size_t>(at_ - buf_.data()));
    at_ = buf_.data();
    if (std::fflush(f_) != 0) fail();
  }
  [[nodiscard]] bool failed() const { return failed_; }
  /// The errno of the first failed write (0 if none).
  [[nodiscard]] int error() const { return error_; }

 private:
  [[gnu::noinline]] void put_long(std::string_view s) {
    if (s.empty()) return;
    if (s.size() > static_cast<std::size_t>(end_ - at_)) {
      flush();
      if (s.size() > buf_.size()) {
        write(s.data(), s.size());
        return;
      }
    }
    std::memcpy(at_, s.data(), s.size());
    at_ += s.size();
  }
  void write(const char* p, std::size_t n) {
    if (!failed_ && std::fwrite(p, 1, n, f_) != n) fail();
  }
  void fail() {
    if (!failed_) error_ = errno;
    failed_ = true;
  }

  std::FILE* f_;
  std::vector<char> buf_;
  char* at_;   // where the next byte goes
  char* end_;  // the end of buf_
  bool failed_ = false;
  int error_ = 0;
};

}  // namespace seawire::tools
