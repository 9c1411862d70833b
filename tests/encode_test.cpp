// SPDX-License-Identifier: BSL-1.0
// What encode writes: only what decode reads back to the same value (values it could not read are
// refused, naming the field decode would name), equality as the written form, positions with a
// fraction of the minute, and a buffer that holds every sentence that decodes.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "seawire/kingfisher/messages.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/registry.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/sandshark/messages.hpp"
#include "seawire/standard/gga.hpp"
#include "seawire/standard/rmc.hpp"
#include "support.hpp"

using namespace seawire;
using namespace seawire::nmea;
using support::resealed;

// ---------------------------------------------------------------------------------------------
// refusals

TEST_CASE("encode refuses a decimal the decoder could not read back") {
  // 20 digits: decode says number_too_long, so encode must not write them.
  kingfisher::pydep p;
  p.thrust = decimal(50);
  p.yaw_rate.mantissa = 18'446'744'073'709'551'615ULL;
  CHECK(encode(p).ec == errc::value_too_large);
  CHECK(encode(p).field == 1);
  p.yaw_rate.places = 19;  // "1.8446744073709551615": still 20 significant digits
  CHECK(encode(p).ec == errc::value_too_large);
  // The largest mantissa the decoder takes is written and read back.
  p.yaw_rate.mantissa = 9'999'999'999'999'999'999ULL;
  const auto e = encode(p);
  REQUIRE(e);
  const auto d = decode<kingfisher::pydep>(e.view(), parse_policy::strict());
  REQUIRE(d);
  CHECK(d.value == p);

  // Zero padding: the writer pads to 20 digits at most, and reads back what it wrote.
  p.yaw_rate = decimal(1);
  p.yaw_rate.int_width = 20;
  const auto padded = encode(p);
  REQUIRE(padded);
  CHECK(decode<kingfisher::pydep>(padded.view()).value == p);
  p.yaw_rate.int_width = 21;
  CHECK(encode(p).ec == errc::value_too_large);

  // The same through a decimal-degrees position (RobotX), whose own range check (<= 90) would
  // let 1.8446744073709551615 through.
  robotx::rxhrb h;
  h.team_id = "AUVSI";
  h.lat = decimal_latitude{};
  h.lat->value.mantissa = 18'446'744'073'709'551'615ULL;
  h.lat->value.places = 19;
  CHECK(encode(h).ec == errc::value_too_large);
  CHECK(encode(h).field == 3);
}

TEST_CASE("encode and decode name the same field for a wrong hemisphere letter") {
  // The letter is a field of its own ("4 [LatNS_NMEA]"): decode reports it there, and so does
  // encode, not at the number before it.
  standard::rmc m;
  m.lat = latitude::from_degrees(42.5).value;
  m.lon = longitude::from_degrees(-71.25).value;
  m.lat->hemi = hemisphere::east;
  CHECK(encode(m).ec == errc::bad_hemisphere);
  CHECK(encode(m).field == 4);
  CHECK(decode<standard::rmc>("$GPRMC,,A,4230.0000,E,07115.0000,W,,,,,*03\r\n").field == 4);
  m.lat->hemi = hemisphere::north;
  m.lon->hemi = hemisphere::north;
  CHECK(encode(m).field == 6);
  CHECK(decode<standard::rmc>("$GPRMC,,A,4230.0000,N,07115.0000,N,,,,,*11\r\n").field == 6);
  // Errors in the number itself stay on the number.
  m.lon->hemi = hemisphere::west;
  m.lon->minutes = decimal(60);
  CHECK(encode(m).ec == errc::minute_out_of_range);
  CHECK(encode(m).field == 5);

  robotx::rxhrb h;
  h.team_id = "AUVSI";
  h.lat = decimal_latitude{decimal::scaled(2131198, 5), hemisphere::west};
  CHECK(encode(h).ec == errc::bad_hemisphere);
  CHECK(encode(h).field == 4);
  h.lat->hemi = hemisphere::north;
  h.lon = decimal_longitude{decimal::scaled(18001, 2), hemisphere::west};
  CHECK(encode(h).ec == errc::bad_longitude);
  CHECK(encode(h).field == 5);
}

