// SPDX-License-Identifier: BSL-1.0
#pragma once
// robotx::validator: the judges' view of a team's link. Fed every line with its arrival time
// (never going backwards), it says whether judge_policy accepts the line and lists every rule
// the line breaks, each field checked on its own; some lines the liberal decoder accepts still
// get findings (lower-case hex, extra fields, no CR LF). Rate and heartbeat-gap rules:
// docs/robotx.md.

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>

#include "seawire/detail/ascii.hpp"
#include "seawire/detail/calendar.hpp"
#include "seawire/detail/enum_names.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/robotx/hst.hpp"
#include "seawire/robotx/messages.hpp"

namespace seawire::robotx {

/// Which rule a finding is about. `errc` in the finding gives the decoder's reason where there
/// is one (ok for rules about time or identity).
enum class rule : std::uint8_t {
  framing,             ///< not a sentence: no '$', bad address or character, too long
  checksum,            ///< checksum missing, malformed, or not matching
  checksum_lowercase,  ///< hex digits in lower case (accepted)
  checksum_decimal,    ///< the checksum is the XOR written in decimal, not hex
  line_ending,         ///< the line ends in LF or CR alone, not CR LF
  unknown_address,     ///< a sentence that is none of the five reports
  field,               ///< a field that does not decode (field number, errc)
  unpadded,            ///< a date or time without leading zeros ("29620", "1384")
  team_id,             ///< a team id that is blank, not five characters, or reserved text
  team_mismatch,       ///< a team id other than the expected one
  field_count,         ///< fields missing at the end, or extra fields (accepted)
  rate,                ///< the same report again less than min_interval after the last
  heartbeat_gap,       ///< no accepted RXHRB for longer than the gap limit
  clock_skew,          ///< the report's HST date and time are far from its arrival time
  hemisphere_flip,     ///< N/S or E/W changed between heartbeats far from the equator/meridian
};
inline constexpr std::size_t rule_count = 15;

/// The identifier of a rule as text ("checksum_lowercase").
// (A template of nothing, so that only a caller reads the enumerators' names.)
template <int = 0>
[[nodiscard]] constexpr std::string_view name(rule r) noexcept {
  return seawire::detail::enumerator_name_of<rule_count>(r, "unknown_rule");
}

/// A sentence of explanation for a rule, for people.
[[nodiscard]] constexpr std::string_view message(rule r) noexcept {
  switch (r) {
    case rule::framing: return "not a well-formed sentence";
    case rule::checksum: return "checksum missing, malformed or wrong";
    case rule::checksum_lowercase: return "checksum hex digits in lower case";
    case rule::checksum_decimal: return "checksum written in decimal instead of hex";
    case rule::line_ending: return "line does not end in CR LF";
    case rule::unknown_address: return "not a RobotX report";
    case rule::field: return "field does not decode";
    case rule::unpadded: return "date or time written without leading zeros";
    case rule::team_id: return "team id is blank or not five characters";
    case rule::team_mismatch: return "team id is not the expected team";
    case rule::field_count: return "fields missing or extra";
    case rule::rate: return "same report sent more often than once per second";
    case rule::heartbeat_gap: return "heartbeat missing for longer than the limit";
    case rule::clock_skew: return "report's HST date and time far from its arrival time";
    case rule::hemisphere_flip: return "hemisphere letter changed far from the equator/meridian";
  }
  return "unknown rule";
}

/// One broken rule.
struct finding {
  rule broken = rule::framing;
  nmea::text<15> address;   ///< the sentence's address; empty when it has none
  std::uint16_t field = 0;  ///< field number as the spec counts it; 0 = the sentence as a whole
  errc ec = errc::ok;       ///< the decoder's reason, where there is one
  instant at{};             ///< arrival time of the line (or the advance()/finish() time)
  /// rate: time since the previous one; heartbeat_gap: the gap; clock_skew: report time minus
  /// arrival time. Zero for other rules.
  std::chrono::nanoseconds elapsed{};

  friend constexpr bool operator==(const finding&, const finding&) noexcept = default;
};

/// Findings held by value. One sentence breaks at most ~20 rules; more are counted in `dropped`.
class finding_list {
 public:
  static constexpr std::size_t capacity = 24;

