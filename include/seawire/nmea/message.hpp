// SPDX-License-Identifier: BSL-1.0
#pragma once
// The message description: one declaration per message, from which decode, encode, field
// names and validation all follow. A message is a plain struct with a static `nmea` member:
//
//   // $PYDIR,<thrust_left>,<thrust_right>*hh
//   struct pydir {
//     decimal thrust_left;   // 1 percent, -100..100
//     decimal thrust_right;  // 2 percent, -100..100
//     static constexpr auto nmea = sentence<"PYDIR">(
//         field<&pydir::thrust_left>("thrust_left", in_range(-100, 100)),
//         field<&pydir::thrust_right>("thrust_right", in_range(-100, 100)));
//   };
//
// Two words are used in one sense throughout: a field is *blank* when it is in the sentence
// but empty (",,"), and *absent* when the sentence ends before it (may_be_absent, the codecs'
// allows_blank, parse_policy::absent_as_blank). Member types pick their codec (fields.hpp);
// std::optional<T> marks a field that may be blank (nullopt). Options after the name add a
// range, a unit letter field, or say when a field may be absent. What the sentence declares
// besides its fields follows them (sentence_desc): an address starting with "--" ("--RMC")
// matches any talker and names the talker_id member that decode fills and encode writes with
// `.talker_in<&rmc::talker>()`.

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

#include "seawire/detail/fixed_string.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"

namespace seawire::nmea {

// ---------------------------------------------------------------------------------------------
// field options

/// Everything a field declaration can add to its codec. Built from the option helpers below,
/// each of which sets the member of its name (the range helpers set min and max).
struct field_options {
  decimal min{};
  decimal max{};
  bool has_min = false;
  bool has_max = false;
  bool max_exclusive = false;
  std::int8_t max_places = -1;  ///< fraction digits allowed (decimal, time); -1 = any
  char unit = 0;                ///< unit letter in the following wire field, e.g. 'N'
  std::uint16_t only_with_field_count =
      0;                              ///< present only in sentences of at least this many fields
  bool may_be_absent = false;         ///< trailing: a nullopt value is not written at all
  std::uint16_t min_length = 0;       ///< text: fewest characters
  std::uint16_t max_length = 0xFFFF;  ///< text: most characters
  std::uint8_t zero_pad = 0;          ///< integers: write at least this many digits ("06")
  bool code_chars = false;            ///< text: upper-case letters and digits only ("NVG")
  /// Fraction digits a double given to nmea::builder is rounded to (minute digits for DDMM.m
  /// positions); -1 = not declared.
  std::int8_t precision = -1;
};

namespace option {
struct range {
  decimal lo, hi;
  bool has_lo = false, has_hi = false, hi_open = false;
  constexpr void apply(field_options& o) const noexcept {
    o.min = lo;
    o.has_min = has_lo;
    o.max = hi;
    o.has_max = has_hi;
    o.max_exclusive = hi_open;
  }
};
struct max_places {
  std::int8_t n;
  constexpr void apply(field_options& o) const noexcept { o.max_places = n; }
};
struct unit {
  char c;
  constexpr void apply(field_options& o) const noexcept { o.unit = c; }
};
struct only_with_field_count {
  std::uint16_t n;
  constexpr void apply(field_options& o) const noexcept { o.only_with_field_count = n; }
};
struct may_be_absent {
  constexpr void apply(field_options& o) const noexcept { o.may_be_absent = true; }
};
struct zero_pad {
  std::uint8_t n;
  constexpr void apply(field_options& o) const noexcept { o.zero_pad = n; }
};
struct code_chars {
  constexpr void apply(field_options& o) const noexcept { o.code_chars = true; }
};
struct precision {
  std::int8_t n;
  constexpr void apply(field_options& o) const noexcept { o.precision = n; }
};
struct length {
  std::uint16_t lo, hi;
  constexpr void apply(field_options& o) const noexcept {
    o.min_length = lo;
    o.max_length = hi;
  }
};
}  // namespace option

/// lo <= value <= hi.
[[nodiscard]] constexpr option::range in_range(decimal lo, decimal hi) noexcept {
  return {.lo = lo, .hi = hi, .has_lo = true, .has_hi = true};
}
/// lo <= value < hi (headings: [0, 360)).
[[nodiscard]] constexpr option::range in_range_below(decimal lo, decimal hi) noexcept {
  return {.lo = lo, .hi = hi, .has_lo = true, .has_hi = true, .hi_open = true};
}
/// lo <= value.
[[nodiscard]] constexpr option::range at_least(decimal lo) noexcept {
  return {.lo = lo, .hi = {}, .has_lo = true};
}
/// A double given to nmea::builder for this field is rounded to n fraction digits (minute
/// digits for a DDMM.m position): what the spec or real senders write. A call may ask for
/// others. Every number and position field of a message declares one.
[[nodiscard]] constexpr option::precision precision(int n) noexcept {
  return {static_cast<std::int8_t>(n)};
}
/// At most n fraction digits (0: whole numbers or whole seconds only).
[[nodiscard]] constexpr option::max_places max_places(int n) noexcept {
  return {static_cast<std::int8_t>(n)};
}
/// The value is followed by a field holding this unit letter ("5.2,N"). On receive the letter
/// may also be blank; seawire always writes it.
[[nodiscard]] constexpr option::unit unit(char c) noexcept { return {c}; }
/// The field exists only in the longer form of the sentence, the one with at least `n` fields
/// (an optional member; written only when it has a value).
[[nodiscard]] constexpr option::only_with_field_count only_with_field_count(int n) noexcept {
  return {static_cast<std::uint16_t>(n)};
}
/// A trailing optional field that senders may leave out entirely; when the value is nullopt
/// it is not written (nor any comma for it).
inline constexpr option::may_be_absent may_be_absent{};
/// Integers written with at least n digits ("06" satellites). Any width is accepted on receive.
[[nodiscard]] constexpr option::zero_pad zero_pad(int n) noexcept {
  return {static_cast<std::uint8_t>(n)};
}
/// Text length bounds.
[[nodiscard]] constexpr option::length length_between(int lo, int hi) noexcept {
  return {static_cast<std::uint16_t>(lo), static_cast<std::uint16_t>(hi)};
}
/// Text that is a code, such as a message id: upper-case letters and digits only (bad_text
/// otherwise; the protocols are case-sensitive, so "nvg" is not "NVG").
inline constexpr option::code_chars code_chars{};
[[nodiscard]] constexpr option::length exact_length(int n) noexcept {
  return {static_cast<std::uint16_t>(n), static_cast<std::uint16_t>(n)};
}

// ---------------------------------------------------------------------------------------------
// descriptors

namespace detail {
template <class T>
struct optional_traits {
  static constexpr bool is_optional = false;
  using value_type = T;
};
template <class T>
struct optional_traits<std::optional<T>> {
  static constexpr bool is_optional = true;
  using value_type = T;
};
template <class M>
struct member_pointer_traits;
template <class C, class T>
struct member_pointer_traits<T C::*> {
  using class_type = C;
  using member_type = T;
};
}  // namespace detail

/// One field of a message: which member, its name in JSON/fmt, its options.
template <auto Member>
struct field_desc {
  using class_type = typename detail::member_pointer_traits<decltype(Member)>::class_type;
  using member_type = typename detail::member_pointer_traits<decltype(Member)>::member_type;
  using value_type = typename detail::optional_traits<member_type>::value_type;
  static constexpr bool is_optional = detail::optional_traits<member_type>::is_optional;
  static constexpr auto member = Member;
  static_assert(has_codec<value_type>, "no codec for this member type");

