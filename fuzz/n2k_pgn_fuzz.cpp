// SPDX-License-Identifier: BSL-1.0
// Every NMEA 2000 PGN of registry::pgns: the first byte picks one, the rest is its payload
// (of any length: short, exact or longer than the PGN). Then a message of that PGN built from
// the same bytes with raw values of any width.
// Properties:
//  - decode -> encode -> decode is the identity: encode accepts whatever decode produced (every
//    raw value fits its field) and writes a payload that decodes to the same message;
//  - encode writes every reserved bit as one and every spare bit as zero (of the bytes it writes:
//    a flag word not sent ends the payload, see encode);
//  - encode keeps the bits the sender sent: each field the payload holds in full comes out bit
//    for bit (so a payload of the PGN's length or longer comes back as its first `length` bytes
//    with the reserved bits set);
//  - encode of a message with raw values from_raw() put there refuses, with value_too_large and
//    the row number of the first field in table order, exactly when some field does not fit.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>

#include "fuzz_common.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/registry.hpp"

namespace seawire::fuzz {
namespace {

namespace n2k = nmea2000;

template <n2k::pgn_like P>
void check_payload(std::span<const std::uint8_t> payload) {
  const std::string pgn = number(P::n2k.info.pgn);
  const P m = n2k::decode<P>(payload);
  const auto e = n2k::encode(m);
  SEAWIRE_FUZZ_CHECK(e.ok(), "encode refused what decode produced", pgn, hex_of(payload),
                     name(e.ec), number(e.field));
  const std::span<const std::uint8_t> out = e.value.view();
  SEAWIRE_FUZZ_CHECK(n2k::decode<P>(out) == m, "decode -> encode -> decode changed the message",
                     pgn, hex_of(payload), hex_of(out));

  P::n2k.for_each([&](const auto& f, unsigned offset, std::uint16_t row) {
    using F = std::remove_cvref_t<decltype(f)>;
    if (offset + F::bits > out.size() * 8) return;  // past a flag word not sent: left out
    const std::uint64_t ones = (std::uint64_t{1} << F::bits) - 1;
    const std::uint64_t written =
        seawire::detail::get_bits<n2k::payload_order>(out, offset, F::bits);
    if constexpr (requires { F::sent_as_zero; }) {
      SEAWIRE_FUZZ_CHECK(written == 0, "a spare bit was written as one", pgn, hex_of(payload),
                         hex_of(out), number(row));
    } else if constexpr (F::is_reserved) {
      SEAWIRE_FUZZ_CHECK(written == ones, "a reserved bit was written as zero", pgn,
                         hex_of(payload), hex_of(out), number(row));
    } else if (offset + F::bits <= payload.size() * 8) {
      SEAWIRE_FUZZ_CHECK(
          written == seawire::detail::get_bits<n2k::payload_order>(payload, offset, F::bits),
          "a field's bits changed on the way through", pgn, hex_of(payload), hex_of(out), f.name);
    }
  });
}

/// A raw value for a field of `bits` bits: mostly one it holds (sentinels and the signed edges
/// included), sometimes one it cannot, which encode must refuse.
std::int64_t make_raw(byte_source& src, unsigned bits, bool is_signed) {
  const std::int64_t top =
      is_signed ? (std::int64_t{1} << (bits - 1)) - 1 : (std::int64_t{1} << bits) - 1;
  const std::int64_t low = is_signed ? -(std::int64_t{1} << (bits - 1)) : 0;
  const auto wide = src.integer<std::uint64_t>();
  switch (src.byte() % 8) {
    case 0: return top - static_cast<std::int64_t>(wide % 4);  // the sentinels and below
    case 1: return low;
    case 2: return top + 1;  // one past
    case 3: return low - 1;  // one under
    case 4: return static_cast<std::int64_t>(wide);
    default: {
      // in range: [low, top]
      const auto span = static_cast<std::uint64_t>(top - low) + 1;
      return low + static_cast<std::int64_t>(wide % span);
    }
  }
}

template <n2k::pgn_like P>
void check_built(byte_source& src) {
  const std::string pgn = number(P::n2k.info.pgn);
  P m{};
  std::uint16_t first_bad = 0;
  P::n2k.for_each([&](const auto& f, unsigned, std::uint16_t row) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (!F::is_reserved) {
      using V = typename F::value_type;
      const V v = V::from_raw(make_raw(src, F::bits, V::is_signed));
      m.*F::member = v;
      if (!v.fits() && first_bad == 0) first_bad = row;
    }
  });
  const auto e = n2k::encode(m);
  if (first_bad != 0) {
    SEAWIRE_FUZZ_CHECK(!e && e.ec == errc::value_too_large && e.field == first_bad,
                       "encode did not refuse the first field that does not fit", pgn, name(e.ec),
                       number(e.field), number(first_bad));
    return;
  }
  SEAWIRE_FUZZ_CHECK(e.ok(), "encode refused fields that fit", pgn, name(e.ec), number(e.field));
  SEAWIRE_FUZZ_CHECK(n2k::decode<P>(e.value) == m, "encode -> decode changed a built message", pgn,
                     hex_of(e.value));
}

template <n2k::pgn_like P>
void check(std::span<const std::uint8_t> payload) {
  check_payload<P>(payload);
  byte_source src(payload);
  check_built<P>(src);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::span<const std::uint8_t> payload(data + 1, size - 1);
  registry::visit_type<registry::pgns>(data[0] % registry::pgns::size, [&](auto tag) {
    check<typename decltype(tag)::type>(payload);
  });
  return 0;
}

}  // namespace seawire::fuzz
