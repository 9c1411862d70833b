// SPDX-License-Identifier: BSL-1.0
// PGN 126208 Group Function: one PGN, a layout per function code (its first byte). Payloads from
// real captures (canboat's sample logs; canboat's analyzer's reading in the comments) decoded
// against a decode written here by hand (bytes little-endian, no library bit reader); the set of
// PGNs gives a payload to the layout its function code names and to none for a code seawire does
// not describe; encode refuses a struct holding another layout's code; the parameter pairs kept
// as bytes, exact both ways; JSON written and read back.

#include <array>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "n2k_json_support.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/registry.hpp"

namespace n2k = seawire::nmea2000;
using seawire::errc;

namespace {

using support::fake_json;
using support::json_of;

std::vector<std::uint8_t> bytes_of(std::string_view hex) {
  std::vector<std::uint8_t> out;
  const auto nibble = [](char c) {
    return static_cast<std::uint8_t>(c <= '9' ? c - '0' : (c | 0x20) - 'a' + 10);
  };
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2)
    out.push_back(static_cast<std::uint8_t>(nibble(hex[i]) << 4 | nibble(hex[i + 1])));
  return out;
}

using support::le;

using seawire::nmea::json_kind;

using request = n2k::group_function_request;
using command = n2k::group_function_command;
using acknowledge = n2k::group_function_acknowledge;
using pgns = seawire::registry::pgns;

// The name of the struct the set of PGNs decodes a 126208 payload as; "" for none.
std::string layout_of(std::span<const std::uint8_t> payload) {
  std::string name;
  const bool known = pgns::visit(126208, payload, [&](const auto& m) {
    name = n2k::pgn_table<std::remove_cvref_t<decltype(m)>>.info.name;
  });
  CHECK(known == !name.empty());
  return name;
}

// canboat's samples/scx20-setting-tool-pgn-127251-200ms.raw: a request for 127251 every 200 ms,
// offset not available, no parameters. canboat: "Transmission interval":"00:00:00.200".
constexpr std::string_view request_hex = "0013f101c8000000ffff00";
// samples/126208.raw: a command for 127501, priority "Leave unchanged", 1 parameter (field 3,
// "On"). canboat: {"Parameter":3,"Value":"On"}.
constexpr std::string_view command_hex = "010df201f8010301";
// samples/dirona-actisense-serial.raw: the acknowledgement of a command for 130824: "Access
// denied", interval "Acknowledge", 5 parameters of 4 bits, two to a byte (the last byte's rest
// ones): the third "Parameter out of range".
constexpr std::string_view acknowledge_hex =
    "0208ff01030500"
    "03f0";
// samples/scx20-setting-tool-offsets.raw: a command for 130822 (Furuno) with 8 pairs in 28 bytes.
constexpr std::string_view long_command_hex =
    "0111ff01f808013f0703040401083300"
    "09ab000a400105280007"
    "1b00";

}  // namespace

TEST_CASE("group function: the layouts' facts", "[group_function]") {
  STATIC_REQUIRE(n2k::pgn_table<request>.info.pgn == 126208);
  STATIC_REQUIRE(n2k::pgn_table<command>.info.pgn == 126208);
  STATIC_REQUIRE(n2k::pgn_table<acknowledge>.info.pgn == 126208);
  STATIC_REQUIRE(n2k::description_of<request>::has_match);
  STATIC_REQUIRE(!n2k::description_of<n2k::pgn_list_message>::has_match);
  // The fixed rows, then what a fast packet's 223 bytes hold.
  STATIC_REQUIRE(n2k::description_of<request>::bit_length == 88);
  STATIC_REQUIRE(n2k::description_of<request>::length == 223);
  STATIC_REQUIRE(n2k::description_of<command>::bit_length == 48);
  STATIC_REQUIRE(n2k::description_of<command>::length == 223);
  STATIC_REQUIRE(decltype(acknowledge::parameters)::capacity == 434);  // 217 bytes, 2 a byte
  CHECK(pgns::layouts(126208) == 3);
  CHECK(pgns::layouts(126464) == 1);
  CHECK(pgns::layouts(12345) == 0);
  CHECK(pgns::length(126208) == 223);
  CHECK(pgns::info(126208)->transport == n2k::framing::fast_packet);
  // A struct starts as its own layout.
  CHECK(request{}.function_code == n2k::group_function::request);
  CHECK(command{}.function_code == n2k::group_function::command);
  CHECK(acknowledge{}.function_code == n2k::group_function::acknowledge);
}

