// SPDX-License-Identifier: BSL-1.0
#pragma once
// --format canboat: a message as canboat's `analyzer -json` writes it (default options: std
// units, field names as keys, no nulls), so that what reads analyzer's JSON can read
// seawire-decode's. One walk over the PGN's description (visit_rows) writes every row by the
// rules analyzer follows for its kind:
//   identifier  a number shown as a string of at least 9 digits (an MMSI: "002442000"); a
//               sentinel left out
//   bits        a number shown as its bytes in hex, whatever they are
//   number      the value at its resolution, in canboat's std unit (nmea2000/canboat.hpp), with
//               as many decimals as a step has (or the unit's fixed count); a whole number at
//               resolution 1 as an integer; a sentinel (not available, out of range, reserved)
//               left out
//   lookup      its title (lookup_titles), or the number for a value without one; a sentinel
//               without a title left out (and so a number field declared with titles)
//   flags       the titles of the bits set, a bit without one as its value; no bit set: left out
//   day_count   "YYYY.MM.DD"
//   time        "hh:mm:ss.ffff" (a time of day, and a number in seconds: a duration)
//   keyed       the title of the (key, value) pair (60928's device function for its device
//               class), or the number when the pair has none; a sentinel left out
//   reserved    left out when every bit is one, else its bytes in hex ("0F 00"); spare bits
//               left out when every bit is zero
//   string      the bytes before the first 0x00 less the padding at their end (0xFF, 0x00, '@',
//               whitespace), up to the first 0xFF, JSON-escaped; a counted string's UTF-16 as
//               UTF-8; empty: left out. A counted string's length byte below 2, or an encoding
//               byte that is neither 0, 1 nor 0xFF, analyzer cannot read
//   group       "list":[{...},...], each repetition's rows by these rules; none: left out
//   pairs       a group function's parameter pairs, "list":[{"Parameter":n,"Value":v},...]: v
//               as the named PGN's field n is written, read from as many whole bytes as that
//               field needs (put_pair_value); a field seawire has no description of: the rest
//               of the bytes as bytes, and no more pairs
// and reads the payload as analyzer does where it is cut short: a field the payload holds only a
// part of is read at the width it has (a 16-bit field of which one byte came is that byte's
// value), the rows after the payload's end are left out, and a message whose cut field analyzer
// cannot read at all (a date of one byte) is not written. Known differences: tools/decode/
// README.md. A new kind of field is one more branch of put_row:
// until it has one, the static_assert at its end names the value type that lacks it.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

#include "seawire/nmea2000/canboat.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/registry.hpp"
#include "seawire/walk.hpp"