  constexpr void push(const finding& f) noexcept {
    if (size_ < capacity) {
      items_[size_++] = f;
    } else {
      ++dropped_;
    }
  }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0; }
  [[nodiscard]] constexpr std::size_t dropped() const noexcept { return dropped_; }
  [[nodiscard]] constexpr const finding& operator[](std::size_t i) const noexcept {
    return items_[i];
  }
  [[nodiscard]] constexpr const finding* begin() const noexcept { return items_.data(); }
  [[nodiscard]] constexpr const finding* end() const noexcept { return items_.data() + size_; }
  /// The first finding about rule `r`, or nullptr.
  [[nodiscard]] constexpr const finding* find(rule r) const noexcept {
    for (const finding& f : *this)
      if (f.broken == r) return &f;
    return nullptr;
  }
  /// How many findings are about rule `r`.
  [[nodiscard]] constexpr std::size_t count(rule r) const noexcept {
    std::size_t n = 0;
    for (const finding& f : *this) n += f.broken == r ? 1 : 0;
    return n;
  }

 private:
  std::array<finding, capacity> items_{};
  std::size_t size_ = 0;
  std::size_t dropped_ = 0;
};

/// A five-character team id, for validator_config::expected_team (empty if `id` is longer).
[[nodiscard]] constexpr nmea::text<5> team(std::string_view id) noexcept {
  nmea::text<5> t;
  (void)t.assign(id);
  return t;
}

struct validator_config {
  /// The judges' decoder: what `accepted` means.
  nmea::parse_policy policy = judge_policy;
  /// Least time between two sentences with the same address.
  std::chrono::nanoseconds min_interval = std::chrono::seconds(1);
  /// Longest silence between heartbeats before it is a gap. 1.5 s: one lost heartbeat (a 2 s
  /// gap) is reported, half a second of network jitter is not.
  std::chrono::nanoseconds heartbeat_gap_limit = std::chrono::milliseconds(1500);
  /// If set, every team id must be this one.
  std::optional<nmea::text<5>> expected_team{};
  /// If set, a report whose HST date and time differ from its arrival time by more than this
  /// is flagged (a clock on UTC shows as 10 h). Off by default: replayed logs arrive "now".
  std::optional<std::chrono::nanoseconds> clock_tolerance{};
  bool flag_lowercase_checksum = true;
  bool flag_line_ending = true;
  bool flag_hemisphere_flip = true;
};

/// What the validator says about one line.
struct verdict {
  finding_list findings;
  /// The judges' decoder (validator_config::policy) took the line as a RobotX report.
  bool accepted = false;
  /// The report, when accepted; otherwise unknown_sentence, whose views are into the line when
  /// the line is a well-formed sentence of some other address, and empty when it is not.
  reports::variant message;

  [[nodiscard]] constexpr bool clean() const noexcept { return accepted && findings.empty(); }
};

/// Totals since construction.
struct validator_totals {
  std::uint64_t lines = 0;
  std::uint64_t accepted = 0;
  std::array<std::uint64_t, rule_count> findings{};  ///< indexed by rule

  [[nodiscard]] constexpr std::uint64_t of(rule r) const noexcept {
    return findings[static_cast<std::size_t>(r)];
  }
};

namespace detail {

/// Whether 3 to 5 digits read as a valid three-part value (ddmmyy, hhmmss) once each part
/// written with one digit gets its leading zero back; `valid(a, b, c)` judges the parts.
template <class Valid>
[[nodiscard]] constexpr bool unpadded_reading(std::string_view s, Valid valid) noexcept {
  if (s.size() < 3 || s.size() > 5) return false;
  for (char c : s)
    if (!seawire::detail::is_digit(c)) return false;
  for (std::size_t a = 1; a <= 2; ++a) {
    for (std::size_t b = 1; b <= 2; ++b) {
      if (a + b >= s.size() || s.size() - a - b > 2) continue;
      unsigned x = 0, y = 0, z = 0;
      (void)nmea::detail::parse_fixed_digits(s, 0, a, x);
      (void)nmea::detail::parse_fixed_digits(s, a, b, y);
      (void)nmea::detail::parse_fixed_digits(s, a + b, s.size() - a - b, z);
      if (valid(x, y, z)) return true;
    }
  }
  return false;
}

[[nodiscard]] constexpr bool unpadded_date(std::string_view s) noexcept {
  return unpadded_reading(s, [](unsigned d, unsigned m, unsigned y) {
    return seawire::detail::valid_date({2000 + y, m, d});
  });
}
[[nodiscard]] constexpr bool unpadded_time(std::string_view s) noexcept {
  return unpadded_reading(
      s, [](unsigned h, unsigned m, unsigned sec) { return h < 24 && m < 60 && sec < 60; });
}

/// Where the checksum starts: the first '*', as parse() reads it (npos when there is none).
[[nodiscard]] constexpr std::size_t star_of(std::string_view line) noexcept {
  return line.find('*');
}

}  // namespace detail

