// SPDX-License-Identifier: BSL-1.0
#pragma once
// NMEA 2000 field values (number, lookup, flags, day_count, time_since_midnight) and the PGN
// table they are declared in (describe_pgn). A payload is one little-endian bit string: a field
// at bit offset o starts at bit o % 8 of byte o / 8, least significant byte first, signed fields
// two's complement. Values are kept raw, so decode -> encode is bit for bit; the top raw values
// of a field are sentinels (not available, out of range, reserved), reserved bits are sent as
// ones. The full rules, sentinel counts by width and kind: docs/nmea2000.md.

#include <array>
#include <chrono>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

#include "seawire/detail/algorithm.hpp"
#include "seawire/detail/ascii.hpp"
#include "seawire/detail/bit_layout.hpp"
#include "seawire/detail/enum_names.hpp"
#include "seawire/detail/member.hpp"
#include "seawire/detail/rounding.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/decimal.hpp"
#include "seawire/nmea2000/fast_packet.hpp"

namespace seawire::nmea2000 {

/// What a field's raw value means.
enum class field_state : std::uint8_t {
  value,          ///< an ordinary value
  not_available,  ///< the sender has no data for this field
  out_of_range,   ///< the sender's value did not fit the field, or its sensor reports an error
  reserved,       ///< a raw value the standard keeps for future use
};

// A template of nothing, so that only a caller reads the enumerators' names (at compile time).
template <int = 0>
[[nodiscard]] constexpr std::string_view name(field_state s) noexcept {
  return seawire::detail::enumerator_name_of<4>(s);
}

/// The size of one raw step: physical value = raw x mantissa x 10^exponent (0.25 rpm = 25e-2,
/// 0.004 % = 4e-3, 100 Pa = 1e2), so values convert to and from decimal text exactly.
struct resolution {
  std::int64_t mantissa = 1;
  int exponent = 0;

  [[nodiscard]] constexpr bool operator==(const resolution&) const noexcept = default;
  /// Fraction digits of a value at this resolution: 2 for 0.25, 3 for 0.004, 0 for 100.
  [[nodiscard]] constexpr unsigned places() const noexcept {
    return exponent < 0 ? static_cast<unsigned>(-exponent) : 0U;
  }
};

namespace detail {

/// How many of a number's top raw values are sentinels (docs/nmea2000.md).
[[nodiscard]] constexpr unsigned sentinel_count(unsigned bits) noexcept {
  return bits >= 8 ? 3U : bits >= 4 ? 2U : bits >= 2 ? 1U : 0U;
}

/// How many of a lookup's top raw values are sentinels (docs/nmea2000.md).
[[nodiscard]] constexpr unsigned lookup_sentinel_count(unsigned bits) noexcept {
  return bits > 2 ? 3U : bits == 2 ? 2U : 0U;
}

/// The state of raw value `raw` of a field whose top `sentinels` values (at most 3) are
/// sentinels, `top` being the largest raw value.
[[nodiscard]] constexpr field_state state_of(std::int64_t raw, std::int64_t top,
                                             unsigned sentinels) noexcept {
  if (raw <= top - sentinels) return field_state::value;
  if (raw == top) return field_state::not_available;
  if (raw == top - 1) return field_state::out_of_range;
  return field_state::reserved;
}

/// The raw value as a decimal at resolution R: raw 3194 at 0.25 is 798.50.
template <resolution R>
[[nodiscard]] constexpr nmea::decimal scaled_decimal(std::int64_t raw) noexcept {
  nmea::decimal d;
  const std::uint64_t mag = seawire::detail::magnitude(raw);
  std::uint64_t m = mag * static_cast<std::uint64_t>(R.mantissa);
  if constexpr (R.exponent > 0) m *= seawire::detail::pow10_table[R.exponent];
  d.mantissa = m;
  d.places = static_cast<std::uint8_t>(R.places());
  d.negative = raw < 0;
  return d;
}

/// `magnitude`, negated when `negative`, as an int64_t (2^63 negated is the most negative one);
/// false when it does not fit.
[[nodiscard]] constexpr bool signed_raw(std::uint64_t magnitude, bool negative,
                                        std::int64_t& out) noexcept {
  constexpr auto max = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
  if (magnitude > max + (negative ? 1 : 0)) return false;
  out = negative ? static_cast<std::int64_t>(~magnitude + 1) : static_cast<std::int64_t>(magnitude);
  return true;
}

/// The raw value nearest m x 10^t at resolution R, negated when `negative`, halves away from
/// zero; false beyond 64 bits (the caller's range check refuses it).
template <resolution R>
[[nodiscard]] constexpr bool raw_from_scaled(std::uint64_t m, int t, bool negative,
                                             std::int64_t& out) noexcept {
  // raw = m x 10^(t - exponent) / mantissa
  std::uint64_t q = 0;
  return seawire::detail::round_scaled(m, t - R.exponent, static_cast<std::uint64_t>(R.mantissa),
                                       q) &&
         signed_raw(q, negative, out);
}

}  // namespace detail

/// An integer field of `Bits` bits, `Signed` or not, at resolution `Res` (1 by default); "not
/// available" by default. Built with from() (a physical value) or from_raw(), never from a plain
/// number (3 m/s is not raw 3 = 0.03 m/s). `Sentinels` top raw values are sentinels, by default
/// as many as the width has (docs/nmea2000.md); 0 for a field every raw value of which is a
/// value (unsigned_no_sentinel).
template <unsigned Bits, bool Signed, resolution Res = resolution{},
          unsigned Sentinels = detail::sentinel_count(Bits)>
class number {
  // Raw values are kept in an int64_t: every signed width up to 64 bits and every unsigned width
  // up to 63 bits fits exactly. An unsigned 64-bit field does not, and does not compile.
  static_assert(Bits >= 1 && Bits <= 64 && (!Signed || Bits >= 2), "field width 1..64 bits");
  static_assert(Signed || Bits <= 63,
                "an unsigned 64-bit field's raw values do not fit the int64_t a number keeps");
  static_assert(Res.mantissa > 0, "resolution must be positive");
  static_assert(Sentinels <= detail::sentinel_count(Bits), "more sentinels than the width has");

 public:
  static constexpr unsigned bits = Bits;
  static constexpr bool is_signed = Signed;
  static constexpr resolution res = Res;
  static constexpr unsigned sentinels = Sentinels;
  /// All ones (unsigned) or the largest positive value (signed): "not available".
  static constexpr std::int64_t top_raw = static_cast<std::int64_t>(
      Signed ? (std::uint64_t{1} << (Bits - 1)) - 1 : (std::uint64_t{1} << Bits) - 1);
  static constexpr std::int64_t min_raw = Signed ? -top_raw - 1 : 0;

 private:
  // The physical value's decimal mantissa is raw x mantissa x 10^exponent (exponent > 0): it
  // must fit 64 bits for every raw value, or exact() could not be exact.
  static constexpr bool scale_fits = [] {
    std::uint64_t limit = ~std::uint64_t{0} / static_cast<std::uint64_t>(Res.mantissa);
    for (int e = 0; e < Res.exponent; ++e) limit /= 10;
    return static_cast<std::uint64_t>(top_raw) + 1 <= limit && Res.exponent <= 19 &&
           -Res.exponent <= 19;
  }();
  static_assert(scale_fits, "a raw value at this resolution does not fit a decimal exactly");

 public:
  /// The largest raw value that is an ordinary value.
  static constexpr std::int64_t max_valid_raw = top_raw - sentinels;

  constexpr number() noexcept = default;
  template <class V>
  requires std::is_arithmetic_v<V> number(V)
  = delete;  // a plain number is ambiguous here: use number::from(v) or from_raw(raw)

  /// The wire's integer as it is. encode refuses one that does not fit `Bits`.
  [[nodiscard]] static constexpr number from_raw(std::int64_t raw) noexcept {
    number n;
    n.raw_ = raw;
    return n;
  }
  [[nodiscard]] static constexpr number not_available() noexcept { return number{}; }
  [[nodiscard]] static constexpr number out_of_range() noexcept requires(sentinels >= 2) {
    return from_raw(top_raw - 1);
  }
  [[nodiscard]] static constexpr number reserved() noexcept requires(sentinels >= 3) {
    return from_raw(top_raw - 2);
  }

  /// The physical value `d` (in the field's unit), rounded to the nearest step, halves away from
  /// zero (1.005 at 0.01 is raw 101). out_of_range outside the field's ordinary values.
  [[nodiscard]] static constexpr result<number> from(const nmea::decimal& d) noexcept {
    std::int64_t raw = 0;
    const bool fits =
        detail::raw_from_scaled<Res>(d.mantissa, -static_cast<int>(d.places), d.negative, raw);
    return checked(fits, raw);
  }
  /// The physical value `v` by decimal::from_double's rule (363.15 K is 363.15, not
  /// 363.149999...), then as for a decimal. not_finite for NaN and infinities.
  [[nodiscard]] static constexpr result<number> from(double v) noexcept {
    seawire::detail::rounded_double m;
    const errc e = seawire::detail::round_double(v, 1, -Res.exponent,
                                                 static_cast<std::uint64_t>(Res.mantissa), m);
    if (e == errc::not_finite) return {number{}, e};
    std::int64_t raw = 0;
    const bool fits = e == errc::ok && detail::signed_raw(m.magnitude, m.negative, raw);
    return checked(fits, raw);
  }
  template <nmea::whole_number I>
  [[nodiscard]] static constexpr result<number> from(I v) noexcept {
    return from(nmea::decimal(v));
  }
  /// A character or a bool is not a physical value ('A' would be 65).
  template <std::integral I>
  requires(!nmea::whole_number<I>) static result<number> from(I) = delete;

  /// Sets the field to the physical value `v` (double, decimal or integer); on error the field is
  /// left as it was and the errc says why.
  template <class V>
  constexpr errc assign(const V& v) noexcept {
    const auto r = from(v);
    if (r) *this = r.value;
    return r.ec;
  }

  [[nodiscard]] constexpr std::int64_t raw() const noexcept { return raw_; }
  [[nodiscard]] constexpr bool fits() const noexcept { return raw_ >= min_raw && raw_ <= top_raw; }
  [[nodiscard]] constexpr field_state state() const noexcept {
    if (raw_ <= max_valid_raw) return field_state::value;
    if (raw_ == top_raw) return field_state::not_available;
    if (raw_ == top_raw - 1) return field_state::out_of_range;
    return field_state::reserved;
  }
  [[nodiscard]] constexpr bool has_value() const noexcept { return state() == field_state::value; }
  /// The physical value exactly, with the resolution's fraction digits; nullopt unless a value.
  [[nodiscard]] constexpr std::optional<nmea::decimal> exact() const noexcept {
    if (!has_value()) return std::nullopt;
    return detail::scaled_decimal<Res>(raw_);
  }
  /// The physical value; nullopt unless a value.
  [[nodiscard]] constexpr std::optional<double> value() const noexcept {
    if (!has_value()) return std::nullopt;
    return exact()->to_double();
  }

