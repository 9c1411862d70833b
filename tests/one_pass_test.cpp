// SPDX-License-Identifier: BSL-1.0
// The one-pass reading of plain sentences (seawire/nmea/one_pass.hpp) against the general path
// (parse, then decode of the sentence_view): on every sample line of every family, and on every
// one-byte change of each (a byte replaced, removed or added, the checksum made right again so
// the one-pass path sees the line), under the liberal, default and strict policies and each
// role's: the same message and value, or the same error with the same field and column.
// And the one-pass path does read the plain lines, and gives the rest to the general path.

#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/one_pass.hpp"
#include "seawire/registry.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/rmc.hpp"

namespace {

using namespace seawire;
using all = registry::sentences;

std::vector<std::string> sample_lines() {
  std::vector<std::string> lines;
  for (const char* name :
       {"standard", "kingfisher", "sandshark", "robotx", "anello", "anello_mixed", "bad"}) {
    std::ifstream in(std::string(SEAWIRE_TEST_DATA_DIR) + "/../../examples/data/" + name + ".nmea");
    REQUIRE(in);
    for (std::string line; std::getline(in, line);)
      if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

/// The line with "*hh" made right for its bytes (added where there is none).
std::string sealed(std::string_view line) {
  std::string out(line.substr(0, line.find('*')));
  if (out.empty()) return out;
  const std::uint8_t x = nmea::checksum(std::string_view(out).substr(1));
  constexpr char hex[] = "0123456789ABCDEF";
  out += '*';
  out += hex[x >> 4U];
  out += hex[x & 15U];
  return out;
}

nmea::parse_policy liberal() {
  nmea::parse_policy p;
  p.checksum = nmea::checksum_policy::ignore;
  p.spaced_numbers = true;
  p.empty_checksum = true;
  return p;
}

std::vector<nmea::parse_policy> policies() {
  std::vector<nmea::parse_policy> out{nmea::parse_policy{}, nmea::parse_policy::strict(),
                                      liberal()};
  nmea::parse_policy upper_hex;
  upper_hex.lowercase_hex = false;
  upper_hex.absent_as_blank = false;
  out.push_back(upper_hex);
  registry::for_each_role([&](const auto& role) { out.push_back(role.policy); });
  return out;
}

template <std::size_t... I>
bool same_variant(const all::variant& a, const all::variant& b, std::index_sequence<I...>) {
  if (a.index() != b.index()) return false;
  bool same = true;
  (void)((a.index() == I + 1 ? (same = std::get<I + 1>(a) == std::get<I + 1>(b), true) : false) ||
         ...);
  return same;
}

/// decode(line), visit(line) and decode<T>(line) against the general path; the count of
/// disagreements (each reported).
std::size_t disagreements(std::string_view line, const nmea::parse_policy& p) {
  const result<all::variant> one = all::decode(line, p);
  const result<nmea::sentence_view> s = nmea::parse(line, p);
  const result<all::variant> general =
      s ? all::decode(s.value, p) : nmea::detail::parse_failure<all::variant>(s);
  // visit(line) hands over what decode(line) gives, or gives its error.
  std::optional<all::variant> visited;
  const result<bool> v = all::visit(line, p, [&](const auto& m) {
    visited.emplace(std::in_place_type<std::remove_cvref_t<decltype(m)>>, m);
  });
  const bool same =
      one.ec == general.ec && one.field == general.field && one.column == general.column &&
      (!one || same_variant(one.value, general.value, std::make_index_sequence<all::size>{}));
  const bool same_visit =
      v.ec == general.ec && v.field == general.field && v.column == general.column &&
      visited.has_value() == (general.ok()) &&
      (!general || same_variant(*visited, general.value, std::make_index_sequence<all::size>{}));
  // decode<M>(line), for the message M the address names, against decode<M>(sentence_view).
  bool same_typed = true;
  nmea::detail::plain_line l;
  const std::size_t i = s                                       ? all::index_of(s.value.address)
                        : nmea::detail::frame_plain(line, p, l) ? all::index_of(l.address)
                                                                : all::size;
  (void)registry::visit_type<all>(i, [&](auto tag) {
    using M = typename decltype(tag)::type;
    const result<M> typed = nmea::decode<M>(line, p);
    const result<M> typed_general =
        s ? nmea::decode<M>(s.value, p) : nmea::detail::parse_failure<M>(s);
    same_typed = typed.ec == typed_general.ec && typed.field == typed_general.field &&
                 typed.column == typed_general.column &&
                 (!typed || typed.value == typed_general.value);
  });
  if (same && same_visit && same_typed) return 0;
  UNSCOPED_INFO(line << ": one pass " << name(one.ec) << " field " << one.field << " column "
                     << one.column << ", visit " << name(v.ec) << " field " << v.field << " column "
                     << v.column << ", general " << name(general.ec) << " field " << general.field
                     << " column " << general.column << (same_typed ? "" : ", decode<T> differs"));
  return 1;
}

/// Whether decode(line) took the one-pass path.
bool read_in_one_pass(std::string_view line, const nmea::parse_policy& p = {}) {
  nmea::detail::plain_line l;
  if (!nmea::detail::frame_plain(line, p, l)) return false;
  bool done = false;
  (void)registry::visit_type<all>(all::index_of(l.address), [&](auto tag) {
    using M = typename decltype(tag)::type;
    if constexpr (nmea::detail::plain_decodable<M>) {
      M m{};
      done = nmea::detail::decode_plain(l, p, m);
    }
  });
  return done;
}

}  // namespace

TEST_CASE("one pass: every sample line, and every one-byte change of it, as the general path") {
  const std::vector<std::string> lines = sample_lines();
  const std::vector<nmea::parse_policy> every = policies();
  const std::vector<nmea::parse_policy> three(every.begin(), every.begin() + 3);
  constexpr std::string_view bytes = "05.-+,* NWx";
  std::size_t checked = 0;
  std::size_t bad = 0;
  const auto check = [&](std::string_view line, bool every_policy = false) {
    for (const nmea::parse_policy& p : every_policy ? every : three) {
      bad += disagreements(line, p);
      ++checked;
    }
  };
  for (const std::string& line : lines) {
    check(line, true);
    check(line + "\r\n", true);
    check(sealed(line), true);
    const std::string base = sealed(line);
    const std::size_t star = base.find('*');
    for (std::size_t i = 1; i < star; ++i) {
      for (const char c : bytes) {
        std::string changed = base;
        changed[i] = c;
        check(sealed(changed));
        std::string added = base;
        added.insert(i, 1, c);
        check(sealed(added));
      }
      std::string removed = base;
      removed.erase(i, 1);
      check(sealed(removed));
    }
  }
  INFO(checked << " decodes compared");
  CHECK(checked > 100000);
  CHECK(bad == 0);
}

TEST_CASE("one pass: every sample line that decodes to a message is read in one pass") {
  std::size_t messages = 0;
  for (const std::string& line : sample_lines()) {
    const result<all::variant> r = all::decode(line);
    if (!r || r.value.index() == 0) continue;
    ++messages;
    INFO(line);
    CHECK(read_in_one_pass(line));
  }
  CHECK(messages > 400);
}

TEST_CASE("one pass: plain lines are read in one pass, to the general path's value") {
  const std::vector<std::string> plain = {
      "$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W*6A",
      "$GPRMC,092751.000,A,5321.6802,N,00630.3371,W,0.06,31.66,280511,,,A*45",
      "$GNRMC,001031.00,A,4404.13993,N,12118.86023,W,0.146,,100117,,,A*7B",
      "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47",
      "$GPGGA,172814.0,3723.46587704,N,12202.26957864,W,2,6,1.2,18.893,M,-25.669,M,2.0,0031*4F",
      "$GPGGA,,,,,,0,00,99.99,,,,,,*48",
      "$CPNVG,081025.987,22.2,N,07106.84603,W,1,0,0,203.1,-3.4,4.5,081025.980*5C",
      "$CPRBS,165004.100,15.111097,15.107097,15.114097,0*72",
      "$CPRBS,165004.100,,15.111097,15.107097,15.114097,0*72",
      "$CPRBS,165004.100,2,15.111097,15.107097,15.114097,0*72",
      "$RXGAT,101218,161229,AUVSI,1,2,Y,RGB*25",
      "$BFMIS,231121.30,dive1.xml,Ready,Waiting for start*1F",
  };
  for (const std::string& text : plain) {
    const std::string line = sealed(text);
    INFO(line);
    CHECK(read_in_one_pass(line));
    CHECK(read_in_one_pass(line + "\r\n"));
    CHECK(all::decode(line).ok());
    CHECK(disagreements(line, {}) == 0);
  }
  // The same message through decode<T>(line).
  const auto r = nmea::decode<standard::rmc>(plain[0]);
  REQUIRE(r.ok());
  CHECK(r.value.talker.view() == "GP");
  CHECK(r.value.lat->whole_degrees == 48);
  CHECK(r.value.lat->minutes.mantissa == 7038);
  CHECK(r.value.speed_knots->mantissa == 224);
  CHECK(r.value.speed_knots->int_width == 3);
  CHECK(r.value.magnetic_variation->direction == nmea::hemisphere::west);
  CHECK(!r.value.mode.has_value());
}

TEST_CASE("one pass: what is not the plain form goes to the general path, which decides") {
  // Each with its checksum made right, so that only what is in its fields keeps it off.
  const std::vector<std::string> fields = {
      "$GPRMC,123519,A,4807.038,N,01131.000,E,+022.4,084.4,230394,003.1,W",       // a '+' sign
      "$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W,A,V,X",  // extra field
      "$GPRMC,123519,A,,N,01131.000,E,022.4,084.4,230394,003.1,W",          // a letter, no number
      "$GPRMC,123519,A,4807.,N,01131.000,E,022.4,084.4,230394,003.1,W",     // no fraction digit
      "$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,A",  // letter left out
      "$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,,,A,",     // blank status
      "$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,384.4,230394,003.1,W",  // course past 360
      "$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,300294,003.1,W",  // 30 February
      "$GPRMC,12:35:19,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W",
      "$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,-003.1,W",  // a signed variation
      "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,F,46.9,M,,",      // unit F
      "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,NaN,M,46.9,M,,",
      "$GPGGA,123519,4807.038,N,01131.000,E,1,08, 0.9,545.4,M,46.9,M,,",  // a space
      "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,,",  // one too many
      "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,12345678901234567890,M,46.9,M,,",
      "$GPGGA,123519,4807.038,N,01131.000,E,1,256,0.9,545.4,M,46.9,M,,",     // uint8 overflow
      "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,1024",  // station > 1023
      "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,$",
      "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,\x01",
  };
  for (const std::string& text : fields) {
    const std::string line = sealed(text);
    INFO(line);
    CHECK(!read_in_one_pass(line));
    for (const nmea::parse_policy& p : policies()) CHECK(disagreements(line, p) == 0);
  }
  const std::string good = "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47";
  const std::vector<std::string> framing = {
      good.substr(0, good.size() - 3),        // no checksum
      good.substr(0, good.size() - 1) + "8",  // a wrong one
      good.substr(0, good.size() - 1),        // half of one
      good + "\n\r",                          // not a line ending
      good + "*47",                           // after the checksum
      "!" + good.substr(1),                   // an encapsulated sentence
      "$GPGGA*56",                            // no fields
  };
  for (const std::string& line : framing) {
    INFO(line);
    CHECK(!read_in_one_pass(line));
    for (const nmea::parse_policy& p : policies()) CHECK(disagreements(line, p) == 0);
  }
  // Lower-case hex digits are the policy's to allow; a line ending the policy's to require.
  const std::string lower =
      sealed("$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,8");
  REQUIRE(lower.substr(lower.size() - 2) == "7F");
  const std::string lower_line = lower.substr(0, lower.size() - 1) + "f";
  nmea::parse_policy upper_only;
  upper_only.lowercase_hex = false;
  CHECK(read_in_one_pass(lower_line));
  CHECK(!read_in_one_pass(lower_line, upper_only));
  CHECK(disagreements(lower_line, upper_only) == 0);
  CHECK(!read_in_one_pass(good, nmea::parse_policy::strict()));
  CHECK(read_in_one_pass(good + "\r\n", nmea::parse_policy::strict()));
}

TEST_CASE("one pass: the plain form is read in constant evaluation too") {
  constexpr std::string_view line =
      "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47";
  constexpr auto r = nmea::decode<standard::gga>(line);
  static_assert(r.ok() && r.value.satellites && *r.value.satellites == 8 &&
                r.value.altitude_m->mantissa == 5454);
  // The same line read at run time (where the SIMD checksum runs) gives the same message.
  const auto at_run_time = nmea::decode<standard::gga>(line);
  REQUIRE(at_run_time.ok());
  CHECK(at_run_time.value == r.value);
}

TEST_CASE("one pass: a field is scanned first where its scanner refuses a blank one") {
  using nmea::detail::scans_no_blank;
  static_assert(scans_no_blank<standard::rmc, nmea::time_of_day>);
  static_assert(scans_no_blank<standard::rmc, nmea::date>);
  static_assert(scans_no_blank<standard::rmc, nmea::decimal>);
  static_assert(scans_no_blank<standard::gga, nmea::latitude>);
  static_assert(scans_no_blank<standard::gga, nmea::longitude>);
  static_assert(scans_no_blank<standard::gga, nmea::integer<std::uint8_t>>);
  static_assert(scans_no_blank<standard::gga, nmea::integer<std::uint16_t>>);
  // A variation's scanner reads a letter without its number; text's blank is the empty text.
  static_assert(!scans_no_blank<standard::rmc, nmea::magnetic_variation>);
  static_assert(!scans_no_blank<standard::rmc, nmea::text<8>>);
  // Blank fields of those types, at the body's end and before others, read in one pass.
  for (const std::string_view text : {
           "$GPRMC,,V,,,,,,,,,,N",
           "$GPRMC,123519,A,4807.038,N,01131.000,E,,,230394,,",
           "$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,,003.1,W",
           "$GPGGA,123519,,,,,0,,,,,,,,",
           "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,,M,,M,,",
       }) {
    const std::string line = sealed(text);
    INFO(line);
    CHECK(read_in_one_pass(line));
    for (const nmea::parse_policy& p : policies()) CHECK(disagreements(line, p) == 0);
  }
}

// A codec of the user's own, whose scan() takes a blank number before its letter and is no
// constexpr function (neither is asked of a codec): it does not say scan_refuses_blank, so its
// fields are tested for a blank first, and lines read in one pass read as the general path
// reads them.
namespace own_codec {
struct bearing {
  std::optional<nmea::decimal> degrees;
  char reference = 'T';
  friend constexpr bool operator==(const bearing&, const bearing&) noexcept = default;
};
}  // namespace own_codec

template <>
struct seawire::nmea::codec<own_codec::bearing> {
  static constexpr unsigned width = 2;
  static constexpr std::size_t max_chars = 24;
  static constexpr bool allows_blank = false;
  static constexpr errc read(field_reader& r, own_codec::bearing& v) noexcept {
    const field_token number = r.take();
    const field_token letter = r.take();
    if (!letter.present) return errc::too_few_fields;
    if (letter.text != "T" && letter.text != "M") return errc::bad_unit;
    v.reference = letter.text[0];
    v.degrees.reset();
    if (!number.text.empty()) {
      decimal d;
      if (const errc e = detail::parse_decimal(number.text, r.policy(), d); e != errc::ok) return e;
      v.degrees = d;
    }
    return errc::ok;
  }
  static constexpr errc check(const own_codec::bearing&) noexcept { return errc::ok; }
  static constexpr void write(writer& w, const own_codec::bearing& v) noexcept {
    if (v.degrees) detail::write_decimal(w, *v.degrees);
    w.next_field();
    w.put(v.reference);
  }
  static const char* scan(const char* p, const char* end, own_codec::bearing& v) noexcept {
    v.degrees.reset();
    if (p != end && *p != ',') {
      decimal d;
      p = detail::scan_decimal(p, d);
      if (p == nullptr) return nullptr;
      v.degrees = d;
    }
    if (p == end || *p != ',' || (p[1] != 'T' && p[1] != 'M')) return nullptr;
    v.reference = p[1];
    return p + 2;
  }
};

namespace own_codec {
struct course {
  bearing required;
  std::optional<bearing> optional;
  std::uint16_t n = 0;
  static constexpr auto nmea = nmea::sentence<"PXYZB">(nmea::field<&course::required>("required"),
                                                       nmea::field<&course::optional>("optional"),
                                                       nmea::field<&course::n>("n"));
};
}  // namespace own_codec

TEST_CASE("one pass: a codec that does not say its scanner refuses a blank is tested first") {
  static_assert(!nmea::detail::scans_no_blank<own_codec::course, own_codec::bearing>);
  for (const std::string_view text : {
           "$PXYZB,12.5,T,3.5,M,5",
           "$PXYZB,,T,3.5,M,5",  // the required value blank: missing, though scan() takes it
           "$PXYZB,12.5,T,,M,5",
           "$PXYZB,12.5,T,,,5",
           "$PXYZB,,,,,5",
       }) {
    const std::string line = sealed(text);
    INFO(line);
    const auto one = nmea::decode<own_codec::course>(line);
    const auto s = nmea::parse(line);
    REQUIRE(s);
    const auto general = nmea::decode<own_codec::course>(s.value);
    CHECK(one.ec == general.ec);
    CHECK(one.field == general.field);
    if (one && general) {
      CHECK(one.value.required == general.value.required);
      CHECK(one.value.optional == general.value.optional);
      CHECK(one.value.n == general.value.n);
    }
  }
  const auto blank_required = nmea::decode<own_codec::course>(sealed("$PXYZB,,T,3.5,M,5"));
  CHECK(blank_required.ec == errc::missing_field);
  CHECK(blank_required.field == 1);
  // The first is read in one pass; the blank required value is left to the general path.
  const auto one_pass = [](const std::string& line) {
    nmea::detail::plain_line l;
    REQUIRE(nmea::detail::frame_plain(line, {}, l));
    own_codec::course m{};
    return nmea::detail::decode_plain(l, {}, m);
  };
  CHECK(one_pass(sealed("$PXYZB,12.5,T,3.5,M,5")));
  CHECK(!one_pass(sealed("$PXYZB,,T,3.5,M,5")));
}