TEST_CASE("an absent text field can only be left out at the end") {
  // BFACK's description (7) and trailing field (8) may each be absent. Blank text is empty
  // text, so a description that is absent while field 8 is there cannot be written: it would
  // come back as an empty description.
  sandshark::bfack a;
  a.command = "RMB";
  a.description.reset();
  CHECK(encode(a).ec == errc::missing_field);
  CHECK(encode(a).field == 7);
  a.trailing.reset();
  const auto seven = encode(a);
  REQUIRE(seven);
  CHECK(seven.view() == "$BFACK,000000,RMB,,,2,0*12\r\n");
  a.description = text<256>{};
  a.trailing = text<128>{};
  const auto e = encode(a);
  REQUIRE(e);
  const auto d = decode<sandshark::bfack>(e.view(), parse_policy::strict());
  REQUIRE(d);
  CHECK(d.value == a);
  {
    // An empty trailing field keeps it from being left out just as well.
    sandshark::bfack b;
    b.command = "RMB";
    b.description.reset();
    b.trailing = text<128>{};
    const auto line = encode(b);
    CHECK(line.ec == errc::missing_field);
    CHECK(line.field == 7);
    b.trailing.reset();  // both absent: the 6-field form
    const auto six = encode(b);
    REQUIRE(six);
    const auto back = decode<sandshark::bfack>(six.view(), parse_policy::strict());
    REQUIRE(back);
    CHECK(back.value == b);
  }
}

// ---------------------------------------------------------------------------------------------
// equality is the written form

TEST_CASE("equality is the written form: padding that writes nothing is no difference") {
  // int_width 1 on "45" and degree_digits 1 on 42 degrees pad nothing: the writer writes what
  // it would without them, so decode(encode(v)) must equal v.
  kingfisher::pydir p;
  p.thrust_left = decimal(48);
  p.thrust_left.int_width = 1;
  p.thrust_right = decimal(0);
  p.thrust_right.int_width = 1;
  const auto e = encode(p);
  REQUIRE(e);
  CHECK(e.view() == "$PYDIR,48,0*6A\r\n");
  const auto d = decode<kingfisher::pydir>(e.view(), parse_policy::strict());
  REQUIRE(d);
  CHECK(d.value == p);
  // Padding that is written is part of the value.
  decimal padded(45);
  padded.int_width = 3;  // "045"
  CHECK(padded != decimal(45));
  CHECK(padded.written_int_digits() == 3);

  standard::rmc m;
  m.lat = latitude{42, decimal::scaled(217, 1), hemisphere::north, 1};  // written "4221.7"
  m.lon = longitude{100, decimal::scaled(5, 1), hemisphere::west, 2};   // written "10000.5"
  const auto r = encode(m);
  REQUIRE(r);
  CHECK(r.view().starts_with("$GPRMC,,A,4221.7,N,10000.5,W,"));
  const auto back = decode<standard::rmc>(r.view(), parse_policy::strict());
  REQUIRE(back);
  CHECK(back.value.lat == m.lat);
  CHECK(back.value.lon == m.lon);
  CHECK(back.value == m);
  // An unpadded longitude is a different written form from the padded one.
  CHECK(longitude{71, decimal::scaled(5, 1), hemisphere::west, 2} !=
        longitude{71, decimal::scaled(5, 1), hemisphere::west, 3});
}

TEST_CASE("decimal equality is the text form: int_width that pads nothing is no difference") {
  // A thrust of -25.7 built with int_width 1 is written "-25.7" and reads back with int_width 0.
  kingfisher::pydir m;
  m.thrust_left = decimal::scaled(-257, 1);
  m.thrust_left.int_width = 1;  // "-25.7" has two integer digits: 1 pads nothing
  m.thrust_right = m.thrust_left;
  const auto line = encode(m);
  REQUIRE(line);
  CHECK(line.view() == "$PYDIR,-25.7,-25.7*56\r\n");
  const auto back = decode<kingfisher::pydir>(line.view(), parse_policy::strict());
  REQUIRE(back);
  CHECK(back.value == m);
  CHECK(decimal(5) == decimal(5));
  decimal padded(5);
  padded.int_width = 3;  // "005": a different text
  CHECK_FALSE(padded == decimal(5));
}