  [[nodiscard]] constexpr bool operator==(const number& o) const noexcept { return raw_ == o.raw_; }

 private:
  [[nodiscard]] static constexpr result<number> checked(bool fits, std::int64_t raw) noexcept {
    if (!fits || raw < min_raw || raw > max_valid_raw) return {number{}, errc::out_of_range};
    return {from_raw(raw), errc::ok};
  }

  std::int64_t raw_ = top_raw;
};

template <unsigned Bits, resolution Res = resolution{}>
using unsigned_number = number<Bits, false, Res>;
template <unsigned Bits, resolution Res = resolution{}>
using signed_number = number<Bits, true, Res>;
/// An unsigned integer field every raw value of which is a value, all ones included (an ISO
/// NAME's device instances): no sentinel, so never "not available".
template <unsigned Bits>
using unsigned_no_sentinel = number<Bits, false, resolution{}, 0>;

// ---------------------------------------------------------------------------------------------
// lookups and flag sets

/// The JSON and fmt names of a lookup's values or a flag set's bits, by value or bit: declared
/// beside the enum as `constexpr std::array<std::string_view, N> lookup_names(E)` (found by ADL).
template <class E>
concept named_enum = std::is_enum_v<E> && requires(E e) {
  { lookup_names(e).size() } -> std::convertible_to<std::size_t>;
};

namespace detail {
template <named_enum E>
inline constexpr auto names_of = lookup_names(E{});

template <named_enum E>
[[nodiscard]] constexpr std::string_view enum_name(std::uint64_t v) noexcept {
  return seawire::detail::name_at(names_of<E>, v);
}
template <named_enum E>
[[nodiscard]] constexpr std::optional<std::uint64_t> enum_value(std::string_view name) noexcept {
  const std::optional<std::size_t> i = seawire::detail::index_of_name(names_of<E>, name);
  if (!i) return std::nullopt;
  return *i;
}
/// Whether no name of E is a field state's.
template <named_enum E>
inline constexpr bool names_clear_of_states =
    !enum_value<E>("not_available") && !enum_value<E>("out_of_range") && !enum_value<E>("reserved");
}  // namespace detail

/// An enum with display titles, canboat's texts ("Paddle wheel", "Pitot tube"): declared as
/// `constexpr std::array<std::string_view, N> lookup_titles(E)` (found by ADL). Every lookup and
/// flag enum has them beside lookup_names, the same values in the same order; a title may go on
/// past the names for the raw values canboat names among the sentinels (a heading reference's
/// raw 2, "Error"). An enum with titles alone names the values of a number field
/// (field<&P::m, E>). An empty title names nothing.
template <class E>
concept titled_enum = std::is_enum_v<E> && requires(E e) {
  { lookup_titles(e).size() } -> std::convertible_to<std::size_t>;
};

namespace detail {
template <titled_enum E>
inline constexpr auto titles_of = lookup_titles(E{});

template <titled_enum E>
inline constexpr bool titles_cover_names = [] {
  if constexpr (named_enum<E>) {
    if (titles_of<E>.size() < names_of<E>.size()) return false;
    for (std::size_t i = 0; i < names_of<E>.size(); ++i)
      if (names_of<E>[i].empty() != titles_of<E>[i].empty()) return false;
  }
  return true;
}();

}  // namespace detail

/// The title of raw value `v` of E ("Pitot tube" for water_reference 1); empty when E has none
/// for it.
template <titled_enum E>
[[nodiscard]] constexpr std::string_view lookup_title(std::uint64_t v) noexcept {
  static_assert(detail::titles_cover_names<E>,
                "lookup_titles must title every value lookup_names names, and only those, before "
                "any sentinel titles");
  return seawire::detail::name_at(detail::titles_of<E>, v);
}

/// A field of `Bits` bits whose values name things (a speed sensor's type). Values the standard
/// has not named are kept and sent as they are; the top 3 raw values are sentinels (2 of a 2-bit
/// lookup), except those the lookup names: a named raw value is always a value (a 2-bit gear's
/// 2 is "reverse", not J1939's "error").
template <named_enum E, unsigned Bits>
class lookup {
  static_assert(Bits >= 1 && Bits <= 16);

 public:
  static constexpr unsigned bits = Bits;
  static constexpr bool is_signed = false;
  static constexpr unsigned sentinels = detail::lookup_sentinel_count(Bits);
  static constexpr std::int64_t top_raw = (std::int64_t{1} << Bits) - 1;
  /// The largest raw value that is a value whether named or not.
  static constexpr std::int64_t max_valid_raw = top_raw - sentinels;

  /// Whether raw value `raw` is a value: below the sentinels, or one the lookup names.
  [[nodiscard]] static constexpr bool is_value(std::int64_t raw) noexcept {
    return (raw >= 0 && raw <= max_valid_raw) ||
           (raw > max_valid_raw && raw <= top_raw &&
            !seawire::detail::name_at(names(), static_cast<std::uint64_t>(raw)).empty());
  }

  constexpr lookup() noexcept = default;
  // NOLINTNEXTLINE(google-explicit-constructor): m.speed_type = water_reference::doppler;
  constexpr lookup(E e) noexcept : raw_(static_cast<std::int64_t>(e)) {}

  [[nodiscard]] static constexpr lookup from_raw(std::int64_t raw) noexcept {
    lookup l;
    l.raw_ = raw;
    return l;
  }
  /// All ones; not offered when the lookup names all ones (then no raw value means "not
  /// available").
  [[nodiscard]] static constexpr lookup not_available() noexcept requires(!is_value(top_raw)) {
    return lookup{};
  }
  /// The value called `name` (a name of lookup_names); bad_enum for any other.
  [[nodiscard]] static constexpr result<lookup> from_name(std::string_view name) noexcept {
    const auto i = seawire::detail::index_of_name(names(), name);
    if (!i) return {lookup{}, errc::bad_enum};
    return {from_raw(static_cast<std::int64_t>(*i)), errc::ok};
  }

  [[nodiscard]] constexpr std::int64_t raw() const noexcept { return raw_; }
  [[nodiscard]] constexpr bool fits() const noexcept { return raw_ >= 0 && raw_ <= top_raw; }
  [[nodiscard]] constexpr field_state state() const noexcept {
    return is_value(raw_) ? field_state::value : detail::state_of(raw_, top_raw, sentinels);
  }
  [[nodiscard]] constexpr bool has_value() const noexcept { return state() == field_state::value; }
  /// The value, named or not; nullopt unless state() is value.
  [[nodiscard]] constexpr std::optional<E> value() const noexcept {
    if (!has_value()) return std::nullopt;
    return static_cast<E>(raw_);
  }
  /// The value's name; empty for a sentinel or a value the standard has not named.
  [[nodiscard]] constexpr std::string_view name() const noexcept {
    return has_value() ? seawire::detail::name_at(names(), static_cast<std::uint64_t>(raw_))
                       : std::string_view{};
  }
  [[nodiscard]] constexpr bool operator==(const lookup& o) const noexcept { return raw_ == o.raw_; }
  [[nodiscard]] constexpr bool operator==(E e) const noexcept {
    return raw_ == static_cast<std::int64_t>(e);
  }

 private:
  // E's names, checked where the lookup first reads them (its state, name, from_name): a header
  // that only declares lookup members evaluates no table (a manufacturer code names 2048 values).
  [[nodiscard]] static constexpr const auto& names() noexcept {
    static_assert(std::tuple_size_v<std::remove_cvref_t<decltype(lookup_names(E{}))>> <=
                      static_cast<std::size_t>(top_raw) + 1,
                  "more names than the field has raw values");
    static_assert(detail::names_clear_of_states<E>,
                  "a lookup's name cannot be a state's: JSON could not tell them apart");
    return detail::names_of<E>;
  }

  std::int64_t raw_ = top_raw;
};

/// A word of `Bits` independent flags; E's values are bit numbers, unnamed bits are kept. No raw
/// value is a sentinel: default-constructed it is "not available" (a word not sent), which is not
/// none(), every flag clear.
template <named_enum E, unsigned Bits>
class flags {
  static_assert(Bits >= 1 && Bits <= 32);

 public:
  static constexpr unsigned bits = Bits;
  static constexpr bool is_signed = false;
  static constexpr std::int64_t top_raw = (std::int64_t{1} << Bits) - 1;

  constexpr flags() noexcept = default;  // not available
  /// The flags in `set` set, every other clear.
  constexpr flags(std::initializer_list<E> set) noexcept : available_(true) {
    for (const E e : set) raw_ |= std::int64_t{1} << static_cast<unsigned>(e);
  }
  [[nodiscard]] static constexpr flags from_raw(std::int64_t raw) noexcept {
    flags f;
    f.raw_ = raw;
    f.available_ = true;
    return f;
  }
  /// Every flag clear.
  [[nodiscard]] static constexpr flags none() noexcept { return from_raw(0); }
  [[nodiscard]] static constexpr flags not_available() noexcept { return flags{}; }
  /// Whether flag `e` is set (false when not available).
  [[nodiscard]] constexpr bool test(E e) const noexcept {
    return ((raw_ >> static_cast<unsigned>(e)) & 1) != 0;
  }
  [[nodiscard]] constexpr bool test_bit(unsigned bit) const noexcept {
    return bit < Bits && ((raw_ >> bit) & 1) != 0;
  }
  /// Sets or clears flag `e`; a word not available becomes one with only this change from none.
  constexpr void set(E e, bool on = true) noexcept {
    const std::int64_t m = std::int64_t{1} << static_cast<unsigned>(e);
    raw_ = on ? (raw_ | m) : (raw_ & ~m);
    available_ = true;
  }
  /// The word (0 when not available).
  [[nodiscard]] constexpr std::int64_t raw() const noexcept { return raw_; }
  [[nodiscard]] constexpr bool fits() const noexcept { return raw_ >= 0 && raw_ <= top_raw; }
  [[nodiscard]] constexpr field_state state() const noexcept {
    return available_ ? field_state::value : field_state::not_available;
  }
  [[nodiscard]] constexpr bool has_value() const noexcept { return available_; }
  [[nodiscard]] constexpr bool operator==(const flags& o) const noexcept {
    return available_ == o.available_ && raw_ == o.raw_;
  }

 private:
  std::int64_t raw_ = 0;
  bool available_ = false;
};

// ---------------------------------------------------------------------------------------------
// date and time of day

/// A date as days since 1970-01-01 (16 bits: up to 2149-06-03).
class day_count {
 public:
  static constexpr unsigned bits = 16;
  static constexpr bool is_signed = false;
  using number_type = number<16, false>;
  static constexpr std::int64_t top_raw = number_type::top_raw;