  std::string_view name;
  field_options opts;

  /// Wire fields this declaration spans.
  [[nodiscard]] constexpr unsigned width() const noexcept {
    return codec<value_type>::width + (opts.unit != 0 ? 1u : 0u);
  }
};

struct magnetic_variation;

namespace detail {
template <class V>
inline constexpr bool fills_from_double =
    std::is_same_v<V, decimal> || std::is_same_v<V, latitude> || std::is_same_v<V, longitude> ||
    std::is_same_v<V, decimal_latitude> || std::is_same_v<V, decimal_longitude> ||
    std::is_same_v<V, magnetic_variation>;

template <class V>
inline constexpr bool is_integer_field = std::is_integral_v<V> && !std::is_same_v<V, bool>;

template <class V>
inline constexpr bool is_text_field = requires(const V& v) {
  v.view();
  V::capacity;
};

// An option that does not apply to the member's type would be ignored without a word: it is a
// compile error instead, naming the option and what it applies to.
template <class Option, class V, bool Optional>
consteval bool option_applies() {
  if constexpr (std::is_same_v<Option, option::range>) {
    static_assert(std::is_same_v<V, decimal> || is_integer_field<V>,
                  "in_range / in_range_below / at_least apply to number fields (decimal or an "
                  "integer type) only");
  } else if constexpr (std::is_same_v<Option, option::max_places>) {
    static_assert(std::is_same_v<V, decimal> || std::is_same_v<V, time_of_day>,
                  "max_places applies to decimal and time_of_day fields only");
  } else if constexpr (std::is_same_v<Option, option::only_with_field_count>) {
    static_assert(Optional,
                  "only_with_field_count applies to std::optional members only (the "
                  "shorter form has no value for it)");
  } else if constexpr (std::is_same_v<Option, option::may_be_absent>) {
    static_assert(Optional,
                  "may_be_absent applies to std::optional members only (a field left "
                  "out has no value)");
  } else if constexpr (std::is_same_v<Option, option::zero_pad>) {
    static_assert(is_integer_field<V>, "zero_pad applies to integer fields only");
  } else if constexpr (std::is_same_v<Option, option::code_chars> ||
                       std::is_same_v<Option, option::length>) {
    static_assert(is_text_field<V>,
                  "code_chars / length_between / exact_length apply to text fields only");
  } else if constexpr (std::is_same_v<Option, option::precision>) {
    static_assert(fills_from_double<V>,
                  "precision applies to the fields nmea::builder fills from a double: decimal, "
                  "positions, magnetic variation");
  }
  return true;
}
}  // namespace detail

template <auto Member, class... Options>
[[nodiscard]] constexpr field_desc<Member> field(std::string_view name,
                                                 Options... options) noexcept {
  using desc = field_desc<Member>;
  static_assert(
      (detail::option_applies<Options, typename desc::value_type, desc::is_optional>() && ...));
  field_desc<Member> f{name, {}};
  (options.apply(f.opts), ...);
  return f;
}

namespace detail {
template <std::size_t I, class T>
struct field_slot {
  T value;
};
template <class Indices, class... Fields>
struct field_slots;
template <std::size_t... I, class... Fields>
struct field_slots<std::index_sequence<I...>, Fields...> : field_slot<I, Fields>... {};
}  // namespace detail

/// The field descriptors of a message in wire order: a flat aggregate with one base per field.
/// (std::tuple, which this replaces, instantiates a recursive chain of bases and constraint
/// checks per message: a large share of the compile time of a file that includes every family.)
template <class... Fields>
struct field_list : detail::field_slots<std::index_sequence_for<Fields...>, Fields...> {
  static constexpr std::size_t size = sizeof...(Fields);