TEST_CASE("group function: the function code picks the layout", "[group_function]") {
  CHECK(layout_of(bytes_of(request_hex)) == "group_function_request");
  CHECK(layout_of(bytes_of(command_hex)) == "group_function_command");
  CHECK(layout_of(bytes_of(acknowledge_hex)) == "group_function_acknowledge");
  // Read Fields (3) to Write Fields Reply (6), and codes the standard has not named: no layout
  // here, so the payload comes out raw.
  for (const int code : {3, 4, 5, 6, 7, 0x20, 0xFF}) {
    std::vector<std::uint8_t> p = bytes_of(command_hex);
    p[0] = static_cast<std::uint8_t>(code);
    INFO(code);
    CHECK(layout_of(p).empty());
  }
  // An empty payload holds no function code.
  CHECK(layout_of({}).empty());
  CHECK_FALSE(n2k::layout_matches<request>({}));
  // Without a match row every payload has the struct's layout.
  CHECK(n2k::layout_matches<n2k::pgn_list_message>({}));
}

TEST_CASE("group function: real payloads against a decode by hand", "[group_function]") {
  SECTION("request") {
    const auto p = bytes_of(request_hex);
    const request m = n2k::decode<request>(p);
    CHECK(m.pgn.raw() == static_cast<std::int64_t>(le(p, 1, 3)));
    CHECK(m.pgn.raw() == 127251);
    CHECK(m.transmission_interval_s.raw() == static_cast<std::int64_t>(le(p, 4, 4)));
    CHECK(m.transmission_interval_s.raw() == 200);  // 0.2 s
    CHECK(m.transmission_interval_offset_s.state() == n2k::field_state::not_available);
    CHECK(m.number_of_parameters.raw() == p[10]);
    CHECK(m.parameters.empty());
    CHECK(json_of(m) == R"({"type":"PGN126208","function_code":"request","pgn":127251,)"
                        R"("transmission_interval_s":0.200,"transmission_interval_offset_s":null,)"
                        R"("number_of_parameters":0,"parameters":""})");
  }
  SECTION("command") {
    const auto p = bytes_of(command_hex);
    const command m = n2k::decode<command>(p);
    CHECK(m.pgn.raw() == static_cast<std::int64_t>(le(p, 1, 3)));
    CHECK(m.priority.raw() == (p[4] & 0x0F));
    CHECK(m.priority == n2k::priority_setting::leave_unchanged);
    CHECK(m.number_of_parameters.raw() == p[5]);
    REQUIRE(m.parameters.size() == p.size() - 6);
    for (std::size_t i = 0; i < m.parameters.size(); ++i)
      CHECK(m.parameters.bytes()[i] == p[6 + i]);
    CHECK(json_of(m) == R"({"type":"PGN126208","function_code":"command","pgn":127501,)"
                        R"("priority":"leave_unchanged","number_of_parameters":1,)"
                        R"("parameters":"0301"})");
  }
  SECTION("acknowledge") {
    const auto p = bytes_of(acknowledge_hex);
    const acknowledge m = n2k::decode<acknowledge>(p);
    CHECK(m.pgn.raw() == static_cast<std::int64_t>(le(p, 1, 3)));
    CHECK(m.pgn_error_code.raw() == (p[4] & 0x0F));
    CHECK(m.pgn_error_code == n2k::pgn_error_code::access_denied);
    CHECK(m.transmission_interval_priority_error_code.raw() == (p[4] >> 4));
    CHECK(m.number_of_parameters.raw() == p[5]);
    REQUIRE(m.parameters.size() == p[5]);
    for (std::size_t i = 0; i < m.parameters.size(); ++i)
      CHECK(m.parameters.items()[i].parameter.raw() == ((p[6 + i / 2] >> (4 * (i % 2))) & 0x0F));
    CHECK(m.parameters.items()[2].parameter == n2k::parameter_error_code::parameter_out_of_range);
    CHECK(json_of(m) ==
          R"({"type":"PGN126208","function_code":"acknowledge","pgn":130824,)"
          R"("pgn_error_code":"access_denied","transmission_interval_priority_error_code":)"
          R"("acknowledge","number_of_parameters":5,"parameters":[{"parameter":"acknowledge"},)"
          R"({"parameter":"acknowledge"},{"parameter":"parameter_out_of_range"},)"
          R"({"parameter":"acknowledge"},{"parameter":"acknowledge"}]})");
  }
}