namespace seawire::tools::canboat {

// ---- what kind of field a value type is ----

template <class V>
struct kind {
  static constexpr bool number = false, lookup = false, flags = false;
};
template <unsigned B, bool S, nmea2000::resolution R, unsigned N>
struct kind<nmea2000::number<B, S, R, N>> {
  static constexpr bool number = true, lookup = false, flags = false;
};
template <class E, unsigned B>
struct kind<nmea2000::lookup<E, B>> {
  static constexpr bool number = false, lookup = true, flags = false;
};
template <class E, unsigned B>
struct kind<nmea2000::flags<E, B>> {
  static constexpr bool number = false, lookup = false, flags = true;
};
template <class>
inline constexpr bool unhandled_kind = false;
// A repeating group's value (nmea2000::group).
template <class V>
inline constexpr bool is_group = false;
template <class I, std::size_t C>
inline constexpr bool is_group<nmea2000::group<I, C>> = true;
template <class V>
inline constexpr bool is_opaque = false;
template <std::size_t N>
inline constexpr bool is_opaque<nmea2000::opaque_bytes<N>> = true;

// ---- numbers as analyzer computes and prints them ----

// canboat's pi and its radians-to-degrees factor, the same doubles.
constexpr double pi = 3.141592653589793;
constexpr double radian_to_degree = 360.0 / 2 / pi;

// A resolution as the double canboat's database holds for it (0.0001, 3.125e-8, 100.0): the
// exact quotient or product of two exact doubles, so the same double as the decimal literal.
template <nmea2000::resolution R>
[[nodiscard]] constexpr double resolution_value() noexcept {
  double scale = 1;
  for (int i = 0; i < (R.exponent < 0 ? -R.exponent : R.exponent); ++i) scale *= 10;
  const auto m = static_cast<double>(R.mantissa);
  return R.exponent < 0 ? m / scale : m * scale;
}

inline void put_format(std::string& out, const char* fmt, auto... args) {
  char buf[128];
  const int n = std::snprintf(buf, sizeof buf, fmt, args...);
  if (n > 0) out.append(buf, std::min(static_cast<std::size_t>(n), sizeof buf - 1));
}

// analyzer's decimals for a resolution: one more for each tenfold step below 1 (in doubles,
// as it counts them).
[[nodiscard]] inline int precision_of(double res) {
  int p = 0;
  for (double r = res; r > 0.0 && r < 1.0; r *= 10.0) ++p;
  return p;
}

// A time or duration of `value` steps of `res` seconds: [-]hh:mm:ss, and the fraction digits of
// the smallest power of ten of steps a second has.
inline void put_time(std::string& out, std::int64_t value, double res) {
  const char* sign = "";
  if (value < 0) {
    value = -value;
    sign = "-";
  }
  std::uint64_t per_second = 1;
  if (res < 1.0) {
    per_second = static_cast<std::uint64_t>(1.0 / res);
  } else {
    value *= static_cast<std::int64_t>(res);
  }
  const auto t = static_cast<std::uint64_t>(value);
  auto seconds = static_cast<std::uint32_t>(t / per_second);
  auto fraction = static_cast<std::uint32_t>(t % per_second);
  std::uint32_t minutes = seconds / 60;
  seconds %= 60;
  const std::uint32_t hours = minutes / 60;
  minutes %= 60;
  std::uint64_t scale = 1;
  int digits = 0;
  while (scale < per_second && digits < 9) {
    scale *= 10;
    ++digits;
  }
  if (digits > 0) fraction = static_cast<std::uint32_t>(fraction * scale / per_second);
  if (digits > 0) {
    put_format(out, "\"%s%02u:%02u:%02u.%0*u\"", sign, hours, minutes, seconds, digits, fraction);
  } else {
    put_format(out, "\"%s%02u:%02u:%02u\"", sign, hours, minutes, seconds);
  }
}

// Number field V of row L, raw value `raw` (not a sentinel), in canboat's std unit.
template <class V, class L>
void put_number(std::string& out, std::int64_t raw) {
  constexpr nmea2000::canboat_unit u = nmea2000::canboat_std_unit(L::unit, V::is_signed);
  double res = resolution_value<V::res>();
  double offset = 0;
  int precision = u.precision;
  switch (u.display) {
    case nmea2000::canboat_display::degrees: res *= radian_to_degree; break;
    case nmea2000::canboat_display::celsius: offset = -273.15; break;
    case nmea2000::canboat_display::bar: res /= 100000.0; break;
    case nmea2000::canboat_display::duration: put_time(out, raw, res); return;
    case nmea2000::canboat_display::coordinate:
    case nmea2000::canboat_display::number: break;
  }
  if (res == 1.0 && offset == 0.0) {
    put_format(out, "%lld", static_cast<long long>(raw));
    return;
  }
  if (precision < 0) precision = precision_of(res);
  put_format(out, "%.*f", precision, static_cast<double>(raw) * res + offset);
}

// A JSON string of `s` (titles and descriptions: printable ASCII, quotes and backslashes escaped
// to be safe).
inline void put_string(std::string& out, std::string_view s) {
  out += '"';
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  out += '"';
}

// ---- reading the payload as analyzer does ----

// A row at `offset` bits, `size` wide, in a payload of `length` bytes: whether analyzer gets to
// it (it stops at the first row starting past the end), how many bits it reads (cut to the bytes
// left), and whether those bits are there (else it cannot read the row).
struct row_read {
  bool reached = false;
  unsigned bits = 0;
  bool readable = false;
};
[[nodiscard]] constexpr row_read read_row(unsigned offset, unsigned size, std::size_t length) {
  if (offset / 8 >= length) return {};
  const std::size_t left = length - offset / 8;
  const auto bytes = static_cast<unsigned>(std::min<std::size_t>((size + 7) / 8, left));
  const unsigned bits = std::min(bytes * 8, size);
  return {true, bits, offset % 8 + bits <= left * 8};
}

// The `bits` bits at `offset` (least significant first, as NMEA 2000 lays them out; at most 64,
// inside the payload), sign-extended when `is_signed`.
[[nodiscard]] inline std::int64_t raw_bits(std::span<const std::uint8_t> payload, unsigned offset,
                                           unsigned bits, bool is_signed) {
  std::uint64_t u = 0;
  for (unsigned i = 0; i < bits; ++i) {
    const unsigned at = offset + i;
    u |= static_cast<std::uint64_t>((static_cast<unsigned>(payload[at / 8]) >> (at % 8)) & 1U) << i;
  }
  if (is_signed && bits < 64 && ((u >> (bits - 1)) & 1) != 0)
    return static_cast<std::int64_t>(u) - (std::int64_t{1} << bits);
  return static_cast<std::int64_t>(u);
}

// The largest raw value of `bits` bits: all ones, or the largest positive one when signed.
[[nodiscard]] constexpr std::int64_t top_of(unsigned bits, bool is_signed) {
  const std::uint64_t ones = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
  return static_cast<std::int64_t>(is_signed ? ones >> 1 : ones);
}

// Whether a number read at `bits` bits is a value: its `sentinels` (as many as its declared
// width has) are counted from the top of what was read.
[[nodiscard]] constexpr bool number_has_value(std::int64_t raw, unsigned bits, unsigned sentinels,
                                              bool is_signed) {
  return raw <= top_of(bits, is_signed) - static_cast<std::int64_t>(sentinels);
}

// Reserved or binary bits in hex, a byte each, as analyzer shows them: the first byte's bits
// before `offset` cleared, and only (bits + 7) / 8 bytes, however many the bits touch.
inline void put_binary(std::string& out, std::span<const std::uint8_t> payload, unsigned offset,
                       std::size_t bits) {
  const std::span<const std::uint8_t> data = payload.subspan(offset / 8);
  const unsigned start = offset % 8;
  if (start + bits > data.size() * 8) bits = data.size() * 8 - start;
  std::size_t remaining = bits;
  out += '"';
  for (std::size_t i = 0; i < (bits + 7) / 8; ++i) {
    auto byte = data[i];
    if (i == 0 && start != 0) {
      byte = static_cast<std::uint8_t>(byte >> start);
      if (remaining + start < 8) byte = static_cast<std::uint8_t>(byte & ((1U << remaining) - 1));
      byte = static_cast<std::uint8_t>(byte << start);
      remaining -= 8 - start;  // may wrap, as analyzer's does: then no later byte is masked
    } else {
      if (remaining < 8) byte = static_cast<std::uint8_t>(byte & ((1U << remaining) - 1));
      remaining -= 8;
    }
    if (i != 0) out += ' ';
    put_format(out, "%02X", static_cast<unsigned>(byte));
  }
  out += '"';
}

// ---- one message ----

// The "fields" object being written: the separator before each key, and whether any was.
// A repetition of a group is an object of its own: opened by "{" and written even when empty.
class fields_text {
 public:
  explicit fields_text(std::string& out, std::string_view opener = ",\"fields\":{")
      : out_(out), opener_(opener) {}
  void key(std::string_view k) {
    out_ += any_ ? std::string_view(",") : opener_;
    any_ = true;
    put_string(out_, k);
    out_ += ':';
  }
  void close() {
    if (any_) out_ += '}';
  }
  [[nodiscard]] bool any() const { return any_; }
  std::string& out() { return out_; }