  /// f(descriptor...), all of them in wire order.
  template <class F>
  constexpr decltype(auto) apply(F&& f) const {
    return [&]<std::size_t... I>(std::index_sequence<I...>)->decltype(auto) {
      return f(static_cast<const detail::field_slot<I, Fields>&>(*this).value...);
    }
    (std::index_sequence_for<Fields...>{});
  }
};

/// The I-th descriptor (0-based) of a field_list.
template <std::size_t I, class T>
[[nodiscard]] constexpr const T& field_at(const detail::field_slot<I, T>& slot) noexcept {
  return slot.value;
}

/// What a sentence declares besides its fields (see sentence_desc): the member a "--" address's
/// talker goes to, the member that keeps a decoded sentence's field count, the field counts of
/// its standard forms, and a larger encode buffer. nullptr / 0 / no counts: not declared.
template <auto Talker, auto WireFields, std::size_t BufferSize, std::uint8_t... Counts>
struct sentence_forms {
  static constexpr auto talker = Talker;
  static constexpr auto wire_fields = WireFields;
  static constexpr std::size_t buffer_size = BufferSize;
  static constexpr std::array<std::uint8_t, sizeof...(Counts)> field_counts{Counts...};

  template <auto M>
  using with_talker = sentence_forms<M, WireFields, BufferSize, Counts...>;
  template <auto M>
  using with_wire_fields = sentence_forms<Talker, M, BufferSize, Counts...>;
  template <std::size_t N>
  using with_buffer_size = sentence_forms<Talker, WireFields, N, Counts...>;
  template <std::uint8_t... C>
  using with_field_counts = sentence_forms<Talker, WireFields, BufferSize, C...>;
};
using no_forms = sentence_forms<nullptr, nullptr, 0>;

namespace detail {
template <std::uint8_t... C>
[[nodiscard]] consteval bool increasing() noexcept {
  const std::uint8_t c[] = {C...};
  for (std::size_t i = 1; i < sizeof...(C); ++i)
    if (c[i] <= c[i - 1]) return false;
  return true;
}
template <auto M>
using member_type_of = typename member_pointer_traits<decltype(M)>::member_type;
}  // namespace detail

/// A message's wire layout: its address, its fields in wire order, and the forms it comes in,
/// declared after the fields:
///
///   static constexpr auto nmea = nmea::sentence<"--VBW">(nmea::field<...>(...), ...)
///                                    .talker_in<&vbw::talker>()
///                                    .field_counts<6, 10>()
///                                    .wire_fields_in<&vbw::wire_fields>();
template <seawire::detail::fixed_string Address, class Forms, class... Fields>
struct sentence_desc {
  static constexpr std::string_view address = Address.view();
  /// "--RMC": any two-character talker followed by RMC. A 'P' first is not a talker but a
  /// proprietary sentence (Garmin's $PGRMC is no RMC), so it never matches.
  static constexpr bool any_talker = Address.size() > 2 && address[0] == '-' && address[1] == '-';
  /// The talker_id member a "--" sentence's talker is read into and written from (talker_in);
  /// nullptr for a fixed address.
  static constexpr auto talker_member = Forms::talker;
  /// The std::uint8_t member that keeps a decoded sentence's field count (wire_fields_in), or
  /// nullptr.
  static constexpr auto wire_fields_member = Forms::wire_fields;
  /// The field counts of the standard forms, increasing (field_counts); empty: any count.
  static constexpr auto field_counts = Forms::field_counts;
  /// The smallest buffer encode() gives the message (buffer_size); 0: what its fields need.
  static constexpr std::size_t buffer_size = Forms::buffer_size;
  field_list<Fields...> fields;

  [[nodiscard]] constexpr bool matches(std::string_view a) const noexcept {
    if constexpr (any_talker) {
      return a.size() == address.size() && a[0] != 'P' && a.substr(2) == address.substr(2);
    } else {
      return a == address;
    }
  }
  [[nodiscard]] static constexpr std::size_t size() noexcept { return sizeof...(Fields); }

  /// For an address that starts with "--", which any talker may send: member M (a talker_id)
  /// receives the talker on decode ("GN" of $GNRMC) and gives it on encode. Such a sentence
  /// must declare it; no other may.
  template <auto M>
  [[nodiscard]] consteval auto talker_in() const noexcept {
    static_assert(any_talker, "talker_in: only an address starting with \"--\" has a talker");
    static_assert(std::is_same_v<detail::member_type_of<M>, talker_id>,
                  "talker_in: the member must be a nmea::talker_id");
    return sentence_desc<Address, typename Forms::template with_talker<M>, Fields...>{fields};
  }

