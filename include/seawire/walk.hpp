// SPDX-License-Identifier: BSL-1.0
#pragma once
// One walk over the fields of a message of any wire: an NMEA 0183 sentence (message_like), an
// NMEA 2000 PGN (pgn_like) or ANELLO's 0xAB00 frame (sensor_frame_raw). JSON, CSV, fmt and the
// docs are loops over it: visit_fields(msg, fn) calls fn(field_view) once per field in wire
// order, visit_layout<M>(fn) fn(field_layout) without a message, visit_rows<M>(fn) a PGN's
// reserved bits too. What a field_layout says is a compile-time constant (its members below).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>

#include "seawire/anello/frame.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/detail/member.hpp"
#include "seawire/nmea/decimal.hpp"
#include "seawire/nmea/description.hpp"
#include "seawire/nmea/variation.hpp"
#include "seawire/nmea2000/field.hpp"

namespace seawire {

/// Which wire a field is of.
enum class wire_kind : std::uint8_t { nmea0183, nmea2000, anello_frame };

/// How a field's bytes are laid out: as text between commas, or as a binary field of either
/// byte order.
enum class byte_order : std::uint8_t { text, little_endian, big_endian };

/// What a position-typed field holds.
enum class position_axis : std::uint8_t { none, latitude, longitude };

/// What a field's value means, on every wire: a value, blank / not available, or a PGN field's
/// out_of_range and reserved sentinels.
using field_state = nmea2000::field_state;

namespace detail {
/// Row I (numbered from 1) of a binary wire's table, at `Offset` bits, `Bits` wide.
template <wire_kind Kind, byte_order Order, std::size_t I, unsigned Offset, unsigned Bits>
struct binary_field {
  static constexpr wire_kind kind = Kind;
  static constexpr std::uint16_t number = static_cast<std::uint16_t>(I + 1);
  static constexpr unsigned wire_fields = 1;
  static constexpr unsigned bit_offset = Offset;
  static constexpr unsigned bits = Bits;
  static constexpr byte_order order = Order;
};

/// The unit a field's name ends with, by seawire's naming rule (speed_water_mps, heading_deg,
/// altitude_m); "" for a name that ends with no unit.
[[nodiscard]] constexpr std::string_view unit_of_name(std::string_view name) noexcept {
  constexpr std::string_view units[] = {"deg", "mps", "m",   "pct", "hpa",   "c",     "k",    "rpm",
                                        "pa",  "s",   "v",   "a",   "knots", "kmh",   "degs", "rad",
                                        "kpa", "l",   "lph", "hz",  "ms",    "radps", "ah"};
  const std::size_t at = name.rfind('_');
  if (at == std::string_view::npos) return {};
  const std::string_view last = name.substr(at + 1);
  for (const std::string_view u : units)
    if (u == last) return u;
  return {};
}
}  // namespace detail

/// A field of a message type, without a message (visit_layout); Info is the wire's walk_field.
template <class Info>
struct field_layout {
  using info = Info;
  using value_type = typename Info::value_type;
  static constexpr wire_kind kind = Info::kind;
  static constexpr std::string_view name = Info::name;  ///< declared: "speed_water_mps"
  /// JSON key: the name, but "latitude"/"longitude" for the frame's position.
  static constexpr std::string_view key = Info::key;
  static constexpr std::string_view unit = detail::unit_of_name(Info::name);  ///< "mps", or ""
  /// A sentence's first wire field (1-based, longest form), a PGN's row (reserved rows counted),
  /// the frame's field number (heading 1 .. pressure 19).
  static constexpr std::uint16_t number = Info::number;
  static constexpr unsigned wire_fields = Info::wire_fields;  ///< a position and its letter: 2
  /// A binary field's first bit (the frame's from its first byte), width and byte order.
  static constexpr unsigned bit_offset = Info::bit_offset;
  static constexpr unsigned bits = Info::bits;
  static constexpr byte_order order = Info::order;
  static constexpr position_axis axis = Info::axis;
  static constexpr bool reserved = Info::reserved;  ///< a PGN's reserved bits (visit_rows only)
  static constexpr const auto& desc = Info::desc;   ///< the description's own row
};

/// A field of a message (visit_fields): its layout, the member as the message holds it (the
/// frame's: a frame_value made from the raw integer) and its state: not_available for a blank
/// optional, a variation without a value, a PGN or frame field not available; out_of_range or
/// reserved for a PGN field's sentinels, and for a frame field build_frame would refuse (the
/// value is still there: the frame has no sentinel for it).
template <class Info>
struct field_view : field_layout<Info> {
  using held = std::conditional_t<Info::by_value, typename Info::value_type,
                                  const typename Info::value_type&>;
  held value;
  field_state state = field_state::value;