 private:
  std::string& out_;
  std::string_view opener_;
  bool any_ = false;
};

// Lookup value `raw` of E, read at `bits` bits: its title, or the number when it has none and is
// not among the top values analyzer takes for sentinels.
template <class E>
void put_lookup(fields_text& f, std::string_view key, std::int64_t raw, unsigned bits) {
  static_assert(nmea2000::titled_enum<E>,
                "every lookup enum declares lookup_titles (canboat's texts) beside lookup_names");
  const std::string_view title =
      raw >= 0 ? nmea2000::lookup_title<E>(static_cast<std::uint64_t>(raw)) : std::string_view{};
  if (!title.empty()) {
    f.key(key);
    put_string(f.out(), title);
    return;
  }
  if (bits > 1 && raw >= top_of(bits, false) - (bits > 2 ? 2 : 1)) return;
  f.key(key);
  put_format(f.out(), "%lld", static_cast<long long>(raw));
}

// Flag word `raw` of E: the titles of the bits set (a bit without one as its value); none set:
// left out.
template <class E>
void put_flags(fields_text& f, std::string_view key, std::int64_t raw, unsigned bits) {
  static_assert(nmea2000::titled_enum<E>,
                "every flag enum declares lookup_titles (canboat's texts) beside lookup_names");
  if (raw == 0) return;
  f.key(key);
  std::string& out = f.out();
  out += '[';
  bool first = true;
  for (unsigned bit = 0; bit < bits; ++bit) {
    if (((static_cast<std::uint64_t>(raw) >> bit) & 1) == 0) continue;
    if (!first) out += ',';
    first = false;
    const std::string_view title = nmea2000::lookup_title<E>(bit);
    if (!title.empty()) {
      put_string(out, title);
    } else {
      put_format(out, "%llu", static_cast<unsigned long long>(std::uint64_t{1} << bit));
    }
  }
  out += ']';
}

// A date of `days` since 1970-01-01 as "YYYY.MM.DD".
inline void put_date(std::string& out, std::int64_t days) {
  const std::chrono::year_month_day d{std::chrono::sys_days(std::chrono::days(days))};
  put_format(out, "\"%04d.%02u.%02u\"", static_cast<int>(d.year()),
             static_cast<unsigned>(d.month()), static_cast<unsigned>(d.day()));
}

template <class M>
bool put_rows(fields_text& f, const M& msg, std::span<const std::uint8_t> payload, unsigned base);

// Whether M's rows start where the one before ended (a PGN with a counted string), not at
// their declared offsets.
template <class M>
[[nodiscard]] consteval bool varying_rows() {
  if constexpr (nmea2000::pgn_like<M>) {
    return !nmea2000::description_of<M>::fixed_layout;
  } else {
    return false;
  }
}

// Whether row L (a field_layout of visit_rows) is a string's.
template <class L>
[[nodiscard]] consteval bool string_row() {
  if constexpr (L::reserved) {
    return false;
  } else {
    return nmea2000::text_value<typename L::value_type>;
  }
}

// The repetitions of group `g`, from bit `at` of the payload, as analyzer writes a repeating
// field set: "list":[{...},...], each repetition's rows as a message's; no repetition: left out.
template <class G>
bool put_group(fields_text& f, const G& g, std::span<const std::uint8_t> payload, unsigned at) {
  if (g.empty()) return true;
  f.key("list");
  std::string& out = f.out();
  out += '[';
  constexpr unsigned item_bits = std::remove_cvref_t<decltype(G::item_type::n2k_item)>::bit_length;
  bool ok = true;
  for (std::size_t i = 0; i < g.size() && ok; ++i) {
    if (i != 0) out += ',';
    fields_text item(out, "{");
    ok = put_rows(item, g.items()[i], payload, at + static_cast<unsigned>(i) * item_bits);
    if (item.any()) {
      item.close();
    } else {
      out += "{}";
    }
  }
  out += ']';
  return ok;
}

// UTF-16 code units (little-endian, `bytes` / 2 of them) as UTF-8, as analyzer converts them: a
// surrogate pair as its character, any other surrogate as U+FFFD.
inline std::string utf16_to_utf8(std::span<const std::uint8_t> bytes) {
  std::string out;
  const std::size_t n = bytes.size() / 2;
  const auto unit = [&](std::size_t i) {
    return static_cast<std::uint32_t>(bytes[2 * i] | (bytes[2 * i + 1] << 8));
  };
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t c = unit(i);
    if ((c & 0xF800U) == 0xD800U) {
      if ((c & 0xFC00U) != 0xD800U || i + 1 == n || (unit(i + 1) & 0xFC00U) != 0xDC00U) {
        c = 0xFFFD;
      } else {
        c = 0x10000U + (((c & 0x3FFU) << 10) | (unit(i + 1) & 0x3FFU));
        ++i;
      }
    }
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      out += static_cast<char>(0xE0 | (c >> 12));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (c >> 18));
      out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  return out;
}

