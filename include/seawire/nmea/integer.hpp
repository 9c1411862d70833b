// SPDX-License-Identifier: BSL-1.0
#pragma once
// Whole-number fields (a satellite count, an engine number) and their codec. A member is an
// nmea::integer<T>, not a plain T, which would take 7.9 as 7 and 300 as 44 without a word:
// integer<T> takes any integer implicitly and keeps it whole, refuses a floating-point value at
// compile time, converts to T only explicitly, and is checked against T's range on encode
// (out_of_range, naming the field). Decoded values are always within T's range.

#include <compare>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include "seawire/detail/inline.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/codec.hpp"
#include "seawire/nmea/decimal.hpp"

namespace seawire::nmea {

/// A whole-number field of type T (an integer type of at most 32 bits).
template <class T>
class integer {
  static_assert(whole_number<T> && sizeof(T) <= 4,
                "nmea::integer<T>: T is an integer type of at most 32 bits");

 public:
  using value_type = T;
  static constexpr std::int64_t min = std::numeric_limits<T>::min();
  static constexpr std::int64_t max = std::numeric_limits<T>::max();

  constexpr integer() noexcept = default;
  /// Any integer, kept whole; one outside T's range is refused when the message is encoded.
  /// (Not bool or a character type: `= '7'` would be 55.) An unsigned value beyond the 64-bit
  /// signed range (only a std::uint64_t can hold one) is kept as INT64_MAX: still outside T, so
  /// still refused.
  template <whole_number I>
  constexpr integer(I v) noexcept  // NOLINT: implicit
      : v_(std::cmp_greater(v, std::numeric_limits<std::int64_t>::max())
               ? std::numeric_limits<std::int64_t>::max()
               : static_cast<std::int64_t>(v)) {}
  /// A floating-point value would be cut to a whole number without a word: round it as the code
  /// means it (std::lround) and assign the integer.
  template <std::floating_point F>
  integer(F) = delete;

  /// The value as assigned or decoded.
  [[nodiscard]] constexpr std::int64_t value() const noexcept { return v_; }
  /// Whether the value is one of T's (always, for a decoded value).
  [[nodiscard]] constexpr bool fits() const noexcept { return v_ >= min && v_ <= max; }
  /// The value as T: exact whenever fits(), wrapped otherwise, so only on request.
  constexpr explicit operator T() const noexcept { return static_cast<T>(v_); }

  [[nodiscard]] friend constexpr bool operator==(const integer&, const integer&) noexcept = default;
  [[nodiscard]] friend constexpr std::strong_ordering operator<=>(
      const integer&, const integer&) noexcept = default;
  // Against a plain integer, compared as numbers (not through T, which could wrap).
  template <whole_number I>
  [[nodiscard]] friend constexpr bool operator==(const integer& a, I b) noexcept {
    return std::cmp_equal(a.v_, b);
  }
  template <whole_number I>
  [[nodiscard]] friend constexpr std::strong_ordering operator<=>(const integer& a, I b) noexcept {
    return std::cmp_less(a.v_, b)    ? std::strong_ordering::less
           : std::cmp_equal(a.v_, b) ? std::strong_ordering::equal
                                     : std::strong_ordering::greater;
  }

 private:
  std::int64_t v_ = 0;
};

template <class V>
inline constexpr bool is_integer_wrapper = false;
template <class T>
inline constexpr bool is_integer_wrapper<integer<T>> = true;

template <class T>
struct codec<integer<T>> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = codec<T>::max_chars;
  static constexpr bool allows_blank = false;
  static constexpr bool scan_refuses_blank = codec<T>::scan_refuses_blank;
  static constexpr errc read(field_reader& r, integer<T>& v) noexcept {
    T t{};
    const errc e = codec<T>::read(r, t);
    if (e == errc::ok) v = t;
    return e;
  }
  /// The one-pass reader (as codec<T>::scan).
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan(const char* p, const char* end,
                                                          integer<T>& v) noexcept {
    T t{};
    p = codec<T>::scan(p, end, t);
    if (p != nullptr) v = t;
    return p;
  }
  static constexpr errc check(const integer<T>& v) noexcept {
    return v.fits() ? errc::ok : errc::out_of_range;
  }
  template <sentence_writer W>
  static constexpr void write(W& w, const integer<T>& v) noexcept {
    codec<T>::write(w, static_cast<T>(v));
  }
};

}  // namespace seawire::nmea