class validator {
 public:
  constexpr explicit validator(const validator_config& config = {}) noexcept : config_(config) {}

  /// Start the clock for the first heartbeat gap (otherwise the first line starts it).
  constexpr void start(instant t) noexcept {
    if (!since_heartbeat_) since_heartbeat_ = t;
  }

  /// Judge one received line (with or without its line ending) that arrived at `at`. (A
  /// template of nothing, like the role decoders: nmea::lazy.)
  template <int N = 0>
  [[nodiscard]] constexpr verdict check(std::string_view line, instant at) noexcept {
    verdict v;
    ++totals_.lines;
    start(at);
    judge<N>(line, at, v);
    for (const finding& f : v.findings) ++totals_.findings[static_cast<std::size_t>(f.broken)];
    if (v.accepted) ++totals_.accepted;
    return v;
  }

  /// Report a heartbeat gap open at `now` (once per gap). Call from a timer in a live tool.
  [[nodiscard]] constexpr finding_list advance(instant now) noexcept {
    finding_list out;
    if (since_heartbeat_ && !gap_reported_ &&
        detail::elapsed(now, *since_heartbeat_) > config_.heartbeat_gap_limit) {
      gap_reported_ = true;
      finding f;
      f.broken = rule::heartbeat_gap;
      (void)f.address.assign(rxhrb::nmea.address);
      f.at = now;
      f.elapsed = detail::elapsed(now, *since_heartbeat_);
      out.push(f);
      ++totals_.findings[static_cast<std::size_t>(rule::heartbeat_gap)];
    }
    return out;
  }
  /// The end of a session: a gap still open is reported.
  [[nodiscard]] constexpr finding_list finish(instant end) noexcept { return advance(end); }

  [[nodiscard]] constexpr const validator_totals& totals() const noexcept { return totals_; }
  [[nodiscard]] constexpr const validator_config& config() const noexcept { return config_; }

 private:
  static constexpr nmea::parse_policy inspect_policy(const nmea::parse_policy& p) noexcept {
    return {.checksum = nmea::checksum_policy::ignore, .max_length = p.max_length};
  }

  /// Each declared field of M read on its own: a reader is walked to the field's first wire
  /// field and the declaration's own read (codec + options) runs there.
  template <class M>
  constexpr void fields(const nmea::sentence_view& sv, const finding& base, verdict& v) noexcept {
    M msg{};
    std::uint16_t first = 1;
    bool ended = false;
    bool date_ok = false;
    bool time_ok = false;
    M::nmea.fields.apply([&](const auto&... d) {
      (one_field(sv, d, msg, first, ended, date_ok, time_ok, base, v), ...);
    });
    // Optional fields may be blank but not missing: the spec's sentences have every comma.
    if (!ended && sv.field_count != first - 1) {
      finding f = base;
      f.broken = rule::field_count;
      const bool extra = sv.field_count >= first;
      f.field = extra ? first : static_cast<std::uint16_t>(sv.field_count + 1);
      f.ec = extra ? errc::too_many_fields : errc::too_few_fields;
      v.findings.push(f);
    }
    if (config_.clock_tolerance && date_ok && time_ok) {
      const result<instant> t = from_hst(msg.date, msg.time);
      if (t) {
        const auto skew = t.value - base.at;
        if (skew > *config_.clock_tolerance || -skew > *config_.clock_tolerance) {
          finding f = base;
          f.broken = rule::clock_skew;
          f.field = 2;
          f.elapsed = skew;
          v.findings.push(f);
        }
      }
    }
  }

