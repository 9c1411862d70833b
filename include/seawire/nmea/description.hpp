// SPDX-License-Identifier: BSL-1.0
#pragma once
// The message description: a message is a plain struct with a static `nmea` member,
// `nmea::sentence<"ADDR">(nmea::field<&M::m>("name", options...)...)` then the forms it comes in
// (talker_in, wire_fields_in, blank_units_in, standard_forms, sender_writes); decode, encode,
// field names and validation all follow from it. A field is *blank* when empty (",,") and
// *absent* when the sentence ends before it; std::optional<T> members may be blank. The options
// and forms, with an example: docs/adding-a-message.md.

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

#include "seawire/detail/fixed_string.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/detail/member.hpp"
#include "seawire/detail/row_list.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"

namespace seawire::nmea {

// ---------------------------------------------------------------------------------------------
// field options

/// Everything a field declaration can add to its codec, set by the option helper of its name.
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
  /// Fraction digits nmea::builder rounds a double to (DDMM.m: minute digits); -1 = none.
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
/// nmea::builder rounds a double for this field to n fraction digits (DDMM.m: minute digits), as
/// the spec or real senders write. Every number and position field declares one.
[[nodiscard]] constexpr option::precision precision(int n) noexcept {
  return {static_cast<std::int8_t>(n)};
}
/// At most n fraction digits (0: whole numbers or whole seconds only).
[[nodiscard]] constexpr option::max_places max_places(int n) noexcept {
  return {static_cast<std::int8_t>(n)};
}
/// The value is followed by a field holding this unit letter ("5.2,N"); blank accepted on
/// receive, always written but where blank_units_in keeps it blank.
[[nodiscard]] constexpr option::unit unit(char c) noexcept { return {c}; }
/// The field exists only in the form of the sentence with at least `n` fields (optional member).
[[nodiscard]] constexpr option::only_with_field_count only_with_field_count(int n) noexcept {
  return {static_cast<std::uint16_t>(n)};
}
/// A trailing optional field senders may leave out; nullopt is not written, nor its comma.
inline constexpr option::may_be_absent may_be_absent{};
/// Integers written with at least n digits ("06" satellites). Any width is accepted on receive.
[[nodiscard]] constexpr option::zero_pad zero_pad(int n) noexcept {
  return {static_cast<std::uint8_t>(n)};
}
/// Text length bounds.
[[nodiscard]] constexpr option::length length_between(int lo, int hi) noexcept {
  return {static_cast<std::uint16_t>(lo), static_cast<std::uint16_t>(hi)};
}
/// Upper-case letters and digits only, bad_text otherwise (case-sensitive: "nvg" is not "NVG").
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
}  // namespace detail

/// One field of a message: which member, its name in JSON/fmt, its options.
template <auto Member>
struct field_desc {
  using class_type = seawire::detail::member_class_t<Member>;
  using member_type = seawire::detail::member_type_t<Member>;
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
inline constexpr bool is_integer_field = whole_number<V> || is_integer_wrapper<V>;

template <class V>
inline constexpr bool is_unsigned_integer_field = [] {
  if constexpr (is_integer_wrapper<V>) {
    return std::is_unsigned_v<typename V::value_type>;
  } else {
    return whole_number<V> && std::is_unsigned_v<V>;
  }
}();

template <class V>
inline constexpr bool is_text_field = requires(const V& v) {
  v.view();
  V::capacity;
};

// An option that does not apply to the member's type is a compile error, not ignored.
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
    static_assert(is_unsigned_integer_field<V>,
                  "zero_pad applies to unsigned integer fields only (a signed one is written "
                  "unpadded)");
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

/// The field descriptors of a message in wire order (a row_list: `field_at<I>(list)`,
/// `apply(f)`).
template <class... Fields>
using field_list = seawire::detail::row_list<Fields...>;

/// The I-th descriptor (0-based) of a field_list.
template <std::size_t I, class T>
[[nodiscard]] constexpr const T& field_at(const seawire::detail::row_slot<I, T>& slot) noexcept {
  return slot.value;
}

/// Number forms beyond NMEA 0183 that a message's sender writes (a printf "%f" sender such as the
/// Clearpath vehicle), read for the messages that declare them (sender_writes) only, never
/// written otherwise. Each form's rule: docs/parse-policy.md.
struct number_forms {
  /// DDMM.m as degrees * 100 + minutes, unpadded ("22.2,W" is 0 deg 22.2 min W); kept as it came.
  bool unpadded_positions = false;
  /// "nan" (any case, any sign) in an optional number field: nullopt; refused by strict_values.
  bool nan_as_blank = false;
  /// Second 60 with a zero fraction at any minute ("%06.3f" of hh:mm:59.9995); kept as it came.
  bool rounded_seconds = false;