  constexpr day_count() noexcept = default;
  [[nodiscard]] static constexpr day_count from_raw(std::int64_t raw) noexcept {
    day_count d;
    d.n_ = number_type::from_raw(raw);
    return d;
  }
  /// out_of_range before 1970 or after 2149-06-03.
  [[nodiscard]] static constexpr result<day_count> from(std::chrono::sys_days day) noexcept {
    const auto r = number_type::from(day.time_since_epoch().count());
    day_count d;
    d.n_ = r.value;
    return {d, r.ec};
  }
  [[nodiscard]] constexpr std::optional<std::chrono::sys_days> value() const noexcept {
    if (!n_.has_value()) return std::nullopt;
    return std::chrono::sys_days(std::chrono::days(n_.raw()));
  }
  [[nodiscard]] constexpr std::int64_t raw() const noexcept { return n_.raw(); }
  [[nodiscard]] constexpr bool fits() const noexcept { return n_.fits(); }
  [[nodiscard]] constexpr field_state state() const noexcept { return n_.state(); }
  [[nodiscard]] constexpr bool has_value() const noexcept { return n_.has_value(); }
  [[nodiscard]] constexpr bool operator==(const day_count&) const noexcept = default;

 private:
  number_type n_;
};

/// A time of day in units of 0.1 ms since midnight (32 bits; up to 86 401 s, a leap second).
class time_since_midnight {
 public:
  static constexpr unsigned bits = 32;
  static constexpr bool is_signed = false;
  using ticks = std::chrono::duration<std::int64_t, std::ratio<1, 10000>>;
  using number_type = number<32, false, resolution{1, -4}>;
  static constexpr std::int64_t top_raw = number_type::top_raw;
  static constexpr std::int64_t max_ticks = 864'010'000;  // 24 h and one leap second

  constexpr time_since_midnight() noexcept = default;
  [[nodiscard]] static constexpr time_since_midnight from_raw(std::int64_t raw) noexcept {
    time_since_midnight t;
    t.n_ = number_type::from_raw(raw);
    return t;
  }
  /// The time `since_midnight`, rounded to 0.1 ms; out_of_range when negative or past 86 401 s.
  template <class Rep, class Period>
  [[nodiscard]] static constexpr result<time_since_midnight> from(
      std::chrono::duration<Rep, Period> since_midnight) noexcept {
    const auto t = std::chrono::round<ticks>(since_midnight);
    if (t.count() < 0 || t.count() > max_ticks) return {time_since_midnight{}, errc::out_of_range};
    return {from_raw(t.count()), errc::ok};
  }
  /// Since midnight; nullopt for a sentinel. A sender's value past 86 401 s is kept as it is.
  [[nodiscard]] constexpr std::optional<ticks> value() const noexcept {
    if (!n_.has_value()) return std::nullopt;
    return ticks(n_.raw());
  }
  [[nodiscard]] constexpr std::int64_t raw() const noexcept { return n_.raw(); }
  [[nodiscard]] constexpr bool fits() const noexcept { return n_.fits(); }
  [[nodiscard]] constexpr field_state state() const noexcept { return n_.state(); }
  [[nodiscard]] constexpr bool has_value() const noexcept { return n_.has_value(); }
  [[nodiscard]] constexpr bool operator==(const time_since_midnight&) const noexcept = default;

 private:
  number_type n_;
};

/// The former names of day_count and time_since_midnight, kept for one release.
using date [[deprecated("use nmea2000::day_count")]] = day_count;
using time_of_day [[deprecated("use nmea2000::time_since_midnight")]] = time_since_midnight;

// ---------------------------------------------------------------------------------------------
// ---- strings ----

namespace detail {

/// Whether a byte (or UTF-16 unit) is trimmed from the end of a string's text: padding 0xFF and
/// 0x00, '@' (AIS's padding), spaces and the other C whitespace (docs/nmea2000.md).
[[nodiscard]] constexpr bool is_text_padding(std::uint32_t c) noexcept {
  return c == 0xFF || c == 0x00 || c == '@' || c == ' ' || (c >= '\t' && c <= '\r');
}

/// The length of a single-byte string's text in `b`: the bytes before the first 0x00 or 0xFF,
/// trailing padding trimmed.
[[nodiscard]] constexpr std::size_t single_byte_text_length(std::string_view b) noexcept {
  std::size_t n = 0;
  while (n < b.size() && b[n] != '\0' && static_cast<unsigned char>(b[n]) != 0xFF) ++n;
  while (n > 0 && is_text_padding(static_cast<unsigned char>(b[n - 1]))) --n;
  return n;
}

/// Code unit `i` of UTF-16LE bytes `b`.
[[nodiscard]] constexpr std::uint32_t utf16_unit(std::string_view b, std::size_t i) noexcept {
  return static_cast<unsigned char>(b[2 * i]) |
         (static_cast<std::uint32_t>(static_cast<unsigned char>(b[2 * i + 1])) << 8U);
}

/// The number of UTF-16 code units of a string's text in UTF-16LE bytes `b` (an odd last byte is
/// no unit): the units before the first U+0000 or U+FFFF, trailing padding units trimmed.
[[nodiscard]] constexpr std::size_t utf16_text_units(std::string_view b) noexcept {
  const std::size_t units = b.size() / 2;
  std::size_t n = 0;
  while (n < units && utf16_unit(b, n) != 0 && utf16_unit(b, n) != 0xFFFF) ++n;
  while (n > 0 && utf16_unit(b, n - 1) != 0xFF && is_text_padding(utf16_unit(b, n - 1))) --n;
  return n;
}

/// The next code point of UTF-8 `t` at `i` (advanced past it); nullopt for bytes that are not
/// UTF-8 (overlong forms, surrogates and values past U+10FFFF included).
[[nodiscard]] constexpr std::optional<std::uint32_t> next_code_point(std::string_view t,
                                                                     std::size_t& i) noexcept {
  const auto b0 = static_cast<unsigned char>(t[i]);
  if (b0 < 0x80) {
    ++i;
    return b0;
  }
  const std::size_t n = b0 >= 0xF0 ? 4 : b0 >= 0xE0 ? 3 : b0 >= 0xC0 ? 2 : 0;
  if (n == 0 || b0 > 0xF4 || i + n > t.size()) return std::nullopt;
  std::uint32_t c = b0 & (0x7FU >> n);
  for (std::size_t k = 1; k < n; ++k) {
    const auto b = static_cast<unsigned char>(t[i + k]);
    if ((b & 0xC0) != 0x80) return std::nullopt;
    c = (c << 6U) | (b & 0x3FU);
  }
  constexpr std::uint32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
  if (c < least[n] || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return std::nullopt;
  i += n;
  return c;
}

/// Whether code point `c` may be a single-byte string's character: U+0001..U+00FE, the byte of
/// the same value (0x00 and 0xFF end the text).
[[nodiscard]] constexpr bool single_byte_char(std::uint32_t c) noexcept {
  return c >= 0x01 && c <= 0xFE;
}

}  // namespace detail

/// A string of exactly `Bytes` bytes, one character a byte (canboat's STRING_FIX): the text is
/// the bytes before the first 0x00 or 0xFF, its trailing padding ('@', spaces, 0x00, 0xFF)
/// trimmed; an empty text is "not available". Every byte is kept, so decode -> encode is byte
/// for byte; from_text() pads with `Pad` (0xFF, the NMEA 2000 "no data" byte; '@' for the
/// strings an AIS message carries). Bytes outside printable ASCII are characters U+0080..U+00FE
/// of the text, shown escaped (docs/nmea2000.md).
template <std::size_t Bytes, std::uint8_t Pad = 0xFF>
class fixed_text {
  static_assert(Bytes >= 1 && Bytes <= max_fast_packet_length, "a string of 1..223 bytes");
  static_assert(detail::is_text_padding(Pad), "the padding must be a byte the text is cut at");

 public:
  static constexpr unsigned bits = 8 * static_cast<unsigned>(Bytes);
  static constexpr bool is_signed = false;
  static constexpr bool variable = false;  ///< always Bytes on the wire
  static constexpr std::size_t capacity = Bytes;
  static constexpr std::uint8_t padding = Pad;

  constexpr fixed_text() noexcept { bytes_.fill(static_cast<char>(0xFF)); }  // not available

  /// The field's bytes as sent: the first `Bytes` of `b`, 0xFF for those `b` is too short for.
  [[nodiscard]] static constexpr fixed_text from_bytes(std::span<const std::uint8_t> b) noexcept {
    fixed_text t;
    for (std::size_t i = 0; i < Bytes && i < b.size(); ++i) t.bytes_[i] = static_cast<char>(b[i]);
    return t;
  }
  [[nodiscard]] static constexpr fixed_text not_available() noexcept { return fixed_text{}; }
  /// The string holding `text` (UTF-8), padded with `Pad`. text_too_long past `Bytes`
  /// characters; bad_text for bytes that are not UTF-8, a character past U+00FE or U+0000 (one
  /// byte a character, 0x00 and 0xFF end the text) or a text ending in padding (a space, '@':
  /// the receiver would cut it). "" is the string not available.
  [[nodiscard]] static constexpr result<fixed_text> from_text(std::string_view text) noexcept {
    fixed_text t;
    std::size_t n = 0;
    for (std::size_t i = 0; i < text.size();) {
      const std::optional<std::uint32_t> c = detail::next_code_point(text, i);
      if (!c || !detail::single_byte_char(*c)) return {fixed_text{}, errc::bad_text};
      if (n == Bytes) return {fixed_text{}, errc::text_too_long};
      t.bytes_[n++] = static_cast<char>(*c);
    }
    if (n > 0 && detail::is_text_padding(static_cast<unsigned char>(t.bytes_[n - 1])))
      return {fixed_text{}, errc::bad_text};
    for (std::size_t i = n; i < Bytes; ++i) t.bytes_[i] = static_cast<char>(Pad);
    return {t, errc::ok};
  }

  /// The bytes as sent, padding included.
  [[nodiscard]] constexpr std::string_view bytes() const noexcept { return {bytes_.data(), Bytes}; }
  /// The text: one character a byte (0x80..0xFE as U+0080..U+00FE), padding left out.
  [[nodiscard]] constexpr std::string_view text() const noexcept {
    return bytes().substr(0, detail::single_byte_text_length(bytes()));
  }
  [[nodiscard]] static constexpr bool is_utf16() noexcept { return false; }
  [[nodiscard]] constexpr bool fits() const noexcept { return true; }
  [[nodiscard]] constexpr field_state state() const noexcept {
    return text().empty() ? field_state::not_available : field_state::value;
  }
  [[nodiscard]] constexpr bool has_value() const noexcept { return !text().empty(); }
  [[nodiscard]] constexpr bool operator==(const fixed_text&) const noexcept = default;

 private:
  std::array<char, Bytes> bytes_{};
};

/// What the second byte of a counted string (counted_text) says its characters are.
enum class text_encoding : std::uint8_t {
  utf16 = 0,  ///< UTF-16, little-endian code units
  ascii = 1,  ///< one byte a character
};

/// A string of varying length (canboat's STRING_LAU): a length byte counting itself, the
/// encoding byte (text_encoding) and up to `MaxBytes` bytes of characters. The text is read as
/// fixed_text's (cut at 0x00 / 0xFF, padding trimmed), UTF-16 by code units; an empty text is
/// "not available", which is sent as the empty string (02 01). Every byte and the encoding byte
/// are kept as sent, so decode -> encode is byte for byte. The fields after it start where it
/// ends (decode<P> / encode<P> keep a running offset).
template <std::size_t MaxBytes>
class counted_text {
  static_assert(MaxBytes >= 1 && MaxBytes + 2 <= max_fast_packet_length,
                "a counted string of 1..221 bytes of text (a fast packet holds 223)");