  [[nodiscard]] constexpr bool has_value() const noexcept { return state == field_state::value; }
};

}  // namespace seawire

// ---------------------------------------------------------------------------------------------
// the wires' fields

namespace seawire::nmea {

namespace detail {
template <class V>
[[nodiscard]] consteval position_axis axis_of() noexcept {
  if constexpr (std::is_same_v<V, latitude> || std::is_same_v<V, decimal_latitude>) {
    return position_axis::latitude;
  } else if constexpr (std::is_same_v<V, longitude> || std::is_same_v<V, decimal_longitude>) {
    return position_axis::longitude;
  } else {
    return position_axis::none;
  }
}

// The first wire field (1-based) of descriptor I of T, in the longest form.
template <class T, std::size_t I>
[[nodiscard]] consteval std::uint16_t first_wire_field() noexcept {
  unsigned n = 1;
  std::size_t i = 0;
  T::nmea.fields.apply([&](const auto&... d) { ((n += i++ < I ? d.width() : 0U), ...); });
  return static_cast<std::uint16_t>(n);
}
}  // namespace detail

/// Field I of sentence T, for the walk (walk.hpp).
template <class T, std::size_t I>
struct walk_field {
  static constexpr const auto& desc = field_at<I>(T::nmea.fields);
  using desc_type = std::remove_cvref_t<decltype(desc)>;
  using value_type = typename desc_type::member_type;
  static constexpr bool by_value = false;
  static constexpr wire_kind kind = wire_kind::nmea0183;
  static constexpr std::string_view name = desc.name;
  static constexpr std::string_view key = desc.name;
  static constexpr std::uint16_t number = detail::first_wire_field<T, I>();
  static constexpr unsigned wire_fields = desc.width();
  static constexpr unsigned bit_offset = 0;
  static constexpr unsigned bits = 0;
  static constexpr byte_order order = byte_order::text;
  static constexpr position_axis axis = detail::axis_of<typename desc_type::value_type>();
  static constexpr bool reserved = false;

  [[nodiscard]] static constexpr const value_type& value(const T& msg) noexcept {
    return msg.*desc_type::member;
  }
  [[nodiscard]] static constexpr field_state state(const value_type& v) noexcept {
    if constexpr (desc_type::is_optional) {
      if (!v.has_value()) return field_state::not_available;
    }
    if constexpr (std::is_same_v<typename desc_type::value_type, magnetic_variation>) {
      if constexpr (desc_type::is_optional) {
        if (!v->value) return field_state::not_available;
      } else {
        if (!v.value) return field_state::not_available;
      }
    }
    return field_state::value;
  }
};

}  // namespace seawire::nmea

