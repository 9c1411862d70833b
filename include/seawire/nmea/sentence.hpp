// SPDX-License-Identifier: BSL-1.0
#pragma once
// sentence_view: one NMEA-style line split into address, fields and checksum state, checked
// against a parse_policy. Views into the caller's text; nothing is copied or allocated.
//
//   $GPRMC,164959.00,A,4221.71114,N,...,A*70\r\n
//    ^^^^^ address  ^^^^^^^^^^^^^^^^^^^^^^^^ body (fields)   ^^ checksum
//
// A sentence starts with '$' (parametric sentences: every message seawire decodes) or '!'
// (NMEA 0183 encapsulation sentences: !AIVDM, !AIVDO, ...). Both are read the same way, the
// checksum included (XOR of the bytes between the start character and '*'); sentence_view::start
// says which it was. A '$' inside a sentence is refused either way; a '!' inside is text.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

#include "seawire/detail/ascii.hpp"
#include "seawire/detail/byte_order.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/detail/simd.hpp"
#include "seawire/error.hpp"

namespace seawire::nmea {

enum class checksum_policy : std::uint8_t {
  required,           ///< a sentence without a checksum is rejected
  verify_if_present,  ///< a missing checksum is accepted; a wrong one never is
  ignore,             ///< neither checked nor required (the state is still reported)
};

/// How liberal a receiver is (docs/parse-policy.md). Each protocol role starts from its spec's
/// defaults.
struct parse_policy {
  checksum_policy checksum = checksum_policy::verify_if_present;
  bool lowercase_hex = true;      ///< accept "*4e" as well as "*4E"
  bool extra_fields = true;       ///< ignore fields past the last one a message defines (SPI 4.2)
  bool require_crlf = false;      ///< otherwise CR LF, LF, CR or no ending at all are accepted
  bool strict_values = false;     ///< send-side value rules: no '+' signs, no reserved text
  std::size_t max_length = 1024;  ///< bytes from '$' or '!' to the checksum's end (65535 at most)
  /// Spaces around a number (" -5.0", SPI 4.2); strict_values refuses them whatever this says.
  bool spaced_numbers = false;
  /// Optional fields a sentence stops before read as blank, only when a valid checksum vouches
  /// for where it ends (else too_few_fields). Off: only may_be_absent / only_with_field_count
  /// fields may be missing. strict_values implies off.
  bool absent_as_blank = true;
  /// A '*' with nothing after it reads as "no checksum" (Kingfisher commands); off, it is
  /// bad_checksum_format.
  bool empty_checksum = false;

  /// The rules seawire follows when it writes, applied to input: what `--strict` checks.
  [[nodiscard]] static constexpr parse_policy strict() noexcept {
    return {.checksum = checksum_policy::required,
            .lowercase_hex = false,
            .extra_fields = false,
            .require_crlf = true,
            .strict_values = true};
  }
};

enum class checksum_state : std::uint8_t {
  absent,    ///< no '*' (or '*' with nothing after it, where parse_policy::empty_checksum allows)
  valid,     ///< present and matching
  mismatch,  ///< present and wrong (only returned under checksum_policy::ignore)
};

struct field_token;

/// A parsed line. `body` is the text between the comma after the address and the '*'
/// (or the end); `field_count` counts its comma-separated fields, blanks included.
struct sentence_view {
  std::string_view line;     ///< the whole input, line ending excluded
  std::string_view address;  ///< "GPRMC", "PAPGPSCTRL"
  std::string_view body;
  std::uint16_t field_count = 0;
  checksum_state checksum = checksum_state::absent;
  std::uint8_t received_checksum = 0;  ///< meaningful unless checksum == absent
  std::uint8_t computed_checksum = 0;
  /// The start character: '$', or '!' for an encapsulation sentence (!AIVDM). Writing the
  /// sentence back starts it with this. Messages seawire decodes are '$' sentences only: a '!'
  /// sentence matches none of them, whatever its address, and decodes as an unknown_sentence.
  char start = '$';