 public:
  /// The field's width at its longest (its bytes on the wire vary: wire_size()).
  static constexpr unsigned bits = 8 * static_cast<unsigned>(MaxBytes + 2);
  static constexpr bool is_signed = false;
  static constexpr bool variable = true;
  static constexpr std::size_t capacity = MaxBytes;

  constexpr counted_text() noexcept = default;  // not available: the empty string

  [[nodiscard]] static constexpr counted_text not_available() noexcept { return counted_text{}; }
  /// The string of encoding byte `control` and bytes `b` (its first MaxBytes; false when `b` is
  /// longer).
  [[nodiscard]] static constexpr result<counted_text> from_bytes(
      std::uint8_t control, std::span<const std::uint8_t> b) noexcept {
    counted_text t;
    t.control_ = control;
    t.size_ = static_cast<std::uint8_t>(std::min(b.size(), MaxBytes));
    for (std::size_t i = 0; i < t.size_; ++i) t.bytes_[i] = static_cast<char>(b[i]);
    return {t, b.size() > MaxBytes ? errc::text_too_long : errc::ok};
  }
  /// The string holding `text` (UTF-8): one byte a character (ascii) when every character is
  /// U+0001..U+00FE, else UTF-16. text_too_long past MaxBytes bytes; bad_text for bytes that are
  /// not UTF-8, U+0000, U+FFFF, or a text ending in padding (a space, '@').
  [[nodiscard]] static constexpr result<counted_text> from_text(std::string_view text) noexcept {
    bool single = true;
    for (std::size_t i = 0; i < text.size();) {
      const std::optional<std::uint32_t> c = detail::next_code_point(text, i);
      if (!c || *c == 0 || *c == 0xFFFF) return {counted_text{}, errc::bad_text};
      single = single && detail::single_byte_char(*c);
    }
    counted_text t;
    t.control_ = static_cast<std::uint8_t>(single ? text_encoding::ascii : text_encoding::utf16);
    std::uint32_t last = 0;
    for (std::size_t i = 0; i < text.size();) {
      last = *detail::next_code_point(text, i);
      std::uint32_t units[2] = {last, 0};
      std::size_t count = 1;
      if (!single && last > 0xFFFF) {
        units[0] = 0xD800 + ((last - 0x10000) >> 10U);
        units[1] = 0xDC00 + ((last - 0x10000) & 0x3FFU);
        count = 2;
      }
      for (std::size_t k = 0; k < count; ++k) {
        if (t.size_ + (single ? 1U : 2U) > MaxBytes) return {counted_text{}, errc::text_too_long};
        t.bytes_[t.size_++] = static_cast<char>(units[k] & 0xFFU);
        if (!single) t.bytes_[t.size_++] = static_cast<char>(units[k] >> 8U);
      }
    }
    if (last != 0 && last != 0xFF && detail::is_text_padding(last))
      return {counted_text{}, errc::bad_text};
    return {t, errc::ok};
  }

  /// The encoding byte as sent (text_encoding; others are kept, their bytes read as ascii).
  [[nodiscard]] constexpr std::uint8_t control() const noexcept { return control_; }
  [[nodiscard]] constexpr bool is_utf16() const noexcept {
    return control_ == static_cast<std::uint8_t>(text_encoding::utf16);
  }
  /// The bytes after the encoding byte, as sent.
  [[nodiscard]] constexpr std::string_view bytes() const noexcept { return {bytes_.data(), size_}; }
  /// The bytes of the text: padding left out; UTF-16LE code units when is_utf16().
  [[nodiscard]] constexpr std::string_view text() const noexcept {
    if (is_utf16()) return bytes().substr(0, 2 * detail::utf16_text_units(bytes()));
    return bytes().substr(0, detail::single_byte_text_length(bytes()));
  }
  /// The bytes on the wire: length, encoding, text.
  [[nodiscard]] constexpr std::size_t wire_size() const noexcept { return size_ + 2U; }
  [[nodiscard]] constexpr bool fits() const noexcept { return size_ <= MaxBytes; }
  [[nodiscard]] constexpr field_state state() const noexcept {
    return text().empty() ? field_state::not_available : field_state::value;
  }
  [[nodiscard]] constexpr bool has_value() const noexcept { return !text().empty(); }
  [[nodiscard]] constexpr bool operator==(const counted_text& o) const noexcept {
    return control_ == o.control_ && bytes() == o.bytes();
  }

 private:
  std::array<char, MaxBytes> bytes_{};
  std::uint8_t size_ = 0;
  std::uint8_t control_ = static_cast<std::uint8_t>(text_encoding::ascii);
};

/// A string field's value type: fixed_text or counted_text.
template <class T>
concept text_value = requires(const T& t) {
  { T::bits } -> std::convertible_to<unsigned>;
  { T::variable } -> std::convertible_to<bool>;
  { T::capacity } -> std::convertible_to<std::size_t>;
  { t.text() } -> std::same_as<std::string_view>;
  { t.bytes() } -> std::same_as<std::string_view>;
  { t.is_utf16() } -> std::same_as<bool>;
  { t.fits() } -> std::same_as<bool>;
  { t.state() } -> std::same_as<field_state>;
};

// ---------------------------------------------------------------------------------------------
// descriptions

/// A value type a PGN member may have: bits, signedness, raw access.
template <class T>
concept raw_field_value = requires(const T& t, std::int64_t raw) {
  { T::bits } -> std::convertible_to<unsigned>;
  { T::is_signed } -> std::convertible_to<bool>;
  { T::from_raw(raw) } -> std::same_as<T>;
  { t.raw() } -> std::same_as<std::int64_t>;
  { t.fits() } -> std::same_as<bool>;
  { t.state() } -> std::same_as<field_state>;
};

/// A value type a PGN member may have: one with a raw integer, or a string (text_value).
template <class T>
concept field_value = raw_field_value<T> || text_value<T>;

/// One row of a PGN table: the member, its name (snake_case with the unit last, as JSON, CSV and
/// fmt show it) and its title, the field's name as canboat's database spells it (the key of its
/// JSON).
template <auto Member>
struct field_entry {
  using value_type = seawire::detail::member_type_t<Member>;
  static_assert(field_value<value_type>,
                "a PGN member must be a number, lookup, flags, day_count, time_since_midnight "
                "or a string (fixed_text, counted_text)");
  static constexpr auto member = Member;
  static constexpr unsigned bits = value_type::bits;
  static constexpr bool is_reserved = false;
  std::string_view name;
  std::string_view title;
};

template <auto Member>
[[nodiscard]] constexpr field_entry<Member> field(std::string_view name,
                                                  std::string_view title) noexcept {
  return {name, title};
}

// ---------------------------------------------------------------------------------------------
// lookups whose names depend on another field

/// One name of a lookup whose names depend on another field (its key): 60928's device function
/// 130 is "diagnostic" in device class 10 and "bus_traffic_logger" is 140 there, but 130 of class
/// 20 is an EPIRB. `name` is snake_case (JSON, CSV, fmt), `title` the standard's text.
struct keyed_name {
  std::uint16_t key = 0;
  std::uint16_t value = 0;
  std::string_view name;
  std::string_view title;
};

namespace detail {
[[nodiscard]] constexpr bool keyed_before(const keyed_name& a, std::int64_t key,
                                          std::int64_t value) noexcept {
  return a.key < key || (a.key == key && a.value < value);
}
/// Whether `t` is sorted by (key, value), each pair once, every name set and unique in its key.
template <std::size_t N>
[[nodiscard]] constexpr bool keyed_table_valid(const std::array<keyed_name, N>& t) noexcept {
  for (std::size_t i = 0; i < N; ++i) {
    if (t[i].name.empty() || t[i].title.empty()) return false;
    if (i > 0 && !keyed_before(t[i - 1], t[i].key, t[i].value)) return false;
    for (std::size_t j = i + 1; j < N && t[j].key == t[i].key; ++j)
      if (t[j].name == t[i].name) return false;
  }
  return true;
}
/// The index of (key, value) in a sorted table, by binary search; N when it has none.
template <std::size_t N>
[[nodiscard]] constexpr std::size_t keyed_find(const std::array<keyed_name, N>& t, std::int64_t key,
                                               std::int64_t value) noexcept {
  std::size_t lo = 0;
  std::size_t hi = N;
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (keyed_before(t[mid], key, value)) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo < N && t[lo].key == key && t[lo].value == value ? lo : N;
}
}  // namespace detail

/// A table of keyed names: a type with `static constexpr std::array<keyed_name, N> entries`.
template <class T>
concept keyed_table = requires {
  T::entries.size();
  { T::entries[0] } -> std::convertible_to<const keyed_name&>;
};

/// A field of `Bits` bits whose names depend on another field of the PGN, its key (declared with
/// keyed_field). Table T lists the named (key, value) pairs once, sorted; a pair it does not list
/// is kept and shown as its number. The top raw values are sentinels as for a lookup; no pair may
/// name one, so the state never depends on the key.
template <keyed_table T, unsigned Bits>
class keyed_lookup {
  static_assert(Bits >= 1 && Bits <= 16);

 public:
  using table = T;
  static constexpr unsigned bits = Bits;
  static constexpr bool is_signed = false;
  static constexpr unsigned sentinels = detail::lookup_sentinel_count(Bits);
  static constexpr std::int64_t top_raw = (std::int64_t{1} << Bits) - 1;
  static constexpr std::int64_t max_valid_raw = top_raw - sentinels;

  constexpr keyed_lookup() noexcept = default;
  [[nodiscard]] static constexpr keyed_lookup from_raw(std::int64_t raw) noexcept {
    keyed_lookup l;
    l.raw_ = raw;
    return l;
  }
  [[nodiscard]] static constexpr keyed_lookup not_available() noexcept { return keyed_lookup{}; }
  /// The value called `name` when the key is `key`; bad_enum when no value of that key is.
  [[nodiscard]] static constexpr result<keyed_lookup> from_name(std::int64_t key,
                                                                std::string_view name) noexcept {
    for (const keyed_name& e : entries())
      if (e.key == key && e.name == name) return {from_raw(e.value), errc::ok};
    return {keyed_lookup{}, errc::bad_enum};
  }

  [[nodiscard]] constexpr std::int64_t raw() const noexcept { return raw_; }
  [[nodiscard]] constexpr bool fits() const noexcept { return raw_ >= 0 && raw_ <= top_raw; }
  [[nodiscard]] constexpr field_state state() const noexcept {
    return detail::state_of(raw_, top_raw, sentinels);
  }
  [[nodiscard]] constexpr bool has_value() const noexcept { return state() == field_state::value; }
  /// The value's name when the key is `key` (O(log n)); empty for a sentinel or a pair the table
  /// does not name.
  [[nodiscard]] constexpr std::string_view name(std::int64_t key) const noexcept {
    const std::size_t i = at(key);
    return i < entries().size() ? entries()[i].name : std::string_view{};
  }
  /// The standard's text for the value when the key is `key`; empty as for name().
  [[nodiscard]] constexpr std::string_view title(std::int64_t key) const noexcept {
    const std::size_t i = at(key);
    return i < entries().size() ? entries()[i].title : std::string_view{};
  }
  [[nodiscard]] constexpr bool operator==(const keyed_lookup&) const noexcept = default;