namespace seawire::nmea2000 {

namespace detail {
template <class Rows, std::size_t I>
[[nodiscard]] consteval unsigned row_offset() noexcept {
  return [&]<std::size_t... J>(std::index_sequence<J...>) {
    return (0U + ... + static_cast<unsigned>(seawire::detail::row_type_t<J, Rows>::bits));
  }
  (std::make_index_sequence<I>{});
}
template <class Row, bool Reserved = Row::is_reserved>
struct row_value {
  using type = typename Row::value_type;
};
template <class Row>
struct row_value<Row, true> {
  using type = void;
};
// A keyed field is walked with its key's value beside it (its name needs both).
template <class Row>
requires keyed_row<Row>
struct row_value<Row, false> {
  using type = keyed_reading<typename Row::value_type>;
};
/// The rows of a PGN's table, or of one repetition of a repeating group's.
template <class P>
[[nodiscard]] consteval const auto& rows_of() noexcept {
  if constexpr (pgn_like<P>) {
    return nmea2000::pgn_table<P>.fields;
  } else {
    return P::n2k_item.fields;
  }
}
template <class P>
using rows_type = std::remove_cvref_t<decltype(rows_of<P>())>;
}  // namespace detail

/// Row I of PGN P's table (or of a group's repetition P, its offsets from the repetition's first
/// bit), for the walk (walk.hpp).
template <class P, std::size_t I>
struct walk_field
    : seawire::detail::binary_field<wire_kind::nmea2000, byte_order::little_endian, I,
                                    detail::row_offset<detail::rows_type<P>, I>(),
                                    seawire::detail::row_type_t<I, detail::rows_type<P>>::bits> {
  using row_type = seawire::detail::row_type_t<I, detail::rows_type<P>>;
  static constexpr const auto& desc = seawire::detail::row_at<I>(detail::rows_of<P>());
  using value_type = typename detail::row_value<row_type>::type;
  static constexpr bool by_value = keyed_row<row_type>;
  static constexpr std::string_view name = desc.name;
  static constexpr std::string_view key = desc.name;
  static constexpr position_axis axis = position_axis::none;
  static constexpr bool reserved = row_type::is_reserved;

  // (Templates, since a reserved row has neither.)
  template <class Msg>
  [[nodiscard]] static constexpr decltype(auto) value(const Msg& msg) noexcept {
    if constexpr (keyed_row<row_type>) {
      const auto& k = msg.*row_type::key_member;
      return value_type{msg.*row_type::member, k.raw(), k.has_value()};
    } else {
      return (msg.*row_type::member);
    }
  }
  template <class V>
  [[nodiscard]] static constexpr field_state state(const V& v) noexcept {
    return v.state();
  }
};

}  // namespace seawire::nmea2000

namespace seawire::anello {

/// A frame field's value as the walk gives it: the wire's integer and its scale (physical value =
/// raw / 10^places), or milliseconds of Unix time for gps_time.
template <class Raw, unsigned Places, bool Time>
struct frame_value {
  using raw_type = Raw;
  static constexpr unsigned places = Places;
  static constexpr bool is_time = Time;
  Raw raw{};

  /// The value as the decimal it stands for, exactly (raw 893 at one place is 89.3).
  [[nodiscard]] constexpr nmea::decimal exact() const noexcept {
    nmea::decimal d;
    d.negative = raw < 0;
    d.mantissa = seawire::detail::magnitude(raw);
    d.places = static_cast<std::uint8_t>(Places);
    return d;
  }
};

/// Field I of the frame's table (anello::sensor_fields), for the walk (walk.hpp).
template <std::size_t I>
struct walk_field
    : seawire::detail::binary_field<wire_kind::anello_frame, byte_order::big_endian, I,
                                    8 * static_cast<unsigned>(
                                            seawire::detail::row_at<I>(sensor_fields).offset),
                                    seawire::detail::row_type_t<I, decltype(sensor_fields)>::bits> {
  static constexpr const auto& desc = seawire::detail::row_at<I>(sensor_fields);
  using desc_type = std::remove_cvref_t<decltype(desc)>;
  using value_type = frame_value<typename desc_type::raw_type, detail::divisor_places(desc.divisor),
                                 std::is_same_v<typename desc_type::value_type, time_ms>>;
  static constexpr bool by_value = true;
  static constexpr std::string_view name = desc.name;
  static constexpr std::string_view key = desc.json_key;
  static constexpr position_axis axis =
      seawire::detail::same_member<desc_type::value_member, &sensor_values::latitude_deg>
          ? position_axis::latitude
      : seawire::detail::same_member<desc_type::value_member, &sensor_values::longitude_deg>
          ? position_axis::longitude
          : position_axis::none;
  static constexpr bool reserved = false;

  [[nodiscard]] static constexpr value_type value(const sensor_frame_raw& frame) noexcept {
    return {frame.*desc_type::raw_member};
  }
  [[nodiscard]] static constexpr field_state state(const value_type& v) noexcept {
    if (desc.not_available(v.raw)) return field_state::not_available;
    // A value build_frame would refuse: outside the spec's range or the wire type's.
    return desc.acceptable(v.raw) ? field_state::value : field_state::out_of_range;
  }
};

}  // namespace seawire::anello