// The text analyzer shows of a string's bytes: up to the first 0x00 (a last byte excepted), less
// the padding at the end (0xFF, 0x00, '@', whitespace), written up to the first 0xFF, escaped;
// empty: left out.
inline void put_text(fields_text& f, std::string_view key, std::string_view bytes) {
  std::size_t len = bytes.size();
  if (len > 1) {
    const std::size_t zero = bytes.substr(0, len - 1).find('\0');
    if (zero != std::string_view::npos) len = zero;
  }
  const auto padding = [](unsigned char c) {
    return c == 0xFF || c == 0 || c == '@' || c == ' ' || (c >= '\t' && c <= '\r');
  };
  while (len > 0 && padding(static_cast<unsigned char>(bytes[len - 1]))) --len;
  if (len == 0) return;
  f.key(key);
  std::string& out = f.out();
  out += '"';
  for (const char ch : bytes.substr(0, len)) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == 0xFF) break;
    switch (c) {
      case '\b': out += "\\b"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\f': out += "\\f"; break;
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '/': out += "\\/"; break;
      default:
        if (c < 0x20) {
          put_format(out, "\\u%04x", static_cast<unsigned>(c));
        } else {
          out += ch;
        }
    }
  }
  out += '"';
}

// String row V at bit `at` (a byte boundary the payload reaches), read from the payload as
// analyzer reads it: a fixed string its bytes there (fewer where the payload ends), a counted
// string its length byte's count of bytes (what is left where that runs past the end). `bits`:
// the bits it takes. False when analyzer cannot read it.
template <class V>
bool put_string_row(fields_text& f, std::string_view key, std::span<const std::uint8_t> payload,
                    unsigned at, unsigned& bits) {
  const std::span<const std::uint8_t> data = payload.subspan(at / 8);
  const auto chars = [](std::span<const std::uint8_t> b) {
    return std::string(b.begin(), b.end());
  };
  if constexpr (V::variable) {
    if (data.size() < 2 || data[0] < 2) return false;
    const std::size_t taken = std::min<std::size_t>(data[0], data.size());
    bits = static_cast<unsigned>(8 * taken);
    const std::uint8_t control = data[1];
    const std::span<const std::uint8_t> body = data.subspan(2, taken - 2);
    if (control == 0) {
      put_text(f, key, utf16_to_utf8(body));
    } else if (control == 1 || control == 0xFF) {
      put_text(f, key, chars(body));
    } else {
      return false;  // an encoding analyzer does not know
    }
  } else {
    const std::span<const std::uint8_t> body = data.first(std::min(V::capacity, data.size()));
    bits = static_cast<unsigned>(8 * V::capacity);
    put_text(f, key, chars(body));
  }
  return true;
}