  template <class D, class M>
  constexpr void one_field(const nmea::sentence_view& sv, const D& d, M& msg, std::uint16_t& first,
                           bool& ended, bool& date_ok, bool& time_ok, const finding& base,
                           verdict& v) noexcept {
    const std::uint16_t number = first;
    first = static_cast<std::uint16_t>(first + d.width());
    if (ended) return;
    nmea::field_reader r(sv, config_.policy);
    for (std::uint16_t k = 1; k < number; ++k) (void)r.take();
    const std::string_view raw = r.peek().text;
    const errc e = nmea::detail::read_field(d, r, msg);
    finding f = base;
    f.field = r.index();
    f.ec = e;
    if (e == errc::too_few_fields) {
      ended = true;
      f.broken = rule::field_count;
      v.findings.push(f);
      return;
    }
    if (e != errc::ok) {
      f.broken = rule::field;
      if (d.name == "team_id") {
        f.broken = rule::team_id;
      } else if ((d.name == "date" && detail::unpadded_date(raw)) ||
                 (d.name == "time" && detail::unpadded_time(raw))) {
        f.broken = rule::unpadded;
      }
      v.findings.push(f);
      return;
    }
    if (d.name == "date") date_ok = true;
    if (d.name == "time") time_ok = true;
    if constexpr (requires { msg.team_id; }) {
      if (d.name == "team_id" && config_.expected_team && msg.team_id != *config_.expected_team) {
        f.broken = rule::team_mismatch;
        v.findings.push(f);
      }
    }
  }

  constexpr void heartbeat(const rxhrb& hb, instant at, const finding& base, verdict& v) noexcept {
    if (since_heartbeat_ && !gap_reported_ &&
        detail::elapsed(at, *since_heartbeat_) > config_.heartbeat_gap_limit) {
      finding f = base;
      f.broken = rule::heartbeat_gap;
      f.elapsed = detail::elapsed(at, *since_heartbeat_);
      v.findings.push(f);
    }
    since_heartbeat_ = at;
    gap_reported_ = false;

    if (config_.flag_hemisphere_flip && last_heartbeat_) {
      // A vehicle cannot cross the equator or the 0/180 meridian between two heartbeats when
      // both positions are a degree or more away from it: the letter is wrong (team code that
      // takes N/S and E/W from the heading, not the position, does this).
      const auto flipped = [](const auto& a, const auto& b) {
        return a && b && a->hemi != b->hemi && a->value.compare(nmea::decimal(1)) >= 0 &&
               b->value.compare(nmea::decimal(1)) >= 0;
      };
      const auto far_from_antimeridian = [](const auto& a, const auto& b) {
        return a->value.compare(nmea::decimal(179)) <= 0 &&
               b->value.compare(nmea::decimal(179)) <= 0;
      };
      if (flipped(last_heartbeat_->lat, hb.lat)) {
        finding f = base;
        f.broken = rule::hemisphere_flip;
        f.field = 4;
        f.ec = errc::bad_hemisphere;
        v.findings.push(f);
      }
      if (flipped(last_heartbeat_->lon, hb.lon) &&
          far_from_antimeridian(last_heartbeat_->lon, hb.lon)) {
        finding f = base;
        f.broken = rule::hemisphere_flip;
        f.field = 6;
        f.ec = errc::bad_hemisphere;
        v.findings.push(f);
      }
    }
    last_heartbeat_ = hb;
  }