  friend constexpr bool operator==(const number_forms&, const number_forms&) noexcept = default;
};

/// What a sentence declares besides its fields (sentence_desc's members of the same names);
/// nullptr / 0 / {} / no counts: not declared.
template <auto Talker, auto WireFields, auto BlankUnits, std::size_t BufferSize,
          number_forms Numbers, std::uint8_t... Counts>
struct sentence_forms {
  static constexpr auto talker = Talker;
  static constexpr auto wire_fields = WireFields;
  static constexpr auto blank_units = BlankUnits;
  static constexpr std::size_t buffer_size = BufferSize;
  static constexpr number_forms numbers = Numbers;
  static constexpr std::array<std::uint8_t, sizeof...(Counts)> field_counts{Counts...};

  template <auto M>
  using with_talker = sentence_forms<M, WireFields, BlankUnits, BufferSize, Numbers, Counts...>;
  template <auto M>
  using with_wire_fields = sentence_forms<Talker, M, BlankUnits, BufferSize, Numbers, Counts...>;
  template <auto M>
  using with_blank_units = sentence_forms<Talker, WireFields, M, BufferSize, Numbers, Counts...>;
  template <std::size_t N>
  using with_buffer_size = sentence_forms<Talker, WireFields, BlankUnits, N, Numbers, Counts...>;
  template <number_forms F>
  using with_numbers = sentence_forms<Talker, WireFields, BlankUnits, BufferSize, F, Counts...>;
  template <std::uint8_t... C>
  using with_field_counts =
      sentence_forms<Talker, WireFields, BlankUnits, BufferSize, Numbers, C...>;
};
using no_forms = sentence_forms<nullptr, nullptr, nullptr, 0, number_forms{}>;

namespace detail {
template <std::uint8_t... C>
[[nodiscard]] consteval bool increasing() noexcept {
  const std::uint8_t c[] = {C...};
  for (std::size_t i = 1; i < sizeof...(C); ++i)
    if (c[i] <= c[i - 1]) return false;
  return true;
}
}  // namespace detail

/// A message's wire layout: its address, its fields in wire order, and the forms it comes in,
/// declared after the fields (`sentence<"--VBW">(...).talker_in<&vbw::talker>()`). Every member
/// of the message has an initializer or a type that sets itself: decoding default-initializes a
/// message, then writes each field the layout names.
template <seawire::detail::fixed_string Address, class Forms, class... Fields>
struct sentence_desc {
  static constexpr std::string_view address = Address.view();
  /// "--RMC": any two-character talker followed by RMC. A 'P' first is not a talker but a
  /// proprietary sentence (Garmin's $PGRMC is no RMC), so it never matches.
  static constexpr bool any_talker = Address.size() > 2 && address[0] == '-' && address[1] == '-';
  // The members declared by the functions below (nullptr / empty / 0 when not declared).
  static constexpr auto talker_member = Forms::talker;            // talker_in
  static constexpr auto wire_fields_member = Forms::wire_fields;  // wire_fields_in
  static constexpr auto blank_units_member = Forms::blank_units;  // blank_units_in
  static constexpr auto field_counts = Forms::field_counts;       // standard_forms, increasing
  static constexpr std::size_t buffer_size = Forms::buffer_size;  // buffer_size_at_least
  static constexpr number_forms numbers = Forms::numbers;         // sender_writes
  field_list<Fields...> fields;