// Row L of a PGN or of a group's repetition (a field_layout of visit_rows) of `msg`, whose
// payload is `payload`, at bit `at` of it: written into `f`, or left out; false when analyzer
// cannot read it, and writes nothing of the message.
template <class R, class P>
bool put_pairs(fields_text& f, const P& msg, std::span<const std::uint8_t> payload, unsigned at);

template <class L, class P>
bool put_row(fields_text& f, const P& msg, std::span<const std::uint8_t> payload, const row_read& r,
             unsigned at, std::string_view key = L::desc.title) {
  if constexpr (L::reserved) {
    if (!r.readable) return true;  // a reserved or spare row cut short is left out
    const std::int64_t raw = raw_bits(payload, at, r.bits, false);
    if constexpr (requires { L::desc.is_spare; }) {
      if (raw == 0) return true;  // spare bits are sent as zeros
    } else {
      if (raw == top_of(r.bits, false)) return true;
    }
    f.key(key);
    put_binary(f.out(), payload, at, r.bits);
    return true;
  } else if constexpr (is_group<typename L::value_type>) {
    return put_group(f, L::info::value(msg), payload, at);
  } else if constexpr (is_opaque<typename L::value_type>) {
    using row = std::remove_cvref_t<decltype(L::desc)>;
    const auto& b = L::info::value(msg);
    if constexpr (requires { row::is_pairs; }) {
      return put_pairs<row>(f, msg, payload, at);
    } else if (!b.empty()) {
      f.key(key);  // bytes no table lays out, as analyzer writes bytes
      put_binary(f.out(), payload, at, 8 * b.size());
    }
    return true;
  } else if constexpr (nmea2000::keyed_row<typename L::info::row_type>) {
    if (!r.readable) return false;
    // The pair's title when the key is known (a value), else the number unless a sentinel.
    const auto v = L::info::value(msg);
    using K = decltype(v.value);
    const K read = r.bits == L::bits ? v.value : K::from_raw(raw_bits(payload, at, r.bits, false));
    const std::string_view title = v.key_known ? read.title(v.key) : std::string_view{};
    if (!title.empty()) {
      f.key(key);
      put_string(f.out(), title);
    } else if (!(r.bits > 1 && read.raw() >= top_of(r.bits, false) - (r.bits > 2 ? 2 : 1))) {
      f.key(key);
      put_format(f.out(), "%lld", static_cast<long long>(read.raw()));
    }
    return true;
  } else {
    using V = typename L::value_type;
    if (!r.readable) return false;
    // A whole field as the library decoded it; a cut one from the bits there are.
    const bool whole = r.bits == L::bits;
    const std::int64_t raw =
        whole ? L::info::value(msg).raw() : raw_bits(payload, at, r.bits, V::is_signed);
    using row = std::remove_cvref_t<decltype(L::desc)>;
    if constexpr (kind<V>::number && requires { row::display; }) {
      if constexpr (row::display == nmea2000::raw_display::bits) {
        f.key(key);  // analyzer shows binary bits whatever they are
        put_binary(f.out(), payload, at, r.bits);
      } else {
        if (!number_has_value(raw, r.bits, V::sentinels, V::is_signed)) return true;
        f.key(key);
        put_format(f.out(), "\"%09lld\"", static_cast<long long>(raw));
      }
    } else if constexpr (kind<V>::number && requires { typename row::titles; }) {
      put_lookup<typename row::titles>(f, key, raw, r.bits);  // a number canboat names values of
    } else if constexpr (kind<V>::number) {
      if (!number_has_value(raw, r.bits, V::sentinels, V::is_signed)) return true;
      f.key(key);
      put_number<V, L>(f.out(), raw);
    } else if constexpr (kind<V>::lookup) {
      put_lookup<nmea2000::value_enum_t<V>>(f, key, raw, r.bits);
    } else if constexpr (kind<V>::flags) {
      if (whole && !L::info::value(msg).has_value()) return true;
      put_flags<nmea2000::value_enum_t<V>>(f, key, raw, r.bits);
    } else if constexpr (std::is_same_v<V, nmea2000::day_count>) {
      if (r.bits != 16) return false;  // analyzer reads a date of two whole bytes only
      if (raw >= 0xFFFD) return true;
      f.key(key);
      put_date(f.out(), raw);
    } else if constexpr (std::is_same_v<V, nmea2000::time_since_midnight>) {
      if (!number_has_value(raw, r.bits, V::number_type::sentinels, false)) return true;
      f.key(key);
      put_time(f.out(), raw, resolution_value<nmea2000::time_since_midnight::number_type::res>());
    } else {
      static_assert(unhandled_kind<V>,
                    "a field kind --format canboat does not write: add its rule to put_row");
    }
    return true;
  }
}