  // Defined after the helpers it calls: Clang 14 does not instantiate a member template
  // defined later in the class in time for a constant expression.
  template <int N>
  constexpr void judge(std::string_view line, instant at, verdict& v) noexcept {
    finding base;
    base.at = at;
    const auto add = [&](rule r, std::uint16_t fld, errc e) {
      finding f = base;
      f.broken = r;
      f.field = fld;
      f.ec = e;
      v.findings.push(f);
    };

    // Line ending: judged only when the line has one (reported once the address is known).
    const std::size_t n = line.size();
    bool bad_ending = false;
    if (n >= 1 && (line[n - 1] == '\n' || line[n - 1] == '\r')) {
      const bool crlf = n >= 2 && line[n - 2] == '\r' && line[n - 1] == '\n';
      bad_ending = !crlf && config_.flag_line_ending;
      line.remove_suffix(crlf ? 2 : 1);
    }

    // Read the sentence with nothing checked but its framing, so every field can be judged.
    const nmea::parse_policy inspect = inspect_policy(config_.policy);
    result<nmea::sentence_view> s = nmea::parse(line, inspect);
    std::string_view digits;  // checksum text when it could not be read as two hex digits alone
    const errc checksum_error = s.ec;
    if (s.ec == errc::bad_checksum_format || s.ec == errc::trailing_characters) {
      const std::size_t star = detail::star_of(line);
      digits = line.substr(star + 1);
      s = nmea::parse(line.substr(0, star), inspect);
    }
    // RobotX reports are '$' sentences: a '!' one (an encapsulation sentence) has the wrong start.
    if (!s || s.value.start != '$') {
      if (bad_ending) add(rule::line_ending, 0, errc::bad_line_ending);
      add(rule::framing, 0, s ? errc::missing_start : s.ec);
      return;
    }
    const nmea::sentence_view& sv = s.value;
    (void)base.address.assign(sv.address);
    if (bad_ending) add(rule::line_ending, 0, errc::bad_line_ending);
    const auto type = report_type_for(sv.address);
    if (!type) add(rule::unknown_address, 0, errc::unknown_address);

    // Checksum.
    if (!digits.empty()) {
      if (nmea::written_in_decimal(digits, sv.computed_checksum))
        add(rule::checksum_decimal, 0, errc::bad_checksum_format);
      else
        add(rule::checksum, 0, checksum_error);  // malformed, or characters after it
    } else if (sv.checksum == nmea::checksum_state::absent) {
      if (config_.policy.checksum == nmea::checksum_policy::required)
        add(rule::checksum, 0, errc::missing_checksum);
    } else {
      const std::string_view hex = line.substr(detail::star_of(line) + 1);
      if (sv.checksum == nmea::checksum_state::mismatch)
        add(nmea::written_in_decimal(hex, sv.computed_checksum) ? rule::checksum_decimal
                                                                : rule::checksum,
            0, errc::checksum_mismatch);
      if (config_.flag_lowercase_checksum && has_lowercase(hex))
        add(rule::checksum_lowercase, 0, errc::ok);
    }

    const result<reports::variant> decoded = nmea::lazy<reports, N>::decode(line, config_.policy);
    v.accepted = type && decoded.ok() && decoded.value.index() != 0;
    if (decoded.ok()) v.message = decoded.value;
    if (!type) return;

    // Rate, per address, on every transmission.
    const auto ti = static_cast<std::size_t>(*type);
    if (last_seen_[ti] && detail::elapsed(at, *last_seen_[ti]) < config_.min_interval) {
      finding f = base;
      f.broken = rule::rate;
      f.elapsed = detail::elapsed(at, *last_seen_[ti]);
      v.findings.push(f);
    }
    last_seen_[ti] = at;

    // Each field on its own, so every bad one is reported.
    switch (*type) {
      case report_type::heartbeat: fields<nmea::lazy<rxhrb, N>>(sv, base, v); break;
      case report_type::gates: fields<nmea::lazy<rxgat, N>>(sv, base, v); break;
      case report_type::scan_code: fields<nmea::lazy<rxcod, N>>(sv, base, v); break;
      case report_type::dock: fields<nmea::lazy<rxdok, N>>(sv, base, v); break;
      case report_type::deliver: fields<nmea::lazy<rxdel, N>>(sv, base, v); break;
    }
    if (v.accepted && *type == report_type::heartbeat)
      heartbeat(std::get<rxhrb>(v.message), at, base, v);
  }

  [[nodiscard]] static constexpr bool has_lowercase(std::string_view hex) noexcept {
    for (char c : hex)
      if (c >= 'a' && c <= 'f') return true;
    return false;
  }
  validator_config config_;
  validator_totals totals_;
  std::array<std::optional<instant>, report_type_count> last_seen_{};
  std::optional<instant> since_heartbeat_;
  bool gap_reported_ = false;
  std::optional<rxhrb> last_heartbeat_;
};

}  // namespace seawire::robotx
