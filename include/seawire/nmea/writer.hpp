// SPDX-License-Identifier: BSL-1.0
#pragma once
// Fixed-capacity sentence output. Writes '$' (or '!'), the address and fields, then seals the
// sentence with '*', two upper-case hex digits and CR LF. Never allocates; running out of room is
// an error the caller sees, never a truncated sentence.

#include <cassert>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "seawire/detail/ascii.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/checksum.hpp"

namespace seawire::nmea {

/// Whether `a` can be written as a sentence's address: 1 to 15 upper-case letters and digits,
/// the first a letter ("GPRMC", "PYDEV", "AIVDM").
[[nodiscard]] constexpr bool is_address(std::string_view a) noexcept {
  if (a.empty() || a.size() > 15 || !seawire::detail::is_upper(a[0])) return false;
  for (const char c : a)
    if (!seawire::detail::is_upper(c) && !seawire::detail::is_digit(c)) return false;
  return true;
}

/// Whether `f` can be written as one field: printable ASCII without the characters NMEA 0183
/// reserves for framing ($ , * ! \ ^ ~).
[[nodiscard]] constexpr bool is_field_text(std::string_view f) noexcept {
  for (const char c : f)
    if (!seawire::detail::is_printable(c) || seawire::detail::is_reserved(c)) return false;
  return true;
}

namespace detail {

/// The sentence writer, checked or not. `writer` (below) is the checked one, the only one a
/// caller makes: it refuses, once at seal(), a sentence that did not fit. The unchecked one
/// (Checked = false) is encode's own: it writes without looking at the room left, into a buffer
/// that encode knows holds the longest sentence the message's codecs can write (longest_sentence
/// in message.hpp, from each codec's max_chars), so that a sentence costs one room check instead
/// of one a character or number.
template <bool Checked>
class basic_writer {
 public:
  constexpr explicit basic_writer(std::span<char> out) noexcept : out_(out) {}

  /// Start a sentence: the start character and the address. `start` is '$' but to write an
  /// encapsulation sentence back ('!', sentence_view::start).
  constexpr void begin(std::string_view address, char start = '$') noexcept {
    size_ = 0;
    failed_ = false;
    put(start);
    put(address);
  }
  /// Start the next field (writes the separating comma).
  constexpr void next_field() noexcept { put(','); }

  constexpr void put(char c) noexcept {
    if (!has_room(1)) return;
    out_[size_++] = c;
  }
  constexpr void put(std::string_view s) noexcept {
    if (!has_room(s.size())) return;
    for (char c : s) out_[size_++] = c;
  }
  /// Unsigned integer, zero-padded to at least `min_digits` digits (at most 20 are written).
  constexpr void put_uint(std::uint64_t v, unsigned min_digits = 1) noexcept {
    // The parts of times and dates: one digit pair, no division. Written here rather than through
    // append_uint (one room check for the widest number, then append_uint): that made put_uint
    // too large to inline, and encode_to cost 16-35% more instructions; forced inline, up to 5%.
    if (min_digits == 2 && v < 100) {
      if (!has_room(2)) return;
      seawire::detail::copy_pair(out_.data() + size_, static_cast<std::size_t>(v) * 2);
      size_ += 2;
      return;
    }
    put_fixed(v, 0, min_digits);
  }
  /// Three numbers of two digits each, one after the other ("hhmmss", "ddmmyy") with one room
  /// check. A number of 100 or more is written whole, as put_uint(v, 2) writes it.
  constexpr void put_pairs(std::uint64_t a, std::uint64_t b, std::uint64_t c) noexcept {
    if (a < 100 && b < 100 && c < 100) [[likely]] {
      if (!has_room(6)) return;
      char* const p = out_.data() + size_;
      seawire::detail::copy_pair(p, static_cast<std::size_t>(a) * 2);
      seawire::detail::copy_pair(p + 2, static_cast<std::size_t>(b) * 2);
      seawire::detail::copy_pair(p + 4, static_cast<std::size_t>(c) * 2);
      size_ += 6;
      return;
    }
    put_uint(a, 2);
    put_uint(b, 2);
    put_uint(c, 2);
  }
  /// The fixed-point number scaled / 10^places, e.g. "4.50" from 450 and 2: all `places` fraction
  /// digits, and the integer part zero-padded to at least `min_int_digits` digits (at most 20).
  /// Nothing is written, and the writer fails, if it does not all fit.
  constexpr void put_fixed(std::uint64_t scaled, unsigned places,
                           unsigned min_int_digits = 1) noexcept {
    const unsigned int_digits = seawire::detail::integer_digits(
        scaled, places, min_int_digits, seawire::detail::max_integer_digits);
    if (!has_room(seawire::detail::fixed_size(places, int_digits))) return;
    size_ = seawire::detail::append_fixed(out_.data(), size_, scaled, places, int_digits);
  }

