// SPDX-License-Identifier: BSL-1.0
// NMEA 2000 strings: fixed_text (a fixed number of bytes, padded) and counted_text (a length
// byte, an encoding byte, the text) and the PGNs that carry them (126996, 126998, 129794,
// 129809, 129810). Each mechanism is checked against a decoder written here from the byte rules
// (docs/nmea2000.md), on captures from canboat's sample logs (canboat's analyzer's reading in the
// comments) and on random payloads, then its edges: empty, padding only, not available, a length
// byte past the payload or below 2, bytes outside ASCII, UTF-16; then JSON, CSV and fmt, and
// JSON read back. tools/decode/n2k_test.py compares the vectors 41-47 with canboat's analyzer.

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/registry.hpp"
#include "support.hpp"

#if SEAWIRE_HAS_FMT
#include <fmt/format.h>

#include "seawire/fmt.hpp"
#endif

namespace n2k = seawire::nmea2000;
using n2k::field_state;
using seawire::errc;

namespace {

using bytes = std::vector<std::uint8_t>;

bytes of(std::string_view s) { return {s.begin(), s.end()}; }

bytes cat(std::initializer_list<bytes> parts) {
  bytes out;
  for (const bytes& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

/// `text` then `pad` up to `n` bytes.
bytes padded(std::string_view text, std::size_t n, std::uint8_t pad) {
  bytes b = of(text);
  b.resize(n, pad);
  return b;
}

// ---------------------------------------------------------------------------------------------
// The byte rules, written here from docs/nmea2000.md (not from the library): a text is what comes
// before the first 0x00 or 0xFF, less the padding at its end (0xFF, 0x00, '@', whitespace); the
// result is UTF-8 (a byte as the character of its value, UTF-16 units as characters); empty is
// "not available" (nullopt).

bool is_pad(std::uint32_t c) {
  return c == 0xFF || c == 0 || c == '@' || c == ' ' || c == '\t' || c == '\n' || c == '\v' ||
         c == '\f' || c == '\r';
}

/// `c` in UTF-8 by the encoding's rule: below 0x80 the byte itself; else a lead byte whose top
/// bits count the bytes (110, 1110, 11110) over the highest bits of `c`, then 10xxxxxx for each
/// following 6 bits, most significant first.
void utf8(std::string& out, std::uint32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
    return;
  }
  const unsigned following = c < 0x800 ? 1U : c < 0x10000 ? 2U : 3U;
  const std::uint32_t lead = (0xFFU << (7U - following)) & 0xFFU;
  out += static_cast<char>(lead | (c >> (6U * following)));
  for (unsigned k = following; k-- > 0;)
    out += static_cast<char>(0x80U | ((c >> (6U * k)) & 0x3FU));
}

std::optional<std::string> ref_single(std::span<const std::uint8_t> b) {
  std::size_t end = 0;
  while (end < b.size() && b[end] != 0 && b[end] != 0xFF) ++end;
  while (end > 0 && is_pad(b[end - 1])) --end;
  if (end == 0) return std::nullopt;
  std::string s;
  for (std::size_t i = 0; i < end; ++i) utf8(s, b[i]);
  return s;
}

std::optional<std::string> ref_utf16(std::span<const std::uint8_t> b) {
  std::vector<std::uint32_t> units;
  for (std::size_t i = 0; i + 1 < b.size(); i += 2) {
    const std::uint32_t u = b[i] | (std::uint32_t{b[i + 1]} << 8);
    if (u == 0 || u == 0xFFFF) break;
    units.push_back(u);
  }
  while (!units.empty() && units.back() != 0xFF && is_pad(units.back())) units.pop_back();
  if (units.empty()) return std::nullopt;
  std::string s;
  for (std::size_t i = 0; i < units.size(); ++i) {
    const std::uint32_t u = units[i];
    if (u >= 0xD800 && u < 0xDC00 && i + 1 < units.size() && units[i + 1] >= 0xDC00 &&
        units[i + 1] < 0xE000) {
      utf8(s, 0x10000 + ((u - 0xD800) << 10) + (units[++i] - 0xDC00));
    } else {
      utf8(s, u);  // a lone surrogate as its (CESU) three bytes: compared, never written
    }
  }
  return s;
}

/// The library's text as UTF-8, by the same conversion (a byte or a unit as a character).
template <class T>
std::optional<std::string> library_text(const T& v) {
  if (!v.has_value()) return std::nullopt;
  const std::string_view t = v.text();
  const bytes b(t.begin(), t.end());
  return v.is_utf16() ? ref_utf16(b) : ref_single(b);
}

/// 126998's three strings by the rule: each at the byte where the one before ended.
std::array<std::optional<std::string>, 3> ref_126998(std::span<const std::uint8_t> p) {
  std::array<std::optional<std::string>, 3> out;
  std::size_t at = 0;
  for (auto& s : out) {
    if (at >= p.size() || p[at] < 2 || p.size() - at < 2) break;  // not sent, or no string
    const std::size_t taken = std::min<std::size_t>(p[at], p.size() - at);
    const auto body = p.subspan(at + 2, taken - 2);
    s = p[at + 1] == 0 ? ref_utf16(body) : ref_single(body);
    at += taken;
  }
  return out;
}

template <class P>
std::string json_of(const P& m) {
  seawire::nmea::json_buffer<4096> out;
  n2k::write_json(out, m);
  REQUIRE_FALSE(out.overflow());
  return std::string(out.view());
}

/// A JSON object's members for read_json: key -> value (strings already unescaped, as a JSON
/// parser gives them).
struct members {
  std::vector<std::pair<std::string, seawire::nmea::json_value>> m;
  seawire::nmea::json_value operator()(std::string_view object, std::string_view key) const {
    if (!object.empty()) return {};
    for (const auto& [k, v] : m)
      if (k == key) return v;
    return {};
  }
};

seawire::nmea::json_value str(std::string_view s) { return {seawire::nmea::json_kind::string, s}; }

}  // namespace

TEST_CASE("fixed_text: the text, padding, not available, by the byte rules", "[strings]") {
  using T = n2k::fixed_text<8>;
  static_assert(T::bits == 64 && !T::variable && T::padding == 0xFF);
  static_assert(n2k::field_value<T> && n2k::text_value<T> && !n2k::raw_field_value<T>);
  CHECK(T{}.state() == field_state::not_available);
  CHECK(T{}.bytes() == std::string(8, '\xFF'));

  const auto text_of = [](const bytes& b) {
    const T t = T::from_bytes(b);
    CHECK(library_text(t) == ref_single(b));
    return std::string(t.text());
  };
  CHECK(text_of(padded("ABC", 8, 0xFF)) == "ABC");
  CHECK(text_of(padded("ABC", 8, ' ')) == "ABC");
  CHECK(text_of(padded("ABC", 8, '@')) == "ABC");
  CHECK(text_of(padded("ABC", 8, 0x00)) == "ABC");
  CHECK(text_of(padded("A@B C", 8, '@')) == "A@B C");    // inner '@' and spaces stay
  CHECK(text_of(padded("  lead", 8, ' ')) == "  lead");  // leading spaces stay
  CHECK(text_of(of("AB\xFF"
                   "CDEFG")) == "AB");  // 0xFF ends the text
  CHECK(text_of(of(std::string_view("AB\0CDEFG", 8))) == "AB");
  CHECK(text_of(of("ABCD \t\r\n")) == "ABCD");
  CHECK(text_of(of("ABCDEFGH")) == "ABCDEFGH");  // no padding at all
  // Padding only, or a NUL first: empty, not available (canboat shows null)
  for (const std::uint8_t pad :
       {std::uint8_t{0xFF}, std::uint8_t{0x00}, std::uint8_t{'@'}, std::uint8_t{' '}}) {
    const T t = T::from_bytes(padded("", 8, pad));
    CHECK(t.text().empty());
    CHECK(t.state() == field_state::not_available);
    CHECK(t.bytes() == std::string(8, static_cast<char>(pad)));  // kept as sent
  }
  // A payload cut short: the bytes there, 0xFF after
  const T cut = T::from_bytes(of("XY"));
  CHECK(cut.text() == "XY");
  CHECK(cut.bytes() == std::string("XY") + std::string(6, '\xFF'));
  // Bytes outside ASCII are characters U+0080..U+00FE
  const T latin = T::from_bytes(of("Caf\xE9\x01\x7F\x80\xFE"));
  CHECK(latin.text() == "Caf\xE9\x01\x7F\x80\xFE");
  CHECK(library_text(latin) == std::string("Caf\xC3\xA9\x01\x7F\xC2\x80\xC3\xBE"));
}

TEST_CASE("fixed_text::from_text pads as the field says and refuses what cannot come back",
          "[strings]") {
  const auto t = n2k::fixed_text<6>::from_text("AB");
  REQUIRE(t);
  CHECK(t.value.bytes() == "AB\xFF\xFF\xFF\xFF");
  const auto a = n2k::fixed_text<6, '@'>::from_text("AB");
  REQUIRE(a);
  CHECK(a.value.bytes() == "AB@@@@");
  CHECK(n2k::fixed_text<6>::from_text("ABCDEF").value.bytes() == "ABCDEF");
  CHECK(n2k::fixed_text<6>::from_text("ABCDEFG").ec == errc::text_too_long);
  CHECK(n2k::fixed_text<6>::from_text("").value.state() == field_state::not_available);
  // U+00E9 in UTF-8 is the byte E9
  CHECK(n2k::fixed_text<6>::from_text("Caf\xC3\xA9").value.bytes() == "Caf\xE9\xFF\xFF");
  // What the receiver would cut or cannot carry: refused
  CHECK(n2k::fixed_text<6>::from_text("AB ").ec == errc::bad_text);
  CHECK(n2k::fixed_text<6>::from_text("AB@").ec == errc::bad_text);
  CHECK(n2k::fixed_text<6>::from_text(std::string_view("A\0B", 3)).ec == errc::bad_text);
  CHECK(n2k::fixed_text<6>::from_text("\xC3\xBF").ec == errc::bad_text);      // U+00FF
  CHECK(n2k::fixed_text<6>::from_text("\xE2\x82\xAC").ec == errc::bad_text);  // U+20AC
  CHECK(n2k::fixed_text<6>::from_text("\xE9").ec == errc::bad_text);          // not UTF-8
  CHECK(n2k::fixed_text<6>::from_text("\xC0\x80").ec == errc::bad_text);      // overlong
}

TEST_CASE("counted_text: length, encoding byte, ASCII and UTF-16 texts", "[strings]") {
  using T = n2k::counted_text<40>;
  static_assert(T::variable && T::bits == 8 * 42);
  CHECK(T{}.wire_size() == 2);
  CHECK(T{}.state() == field_state::not_available);
  CHECK(T{}.control() == 1);

  const auto utf16 = [](std::u16string_view s) {
    bytes b;
    for (const char16_t c : s) {
      b.push_back(static_cast<std::uint8_t>(c & 0xFF));
      b.push_back(static_cast<std::uint8_t>(c >> 8));
    }
    return b;
  };
  const auto check_text = [](std::uint8_t control, const bytes& b) {
    const T t = T::from_bytes(control, b).value;
    CHECK(library_text(t) == (control == 0 ? ref_utf16(b) : ref_single(b)));
    return library_text(t);
  };
  CHECK(check_text(1, of("Hello  @@")) == "Hello");
  CHECK(check_text(0, utf16(u"H\u00E9\u20AC")) == "H\xC3\xA9\xE2\x82\xAC");
  CHECK(check_text(0, utf16(u"\U0001F600!")) == "\xF0\x9F\x98\x80!");  // a surrogate pair
  CHECK(check_text(0, utf16(u"ab @")) == "ab");
  CHECK(check_text(0, utf16(u"\u00FF")) == "\xC3\xBF");  // U+00FF is a letter in UTF-16
  bytes odd = utf16(u"Hi");
  odd.push_back('x');  // an odd last byte is no unit
  CHECK(check_text(0, odd) == "Hi");
  CHECK(check_text(0xFF, of("\xFF\xFF")) == std::nullopt);   // unset: the H5000's filler
  CHECK(check_text(7, of("odd control")) == "odd control");  // read as one byte a character

  // from_text: ASCII when every character fits a byte, else UTF-16
  const auto a = T::from_text("abc");
  REQUIRE(a);
  CHECK(a.value.control() == 1);
  CHECK(a.value.bytes() == "abc");
  CHECK(a.value.wire_size() == 5);
  const auto e = T::from_text("\xE2\x82\xAC\xF0\x9F\x98\x80");  // U+20AC U+1F600
  REQUIRE(e);
  CHECK(e.value.control() == 0);
  CHECK(e.value.bytes() == std::string_view("\xAC\x20\x3D\xD8\x00\xDE", 6));
  CHECK(library_text(e.value) == "\xE2\x82\xAC\xF0\x9F\x98\x80");
  CHECK(T::from_text("\xC3\xBF").value.control() == 0);  // U+00FF: a byte would end the text
  CHECK(T::from_text("").value == T{});
  CHECK(T::from_text(std::string(40, 'x')));
  CHECK(T::from_text(std::string(41, 'x')).ec == errc::text_too_long);
  CHECK(T::from_text(std::string(20, '\xE2') + "").ec == errc::bad_text);
  CHECK(T::from_text("x ").ec == errc::bad_text);
  CHECK(T::from_text(std::string_view("\0", 1)).ec == errc::bad_text);
  CHECK(T::from_text("\xEF\xBF\xBF").ec == errc::bad_text);  // U+FFFF ends a UTF-16 text
}

TEST_CASE("126998: counted strings at running offsets, the edges of the length byte",
          "[strings][126998]") {
  using P = n2k::configuration_information;
  static_assert(!n2k::description_of<P>::fixed_layout);
  static_assert(n2k::description_of<n2k::product_information>::fixed_layout);
  CHECK(n2k::description_of<P>::length == 223);
  CHECK(n2k::description_of<P>::min_length == 6);
  CHECK(seawire::registry::pgns::length(126998) == 223);

  const auto check = [](const bytes& p) {
    const P m = n2k::decode<P>(p);
    const auto want = ref_126998(p);
    CHECK(library_text(m.installation_description_1) == want[0]);
    CHECK(library_text(m.installation_description_2) == want[1]);
    CHECK(library_text(m.manufacturer_information) == want[2]);
    return m;
  };
  // 2026-06-08T01:52:35.124, source 178 (ac42-commissioning.raw); canboat:
  // {"installationDescription1":null,"installationDescription2":null,
  //  "manufacturerInformation":"PreditWind DataHub"}
  const bytes capture = cat({{0x02, 0x01, 0x02, 0x01, 0x14, 0x01}, of("PreditWind DataHub")});
  const P m = check(capture);
  CHECK(m.manufacturer_information.text() == "PreditWind DataHub");
  CHECK(m.installation_description_1.state() == field_state::not_available);
  const auto e = n2k::encode(m);
  REQUIRE(e);
  CHECK(std::ranges::equal(e.value.view(), capture));

  // Running offsets: a UTF-16 first string moves the others
  const P moved = check(cat({{0x08, 0x00, 'H', 0x00, 0xE9, 0x00, 0xAC, 0x20},
                             {0x05, 0x01},
                             of("abc"),
                             {0x03, 0x01, 'z'}}));
  CHECK(moved.installation_description_2.text() == "abc");
  CHECK(moved.manufacturer_information.text() == "z");
  // A length byte past the payload: what there is (canboat's reading); nothing after it
  const P past = check(cat({{0x04, 0x01}, of("ab"), {0x30, 0x01}, of("tail")}));
  CHECK(past.installation_description_2.text() == "tail");
  CHECK(past.manufacturer_information.state() == field_state::not_available);
  // A length byte below 2: no string, and nothing after it is read
  for (const std::uint8_t bad : {std::uint8_t{0x00}, std::uint8_t{0x01}}) {
    const P none = check(cat({{0x04, 0x01}, of("ab"), {bad, 0x01}, of("CD"), {0x03, 0x01, 'z'}}));
    CHECK(none.installation_description_1.text() == "ab");
    CHECK(none.installation_description_2 == n2k::counted_text<221>{});
    CHECK(none.manufacturer_information == n2k::counted_text<221>{});
  }
  check({0x05});        // a length byte alone
  check({});            // nothing at all
  check({0x02, 0x01});  // one empty string, the others not sent
  // A length byte of 255 in a long payload: the text stops at the capacity, never past it
  bytes longest(240, 'x');
  longest[0] = 0xFF;
  longest[1] = 0x01;
  const P big = n2k::decode<P>(longest);
  CHECK(big.installation_description_1.bytes().size() == 221);

  // Random payloads: the library and the rule agree, and decode -> encode is byte for byte
  // where the payload is one encode can write (each length byte at least 2, within the payload).
  support::prng g{41};
  for (int i = 0; i < 3000; ++i) {
    bytes p(g.below(60));
    for (auto& b : p) b = static_cast<std::uint8_t>(g.below(4) == 0 ? g.below(12) : g.below(256));
    const P d = check(p);
    const auto again = n2k::encode(d);
    REQUIRE(again);
    CHECK(n2k::decode<P>(again.value.view()) == d);
  }
}

TEST_CASE("126998: encode refuses strings longer than a fast packet carries", "[strings][126998]") {
  using P = n2k::configuration_information;
  P m;
  m.installation_description_1 = n2k::counted_text<221>::from_text(std::string(100, 'a')).value;
  m.installation_description_2 = n2k::counted_text<221>::from_text(std::string(100, 'b')).value;
  const auto fits = n2k::encode(m);
  REQUIRE(fits);
  CHECK(fits.value.size() == 102 + 102 + 2);
  m.manufacturer_information = n2k::counted_text<221>::from_text(std::string(17, 'c')).value;
  CHECK(n2k::encode(m).value.size() == 223);
  m.manufacturer_information = n2k::counted_text<221>::from_text(std::string(18, 'c')).value;
  const auto over = n2k::encode(m);
  CHECK(over.ec == errc::text_too_long);
  CHECK(over.field == 3);
  CHECK(over.column == 204);
}

TEST_CASE("126998: strings not available past a full fast packet are left out",
          "[strings][126998]") {
  using P = n2k::configuration_information;
  // A first string whose length byte runs to the end of a 223-byte payload: it keeps 221 bytes,
  // the other two are not sent. Encoding leaves them out rather than refuse (their 02 01 would
  // not fit), and the payload decodes to the same message.
  bytes full(223, 'x');
  full[0] = 0xFF;
  full[1] = 0x01;
  const P m = n2k::decode<P>(full);
  CHECK(m.installation_description_1.bytes().size() == 221);
  CHECK(m.installation_description_2 == n2k::counted_text<221>{});
  const auto e = n2k::encode(m);
  REQUIRE(e);
  CHECK(e.value.size() == 223);
  CHECK(e.value[0] == 223);  // the length byte as it should be
  CHECK(n2k::decode<P>(e.value.view()) == m);
  // A string with a value past the packet is refused, naming it
  P over = m;
  over.manufacturer_information = n2k::counted_text<221>::from_text("x").value;
  const auto refused = n2k::encode(over);
  CHECK(refused.ec == errc::text_too_long);
  CHECK(refused.field == 3);
}

TEST_CASE("126996 Product Information: captures decoded by the byte rules, encoded back",
          "[strings][126996]") {
  using P = n2k::product_information;
  CHECK(n2k::description_of<P>::length == 134);
  constexpr auto info = n2k::pgn_table<P>.info;
  CHECK(info.pgn == 126996);
  CHECK(info.transport == n2k::framing::fast_packet);
  // 2026-06-08T01:52:35.124, source 178 (ac42-commissioning.raw), padded with 0xFF; canboat:
  // {"nmea2000Version":0.003,"productCode":9058,"modelId":"RDS Sender NMEAD",
  //  "softwareVersionCode":"v4.50","modelVersion":"HUB-V2","modelSerialCode":"000A520DF69B",
  //  "certificationLevel":2,"loadEquivalency":0}
  const bytes wire = cat({{0x03, 0x00, 0x62, 0x23},
                          padded("RDS Sender NMEAD", 32, 0xFF),
                          padded("v4.50", 32, 0xFF),
                          padded("HUB-V2", 32, 0xFF),
                          padded("000A520DF69B", 32, 0xFF),
                          {0x02, 0x00}});
  const P m = n2k::decode<P>(wire);
  CHECK(m.nmea2000_version.raw() == 3);
  CHECK(m.product_code.raw() == 0x2362);
  CHECK(m.model_id.text() == "RDS Sender NMEAD");
  CHECK(m.software_version_code.text() == "v4.50");
  CHECK(m.model_version.text() == "HUB-V2");
  CHECK(m.model_serial_code.text() == "000A520DF69B");
  CHECK(m.certification_level.raw() == 2);
  CHECK(m.load_equivalency.raw() == 0);
  const auto e = n2k::encode(m);
  REQUIRE(e);
  CHECK(std::ranges::equal(e.value.view(), wire));
  // Spaces and NULs as padding are kept as sent, byte for byte (SCX-20: NUL; AC42: spaces)
  bytes nul = wire;
  std::fill(nul.begin() + 4 + 6, nul.begin() + 36, 0x00);
  const P n = n2k::decode<P>(nul);
  CHECK(n.model_id.text() == "RDS Se");
  CHECK(std::ranges::equal(n2k::encode(n).value.view(), nul));
  // Random payloads: every string by the rule
  support::prng g{42};
  for (int i = 0; i < 500; ++i) {
    bytes p(134);
    for (auto& b : p) b = static_cast<std::uint8_t>(g.below(3) == 0 ? 0xFF : g.below(256));
    const P r = n2k::decode<P>(p);
    CHECK(library_text(r.model_id) == ref_single(std::span(p).subspan(4, 32)));
    CHECK(library_text(r.model_serial_code) == ref_single(std::span(p).subspan(100, 32)));
    CHECK(std::ranges::equal(n2k::encode(r).value.view(), p));  // every byte is kept
  }
}

TEST_CASE("129794, 129809, 129810 AIS static data: captures decoded by hand", "[strings][ais]") {
  CHECK(n2k::description_of<n2k::ais_class_a_static_data>::length == 76);
  CHECK(n2k::description_of<n2k::ais_class_b_static_data_a>::length == 27);
  CHECK(n2k::description_of<n2k::ais_class_b_static_data_b>::length == 35);
  // 129794, 2016-04-09T16:41:27.039Z (susteranna-actisense-serial.raw); canboat:
  // {"messageId":"Static and voyage related data","repeatIndicator":"Initial",
  //  "userId":"244740922","imoNumber":null,"callsign":"PG9182","name":"GAASTERLAND",
  //  "typeOfShip":"Engaged in dredging or underwater operations","length":86.0,"beam":11.0,
  //  "positionReferenceFromStarboard":5.0,"positionReferenceFromBow":76.0,"etaDate":"2017.02.10",
  //  "etaTime":"12:15:00.0000","draft":null,"destination":null,
  //  "aisVersionIndicator":"ITU-R M.1371-3","gnssType":null,"dte":"Available",
  //  "aisTransceiverInformation":"Channel A VDL reception"}
  const bytes a = {0x05, 0x3a, 0x73, 0x96, 0x0e, 0xff, 0xff, 0xff, 0xff, 0x50, 0x47, 0x39, 0x31,
                   0x38, 0x32, 0x40, 0x47, 0x41, 0x41, 0x53, 0x54, 0x45, 0x52, 0x4c, 0x41, 0x4e,
                   0x44, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x21, 0x5c, 0x03,
                   0x6e, 0x00, 0x32, 0x00, 0xf8, 0x02, 0x37, 0x43, 0x40, 0x20, 0x49, 0x1a, 0xff,
                   0xff, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40,
                   0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x40, 0x3d, 0xe0};
  const auto m = n2k::decode<n2k::ais_class_a_static_data>(a);
  CHECK(m.message_id == n2k::ais_message_id::static_and_voyage_related_data);  // 0x05 & 0x3F
  CHECK(m.repeat_indicator == n2k::ais_repeat_indicator::initial);             // 0x05 >> 6
  CHECK(m.user_id.raw() == 0x0e96733a);                                        // 244740922
  CHECK(m.imo_number.state() == field_state::not_available);
  CHECK(m.callsign.text() == "PG9182");  // 50 47 39 31 38 32 40
  CHECK(m.name.text() == "GAASTERLAND");
  CHECK(m.type_of_ship.raw() == 0x21);
  CHECK(m.length_m.raw() == 0x035c);  // 86.0 m
  CHECK(m.beam_m.raw() == 0x6e);
  CHECK(m.position_reference_from_starboard_m.raw() == 0x32);
  CHECK(m.position_reference_from_bow_m.raw() == 0x2f8);
  CHECK(m.eta_date.raw() == 0x4337);      // 2017-02-10
  CHECK(m.eta_time.raw() == 0x1a492040);  // 12:15:00
  CHECK(m.draft_m.state() == field_state::not_available);
  CHECK(m.destination.state() == field_state::not_available);  // '@' only
  CHECK(m.ais_version_indicator.raw() == 1);                   // 0x3d: bits 0-1
  CHECK(m.gnss_type.state() == field_state::not_available);    // bits 2-5: 15
  CHECK(m.dte == n2k::dte_availability::available);            // bit 6
  CHECK(m.ais_transceiver_information.raw() == 0);             // 0xe0: bits 0-4
  CHECK(m.sequence_id.state() == field_state::not_available);  // not sent (76th byte)
  // Both 2-bit AIS lookups name every raw value: 3 is a value, none is "not available"
  CHECK(n2k::lookup<n2k::ais_repeat_indicator, 2>::from_raw(3).state() == field_state::value);
  CHECK(n2k::lookup<n2k::ais_version, 2>::from_raw(3).name() == "itu_r_m1371_future");
  CHECK(n2k::lookup<n2k::dte_availability, 1>::from_raw(1).name() == "unavailable");
  const auto e = n2k::encode(m);
  REQUIRE(e);
  // The same bytes but the reserved bit the sender cleared (bit 7 of byte 73: sent as one) and
  // the sequence ID it left out (not available: 0xFF)
  CHECK(std::ranges::equal(std::span(e.value.view()).first(73), std::span(a).first(73)));
  CHECK(e.value[73] == 0xbd);
  CHECK(e.value[74] == 0xe0);
  CHECK(e.value[75] == 0xff);

  // 129810, 2016-04-09T16:41:11.228Z; canboat: {"typeOfShip":"Pleasure","vendorId":"THAFXEF",
  // "callsign":"PE5738","length":11.0,"beam":4.0,...,"mothershipUserId":null,
  // "gnssType":"Default: undefined","aisTransceiverInformation":"Channel B VDL reception"}
  const bytes b = {0x18, 0x19, 0xae, 0x8c, 0x0e, 0x25, 0x54, 0x48, 0x41, 0x46, 0x58, 0x45,
                   0x46, 0x50, 0x45, 0x35, 0x37, 0x33, 0x38, 0x40, 0x6e, 0x00, 0x28, 0x00,
                   0x1e, 0x00, 0x32, 0x00, 0xff, 0xff, 0xff, 0xff, 0x03, 0xe1};
  const auto pb = n2k::decode<n2k::ais_class_b_static_data_b>(b);
  CHECK(pb.type_of_ship == n2k::ship_type::pleasure);  // 0x25 = 37
  CHECK(pb.vendor_id.text() == "THAFXEF");
  CHECK(pb.callsign.text() == "PE5738");
  CHECK(pb.length_m.raw() == 110);
  CHECK(pb.mothership_user_id.state() == field_state::not_available);
  CHECK(pb.gnss_type.raw() == 0);  // 0x03: reserved 11, spare 00, GNSS 0000
  CHECK(pb.ais_transceiver_information == n2k::ais_transceiver::channel_b_vdl_reception);
  const auto eb = n2k::encode(pb);
  REQUIRE(eb);
  // Spare bits go out as zeros, reserved ones as ones: the capture's byte 32 again
  CHECK(std::ranges::equal(std::span(eb.value.view()).first(34), b));

  // 129809 cut inside its name: the bytes there (canboat shows "VLIEG")
  const bytes cut = {0x18, 0x47, 0x38, 0x8c, 0x0e, 'V', 'L', 'I', 'E', 'G'};
  const auto pa = n2k::decode<n2k::ais_class_b_static_data_a>(cut);
  CHECK(pa.name.text() == "VLIEG");
  CHECK(pa.ais_transceiver_information.state() == field_state::not_available);
  // from_text pads an AIS string with '@'
  const auto name = n2k::ais_text<20>::from_text("VLIEGER");
  REQUIRE(name);
  CHECK(name.value.bytes() == "VLIEGER@@@@@@@@@@@@@");
}

TEST_CASE("strings in JSON, CSV and fmt: escaped, null when empty, read back exactly",
          "[strings][json]") {
  n2k::product_information m;
  m.model_id = n2k::fixed_text<32>::from_bytes(of("Q\"\\,\x01\xE9\x7F"));
  m.software_version_code = n2k::fixed_text<32>::from_bytes(padded("", 32, '@'));
  m.model_version = n2k::fixed_text<32>::from_text("v1").value;
  const std::string json = json_of(m);
  CHECK(json.find(R"("model_id":"Q\"\\,\u0001\u00E9\u007F")") != std::string::npos);
  CHECK(json.find(R"("software_version_code":null)") != std::string::npos);
  CHECK(json.find(R"("model_version":"v1")") != std::string::npos);

  // CSV: the text, what is not printable ASCII escaped, quoted by CSV's rule (the comma, the
  // quote)
  seawire::nmea::json_buffer<2048> csv;
  n2k::write_csv(csv, n2k::message_header{}, m);
  CHECK(std::string(csv.view()).find(R"(,"Q""\,\u0001\u00E9\u007F",,v1,)") != std::string::npos);

#if SEAWIRE_HAS_FMT
  CHECK(fmt::format("{}", m.model_version) == "\"v1\"");
  CHECK(fmt::format("{}", m.software_version_code) == "null");
  CHECK(fmt::format("{}", m.model_id) == R"("Q\"\\,\u0001\u00E9\u007F")");
#endif

  // Read back: the JSON parser's unescaped text (UTF-8) gives the same bytes
  members in;
  in.m = {{"model_id", str("Q\"\\,\x01\xC3\xA9\x7F")},
          {"software_version_code", {seawire::nmea::json_kind::null, "null"}},
          {"model_version", str("v1")}};
  const auto back = n2k::read_json<n2k::product_information>(in);
  REQUIRE(back);
  CHECK(back.value.model_id.text() == m.model_id.text());
  CHECK(back.value.software_version_code.state() == field_state::not_available);
  CHECK(back.value.model_version == m.model_version);
  // What a string field cannot carry: the row and why
  members bad;
  bad.m = {{"model_version", str("ends in a space ")}};
  const auto refused = n2k::read_json<n2k::product_information>(bad);
  CHECK(refused.ec == errc::bad_text);
  CHECK(refused.field == 5);
  const std::string too_long(33, 'x');
  bad.m = {{"model_id", str(too_long)}};
  CHECK(n2k::read_json<n2k::product_information>(bad).ec == errc::text_too_long);
  bad.m = {{"model_id", {seawire::nmea::json_kind::number, "12"}}};
  CHECK(n2k::read_json<n2k::product_information>(bad).ec == errc::bad_text);

  // UTF-16: code units as \uXXXX, a pair for a character past U+FFFF; read back as UTF-16
  n2k::configuration_information c;
  c.installation_description_1 =
      n2k::counted_text<221>::from_text("H\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80").value;
  c.manufacturer_information = n2k::counted_text<221>::from_text("B,\"q\"").value;
  const std::string cj = json_of(c);
  CHECK(cj == R"({"type":"PGN126998","installation_description_1":"H\u00E9\u20AC\uD83D\uDE00",)"
              R"("installation_description_2":null,"manufacturer_information":"B,\"q\""})");
  members cin;
  cin.m = {{"installation_description_1", str("H\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80")},
           {"manufacturer_information", str("B,\"q\"")}};
  const auto cback = n2k::read_json<n2k::configuration_information>(cin);
  REQUIRE(cback);
  CHECK(cback.value == c);
  CHECK(std::ranges::equal(n2k::encode(cback.value).value.view(), n2k::encode(c).value.view()));
}