  /// The i-th field (1-based), or a token that is not present. O(i): for occasional use (an
  /// error message, a field no message describes); a message's decode reads them in one pass.
  [[nodiscard]] constexpr field_token field(std::size_t i) const noexcept;

  /// Column of the first byte of `body` within `line`.
  [[nodiscard]] constexpr std::size_t body_column() const noexcept {
    return static_cast<std::size_t>(address.size()) + 2;
  }
};

namespace detail {

/// What the one pass over a sentence finds between its start character and its '*' (or its end).
struct body_scan {
  std::size_t star = 0;    ///< index of the first '*'; 0 if there is none
  std::size_t bad = 0;     ///< index of the first byte that may not stand there; 0 if none
  std::size_t commas = 0;  ///< ',' before the '*'
  std::uint8_t x = 0;      ///< XOR of every byte before the '*' (the start character excluded)
};

/// The byte loop: the reference, and what constant evaluation, short lines and lines with
/// something wrong in them use.
constexpr void scan_body_bytes(std::string_view line, body_scan& b) noexcept {
  std::uint8_t x = 0;
  for (std::size_t i = 1; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '*') {
      b.star = i;
      break;
    }
    if (!seawire::detail::is_printable(c) || c == '$') {
      b.bad = i;
      return;
    }
    if (c == ',') ++b.commas;
    x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(c));
  }
  b.x = x;
}

#if SEAWIRE_SIMD
/// The scan of line[begin, end) when nothing in it is out of place: no '*', no '$', no byte
/// outside 0x20..0x7E. Sixteen bytes per step with no branch but the loop's: the XOR, the comma
/// count and an accumulated "something special" flag; the last step takes the 16 bytes that end
/// at `end`, with the lanes already seen masked out, so nothing outside the range is read.
/// False when something special is there: the byte loop then says what and where.
/// Precondition: end - begin >= 16.
inline bool scan_clean_simd(const char* p, std::size_t begin, std::size_t end,
                            body_scan& b) noexcept {
  namespace simd = seawire::detail::simd;
  const auto special = [](simd::bytes16 v) {
    return simd::not_printable(v) | simd::equal(v, '$') | simd::equal(v, '*');
  };
  simd::bytes16 x = simd::zero();
  simd::bytes16 odd = simd::zero();
  std::size_t commas = 0;
  std::size_t at = begin;
  while (end - at > 16) {
    // Byte counters hold 255 blocks; a line may have 4096.
    std::size_t blocks = (end - at - 1) / 16;
    if (blocks > 255) blocks = 255;
    simd::bytes16 counts = simd::zero();
    for (const std::size_t stop = at + blocks * 16; at != stop; at += 16) {
      const simd::bytes16 v = simd::load(p + at);
      odd = odd | special(v);
      counts = simd::count(counts, simd::equal(v, ','));
      x = x ^ v;
    }
    commas += simd::sum(counts);
  }
  const simd::bytes16 keep = simd::lanes_from(at - (end - 16));
  const simd::bytes16 last = simd::load(p + end - 16);
  const simd::bytes16 v = last & keep;  // a masked lane is 0: no comma, XOR unchanged
  odd = odd | (keep & special(last));
  if (simd::any(odd)) return false;
  commas += simd::sum(simd::count(simd::zero(), simd::equal(v, ',')));
  b.x = simd::xor_all(x ^ v);
  b.commas = commas;
  return true;
}
#endif