namespace seawire {

namespace detail {
/// How the walk sees a message type: its number of rows and row I's walk_field.
template <class M>
struct walk_of;

template <class T>
requires nmea::message_like<T>
struct walk_of<T> {
  static constexpr std::size_t size = std::remove_cvref_t<decltype(T::nmea.fields)>::size;
  template <std::size_t I>
  using field = nmea::walk_field<T, I>;
};

template <class P>
requires nmea2000::pgn_like<P>
struct walk_of<P> {
  static constexpr std::size_t size = nmea2000::description_of<P>::field_count;
  template <std::size_t I>
  using field = nmea2000::walk_field<P, I>;
};

/// One repetition of a PGN's repeating group: its rows as a PGN's.
template <class Item>
requires nmea2000::group_item<Item>
struct walk_of<Item> {
  static constexpr std::size_t size = std::remove_cvref_t<decltype(Item::n2k_item)>::field_count;
  template <std::size_t I>
  using field = nmea2000::walk_field<Item, I>;
};

template <>
struct walk_of<anello::sensor_frame_raw> {
  static constexpr std::size_t size = anello::sensor_field_count;
  template <std::size_t I>
  using field = anello::walk_field<I>;
};
}  // namespace detail

/// A message type the walk knows: a sentence, a PGN (or one repetition of its repeating group)
/// or the 0xAB00 frame.
template <class M>
concept walkable = requires {
  detail::walk_of<M>::size;
};

/// fn(field_layout) for every row of M's description in wire order, a PGN's reserved bits too
/// (layout.reserved says which).
template <walkable M, class Fn>
constexpr void visit_rows(Fn&& fn) {
  using W = detail::walk_of<M>;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (fn(field_layout<typename W::template field<I>>{}), ...);
  }
  (std::make_index_sequence<W::size>{});
}

namespace detail {
// One row of the walks below (not a lambda in the pack expansion: clang 14 fails on that).
template <class F, class Fn>
constexpr void walk_layout_row(Fn& fn) {
  if constexpr (!F::reserved) fn(field_layout<F>{});
}
template <class F, class M, class Fn>
SEAWIRE_ALWAYS_INLINE constexpr void walk_field_row(const M& msg, Fn& fn) {
  if constexpr (!F::reserved) {
    const auto& value = F::value(msg);
    const field_view<F> view{{}, value, F::state(value)};
    fn(view);
  }
}
template <class W, class M, class Fn, std::size_t... I>
SEAWIRE_ALWAYS_INLINE constexpr void walk_fields(const M& msg, Fn& fn, std::index_sequence<I...>) {
  (walk_field_row<typename W::template field<I>>(msg, fn), ...);
}
}  // namespace detail

/// fn(field_layout) for every field of M in wire order: for headers, documentation, schemas.
template <walkable M, class Fn>
constexpr void visit_layout(Fn&& fn) {
  using W = detail::walk_of<M>;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (detail::walk_layout_row<typename W::template field<I>>(fn), ...);
  }
  (std::make_index_sequence<W::size>{});
}

/// fn(field_view) for every field of `msg` in wire order, once each.
template <walkable M, class Fn>
SEAWIRE_ALWAYS_INLINE constexpr void visit_fields(const M& msg, Fn&& fn) {
  using W = detail::walk_of<M>;
  detail::walk_fields<W>(msg, fn, std::make_index_sequence<W::size>{});
}

/// The number of fields visit_fields gives for M.
template <walkable M>
inline constexpr std::size_t field_count_of = [] {
  std::size_t n = 0;
  visit_layout<M>([&](auto) { ++n; });
  return n;
}();

}  // namespace seawire