// canboat's description of a PGN it has no definition of, by its range (the last range whose
// first PGN is not past it), whether that range's layout begins with a manufacturer's code
// (the proprietary ranges, and 0xF000-0xFEFF as canboat has it), and how many bits of data
// follow (what is past them analyzer does not show).
struct catch_all {
  std::uint32_t first = 0;
  std::string_view description;
  bool manufacturer = false;
  unsigned data_bits = 0;
};
inline constexpr catch_all catch_alls[] = {
    {0, "0xE800-0xEE00: Standardized single-frame addressed", false, 64},
    {61184, "0xEF00: Manufacturer Proprietary single-frame addressed", true, 48},
    {61440, "0xF000-0xFEFF: Standardized single-frame non-addressed", true, 48},
    {65280, "0xFF00-0xFFFF: Manufacturer Proprietary single-frame non-addressed", true, 48},
    {126208, "0x1ED00 - 0x1EE00: Standardized fast-packet addressed", false, 1784},
    {126720, "0x1EF00: Manufacturer Proprietary fast-packet addressed", true, 1768},
    {126976, "0x1F000-0x1FEFF: Standardized mixed single/fast packet non-addressed", false, 1784},
    {130816, "0x1FF00-0x1FFFF: Manufacturer Specific fast-packet non-addressed", true, 1784},
};
[[nodiscard]] constexpr const catch_all& catch_all_of(std::uint32_t pgn) {
  const catch_all* found = &catch_alls[0];
  for (const catch_all& c : catch_alls)
    if (c.first <= pgn) found = &c;
  return *found;
}

// The industry codes of a proprietary PGN's first two bytes, as canboat names them.
enum class industry_code : std::uint8_t {};
constexpr std::array<std::string_view, 6> lookup_names(industry_code) noexcept {
  return {"global", "highway", "agriculture", "construction", "marine", "industrial"};
}
constexpr std::array<std::string_view, 6> lookup_titles(industry_code) noexcept {
  return {"Global", "Highway", "Agriculture", "Construction", "Marine Industry", "Industrial"};
}

// The header analyzer writes before "fields": time, priority, addresses, PGN, description.
inline void put_header(std::string& out, const nmea2000::message_header& h,
                       std::string_view description, std::string_view timestamp) {
  out += "{\"timestamp\":";
  put_string(out, timestamp);
  put_format(out, ",\"prio\":%u,\"src\":%u,\"dst\":%u,\"pgn\":%u,\"description\":",
             static_cast<unsigned>(h.id.priority), static_cast<unsigned>(h.id.source),
             static_cast<unsigned>(h.id.destination), static_cast<unsigned>(h.id.pgn));
  put_string(out, description);
}

// The message of PGN P, decoded from `payload`, as analyzer writes it (a line without its
// newline); false when analyzer would write nothing of it.
template <nmea2000::pgn_like P>
bool put_message(std::string& out, const nmea2000::message_header& h, const P& msg,
                 std::span<const std::uint8_t> payload, std::string_view timestamp) {
  put_header(out, h, seawire::nmea2000::pgn_table<P>.info.title, timestamp);
  fields_text f(out);
  if (!put_rows(f, msg, payload, 0)) return false;
  f.close();
  out += '}';
  return true;
}

// The rows of `msg` (a PGN, or a group's repetition starting at bit `base` of the payload) up to
// the first the payload does not reach; false when analyzer cannot read one.
template <class M>
bool put_rows(fields_text& f, const M& msg, std::span<const std::uint8_t> payload, unsigned base) {
  bool ok = true;
  bool ended = false;
  unsigned next = base;  // where the row before ended (after a counted string, where it did)
  visit_rows<M>([&](auto layout) {
    using L = decltype(layout);
    if (!ok || ended) return;
    const unsigned at = varying_rows<M>() ? next : base + L::bit_offset;
    const row_read r = read_row(at, L::bits, payload.size());
    if (!r.reached) {
      ended = true;
      return;
    }
    unsigned bits = L::bits;
    if constexpr (string_row<L>()) {
      ok = put_string_row<typename L::value_type>(f, L::desc.title, payload, at, bits);
    } else {
      ok = put_row<L>(f, msg, payload, r, at);
    }
    next = at + bits;
  });
  return ok;
}

