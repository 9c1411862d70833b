// SPDX-License-Identifier: BSL-1.0
#pragma once
// What the fuzz targets share: a failure report that stops the run, the checksum and CRC
// fix-ups that let the fuzzer past the integrity checks, a byte source to build values from,
// and the properties every NMEA-style decoder and encoder must have.
//
// The properties, for a message set S (check_sentence_input):
//  1. parse() of any line either fails with a sentence-level errc and no field number, or gives
//     a sentence_view whose parts are the line's own bytes, re-joinable into the line (from its
//     start, '$' or '!'). A '!' sentence is never a message: it decodes to unknown_sentence.
//  2. A failed decode reports a column inside the line, and a field number exactly when the
//     error is about a field (then a field the message has, or one past it for too_many_fields).
//  3. Every policy accepts a subset of what the most liberal policy accepts, and decodes it to
//     the same value (strict is liberal minus some inputs, never a different reading).
//  4. A decoded value v encodes, unless v carries text with a reserved character (! \ ^ ~),
//     which liberal receivers accept and encoders refuse with bad_text; that is the one
//     documented receive-liberally case, so encode must fail then and only then.
//  5. What encode writes is a sealed sentence of printable ASCII with upper-case hex, which the
//     strict policy decodes, through S's dispatch, to the same message type and the same value
//     (decode -> encode -> decode is the identity), and which encodes again to the same bytes.
//  6. decode(line), which reads a line in the plain form in one pass (nmea/one_pass.hpp), and
//     the general path (parse, then decode of the sentence_view) give the same message and
//     value, or the same error with the same field and column, under every policy; so do
//     decode<M>(line) and decode<M>(sentence_view) for the message M the address names.
// For encoders fed arbitrary values (check_encoder): when encode succeeds, property 5 holds.

#include <algorithm>
#include <array>
#include <chrono>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "../tests/hex_of.hpp"
#include "seawire/detail/ascii.hpp"
#include "seawire/detail/crc32.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/variation.hpp"
#include "seawire/nmea/writer.hpp"
#include "seawire/registry.hpp"

namespace seawire::fuzz {

using support::hex_of;

// ---------------------------------------------------------------------------------------------
// reporting

/// Bytes as C-escaped text, for failure reports.
inline std::string escaped(std::string_view s) {
  std::string out;
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\\') {
      out += "\\\\";
    } else if (u >= 0x20 && u < 0x7F) {
      out += c;
    } else {
      out += "\\x";
      out += "0123456789abcdef"[u >> 4U];
      out += "0123456789abcdef"[u & 15U];
    }
  }
  return out;
}

/// Prints what broke and aborts: libFuzzer keeps the input, a replay test fails.
[[noreturn]] inline void fail(const char* file, int line, const char* what,
                              std::initializer_list<std::string_view> context) {
  std::fprintf(stderr, "\n%s:%d: property violated: %s\n", file, line, what);
  for (const std::string_view c : context) std::fprintf(stderr, "  %s\n", escaped(c).c_str());
  std::fflush(stderr);
  std::abort();
}