  /// For a sentence with fields that senders may leave out (may_be_absent at the end, or
  /// fields of only the longer form): member M (a std::uint8_t) remembers the field count of
  /// the sentence a message was decoded from when that is more than its values need, because
  /// one of those fields came blank instead of left out. Encode then writes that many fields,
  /// so the Kingfisher spec's eight-field "$CPIMU,...,-0.932172,*hh" goes back out with its
  /// empty eighth field and a six-field CPRBS with a blank battery id keeps its six. 0 (the
  /// default, and what decode leaves otherwise) writes the fields the values need.
  template <auto M>
  [[nodiscard]] consteval auto wire_fields_in() const noexcept {
    static_assert(std::is_same_v<detail::member_type_of<M>, std::uint8_t>,
                  "wire_fields_in: the member must be a std::uint8_t");
    return sentence_desc<Address, typename Forms::template with_wire_fields<M>, Fields...>{fields};
  }

  /// A sentence whose standard forms have only some field counts lists them, increasing
  /// (VBW: 6 and 10). Encode writes the shortest listed form that holds the values (an NMEA 3.0
  /// stern speed alone goes out with all four stern fields, not as a seven-field sentence); a
  /// strict decode refuses the counts in between (too_few_fields).
  template <std::uint8_t... Counts>
  [[nodiscard]] consteval auto standard_forms() const noexcept {
    static_assert(sizeof...(Counts) > 0, "standard_forms: list at least one field count");
    static_assert(detail::increasing<Counts...>(), "standard_forms: the counts must increase");
    return sentence_desc<Address, typename Forms::template with_field_counts<Counts...>, Fields...>{
        fields};
  }