  [[nodiscard]] constexpr bool matches(std::string_view a) const noexcept {
    if (a.size() != address.size()) return false;
    if constexpr (any_talker) {
      if (a[0] == 'P') return false;
    }
    // A constant length: a few unrolled byte compares, not a string compare call.
    for (std::size_t i = any_talker ? 2 : 0; i < address.size(); ++i)
      if (a[i] != address[i]) return false;
    return true;
  }
  [[nodiscard]] static constexpr std::size_t size() noexcept { return sizeof...(Fields); }

  /// A "--" address only, and it must: member M (a talker_id) receives the talker on decode ("GN"
  /// of $GNRMC) and gives it on encode.
  template <auto M>
  [[nodiscard]] consteval auto talker_in() const noexcept {
    static_assert(any_talker, "talker_in: only an address starting with \"--\" has a talker");
    static_assert(std::is_same_v<seawire::detail::member_type_t<M>, talker_id>,
                  "talker_in: the member must be a nmea::talker_id");
    return sentence_desc<Address, typename Forms::template with_talker<M>, Fields...>{fields};
  }

  /// Member M (a std::uint8_t) keeps a decoded sentence's field count when more than its values
  /// need (a field that may be left out came blank); encode writes that many. 0: what they need.
  template <auto M>
  [[nodiscard]] consteval auto wire_fields_in() const noexcept {
    static_assert(std::is_same_v<seawire::detail::member_type_t<M>, std::uint8_t>,
                  "wire_fields_in: the member must be a std::uint8_t");
    return sentence_desc<Address, typename Forms::template with_wire_fields<M>, Fields...>{fields};
  }

  /// Member M (a std::uint32_t) keeps, bit n for wire field n, which unit letters beside a blank
  /// value came blank ("$IIVHW,,,211.0,M"); encode writes those blank again. 0: every letter.
  template <auto M>
  [[nodiscard]] consteval auto blank_units_in() const noexcept {
    static_assert(std::is_same_v<seawire::detail::member_type_t<M>, std::uint32_t>,
                  "blank_units_in: the member must be a std::uint32_t");
    return sentence_desc<Address, typename Forms::template with_blank_units<M>, Fields...>{fields};
  }

  /// The field counts of the standard forms, increasing (VBW: 6, 10). Encode writes the shortest
  /// that holds the values; a strict decode refuses counts in between (too_few_fields).
  template <std::uint8_t... Counts>
  [[nodiscard]] consteval auto standard_forms() const noexcept {
    static_assert(sizeof...(Counts) > 0, "standard_forms: list at least one field count");
    static_assert(detail::increasing<Counts...>(), "standard_forms: the counts must increase");
    return sentence_desc<Address, typename Forms::template with_field_counts<Counts...>, Fields...>{
        fields};
  }

  /// Number forms the message's sender writes (number_forms), read for this message only.
  template <number_forms F>
  [[nodiscard]] consteval auto sender_writes() const noexcept {
    return sentence_desc<Address, typename Forms::template with_numbers<F>, Fields...>{fields};
  }