// A macro, so the report names the line of the property that failed.
// NOLINTNEXTLINE(cppcoreguidelines-macro-usage)
#define SEAWIRE_FUZZ_CHECK(cond, ...) \
  ((cond) ? (void)0 : ::seawire::fuzz::fail(__FILE__, __LINE__, #cond, {__VA_ARGS__}))

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) noexcept {
  return size == 0 ? std::string_view{}
                   : std::string_view(reinterpret_cast<const char*>(data), size);
}

inline std::string number(std::uint64_t v) { return std::to_string(v); }

// ---------------------------------------------------------------------------------------------
// integrity fix-ups

/// Chunk sizes for feeding a stream reader of `capacity` bytes in pieces: mostly 0 to 8 bytes
/// (the boundary cases), sometimes up to twice the capacity (longer than a line); the same
/// sequence for the same seed, so that a finding replays.
class chunk_sizes {
 public:
  chunk_sizes(std::size_t capacity, std::uint8_t seed) noexcept
      : capacity_(capacity), x_(0x9E3779B9U ^ seed) {}
  std::size_t operator()() noexcept {
    x_ ^= x_ << 13U;
    x_ ^= x_ >> 17U;
    x_ ^= x_ << 5U;
    return (x_ & 3U) == 0 ? std::size_t{x_ >> 8U} % (2 * capacity_ + 2) : std::size_t{x_ >> 8U} % 9;
  }

 private:
  std::size_t capacity_;
  std::uint32_t x_;
};

/// The line with a checksum that matches, so a fuzzed sentence gets past the XOR check: the
/// two characters after the first '*' become the XOR of the bytes between the start ('$' or '!')
/// and '*' (in lower case when the input used a lower-case letter there, to keep that path in
/// play), or "*HH" is appended before the line ending when there is no '*'. A line that does not
/// start with '$' or '!', or whose '*' is followed by other than two characters, is returned
/// unchanged:
/// those are the framing errors the raw input is there to test.
inline std::string with_good_checksum(std::string_view line) {
  std::string out(line);
  if (out.empty() || (out[0] != '$' && out[0] != '!')) return out;
  std::size_t n = out.size();
  if (n >= 2 && out[n - 2] == '\r' && out[n - 1] == '\n') {
    n -= 2;
  } else if (out[n - 1] == '\r' || out[n - 1] == '\n') {
    n -= 1;
  }
  const std::size_t star = out.find('*', 1);
  if (star >= n) {
    const std::uint8_t x = nmea::checksum(std::string_view(out).substr(1, n - 1));
    const char hex[3] = {'*', seawire::detail::hex_digit_upper(x >> 4U),
                         seawire::detail::hex_digit_upper(x)};
    out.insert(n, hex, 3);
    return out;
  }
  if (n - star - 1 != 2) return out;
  const std::uint8_t x = nmea::checksum(std::string_view(out).substr(1, star - 1));
  const bool lower = (out[star + 1] >= 'a' && out[star + 1] <= 'f') ||
                     (out[star + 2] >= 'a' && out[star + 2] <= 'f');
  const auto digit = [lower](unsigned nibble) {
    const char c = seawire::detail::hex_digit_upper(nibble);
    return lower && c >= 'A' ? static_cast<char>(c - 'A' + 'a') : c;
  };
  out[star + 1] = digit(x >> 4U);
  out[star + 2] = digit(x & 15U);
  return out;
}

/// Writes the zlib CRC-32 of bytes [8, 56) big-endian into bytes [4, 8), when there are 56.
inline void fix_frame_crc(std::span<std::uint8_t> frame) noexcept {
  if (frame.size() < 56) return;
  const std::uint32_t crc = crc32(frame.subspan(8, 48));
  for (std::size_t i = 0; i < 4; ++i)
    frame[4 + i] = static_cast<std::uint8_t>(crc >> (24U - 8U * static_cast<unsigned>(i)));
}

// ---------------------------------------------------------------------------------------------
// a byte source for building values

/// Hands out the fuzzer's bytes as choices. Past the end every choice is 0 (or empty), so any
/// input builds a complete value.
class byte_source {
 public:
  explicit byte_source(std::span<const std::uint8_t> bytes) noexcept : rest_(bytes) {}

  [[nodiscard]] std::uint8_t byte() noexcept {
    if (rest_.empty()) return 0;
    const std::uint8_t b = rest_.front();
    rest_ = rest_.subspan(1);
    return b;
  }
  [[nodiscard]] bool coin() noexcept { return (byte() & 1U) != 0; }
  /// An integer from sizeof(I) bytes, little-endian.
  template <std::integral I>
  [[nodiscard]] I integer() noexcept {
    std::make_unsigned_t<I> v = 0;
    for (std::size_t i = 0; i < sizeof(I); ++i)
      v = static_cast<std::make_unsigned_t<I>>(
          v | static_cast<std::make_unsigned_t<I>>(std::make_unsigned_t<I>{byte()} << (8 * i)));
    return static_cast<I>(v);
  }
  /// 0 .. n-1, from one byte when n <= 256.
  [[nodiscard]] std::size_t below(std::size_t n) noexcept {
    if (n <= 1) return 0;
    if (n <= 256) return byte() % n;
    return integer<std::uint32_t>() % n;
  }
  /// Up to `max` bytes, length chosen first.
  [[nodiscard]] std::string_view bytes(std::size_t max) noexcept {
    const std::size_t want = below(max + 1);
    const std::size_t n = std::min(want, rest_.size());
    const std::string_view s = as_text(rest_.data(), n);
    rest_ = rest_.subspan(n);
    return s;
  }
  [[nodiscard]] std::span<const std::uint8_t> rest() const noexcept { return rest_; }
  [[nodiscard]] bool empty() const noexcept { return rest_.empty(); }

 private:
  std::span<const std::uint8_t> rest_;
};

// ---------------------------------------------------------------------------------------------
// values from bytes: one fill() per value type, over the whole domain of the C++ type (so the
// encoder's refusals are exercised as much as its output)

template <class T>
inline constexpr bool is_text_v = false;
template <std::size_t N>
inline constexpr bool is_text_v<nmea::text<N>> = true;

template <class T>
inline constexpr bool is_optional_v = false;
template <class T>
inline constexpr bool is_optional_v<std::optional<T>> = true;

inline void fill(byte_source& src, nmea::decimal& d) {
  // Mostly the numbers senders write; sometimes anything the struct can hold.
  switch (src.byte() % 4) {
    case 0: d.mantissa = src.byte(); break;
    case 1: d.mantissa = src.integer<std::uint16_t>(); break;
    case 2: d.mantissa = src.integer<std::uint32_t>(); break;
    default: d.mantissa = src.integer<std::uint64_t>(); break;
  }
  d.places = src.byte();
  if (d.places >= 32) d.places = static_cast<std::uint8_t>(d.places % 4);  // mostly 0..3
  d.negative = src.coin();
  d.int_width = src.byte();
  if (d.int_width >= 32) d.int_width = 0;  // mostly written naturally
}

template <std::integral I>
void fill(byte_source& src, I& v) {
  if constexpr (std::is_same_v<I, bool>) {
    v = src.coin();
  } else {
    v = src.integer<I>();
  }
}

// Any whole number at all, in range or not: encode must refuse what its type cannot carry.
template <class T>
void fill(byte_source& src, nmea::integer<T>& v) {
  v = src.coin() ? src.integer<std::int64_t>() : std::int64_t{src.integer<T>()};
}

template <class Axis>
void fill(byte_source& src, nmea::nmea_coordinate<Axis>& c) {
  c.whole_degrees = src.coin() ? src.byte() : src.integer<std::uint16_t>();
  fill(src, c.minutes);
  constexpr std::string_view letters = "NSEWX";
  c.hemi = static_cast<nmea::hemisphere>(letters[src.below(letters.size())]);
  c.degree_digits = static_cast<std::uint8_t>(src.below(6));
}

template <class Axis>
void fill(byte_source& src, nmea::decimal_coordinate<Axis>& c) {
  fill(src, c.value);
  constexpr std::string_view letters = "NSEWX";
  c.hemi = static_cast<nmea::hemisphere>(letters[src.below(letters.size())]);
}

inline void fill(byte_source& src, nmea::magnetic_variation& v) {
  if (src.coin()) {
    v.value.reset();
  } else {
    nmea::decimal d;
    fill(src, d);
    v.value = d;
  }
  constexpr std::string_view letters = "EWNX";
  v.direction = static_cast<nmea::hemisphere>(letters[src.below(letters.size())]);
}

inline void fill(byte_source& src, nmea::time_of_day& t) {
  t.hour = static_cast<std::uint8_t>(src.below(26));
  t.minute = static_cast<std::uint8_t>(src.below(62));
  t.second = static_cast<std::uint8_t>(src.below(62));
  t.places = static_cast<std::uint8_t>(src.below(11));
  t.fraction = src.integer<std::uint32_t>();
  if (t.places <= 9 && src.coin())
    t.fraction = static_cast<std::uint32_t>(t.fraction % seawire::detail::pow10_table[t.places]);
}

inline void fill(byte_source& src, nmea::date& d) {
  d.year =
      src.coin() ? static_cast<std::uint16_t>(1970 + src.byte()) : src.integer<std::uint16_t>();
  d.month = static_cast<std::uint8_t>(src.below(14));
  d.day = static_cast<std::uint8_t>(src.below(33));
}

template <std::size_t N>
void fill(byte_source& src, nmea::text<N>& t) {
  (void)t.assign(src.bytes(N));
}

template <class E>
requires nmea::char_enum_like<E>
void fill(byte_source& src, E& e) {
  constexpr std::string_view chars = seawire::nmea::enum_letters<E>;
  // One choice past the letters: any byte at all.
  const std::size_t i = src.below(chars.size() + 1);
  e = static_cast<E>(i < chars.size() ? chars[i] : static_cast<char>(src.byte()));
}

template <class E>
requires nmea::word_enum_like<E>
void fill(byte_source& src, E& e) {
  constexpr auto words = enum_words(E{});
  e = static_cast<E>(src.below(words.size() + 2));
}

template <class T>
void fill(byte_source& src, std::optional<T>& o) {
  if (src.coin()) {
    o.reset();
  } else {
    T v{};
    fill(src, v);
    o = v;
  }
}

/// A message, field by field from its description; the talker too for "--XXX" messages.
template <nmea::message_like M>
M make_message(byte_source& src) {
  M m{};
  if constexpr (std::remove_cvref_t<decltype(M::nmea)>::any_talker) {
    constexpr std::string_view alphabet = "GPINVWAE0Z9a,*$";
    char t[2] = {alphabet[src.below(alphabet.size())], alphabet[src.below(alphabet.size())]};
    (void)nmea::detail::talker_of(m).assign(
        std::string_view(t, src.below(4) == 0 ? src.below(3) : 2));
  }
  nmea::for_each_field(m, [&](std::string_view, auto& member) { fill(src, member); });
  return m;
}

// ---------------------------------------------------------------------------------------------
// message properties

/// Field-by-field equality over the description (the talker too): what "the same value" means.
template <nmea::message_like M>
bool same_message(const M& a, const M& b) {
  bool same = true;
  if constexpr (std::remove_cvref_t<decltype(M::nmea)>::any_talker)
    same = nmea::detail::talker_of(a) == nmea::detail::talker_of(b);
  M::nmea.fields.apply(
      [&](const auto&... d) { ((same = same && a.*(d.member) == b.*(d.member)), ...); });
  return same;
}

/// Whether the message holds text with a character NMEA reserves ('!', '\', '^', '~'; the
/// others cannot reach a decoded field): the liberal receive case encoders refuse.
template <nmea::message_like M>
bool has_reserved_text(const M& m) {
  bool reserved = false;
  const auto in = [](std::string_view s) {
    return std::any_of(s.begin(), s.end(), [](char c) { return seawire::detail::is_reserved(c); });
  };
  nmea::for_each_field(m, [&](std::string_view, const auto& member) {
    using T = std::remove_cvref_t<decltype(member)>;
    if constexpr (is_text_v<T>) {
      reserved = reserved || in(member.view());
    } else if constexpr (is_optional_v<T>) {
      if constexpr (is_text_v<typename T::value_type>) {
        reserved = reserved || (member && in(member->view()));
      }
    }
  });
  return reserved;
}

/// Wire fields the description spans.
template <nmea::message_like M>
constexpr std::size_t wire_width() {
  return M::nmea.fields.apply([](const auto&... d) { return (std::size_t{0} + ... + d.width()); });
}

/// The policies every decoder target tries besides its roles' own: the most liberal one (any
/// checksum, anything else the defaults take) and the strict one (what seawire sends).
inline constexpr nmea::parse_policy liberal_policy = [] {
  nmea::parse_policy p;
  p.checksum = nmea::checksum_policy::ignore;
  p.spaced_numbers = true;
  p.empty_checksum = true;
  return p;
}();
inline constexpr nmea::parse_policy strict_policy = nmea::parse_policy::strict();

inline bool sentence_level(errc e) {
  return (e >= errc::empty_input && e <= errc::too_long) || e == errc::trailing_characters;
}
inline bool field_level(errc e) {
  return (e >= errc::too_few_fields && e <= errc::bad_length) || e == errc::bad_variation ||
         e == errc::bad_variation_direction || e == errc::variation_out_of_range;
}

/// Property 5 for an encoded sentence of message M.
template <class Set, nmea::message_like M>
void check_encoded(const M& m, std::string_view sentence, std::string_view origin) {
  const std::string_view s = sentence;
  SEAWIRE_FUZZ_CHECK(
      s.size() >= 6 && s[0] == '$' && s.substr(s.size() - 2) == "\r\n" && s[s.size() - 5] == '*',
      origin, s);
  for (std::size_t i = 1; i + 5 < s.size(); ++i) {
    const char c = s[i];
    SEAWIRE_FUZZ_CHECK(
        seawire::detail::is_printable(c) && (c == ',' || !seawire::detail::is_reserved(c)), origin,
        s);
  }
  const std::string_view hex = s.substr(s.size() - 4, 2);
  for (const char c : hex) SEAWIRE_FUZZ_CHECK((c >= '0' && c <= '9') || (c >= 'A' && c <= 'F'), s);

  const result<typename Set::variant> back = Set::decode(s, strict_policy);
  SEAWIRE_FUZZ_CHECK(back.ok(), "strict decode of what encode wrote failed", origin, s,
                     name(back.ec), number(back.field));
  const M* again = std::get_if<M>(&back.value);
  SEAWIRE_FUZZ_CHECK(again != nullptr, "dispatch picked another message type", origin, s);
  SEAWIRE_FUZZ_CHECK(same_message(*again, m), "decode(encode(v)) != v", origin, s);

  std::array<char, 4096> buf{};
  const result<std::size_t> twice = nmea::encode_to(*again, buf);
  SEAWIRE_FUZZ_CHECK(twice.ok() && std::string_view(buf.data(), twice.value) == s,
                     "encode(decode(encode(v))) != encode(v)", origin, s);

  // encode(), with the buffer it picks for the message, writes the same bytes: its buffer holds
  // the longest sentence the message can have.
  const auto held = nmea::encode(m);
  SEAWIRE_FUZZ_CHECK(held.ec == errc::ok && held.view() == s, "encode() disagrees with encode_to()",
                     s, name(held.ec), number(sizeof held.data));

  // The room encode counts on. A message whose codecs say how long they write is written without
  // a check of the room when the buffer holds its longest sentence (exactly that much here, on
  // the heap, where the address sanitizer sees a byte written past it), and a shorter buffer
  // with the room checked at each write: a buffer of the sentence's size takes the same bytes,
  // one byte less none.
  constexpr std::size_t longest = nmea::detail::longest_sentence<M>();
  if constexpr (nmea::detail::writes_unchecked<M>()) {
    SEAWIRE_FUZZ_CHECK(s.size() <= longest, "a sentence longer than its message's longest", s,
                       number(longest));
    std::vector<char> room(longest, '#');
    const result<std::size_t> in_room = nmea::encode_to(m, std::span<char>(room));
    SEAWIRE_FUZZ_CHECK(in_room.ok() && std::string_view(room.data(), in_room.value) == s,
                       "encode_to into the longest sentence's room disagrees", s);
  }
  std::vector<char> exact(s.size(), '#');
  const result<std::size_t> in_exact = nmea::encode_to(m, std::span<char>(exact));
  SEAWIRE_FUZZ_CHECK(in_exact.ok() && std::string_view(exact.data(), in_exact.value) == s,
                     "encode_to into a buffer of the sentence's size disagrees", s);
  std::vector<char> short_by_one(s.size() - 1, '#');
  const result<std::size_t> in_short = nmea::encode_to(m, std::span<char>(short_by_one));
  SEAWIRE_FUZZ_CHECK(in_short.ec == errc::buffer_too_small,
                     "encode_to into a buffer a byte short of the sentence", s, name(in_short.ec));
}

/// Properties 4 and 5 for a decoded message.
template <class Set, nmea::message_like M>
void check_decoded(const M& m, const nmea::parse_policy& policy, std::string_view line) {
  std::array<char, 4096> buf{};
  const result<std::size_t> e = nmea::encode_to(m, buf);
  if (has_reserved_text(m)) {
    SEAWIRE_FUZZ_CHECK(!policy.strict_values, "strict decode let reserved text through", line);
    SEAWIRE_FUZZ_CHECK(e.ec == errc::bad_text, "encode took reserved text", line, name(e.ec));
    return;
  }
  SEAWIRE_FUZZ_CHECK(e.ok(), "encode refused a value decode produced", line, name(e.ec),
                     number(e.field), nmea::field_name<M>(e.field));
  check_encoded<Set>(m, std::string_view(buf.data(), e.value), line);
}

/// Property 1: the parts of a parsed sentence are the line's bytes.
inline void check_parsed(const nmea::sentence_view& s, std::string_view line) {
  SEAWIRE_FUZZ_CHECK(!s.line.empty() && (s.start == '$' || s.start == '!') &&
                         s.line[0] == s.start && line.substr(0, s.line.size()) == s.line,
                     line);
  SEAWIRE_FUZZ_CHECK(s.line.substr(1, s.address.size()) == s.address, line);
  std::string rebuilt(1, s.start);
  rebuilt += s.address;
  if (s.field_count > 0 || !s.body.empty()) {
    rebuilt += ',';
    rebuilt += s.body;
  }
  nmea::parse_policy p;
  nmea::field_reader r(s, p);
  std::size_t fields = 0;
  std::string joined;
  while (!r.at_end()) {
    const nmea::field_token t = r.take();
    SEAWIRE_FUZZ_CHECK(t.present, line);
    if (fields++ > 0) joined += ',';
    joined += t.text;
    SEAWIRE_FUZZ_CHECK(t.text.find(',') == std::string_view::npos, line);
  }
  SEAWIRE_FUZZ_CHECK(fields == s.field_count && joined == s.body, "fields do not rebuild the body",
                     line, number(fields), number(s.field_count));
  const std::size_t data_end = rebuilt.size();
  SEAWIRE_FUZZ_CHECK(s.line.substr(0, data_end) == rebuilt, "address and body do not rebuild", line,
                     rebuilt);
  SEAWIRE_FUZZ_CHECK(s.computed_checksum == nmea::checksum(s.line.substr(1, data_end - 1)), line);
  if (s.checksum == nmea::checksum_state::valid) {
    SEAWIRE_FUZZ_CHECK(s.received_checksum == s.computed_checksum, line);
  }
  if (s.checksum == nmea::checksum_state::absent) {
    SEAWIRE_FUZZ_CHECK(s.line.size() <= data_end + 1, line);
  } else {
    SEAWIRE_FUZZ_CHECK(s.line.size() == data_end + 3 && s.line[data_end] == '*', line);
  }
}

/// Property 2 for a failed decode of `line` under set S.
template <class Set>
void check_error(const result<typename Set::variant>& r, std::string_view line,
                 std::string_view address) {
  SEAWIRE_FUZZ_CHECK(name(r.ec) != "unknown_error" && r.ec != errc::ok, line);
  SEAWIRE_FUZZ_CHECK(r.column <= line.size(), "error column past the line", line, number(r.column));
  if (sentence_level(r.ec)) {
    SEAWIRE_FUZZ_CHECK(r.field == 0, "sentence error with a field number", line, name(r.ec));
    return;
  }
  SEAWIRE_FUZZ_CHECK(field_level(r.ec), "decode gave an errc no decoder should", line, name(r.ec));
  SEAWIRE_FUZZ_CHECK(r.field >= 1, "field error without a field number", line, name(r.ec));
  const bool named = !Set::field_name(address, r.field).empty();
  if (r.ec == errc::too_many_fields) {
    SEAWIRE_FUZZ_CHECK(!named, "too_many_fields names a declared field", line, number(r.field));
  } else {
    SEAWIRE_FUZZ_CHECK(named, "field error names no declared field", line, name(r.ec),
                       number(r.field));
  }
}

template <class Variant, std::size_t... I>
bool same_variant(const Variant& a, const Variant& b, std::index_sequence<I...>) {
  if (a.index() != b.index()) return false;
  bool same = true;
  (void)((a.index() == I + 1 ? (same = same_message(std::get<I + 1>(a), std::get<I + 1>(b)), true)
                             : false) ||
         ...);
  return same;
}

/// Property 6 for `r`, what decode(line, policy) gave.
template <class Set>
void check_one_pass(std::string_view line, const nmea::parse_policy& policy,
                    const result<typename Set::variant>& r) {
  const result<nmea::sentence_view> s = nmea::parse(line, policy);
  const result<typename Set::variant> general =
      s ? Set::decode(s.value, policy) : nmea::detail::parse_failure<typename Set::variant>(s);
  SEAWIRE_FUZZ_CHECK(r.ec == general.ec && r.field == general.field && r.column == general.column,
                     "decode(line) and the general path disagree", line, name(r.ec),
                     name(general.ec), number(r.field), number(general.field), number(r.column),
                     number(general.column));
  if (r) {
    SEAWIRE_FUZZ_CHECK(same_variant(r.value, general.value, std::make_index_sequence<Set::size>{}),
                       "decode(line) and the general path read different values", line);
  }
  // decode<M>(line), for the message M the address names, against decode<M>(sentence_view).
  nmea::detail::plain_line l;
  const std::size_t i = s ? Set::index_of(s.value.address)
                        : nmea::detail::frame_plain(line, policy, l) ? Set::index_of(l.address)
                                                                     : Set::size;
  (void)registry::visit_type<Set>(i, [&](auto tag) {
    using M = typename decltype(tag)::type;
    const result<M> typed = nmea::decode<M>(line, policy);
    const result<M> typed_general =
        s ? nmea::decode<M>(s.value, policy) : nmea::detail::parse_failure<M>(s);
    SEAWIRE_FUZZ_CHECK(typed.ec == typed_general.ec && typed.field == typed_general.field &&
                           typed.column == typed_general.column,
                       "decode<T>(line) and the general path disagree", line, name(typed.ec),
                       name(typed_general.ec));
    if (typed) {
      SEAWIRE_FUZZ_CHECK(same_message(typed.value, typed_general.value),
                         "decode<T>(line) and the general path read different values", line);
    }
  });
}

/// Properties 1-6 for one line under set S and each policy given (plus liberal and strict).
template <class Set>
void check_line(std::string_view line, std::initializer_list<nmea::parse_policy> roles) {
  const result<nmea::sentence_view> parsed = nmea::parse(line, liberal_policy);
  if (parsed) check_parsed(parsed.value, line);
  const std::string_view address = parsed ? parsed.value.address : std::string_view{};

  const result<typename Set::variant> liberal = Set::decode(line, liberal_policy);
  const auto check_one = [&](const nmea::parse_policy& policy,
                             const result<typename Set::variant>& r) {
    check_one_pass<Set>(line, policy, r);
    if (!r) {
      check_error<Set>(r, line, address);
      return;
    }
    SEAWIRE_FUZZ_CHECK(liberal.ok(), "a policy took what the most liberal one refused", line,
                       name(liberal.ec));
    SEAWIRE_FUZZ_CHECK(same_variant(r.value, liberal.value, std::make_index_sequence<Set::size>{}),
                       "two policies read the same line differently", line);
    std::visit(
        [&](const auto& m) {
          using M = std::remove_cvref_t<decltype(m)>;
          if constexpr (std::is_same_v<M, nmea::unknown_sentence>) {
            // Unknown: an address no message has, or a '!' sentence (messages are '$' ones).
            SEAWIRE_FUZZ_CHECK(m.sentence.start == '!' || !Set::knows(m.sentence.address), line);
          } else {
            SEAWIRE_FUZZ_CHECK(line[0] == '$', "a '!' sentence decoded as a message", line);
            check_decoded<Set>(m, policy, line);
          }
        },
        r.value);
  };
  check_one(liberal_policy, liberal);
  check_one(strict_policy, Set::decode(line, strict_policy));
  for (const nmea::parse_policy& p : roles) check_one(p, Set::decode(line, p));
}

/// A decoder target's whole job: the input as it is, then with its checksum made right.
template <class Set>
void check_sentence_input(const std::uint8_t* data, std::size_t size,
                          std::initializer_list<nmea::parse_policy> roles) {
  const std::string_view raw = as_text(data, size);
  check_line<Set>(raw, roles);
  const std::string fixed = with_good_checksum(raw);
  if (fixed != raw) check_line<Set>(fixed, roles);
}

/// A family's decoder target: check_sentence_input over the union of the roles' sets (see
/// seawire/registry.hpp), under each role's policy.
template <class... Sets>
void check_roles(const std::uint8_t* data, std::size_t size, const registry::role<Sets>&... roles) {
  check_sentence_input<typename nmea::merge_sets<Sets...>::type>(data, size, {roles.policy...});
}

/// An encoder target's property: a message built from the bytes either is refused or writes a
/// sentence its own strict decoder reads back to the same value.
template <class Set, nmea::message_like M>
void check_encoder(byte_source& src) {
  const M m = make_message<M>(src);
  std::array<char, 4096> buf{};
  const result<std::size_t> e = nmea::encode_to(m, buf);
  if (!e) {
    SEAWIRE_FUZZ_CHECK(e.ec != errc::buffer_too_small, "4096 bytes were not enough");
    return;
  }
  check_encoded<Set>(m, std::string_view(buf.data(), e.value), "(encoder input)");
}

}  // namespace seawire::fuzz
