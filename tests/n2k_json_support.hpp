// SPDX-License-Identifier: BSL-1.0
#pragma once
// What the NMEA 2000 tests share to write a message as JSON and to read one back: json_of (the
// library's writer into a buffer), fake_json (an object as seawire-encode's reader gives it to
// read_json, written out by hand).

#include <catch2/catch.hpp>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/json.hpp"

namespace support {

/// A PGN message as seawire's JSON (`{"type":"PGN..."`, no header).
template <class Msg>
std::string json_of(const Msg& m) {
  seawire::nmea::json_buffer<8192> j;
  seawire::nmea2000::write_json(j, m);
  REQUIRE(!j.overflow());
  return std::string(j.view());
}

/// A JSON object as seawire-encode's reader gives it to read_json: members by key, array
/// elements by "i", a group element's members by "i.member".
struct fake_json {
  struct entry {
    std::string object;
    std::string key;
    seawire::nmea::json_value value;
  };
  std::vector<entry> entries;
  std::deque<std::string> texts;  // views into them stay valid as more are added
  void add(std::string_view object, std::string_view key, seawire::nmea::json_kind kind,
           std::string_view text) {
    texts.emplace_back(text);
    entries.push_back({std::string(object), std::string(key), {kind, texts.back()}});
  }
  seawire::nmea::json_value operator()(std::string_view object, std::string_view key) const {
    for (const entry& e : entries)
      if (e.object == object && e.key == key) return e.value;
    return {};
  }
};

}  // namespace support