/// Where the address that starts at line[1] ends, eight bytes at once: the index of the first
/// byte that is not an upper-case letter (or, past the first, a digit). 0 when that cannot be
/// told this way (fewer than 9 bytes, or all eight are address characters) and the caller
/// must look byte by byte. Precondition: line[1, 9) are printable ASCII (scan_body found no bad
/// byte before data_end, and the byte at data_end, if any is read, is the '*').
[[nodiscard]] constexpr std::size_t address_end_word(std::string_view line) noexcept {
  if (line.size() < 9) return 0;
  const std::uint64_t w = seawire::detail::load_le64(line.data() + 1);
  // Per byte b in 0x20..0x7E (no carry between bytes): b + (0x80 - k) has its top bit set
  // exactly when b >= k.
  constexpr std::uint64_t ones = 0x0101010101010101U;
  constexpr std::uint64_t top = 0x8080808080808080U;
  const std::uint64_t upper = (w + 0x3F * ones) & ~(w + 0x25 * ones);  // 'A'..'Z'
  const std::uint64_t digit = (w + 0x50 * ones) & ~(w + 0x46 * ones);  // '0'..'9'
  const std::uint64_t other = ~(upper | (digit & ~std::uint64_t{0x80})) & top;
  if (other == 0) return 0;
  return 1 + static_cast<std::size_t>(std::countr_zero(other)) / 8;
}

/// One pass over `line` (no line ending; line[0] is the start character, '$' or '!').
[[nodiscard]] constexpr body_scan scan_body(std::string_view line) noexcept {
  body_scan b;
#if SEAWIRE_SIMD
  const std::size_t n = line.size();
  if (!std::is_constant_evaluated() && n >= 20) {
    // Nearly every sentence ends "*hh": scan up to that '*'; if there is none there, the whole
    // line, which then must hold no '*' at all.
    const std::size_t end = line[n - 3] == '*' ? n - 3 : n;
    if (scan_clean_simd(line.data(), 1, end, b)) {  // b untouched when it fails
      b.star = end == n ? 0 : end;
      return b;
    }
  }
#endif
  scan_body_bytes(line, b);
  return b;
}