  /// encode() gives the message a buffer of at least N bytes (it gives 256, or what the
  /// fields' longest text needs when a codec says): for a message with a codec of its own that
  /// cannot say how long its text gets.
  template <std::size_t N>
  [[nodiscard]] consteval auto buffer_size_at_least() const noexcept {
    return sentence_desc<Address, typename Forms::template with_buffer_size<N>, Fields...>{fields};
  }
};

template <seawire::detail::fixed_string Address, class... Fields>
[[nodiscard]] constexpr sentence_desc<Address, no_forms, Fields...> sentence(
    Fields... fields) noexcept {
  static_assert(Address.size() >= 1 && Address.size() <= 15, "addresses are 1-15 characters");
  return {field_list<Fields...>{{{fields}...}}};
}

/// A type with a sentence description.
template <class T>
concept message_like = requires {
  T::nmea.fields;
  T::nmea.address;
};

namespace detail {
template <auto A, auto B>
[[nodiscard]] consteval bool same_member() noexcept {
  if constexpr (std::is_same_v<decltype(A), decltype(B)>) {
    return A == B;
  } else {
    return false;
  }
}
/// The descriptor index of member M in T's description (fields.size when it is not a field).
template <message_like T, auto M>
[[nodiscard]] consteval std::size_t field_index_of() noexcept {
  std::size_t index = 0;
  std::size_t found = T::nmea.fields.size;
  T::nmea.fields.apply([&](const auto&... d) {
    (((same_member<std::remove_cvref_t<decltype(d)>::member, M>() ? (found = index) : 0), ++index),
     ...);
  });
  return found;
}
}  // namespace detail

/// The fraction digits (minute digits for a DDMM.m position) a double given for member M is
/// rounded to by default: the precision its field declares. `precision_of<&pydev::speed_mps>()`.
template <auto M>
[[nodiscard]] consteval int precision_of() noexcept {
  using T = typename detail::member_pointer_traits<decltype(M)>::class_type;
  constexpr std::size_t i = detail::field_index_of<T, M>();
  static_assert(i < T::nmea.fields.size, "precision_of: the member is not a field");
  constexpr int p = field_at<i>(T::nmea.fields).opts.precision;
  static_assert(p >= 0, "precision_of: the field declares no precision");
  return p;
}

/// A message whose description keeps a decoded sentence's field count (wire_fields_in).
template <class T>
concept keeps_wire_fields = message_like<T> &&
    !std::is_null_pointer_v<decltype(std::remove_cvref_t<decltype(T::nmea)>::wire_fields_member)>;

/// A message whose description lists its standard forms' field counts (standard_forms).
template <class T>
concept lists_field_counts = message_like<T> &&
                             std::remove_cvref_t<decltype(T::nmea)>::field_counts.size() != 0;

namespace detail {
/// The talker member of a message with a "--" address (const or not).
template <class T>
[[nodiscard]] constexpr auto& talker_of(T& msg) noexcept {
  using desc = std::remove_cvref_t<decltype(std::remove_cv_t<T>::nmea)>;
  static_assert(!std::is_null_pointer_v<decltype(desc::talker_member)>,
                "an address starting with \"--\" declares the member its talker goes to: "
                "sentence<\"--XXX\">(...).talker_in<&T::talker>()");
  return msg.*desc::talker_member;
}

/// The wire_fields of a message, 0 for one without.
template <message_like T>
[[nodiscard]] constexpr std::size_t wire_fields_of(const T& msg) noexcept {
  if constexpr (keeps_wire_fields<T>) {
    return msg.*T::nmea.wire_fields_member;
  } else {
    return 0;
  }
}
/// Whether T declares a field that only the longer form has, and one that may be left out at
/// the end: a message that keeps its wire_fields may have one kind or the other, not both.
template <message_like T>
[[nodiscard]] consteval bool has_both_optional_kinds() noexcept {
  bool longer = false;
  bool absent = false;
  T::nmea.fields.apply([&](const auto&... d) {
    ((longer = longer || d.opts.only_with_field_count != 0,
      absent = absent || d.opts.may_be_absent),
     ...);
  });
  return longer && absent;
}
}  // namespace detail

// ---------------------------------------------------------------------------------------------
// decode

namespace detail {

[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr errc check_options(const decimal& v,
                                                                 const field_options& o) noexcept {
  if (o.max_places >= 0 && v.places > o.max_places) [[unlikely]]
    return errc::out_of_range;
  if (o.has_min && v.compare(o.min) < 0) [[unlikely]]
    return errc::out_of_range;
  if (o.has_max) {
    const int c = v.compare(o.max);
    if (c > 0 || (c == 0 && o.max_exclusive)) [[unlikely]]
      return errc::out_of_range;
  }
  return errc::ok;
}
template <class T>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr errc check_options(const T& v,
                                                                 const field_options& o) noexcept {
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    return check_options(decimal(static_cast<std::int64_t>(v)), o);
  } else if constexpr (std::is_same_v<T, time_of_day>) {
    return o.max_places >= 0 && v.places > o.max_places ? errc::bad_time : errc::ok;
  } else if constexpr (requires {
                         v.view();
                         T::capacity;
                       }) {
    if (v.size() < o.min_length || v.size() > o.max_length) return errc::bad_length;
    if (o.code_chars)
      for (const char c : v.view())
        if (!seawire::detail::is_upper(c) && !seawire::detail::is_digit(c)) return errc::bad_text;
    return errc::ok;
  } else {
    return errc::ok;
  }
}

[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr errc read_unit(field_reader& r,
                                                             const field_options& o,
                                                             bool value_present) noexcept {
  if (o.unit == 0) return errc::ok;
  const field_token t = r.take();
  if (!t.present) return value_present ? errc::too_few_fields : errc::ok;
  if (t.text.empty()) return errc::ok;
  return t.text.size() == 1 && t.text[0] == o.unit ? errc::ok : errc::bad_unit;
}

/// Empty an optional member. Not reset(): clang (14, with libstdc++) refuses to copy, in a
/// constant expression, an optional that was engaged and then reset, which a member with an
/// engaged default (`std::optional<text<8>> x = text<8>{}`) runs into on decode.
template <class O>
constexpr void clear_optional(O& o) noexcept {
  if (o.has_value()) {
    std::destroy_at(&o);
    std::construct_at(&o);
  }
}

template <class F, class T>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr errc read_field(const F& f, field_reader& r,
                                                              T& msg) noexcept {
  using V = typename F::value_type;
  auto& m = msg.*F::member;
  const field_options& o = f.opts;
  if constexpr (F::is_optional) {
    if (o.only_with_field_count != 0 && r.field_count() < o.only_with_field_count) {
      clear_optional(m);
      return errc::ok;
    }
    const field_token t = r.peek();
    // A sentence that stops before an optional field is cut short, unless the field is
    // declared as droppable or the policy reads what is missing as blank.
    if (!t.present && !o.may_be_absent &&
        (r.policy().strict_values || !r.policy().absent_as_blank)) {
      (void)r.take();
      return errc::too_few_fields;
    }
    // Blank means "no value", except for text, where blank is the empty string and only a
    // field that is not there at all is nullopt.
    // The wire fields to pass over when they hold nothing; 0 when they hold a value. A codec
    // that reads blanks (to keep what came with them) says itself when they hold nothing.
    unsigned nothing = !t.present || (t.blank() && !codec<V>::allows_blank) ? codec<V>::width : 0;
    if constexpr (requires(const field_reader& probe) { codec<V>::nothing_span(probe); }) {
      if (t.present) nothing = codec<V>::nothing_span(r);
    }
    if (nothing != 0) {
      // Blank where it could have been left out: the form to write back is the sentence's
      // (unless a trailing value further on needs it anyway, which resets it below).
      if constexpr (keeps_wire_fields<T>) {
        if ((o.may_be_absent || o.only_with_field_count != 0) && t.present)
          msg.*T::nmea.wire_fields_member =
              static_cast<std::uint8_t>(r.field_count() < 255 ? r.field_count() : 255);
      }
      for (unsigned k = 0; k < nothing; ++k) (void)r.take();
      clear_optional(m);
      return read_unit(r, o, false);
    }
    if constexpr (keeps_wire_fields<T>) {
      if (o.may_be_absent) msg.*T::nmea.wire_fields_member = 0;
    }
    // Read in place: a value built on the side and copied in would be copied through the
    // stack in wide loads that wait on the narrow stores that just wrote it.
    errc e = codec<V>::read(r, m.emplace());
    if (e == errc::ok) e = check_options(*m, o);
    if (e == errc::ok) e = read_unit(r, o, true);
    if (e != errc::ok) clear_optional(m);
    return e;
  } else {
    const field_token t = r.peek();
    if (!t.present) {
      (void)r.take();
      return errc::too_few_fields;
    }
    if (t.blank() && (!codec<V>::allows_blank || o.min_length > 0)) {
      (void)r.take();
      return errc::missing_field;
    }
    errc e = codec<V>::read(r, m);
    if (e == errc::ok) e = check_options(m, o);
    if (e == errc::ok) e = read_unit(r, o, true);
    return e;
  }
}

/// Every field of T in wire order, up to the first error. Each descriptor is named by its place
/// in the constant table, not passed by reference: its options are then constants where
/// read_field is inlined, and the checks a field does not have compile away. Inlined into
/// decode_into, so that the reader lives in registers.
template <class T, std::size_t I, std::size_t... Rest>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr errc read_fields(
    field_reader& r, T& msg, std::index_sequence<I, Rest...>) noexcept {
  const errc e = detail::read_field(field_at<I>(T::nmea.fields), r, msg);
  if (e != errc::ok) [[unlikely]]
    return e;
  if constexpr (sizeof...(Rest) == 0) {
    return errc::ok;
  } else {
    return read_fields(r, msg, std::index_sequence<Rest...>{});
  }
}
template <class T>
[[nodiscard]] constexpr errc read_fields(field_reader&, T&, std::index_sequence<>) noexcept {
  return errc::ok;
}

/// Whether encode leaves field `f` out of `msg`'s sentence for want of a value: a field that may
/// be absent at the end (if nothing after it is written), or one of only the longer form when
/// the message is not written in that form.
template <class F, class T>
[[nodiscard]] constexpr bool skipped(const F& f, const T& msg) noexcept {
  if constexpr (F::is_optional) {
    if ((msg.*F::member).has_value()) return false;
    if (f.opts.only_with_field_count != 0)
      return wire_fields_of(msg) < f.opts.only_with_field_count;
    return f.opts.may_be_absent;
  } else {
    return false;
  }
}

/// The wire field (0-based) each of T's field declarations starts at, as if every one were
/// written, and the field count of the whole at the end.
template <message_like T>
inline constexpr auto field_starts = [] {
  std::array<std::size_t, std::remove_cvref_t<decltype(T::nmea.fields)>::size + 1> starts{};
  std::size_t i = 0;
  T::nmea.fields.apply(
      [&](const auto&... d) { ((starts[i + 1] = starts[i] + d.width(), ++i), ...); });
  return starts;
}();

/// How many of T's field declarations encode writes for the values `msg` holds: all but the
/// trailing ones left out for want of a value, and at least those that the wire_fields of a
/// decoded message reach, up to the next of the message's standard forms.
template <message_like T>
[[nodiscard]] constexpr std::size_t written_fields(const T& msg) noexcept {
  constexpr std::size_t n = std::remove_cvref_t<decltype(T::nmea.fields)>::size;
  constexpr const auto& starts = field_starts<T>;
  std::size_t keep = n;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    const bool skips[] = {skipped(field_at<I>(T::nmea.fields), msg)..., false};
    while (keep > 0 && skips[keep - 1]) --keep;
  }
  (std::make_index_sequence<n>{});
  // At least the declarations that start within the first `wire` fields (those of only the
  // longer form count as written: the messages that need this have none left out).
  const auto reach = [&](std::size_t wire) {
    while (keep < n && starts[keep] < wire) ++keep;
  };
  if constexpr (keeps_wire_fields<T>) {
    if (const std::size_t wire = wire_fields_of(msg); wire != 0) [[unlikely]]
      reach(wire);
  }
  if constexpr (lists_field_counts<T>) {
    for (const std::size_t form : T::nmea.field_counts) {
      if (form >= starts[keep]) {
        reach(form);
        break;
      }
    }
  }
  return keep;
}

/// Whether `count` is one of T's listed field counts (any count, for a message without a list).
template <message_like T>
[[nodiscard]] constexpr bool listed_field_count(std::size_t count) noexcept {
  if constexpr (lists_field_counts<T>) {
    for (const std::size_t form : T::nmea.field_counts)
      if (form == count) return true;
    return false;
  } else {
    return true;
  }
}

/// decode<T>() into `msg`, a default-constructed T the caller owns (the value of a result, the
/// alternative of a variant), so that no finished message is ever copied; the errc, field and
/// column go to `status` (any result<>). On error `msg` holds what was read before it.
template <message_like T, class Status>
constexpr void decode_into(const sentence_view& s, const parse_policy& policy, T& msg,
                           Status& status) noexcept {
  static_assert(!keeps_wire_fields<T> || !has_both_optional_kinds<T>(),
                "wire_fields_in: fields of only the longer form and fields left out at the end in "
                "one message are not supported");
  status.ec = errc::ok;
  status.field = 0;
  status.column = 0;
  // Messages are '$' sentences: a '!' one (!AIVDM) is not the message, whatever its address.
  if (s.start != '$' || !T::nmea.matches(s.address)) {
    status.ec = errc::wrong_address;
    return;
  }
  if constexpr (std::remove_cvref_t<decltype(T::nmea)>::any_talker) {
    (void)talker_of(msg).assign(s.address.substr(0, 2));
  }
  field_reader r(s, policy);
  errc e = read_fields(
      r, msg, std::make_index_sequence<std::remove_cvref_t<decltype(T::nmea.fields)>::size>{});
  if (e == errc::ok && !r.at_end() && !policy.extra_fields) {
    (void)r.take();
    e = errc::too_many_fields;
  }
  if (e != errc::ok) {
    status.ec = e;
    status.field = r.index();
    status.column = r.column();
    return;
  }
  if constexpr (lists_field_counts<T>) {
    // Strict: a count between the standard forms is a sentence cut short; the first field
    // missing is named.
    if (policy.strict_values && !listed_field_count<T>(s.field_count)) [[unlikely]] {
      status.ec = errc::too_few_fields;
      status.field = static_cast<decltype(status.field)>(s.field_count + 1);
      status.column = static_cast<decltype(status.column)>(s.body_column() + s.body.size());
    }
  }
}

}  // namespace detail

/// Decode a message from a sentence already split by parse(). A '!' sentence is never T
/// (wrong_address): messages are '$' sentences.
template <message_like T>
[[nodiscard]] constexpr result<T> decode(const sentence_view& s,
                                         const parse_policy& policy = {}) noexcept {
  result<T> out;
  detail::decode_into(s, policy, out.value, out);
  if (!out) out.value = T{};
  return out;
}

/// Parse and decode one line.
template <message_like T>
[[nodiscard]] constexpr result<T> decode(std::string_view line,
                                         const parse_policy& policy = {}) noexcept {
  const result<sentence_view> s = parse(line, policy);
  if (!s) {
    result<T> out;
    out.ec = s.ec;
    out.column = s.column;
    return out;
  }
  return decode<T>(s.value, policy);
}

// ---------------------------------------------------------------------------------------------
// encode

namespace detail {

/// Which of a codec's wire fields (0 = its first) an error of its check() is about, so that
/// encode names the field decode would: a position's hemisphere letter is its second.
template <class V>
[[nodiscard]] constexpr unsigned error_offset(errc e) noexcept {
  if constexpr (requires { codec<V>::error_offset(e); }) {
    return codec<V>::error_offset(e);
  } else {
    return 0;
  }
}

template <class F, class T>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr errc write_field(const F& f, writer& w, const T& msg,
                                                               bool& skip_rest) noexcept {
  using V = typename F::value_type;
  const auto& m = msg.*F::member;
  const field_options& o = f.opts;
  if (skip_rest) return errc::ok;
  const V* v = nullptr;
  bool has = true;
  if constexpr (F::is_optional) {
    has = m.has_value();
    if (!has && o.only_with_field_count != 0 && wire_fields_of(msg) < o.only_with_field_count)
      return errc::ok;  // the shorter form has no such field
    if (has) v = &*m;
  } else {
    v = &m;
  }
  if (has) {
    errc e = codec<V>::check(*v);
    if (e == errc::ok) e = check_options(*v, o);
    if (e != errc::ok) return e;
  } else if (codec<V>::allows_blank &&
             !requires(const field_reader& probe) { codec<V>::nothing_span(probe); }) {
    // A blank field reads back as nullopt, except text: there blank is the empty string, and
    // only a field left out is nullopt. One that a later field keeps from being left out cannot
    // be written as nullopt at all.
    return errc::missing_field;
  }
  w.next_field();
  if (has) {
    if constexpr (std::is_integral_v<V> && std::is_unsigned_v<V> && !std::is_same_v<V, bool>) {
      w.put_uint(*v, o.zero_pad);
    } else {
      codec<V>::write(w, *v);
    }
  } else {
    for (unsigned k = 1; k < codec<V>::width; ++k) w.next_field();
  }
  if (o.unit != 0) {
    w.next_field();
    w.put(o.unit);
  }
  return errc::ok;
}

}  // namespace detail

/// Write a message as a sealed sentence into `out`. Values outside their field's domain are
/// refused with the field number; nothing partial is reported as success.
template <message_like T>
[[nodiscard]] constexpr result<std::size_t> encode_to(const T& msg, std::span<char> out) noexcept {
  writer w(out);
  constexpr auto& desc = T::nmea;
  if constexpr (std::remove_cvref_t<decltype(desc)>::any_talker) {
    const std::string_view t = detail::talker_of(msg).view();
    if (t.size() != 2 || !seawire::detail::is_upper(t[0]) || t[0] == 'P' ||
        !(seawire::detail::is_upper(t[1]) || seawire::detail::is_digit(t[1]))) {
      result<std::size_t> r;
      r.ec = errc::bad_address;
      return r;
    }
    w.begin(t);
    w.put(desc.address.substr(2));
  } else {
    w.begin(desc.address);
  }
  // Trailing fields that may be absent and have no value are left out, with their commas
  // (but for those a decoded message's wire_fields or the message's standard forms keep).
  constexpr std::size_t n = std::remove_cvref_t<decltype(desc.fields)>::size;
  const std::size_t keep = detail::written_fields(msg);

  errc e = errc::ok;
  std::uint16_t wire_field = 0;  // spec number of the first wire field of the current one
  std::size_t index = 0;
  bool skip_rest = false;
  // Each descriptor named by its place in the constant table (as in decode_into), so that its
  // options are constants in the code written for it.
  const auto one = [&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
    constexpr const auto& f = field_at<I>(T::nmea.fields);
    if (index++ >= keep) skip_rest = true;
    // A field of the longer form that this message does not have takes no number.
    if (f.opts.only_with_field_count != 0 && detail::skipped(f, msg)) return true;
    ++wire_field;
    e = detail::write_field(f, w, msg, skip_rest);
    using V = typename std::remove_cvref_t<decltype(f)>::value_type;
    wire_field = static_cast<std::uint16_t>(
        wire_field + (e == errc::ok ? f.width() - 1 : detail::error_offset<V>(e)));
    return e == errc::ok;
  };
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (void)(one(std::integral_constant<std::size_t, I>{}) && ...);
  }
  (std::make_index_sequence<n>{});
  result<std::size_t> r;
  if (e != errc::ok) {
    r.ec = e;
    r.field = wire_field;
    return r;
  }
  return w.seal();
}