TEST_CASE("group function: decode -> encode gives the bytes back", "[group_function]") {
  const auto same = [](const auto& decoded, const std::vector<std::uint8_t>& p) {
    const auto e = n2k::encode(decoded);
    REQUIRE(e);
    CHECK(std::vector<std::uint8_t>(e.value.begin(), e.value.end()) == p);
  };
  same(n2k::decode<request>(bytes_of(request_hex)), bytes_of(request_hex));
  same(n2k::decode<command>(bytes_of(command_hex)), bytes_of(command_hex));
  same(n2k::decode<command>(bytes_of(long_command_hex)), bytes_of(long_command_hex));
  same(n2k::decode<acknowledge>(bytes_of(acknowledge_hex)), bytes_of(acknowledge_hex));
  // An even count fills its last byte; an odd one's last byte ends in ones.
  const auto four = bytes_of("0208ff0103043021");
  same(n2k::decode<acknowledge>(four), four);
  acknowledge a = n2k::decode<acknowledge>(four);
  a.number_of_parameters = decltype(a.number_of_parameters)::from_raw(3);
  a.parameters.clear();
  for (const auto code :
       {n2k::parameter_error_code::temporary_error, n2k::parameter_error_code::acknowledge,
        n2k::parameter_error_code::not_supported}) {
    acknowledge::parameter_answer item;
    item.parameter = code;
    REQUIRE(a.parameters.push_back(item));
  }
  const auto odd = n2k::encode(a);
  REQUIRE(odd);
  CHECK(std::vector<std::uint8_t>(odd.value.begin(), odd.value.end()) ==
        bytes_of("0208ff01030302f5"));
  // With a count that says nothing, or more than were held, a receiver counts the codes by the
  // payload's length: three would come back as four (the padding read as a code), so encode
  // refuses them; four go.
  a.number_of_parameters = decltype(a.number_of_parameters)::not_available();
  const auto unsaid = n2k::encode(a);
  CHECK(unsaid.ec == errc::bad_length);
  CHECK(n2k::field_name<acknowledge>(unsaid.field) == "parameters");
  a.number_of_parameters = decltype(a.number_of_parameters)::from_raw(5);
  CHECK(n2k::encode(a).ec == errc::bad_length);
  a.number_of_parameters = decltype(a.number_of_parameters)::not_available();
  acknowledge::parameter_answer fourth;
  fourth.parameter = n2k::parameter_error_code::access_denied;
  REQUIRE(a.parameters.push_back(fourth));
  const auto filled = n2k::encode(a);
  REQUIRE(filled);
  CHECK(n2k::decode<acknowledge>(filled.value.view()) == a);
}

TEST_CASE("group function: a struct sends only its own layout", "[group_function]") {
  command c;
  c.pgn = decltype(c.pgn)::from_raw(127501);
  c.priority = n2k::priority_setting::priority_3;
  c.number_of_parameters = decltype(c.number_of_parameters)::from_raw(1);
  c.parameters = decltype(c.parameters)::from_hex("0301").value;
  const auto ok = n2k::encode(c);
  REQUIRE(ok);
  CHECK(std::vector<std::uint8_t>(ok.value.begin(), ok.value.end()) ==
        bytes_of("010df201f3010301"));  // priority 3, reserved bits as ones
  // A command holding the request's code would be read as a request: refused, at the row.
  c.function_code = n2k::group_function::request;
  const auto wrong = n2k::encode(c);
  CHECK(wrong.ec == errc::wrong_address);
  CHECK(wrong.field == 1);
  CHECK(n2k::field_name<command>(wrong.field) == "function_code");
  c.function_code = decltype(c.function_code)::from_raw(7);
  CHECK(n2k::encode(c).ec == errc::wrong_address);
}