// The value of field `index` of PGN `pgn` (a parameter pair's), at bit `at` of `payload`, as
// analyzer reads it: the field's bits at the start of as many whole bytes as the field needs
// (a 2-bit field's value takes a byte, an 11-bit one two), written as that PGN's field is, `at`
// moved past the bytes: fields of a PGN seawire describes (its first layout's), and a
// proprietary PGN's first three (manufacturer, reserved bits, industry). A value the payload
// ends in is read from the bits there are, as analyzer reads a field cut short; none at all
// (cut): no value. A number that is no field of a PGN seawire describes: analyzer gives up on
// the message (none). Any other field: the caller writes the rest of the bytes as analyzer
// does for a field it does not know (unknown). No more pairs are read after any of those.
enum class pair_value : std::uint8_t { read, unknown, cut, none };
inline pair_value put_pair_value(fields_text& item, std::uint32_t pgn, std::int64_t index,
                                 std::span<const std::uint8_t> payload, unsigned& at) {
  bool described = false;
  pair_value written = pair_value::none;
  registry::for_each_type<registry::pgns>([&](auto tag) {
    using Q = typename decltype(tag)::type;
    if (described || seawire::nmea2000::pgn_table<Q>.info.pgn != pgn) return;
    described = true;
    visit_rows<Q>([&](auto layout) {
      using L = decltype(layout);
      if (L::number != index) return;
      written = pair_value::unknown;
      if (at / 8 >= payload.size()) {
        written = pair_value::cut;
        return;
      }
      if constexpr (string_row<L>()) {
        unsigned bits = 0;
        if (at % 8 == 0 && at / 8 < payload.size() &&
            put_string_row<typename L::value_type>(item, "Value", payload, at, bits))
          written = pair_value::read;
        at += bits;
      } else if constexpr (L::bits == 0 || !nmea2000::description_of<Q>::fixed_layout) {
        // a group, bytes, or a field whose offset a string before it moves
      } else {
        constexpr unsigned taken = (L::bits + 7) / 8 * 8;  // a value takes whole bytes
        const unsigned have =
            std::min<unsigned>(L::bits, static_cast<unsigned>(payload.size() * 8) - at);
        // The field at its own offset in a payload of Q (as long as the bits there are), as Q's
        // rows read it.
        std::array<std::uint8_t, nmea2000::max_fast_packet_length> q{};
        q.fill(0xFF);
        for (unsigned i = 0; i < have; ++i) {
          const unsigned from = at + i;
          const unsigned to = L::bit_offset + i;
          const unsigned bit = (static_cast<unsigned>(payload[from / 8]) >> (from % 8)) & 1U;
          q[to / 8] = static_cast<std::uint8_t>(
              (static_cast<unsigned>(q[to / 8]) & ~(1U << (to % 8))) | (bit << (to % 8)));
        }
        const std::span<const std::uint8_t> qs(q.data(), (L::bit_offset + have + 7) / 8);
        const Q decoded = nmea2000::decode<Q>(qs);
        if (put_row<L>(item, decoded, qs, read_row(L::bit_offset, L::bits, qs.size()),
                       L::bit_offset, "Value"))
          written = have == L::bits ? pair_value::read : pair_value::cut;
        at += taken;
      }
    });
  });
  if (described) return written;
  if (!catch_all_of(pgn).manufacturer) return pair_value::unknown;
  constexpr unsigned widths[] = {11, 2, 3};
  if (index < 1 || index > 3) return pair_value::unknown;
  const unsigned bits = widths[index - 1];
  if (at + (bits + 7) / 8 * 8 > payload.size() * 8) return pair_value::cut;
  const std::int64_t raw = raw_bits(payload, at, bits, false);
  if (index == 1) {
    put_lookup<nmea2000::manufacturer_code>(item, "Value", raw, bits);
  } else if (index == 2) {
    item.key("Value");
    put_binary(item.out(), payload, at, bits);
  } else {
    put_lookup<industry_code>(item, "Value", raw, bits);
  }
  at += (bits + 7) / 8 * 8;
  return pair_value::read;
}

// A group function's parameter pairs (row R of `msg`, from bit `at`) as analyzer reads them:
// "list":[{"Parameter":n,"Value":...},...], as many as the count says while the payload lasts,
// each value at the bit where the pair before ended (put_pair_value); the first value it cannot
// read takes the rest of the bytes, as bytes, and ends the list. False when analyzer writes
// nothing of the message (a number that is no field of the PGN).
template <class R, class P>
bool put_pairs(fields_text& f, const P& msg, std::span<const std::uint8_t> payload, unsigned at) {
  const auto& count = msg.*R::count_member;
  const auto& pgn = msg.*R::pgn_member;
  if (!count.has_value() || count.raw() == 0 || at / 8 >= payload.size()) return true;
  f.key("list");
  std::string& out = f.out();
  out += '[';
  for (std::int64_t i = 0; i < count.raw() && at / 8 < payload.size(); ++i) {
    if (i != 0) out += ',';
    fields_text item(out, "{");
    const std::int64_t index = payload[at / 8];
    item.key("Parameter");
    put_format(item.out(), "%lld", static_cast<long long>(index));
    at += 8;
    const pair_value v =
        pgn.has_value()
            ? put_pair_value(item, static_cast<std::uint32_t>(pgn.raw()), index, payload, at)
            : pair_value::unknown;
    if (v == pair_value::unknown && at / 8 < payload.size()) {
      item.key("Value");
      put_binary(item.out(), payload, at, payload.size() * 8 - at);
    }
    if (v == pair_value::none) return false;
    item.close();
    if (v != pair_value::read) break;
  }
  out += ']';
  return true;
}

