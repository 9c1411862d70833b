// SPDX-License-Identifier: BSL-1.0
#pragma once
// decode<T>() and encode() for any message with a description (description.hpp): each field read
// or written by its member type's codec (fields.hpp), with the blanks, optionals, units, ranges
// and sentence forms its declaration gives.

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <new>
#include <optional>
// std::construct_at and std::destroy_at: <memory> declares them, and costs a translation unit
// about a third of what <variant>, <optional>, <string_view> and <chrono> cost together;
// libstdc++ declares them in a header of their own.
#if __has_include(<bits/stl_construct.h>)
#include <bits/stl_construct.h>
#else
#include <memory>
#endif
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

#include "seawire/detail/ascii.hpp"
#include "seawire/detail/fixed_string.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/description.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"

namespace seawire::nmea {

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
  if constexpr (whole_number<T>) {
    return check_options(decimal(static_cast<std::int64_t>(v)), o);
  } else if constexpr (is_integer_wrapper<T>) {
    return check_options(v.value(), o);
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

/// A text longer than its member holds, in a field that declares its length (length_between,
/// exact_length) no longer than that: it breaks the declared rule, and gets the error a text
/// too short gets (bad_length), not text_too_long.
template <class V>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr errc length_rule(errc e,
                                                               const field_options& o) noexcept {
  if constexpr (is_text_field<V>) {
    if (e == errc::text_too_long && o.max_length <= V::capacity) return errc::bad_length;
  }
  return e;
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

/// Whether `s` is "nan" in any case, with or without a sign: what a float formatter prints for a
/// value it does not have.
[[nodiscard]] constexpr bool is_nan_text(std::string_view s) noexcept {
  if (!s.empty() && (s[0] == '-' || s[0] == '+')) s.remove_prefix(1);
  return s.size() == 3 && (s[0] | 0x20) == 'n' && (s[1] | 0x20) == 'a' && (s[2] | 0x20) == 'n';
}

/// codec<V>::read, or the read of the number forms T's sender writes (number_forms).
template <class T, class V>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr errc read_value(field_reader& r, V& v) noexcept {
  constexpr number_forms numbers = std::remove_cvref_t<decltype(T::nmea)>::numbers;
  if constexpr (is_ddmm_position<V> && numbers.unpadded_positions) {
    return codec<V>::read_unpadded(r, v);
  } else if constexpr (std::is_same_v<V, time_of_day> && numbers.rounded_seconds) {
    return codec<V>::read_rounded_seconds(r, v);
  } else {
    return codec<V>::read(r, v);
  }
}

template <class F, class T>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr errc read_field(const F& f, field_reader& r,
                                                              T& msg) noexcept {
  using V = typename F::value_type;
  auto& m = msg.*F::member;
  const field_options& o = f.opts;
  constexpr number_forms numbers = std::remove_cvref_t<decltype(T::nmea)>::numbers;
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
    if constexpr (numbers.nan_as_blank && (std::is_same_v<V, decimal> || is_integer_field<V>)) {
      // The sender's "nan": no value, as a blank is. Not under the sending rules.
      if (t.present && is_nan_text(t.text) && !r.policy().strict_values) nothing = codec<V>::width;
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
      if constexpr (keeps_blank_units<T>) {
        // A unit letter left blank beside the blank value: kept, to be written back blank.
        const unsigned unit_field = r.index() + 1U;  // the unit letter's wire field, next
        if (o.unit != 0 && unit_field < 32 && r.peek().present && r.peek().blank())
          msg.*T::nmea.blank_units_member |= std::uint32_t{1} << unit_field;
      }
      return read_unit(r, o, false);
    }
    if constexpr (keeps_wire_fields<T>) {
      if (o.may_be_absent) msg.*T::nmea.wire_fields_member = 0;
    }
    // Read in place: a value built on the side and copied in would be copied through the
    // stack in wide loads that wait on the narrow stores that just wrote it.
    errc e = length_rule<V>(read_value<T>(r, m.emplace()), o);
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
    errc e = length_rule<V>(read_value<T>(r, m), o);
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

/// How decoding into a message went: the errc, and the field and column it names (as result<>
/// has them). One type for every caller, so that decode_into is one function per message, not
/// one per message and result type (decode<T>, each message_set's decode, visit).
struct decode_status {
  errc ec = errc::ok;
  std::uint16_t field = 0;
  std::uint16_t column = 0;

  /// The errc, field and column into a result<> of any value type.
  template <class R>
  constexpr void copy_to(R& r) const noexcept {
    r.ec = ec;
    r.field = field;
    r.column = column;
  }
};

/// decode<T>() into `msg`, a default-constructed T the caller owns (the value of a result, the
/// alternative of a variant), so that no finished message is ever copied. On error `msg` holds
/// what was read before it.
template <message_like T>
[[nodiscard]] constexpr decode_status decode_into(const sentence_view& s,
                                                  const parse_policy& policy, T& msg) noexcept {
  static_assert(!keeps_wire_fields<T> || !has_both_optional_kinds<T>(),
                "wire_fields_in: fields of only the longer form and fields left out at the end in "
                "one message are not supported");
  // Messages are '$' sentences: a '!' one (!AIVDM) is not the message, whatever its address.
  if (s.start != '$' || !T::nmea.matches(s.address)) return {errc::wrong_address, 0, 0};
  if constexpr (std::remove_cvref_t<decltype(T::nmea)>::any_talker) {
    (void)talker_of(msg).assign(std::string_view(s.address.data(), 2));  // matched "--XXX"
  }
  field_reader r(s, policy);
  errc e = read_fields(
      r, msg, std::make_index_sequence<std::remove_cvref_t<decltype(T::nmea.fields)>::size>{});
  if (e == errc::ok && !r.at_end() && !policy.extra_fields) {
    (void)r.take();
    e = errc::too_many_fields;
  }
  if (e != errc::ok) return {e, r.index(), r.column()};
  if constexpr (lists_field_counts<T>) {
    // Strict: a count between the standard forms is a sentence cut short; the first field
    // missing is named.
    if (policy.strict_values && !listed_field_count<T>(s.field_count)) [[unlikely]] {
      return {errc::too_few_fields, static_cast<std::uint16_t>(s.field_count + 1),
              static_cast<std::uint16_t>(s.body_column() + s.body.size())};
    }
  }
  return {};
}

/// f(m) for a default-initialized M of its own, returning what f returns. Where M is trivially
/// destructible, in storage of its own: GCC folds a local `M m;`, and a message built in a
/// variant or a result, into a clear of the whole message (a `rep stos` of ~200 bytes, ~15 ns a
/// sentence) before the members' initializers; placement new writes only those, and decoding
/// writes every field. A message's members all have initializers (docs/adding-a-message.md);
/// in a constant expression, where nothing may be left indeterminate, M is value-initialized.
template <class M, class F>
SEAWIRE_ALWAYS_INLINE constexpr decltype(auto) with_default_initialized(F&& f) {
  if (std::is_constant_evaluated()) {
    M m{};
    return f(m);
  }
  if constexpr (std::is_trivially_destructible_v<M>) {
    alignas(M) unsigned char storage[sizeof(M)];
    return f(*::new (static_cast<void*>(storage)) M);
  } else {
    M m;
    return f(m);
  }
}
}  // namespace detail

/// Decode a message from a sentence already split by parse(). A '!' sentence is never T
/// (wrong_address): messages are '$' sentences.
template <message_like T>
[[nodiscard]] constexpr result<T> decode(const sentence_view& s,
                                         const parse_policy& policy = {}) noexcept {
  // Into a T of its own, default-initialized, then copied into the result: a T built in the
  // result would be cleared whole first.
  return detail::with_default_initialized<T>([&](T& m) SEAWIRE_INLINE_LAMBDA {
    const detail::decode_status d = detail::decode_into(s, policy, m);
    if (d.ec == errc::ok) return result<T>{std::as_const(m)};
    return result<T>{T{}, d.ec, d.field, d.column};
  });
}

// decode<T>(std::string_view line) is in one_pass.hpp (included at the end of this header).

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

template <class F, class W, class T>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr errc write_field(const F& f, W& w, const T& msg,
                                                               bool& skip_rest,
                                                               std::uint16_t first_wire) noexcept {
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
    errc e = errc::ok;
    if constexpr (std::is_same_v<V, time_of_day> &&
                  std::remove_cvref_t<decltype(T::nmea)>::numbers.rounded_seconds) {
      e = codec<V>::template check_form<true>(*v);
    } else {
      e = codec<V>::check(*v);
    }
    if (e == errc::ok) e = check_options(*v, o);
    if constexpr (is_ddmm_position<V> &&
                  !std::remove_cvref_t<decltype(T::nmea)>::numbers.unpadded_positions) {
      // Receivers of this message read "22.2" as 22 degrees (or refuse it): only a message whose
      // sender writes the unpadded form may carry it.
      if (e == errc::ok && v->unpadded) e = V::axis_type::error;
    }
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
    if constexpr (whole_number<V> && std::is_unsigned_v<V>) {
      w.put_uint(*v, o.zero_pad);
    } else if constexpr (is_integer_wrapper<V>) {
      // check() has refused a value outside the type: an unsigned one is not negative here.
      if constexpr (std::is_unsigned_v<typename V::value_type>) {
        w.put_uint(static_cast<std::uint64_t>(v->value()), o.zero_pad);
      } else {
        codec<V>::write(w, *v);
      }
    } else {
      codec<V>::write(w, *v);
    }
  } else {
    for (unsigned k = 1; k < codec<V>::width; ++k) w.next_field();
  }
  if (o.unit != 0) {
    w.next_field();
    bool blank = false;
    if constexpr (keeps_blank_units<T>) {
      // Blank as it came: only beside a blank value (a value always has its unit).
      const unsigned unit_field = first_wire + f.width() - 1U;
      blank =
          !has && unit_field < 32 && ((msg.*T::nmea.blank_units_member >> unit_field) & 1U) != 0;
    }
    if (!blank) w.put(o.unit);
  }
  return errc::ok;
}

}  // namespace detail

namespace detail {
/// The longest sentence encode_to can write for T: '$', the address, a comma and the longest
/// text of each field (codec max_chars, wider zero padding, ",X" for a unit letter), "*hh\r\n".
/// 0 when a field's codec does not say how long it can be.
template <message_like T>
[[nodiscard]] consteval std::size_t longest_sentence() noexcept {
  std::size_t n = 1 + T::nmea.address.size() + 5;
  bool known = true;
  const auto add = [&](const auto& f) {
    using V = typename std::remove_cvref_t<decltype(f)>::value_type;
    if constexpr (requires { codec<V>::max_chars; }) {
      std::size_t chars = codec<V>::max_chars;
      if constexpr (is_integer_field<V>) {
        constexpr unsigned most = seawire::detail::max_integer_digits;
        const std::size_t pad = f.opts.zero_pad < most ? f.opts.zero_pad : most;
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

/// encode_sentence's walk over the fields, through the writer W. Inlined where it is called (the
/// one place): left to GCC 12, the walk's lambdas went out of line and encode cost 2-7% more
/// instructions than with the room checked at each write.
template <class W, message_like T>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr result<std::size_t> write_sentence(
    const T& msg, std::span<char> out) noexcept {
  W w(out);
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
    e = detail::write_field(f, w, msg, skip_rest, wire_field);
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

/// Whether encode can write T with its unchecked writer: every field's codec takes any
/// sentence_writer, and says how long its text gets (longest_sentence is not 0).
template <message_like T>
[[nodiscard]] consteval bool writes_unchecked() noexcept {
  if constexpr (longest_sentence<T>() == 0) {
    return false;
  } else {
    return T::nmea.fields.apply([](const auto&... f) {
      return (requires(basic_writer<false> & w,
                       const typename std::remove_cvref_t<decltype(f)>::value_type& v) {
        codec<typename std::remove_cvref_t<decltype(f)>::value_type>::write(w, v);
      } && ...);
    });
  }
}

/// encode_sentence into a buffer shorter than T's longest sentence: with the room checked at each
/// write (a sentence that does not fit is buffer_too_small). Out of line: kept out of the common
/// case's code. (Written in storage of encode's own and copied instead, such a sentence took
/// 20-35% more time on the benchmark's 256-byte buffer, for CPIMU, BFNVG or BFACK, whose
/// longest sentences are longer.)
template <message_like T>
[[nodiscard]] SEAWIRE_NOINLINE constexpr result<std::size_t> encode_checked(
    const T& msg, std::span<char> out) noexcept {
  return write_sentence<writer>(msg, out);
}

/// encode_to's work (below). With one check of the room, where T's codecs say how long they
/// write: a buffer that holds T's longest sentence is written without looking at the room left,
/// a shorter one with the room checked at each write.
template <message_like T>
[[nodiscard]] constexpr result<std::size_t> encode_sentence(const T& msg,
                                                            std::span<char> out) noexcept {
  if constexpr (writes_unchecked<T>()) {
    if (out.size() >= longest_sentence<T>()) return write_sentence<basic_writer<false>>(msg, out);
    return encode_checked(msg, out);
  } else {
    return write_sentence<writer>(msg, out);
  }
}

/// Whether T's encoder is compiled once, by <seawire/impl/src.hpp> (SEAWIRE_SEPARATE_COMPILATION;
/// a family header says so for each of its messages with SEAWIRE_COMPILED_ENCODER).
template <class T>
inline constexpr bool compiled_encoder = false;

/// encode_sentence, not inline: where it is declared `extern template`, callers only reference it.
template <message_like T>
[[nodiscard]] result<std::size_t> compiled_encode_to(const T& msg, std::span<char> out) noexcept {
  return encode_sentence(msg, out);
}
}  // namespace detail

/// Write a message as a sealed sentence into `out`. Values outside their field's domain are
/// refused with the field number; nothing partial is reported as success.
template <message_like T>
[[nodiscard]] constexpr result<std::size_t> encode_to(const T& msg, std::span<char> out) noexcept {
  if constexpr (detail::compiled_encoder<T>) {
    return detail::compiled_encode_to(msg, out);
  } else {
    return detail::encode_sentence(msg, out);
  }
}

namespace detail {
/// The buffer encode() gives a message: 256 bytes, or more when its longest sentence needs more
/// (or its description's buffer_size_at_least says so), so that whatever decodes also encodes.
/// Constrained, so that encode(x) for an x that is no message is no candidate (not an error in
/// this body) wherever a call named encode finds seawire::nmea by argument-dependent lookup:
/// Clang 14 forms encode's return type before it checks encode's own constraint.
template <message_like T>
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

}  // namespace seawire::nmea

// In a family header, at global scope: the message's encoder is compiled once, by
// <seawire/impl/src.hpp>, when SEAWIRE_SEPARATE_COMPILATION is defined; otherwise nothing.
#if defined(SEAWIRE_SEPARATE_COMPILATION)
#define SEAWIRE_COMPILED_ENCODER(M)                                                          \
  template <>                                                                                \
  inline constexpr bool seawire::nmea::detail::compiled_encoder<M> = true;                   \
  extern template seawire::result<std::size_t> seawire::nmea::detail::compiled_encode_to<M>( \
      const M&, std::span<char>) noexcept;
#else
#define SEAWIRE_COMPILED_ENCODER(M)
#endif

// decode<T>(line): the plain form read in one pass, the general path for the rest.
#include "seawire/nmea/one_pass.hpp"  // IWYU pragma: export