namespace detail {
/// The longest sentence encode_to can write for T: '$', the address, a comma and the longest
/// text of each field (codec max_chars, wider zero padding, ",X" for a unit letter), "*hh\r\n".
/// 0 when a field's codec does not say how long it can be.
template <class T>
[[nodiscard]] consteval std::size_t longest_sentence() noexcept {
  std::size_t n = 1 + T::nmea.address.size() + 5;
  bool known = true;
  const auto add = [&](const auto& f) {
    using V = typename std::remove_cvref_t<decltype(f)>::value_type;
    if constexpr (requires { codec<V>::max_chars; }) {
      std::size_t chars = codec<V>::max_chars;
      if constexpr (std::is_integral_v<V>) {
        const std::size_t pad = f.opts.zero_pad < 20 ? f.opts.zero_pad : 20;
        if (pad > chars) chars = pad;
      }
      n += 1 + chars + (f.opts.unit != 0 ? 2 : 0);
    } else {
      known = false;
    }
  };
  T::nmea.fields.apply([&](const auto&... f) { (add(f), ...); });
  return known ? n : 0;
}

/// The buffer encode() gives a message: 256 bytes, or more when its longest sentence needs more
/// (or its description's buffer_size_at_least says so), so that whatever decodes also encodes.
template <class T>
[[nodiscard]] consteval std::size_t sentence_size() noexcept {
  std::size_t n = longest_sentence<T>() > 256 ? longest_sentence<T>() : 256;
  if (T::nmea.buffer_size > n) n = T::nmea.buffer_size;
  return n;
}
}  // namespace detail