TEST_CASE("position equality is the text form: degree digits the degrees need anyway") {
  // Latitude 0 with degree_digits 0 is written with one degree digit ("000.0"), as with 1.
  standard::gga m;
  m.lat = latitude{0, decimal(0), hemisphere::north, 0};
  m.lon = longitude{0, decimal(0), hemisphere::east, 1};
  const auto line = encode(m);
  REQUIRE(line);
  CHECK(line.view().starts_with("$GPGGA,,000.0,N,000.0,E,"));  // minutes: one fraction digit
  const auto back = decode<standard::gga>(line.view(), parse_policy::strict());
  REQUIRE(back);
  CHECK(back.value.lat == m.lat);
  CHECK(back.value.lon == m.lon);
  CHECK(back.value.lat->degree_digits == 1);
  // Digits beyond what the degrees need are a different text.
  CHECK_FALSE(latitude{5, decimal(0), hemisphere::north, 2} ==
              latitude{5, decimal(0), hemisphere::north, 1});
}

// ---------------------------------------------------------------------------------------------
// positions

// The text a DDMM position is written as, built here digit by digit: the degrees zero-padded to
// their digits (at least one), the minutes' two integer digits, a point and every fraction digit
// (at least one).
template <class C>
std::string ddmm_text(const C& c) {
  std::string deg = std::to_string(c.whole_degrees);
  const std::size_t deg_width = c.degree_digits > 0 ? c.degree_digits : 1;
  if (deg.size() < deg_width) deg.insert(0, deg_width - deg.size(), '0');
  const unsigned places = c.minutes.places > 0 ? c.minutes.places : 1;
  std::string digits = std::to_string(c.minutes.mantissa * (c.minutes.places > 0 ? 1 : 10));
  if (digits.size() < places + 2) digits.insert(0, places + 2 - digits.size(), '0');
  return deg + digits.substr(0, 2) + "." + digits.substr(2);
}

TEST_CASE("a DDMM position is written as its degrees' digits, two minute digits and the fraction") {
  // Every degree width, degrees at their edges, minutes with 0 to 12 fraction digits at theirs.
  std::size_t written = 0;
  for (std::uint8_t width = 0; width <= 3; ++width) {
    for (const std::uint16_t degrees :
         std::initializer_list<std::uint16_t>{0, 1, 9, 10, 89, 90, 99, 100, 179, 180}) {
      for (std::uint8_t places = 0; places <= 12; ++places) {
        const std::uint64_t one = seawire::detail::pow10_table[places];
        for (const std::uint64_t mantissa : {std::uint64_t{0}, std::uint64_t{1}, 9 * one / 10,
                                             10 * one - 1, 10 * one, 60 * one - 1}) {
          standard::rmc m{};
          m.talker = talker_id("GP");
          m.lat = latitude(degrees, decimal::scaled(static_cast<std::int64_t>(mantissa), places),
                           hemisphere::north, width);
          m.lon = longitude(degrees, decimal::scaled(static_cast<std::int64_t>(mantissa), places),
                            hemisphere::west, width);
          const auto e = encode(m);
          const bool lat_ok = width <= 2 && (degrees < 90 || (degrees == 90 && mantissa == 0));
          const bool lon_ok = degrees < 180 || mantissa == 0;
          INFO("width " << int{width} << ", " << degrees << " degrees, " << mantissa << " / 10^"
                        << int{places} << " minutes");
          if (!lat_ok) {
            CHECK(e.ec == errc::bad_latitude);
            continue;
          }
          if (!lon_ok) {
            CHECK(e.ec == errc::bad_longitude);
            continue;
          }
          REQUIRE(e);
          const std::string expected =
              ",A," + ddmm_text(*m.lat) + ",N," + ddmm_text(*m.lon) + ",W,";
          CHECK(std::string(e.view()).find(expected) == 7);  // after "$GPRMC,," (no time)
          ++written;
        }
      }
    }
  }
  CHECK(written > 1000);
}

