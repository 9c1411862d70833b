// SPDX-License-Identifier: BSL-1.0
#pragma once
// Which NMEA 2000 PGNs travel as fast packets (fast_packet.hpp), whether seawire declares them or
// not, so that a reader can assemble a PGN it has no description of and hand on one whole
// payload rather than its frames. The rule, in order:
//  - 0x1EF00-0x1EFFF (126720-126975, manufacturer proprietary, addressed) and 0x1FF00-0x1FFFF
//    (130816-131071, manufacturer proprietary, broadcast): fast packets, every PGN of them. The
//    standard reserves these two ranges for proprietary fast packets, and every proprietary PGN
//    canboat describes there is one.
//  - 0x1ED00-0x1FEFF (126208-130815): fast packets for the standard PGNs of
//    standard_fast_packet_pgns, the PGNs canboat's database marks "Fast" (126208 group
//    functions, 126464 PGN lists, 126996 product information, 129029 GNSS position, 129540
//    satellites in view, the AIS and route/waypoint PGNs, ...). Any other PGN there is read as
//    single frames. The standard lets 0x1F000-0x1FEFF hold either framing (canboat calls the
//    range "mixed"), so a PGN nobody has described there may be either; reading its frames one
//    by one loses nothing (each is handed on as it came), whereas assembling single frames would
//    take their first byte for a frame counter and drop or merge them.
//  - below 0x10000 (59392-65535: ISO and the proprietary single-frame ranges 61184 0xEF00 and
//    65280-65535 0xFF00-0xFFFF) and above 0x1FFFF: single frames (an ISO 11783 message longer
//    than 8 bytes goes by the ISO transport protocol, not as a fast packet).
// No PGN canboat describes has both a single-frame and a fast-packet variant: its proprietary
// PGNs of one manufacturer share the framing of their range. Lookup: a binary search of the
// sorted table, O(log n), constexpr.

#include <array>
#include <cstdint>

#include "seawire/detail/algorithm.hpp"

namespace seawire::nmea2000 {

/// The standard PGNs (outside the two proprietary fast-packet ranges) that travel as fast
/// packets, sorted: those canboat's database marks "Fast".
inline constexpr std::array<std::uint32_t, 123> standard_fast_packet_pgns = {
    126208, 126464, 126983, 126984, 126985, 126986, 126987, 126988, 126996, 126998, 127233, 127237,
    127489, 127490, 127491, 127494, 127495, 127496, 127497, 127498, 127503, 127504, 127506, 127507,
    127509, 127510, 127511, 127512, 127513, 127514, 128275, 128520, 128538, 129029, 129038, 129039,
    129040, 129041, 129044, 129045, 129284, 129285, 129301, 129302, 129538, 129540, 129541, 129542,
    129545, 129547, 129549, 129551, 129556, 129792, 129793, 129794, 129795, 129796, 129797, 129798,
    129799, 129800, 129801, 129802, 129803, 129804, 129805, 129806, 129807, 129808, 129809, 129810,
    129811, 129812, 129813, 129814, 129815, 129816, 130052, 130053, 130054, 130060, 130061, 130064,
    130065, 130066, 130067, 130068, 130069, 130070, 130071, 130072, 130073, 130074, 130320, 130321,
    130322, 130323, 130324, 130329, 130330, 130561, 130562, 130563, 130564, 130565, 130566, 130567,
    130568, 130569, 130570, 130571, 130572, 130573, 130574, 130575, 130577, 130578, 130580, 130581,
    130583, 130584, 130586,
};
static_assert(std::is_sorted(standard_fast_packet_pgns.begin(), standard_fast_packet_pgns.end()) &&
                  std::adjacent_find(standard_fast_packet_pgns.begin(),
                                     standard_fast_packet_pgns.end()) ==
                      standard_fast_packet_pgns.end(),
              "the table is searched by halves: sorted, without repeats");

/// The manufacturer proprietary fast-packet ranges, first and last PGN.
inline constexpr std::uint32_t proprietary_fast_addressed_first = 0x1EF00;  ///< 126720
inline constexpr std::uint32_t proprietary_fast_addressed_last = 0x1EFFF;   ///< 126975
inline constexpr std::uint32_t proprietary_fast_broadcast_first = 0x1FF00;  ///< 130816
inline constexpr std::uint32_t proprietary_fast_broadcast_last = 0x1FFFF;   ///< 131071

/// Whether frames of `pgn` are fast-packet frames, by the rule at the top of this file.
[[nodiscard]] constexpr bool is_fast_packet_pgn(std::uint32_t pgn) noexcept {
  if (pgn >= proprietary_fast_addressed_first && pgn <= proprietary_fast_addressed_last)
    return true;
  if (pgn >= proprietary_fast_broadcast_first && pgn <= proprietary_fast_broadcast_last)
    return true;
  return std::binary_search(standard_fast_packet_pgns.begin(), standard_fast_packet_pgns.end(),
                            pgn);
}

}  // namespace seawire::nmea2000
