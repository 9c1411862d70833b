// SPDX-License-Identifier: BSL-1.0
#pragma once
// sentence_view: one NMEA-style line split into address, fields and checksum state, checked
// against a parse_policy. Views into the caller's text; nothing is copied or allocated.
//
//   $GPRMC,164959.00,A,4221.71114,N,...,A*70\r\n
//    ^^^^^ address  ^^^^^^^^^^^^^^^^^^^^^^^^ body (fields)   ^^ checksum

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "seawire/detail/ascii.hpp"
#include "seawire/error.hpp"

namespace seawire::nmea {

enum class checksum_policy : std::uint8_t {
  required,           ///< a sentence without a checksum is rejected
  verify_if_present,  ///< a missing checksum is accepted; a wrong one never is
  ignore,             ///< neither checked nor required (the state is still reported)
};

/// How liberal a receiver is. Each protocol role starts from its spec's defaults.
struct parse_policy {
  checksum_policy checksum = checksum_policy::verify_if_present;
  bool lowercase_hex = true;      ///< accept "*4e" as well as "*4E"
  bool extra_fields = true;       ///< ignore fields past the last one a message defines (SPI 4.2)
  bool require_crlf = false;      ///< otherwise CR LF, LF, CR or no ending at all are accepted
  bool strict_values = false;     ///< send-side rules on values too: no '+' signs, no reserved text
  std::size_t max_length = 1024;  ///< bytes from '$' to the end of the checksum (65535 at most)

  /// The rules seawire follows when it writes, applied to input: what `--strict` checks.
  [[nodiscard]] static constexpr parse_policy strict() noexcept {
    return {checksum_policy::required, false, false, true, true, 1024};
  }
};

enum class checksum_state : std::uint8_t {
  absent,    ///< no '*', or '*' with nothing after it
  valid,     ///< present and matching
  mismatch,  ///< present and wrong (only returned under checksum_policy::ignore)
};

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

  /// Column of the first byte of `body` within `line`.
  [[nodiscard]] constexpr std::size_t body_column() const noexcept {
    return static_cast<std::size_t>(address.size()) + 2;
  }
};

namespace detail {
[[nodiscard]] constexpr result<sentence_view> fail(errc e, std::size_t column) noexcept {
  result<sentence_view> r;
  r.ec = e;
  r.column = static_cast<std::uint16_t>(column > 0xFFFF ? 0xFFFF : column);
  return r;
}
}  // namespace detail

/// Split and check one line. The line may carry its CR LF / LF / CR ending or none.
[[nodiscard]] constexpr result<sentence_view> parse(std::string_view line,
                                                    const parse_policy& policy = {}) noexcept {
  using seawire::detail::hex_value;
  using seawire::detail::is_digit;
  using seawire::detail::is_upper;

  // Line ending.
  std::size_t n = line.size();
  const bool crlf = n >= 2 && line[n - 2] == '\r' && line[n - 1] == '\n';
  if (crlf) {
    n -= 2;
  } else if (n >= 1 && (line[n - 1] == '\n' || line[n - 1] == '\r')) {
    if (policy.require_crlf) return detail::fail(errc::bad_line_ending, n - 1);
    n -= 1;
  } else if (policy.require_crlf && n > 0) {
    return detail::fail(errc::bad_line_ending, n);
  }
  line = line.substr(0, n);

  if (n == 0) return detail::fail(errc::empty_input, 0);
  if (line[0] != '$') return detail::fail(errc::missing_start, 0);
  // Columns and field counts are 16-bit, so no policy makes a longer line readable: past 65535
  // bytes the count of fields could wrap (65536 commas would read as no fields at all).
  const std::size_t longest = policy.max_length < 0xFFFF ? policy.max_length : 0xFFFF;
  if (n > longest) return detail::fail(errc::too_long, longest);

  sentence_view s;
  s.line = line;

  // One pass: XOR, printable check, address end, comma count, checksum delimiter.
  std::uint8_t x = 0;
  std::size_t i = 1;
  std::size_t address_end = 0;
  std::size_t commas = 0;
  std::size_t star = 0;
  for (; i < n; ++i) {
    const char c = line[i];
    if (c == '*') {
      star = i;
      break;
    }
    if (!seawire::detail::is_printable(c) || c == '$') return detail::fail(errc::bad_character, i);
    if (c == ',') {
      if (address_end == 0) address_end = i;
      ++commas;
    }
    x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(c));
  }
  const std::size_t data_end = star != 0 ? star : n;
  if (address_end == 0) address_end = data_end;

  // Address: upper-case letters and digits, starting with a letter.
  const std::size_t alen = address_end - 1;
  if (alen == 0 || alen > 15) return detail::fail(errc::bad_address, 1);
  for (std::size_t k = 1; k < address_end; ++k) {
    const char c = line[k];
    if (!(is_upper(c) || (k > 1 && is_digit(c)))) return detail::fail(errc::bad_address, k);
  }
  s.address = line.substr(1, alen);
  if (address_end < data_end) {
    s.body = line.substr(address_end + 1, data_end - address_end - 1);
    s.field_count = static_cast<std::uint16_t>(commas);
  }
  s.computed_checksum = x;

  // Checksum.
  if (star != 0) {
    const std::size_t digits = n - star - 1;
    if (digits != 0) {
      if (digits != 2) return detail::fail(errc::bad_checksum_format, star + 1);
      const char h = line[star + 1];
      const char l = line[star + 2];
      const int hv = hex_value(h);
      const int lv = hex_value(l);
      if (hv < 0 || lv < 0) return detail::fail(errc::bad_checksum_format, star + 1);
      if (!policy.lowercase_hex && ((h >= 'a' && h <= 'f') || (l >= 'a' && l <= 'f')))
        return detail::fail(errc::bad_checksum_format, star + 1);
      s.received_checksum = static_cast<std::uint8_t>(hv * 16 + lv);
      if (s.received_checksum == x) {
        s.checksum = checksum_state::valid;
      } else {
        if (policy.checksum != checksum_policy::ignore)
          return detail::fail(errc::checksum_mismatch, star + 1);
        s.checksum = checksum_state::mismatch;
      }
    }
  }
  if (s.checksum == checksum_state::absent && policy.checksum == checksum_policy::required)
    return detail::fail(errc::missing_checksum, data_end);

  result<sentence_view> r;
  r.value = s;
  return r;
}