/// parse() into `s`, which the caller owns: the error, and in `column` where it is. Everything
/// is written in place, so parse() returns one object and the compiler copies nothing.
[[nodiscard]] constexpr errc split(std::string_view line, const parse_policy& policy,
                                   sentence_view& s, std::size_t& column) noexcept {
  const auto fail = [&column](errc e, std::size_t at) {
    column = at;
    return e;
  };
  using seawire::detail::hex_value;
  using seawire::detail::is_digit;
  using seawire::detail::is_upper;

  // Line ending.
  std::size_t n = line.size();
  const bool crlf = n >= 2 && line[n - 2] == '\r' && line[n - 1] == '\n';
  if (crlf) {
    n -= 2;
  } else if (n >= 1 && (line[n - 1] == '\n' || line[n - 1] == '\r')) {
    if (policy.require_crlf) [[unlikely]]
      return fail(errc::bad_line_ending, n - 1);
    n -= 1;
  } else if (policy.require_crlf && n > 0) {
    return fail(errc::bad_line_ending, n);
  }
  line = std::string_view(line.data(), n);  // n <= line.size(): no substr and its check

  if (n == 0) [[unlikely]]
    return fail(errc::empty_input, 0);
  if (line[0] != '$' && line[0] != '!') [[unlikely]]
    return fail(errc::missing_start, 0);
  // Columns and field counts are 16-bit, so no policy makes a longer line readable: past 65535
  // bytes the count of fields could wrap (65536 commas would read as no fields at all).
  const std::size_t longest = policy.max_length < 0xFFFF ? policy.max_length : 0xFFFF;
  if (n > longest) [[unlikely]]
    return fail(errc::too_long, longest);

  s.line = line;
  s.start = line[0];

  // One pass: XOR, printable check, comma count, checksum delimiter.
  const detail::body_scan scan = detail::scan_body(line);
  if (scan.bad != 0) [[unlikely]]
    return fail(errc::bad_character, scan.bad);
  const std::uint8_t x = scan.x;
  const std::size_t commas = scan.commas;
  const std::size_t star = scan.star;
  const std::size_t data_end = star != 0 ? star : n;

  // Address: upper-case letters and digits, starting with a letter, 1 to 15 of them, ended by
  // the first ',' or by the end of the data.
  std::size_t address_end = detail::address_end_word(line);
  if (address_end == 0) {
    address_end = 1;
    while (address_end < data_end && address_end <= 16 &&
           (is_upper(line[address_end]) || (address_end > 1 && is_digit(line[address_end]))))
      ++address_end;
  }
  if (address_end > 16 || address_end == 1 ||
      (address_end < data_end && line[address_end] != ',')) {
    // Wrong: say where. The address is what stands before the first ',' (or the end).
    std::size_t end = 1;
    while (end < data_end && line[end] != ',') ++end;
    return fail(errc::bad_address, end - 1 == 0 || end - 1 > 15 ? 1 : address_end);
  }
  const std::size_t alen = address_end - 1;
  s.address = std::string_view(line.data() + 1, alen);
  if (address_end < data_end) {
    s.body = std::string_view(line.data() + address_end + 1, data_end - address_end - 1);
    s.field_count = static_cast<std::uint16_t>(commas);
  }
  s.computed_checksum = x;

  // Checksum.
  if (star != 0) {
    const std::size_t digits = n - star - 1;
    if (digits == 0 && !policy.empty_checksum) [[unlikely]]
      return fail(errc::bad_checksum_format, star + 1);
    if (digits != 0) {
      if (digits < 2) [[unlikely]]
        return fail(errc::bad_checksum_format, star + 1);
      const char h = line[star + 1];
      const char l = line[star + 2];
      const int hv = hex_value(h);
      const int lv = hex_value(l);
      // The checksum is the run of hex digits after the '*': one of three or more ("*577",
      // "*116") is no checksum of two.
      if (hv < 0 || lv < 0 || (digits > 2 && hex_value(line[star + 3]) >= 0)) [[unlikely]]
        return fail(errc::bad_checksum_format, star + 1);
      if (!policy.lowercase_hex && ((h >= 'a' && h <= 'f') || (l >= 'a' && l <= 'f')))
        return fail(errc::bad_checksum_format, star + 1);
      // Two hex digits and then something else before the line ending ("*6F ", "*57X"): the
      // checksum is whole, and characters follow it where only the line ending may stand.
      if (digits > 2) [[unlikely]]
        return fail(errc::trailing_characters, star + 3);
      s.received_checksum = static_cast<std::uint8_t>(hv * 16 + lv);
      if (s.received_checksum == x) {
        s.checksum = checksum_state::valid;
      } else {
        if (policy.checksum != checksum_policy::ignore)
          return fail(errc::checksum_mismatch, star + 1);
        s.checksum = checksum_state::mismatch;
      }
    }
  }
  if (s.checksum == checksum_state::absent && policy.checksum == checksum_policy::required)
    return fail(errc::missing_checksum, data_end);

  return errc::ok;
}

}  // namespace detail

/// Split and check one line. The line may carry its CR LF / LF / CR ending or none.
[[nodiscard]] constexpr result<sentence_view> parse(std::string_view line,
                                                    const parse_policy& policy = {}) noexcept {
  result<sentence_view> r;
  std::size_t column = 0;
  r.ec = detail::split(line, policy, r.value, column);
  if (r.ec != errc::ok) {
    r.value = {};
    r.column = static_cast<std::uint16_t>(column > 0xFFFF ? 0xFFFF : column);
  }
  return r;
}

namespace detail {
/// A line parse() refused, as the result of what it was parsed for: the same error and column.
template <class T>
[[nodiscard]] constexpr result<T> parse_failure(const result<sentence_view>& s) noexcept {
  result<T> out;
  out.ec = s.ec;
  out.column = s.column;
  return out;
}
}  // namespace detail

/// What stands right after a field's text, for the readers that can use it: nothing known, or
/// the ',' before the next field (a byte that may be read and is no digit).
enum class field_end : bool { unknown, comma };

/// One field as the reader hands it out. `present` is false past the last field.
struct field_token {
  std::string_view text;
  bool present = false;
  [[nodiscard]] constexpr bool blank() const noexcept { return text.empty(); }
};