 private:
  // T's names, checked where the field first reads them (name, title, from_name): a header that
  // only declares keyed members evaluates no table (60928's device functions are 106 pairs).
  [[nodiscard]] static constexpr const auto& entries() noexcept {
    static_assert(detail::keyed_table_valid(T::entries),
                  "a keyed table must be sorted by (key, value), each pair and name once");
    static_assert(std::all_of(T::entries.begin(), T::entries.end(),
                              [](const keyed_name& e) { return e.value <= max_valid_raw; }),
                  "a keyed table names a sentinel");
    return T::entries;
  }

  [[nodiscard]] constexpr std::size_t at(std::int64_t key) const noexcept {
    return has_value() ? detail::keyed_find(entries(), key, raw_) : entries().size();
  }

  std::int64_t raw_ = top_raw;
};

namespace detail {
template <class V>
inline constexpr bool is_keyed_lookup = false;
template <class T, unsigned B>
inline constexpr bool is_keyed_lookup<keyed_lookup<T, B>> = true;
}  // namespace detail

/// A keyed lookup's value read beside its key: what the walk gives writers for a keyed field
/// (the name needs both). The key counts only when its field holds a value.
template <class L>
struct keyed_reading {
  static constexpr bool is_signed = L::is_signed;
  L value;
  std::int64_t key = 0;
  bool key_known = false;

  [[nodiscard]] constexpr std::int64_t raw() const noexcept { return value.raw(); }
  [[nodiscard]] constexpr field_state state() const noexcept { return value.state(); }
  [[nodiscard]] constexpr bool has_value() const noexcept { return value.has_value(); }
  /// The name of the (key, value) pair; empty when the key is not known or the pair not named.
  [[nodiscard]] constexpr std::string_view name() const noexcept {
    return key_known ? value.name(key) : std::string_view{};
  }
  [[nodiscard]] constexpr std::string_view title() const noexcept {
    return key_known ? value.title(key) : std::string_view{};
  }
};

/// A row of a PGN table whose value is a keyed_lookup named by the value of member KeyMember
/// (a field of the same PGN, before or after it).
template <auto Member, auto KeyMember>
struct keyed_field_entry : field_entry<Member> {
  using key_type = seawire::detail::member_type_t<KeyMember>;
  static_assert(detail::is_keyed_lookup<typename field_entry<Member>::value_type>,
                "a keyed field's member must be a keyed_lookup");
  static_assert(field_value<key_type> && std::is_same_v<seawire::detail::member_class_t<Member>,
                                                        seawire::detail::member_class_t<KeyMember>>,
                "a keyed field's key must be another field of the same PGN");
  static_assert(!seawire::detail::same_member<Member, KeyMember>, "a field cannot key itself");
  static constexpr auto key_member = KeyMember;
};

template <auto Member, auto KeyMember>
[[nodiscard]] constexpr keyed_field_entry<Member, KeyMember> keyed_field(
    std::string_view name, std::string_view title) noexcept {
  return {{name, title}};
}

/// Whether row type F is a keyed field.
template <class F>
concept keyed_row = requires {
  F::key_member;
};

/// A number field whose values canboat's database names (an engine instance: 0 "Single Engine or
/// Dual Engine Port"): a number as seawire keeps and writes it, with E's lookup_titles for the
/// writers that show canboat's texts. Declared as field<&P::m, E>(name, title).
template <auto Member, class E>
struct titled_field_entry : field_entry<Member> {
  static_assert(titled_enum<E>, "a titled number's enum declares lookup_titles");
  static_assert(
      requires { field_entry<Member>::value_type::res; },
      "only a number field takes titles; a lookup has its enum's already");
  using titles = E;
};

template <auto Member, class E>
[[nodiscard]] constexpr titled_field_entry<Member, E> field(std::string_view name,
                                                            std::string_view title) noexcept {
  return {{name, title}};
}

/// How a number that is no quantity reads: an identifier's digits (an AIS user's MMSI), or bits
/// with no numeric meaning (AIS's communication state). seawire keeps and writes it as a number;
/// writers that follow canboat show it as canboat does (a string of at least 9 digits, the bytes
/// in hex).
enum class raw_display : std::uint8_t {
  identifier,  ///< an identifier's digits (an MMSI, 9 of them)
  bits,        ///< bits with no numeric meaning, shown as bytes
};

/// A number field read as D says. Declared as field<&P::m, raw_display::bits>(name, title).
template <auto Member, raw_display D>
struct displayed_field_entry : field_entry<Member> {
  static_assert(
      requires { field_entry<Member>::value_type::res; },
      "only a number field is shown as an identifier or bits");
  static constexpr raw_display display = D;
};

template <auto Member, raw_display D>
[[nodiscard]] constexpr displayed_field_entry<Member, D> field(std::string_view name,
                                                               std::string_view title) noexcept {
  return {{name, title}};
}

/// `Bits` bits the standard reserves: sent as ones, ignored when received.
template <unsigned Bits>
struct reserved_bits {
  static constexpr unsigned bits = Bits;
  static constexpr bool is_reserved = true;
  std::string_view name = "reserved";
  std::string_view title = "Reserved";
};
template <unsigned Bits>
inline constexpr reserved_bits<Bits> reserved{};

/// `Bits` spare bits (AIS's and an ISO NAME's, by their standards' rule): sent as zeros, ignored
/// when received. `spare<N>` is named "spare"; a spare field the standard names is declared as
/// spare_bits<N>{"name", "Title"}.
template <unsigned Bits>
struct spare_bits : reserved_bits<Bits> {
  static constexpr bool is_spare = true;
  constexpr spare_bits() noexcept : reserved_bits<Bits>{"spare", "Spare"} {}
  constexpr spare_bits(std::string_view spare_name, std::string_view spare_title) noexcept
      : reserved_bits<Bits>{spare_name, spare_title} {}
};
template <unsigned Bits>
inline constexpr spare_bits<Bits> spare{};

namespace detail {
/// fn(entry, bit_offset, number) for every row of a table (a row_list) from bit 0; what fn
/// returns is ignored.
template <class Rows, class Fn>
constexpr void each_row(const Rows& rows, Fn& fn) {
  seawire::detail::for_each_row(rows, 0, [&](const auto& entry, unsigned at, std::uint16_t n) {
    (void)fn(entry, at, n);
    return true;
  });
}
}  // namespace detail

// ---------------------------------------------------------------------------------------------
// repeating field groups

/// The most bytes a message carries: a fast packet's 223. A group's capacity follows from it.
inline constexpr std::size_t max_payload_bytes = 223;

/// The rows of one repetition of a field group (describe_item): fields and reserved bits, laid
/// out as a PGN's, from the repetition's first bit. Whole bytes; no flag sets, no nested groups.
template <class... F>
struct item_description {
  seawire::detail::row_list<F...> fields;

  static constexpr unsigned bit_length =
      seawire::detail::layout_bits<seawire::detail::row_list<F...>>;
  static_assert(bit_length > 0 && (bit_length % 8 == 0 || 8 % bit_length == 0),
                "a group's repetition must fill whole bytes, or a byte hold a whole number of "
                "them (1, 2 or 4 bits)");
  /// Bytes of one repetition; 0 for one of less than a byte.
  static constexpr std::size_t length = bit_length / 8;
  static constexpr std::size_t field_count = sizeof...(F);

  /// fn(entry, bit_offset from the repetition's start, number) for every row, as a PGN's.
  template <class Fn>
  constexpr void for_each(Fn&& fn) const {
    detail::each_row(fields, fn);
  }
};

template <class... F>
[[nodiscard]] constexpr item_description<F...> describe_item(F... fields) noexcept {
  return {seawire::detail::make_rows(fields...)};
}

/// One repetition of a group: a struct with `static constexpr auto n2k_item = describe_item(...)`.
template <class T>
concept group_item = requires {
  T::n2k_item.fields;
}
&&std::is_default_constructible_v<T>;

/// How many repetitions of Item a payload holds after `header_bytes` bytes: what the group's
/// capacity must be (the table checks it).
template <group_item Item>
[[nodiscard]] consteval std::size_t group_capacity(std::size_t header_bytes) noexcept {
  return (max_payload_bytes - header_bytes) * 8 /
         std::remove_cvref_t<decltype(Item::n2k_item)>::bit_length;
}

/// A repeating field group: up to `Capacity` repetitions of Item, in fixed storage, and how many
/// are held. Declared with the row repeating<&P::group, &P::count> (a count field before it says
/// how many) or repeating_to_end<&P::group> (repetitions to the end of the payload).
template <group_item Item, std::size_t Capacity>
class group {
  static_assert(Capacity > 0);

 public:
  using item_type = Item;
  static constexpr std::size_t capacity = Capacity;

  constexpr group() noexcept = default;

  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0; }
  [[nodiscard]] constexpr bool full() const noexcept { return size_ == Capacity; }
  /// The repetitions held, in wire order.
  [[nodiscard]] constexpr std::span<const Item> items() const noexcept {
    return {items_.data(), size_};
  }
  [[nodiscard]] constexpr std::span<Item> items() noexcept { return {items_.data(), size_}; }
  [[nodiscard]] constexpr const Item* begin() const noexcept { return items_.data(); }
  [[nodiscard]] constexpr const Item* end() const noexcept { return items_.data() + size_; }
  /// Repetition i; nullptr past size().
  [[nodiscard]] constexpr const Item* at(std::size_t i) const noexcept {
    return i < size_ ? &items_[i] : nullptr;
  }
  /// Appends `item`; false (nothing changed) when the group is full.
  constexpr bool push_back(const Item& item) noexcept {
    if (size_ == Capacity) return false;
    items_[size_++] = item;
    return true;
  }
  constexpr void clear() noexcept { size_ = 0; }

  /// A group is always a value (an empty one is sent as no repetitions).
  [[nodiscard]] constexpr field_state state() const noexcept { return field_state::value; }
  [[nodiscard]] constexpr bool has_value() const noexcept { return true; }

  [[nodiscard]] constexpr bool operator==(const group& o) const noexcept {
    if (size_ != o.size_) return false;
    for (std::size_t i = 0; i < size_; ++i)
      if (!(items_[i] == o.items_[i])) return false;
    return true;
  }

