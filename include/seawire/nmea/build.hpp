// SPDX-License-Identifier: BSL-1.0
#pragma once
// nmea::builder: a message filled from doubles, one set<&M::member>(v) per field, then result().
// Each number or position is rounded to its declared nmea::precision, or to nmea::places{n} or
// nmea::shortest when the call says so, by seawire's one rule for doubles (decimal::from_double).
// A value that cannot be written (NaN, infinite, out of range, too many digits) is refused there:
// the member keeps what it had and result() reports the first refusal with its field number, as
// encode() would have. Members of other types are assigned directly.

#include <cstddef>
#include <optional>
#include <type_traits>

#include "seawire/error.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/variation.hpp"

namespace seawire::nmea {

/// Round to this many fraction digits instead of the field's declared precision.
struct places {
  unsigned n = 0;
};
/// The fewest fraction digits that read back as the same double (decimal::shortest).
struct shortest_t {
  explicit constexpr shortest_t() = default;
};
inline constexpr shortest_t shortest{};

namespace detail {

/// The wire field number (1-based, in the message's longest form) where descriptor I starts.
template <message_like T, std::size_t I>
[[nodiscard]] consteval std::uint16_t wire_field_of() noexcept {
  unsigned n = 1;
  std::size_t index = 0;
  T::nmea.fields.apply([&](const auto&... d) { ((index++ < I ? (n += d.width()) : 0), ...); });
  return static_cast<std::uint16_t>(n);
}

/// The value of type V for v at `p` places (p < 0: shortest).
template <class V>
[[nodiscard]] constexpr result<V> from_double(double v, int p) noexcept {
  if constexpr (std::is_same_v<V, decimal>) {
    if (p < 0) return decimal::shortest(v);
    return decimal::from_double(v, static_cast<unsigned>(p));
  } else {
    if (p < 0) {
      if constexpr (std::is_same_v<V, latitude> || std::is_same_v<V, longitude>) {
        // The fewest minute digits whose position reads back as the same double.
        for (unsigned m = 1; m < 12; ++m) {
          const result<V> c = V::from_degrees(v, m);
          if (!c || c.value.degrees() == v) return c;
        }
        return V::from_degrees(v, 12);
      } else {
        // Decimal degrees: the digits of the shortest decimal of the value.
        const result<decimal> d = decimal::shortest(v);
        if (!d) return result<V>{{}, d.ec};
        p = d.value.places;
      }
    }
    return V::from_degrees(v, static_cast<unsigned>(p));
  }
}

}  // namespace detail

/// Fills a message of type T from doubles, keeping the first value it had to refuse.
template <message_like T>
class builder {
 public:
  constexpr builder() noexcept = default;
  /// Start from a message (the other members as they are there).
  constexpr explicit builder(const T& start) noexcept : msg_(start) {}

  /// Member M (a number or position field of T) from `v`, rounded to the field's declared
  /// precision.
  template <auto M>
  constexpr builder& set(double v) noexcept {
    return set_places<M>(v, precision_of<M>());
  }
  /// ... rounded to `p.n` fraction digits (minute digits for a DDMM.m position).
  template <auto M>
  constexpr builder& set(double v, places p) noexcept {
    return set_places<M>(v, p.n > 19 ? 20 : static_cast<int>(p.n));
  }
  /// ... with the fewest digits that read back as the same double.
  template <auto M>
  constexpr builder& set(double v, shortest_t) noexcept {
    return set_places<M>(v, -1);
  }
  /// Member M (optional) left blank.
  template <auto M>
  constexpr builder& clear() noexcept {
    msg_.*M = std::nullopt;
    return *this;
  }

  /// The message, or the first value refused: its errc, and the wire field number
  /// (field_name<T>(r.field) names it).
  [[nodiscard]] constexpr seawire::result<T> result() const noexcept {
    seawire::result<T> r;
    r.value = msg_;
    r.ec = ec_;
    r.field = field_;
    return r;
  }
  /// The message so far, with every value that was accepted.
  [[nodiscard]] constexpr const T& message() const noexcept { return msg_; }
  [[nodiscard]] constexpr explicit operator bool() const noexcept { return ec_ == errc::ok; }

 private:
  template <auto M>
  constexpr builder& set_places(double v, int p) noexcept {
    constexpr std::size_t i = detail::field_index_of<T, M>();
    static_assert(i < T::nmea.fields.size, "builder::set: the member is not a field of T");
    constexpr const auto& desc = field_at<i>(T::nmea.fields);
    using D = std::remove_cvref_t<decltype(desc)>;
    using V = typename D::value_type;
    static_assert(detail::fills_from_double<V>,
                  "builder::set takes a double for numbers, positions and magnetic variation; "
                  "assign other members directly");
    seawire::result<V> r = detail::from_double<V>(v, p);
    if (r) r.ec = codec<V>::check(r.value);
    if (r) r.ec = detail::check_options(r.value, desc.opts);
    if (!r) {
      if (ec_ == errc::ok) {
        ec_ = r.ec;
        field_ = detail::wire_field_of<T, i>();
      }
      return *this;
    }
    msg_.*M = r.value;
    return *this;
  }

  T msg_{};
  errc ec_ = errc::ok;
  std::uint16_t field_ = 0;
};

}  // namespace seawire::nmea