TEST_CASE("positions built from degrees always carry a fraction of the minute") {
  // Every spec writes DDMM.m (Kingfisher: "minimum of one digit to the right of the decimal
  // point"), and receivers depend on it: gpsd 3.22 drops the whole fix for "5906,S", pynmea2's
  // latitude/longitude raise. So the builder refuses zero places.
  CHECK(latitude::from_degrees(42.5, 0).ec == errc::out_of_range);
  CHECK(longitude::from_degrees(-71.25, 0).ec == errc::out_of_range);
  const auto lat = latitude::from_degrees(42.5, 1);
  REQUIRE(lat);
  standard::rmc m;
  m.lat = lat.value;
  CHECK(encode(m).view().starts_with("$GPRMC,,A,4230.0,N,"));

  // A position received without a fraction is still read, as a zero fraction digit, and
  // relayed with it: seawire never sends "4221,N".
  constexpr std::string_view received = "$GPRMC,,A,4221,N,07105,W,,,,,*09\r\n";
  const auto d = decode<standard::rmc>(received);
  REQUIRE(d);
  CHECK(d.value.lat->minutes == decimal::scaled(210, 1));
  CHECK(d.value.lat->degrees() == Approx(42.35));
  const auto relayed = encode(d.value);
  REQUIRE(relayed);
  CHECK(relayed.view().starts_with("$GPRMC,,A,4221.0,N,07105.0,W,,,,,*"));
  const auto again = decode<standard::rmc>(relayed.view(), parse_policy::strict());
  REQUIRE(again);
  CHECK(again.value == d.value);
  // Minutes set in code with no fraction digits are written with one, and compare equal to it.
  standard::rmc m0;
  m0.lat = latitude{42, decimal(21), hemisphere::north, 2};
  CHECK(encode(m0).view().starts_with("$GPRMC,,A,4221.0,N,"));
  CHECK(m0.lat == d.value.lat);
  // Held to the sending rules (seawire-decode --strict), it is refused, at the number.
  const auto strict = decode<standard::rmc>(received, parse_policy::strict());
  CHECK(strict.ec == errc::bad_latitude);
  CHECK(strict.field == 3);
  const auto lon =
      decode<standard::rmc>("$GPRMC,,A,4221.5,N,07105.,W,,,,,*3C\r\n", parse_policy::strict());
  CHECK(lon.ec == errc::bad_longitude);
  CHECK(lon.field == 5);
}

// ---------------------------------------------------------------------------------------------
// the buffer encode() picks

TEST_CASE("encode() holds every sentence that decodes") {
  // A CPIMU whose six numbers are written with 19 zero-padded integer digits and 18 fraction
  // digits decodes (285 bytes, under the 1024 a receiver takes) but would not fit 256 bytes:
  // encode()'s buffer comes from the longest text each field's codec can write.
  const std::string d = "-0000000000000000000.000000000000000001";
  const std::string line = resealed("$CPIMU,235959.123456789," + d + "," + d + "," + d + "," + d +
                                    "," + d + "," + d + ",235959.123456789");
  const auto r = decode<kingfisher::cpimu>(line);
  REQUIRE(r);
  const auto e = encode(r.value);
  REQUIRE(e);
  CHECK(e.view() == line);
  CHECK(sizeof e.data >= 297);  // the longest CPIMU: 6 numbers of 41 characters, 2 times of 16
  // Messages that cannot be long keep the 256-byte buffer.
  CHECK(sizeof encode(kingfisher::pydir{}).data == 256);
}