 private:
  std::array<Item, Capacity> items_{};
  std::size_t size_ = 0;
};

namespace detail {
template <class T>
inline constexpr bool is_group_value = false;
template <class I, std::size_t C>
inline constexpr bool is_group_value<group<I, C>> = true;
}  // namespace detail

/// The row of a repeating group, the last of its PGN's table: after the fixed rows, as many
/// repetitions as the count field `Count` (a member of the same struct, an earlier row) says,
/// or with Count = nullptr as many as the rest of the payload holds. Takes no bits of the fixed
/// layout (`bits` is 0); item_bits is one repetition's.
template <auto Member, auto Count>
struct group_entry {
  using value_type = seawire::detail::member_type_t<Member>;
  static_assert(detail::is_group_value<value_type>, "a group row's member must be a group<>");
  using item_type = typename value_type::item_type;
  static constexpr auto member = Member;
  static constexpr auto count = Count;
  /// Whether a count field says how many repetitions follow (else: to the end of the payload).
  static constexpr bool counted = !std::is_same_v<decltype(Count), std::nullptr_t>;
  static constexpr unsigned bits = 0;
  static constexpr unsigned item_bits =
      std::remove_cvref_t<decltype(item_type::n2k_item)>::bit_length;
  static_assert(counted || item_bits % 8 == 0,
                "a group to the end of the payload has repetitions of whole bytes (a count "
                "says how many of those packed in a byte were sent)");
  static constexpr bool is_reserved = false;
  static constexpr bool is_group = true;
  std::string_view name;
  std::string_view title;
};

/// A group whose repetitions are counted by the earlier field `Count`.
template <auto Member, auto Count>
[[nodiscard]] constexpr group_entry<Member, Count> repeating(std::string_view name,
                                                             std::string_view title) noexcept {
  static_assert(!std::is_same_v<decltype(Count), std::nullptr_t>);
  using C = seawire::detail::member_type_t<Count>;
  static_assert(!C::is_signed && C::bits <= 16, "a group's count is an unsigned number");
  return {name, title};
}

/// A group that repeats to the end of the payload (no count field).
template <auto Member>
[[nodiscard]] constexpr group_entry<Member, nullptr> repeating_to_end(
    std::string_view name, std::string_view title) noexcept {
  return {name, title};
}

namespace detail {
/// Whether row type F is a repeating group's.
template <class F>
concept group_row = requires {
  F::is_group;
};
}  // namespace detail

/// Bytes at the end of a payload that its table cannot lay out, kept as they came (up to
/// MaxBytes) and shown as hex: a group function's parameter pairs are such, each value as wide as
/// the field of the PGN it names. Declared with the row bytes_to_end<&P::member>, the last row.
template <std::size_t MaxBytes>
class opaque_bytes {
  static_assert(MaxBytes >= 1 && MaxBytes <= max_fast_packet_length);

 public:
  static constexpr std::size_t capacity = MaxBytes;

  constexpr opaque_bytes() noexcept = default;

  /// The bytes of `b`; text_too_long (none kept) past the capacity.
  [[nodiscard]] static constexpr result<opaque_bytes> from_bytes(
      std::span<const std::uint8_t> b) noexcept {
    opaque_bytes o;
    if (b.size() > MaxBytes) return {o, errc::text_too_long};
    for (std::size_t i = 0; i < b.size(); ++i) o.bytes_[i] = b[i];
    o.size_ = b.size();
    return {o, errc::ok};
  }
  /// From hex digits, two a byte, either case ("" is no bytes): bad_text for another character
  /// or an odd count of digits, text_too_long past the capacity.
  [[nodiscard]] static constexpr result<opaque_bytes> from_hex(std::string_view hex) noexcept {
    opaque_bytes o;
    if (hex.size() % 2 != 0) return {o, errc::bad_text};
    if (hex.size() / 2 > MaxBytes) return {o, errc::text_too_long};
    for (std::size_t i = 0; i < hex.size(); i += 2) {
      const int hi = seawire::detail::hex_value(hex[i]);
      const int lo = seawire::detail::hex_value(hex[i + 1]);
      if (hi < 0 || lo < 0) return {opaque_bytes{}, errc::bad_text};
      o.bytes_[i / 2] = static_cast<std::uint8_t>(hi * 16 + lo);
    }
    o.size_ = hex.size() / 2;
    return {o, errc::ok};
  }

  [[nodiscard]] constexpr std::span<const std::uint8_t> bytes() const noexcept {
    return {bytes_.data(), size_};
  }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0; }
  /// Always a value (no bytes is sent as none).
  [[nodiscard]] constexpr field_state state() const noexcept { return field_state::value; }
  [[nodiscard]] constexpr bool has_value() const noexcept { return true; }
  [[nodiscard]] constexpr bool fits() const noexcept { return true; }

  [[nodiscard]] constexpr bool operator==(const opaque_bytes& o) const noexcept {
    if (size_ != o.size_) return false;
    for (std::size_t i = 0; i < size_; ++i)
      if (bytes_[i] != o.bytes_[i]) return false;
    return true;
  }

 private:
  std::array<std::uint8_t, MaxBytes> bytes_{};
  std::size_t size_ = 0;
};

namespace detail {
template <class T>
inline constexpr bool is_opaque_bytes = false;
template <std::size_t N>
inline constexpr bool is_opaque_bytes<opaque_bytes<N>> = true;
}  // namespace detail

/// The row of opaque bytes, the last of its table: the payload's bytes after the fixed rows.
/// Takes no bits of the fixed layout (`bits` is 0).
template <auto Member>
struct bytes_entry {
  using value_type = seawire::detail::member_type_t<Member>;
  static_assert(detail::is_opaque_bytes<value_type>,
                "a bytes_to_end row's member must be an opaque_bytes<>");
  static constexpr auto member = Member;
  static constexpr unsigned bits = 0;
  static constexpr bool is_reserved = false;
  static constexpr bool is_bytes = true;
  std::string_view name;
  std::string_view title;
};

/// The bytes from the end of the fixed rows to the end of the payload.
template <auto Member>
[[nodiscard]] constexpr bytes_entry<Member> bytes_to_end(std::string_view name,
                                                         std::string_view title) noexcept {
  return {name, title};
}

/// Opaque bytes that hold a group function's parameter pairs: each a field's number (8 bits,
/// counted from 1 as the named PGN's table counts its rows) in the PGN that the member `Pgn`
/// holds, then that field's value, as wide as the field; `Count` holds how many pairs. The bytes
/// are kept as sent; a reader that knows the named PGN's table can split them
/// (`--format canboat` does).
template <auto Member, auto Pgn, auto Count>
struct pairs_entry : bytes_entry<Member> {
  static constexpr auto pgn_member = Pgn;
  static constexpr auto count_member = Count;
  static constexpr bool is_pairs = true;
};

/// The bytes to the end of the payload as parameter pairs of the PGN `Pgn` holds (pairs_entry).
template <auto Member, auto Pgn, auto Count>
[[nodiscard]] constexpr pairs_entry<Member, Pgn, Count> parameter_pairs(
    std::string_view name, std::string_view title) noexcept {
  return {{name, title}};
}

namespace detail {
/// Whether row type F is opaque bytes to the end of the payload.
template <class F>
concept bytes_row = requires {
  F::is_bytes;
};
/// Whether row type F ends its table by taking the rest of the payload (a group, or bytes).
template <class F>
concept tail_row = group_row<F> || bytes_row<F>;
}  // namespace detail

/// The row that says which of a PGN's layouts a payload has (126208's function code says a
/// request, a command, an acknowledgement...): the struct is the layout for `Value`. A set of
/// PGNs gives a payload to the struct whose match row it holds; encode refuses another value
/// there (wrong_address), so a struct cannot send another layout's function.
template <auto Member, auto Value>
struct match_entry : field_entry<Member> {
  static constexpr std::int64_t match_raw = static_cast<std::int64_t>(Value);
  static constexpr bool is_match = true;
};

template <auto Member, auto Value>
[[nodiscard]] constexpr match_entry<Member, Value> match(std::string_view name,
                                                         std::string_view title) noexcept {
  return {{name, title}};
}

namespace detail {
template <class F>
concept match_row = requires {
  F::is_match;
};
}  // namespace detail

/// How a PGN travels: one CAN frame (up to 8 bytes) or a fast packet (up to 223 bytes).
enum class framing : std::uint8_t { single_frame, fast_packet };

/// What the standard says about a PGN besides its fields.
struct pgn_info {
  std::uint32_t pgn = 0;
  std::string_view name;      ///< snake_case, the C++ struct's name
  std::string_view title;     ///< the PGN's name as canboat's database spells it
  std::uint8_t priority = 6;  ///< default priority (0 highest .. 7)
  framing transport = framing::single_frame;
  std::uint16_t interval_ms = 0;  ///< default transmit interval; 0 = on demand
};

/// The enum of a lookup or flag set type: E of lookup<E, B> and flags<E, B>; void for any other
/// value type.
template <class V>
struct value_enum {
  using type = void;
};
template <class E, unsigned B>
struct value_enum<lookup<E, B>> {
  using type = E;
};
template <class E, unsigned B>
struct value_enum<flags<E, B>> {
  using type = E;
};
template <class V>
using value_enum_t = typename value_enum<V>::type;

namespace detail {
template <class T>
inline constexpr bool is_flag_word = false;
template <class E, unsigned B>
inline constexpr bool is_flag_word<flags<E, B>> = true;
}  // namespace detail

/// How PGN payloads lay out their bits (docs/nmea2000.md).
inline constexpr auto payload_order = seawire::detail::bit_order::lsb_first;

namespace detail {
template <class Row>
[[nodiscard]] consteval bool row_is_text() noexcept {
  if constexpr (Row::is_reserved) {
    return false;
  } else {
    return text_value<typename Row::value_type>;
  }
}
template <class Row>
[[nodiscard]] consteval bool row_is_flag_word() noexcept {
  if constexpr (Row::is_reserved) {
    return false;
  } else {
    return is_flag_word<typename Row::value_type>;
  }
}
template <class Row>
[[nodiscard]] consteval bool row_is_variable() noexcept {
  if constexpr (row_is_text<Row>()) {
    return Row::value_type::variable;
  } else {
    return false;
  }
}
/// Whether every string row of a table starts on a byte boundary.
template <class... F>
[[nodiscard]] consteval bool text_rows_aligned() noexcept {
  unsigned at = 0;
  bool ok = true;
  ((ok = ok && (!row_is_text<F>() || at % 8 == 0), at += F::bits), ...);
  return ok;
}
}  // namespace detail

/// A PGN's table: a binary layout (detail/bit_layout.hpp), each row where the one before ends.
/// A counted string (counted_text) varies in length: the rows after it start where it ends.
template <class... F>
struct pgn_description {
  pgn_info info;
  seawire::detail::row_list<F...> fields;

  /// Whether every row is at a fixed offset (no counted string).
  static constexpr bool fixed_layout = !(detail::row_is_variable<F>() || ...);
  /// The bits of the fixed rows (a repeating group, always last, starts where they end); with a
  /// counted string, every counted string at its longest.
  static constexpr unsigned bit_length =
      seawire::detail::layout_bits<seawire::detail::row_list<F...>>;
  static_assert(bit_length % 8 == 0, "a PGN's fields must fill whole bytes");
  static_assert(detail::text_rows_aligned<F...>(), "a string starts on a byte boundary");
  static_assert(fixed_layout || !(detail::row_is_flag_word<F>() || ...),
                "a flag set cannot end a payload of varying length");
  static_assert(fixed_layout || !(detail::tail_row<F> || ...),
                "a table with a counted string has no repeating group or opaque bytes (they "
                "start at a fixed offset)");
  static_assert(((detail::match_row<F> ? 1 : 0) + ... + 0) <= 1, "a table has one match row");
  /// The payload's least length in bytes: every fixed row, every counted string empty, no
  /// repetition of a group.
  static constexpr std::size_t min_length =
      (0U + ... + (detail::row_is_variable<F>() ? 16U : static_cast<unsigned>(F::bits))) / 8;
  static constexpr std::size_t field_count = sizeof...(F);

