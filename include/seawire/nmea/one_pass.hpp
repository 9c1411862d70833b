// SPDX-License-Identifier: BSL-1.0
#pragma once
// One-pass decoding of a sentence in its plain form. Most lines of a log are plain: '$', an
// address, every field the message declares, "*hh" with the right checksum. For those, the
// decoders here read the line once, from left to right: each field's value is converted where
// it stands, by its codec's scan(), which stops at the first byte that is no part of it (the
// ',' or the final '*'), so nothing splits the line first and no digit loop tests a length.
//
// The one-pass path only ever accepts: it gives a value, or it gives up and the general path
// (parse + the field reader) decodes the line from the start and gives the value or the error,
// with its field and column. It gives up on everything that is not the plain form (a missing or
// wrong checksum, extra or missing fields, a '+' sign, spaces, "NaN", a value out of range, a
// field the general path would pass over without reading), so what it accepts the general path
// reads to the same value under any parse_policy. Tests and a fuzzer hold the two paths to that.

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

#include "seawire/detail/ascii.hpp"
#include "seawire/detail/byte_order.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/detail/simd.hpp"
#include "seawire/nmea/codec.hpp"
#include "seawire/nmea/description.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"

namespace seawire::nmea::detail {

/// A codec with a one-pass reader: `scan(p, end, v)` reads the value whose first wire field
/// starts at `p` and returns the byte after its last one, or nullptr to give up. `p` is at a
/// blank field (at a ',' or at `end`) only where the codec says its scanner refuses one
/// (scan_refuses_blank; see scans_no_blank).
/// `end` is the body's end, the '*' of "*hh": the three bytes from it may be read, nothing after.
template <class V>
concept one_pass_codec = requires(const char* p, V& v) {
  { codec<V>::scan(p, p, v) } -> std::same_as<const char*>;
};

/// A line in the plain form, framed: its address, and its body up to (not including) the '*'.
struct plain_line {
  std::string_view address;
  std::uint64_t head = 0;  ///< the address's first 8 bytes, as dispatch keys them
  const char* body = nullptr;
  const char* end = nullptr;
};

/// Frames `line` if it is in the plain form under `policy`: '$', an address and a ',', and
/// "*hh" matching the XOR of the bytes between, at the end (before a line ending the policy
/// allows); at least 9 bytes and no longer than the policy's max_length. The bytes of the body
/// are not looked at: the codecs' scan() accept only bytes a sentence may hold.
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr bool frame_plain(std::string_view line,
                                                               const parse_policy& policy,
                                                               plain_line& out) noexcept {
  std::size_t n = line.size();
  if (n >= 2 && line[n - 2] == '\r' && line[n - 1] == '\n') {
    n -= 2;
  } else if (policy.require_crlf) {
    return false;
  } else if (n >= 1 && (line[n - 1] == '\n' || line[n - 1] == '\r')) {
    n -= 1;
  }
  const std::size_t longest = policy.max_length < 0xFFFF ? policy.max_length : 0xFFFF;
  if (n < 9 || n > longest || line[0] != '$' || line[n - 3] != '*') [[unlikely]]
    return false;
  const char h = line[n - 2];
  const char l = line[n - 1];
  const int hv = seawire::detail::hex_value(h);
  const int lv = seawire::detail::hex_value(l);
  if (hv < 0 || lv < 0 || (!policy.lowercase_hex && (h >= 'a' || l >= 'a'))) [[unlikely]]
    return false;
  const char* b = line.data() + 1;
  const char* const e = line.data() + n - 3;
  std::uint64_t words = 0;
#if SEAWIRE_SIMD
  if (!std::is_constant_evaluated()) {
    namespace simd = seawire::detail::simd;
    simd::bytes16 x16 = simd::zero();
    for (; e - b >= 16; b += 16) x16 = x16 ^ simd::load(b);
    words = simd::xor_halves(x16);
  }
#endif
  for (; e - b >= 8; b += 8) words ^= seawire::detail::load_le64(b);
  if (b != e && e - line.data() >= 8) {
    // 1 to 7 bytes left: the word that ends with them, less the bytes before them
    const auto left = static_cast<unsigned>(e - b);
    words ^= seawire::detail::load_le64(e - 8) >> (8U * (8U - left));
  } else {
    for (; b != e; ++b) words ^= static_cast<unsigned char>(*b);
  }
  words ^= words >> 32U;
  words ^= words >> 16U;
  words ^= words >> 8U;
  if (static_cast<std::uint8_t>(words) != hv * 16 + lv) [[unlikely]]
    return false;

  std::size_t address_end = address_end_word(line);  // 0: the first 8 bytes are all address
  if (address_end == 0) {
    address_end = 9;
    while (address_end <= 16 && (seawire::detail::is_upper(line[address_end]) ||
                                 seawire::detail::is_digit(line[address_end])))
      ++address_end;
  }
  if (address_end == 1 || address_end > 16 || line[address_end] != ',') [[unlikely]]
    return false;
  const std::size_t size = address_end - 1;
  out.address = std::string_view(line.data() + 1, size);
  out.head = seawire::detail::load_le64(line.data() + 1);
  if (size < 8) out.head &= (std::uint64_t{1} << (8U * size)) - 1U;
  out.body = line.data() + address_end + 1;
  out.end = e;
  return true;
}

/// Where the one-pass reader stands: at the start of a wire field, or past the last one.
struct plain_cursor {
  const char* p;
  const char* end;
  bool done = false;
  std::uint16_t fields = 0;  ///< the body's field count, for a message that needs it
};

/// Past a value that ended at `q`: on to the next field, or done at the body's end. false when
/// `q` is not a field's end.
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr bool next_plain_field(plain_cursor& c,
                                                                    const char* q) noexcept {
  // `end` is the '*' of "*hh", no ','; the commoner case first.
  if (*q == ',') [[likely]] {
    c.p = q + 1;
    return true;
  }
  c.done = q == c.end;
  return c.done;
}

/// The unit letter's field after a value: blank or the letter; absent only after no value.
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr bool plain_unit(plain_cursor& c,
                                                              const field_options& o,
                                                              bool value_present) noexcept {
  if (o.unit == 0) return true;
  if (c.done) return !value_present;
  const char* q = c.p;
  if (q != c.end && *q == o.unit) ++q;
  return next_plain_field(c, q);
}

/// A one-field value whose codec has no scan(): the field's bytes (each one a sentence may
/// hold) read by the codec's read() through a field reader of that one field.
template <class T, class V>
[[nodiscard]] constexpr const char* scan_token(const char* p, const char* end, V& v,
                                               const parse_policy& policy) noexcept {
  const char* q = p;
  for (; q != end && *q != ','; ++q)
    if (!seawire::detail::is_printable(*q) || *q == '$' || *q == '*') return nullptr;
  sentence_view one;
  one.body = std::string_view(p, static_cast<std::size_t>(q - p));
  one.field_count = 1;
  one.checksum = checksum_state::valid;
  field_reader r(one, policy);
  return read_value<T>(r, v) == errc::ok && r.at_end() ? q : nullptr;
}

template <class T, class V>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr const char* scan_value(
    const char* p, const char* end, V& v, const parse_policy& policy) noexcept {
  constexpr number_forms numbers = std::remove_cvref_t<decltype(T::nmea)>::numbers;
  if constexpr (!one_pass_codec<V>) {
    return scan_token<T>(p, end, v, policy);
  } else if constexpr (std::is_same_v<V, time_of_day> && numbers.rounded_seconds) {
    return codec<V>::scan_rounded_seconds(p, end, v);
  } else if constexpr (is_ddmm_position<V> && numbers.unpadded_positions) {
    return codec<V>::scan_unpadded(p, end, v);
  } else {
    return codec<V>::scan(p, end, v);
  }
}

/// The end of the wire fields at the cursor when they hold no value (a blank field, for a
/// value of several fields all of them blank); nullptr when they hold one, or when only the
/// general path can tell.
template <class V>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr const char* plain_nothing(
    const plain_cursor& c) noexcept {
  if constexpr (requires { codec<V>::scan_nothing(c.p, c.end); }) {
    return codec<V>::scan_nothing(c.p, c.end);
  } else if constexpr (codec<V>::allows_blank) {
    return nullptr;  // blank is a value (empty text), not its absence
  } else {
    if (c.p != c.end && *c.p != ',') return nullptr;
    const char* q = c.p;
    for (unsigned k = 1; k < codec<V>::width; ++k) {
      if (q == c.end || (q + 1 != c.end && q[1] != ',')) return nullptr;
      ++q;
    }
    return q;
  }
}

/// Whether V's codec says its scanner refuses a blank field (scan_refuses_blank).
template <class V>
concept claims_scan_refuses_blank = requires {
  requires codec<V>::scan_refuses_blank;
};

/// Whether T's scanner of V refuses a field that holds nothing at its first byte, whatever
/// follows, on the codec's word (`static constexpr bool scan_refuses_blank = true;`): then a
/// field is scanned first, and tested for a blank only where the scanner refuses it (most fields
/// hold a value). A codec that does not say so (a variation's, whose scanner reads a letter
/// without its number; text's, whose blank is a value; a codec of your own) is tested first.
/// Where a codec says so, its scanner is also run here, at compile time, on a blank field at
/// the body's end and before each of the fields a more lenient scanner would take (a letter,
/// digits, a position): a claim those contradict does not compile.
template <class T, class V>
inline constexpr bool scans_no_blank = [] {
  if constexpr (!one_pass_codec<V> || codec<V>::allows_blank || !claims_scan_refuses_blank<V>) {
    return false;
  } else {
    constexpr bool refused = [] {
      // What follows the blank field, one case per line: each is tried up to its "*hh".
      constexpr std::string_view cases =
          "\n,\n,0\n,1\n,A\n,E\n,N\n,S\n,T\n,M\n,W\n,V,\n,1.5\n,0,N,\n,12345\n,123456.00,"
          "010203\n,1234.5678,N,12345.6789,E,123456.00\n";
      for (std::size_t at = 0; at < cases.size();) {
        const std::size_t eol = cases.find('\n', at);
        std::array<char, 48> line{};  // the blank field, what follows it, then "*00"
        std::size_t n = 0;
        for (const char ch : cases.substr(at, eol - at)) line[n++] = ch;
        const char* const end = line.data() + n;
        line[n] = '*';
        line[n + 1] = line[n + 2] = '0';
        V v{};
        if (scan_value<T>(line.data(), end, v, parse_policy{}) != nullptr) return false;
        at = eol + 1;
      }
      return true;
    }();
    static_assert(refused, "scan_refuses_blank, but the codec's scan() takes a blank field");
    return true;
  }
}();

/// A field's value, scanned up to `q`: the field's rules checked, then on past its unit letter.
/// (may_be_absent is an optional member's option only.)
template <class T, class V>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr bool plain_value(plain_cursor& c, const char* q,
                                                               T& msg, const V& v,
                                                               const field_options& o) noexcept {
  if constexpr (keeps_wire_fields<T>) {
    if (o.may_be_absent) msg.*T::nmea.wire_fields_member = 0;
  }
  return check_options(v, o) == errc::ok && next_plain_field(c, q) && plain_unit(c, o, true);
}

/// Field I of the description, as read_field() reads it, for the plain form only.
template <std::size_t I, class F, class T>
[[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr bool plain_field(
    const F& f, plain_cursor& c, T& msg, const parse_policy& policy) noexcept {
  using V = typename F::value_type;
  auto& m = msg.*F::member;
  const field_options& o = f.opts;
  if constexpr (F::is_optional) {
    if (o.only_with_field_count != 0 && c.fields < o.only_with_field_count) {
      clear_optional(m);  // a field of only the longer form, in the shorter
      return true;
    }
    if (c.done) {  // absent: blank, after a valid checksum, unless the policy holds to the form
      if (!o.may_be_absent && (policy.strict_values || !policy.absent_as_blank)) return false;
      clear_optional(m);
      return true;
    }
    const char* q = nullptr;
    if constexpr (scans_no_blank<T, V>) {
      q = scan_value<T>(c.p, c.end, m.emplace(), policy);
      if (q != nullptr) [[likely]]
        return plain_value(c, q, msg, *m, o);
    }
    if (q = plain_nothing<V>(c); q != nullptr) {
      if constexpr (keeps_wire_fields<T>) {
        if (o.may_be_absent) return false;  // the blank's field count is kept: general path
        if (o.only_with_field_count != 0)
          msg.*T::nmea.wire_fields_member =
              static_cast<std::uint8_t>(c.fields < 255 ? c.fields : 255);
      }
      clear_optional(m);
      if (!next_plain_field(c, q)) return false;
      if constexpr (keeps_blank_units<T>) {
        // A blank unit after no value is kept, to be written back blank (blank_units_in).
        constexpr unsigned unit_field = field_starts<T>[I] + codec<V>::width + 1U;
        if (o.unit != 0 && unit_field < 32 && !c.done && (c.p == c.end || *c.p == ','))
          msg.*T::nmea.blank_units_member |= std::uint32_t{1} << unit_field;
      }
      return plain_unit(c, o, false);
    }
    if constexpr (scans_no_blank<T, V>) {
      return false;  // neither a value nor nothing: the general path says what it is
    } else {
      if constexpr (!codec<V>::allows_blank && codec<V>::width > 1) {
        // A blank first field with more after it: the general path passes over the value's
        // fields whole, whatever the others hold (read_field); its to say, not the scanner's.
        if (c.p == c.end || *c.p == ',') return false;
      }
      q = scan_value<T>(c.p, c.end, m.emplace(), policy);
      return q != nullptr && plain_value(c, q, msg, *m, o);
    }
  } else {
    if (c.done) return false;
    if constexpr (!scans_no_blank<T, V>) {
      if (!codec<V>::allows_blank || o.min_length > 0) {
        if (c.p == c.end || *c.p == ',') return false;
      }
    }
    const char* const q = scan_value<T>(c.p, c.end, m, policy);
    return q != nullptr && plain_value(c, q, msg, m, o);
  }
}

/// Whether field `f` is read in one pass: by its codec's scan(), or through its read() if it
/// is one wire field.
template <class F>
[[nodiscard]] constexpr bool plain_field_readable(const F&) noexcept {
  using V = typename F::value_type;
  return one_pass_codec<V> || codec<V>::width == 1;
}

/// Whether every field of T is read in one pass: only then is T decoded in one pass.
template <class T>
inline constexpr bool plain_decodable = T::nmea.fields.apply([](const auto&... f) {
  return (plain_field_readable(f) && ...);
});

/// Whether a field of T is only in the longer of its forms (only_with_field_count): then the
/// one-pass reader counts the body's fields first.
template <class T>
inline constexpr bool counts_plain_fields = T::nmea.fields.apply([](const auto&... f) {
  return ((f.opts.only_with_field_count != 0) || ...);
});

/// Decodes the framed line into `msg` (default-constructed); false to give up, `msg` then
/// holding anything.
template <class T>
[[nodiscard]] constexpr bool decode_plain(const plain_line& l, const parse_policy& policy,
                                          T& msg) noexcept {
  if constexpr (lists_field_counts<T>) {
    if (policy.strict_values) return false;  // the count is checked against the list: general
  }
  if constexpr (std::remove_cvref_t<decltype(T::nmea)>::any_talker) {
    // The address is T's, "--XXX": two bytes, a copy of constant size.
    (void)talker_of(msg).assign(std::string_view(l.address.data(), 2));
  }
  plain_cursor c{l.body, l.end};
  if constexpr (counts_plain_fields<T>) {
    std::size_t commas = 0;
    for (const char* p = l.body; p != l.end; ++p) commas += *p == ',' ? 1U : 0U;
    c.fields = static_cast<std::uint16_t>(commas + 1);
  }
  constexpr std::size_t n = std::remove_cvref_t<decltype(T::nmea.fields)>::size;
  return [&]<std::size_t... I>(std::index_sequence<I...>) SEAWIRE_INLINE_LAMBDA {
    return (plain_field<I>(field_at<I>(T::nmea.fields), c, msg, policy) && ...);
  }
  (std::make_index_sequence<n>{}) && c.done;
}

}  // namespace seawire::nmea::detail

namespace seawire::nmea {

/// Decodes one line as T: the plain form in one pass (one_pass.hpp), anything else through
/// parse() and decode(sentence_view), which gives the value or the error with its field and
/// column.
template <message_like T>
[[nodiscard]] constexpr result<T> decode(std::string_view line,
                                         const parse_policy& policy = {}) noexcept {
  // Each path returns the result it builds in its return statement: built where the caller
  // wants it, never copied there. The one-pass path reads into a T of its own, default-
  // initialized (detail::with_default_initialized: a T built in the result is cleared whole
  // first), and copies it into the result.
  const auto split = [&]() -> result<T> {
    const result<sentence_view> s = parse(line, policy);
    if (!s) return detail::parse_failure<T>(s);
    return decode<T>(s.value, policy);
  };
  if constexpr (detail::plain_decodable<T>) {
    detail::plain_line l;
    if (detail::frame_plain(line, policy, l) && T::nmea.matches(l.address)) {
      return detail::with_default_initialized<T>([&](T& m) SEAWIRE_INLINE_LAMBDA {
        if (detail::decode_plain(l, policy, m)) return result<T>{std::as_const(m)};
        return split();
      });
    }
  }
  return split();
}

}  // namespace seawire::nmea