  /// Finish: '*', checksum, CR LF. Returns the sentence length or buffer_too_small.
  constexpr result<std::size_t> seal() noexcept {
    const std::uint8_t x =
        failed_ || size_ == 0 ? 0 : checksum(std::string_view(out_.data() + 1, size_ - 1));
    // "*hh\r\n" after one check of the room left.
    if (has_room(5)) {
      char* const p = out_.data() + size_;
      p[0] = '*';
      p[1] = seawire::detail::hex_digit_upper(x >> 4u);
      p[2] = seawire::detail::hex_digit_upper(x);
      p[3] = '\r';
      p[4] = '\n';
      size_ += 5;
    }
    result<std::size_t> r;
    if (failed_) {
      r.ec = errc::buffer_too_small;
    } else {
      r.value = size_;
    }
    return r;
  }

  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
  [[nodiscard]] constexpr bool failed() const noexcept { return failed_; }
  [[nodiscard]] constexpr std::string_view view() const noexcept { return {out_.data(), size_}; }

 private:
  /// Whether `n` more bytes fit; when they do not, the writer has failed. The unchecked writer
  /// is only given a buffer its codecs cannot overrun (max_chars): there a build with assertions
  /// says which write broke that promise, and one without does not look.
  constexpr bool has_room(std::size_t n) noexcept {
    if constexpr (Checked) {
      if (n > out_.size() - size_) {
        failed_ = true;
        return false;
      }
    } else {
      assert(n <= out_.size() - size_ && "a codec wrote more than its max_chars said");
    }
    return true;
  }

  std::span<char> out_;
  std::size_t size_ = 0;
  bool failed_ = false;
};

}  // namespace detail

/// Writes one sentence into a caller's buffer: begin(), next_field() and put() per field,
/// seal(). Checks nothing of what it is given (is_address, is_field_text say what is valid), but
/// the room: what does not fit is not written, and seal() says buffer_too_small.
///
/// A codec's write() takes it as a template parameter (`template <sentence_writer W> static
/// constexpr void write(W& w, const T& v)`), so that encode can also hand it its unchecked
/// writer; such a
/// codec's `max_chars` must bound what it writes for every value its check() accepts (encode
/// trusts it for the room). A codec whose write() takes `writer&` is always given this one.
using writer = detail::basic_writer<true>;

/// The writers a codec's write() may be given: `writer`, and encode's unchecked one.
template <class W>
concept sentence_writer =
    std::same_as<W, detail::basic_writer<true>> || std::same_as<W, detail::basic_writer<false>>;

/// A sentence held by value: what encode() returns. encode() picks N per message: 256 bytes, or
/// the longest sentence the message can have when that is more (BFMIS with its three texts;
/// CPIMU, CPNVG, CPNVR, VBW and GGA with every number at its widest), so that whatever decodes
/// also encodes. NMEA 0183's own limit is 82.
template <std::size_t N = 256>
struct sentence_buffer {
  char data[N]{};
  std::size_t size = 0;
  errc ec = errc::ok;
  std::uint16_t field = 0;  ///< field number whose value was refused, when ec != ok

  [[nodiscard]] constexpr std::string_view view() const noexcept { return {data, size}; }
  [[nodiscard]] constexpr explicit operator bool() const noexcept { return ec == errc::ok; }
};

}  // namespace seawire::nmea