 private:
  using last_row = seawire::detail::row_type_t<sizeof...(F) - 1, seawire::detail::row_list<F...>>;
  static_assert(((detail::tail_row<F> ? 1 : 0) + ... + 0) <= (detail::tail_row<last_row> ? 1 : 0),
                "a repeating group or opaque bytes must be the last row of its table");
  static constexpr std::size_t group_bytes = [] {
    if constexpr (detail::group_row<last_row>) {
      using G = typename last_row::value_type;
      static_assert(G::capacity == group_capacity<typename G::item_type>(bit_length / 8),
                    "a group's capacity is what a 223-byte payload holds after the fixed rows "
                    "(group_capacity<Item>(header bytes))");
      return (G::capacity * last_row::item_bits + 7) / 8;
    } else if constexpr (detail::bytes_row<last_row>) {
      using B = typename last_row::value_type;
      static_assert(B::capacity == max_payload_bytes - bit_length / 8,
                    "opaque bytes hold what a 223-byte payload holds after the fixed rows");
      return B::capacity;
    } else {
      return std::size_t{0};
    }
  }();

 public:
  /// Whether the table ends in a repeating group.
  static constexpr bool has_group = detail::group_row<last_row>;
  /// Whether a match row says which of its PGN's layouts the table is (match<>).
  static constexpr bool has_match = (detail::match_row<F> || ...);
  /// The payload's length in bytes: the largest, with a group at its capacity; with a counted
  /// string, the most it may be (a fast packet's 223 bytes at most).
  static constexpr std::size_t length =
      fixed_layout ? bit_length / 8 + group_bytes
                   : std::min<std::size_t>(bit_length / 8, max_fast_packet_length);

  /// fn(entry, bit_offset, number) for every row, reserved ones too, in wire order; `number`
  /// counts from 1 as the table does. What fn returns is ignored: every row is visited.
  template <class Fn>
  constexpr void for_each(Fn&& fn) const {
    detail::each_row(fields, fn);
  }
};

template <class... F>
[[nodiscard]] constexpr pgn_description<F...> describe_pgn(pgn_info info, F... fields) noexcept {
  return {info, seawire::detail::make_rows(fields...)};
}

namespace detail {
/// Whether P declares its table as a constant, `static constexpr auto n2k = describe_pgn(...)`
/// (built where P is declared), or as a function template of P itself, `template <class P>
/// static constexpr auto n2k() { return describe_pgn(...); }` (built where the PGN is first
/// used). Asked in this order: GCC takes `P::template n2k<P>` of a constant for an error, not
/// for a requirement not met.
template <class P>
concept table_constant = requires {
  P::n2k.info.pgn;
};
template <class P>
concept table_function = requires {
  P::template n2k<P>();
};

template <class P>
[[nodiscard]] consteval auto table_of() noexcept {
  if constexpr (table_constant<P>) {
    return P::n2k;
  } else {
    return P::template n2k<P>();
  }
}
}  // namespace detail

/// A PGN struct: has a table, `template <class P> static constexpr auto n2k()` returning
/// describe_pgn(...) of P's members (or the constant `static constexpr auto n2k =
/// describe_pgn(...)`).
template <class P>
concept pgn_like = (detail::table_constant<P> || detail::table_function<P>)&&requires {
  detail::table_of<P>().info.pgn;
};

/// P's table (a pgn_description): built once in a translation unit, where first used, so that a
/// header declaring many PGNs costs only their structs.
template <pgn_like P>
inline constexpr auto pgn_table = detail::table_of<P>();

template <pgn_like P>
using description_of = std::remove_cvref_t<decltype(pgn_table<P>)>;

/// Whether `payload` has P's layout: true unless P's table has a match row (match<>) and the
/// payload holds another value there (or does not hold that row).
template <pgn_like P>
[[nodiscard]] constexpr bool layout_matches(std::span<const std::uint8_t> payload) noexcept {
  if constexpr (!description_of<P>::has_match) {
    return true;
  } else {
    bool ok = false;
    pgn_table<P>.for_each([&](const auto& f, unsigned offset, std::uint16_t) {
      using F = std::remove_cvref_t<decltype(f)>;
      if constexpr (detail::match_row<F>) {
        ok = offset + F::bits <= payload.size() * 8 &&
             seawire::detail::get_bits<payload_order>(payload, offset, F::bits) ==
                 static_cast<std::uint64_t>(F::match_raw);
      }
    });
    return ok;
  }
}

/// The payload of P as bytes.
template <pgn_like P>
using payload_of = std::array<std::uint8_t, description_of<P>::length>;

// ---------------------------------------------------------------------------------------------
// decode and encode

namespace detail {

/// Field row F of a table at bit `offset` of `payload` into `out` (a PGN or a group's
/// repetition): not available when the payload does not hold it in full.
template <class F, class T>
constexpr void decode_field(std::span<const std::uint8_t> payload, unsigned offset,
                            T& out) noexcept {
  using V = typename F::value_type;
  if (offset + F::bits > payload.size() * 8) {
    out.*F::member = V{};  // not available
    return;
  }
  const std::uint64_t u = seawire::detail::get_bits<payload_order>(payload, offset, F::bits);
  auto raw = static_cast<std::int64_t>(u);  // two's complement for a 64-bit field
  if constexpr (V::is_signed && F::bits < 64) {
    if (((u >> (F::bits - 1)) & 1) != 0)
      raw = static_cast<std::int64_t>(u) - (std::int64_t{1} << F::bits);
  }
  out.*F::member = V::from_raw(raw);
}

/// Group row F, starting at bit `offset`, into `out` (its count field already read). It holds
/// as many repetitions as the count says, or for a group to the end (or a count that is not a
/// value: it says nothing) as many as the payload starts; at most the capacity, and never more
/// than the payload starts: a repetition cut short holds the fields it holds in full, the rest
/// not available.
template <class F, class P>
constexpr void decode_group(std::span<const std::uint8_t> payload, unsigned offset,
                            P& out) noexcept {
  using G = typename F::value_type;
  using Item = typename G::item_type;
  const std::size_t have = payload.size() * 8 > offset ? payload.size() * 8 - offset : 0;
  std::size_t n = std::min<std::size_t>(G::capacity, (have + F::item_bits - 1) / F::item_bits);
  if constexpr (F::counted) {
    const auto& count = out.*F::count;
    if (count.has_value()) n = std::min(n, static_cast<std::size_t>(count.raw()));
  }
  G& g = out.*F::member;
  g.clear();
  for (std::size_t i = 0; i < n; ++i) {
    Item item{};
    const auto at = offset + static_cast<unsigned>(i) * F::item_bits;
    Item::n2k_item.for_each([&](const auto& f, unsigned o, std::uint16_t) {
      using R = std::remove_cvref_t<decltype(f)>;
      if constexpr (!R::is_reserved) decode_field<R>(payload, at + o, item);
    });
    (void)g.push_back(item);
  }
}

/// A fixed_text at byte `at` of `payload`: the bytes there, 0xFF past the payload's end (a
/// string cut short keeps what was sent, as canboat's analyzer shows it).
template <class V>
[[nodiscard]] constexpr V read_fixed_text(std::span<const std::uint8_t> payload,
                                          std::size_t at) noexcept {
  return V::from_bytes(payload.subspan(std::min(at, payload.size())));
}

/// decode<P> for a table with a counted string: each row where the one before ended. A counted
/// string takes its length byte's count of bytes, or what the payload still has when the count
/// runs past its end (as canboat's analyzer reads it); a length byte below 2 (less than itself
/// and the encoding byte) is no string: that field and every one after it read as not available.
template <pgn_like P>
[[nodiscard]] constexpr P decode_varying(std::span<const std::uint8_t> payload) noexcept {
  // Bytes past the PGN's longest payload (a fast packet's) are no part of it, as for any PGN.
  payload = payload.first(std::min(payload.size(), description_of<P>::length));
  P out{};
  std::size_t at = 0;  // bits
  bool stop = false;
  seawire::detail::for_each_row(
      pgn_table<P>.fields, 0, [&](const auto& f, unsigned, std::uint16_t) {
        using F = std::remove_cvref_t<decltype(f)>;
        if (stop) return false;
        if constexpr (F::is_reserved) {
          at += F::bits;
        } else {
          using V = typename F::value_type;
          auto& member = out.*F::member;
          if constexpr (row_is_variable<F>()) {
            const std::size_t byte = at / 8;
            if (byte >= payload.size()) return false;  // not sent: this and the rest not available
            const std::size_t left = payload.size() - byte;
            const std::size_t count = payload[byte];
            if (count < 2 || left < 2) {
              stop = true;
              return false;
            }
            const std::size_t taken = std::min(count, left);
            member = V::from_bytes(payload[byte + 1], payload.subspan(byte + 2, taken - 2)).value;
            at += 8 * taken;
          } else if constexpr (row_is_text<F>()) {
            member = read_fixed_text<V>(payload, at / 8);
            at += F::bits;
          } else {
            decode_field<F>(payload, static_cast<unsigned>(at), out);
            at += F::bits;
          }
        }
        return true;
      });
  return out;
}

}  // namespace detail

/// P from a payload. Fields the payload is too short to hold in full read as not available;
/// bytes past P's length and reserved bits are ignored; a repeating group as decode_group says.
/// Never fails.
template <pgn_like P>
[[nodiscard]] constexpr P decode(std::span<const std::uint8_t> payload) noexcept {
  if constexpr (!description_of<P>::fixed_layout) return detail::decode_varying<P>(payload);
  P out{};
  pgn_table<P>.for_each([&](const auto& f, unsigned offset, std::uint16_t) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (detail::group_row<F>) {
      detail::decode_group<F>(payload, offset, out);
    } else if constexpr (detail::bytes_row<F>) {
      using B = typename F::value_type;
      const std::size_t at = std::min<std::size_t>(offset / 8, payload.size());
      const std::size_t n = std::min(B::capacity, payload.size() - at);
      out.*F::member = B::from_bytes(payload.subspan(at, n)).value;
    } else if constexpr (detail::row_is_text<F>()) {
      if constexpr (!detail::row_is_variable<F>())  // a counted string: decode_varying
        out.*F::member = detail::read_fixed_text<typename F::value_type>(payload, offset / 8);
    } else if constexpr (!F::is_reserved) {
      detail::decode_field<F>(payload, offset, out);
    }
  });
  return out;
}

