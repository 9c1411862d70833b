// SPDX-License-Identifier: BSL-1.0
#pragma once
// Messages with random values inside each field's declared domain, read off the message's
// description: the member type gives the codec's own domain (hours below 24, dates 1980-2079,
// printable text without the characters NMEA reserves, an enum's letters or words) and the
// field's options narrow it (in_range, max_places, length_between, code_chars, may_be_absent,
// only_with_field_count). Whatever a description admits, encode must write and decode must read
// back to the same value; a message with a field type of its own gives that type's values by a
// specialization of support::values<T>. NMEA 2000 PGNs and the ANELLO 0xAB00 frame get raw
// values of every width and range their tables declare. Every message of seawire/registry.hpp
// has a generate<T> here (round_trip_test checks it at compile time).

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "seawire/anello/frame.hpp"
#include "seawire/detail/ascii.hpp"
#include "seawire/detail/calendar.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/variation.hpp"
#include "seawire/nmea2000/field.hpp"
#include "support.hpp"

namespace support {

/// Values of a field type of a family's own, for a test to specialize:
/// `static void fill(prng&, T&, const field_options&)`.
template <class T>
struct values;

namespace generated {

namespace nm = seawire::nmea;

using seawire::detail::pow10_table;

/// Integer digits of |d|'s integer part (1 for zero).
inline unsigned int_digits(const nm::decimal& d) {
  return seawire::detail::digit_count(d.mantissa / pow10_table[d.places]);
}

/// Whether d lies inside the range the options declare. Written here rather than taken from
/// the message layer's own check, so that a wrong check cannot narrow the values it is tested
/// on.
inline bool in_declared_range(const nm::decimal& d, const nm::field_options& o) {
  if (o.has_min && d.compare(o.min) < 0) return false;
  if (o.has_max) {
    const int c = d.compare(o.max);
    if (c > 0 || (c == 0 && o.max_exclusive)) return false;
  }
  return true;
}

/// A decimal with up to `digits` integer digits and up to `max_places` fraction digits
/// (mostly few; sometimes the most the type allows), sometimes zero-padded as senders do.
inline nm::decimal any_decimal(prng& g, unsigned digits, int max_places, bool may_be_negative) {
  nm::decimal d;
  const unsigned most = max_places >= 0 ? static_cast<unsigned>(max_places) : 9U;
  d.places = static_cast<std::uint8_t>(g.below(std::min(most, 9U) + 1));
  d.mantissa = g.below(pow10_table[digits + d.places]);
  d.negative = may_be_negative && g.coin();
  if (g.chance(10)) d.int_width = static_cast<std::uint8_t>(int_digits(d) + g.below(3));
  return d;
}

/// The decimal's bounds as a number of integer digits to draw from: enough to reach both ends
/// (and a few more without an upper end), then values outside are drawn again. The range's
/// ends themselves come up now and then: they are the cases a codec gets wrong.
inline nm::decimal bounded_decimal(prng& g, const nm::field_options& o) {
  if (o.has_min && o.has_max && g.chance(5)) {
    nm::decimal end = g.coin() ? o.min : o.max;
    if (in_declared_range(end, o) && (o.max_places < 0 || end.places <= o.max_places)) return end;
  }
  unsigned digits = 6;  // an end left open: numbers of up to six integer digits
  if (o.has_min && o.has_max) {
    digits = std::max(int_digits(o.min), int_digits(o.max));
  } else if (o.has_min) {
    digits = std::max(digits, int_digits(o.min));
  }
  const bool may_be_negative = !o.has_min || o.min.negative;
  for (;;) {
    const nm::decimal d = any_decimal(g, digits, o.max_places, may_be_negative);
    if (in_declared_range(d, o)) return d;
  }
}

template <std::integral I>
I bounded_integer(prng& g, const nm::field_options& o) {
  const auto lo_of = [](const nm::decimal& d) {
    const auto v = static_cast<std::int64_t>(d.mantissa / pow10_table[d.places]);
    return d.negative ? -v : v;
  };
  std::int64_t lo = static_cast<std::int64_t>(std::numeric_limits<I>::min());
  std::int64_t hi = std::numeric_limits<I>::max() > static_cast<std::uint64_t>(INT64_MAX)
                        ? INT64_MAX
                        : static_cast<std::int64_t>(std::numeric_limits<I>::max());
  if (o.has_min) lo = std::max(lo, lo_of(o.min));
  if (o.has_max) hi = std::min(hi, lo_of(o.max) - (o.max_exclusive ? 1 : 0));
  // Mostly small numbers, the kind senders write; sometimes anywhere in the domain.
  if (g.chance(70) && hi - lo > 1000) {
    const std::int64_t small_lo = std::max<std::int64_t>(lo, -500);
    return static_cast<I>(g.between(small_lo, std::min<std::int64_t>(hi, small_lo + 1000)));
  }
  return static_cast<I>(g.between(lo, hi));
}

inline nm::time_of_day any_time(prng& g, const nm::field_options& o) {
  nm::time_of_day t;
  t.hour = static_cast<std::uint8_t>(g.below(24));
  t.minute = static_cast<std::uint8_t>(g.below(60));
  t.second = static_cast<std::uint8_t>(g.below(60));
  if (g.chance(2)) t = {23, 59, 60, 0, 0};  // a leap second
  const unsigned most = o.max_places >= 0 ? static_cast<unsigned>(o.max_places) : 9U;
  t.places = static_cast<std::uint8_t>(g.below(most + 1));
  t.fraction = static_cast<std::uint32_t>(g.below(pow10_table[t.places]));
  return t;
}

inline nm::date any_date(prng& g) {
  nm::date d;
  d.year = static_cast<std::uint16_t>(1980 + g.below(100));
  d.month = static_cast<std::uint8_t>(1 + g.below(12));
  d.day = static_cast<std::uint8_t>(1 + g.below(seawire::detail::days_in_month(d.month, d.year)));
  return d;
}

/// Text of a length the options allow, of characters the field allows: upper-case letters and
/// digits for a code, otherwise any printable character NMEA does not reserve.
template <std::size_t N>
nm::text<N> any_text(prng& g, const nm::field_options& o) {
  std::string chars;
  for (int c = 0x20; c < 0x7F; ++c) {
    const char ch = static_cast<char>(c);
    const bool code = seawire::detail::is_upper(ch) || seawire::detail::is_digit(ch);
    if (o.code_chars ? code : !seawire::detail::is_reserved(ch)) chars += ch;
  }
  const std::size_t most = std::min<std::size_t>(o.max_length, N);
  const std::size_t least = std::min<std::size_t>(o.min_length, most);
  // Short text mostly; the longest the field holds now and then.
  std::size_t n =
      g.chance(10) ? most : least + g.below(std::min<std::size_t>(most - least, 24) + 1);
  std::string s;
  for (std::size_t i = 0; i < n; ++i) s += chars[g.below(chars.size())];
  nm::text<N> t;
  (void)t.assign(s);
  return t;
}

template <class Axis>
void fill_position(prng& g, nm::nmea_coordinate<Axis>& c) {
  c.whole_degrees = static_cast<std::uint16_t>(g.below(Axis::max_degrees + 1U));
  c.minutes.places = static_cast<std::uint8_t>(g.below(13));
  c.minutes.mantissa =
      c.whole_degrees == Axis::max_degrees ? 0 : g.below(60 * pow10_table[c.minutes.places]);
  c.hemi = static_cast<nm::hemisphere>(g.coin() ? Axis::positive : Axis::negative);
  // 0 writes the degrees naturally; up to the axis's width pads them ("007").
  c.degree_digits = static_cast<std::uint8_t>(g.below(Axis::width + 1U));
}

template <class Axis>
void fill_position(prng& g, nm::decimal_coordinate<Axis>& c) {
  do {
    c.value = any_decimal(g, 3, 9, false);
  } while (c.value.compare(nm::decimal(Axis::max_degrees)) > 0);
  c.hemi = static_cast<nm::hemisphere>(g.coin() ? Axis::positive : Axis::negative);
}

inline nm::magnetic_variation any_variation(prng& g) {
  nm::magnetic_variation v;
  if (!g.chance(10)) {
    nm::field_options o;
    o.has_min = o.has_max = true;
    o.min = 0;
    o.max = 180;
    v.value = bounded_decimal(g, o);
  }
  v.direction = g.coin() ? nm::hemisphere::east : nm::hemisphere::west;
  return v;
}

template <class T>
inline constexpr bool is_text = false;
template <std::size_t N>
inline constexpr bool is_text<nm::text<N>> = true;

/// A value of type V inside the domain its codec and the options `o` declare.
template <class V>
void fill(prng& g, V& v, const nm::field_options& o) {
  if constexpr (std::is_same_v<V, bool>) {
    v = g.coin();
  } else if constexpr (std::is_integral_v<V>) {
    v = bounded_integer<V>(g, o);
  } else if constexpr (nm::is_integer_wrapper<V>) {
    v = bounded_integer<typename V::value_type>(g, o);
  } else if constexpr (std::is_same_v<V, nm::decimal>) {
    v = bounded_decimal(g, o);
  } else if constexpr (std::is_same_v<V, nm::time_of_day>) {
    v = any_time(g, o);
  } else if constexpr (std::is_same_v<V, nm::date>) {
    v = any_date(g);
  } else if constexpr (is_text<V>) {
    v = any_text<V::capacity>(g, o);
  } else if constexpr (nm::is_ddmm_position<V> || nm::is_degrees_position<V>) {
    fill_position(g, v);
  } else if constexpr (std::is_same_v<V, nm::magnetic_variation>) {
    v = any_variation(g);
  } else if constexpr (nm::char_enum_like<V>) {
    constexpr std::string_view letters = seawire::nmea::enum_letters<V>;
    v = static_cast<V>(letters[g.below(letters.size())]);
  } else if constexpr (nm::word_enum_like<V>) {
    v = static_cast<V>(g.below(enum_words(V{}).size()));
  } else {
    values<V>::fill(g, v, o);
  }
}

}  // namespace generated

/// A message with every field drawn from its declared domain (and the talker of a "--"
/// sentence). An empty optional text field is written
/// as a blank and read back as empty text, so it stays empty only where encode leaves it out
/// altogether (may_be_absent or only_with_field_count, with nothing written after it).
template <seawire::nmea::message_like M>
M generate(prng& g) {
  namespace nm = seawire::nmea;
  M m{};
  using desc = std::remove_cvref_t<decltype(M::nmea)>;
  if constexpr (desc::any_talker) {
    constexpr std::string_view upper = "ABCDEFGHIJKLMNOQRSTUVWXYZ";  // no 'P': proprietary
    constexpr std::string_view second = "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    const char t[2] = {upper[g.below(upper.size())], second[g.below(second.size())]};
    (void)nm::detail::talker_of(m).assign(std::string_view(t, 2));
  }
  M::nmea.fields.apply([&](const auto&... d) {
    const auto one = [&](const auto& f) {
      using F = std::remove_cvref_t<decltype(f)>;
      auto& member = m.*F::member;
      if constexpr (F::is_optional) {
        // Empty one time in four; every other time for a field that may be left out, so
        // that the shorter forms come up too.
        const bool may_be_left_out = f.opts.may_be_absent || f.opts.only_with_field_count != 0;
        if (g.below(may_be_left_out ? 2 : 4) == 0) {
          member.reset();
        } else {
          typename F::value_type v{};
          generated::fill(g, v, f.opts);
          member = v;
        }
      } else {
        generated::fill(g, member, f.opts);
      }
    };
    (one(d), ...);
  });
  // From the last field back: an empty optional field is left out of the sentence when it is
  // of only the longer form, or may be absent with nothing written after it; otherwise it is
  // written blank, which reads back as empty for every type but text (blank text is empty
  // text), so an empty text field there gets a value.
  bool later_written = false;
  M::nmea.fields.apply([&](const auto&... d) {
    const auto one = [&](const auto& f) {
      using F = std::remove_cvref_t<decltype(f)>;
      if constexpr (F::is_optional) {
        auto& member = m.*F::member;
        if (!member) {
          const bool left_out =
              f.opts.only_with_field_count != 0 || (f.opts.may_be_absent && !later_written);
          if (left_out) return;
          if constexpr (generated::is_text<typename F::value_type>) {
            typename F::value_type v{};
            generated::fill(g, v, f.opts);
            member = v;
          }
        }
      }
      later_written = true;
    };
    // Right to left: the comma operator over a reversed pack is not available, so recurse.
    const auto reversed = [&](const auto& self, const auto& first, const auto&... rest) -> void {
      if constexpr (sizeof...(rest) > 0) self(self, rest...);
      one(first);
    };
    if constexpr (sizeof...(d) > 0) reversed(reversed, d...);
  });
  return m;
}

/// A byte of a string as senders send them: one time in four a byte the text ends at or is
/// padded with (0x00, 0xFF, '@', a space), otherwise any byte.
inline std::uint8_t text_byte(prng& g) {
  constexpr std::uint8_t special[] = {0x00, 0xFF, '@', ' '};
  return g.below(4) == 0 ? special[g.below(4)] : static_cast<std::uint8_t>(g.below(256));
}

/// A string field's bytes as sent: a fixed string's every byte; a counted string's encoding byte
/// (ASCII, UTF-16 or another) and up to 70 bytes (three fit a fast packet).
template <seawire::nmea2000::text_value V>
V generate_text(prng& g) {
  std::array<std::uint8_t, V::capacity> b{};
  if constexpr (V::variable) {
    const std::size_t n = g.below(std::min<std::size_t>(V::capacity, 70) + 1);
    for (std::size_t i = 0; i < n; ++i) b[i] = text_byte(g);
    const auto control = static_cast<std::uint8_t>(g.chance(10) ? g.below(256) : g.below(2));
    return V::from_bytes(control, std::span<const std::uint8_t>(b.data(), n)).value;
  } else {
    for (auto& c : b) c = text_byte(g);
    return V::from_bytes(b);
  }
}

/// A PGN message with a raw value in every field, drawn from what the field's width holds (the
/// not-available and out-of-range sentinels included: senders send them); reserved bits are not
/// members.
namespace detail {
/// A raw value of field row F for `out`'s member, as generate<P> draws it.
template <class F, class T>
void generate_field(prng& g, T& out) {
  using V = typename F::value_type;
  const std::int64_t top = V::top_raw;
  const std::int64_t low = V::is_signed ? -top - 1 : 0;
  V v =
      V::from_raw(g.chance(10) ? top - static_cast<std::int64_t>(g.below(3)) : g.between(low, top));
  while (!v.fits()) v = V::from_raw(g.between(low, top));
  out.*F::member = v;
}
}  // namespace detail

/// A PGN message with a raw value in every field, drawn from what the field's width holds (the
/// not-available and out-of-range sentinels included: senders send them); reserved bits are not
/// members. A string: generate_text. A repeating group gets 0 to its capacity repetitions (a full
/// one 8 times in 100), its count field that many, or sometimes more up to the capacity (a sender's
/// count the payload did not hold in full), or a sentinel (which says nothing). Opaque bytes: 0 to
/// their capacity random bytes. A match row keeps the struct's own layout.
template <seawire::nmea2000::pgn_like P>
P generate(prng& g) {
  P m{};
  seawire::nmea2000::pgn_table<P>.for_each([&](const auto& f, unsigned, std::uint16_t) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (seawire::nmea2000::detail::row_is_text<F>()) {
      m.*F::member = generate_text<typename F::value_type>(g);
    } else if constexpr (seawire::nmea2000::detail::group_row<F>) {
      using G = typename F::value_type;
      using Item = typename G::item_type;
      auto& group = m.*F::member;
      group.clear();
      // At most what the count can say (an 8-bit count says 252 of 434 4-bit repetitions).
      std::size_t most = G::capacity;
      if constexpr (F::counted)
        most = std::min<std::size_t>(
            most,
            static_cast<std::size_t>(std::remove_cvref_t<decltype(m.*F::count)>::max_valid_raw));
      std::size_t n = g.chance(8) ? most : static_cast<std::size_t>(g.below(most + 1));
      if constexpr (F::counted) {
        using C = std::remove_cvref_t<decltype(m.*F::count)>;
        if (g.chance(10)) {  // a sentinel: says nothing
          m.*F::count = C::from_raw(C::top_raw - static_cast<std::int64_t>(g.below(3)));
        } else {
          const std::size_t extra = g.chance(10) ? g.below(most - n + 1) : 0;
          m.*F::count = C::from_raw(static_cast<std::int64_t>(n + extra));
        }
        if ((m.*F::count).has_value())
          n = std::min(n, static_cast<std::size_t>((m.*F::count).raw()));
        // Repetitions of less than a byte the count does not say exactly fill the last byte
        // (a receiver counts them by the payload's length).
        constexpr std::size_t per_byte = F::item_bits < 8 ? 8 / F::item_bits : 1;
        const auto& c = m.*F::count;
        if (!(c.has_value() && static_cast<std::size_t>(c.raw()) == n)) n -= n % per_byte;
      }
      for (std::size_t i = 0; i < n; ++i) {
        Item item{};
        Item::n2k_item.for_each([&](const auto& e, unsigned, std::uint16_t) {
          using R = std::remove_cvref_t<decltype(e)>;
          if constexpr (!R::is_reserved) detail::generate_field<R>(g, item);
        });
        (void)group.push_back(item);
      }
    } else if constexpr (seawire::nmea2000::detail::bytes_row<F>) {
      using B = typename F::value_type;
      std::array<std::uint8_t, B::capacity> b{};
      const std::size_t n = g.chance(8) ? B::capacity : g.below(B::capacity + 1);
      for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<std::uint8_t>(g.below(256));
      m.*F::member = B::from_bytes(std::span<const std::uint8_t>(b.data(), n)).value;
    } else if constexpr (seawire::nmea2000::detail::match_row<F>) {
      // the struct's own layout (the value its member starts with)
    } else if constexpr (!F::is_reserved) {
      // a group's count is drawn with its group (the row after it)
      detail::generate_field<F>(g, m);
    }
  });
  return m;
}

/// An ANELLO 0xAB00 frame: each field not available one time in eight, otherwise a wire value
/// inside what a sender may write (sensor_field::wire_limits).
template <class T>
requires std::is_same_v<T, seawire::anello::sensor_frame_raw> T generate(prng& g) {
  T frame{};
  seawire::anello::sensor_fields.apply([&](const auto&... field) {
    const auto one = [&](const auto& f) {
      using F = std::remove_cvref_t<decltype(f)>;
      using raw = typename F::raw_type;
      if (g.below(8) == 0) return;  // left at "not available"
      auto [lo, hi] = f.wire_limits();
      // A time: up to the year 2100 in milliseconds, what a GPS clock gives.
      if constexpr (std::is_same_v<typename F::value_type, seawire::anello::time_ms>)
        hi = std::min<std::int64_t>(hi, std::int64_t{4102444800000});
      frame.*F::raw_member = static_cast<raw>(g.between(lo, hi));
    };
    (one(field), ...);
  });
  return frame;
}

/// Whether generate<T> gives values of T: true of every message the registry lists.
template <class T>
concept generated_type = requires(prng& g) {
  { generate<T>(g) } -> std::same_as<T>;
};

}  // namespace support