namespace detail {

/// Bit i set when a ',' is at w's byte i (w loaded little-endian). Exact for every byte: the
/// per-byte add cannot carry into its neighbour, unlike the usual zero-byte test.
[[nodiscard]] constexpr std::uint64_t comma_bits8(std::uint64_t w) noexcept {
  constexpr std::uint64_t low7 = 0x7F7F7F7F7F7F7F7FU;
  w ^= 0x2C2C2C2C2C2C2C2CU;                                       // a ',' byte becomes 0
  const std::uint64_t zero = ~(((w & low7) + low7) | w) & ~low7;  // 0x80 where a byte was 0
  // Gather the eight flags (bits 7, 15, ..., 63) into bits 56..63, then down to 0..7.
  return ((zero >> 7U) * 0x0102040810204080U) >> 56U;
}

/// Bit i set when p[i] is a ',', for i < min(64, size). Reads p[0..min(64, size)) only.
[[nodiscard]] constexpr std::uint64_t comma_mask(const char* p, std::size_t size) noexcept {
  const std::size_t n = size < 64 ? size : 64;
  std::uint64_t m = 0;
  std::size_t i = 0;
  if (!std::is_constant_evaluated()) {
#if SEAWIRE_SIMD
    namespace simd = seawire::detail::simd;
    for (; n - i >= 16; i += 16)
      m |= std::uint64_t{simd::bits(simd::equal(simd::load(p + i), ','))} << i;
    if (i < n && n >= 16) {
      // The last bytes: the 16 that end at p[n - 1], overlapping some already seen.
      m |= std::uint64_t{simd::bits(simd::equal(simd::load(p + n - 16), ','))} << (n - 16);
      return m;
    }
#else
    for (; n - i >= 8; i += 8) m |= comma_bits8(seawire::detail::load_le64(p + i)) << i;
#endif
  }
  for (; i < n; ++i) {
    if (p[i] == ',') m |= std::uint64_t{1} << i;
  }
  return m;
}

}  // namespace detail

/// Walks the fields of a sentence in order, remembering where it is for error reports. The commas
/// are found 64 bytes at a time as a bit mask, so each field costs a bit scan.
class field_reader {
 public:
  SEAWIRE_ALWAYS_INLINE constexpr field_reader(const sentence_view& s,
                                               const parse_policy& p) noexcept
      : body_(s.body),
        // With no fields there is nothing to take: start past the end.
        pos_(s.field_count > 0 ? 0 : s.body.size() + 1),
        // With no fields there is no body: point past the address, not past the line.
        column_base_(
            static_cast<std::uint16_t>(s.field_count > 0 ? s.body_column() : s.line.size())),
        total_(s.field_count),
        policy_(p) {
    // Absent fields read as blank only where a checksum vouches for where the sentence ends.
    policy_.absent_as_blank = p.absent_as_blank && s.checksum == checksum_state::valid;
    if (s.field_count > 0) {
      mask_ = ends_in(body_, 0);
      if (mask_ == 0) next_window();
      take_end();
    }
  }