  /// encode() gives the message at least N bytes (else 256, or the fields' longest text), for a
  /// codec that cannot say how long its text gets.
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
/// The descriptor index of member M in T's description (fields.size when it is not a field).
template <message_like T, auto M>
[[nodiscard]] consteval std::size_t field_index_of() noexcept {
  std::size_t index = 0;
  std::size_t found = T::nmea.fields.size;
  T::nmea.fields.apply([&](const auto&... d) {
    (((seawire::detail::same_member<std::remove_cvref_t<decltype(d)>::member, M> ? (found = index)
                                                                                 : 0),
      ++index),
     ...);
  });
  return found;
}
}  // namespace detail

/// The precision member M's field declares: `precision_of<&pydev::speed_mps>()`.
template <auto M>
[[nodiscard]] consteval int precision_of() noexcept {
  using T = seawire::detail::member_class_t<M>;
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

/// A message whose description keeps which unit letters came blank (blank_units_in).
template <class T>
concept keeps_blank_units = message_like<T> &&
    !std::is_null_pointer_v<decltype(std::remove_cvref_t<decltype(T::nmea)>::blank_units_member)>;

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
/// Whether T has both a longer form's field and one absent at the end (wire_fields allows one).
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
// forms

namespace detail {
/// Whether encode leaves field `f` out of `msg`'s sentence: absent at the end, or of a longer
/// form than msg is written in.
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
}  // namespace detail

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

/// The number of wire fields of the form `msg` is written in, for field_name.
template <message_like T>
[[nodiscard]] constexpr std::size_t form_field_count(const T& msg) noexcept {
  std::size_t n = 0;
  T::nmea.fields.apply([&](const auto&... d) {
    ((n += (d.opts.only_with_field_count != 0 && detail::skipped(d, msg)) ? 0 : d.width()), ...);
  });
  return n;
}

/// What a message's description says of wire field `n`: its declared name and options (found
/// false when there is none); `part` names a declaration's later wire fields ("hemisphere
/// letter", "unit letter"), `explain` says what is wrong with a refused text (error_text()).
struct field_about {
  std::string_view name;
  field_options opts{};
  bool found = false;
  std::string_view part;    ///< the wire field within the declaration, after its first
  unsigned part_index = 0;  ///< 0 for the declaration's first wire field
  /// codec<V>::explain(part_index, error, text): why `text` was refused, or "" if no more to say.
  std::string_view (*explain)(unsigned, errc, std::string_view) noexcept = nullptr;
};

namespace detail {
/// field_about for wire field `k` (0-based) of declaration `d`.
template <class D>
[[nodiscard]] constexpr field_about about_part(const D& d, unsigned k) noexcept {
  using V = typename D::value_type;
  field_about a;
  a.name = d.name;
  a.opts = d.opts;
  a.found = true;
  a.part_index = k;
  if (k >= codec<V>::width) {
    a.part = "unit letter";  // the unit option's field follows the codec's
  } else if constexpr (requires { codec<V>::part_name(k); }) {
    a.part = codec<V>::part_name(k);
  }
  if constexpr (requires { codec<V>::explain(k, errc::ok, std::string_view{}); })
    if (k < codec<V>::width) a.explain = &codec<V>::explain;
  return a;
}
}  // namespace detail

/// Wire field `n` of T (field_count as field_name's).
template <message_like T>
[[nodiscard]] constexpr field_about about_field(
    std::size_t n, std::size_t field_count = static_cast<std::size_t>(-1)) noexcept {
  field_about a;
  std::size_t first = 1;
  T::nmea.fields.apply([&](const auto&... d) {
    (void)(((d.opts.only_with_field_count != 0 && field_count < d.opts.only_with_field_count)
                ? false
                : (n >= first && n < first + d.width()
                       ? (a = detail::about_part(d, static_cast<unsigned>(n - first)), true)
                       : (first += d.width(), false))) ||
           ...);
  });
  return a;
}

/// The declared name of the field that holds wire field `n` (1-based), or "" if none. Numbered
/// as in the longest form; give the sentence's field_count to number a shorter form as it came
/// (a five-field CPRBS has no battery id: its field 2 is the stack voltage).
template <message_like T>
[[nodiscard]] constexpr std::string_view field_name(
    std::size_t n, std::size_t field_count = static_cast<std::size_t>(-1)) noexcept {
  return about_field<T>(n, field_count).name;
}

}  // namespace seawire::nmea