/// One field as the reader hands it out. `present` is false past the last field.
struct field_token {
  std::string_view text;
  bool present = false;
  [[nodiscard]] constexpr bool blank() const noexcept { return text.empty(); }
};

/// Walks the fields of a sentence in order, remembering where it is for error reports.
class field_reader {
 public:
  constexpr field_reader(const sentence_view& s, const parse_policy& p) noexcept
      : rest_(s.body),
        more_(s.field_count > 0),
        // With no fields there is no body: point past the address, not past the line.
        column_(static_cast<std::uint16_t>(s.field_count > 0 ? s.body_column() : s.line.size())),
        total_(s.field_count),
        policy_(&p) {}

  /// The next field; past the end, a blank token with present == false.
  [[nodiscard]] constexpr field_token take() noexcept {
    ++index_;
    if (!more_) return {};
    column_ = static_cast<std::uint16_t>(column_ + last_size_);
    const std::size_t comma = rest_.find(',');
    field_token t{rest_.substr(0, comma), true};
    if (comma == std::string_view::npos) {
      more_ = false;
      last_size_ = static_cast<std::uint16_t>(rest_.size() + 1);
      rest_ = {};
    } else {
      rest_.remove_prefix(comma + 1);
      last_size_ = static_cast<std::uint16_t>(comma + 1);
    }
    return t;
  }

  /// Look at the next field without taking it.
  [[nodiscard]] constexpr field_token peek() const noexcept {
    if (!more_) return {};
    return {rest_.substr(0, rest_.find(',')), true};
  }

  [[nodiscard]] constexpr bool at_end() const noexcept { return !more_; }
  /// Spec number (1-based) of the field last taken.
  [[nodiscard]] constexpr std::uint16_t index() const noexcept { return index_; }
  /// Column of the field last taken.
  [[nodiscard]] constexpr std::uint16_t column() const noexcept { return column_; }
  [[nodiscard]] constexpr std::uint16_t field_count() const noexcept { return total_; }
  [[nodiscard]] constexpr const parse_policy& policy() const noexcept { return *policy_; }

 private:
  std::string_view rest_;
  bool more_;
  std::uint16_t index_ = 0;
  std::uint16_t column_;
  std::uint16_t last_size_ = 0;
  std::uint16_t total_;
  const parse_policy* policy_;
};

/// The i-th field (1-based) of a sentence, or a non-present token. O(i); for occasional use.
[[nodiscard]] constexpr field_token field(const sentence_view& s, std::size_t i) noexcept {
  parse_policy p;
  field_reader r(s, p);
  field_token t;
  for (std::size_t k = 0; k < i; ++k) t = r.take();
  return i == 0 ? field_token{} : t;
}

}  // namespace seawire::nmea