TEST_CASE("encode_to fits the sentence into a buffer of its size, and into none smaller") {
  // Every size from empty to a few bytes past the sentence, the trailer ("*hh\r\n") cut at each
  // of its bytes among them: below the sentence's length nothing is reported written.
  const std::string line = "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n";
  const auto r = decode<standard::gga>(line);
  REQUIRE(r);
  for (std::size_t n = 0; n <= line.size() + 3; ++n) {
    std::vector<char> out(n, '#');
    const auto w = encode_to(r.value, std::span<char>(out));
    INFO("buffer of " << n << " bytes");
    if (n < line.size()) {
      CHECK(w.ec == errc::buffer_too_small);
    } else {
      REQUIRE(w);
      CHECK(std::string_view(out.data(), w.value) == line);
    }
  }
}

// Every message of the library is written with one check of the room: each field's codec says
// how long it writes and takes encode's unchecked writer.
static_assert([]<class... M>(std::type_identity<message_set<M...>>) {
  return ((nmea::detail::writes_unchecked<M>() && nmea::detail::longest_sentence<M>() != 0) && ...);
}(std::type_identity<registry::sentences>{}));

// encode_to at compile time: into a buffer that holds the message's longest sentence (written
// with no check of the room) and into one that holds only this sentence (the room checked).
template <std::size_t N>
constexpr bool encodes_at_compile_time(std::string_view expected) {
  standard::gga m{};
  m.talker = talker_id("GP");
  m.time = time_of_day{12, 35, 19};
  m.quality = standard::gps_quality::gps;
  char out[N]{};
  const result<std::size_t> r = encode_to(m, std::span<char>(out, N));
  if (N < expected.size()) return r.ec == errc::buffer_too_small;
  return r && std::string_view(out, r.value) == expected;
}
constexpr std::string_view short_gga = "$GPGGA,123519,,,,,1,,,,M,,M,,*6A\r\n";
static_assert(nmea::detail::longest_sentence<standard::gga>() > 64);
static_assert(encodes_at_compile_time<256>(short_gga));
static_assert(encodes_at_compile_time<34>(short_gga));
static_assert(encodes_at_compile_time<33>(short_gga));

// Two codecs of a user's own, for a letter pair: one whose write() takes only `writer&` (its
// message is written with the room checked at each write), one whose write() takes any
// sentence_writer and says how long it writes (one check a sentence, as the library's).
namespace user {
struct pair_checked {
  char a = 'A', b = 'B';
  friend constexpr bool operator==(const pair_checked&, const pair_checked&) = default;
};
struct pair_any {
  char a = 'A', b = 'B';
  friend constexpr bool operator==(const pair_any&, const pair_any&) = default;
};
}  // namespace user

template <class P>
struct user_pair_codec {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = 2;
  static constexpr bool allows_blank = false;
  static constexpr errc read(field_reader& r, P& v) noexcept {
    const std::string_view t = r.take().text;
    if (t.size() != 2) return errc::bad_enum;
    v.a = t[0];
    v.b = t[1];
    return errc::ok;
  }
  static constexpr errc check(const P& v) noexcept {
    return seawire::detail::is_upper(v.a) && seawire::detail::is_upper(v.b) ? errc::ok
                                                                            : errc::bad_enum;
  }
};
template <>
struct seawire::nmea::codec<user::pair_checked> : user_pair_codec<user::pair_checked> {
  static constexpr void write(writer& w, const user::pair_checked& v) noexcept {
    w.put(v.a);
    w.put(v.b);
  }
};
template <>
struct seawire::nmea::codec<user::pair_any> : user_pair_codec<user::pair_any> {
  template <sentence_writer W>
  static constexpr void write(W& w, const user::pair_any& v) noexcept {
    w.put(v.a);
    w.put(v.b);
  }
};

namespace user {
struct checked_msg {
  pair_checked p;
  std::uint16_t n = 0;
  static constexpr auto nmea =
      nmea::sentence<"PUSRC">(nmea::field<&checked_msg::p>("p"), nmea::field<&checked_msg::n>("n"));
};
struct any_msg {
  pair_any p;
  std::uint16_t n = 0;
  static constexpr auto nmea =
      nmea::sentence<"PUSRA">(nmea::field<&any_msg::p>("p"), nmea::field<&any_msg::n>("n"));
};
}  // namespace user

