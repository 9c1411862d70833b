// SPDX-License-Identifier: BSL-1.0
#pragma once
// The 29-bit CAN identifier of an NMEA 2000 frame (ISO 11783 / J1939): priority (3 bits, 0 most
// urgent), EDP, DP, PDU format, PDU specific, source. PF >= 240: PDU2, PS part of the PGN; else
// PDU1, PS the destination (255 = all). Bit 31 (SocketCAN's CAN_EFF_FLAG) is not part of it.

#include <cstdint>

#include "seawire/error.hpp"

namespace seawire::nmea2000 {

inline constexpr std::uint8_t broadcast_address = 255;  ///< destination "every device"
inline constexpr std::uint8_t null_address = 254;       ///< source of a device without an address
inline constexpr std::uint32_t max_pgn = 0x3FFFF;       ///< 18 bits

/// Whether frames of `pgn` are addressed (PDU1: PDU format below 240).
[[nodiscard]] constexpr bool is_addressed(std::uint32_t pgn) noexcept {
  return ((pgn >> 8) & 0xFF) < 240;
}

/// The fields of a CAN identifier.
struct can_id {
  std::uint8_t priority = 6;
  std::uint32_t pgn = 0;
  std::uint8_t source = 0;
  std::uint8_t destination = broadcast_address;  ///< always 255 for a broadcast (PDU2) PGN

  [[nodiscard]] constexpr bool operator==(const can_id&) const noexcept = default;
};

/// The fields of the 29-bit identifier `id`. bad_can_id when `id` has bits above bit 28.
[[nodiscard]] constexpr result<can_id> parse_can_id(std::uint32_t id) noexcept {
  result<can_id> r;
  if (id > 0x1FFFFFFF) {
    r.ec = errc::bad_can_id;
    return r;
  }
  const auto pf = static_cast<std::uint8_t>((id >> 16) & 0xFF);
  const auto ps = static_cast<std::uint8_t>((id >> 8) & 0xFF);
  r.value.priority = static_cast<std::uint8_t>((id >> 26) & 0x7);
  r.value.source = static_cast<std::uint8_t>(id & 0xFF);
  const std::uint32_t page = (id >> 24) & 0x3;  // EDP and DP
  if (pf < 240) {
    r.value.pgn = page << 16 | std::uint32_t{pf} << 8;
    r.value.destination = ps;
  } else {
    r.value.pgn = page << 16 | std::uint32_t{pf} << 8 | ps;
    r.value.destination = broadcast_address;
  }
  return r;
}

/// The 29-bit identifier of `f`. bad_can_id for a priority above 7, a PGN above 18 bits, an
/// addressed (PDU1) PGN whose low byte is not 0, or a broadcast (PDU2) PGN sent to one address.
[[nodiscard]] constexpr result<std::uint32_t> make_can_id(const can_id& f) noexcept {
  result<std::uint32_t> r;
  if (f.priority > 7 || f.pgn > max_pgn) {
    r.ec = errc::bad_can_id;
    return r;
  }
  std::uint32_t id = std::uint32_t{f.priority} << 26 | f.pgn << 8 | f.source;
  if (is_addressed(f.pgn)) {
    if ((f.pgn & 0xFF) != 0) {
      r.ec = errc::bad_can_id;
      return r;
    }
    id |= std::uint32_t{f.destination} << 8;
  } else if (f.destination != broadcast_address) {
    r.ec = errc::bad_can_id;
    return r;
  }
  r.value = id;
  return r;
}

}  // namespace seawire::nmea2000
