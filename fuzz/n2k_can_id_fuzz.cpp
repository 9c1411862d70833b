// SPDX-License-Identifier: BSL-1.0
// The NMEA 2000 CAN identifier: parse_can_id on every 4 bytes of the input (little-endian), and
// make_can_id on fields built from the same bytes.
// Properties:
//  - parse_can_id(id) succeeds iff id fits 29 bits (bad_can_id otherwise, so a SocketCAN id with
//    CAN_EFF_FLAG left on is refused), and then gives fields a frame can have: priority 0-7, an
//    18-bit PGN, destination 255 for a broadcast (PDU2) PGN and a PDU1 PGN whose low byte is 0;
//  - make_can_id(parse_can_id(id)) == id for every 29-bit id: PDU1 and PDU2 alike, nothing of
//    the 29 bits is lost (the PDU2 group extension is in the PGN, the PDU1 destination in
//    `destination`);
//  - make_can_id(f) refuses exactly the fields no identifier has (priority above 7, PGN above 18
//    bits, PDU1 PGN with a low byte, PDU2 PGN sent to one address), and parse_can_id gives back
//    the very fields it was given otherwise.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "fuzz_common.hpp"
#include "seawire/nmea2000/can_id.hpp"

namespace seawire::fuzz {
namespace {

namespace n2k = nmea2000;

std::string hex32(std::uint32_t v) {
  std::string out = "0x";
  for (int shift = 28; shift >= 0; shift -= 4) out += "0123456789ABCDEF"[(v >> shift) & 0xFU];
  return out;
}

std::string fields_of(const n2k::can_id& f) {
  return "prio " + number(f.priority) + " pgn " + number(f.pgn) + " src " + number(f.source) +
         " dst " + number(f.destination);
}

void check_parse(std::uint32_t id) {
  const seawire::result<n2k::can_id> r = n2k::parse_can_id(id);
  if (id > 0x1FFFFFFFU) {
    SEAWIRE_FUZZ_CHECK(!r && r.ec == errc::bad_can_id, "an id above 29 bits was taken", hex32(id),
                       name(r.ec));
    return;
  }
  SEAWIRE_FUZZ_CHECK(r.ok(), "a 29-bit id was refused", hex32(id), name(r.ec));
  const n2k::can_id& f = r.value;
  SEAWIRE_FUZZ_CHECK(f.priority <= 7 && f.pgn <= n2k::max_pgn, hex32(id), fields_of(f));
  if (n2k::is_addressed(f.pgn)) {
    SEAWIRE_FUZZ_CHECK((f.pgn & 0xFFU) == 0, "a PDU1 PGN with a low byte", hex32(id), fields_of(f));
  } else {
    SEAWIRE_FUZZ_CHECK(f.destination == n2k::broadcast_address, "a PDU2 PGN with a destination",
                       hex32(id), fields_of(f));
  }
  const seawire::result<std::uint32_t> back = n2k::make_can_id(f);
  SEAWIRE_FUZZ_CHECK(back.ok() && back.value == id, "make_can_id(parse_can_id(id)) != id",
                     hex32(id), fields_of(f), name(back.ec), hex32(back.value));
}

void check_make(const n2k::can_id& f) {
  const bool addressed = n2k::is_addressed(f.pgn);
  const bool valid = f.priority <= 7 && f.pgn <= n2k::max_pgn &&
                     (addressed ? (f.pgn & 0xFFU) == 0 : f.destination == n2k::broadcast_address);
  const seawire::result<std::uint32_t> made = n2k::make_can_id(f);
  SEAWIRE_FUZZ_CHECK(made.ok() == valid, "make_can_id took or refused the wrong fields",
                     fields_of(f), name(made.ec));
  if (!made) {
    SEAWIRE_FUZZ_CHECK(made.ec == errc::bad_can_id, fields_of(f), name(made.ec));
    return;
  }
  SEAWIRE_FUZZ_CHECK(made.value <= 0x1FFFFFFFU, "make_can_id wrote above 29 bits", fields_of(f),
                     hex32(made.value));
  const seawire::result<n2k::can_id> back = n2k::parse_can_id(made.value);
  SEAWIRE_FUZZ_CHECK(back.ok() && back.value == f, "parse_can_id(make_can_id(f)) != f",
                     fields_of(f), hex32(made.value), fields_of(back.value));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> input(data, size);
  // Every id the input spells (the last one padded with zero bytes), so one run tries several.
  std::size_t at = 0;
  do {
    byte_source src(input.subspan(at));
    check_parse(src.integer<std::uint32_t>());
    at += 4;
  } while (at < size);

  // Fields from the bytes: mostly near what frames carry (PGNs of both PDU kinds, priority 0-7,
  // destination 255), so both the refusals and the successes are reached.
  byte_source src(input);
  n2k::can_id f;
  f.priority = src.coin() ? static_cast<std::uint8_t>(src.byte() & 7U) : src.byte();
  const auto pgn = src.integer<std::uint32_t>();
  const std::uint32_t page = (pgn >> 16) & 3U;
  const std::uint32_t pf = (pgn >> 8) & 0xFFU;
  switch (src.byte() % 4) {
    case 0: f.pgn = pgn; break;                           // anything, 19 bits and more included
    case 1: f.pgn = pgn & n2k::max_pgn; break;            // any 18-bit PGN
    case 2: f.pgn = page << 16 | (pf % 240) << 8; break;  // PDU1, low byte 0
    default: f.pgn = page << 16 | (240 + pf % 16) << 8 | (pgn & 0xFFU); break;  // PDU2
  }
  f.source = src.byte();
  f.destination = src.coin() ? n2k::broadcast_address : src.byte();
  check_make(f);
  return 0;
}

}  // namespace seawire::fuzz