  /// The next field; past the end, a blank token with present == false.
  [[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr field_token take() noexcept {
    ++index_;
    const std::size_t at = pos_;
    if (at > body_.size()) [[unlikely]]
      return {};
    const std::size_t end = end_;
    pos_ = end + 1;  // past the end of the body after the last field
    last_at_ = at;
    if (mask_ != 0) [[likely]] {
      take_end();
    } else if (pos_ <= body_.size()) [[unlikely]] {  // else that was the last field
      next_window();
      take_end();
    }
    // Built here, not copied: GCC would copy a finished token through the stack in one 16-byte
    // load that waits on its two 8-byte stores.
    return {std::string_view(body_.data() + at, end - at), true};
  }

  /// Look at the next field without taking it.
  [[nodiscard]] SEAWIRE_ALWAYS_INLINE constexpr field_token peek() const noexcept {
    if (pos_ > body_.size()) [[unlikely]]
      return {};
    return {std::string_view(body_.data() + pos_, end_ - pos_), true};
  }

  [[nodiscard]] constexpr bool at_end() const noexcept { return pos_ > body_.size(); }
  /// What follows the text of the field last taken (ask after take()): field_end::comma when it
  /// was not the last field (a reader may then look one byte past the text, and find a byte
  /// that ends any number); field_end::unknown for the last field and past it.
  [[nodiscard]] constexpr field_end end_of_field() const noexcept {
    return at_end() ? field_end::unknown : field_end::comma;
  }
  /// Spec number (1-based) of the field last taken.
  [[nodiscard]] constexpr std::uint16_t index() const noexcept { return index_; }
  /// Column of the field last taken (of the first field before any is taken).
  [[nodiscard]] constexpr std::uint16_t column() const noexcept {
    return static_cast<std::uint16_t>(column_base_ + last_at_);
  }
  [[nodiscard]] constexpr std::uint16_t field_count() const noexcept { return total_; }
  [[nodiscard]] constexpr const parse_policy& policy() const noexcept { return policy_; }

 private:
  // A field ends at a ',' or at the end of the body. The reader knows where the next field
  // ends (end_) and keeps the ends after it in the 64-byte window [window_, window_ + 64) of
  // the body as a bit mask: its commas, and the end of the body when that falls inside the
  // window. The end of the body is always some window's last bit, so taking a field needs no
  // length test: a bit scan finds the next end while the window has one.
  [[nodiscard]] static constexpr std::uint64_t ends_in(std::string_view body,
                                                       std::size_t start) noexcept {
    const std::size_t left = body.size() - start;
    return detail::comma_mask(body.data() + start, left) |
           (left < 64 ? std::uint64_t{1} << left : 0);
  }
  [[nodiscard]] SEAWIRE_ALWAYS_INLINE static constexpr std::size_t lowest(
      std::uint64_t mask) noexcept {
    return static_cast<std::size_t>(std::countr_zero(mask));
  }
  // The lowest end of the window's mask is where the field at pos_ ends.
  SEAWIRE_ALWAYS_INLINE constexpr void take_end() noexcept {
    end_ = window_ + lowest(mask_);
    mask_ &= mask_ - 1;
  }
  // The window's ends are used up and a field is left: on to the next window that has one (the
  // one holding the end of the body has). Out of line (most sentences fit one window) and
  // static, so that the reader's state can stay in registers.
  SEAWIRE_ALWAYS_INLINE constexpr void next_window() noexcept {
    const auto [start, mask] = window_after(body_, window_);
    window_ = start;
    mask_ = mask;
  }
  [[nodiscard]] SEAWIRE_NOINLINE static constexpr std::pair<std::size_t, std::uint64_t>
  window_after(std::string_view body, std::size_t start) noexcept {
    std::uint64_t mask = 0;
    while (mask == 0) {
      start += 64;
      mask = ends_in(body, start);
    }
    return {start, mask};
  }

  std::string_view body_;
  std::size_t pos_;          // where the next field starts; past body_.size() when none is left
  std::size_t end_ = 0;      // where the field at pos_ ends
  std::size_t window_ = 0;   // mask_ covers body_[window_, window_ + 64)
  std::uint64_t mask_ = 0;   // ends in that window after end_
  std::size_t last_at_ = 0;  // where the field last taken starts in body_
  std::uint16_t index_ = 0;
  std::uint16_t column_base_;  // column of body_[0]
  std::uint16_t total_;
  parse_policy policy_;  // a copy: the compiler need not reload it after each store to a message
};

constexpr field_token sentence_view::field(std::size_t i) const noexcept {
  const parse_policy p;
  field_reader r(*this, p);
  field_token t;
  for (std::size_t k = 0; k < i; ++k) t = r.take();
  return i == 0 ? field_token{} : t;
}

}  // namespace seawire::nmea