/// Encode into a buffer of N bytes held by value.
template <std::size_t N, message_like T>
[[nodiscard]] constexpr sentence_buffer<N> encode(const T& msg) noexcept {
  sentence_buffer<N> b;
  const result<std::size_t> r = encode_to(msg, std::span<char>(b.data, N));
  b.ec = r.ec;
  b.field = r.field;
  b.size = r ? r.value : 0;
  return b;
}
/// Encode into a buffer held by value, of 256 bytes unless the message needs more.
template <message_like T>
[[nodiscard]] constexpr sentence_buffer<detail::sentence_size<T>()> encode(const T& msg) noexcept {
  return encode<detail::sentence_size<T>()>(msg);
}

// ---------------------------------------------------------------------------------------------
// reflection

/// Calls f(name, member) for each field in wire order (name as declared: snake_case).
template <message_like T, class F>
constexpr void for_each_field(const T& msg, F&& f) {
  T::nmea.fields.apply([&](const auto&... d) { (f(d.name, msg.*(d.member)), ...); });
}
/// The same with mutable members, to fill a message field by field.
template <message_like T, class F>
constexpr void for_each_field(T& msg, F&& f) {
  T::nmea.fields.apply([&](const auto&... d) { (f(d.name, msg.*(d.member)), ...); });
}