static_assert(!nmea::detail::writes_unchecked<user::checked_msg>());
static_assert(nmea::detail::writes_unchecked<user::any_msg>());

TEST_CASE("a codec of a user's own that takes writer& is written with the room checked") {
  const auto each_size = [](const auto& m, std::string_view expected) {
    for (std::size_t n = 0; n <= expected.size() + 2; ++n) {
      std::vector<char> out(n, '#');
      const auto w = encode_to(m, std::span<char>(out));
      INFO(expected << " into " << n << " bytes");
      if (n < expected.size()) {
        CHECK(w.ec == errc::buffer_too_small);
      } else {
        REQUIRE(w);
        CHECK(std::string_view(out.data(), w.value) == expected);
        CHECK(std::all_of(out.begin() + static_cast<std::ptrdiff_t>(w.value), out.end(),
                          [](char c) { return c == '#'; }));
      }
    }
  };
  each_size(user::checked_msg{{'X', 'Y'}, 7}, resealed("$PUSRC,XY,7"));
  each_size(user::any_msg{{'X', 'Y'}, 65535}, resealed("$PUSRA,XY,65535"));
  CHECK(encode_to(user::any_msg{{'x', 'Y'}, 1}, std::span<char>()).ec == errc::bad_enum);
  // The longest PUSRA: '$', the address, a comma and each field at its longest, "*hh\r\n".
  CHECK(nmea::detail::longest_sentence<user::any_msg>() == 1 + 5 + 1 + 2 + 1 + 5 + 5);
}

TEST_CASE("a BFMIS that decodes also encodes: its texts need more than 256 bytes") {
  sandshark::bfmis m;
  m.timestamp = time_of_day{23, 59, 59, 999'999'999, 9};
  (void)m.dive_file.assign(std::string(128, 'd'));
  (void)m.status.assign("Running " + std::string(120, 's'));
  (void)m.details.assign(std::string(200, 'x'));
  const auto e = encode(m);
  REQUIRE(e);
  CHECK(e.view().size() == 487);
  const auto d = sandshark::decode_from_vehicle(e.view());
  REQUIRE(d);
  REQUIRE(std::holds_alternative<sandshark::bfmis>(d.value));
  CHECK(std::get<sandshark::bfmis>(d.value) == m);
  CHECK(encode(std::get<sandshark::bfmis>(d.value)).view() == e.view());
  // Other messages keep the 256-byte buffer; an explicit size still works.
  static_assert(sizeof(encode(sandshark::bpsts{}).data) == 256);
  CHECK(encode<128>(m).ec == errc::buffer_too_small);
  // A buffer shorter than its longest sentence is written with the room checked at each write,
  // to the same bytes or none.
  std::vector<char> exact(e.view().size());
  const auto w = encode_to(m, std::span<char>(exact));
  REQUIRE(w);
  CHECK(std::string_view(exact.data(), w.value) == e.view());
  CHECK(encode_to(m, std::span<char>(exact.data(), exact.size() - 1)).ec == errc::buffer_too_small);
}

// A program's own function named encode, called without qualification from its namespace on
// something that names seawire's types: argument-dependent lookup finds nmea::encode too, which
// must then be no candidate (not a compile error) for what is not a message.
namespace payload {
using queue = std::vector<std::variant<unknown_sentence, kingfisher::pydep>>;
int encode(const queue& q) { return static_cast<int>(q.size()); }
int send_all(const queue& q) { return encode(q); }  // payload::encode, nmea::encode beside it
}  // namespace payload

// nmea::encode takes a message and nothing else, without an error in its own declaration.
template <class T>
concept encodable = requires(const T& x) {
  nmea::encode(x);
};
static_assert(encodable<kingfisher::pydep>);
static_assert(!encodable<payload::queue>);

TEST_CASE("a program's own encode beside nmea::encode: what is no message is the program's") {
  CHECK(payload::send_all(payload::queue(3)) == 3);
  CHECK(payload::send_all(payload::queue{}) == 0);
}
