// SPDX-License-Identifier: BSL-1.0
#pragma once
// Text fields held inline (nmea::text<N>, nmea::talker_id) and their codec: printable ASCII
// without the characters NMEA reserves.

#include <cstddef>
#include <cstring>
#include <string_view>
#include <type_traits>

#include "seawire/detail/ascii.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/codec.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"

namespace seawire::nmea {

/// Text held inline, at most N bytes: no allocation, no view into the input that could dangle.
template <std::size_t N>
class text {
 public:
  static_assert(N > 0 && N <= 0xFFFF);
  static constexpr std::size_t capacity = N;

  constexpr text() noexcept = default;
  /// From a literal that fits (checked at compile time).
  template <std::size_t M>
  // NOLINTNEXTLINE(google-explicit-constructor): text<5> team = "AUVSI";
  constexpr text(const char (&s)[M]) noexcept {
    static_assert(M - 1 <= N, "literal longer than the text's capacity");
    for (std::size_t i = 0; i + 1 < M; ++i) data_[i] = s[i];
    size_ = static_cast<std::uint16_t>(M - 1);
  }
  /// Replace the content; false (and unchanged) when `s` does not fit.
  constexpr bool assign(std::string_view s) noexcept {
    if (s.size() > N) return false;
    if (std::is_constant_evaluated()) {
      for (std::size_t i = 0; i < s.size(); ++i) data_[i] = s[i];
    } else if (!s.empty()) {
      // One copy of the counted bytes. (A byte loop here, in a caller GCC 12 -O3 compiles on
      // its own, is unrolled into stores past data_ on a path the test above rules out, and
      // warned of: -Wstringop-overflow.)
      std::memcpy(data_, s.data(), s.size());
    }
    size_ = static_cast<std::uint16_t>(s.size());
    return true;
  }
  [[nodiscard]] constexpr std::string_view view() const noexcept { return {data_, size_}; }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0; }

  friend constexpr bool operator==(const text& a, const text& b) noexcept {
    return a.view() == b.view();
  }
  friend constexpr bool operator==(const text& a, std::string_view b) noexcept {
    return a.view() == b;
  }
  template <std::size_t M>
  friend constexpr bool operator==(const text& a, const char (&b)[M]) noexcept {
    return a.view() == std::string_view(b, M - 1);
  }

 private:
  char data_[N]{};
  std::uint16_t size_ = 0;
};

/// Two-character talker of a standard sentence ("GP", "GN", "II").
using talker_id = text<2>;

template <std::size_t N>
struct codec<text<N>> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = N;
  static constexpr bool allows_blank = true;  // blank text is empty text
  static constexpr errc read(field_reader& r, text<N>& v) noexcept {
    const std::string_view s = r.take().text;
    if (r.policy().strict_values) {
      const errc e = check_chars(s);
      if (e != errc::ok) return e;
    }
    return v.assign(s) ? errc::ok : errc::text_too_long;
  }
  /// The one-pass reader: the text at `p` up to the next ',' or `end`. nullptr for a byte no
  /// policy takes in text (a character NMEA reserves, or no printable one), and past N bytes.
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan(const char* p, const char* end,
                                                          text<N>& v) noexcept {
    const char* q = p;
    for (; q != end && *q != ','; ++q)
      if (!seawire::detail::is_printable(*q) || seawire::detail::is_reserved(*q)) [[unlikely]]
        return nullptr;
    return v.assign(std::string_view(p, static_cast<std::size_t>(q - p))) ? q : nullptr;
  }
  static constexpr errc check(const text<N>& v) noexcept { return check_chars(v.view()); }
  static constexpr errc check_chars(std::string_view s) noexcept {
    for (char c : s)
      if (!seawire::detail::is_printable(c) || seawire::detail::is_reserved(c))
        return errc::bad_text;
    return errc::ok;
  }
  template <sentence_writer W>
  static constexpr void write(W& w, const text<N>& v) noexcept {
    w.put(v.view());
  }
};

}  // namespace seawire::nmea