/// The number of wire fields of the form `msg` is written in, for field_name: every field's,
/// but for a field only the longer form has (only_with_field_count) that holds no value.
template <message_like T>
[[nodiscard]] constexpr std::size_t form_field_count(const T& msg) noexcept {
  std::size_t n = 0;
  T::nmea.fields.apply([&](const auto&... d) {
    ((n += (d.opts.only_with_field_count != 0 && detail::skipped(d, msg)) ? 0 : d.width()), ...);
  });
  return n;
}

/// What a message's description says of wire field `n`: its declared name and options (found
/// false when the message has no such field).
struct field_about {
  std::string_view name;
  field_options opts{};
  bool found = false;
};

/// Wire field `n` of T (field_count as field_name's).
template <message_like T>
[[nodiscard]] constexpr field_about about_field(
    std::size_t n, std::size_t field_count = static_cast<std::size_t>(-1)) noexcept {
  field_about a;
  std::size_t first = 1;
  T::nmea.fields.apply([&](const auto&... d) {
    (void)(((d.opts.only_with_field_count != 0 && field_count < d.opts.only_with_field_count)
                ? false
                : (n >= first && n < first + d.width() ? (a = {d.name, d.opts, true}, true)
                                                       : (first += d.width(), false))) ||
           ...);
  });
  return a;
}

/// The declared name of the field that holds wire field `n` (1-based), or "" if none.
/// Numbered as in the longest form of the sentence; give the sentence's field count (e.g.
/// sentence_view::field_count) to number a shorter form as it came: a five-field CPRBS has no
/// battery id, so its field 2 is the stack voltage.
template <message_like T>
[[nodiscard]] constexpr std::string_view field_name(
    std::size_t n, std::size_t field_count = static_cast<std::size_t>(-1)) noexcept {
  return about_field<T>(n, field_count).name;
}

}  // namespace seawire::nmea