TEST_CASE("group function: opaque bytes", "[group_function]") {
  using B = n2k::opaque_bytes<4>;
  CHECK(B::from_hex("").value.empty());
  CHECK(B::from_hex("0aFf").value.size() == 2);
  CHECK(B::from_hex("0aFf").value.bytes()[1] == 0xFF);
  CHECK(B::from_hex("0").ec == errc::bad_text);
  CHECK(B::from_hex("0g").ec == errc::bad_text);
  CHECK(B::from_hex(" 00").ec == errc::bad_text);
  CHECK(B::from_hex("0102030405").ec == errc::text_too_long);
  const std::array<std::uint8_t, 5> five{1, 2, 3, 4, 5};
  CHECK(B::from_bytes(five).ec == errc::text_too_long);
  CHECK(B::from_bytes(std::span(five).first(4)).value.size() == 4);
  CHECK(B{}.state() == n2k::field_state::value);
  CHECK(B::from_hex("01").value == B::from_bytes(std::span(five).first(1)).value);
  CHECK_FALSE(B::from_hex("01").value == B::from_hex("0102").value);

  // A payload longer than a fast packet keeps what the capacity holds.
  std::vector<std::uint8_t> p = bytes_of(command_hex);
  p.resize(240, 0xAB);
  CHECK(n2k::decode<command>(p).parameters.size() == 217);
  // A payload that ends inside the fixed rows: those fields not available, no bytes.
  const std::vector<std::uint8_t> whole = bytes_of(command_hex);
  const command shortened = n2k::decode<command>(std::span<const std::uint8_t>(whole).first(3));
  CHECK(shortened.pgn.state() == n2k::field_state::not_available);
  CHECK(shortened.parameters.empty());
}

TEST_CASE("group function: JSON read back", "[group_function]") {
  fake_json in;
  in.add("", "function_code", json_kind::string, "command");
  in.add("", "pgn", json_kind::number, "127501");
  in.add("", "priority", json_kind::string, "leave_unchanged");
  in.add("", "number_of_parameters", json_kind::number, "1");
  in.add("", "parameters", json_kind::string, "0301");
  const auto r = n2k::read_json<command>(in);
  REQUIRE(r);
  CHECK(r.value == n2k::decode<command>(bytes_of(command_hex)));

  SECTION("the function code may be left out: the struct's own") {
    fake_json bare;
    bare.add("", "pgn", json_kind::number, "126996");
    const auto b = n2k::read_json<request>(bare);
    REQUIRE(b);
    CHECK(b.value.function_code == n2k::group_function::request);
    CHECK(b.value.parameters.empty());
  }
  SECTION("another layout's code is read, and encode refuses it") {
    fake_json other = in;
    other.entries[0].value.text = "request";
    const auto o = n2k::read_json<command>(other);
    REQUIRE(o);
    CHECK(n2k::encode(o.value).ec == errc::wrong_address);
  }
  SECTION("bytes that are not hex, or too many") {
    fake_json bad;
    bad.add("", "parameters", json_kind::string, "03 01");
    const auto e = n2k::read_json<command>(bad);
    CHECK(e.ec == errc::bad_text);
    CHECK(n2k::field_name<command>(e.field) == "parameters");
    fake_json number;
    number.add("", "parameters", json_kind::number, "301");
    CHECK(n2k::read_json<command>(number).ec == errc::bad_text);
    fake_json long_text;
    long_text.add("", "parameters", json_kind::string, std::string(2 * 218, '0'));
    CHECK(n2k::read_json<command>(long_text).ec == errc::text_too_long);
  }
}