/// The bytes encode() writes for a PGN of `N` bytes: the first size() of `bytes` (fewer than N
/// when a flag set not available ends the payload). A contiguous range, as decode takes.
template <std::size_t N>
struct encoded_bytes {
  std::array<std::uint8_t, N> bytes{};
  std::size_t length = N;

  [[nodiscard]] constexpr std::size_t size() const noexcept { return length; }
  [[nodiscard]] constexpr const std::uint8_t* data() const noexcept { return bytes.data(); }
  [[nodiscard]] constexpr const std::uint8_t* begin() const noexcept { return bytes.data(); }
  [[nodiscard]] constexpr const std::uint8_t* end() const noexcept { return bytes.data() + length; }
  [[nodiscard]] constexpr std::uint8_t operator[](std::size_t i) const noexcept { return bytes[i]; }
  [[nodiscard]] constexpr std::span<const std::uint8_t> view() const noexcept {
    return {bytes.data(), length};
  }
  /// The same bytes, as many.
  [[nodiscard]] constexpr bool operator==(std::span<const std::uint8_t> o) const noexcept {
    if (o.size() != length) return false;
    for (std::size_t i = 0; i < length; ++i)
      if (bytes[i] != o[i]) return false;
    return true;
  }
};

/// What encode<P> returns the bytes in.
template <pgn_like P>
using encoded_payload = encoded_bytes<description_of<P>::length>;

namespace detail {

/// Field row F's value `v` at bit `offset` of `bytes`: its low F::bits bits.
template <class F, class V, std::size_t N>
constexpr void encode_field(std::array<std::uint8_t, N>& bytes, unsigned offset,
                            const V& v) noexcept {
  std::uint64_t mask = ~std::uint64_t{0};
  if constexpr (F::bits < 64) mask = (std::uint64_t{1} << F::bits) - 1;
  seawire::detail::put_bits<payload_order>(bytes, offset, F::bits,
                                           static_cast<std::uint64_t>(v.raw()) & mask);
}

/// The row number and bit offset of the row of P's table whose member is `Member`.
template <pgn_like P, auto Member>
[[nodiscard]] constexpr std::pair<std::uint16_t, unsigned> row_of() noexcept {
  std::pair<std::uint16_t, unsigned> out{0, 0};
  pgn_table<P>.for_each([&](const auto& f, unsigned offset, std::uint16_t n) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (!F::is_reserved) {
      if (seawire::detail::same_member<F::member, Member>) out = {n, offset};
    }
  });
  return out;
}

/// A string's bytes at byte `at` of `out` (room checked by the caller): a fixed_text's bytes, a
/// counted_text's length byte, encoding byte and bytes.
template <std::size_t N, class V>
constexpr void put_text(std::array<std::uint8_t, N>& out, std::size_t at, const V& v) noexcept {
  if constexpr (V::variable) {
    out[at++] = static_cast<std::uint8_t>(v.wire_size());
    out[at++] = v.control();
  }
  for (const char c : v.bytes()) out[at++] = static_cast<std::uint8_t>(c);
}

/// encode<P> for a table with a counted string: each row where the one before ends, the payload
/// as long as its rows. Where the rest does not fit a fast packet and every row left is not
/// available, the payload ends there (a receiver reads them as not available: what decode gives
/// for a string whose length byte ran to the payload's end). text_too_long (field = the row)
/// when a row that does not fit holds a value.
template <pgn_like P>
[[nodiscard]] constexpr result<encoded_payload<P>> encode_varying(const P& msg) noexcept {
  constexpr std::size_t room = description_of<P>::length;
  result<encoded_payload<P>> r;
  r.value.bytes.fill(0xFF);
  std::size_t at = 0;         // bits
  std::uint16_t cut_row = 0;  // the row the payload ended before, 0 while it goes on
  std::size_t cut_at = 0;
  seawire::detail::for_each_row(
      pgn_table<P>.fields, 0, [&](const auto& f, unsigned, std::uint16_t n) {
        using F = std::remove_cvref_t<decltype(f)>;
        const auto fail = [&](errc e) {
          r.ec = e;
          r.field = n;
          r.column = static_cast<std::uint16_t>(at / 8);
          return false;
        };
        bool available = false;
        if constexpr (!F::is_reserved)
          available = (msg.*F::member).state() != field_state::not_available;
        std::size_t bits = F::bits;
        if constexpr (row_is_variable<F>()) bits = 8 * (msg.*F::member).wire_size();
        if (cut_row == 0 && at + bits > 8 * room) {
          cut_row = n;
          cut_at = at;
        }
        if (cut_row != 0) return available ? fail(errc::text_too_long) : true;
        if constexpr (requires { F::is_spare; })
          seawire::detail::put_bits<payload_order>(r.value.bytes, static_cast<unsigned>(at),
                                                   F::bits, 0);
        if constexpr (!F::is_reserved) {
          const auto& v = msg.*F::member;
          if (!v.fits()) return fail(errc::value_too_large);
          if constexpr (detail::match_row<F>) {
            if (v.raw() != F::match_raw) return fail(errc::wrong_address);
          }
          if constexpr (row_is_text<F>()) {
            put_text(r.value.bytes, at / 8, v);
          } else {
            encode_field<F>(r.value.bytes, static_cast<unsigned>(at), v);
          }
        }
        at += bits;
        return true;
      });
  r.value.length = ((cut_row != 0 ? cut_at : at) + 7) / 8;
  return r;
}

}  // namespace detail

/// P's payload: every field at its offset, reserved bits as ones (spare bits as zeros), a field
/// not available as its "not available" value; a flag set not available ends the payload at the
/// byte the word starts in (rounded up). A repeating group's repetitions follow the fixed rows,
/// and the payload ends after the last one held (the count field is written as held: a count
/// larger than the repetitions held, up to the capacity, is sent as it is). Errors, `field` = the
/// first such row number, `column` = the byte the field starts in:
///   value_too_large   a member holds a raw value (from_raw) its width cannot carry (in a
///                     group: the group's row, `column` the repetition's field);
///   missing_field     a flag set is not available but a field after it is not "not available"
///                     either (the word can only be left out with everything after it);
///   out_of_range      a group's count field says more repetitions than its capacity (the
///                     count's row);
///   too_many_fields   a group holds more repetitions than its count field says (a count that
///                     is not a value says nothing: not available, out of range, reserved).
///   wrong_address     the match row (match<>) holds another value than the one that makes the
///                     struct this layout of its PGN;
///   bad_length        a group of repetitions of less than a byte holds ones that do not
///                     fill the last byte, and its count does not say exactly how many (the
///                     group's row).
template <pgn_like P>
[[nodiscard]] constexpr result<encoded_payload<P>> encode(const P& msg) noexcept {
  if constexpr (!description_of<P>::fixed_layout) return detail::encode_varying<P>(msg);
  result<encoded_payload<P>> r;
  r.value.bytes.fill(0xFF);
  std::size_t cut = r.value.length;
  std::uint16_t cut_row = 0;
  unsigned cut_offset = 0;
  const auto fail = [&](errc e, std::uint16_t row, unsigned at) {
    if (r.ec != errc::ok) return;
    r.ec = e;
    r.field = row;
    r.column = static_cast<std::uint16_t>(at / 8);
  };
  pgn_table<P>.for_each([&](const auto& f, unsigned offset, std::uint16_t n) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (requires { F::is_spare; })
      seawire::detail::put_bits<payload_order>(r.value.bytes, offset, F::bits, 0);
    if constexpr (detail::group_row<F>) {
      const auto& g = msg.*F::member;
      if (cut_row != 0) {
        if (!g.empty()) fail(errc::missing_field, cut_row, cut_offset);
        return;
      }
      if constexpr (F::counted) {
        const auto& count = msg.*F::count;
        constexpr auto count_row = detail::row_of<P, F::count>();
        if (count.has_value() && static_cast<std::uint64_t>(count.raw()) > g.capacity) {
          fail(errc::out_of_range, count_row.first, count_row.second);
          return;
        }
        if (count.has_value() && g.size() > static_cast<std::size_t>(count.raw())) {
          fail(errc::too_many_fields, n, offset);
          return;
        }
      }
      using Item = typename F::value_type::item_type;
      unsigned at = offset;
      for (const Item& item : g) {
        Item::n2k_item.for_each([&](const auto& e, unsigned o, std::uint16_t) {
          using R = std::remove_cvref_t<decltype(e)>;
          if constexpr (requires { R::is_spare; }) {
            seawire::detail::put_bits<payload_order>(r.value.bytes, at + o, R::bits, 0);
          } else if constexpr (!R::is_reserved) {
            const auto& v = item.*R::member;
            if (!v.fits()) {
              fail(errc::value_too_large, n, at + o);
              return;
            }
            detail::encode_field<R>(r.value.bytes, at + o, v);
          }
        });
        at += F::item_bits;
      }
      // Repetitions of less than a byte that the count does not say exactly: a receiver
      // counts them by the payload's length, so they must fill its last byte (else it reads
      // the padding as one more).
      if constexpr (F::counted && F::item_bits % 8 != 0) {
        const auto& count = msg.*F::count;
        const bool exact = count.has_value() && static_cast<std::size_t>(count.raw()) == g.size();
        if (!exact && (g.size() * F::item_bits) % 8 != 0) fail(errc::bad_length, n, offset);
      }
      cut = (at + 7) / 8;  // repetitions of less than a byte: the last byte's rest as ones
    } else if constexpr (detail::bytes_row<F>) {
      const auto& b = msg.*F::member;
      if (cut_row != 0) {
        if (!b.empty()) fail(errc::missing_field, cut_row, cut_offset);
        return;
      }
      std::size_t at = offset / 8;
      for (const std::uint8_t byte : b.bytes()) r.value.bytes[at++] = byte;
      cut = at;
    } else if constexpr (!F::is_reserved) {
      const auto& v = msg.*F::member;
      if (!v.fits()) {
        fail(errc::value_too_large, n, offset);
        return;
      }
      if constexpr (detail::match_row<F>) {
        if (v.raw() != F::match_raw) {
          fail(errc::wrong_address, n, offset);
          return;
        }
      }
      if (cut_row != 0) {
        if (v.state() != field_state::not_available) fail(errc::missing_field, cut_row, cut_offset);
        return;
      }
      if constexpr (detail::is_flag_word<typename F::value_type>) {
        if (!v.has_value()) {
          cut = (offset + 7) / 8;
          cut_row = n;
          cut_offset = offset;
          return;
        }
      }
      if constexpr (detail::row_is_text<F>()) {
        detail::put_text(r.value.bytes, offset / 8, v);
      } else {
        detail::encode_field<F>(r.value.bytes, offset, v);
      }
    }
  });
  r.value.length = cut;
  return r;
}

/// The name of row `n` (1-based, reserved rows included) of P's table, for error messages.
template <pgn_like P>
[[nodiscard]] constexpr std::string_view field_name(std::uint16_t n) noexcept {
  std::string_view out;
  pgn_table<P>.for_each([&](const auto& f, unsigned, std::uint16_t k) {
    if (k == n) out = f.name;
  });
  return out;
}

}  // namespace seawire::nmea2000
