// SPDX-License-Identifier: BSL-1.0
#pragma once
// Fixed-capacity sentence output. Writes '$', the address and fields, then seals the sentence
// with '*', two upper-case hex digits and CR LF. Never allocates; running out of room is an
// error the caller sees, never a truncated sentence.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "seawire/detail/ascii.hpp"
#include "seawire/error.hpp"

namespace seawire::nmea {

class writer {
 public:
  constexpr explicit writer(std::span<char> out) noexcept : out_(out) {}

  /// Start a sentence: '$' and the address.
  constexpr void begin(std::string_view address) noexcept {
    size_ = 0;
    failed_ = false;
    put('$');
    put(address);
  }
  /// Start the next field (writes the separating comma).
  constexpr void next_field() noexcept { put(','); }

  constexpr void put(char c) noexcept {
    if (size_ < out_.size()) {
      out_[size_++] = c;
    } else {
      failed_ = true;
    }
  }
  constexpr void put(std::string_view s) noexcept {
    if (s.size() > out_.size() - size_) {
      failed_ = true;
      return;
    }
    for (char c : s) out_[size_++] = c;
  }
  /// Unsigned integer, zero-padded to at least `min_digits` digits.
  constexpr void put_uint(std::uint64_t v, unsigned min_digits = 1) noexcept {
    char tmp[20];
    unsigned n = 0;
    do {
      tmp[n++] = static_cast<char>('0' + v % 10);
      v /= 10;
    } while (v != 0);
    while (n < min_digits && n < sizeof tmp) tmp[n++] = '0';
    if (n > out_.size() - size_) {
      failed_ = true;
      return;
    }
    while (n > 0) out_[size_++] = tmp[--n];
  }

  /// Finish: '*', checksum, CR LF. Returns the sentence length or buffer_too_small.
  constexpr result<std::size_t> seal() noexcept {
    std::uint8_t x = 0;
    for (std::size_t i = 1; i < size_ && !failed_; ++i)
      x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(out_[i]));
    put('*');
    put(seawire::detail::hex_digit_upper(x >> 4u));
    put(seawire::detail::hex_digit_upper(x));
    put('\r');
    put('\n');
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
  std::span<char> out_;
  std::size_t size_ = 0;
  bool failed_ = false;
};

/// A sentence held by value: what encode() returns. 256 bytes holds every sentence seawire
/// defines (NMEA 0183's own limit is 82) but one: BFMIS, whose three texts take up to 456 bytes,
/// is encoded into 512 (its max_sentence_size).
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