// A message of a PGN seawire has no description of, as analyzer writes one of a PGN it has
// none of either: its range's catch-all, the payload as "Data" bytes, after the manufacturer's
// and industry's codes in the proprietary ranges (the manufacturer as its number: canboat's
// names for them are not seawire's).
inline void put_raw_message(std::string& out, const nmea2000::message_header& h,
                            std::span<const std::uint8_t> payload, std::string_view timestamp) {
  const catch_all& c = catch_all_of(h.id.pgn);
  put_header(out, h, c.description, timestamp);
  fields_text f(out);
  unsigned offset = 0;
  if (c.manufacturer) {
    if (const row_read r = read_row(0, 11, payload.size()); r.reached && r.readable) {
      const std::int64_t code = raw_bits(payload, 0, r.bits, false);
      if (r.bits <= 1 || code < top_of(r.bits, false) - (r.bits > 2 ? 2 : 1)) {
        f.key("Manufacturer Code");
        put_format(f.out(), "%lld", static_cast<long long>(code));
      }
    }
    if (const row_read r = read_row(11, 2, payload.size()); r.reached && r.readable) {
      if (raw_bits(payload, 11, r.bits, false) != top_of(r.bits, false)) {
        f.key("Reserved");
        put_binary(f.out(), payload, 11, r.bits);
      }
    }
    if (const row_read r = read_row(13, 3, payload.size()); r.reached && r.readable)
      put_lookup<industry_code>(f, "Industry Code", raw_bits(payload, 13, r.bits, false), r.bits);
    offset = 16;
  }
  if (const row_read r = read_row(offset, c.data_bits, payload.size()); r.reached) {
    f.key("Data");
    put_binary(f.out(), payload, offset, r.bits);
  }
  f.close();
  out += '}';
}

// ---- the time ----

// The timestamp analyzer shows for a message read from a log of format `format` at `time_us`:
// a date and time to the millisecond (UTC), or the time of day alone for Actisense N2K ASCII
// (whose lines have no date). Yacht Devices RAW lines have no date either: analyzer gives them
// today's (local), and so does this. candump -L times are rounded to the millisecond (canboat
// reads them through candump2analyzer), others cut. No time at all (candump's screen output):
// now.
[[nodiscard]] inline std::string timestamp(const nmea2000::message_header& h) {
  using namespace std::chrono;
  std::int64_t us = 0;
  bool time_of_day = false;
  if (h.time_us) {
    us = *h.time_us;
    time_of_day = h.format == nmea2000::log_format::yd_raw ||
                  h.format == nmea2000::log_format::actisense_n2k_ascii;
  } else {
    us = duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
  }
  std::int64_t ms = 0;
  if (h.format == nmea2000::log_format::candump_log && h.time_us) {
    ms = static_cast<std::int64_t>(std::lrint(static_cast<double>(us) / 1000.0));
  } else {
    ms = us >= 0 ? us / 1000 : -((-us + 999) / 1000);
  }
  std::string out;
  const std::int64_t day_ms = 86'400'000;
  std::int64_t days = ms >= 0 ? ms / day_ms : -((-ms + day_ms - 1) / day_ms);
  std::int64_t in_day = ms - days * day_ms;
  if (time_of_day) {
    const std::int64_t hours = ms / 3'600'000;
    if (h.format == nmea2000::log_format::actisense_n2k_ascii && hours >= 24) {
      // analyzer keeps a time it cannot read as a time of day as the log had it
      put_format(out, "%02lld:%02lld:%02lld,%03lld", static_cast<long long>(hours),
                 static_cast<long long>(ms / 60'000 % 60), static_cast<long long>(ms / 1000 % 60),
                 static_cast<long long>(ms % 1000));
      return out;
    }
    if (h.format == nmea2000::log_format::actisense_n2k_ascii) {
      put_format(out, "%02lld:%02lld:%02lld.%03lld", static_cast<long long>(hours),
                 static_cast<long long>(ms / 60'000 % 60), static_cast<long long>(ms / 1000 % 60),
                 static_cast<long long>(ms % 1000));
      return out;
    }
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    const year_month_day today{year(local.tm_year + 1900),
                               month(static_cast<unsigned>(local.tm_mon + 1)),
                               day(static_cast<unsigned>(local.tm_mday))};
    days = sys_days(today).time_since_epoch().count();
    in_day = ms % day_ms;
  }
  const year_month_day d{sys_days(std::chrono::days(days))};
  put_format(out, "%04d-%02u-%02uT%02lld:%02lld:%02lld.%03lldZ", static_cast<int>(d.year()),
             static_cast<unsigned>(d.month()), static_cast<unsigned>(d.day()),
             static_cast<long long>(in_day / 3'600'000),
             static_cast<long long>(in_day / 60'000 % 60),
             static_cast<long long>(in_day / 1000 % 60), static_cast<long long>(in_day % 1000));
  return out;
}

}  // namespace seawire::tools::canboat
