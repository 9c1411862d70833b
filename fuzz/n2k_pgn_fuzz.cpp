// SPDX-License-Identifier: BSL-1.0
// Every NMEA 2000 PGN of registry::pgns: the first byte picks one, the rest is its payload
// (of any length: short, exact or longer than the PGN). Then a message of that PGN built from
// the same bytes with raw values of any width.
// Properties:
//  - decode -> encode -> decode is the identity: encode accepts whatever decode produced (every
//    raw value fits its field) and writes a payload that decodes to the same message;
//  - encode writes every reserved bit as one and every spare bit as zero (of the bytes it
//    writes: a flag word not sent ends the payload, see encode);
//  - encode keeps the bits the sender sent: each field the payload holds in full comes out bit
//    for bit (so a payload of the PGN's length or longer comes back as its first `length` bytes
//    with the reserved bits set);
//  - encode of a message with raw values from_raw() put there refuses, with value_too_large and
//    the row number of the first field in table order, exactly when some field does not fit;
//  - strings (126996, 126998, the AIS PGNs): a fixed string's bytes come out as sent; counted
//    strings (126998) are read at running offsets, never past the payload, and a message built
//    from strings of any bytes encodes unless they make the payload longer than a fast packet
//    (text_too_long at the first string past it that holds a text; those without are left out).
// A repeating group (the last row of its table): decode -> encode -> decode is the identity
// unless the count field says more repetitions than the group's capacity, which encode refuses
// (out_of_range, the count's row); each repetition decode held comes out bit for bit where the
// payload held its fields in full; a built message's group is filled from the same bytes.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
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

/// Whether decode left a count field saying more than its group's capacity (encode refuses it).
template <n2k::pgn_like P>
bool count_over_capacity(const P& m) {
  bool over = false;
  seawire::nmea2000::pgn_table<P>.for_each([&](const auto& f, unsigned, std::uint16_t) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (n2k::detail::group_row<F>) {
      if constexpr (F::counted) {
        const auto& c = m.*F::count;
        over = c.has_value() && static_cast<std::uint64_t>(c.raw()) > F::value_type::capacity;
      }
    }
  });
  return over;
}

/// Each field of each repetition the payload held in full comes out bit for bit.
template <class F>
void check_group_bits(const std::string& pgn, std::span<const std::uint8_t> payload,
                      std::span<const std::uint8_t> out, unsigned offset, std::size_t held) {
  using Item = typename F::value_type::item_type;
  SEAWIRE_FUZZ_CHECK(out.size() == (offset + held * F::item_bits + 7) / 8,
                     "the payload does not end after the last repetition", pgn, hex_of(payload),
                     hex_of(out));
  for (std::size_t i = 0; i < held; ++i) {
    const unsigned at = offset + static_cast<unsigned>(i) * F::item_bits;
    Item::n2k_item.for_each([&](const auto& e, unsigned o, std::uint16_t) {
      using R = std::remove_cvref_t<decltype(e)>;
      const std::uint64_t written =
          seawire::detail::get_bits<n2k::payload_order>(out, at + o, R::bits);
      if constexpr (R::is_reserved) {
        SEAWIRE_FUZZ_CHECK(written == (std::uint64_t{1} << R::bits) - 1,
                           "a reserved bit of a repetition was written as zero", pgn,
                           hex_of(payload), hex_of(out));
      } else if (at + o + R::bits <= payload.size() * 8) {
        SEAWIRE_FUZZ_CHECK(
            written == seawire::detail::get_bits<n2k::payload_order>(payload, at + o, R::bits),
            "a repetition's field changed on the way through", pgn, hex_of(payload), hex_of(out),
            e.name);
      }
    });
  }
}

template <n2k::pgn_like P>
void check_payload(std::span<const std::uint8_t> payload) {
  const std::string pgn = number(seawire::nmea2000::pgn_table<P>.info.pgn);
  const P m = n2k::decode<P>(payload);
  const auto e = n2k::encode(m);
  if (!n2k::layout_matches<P>(payload)) {
    // another layout of the PGN (another function code): decoded as asked, never sent as this
    SEAWIRE_FUZZ_CHECK(!e && e.ec == errc::wrong_address,
                       "encode did not refuse a message of another layout", pgn, hex_of(payload),
                       name(e.ec));
    return;
  }
  if (count_over_capacity(m)) {
    SEAWIRE_FUZZ_CHECK(!e && e.ec == errc::out_of_range,
                       "encode did not refuse a count over the group's capacity", pgn,
                       hex_of(payload), name(e.ec));
    return;
  }
  SEAWIRE_FUZZ_CHECK(e.ok(), "encode refused what decode produced", pgn, hex_of(payload),
                     name(e.ec), number(e.field));
  const std::span<const std::uint8_t> out = e.value.view();
  SEAWIRE_FUZZ_CHECK(n2k::decode<P>(out) == m, "decode -> encode -> decode changed the message",
                     pgn, hex_of(payload), hex_of(out));

  if constexpr (!n2k::description_of<P>::fixed_layout) return;  // offsets vary: the identity above
  seawire::nmea2000::pgn_table<P>.for_each([&](const auto& f, unsigned offset, std::uint16_t row) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (n2k::detail::group_row<F>) {
      check_group_bits<F>(pgn, payload, out, offset, (m.*F::member).size());
      return;
    } else if constexpr (n2k::detail::bytes_row<F>) {
      // the bytes after the fixed rows, as sent (up to the capacity), and the payload ends there
      const std::size_t at = std::min<std::size_t>(offset / 8, payload.size());
      const std::size_t n = std::min(F::value_type::capacity, payload.size() - at);
      SEAWIRE_FUZZ_CHECK(out.size() == offset / 8 + n,
                         "the payload does not end after the opaque bytes", pgn, hex_of(payload),
                         hex_of(out));
      for (std::size_t i = 0; i < n; ++i)
        SEAWIRE_FUZZ_CHECK(out[offset / 8 + i] == payload[at + i],
                           "an opaque byte changed on the way through", pgn, hex_of(payload),
                           hex_of(out));
      return;
    }
    if (offset + F::bits > out.size() * 8) return;  // past a flag word not sent: left out
    if constexpr (n2k::detail::row_is_text<F>()) {
      // The bytes sent, 0xFF for those the payload did not reach
      for (std::size_t i = 0; i < F::bits / 8; ++i) {
        const std::size_t at = offset / 8 + i;
        SEAWIRE_FUZZ_CHECK(out[at] == (at < payload.size() ? payload[at] : 0xFF),
                           "a string's bytes changed on the way through", pgn, hex_of(payload),
                           hex_of(out), f.name);
      }
      return;
    } else {
      const std::uint64_t ones =
          F::bits == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << F::bits) - 1;
      const std::uint64_t written =
          seawire::detail::get_bits<n2k::payload_order>(out, offset, F::bits);
      if constexpr (requires { F::is_spare; }) {
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
    }
  });
}

/// A raw value for a field of `bits` bits: mostly one it holds (sentinels and the signed edges
/// included), sometimes one it cannot, which encode must refuse.
std::int64_t make_raw(byte_source& src, std::int64_t top, bool is_signed) {
  const std::int64_t low = is_signed ? -top - 1 : 0;
  const auto wide = src.integer<std::uint64_t>();
  switch (src.byte() % 8) {
    case 0: return top - static_cast<std::int64_t>(wide % 4);  // the sentinels and below
    case 1: return low;
    case 2:  // one past (a 64-bit field has no raw value past its top)
      return top == std::numeric_limits<std::int64_t>::max() ? top : top + 1;
    case 3:  // one under
      return low == std::numeric_limits<std::int64_t>::min() ? low : low - 1;
    case 4: return static_cast<std::int64_t>(wide);
    default: {
      // in range: [low, top] (all of int64_t for a signed 64-bit field: span 0, any value)
      const std::uint64_t span =
          static_cast<std::uint64_t>(top) - static_cast<std::uint64_t>(low) + 1;
      return static_cast<std::int64_t>(static_cast<std::uint64_t>(low) +
                                       (span == 0 ? wide : wide % span));
    }
  }
}

template <n2k::pgn_like P>
void check_built(byte_source& src) {
  const std::string pgn = number(seawire::nmea2000::pgn_table<P>.info.pgn);
  P m{};
  std::uint16_t first_bad = 0;  // a fixed row's field that does not fit
  std::uint16_t group_bad = 0;  // a repetition's field that does not fit: the group's row
  std::uint16_t first_too_long = 0;
  std::uint16_t odd_group = 0;  // a group of sub-byte repetitions that does not fill its byte
  P left_out{};                 // m as a receiver reads it back: filled in below
  std::size_t length = 0;       // bits, counted strings as they are
  seawire::nmea2000::pgn_table<P>.for_each([&](const auto& f, unsigned, std::uint16_t row) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (n2k::detail::row_is_text<F>()) {
      using V = typename F::value_type;
      std::array<std::uint8_t, V::capacity> b{};
      const std::string_view chosen = src.bytes(V::capacity);
      std::copy(chosen.begin(), chosen.end(), b.begin());
      if constexpr (V::variable) {
        const std::uint8_t control = src.byte();
        m.*F::member =
            V::from_bytes(control, std::span<const std::uint8_t>(b.data(), chosen.size())).value;
        length += 8 * (chosen.size() + 2);
      } else {
        m.*F::member = V::from_bytes(b);
        length += F::bits;
      }
      // Past a fast packet, a string that is not available is left out with the rest (read
      // back as the default string); one with a value is refused.
      if (length > 8 * n2k::description_of<P>::length && (m.*F::member).has_value() &&
          first_too_long == 0)
        first_too_long = row;
    } else if constexpr (n2k::detail::group_row<F>) {
      // as many repetitions as the next byte says, at most the count when it is a value (none
      // when the count is past the capacity)
      using G = typename F::value_type;
      using Item = typename G::item_type;
      std::size_t n = src.byte() % (G::capacity + 1);
      if constexpr (F::counted) {
        const auto& c = m.*F::count;
        if (c.has_value()) n = std::min(n, static_cast<std::size_t>(c.raw()));
        // repetitions of less than a byte the count does not say exactly fill the last byte
        const bool exact = c.has_value() && static_cast<std::size_t>(c.raw()) == n;
        if (!exact && (n * F::item_bits) % 8 != 0) odd_group = row;
      }
      auto& g = m.*F::member;
      g.clear();
      for (std::size_t i = 0; i < n; ++i) {
        Item item{};
        Item::n2k_item.for_each([&](const auto& e, unsigned, std::uint16_t) {
          using R = std::remove_cvref_t<decltype(e)>;
          if constexpr (!R::is_reserved) {
            using V = typename R::value_type;
            const V v = V::from_raw(make_raw(src, V::top_raw, V::is_signed));
            item.*R::member = v;
            if (!v.fits() && group_bad == 0) group_bad = row;
          }
        });
        (void)g.push_back(item);
      }
    } else if constexpr (n2k::detail::bytes_row<F>) {
      using B = typename F::value_type;
      const std::string_view chosen = src.bytes(B::capacity);
      m.*F::member =
          B::from_bytes(std::span<const std::uint8_t>(
                            reinterpret_cast<const std::uint8_t*>(chosen.data()), chosen.size()))
              .value;
    } else if constexpr (F::is_reserved || n2k::detail::match_row<F>) {
      length += F::bits;  // a match row keeps the struct's own layout
    } else {
      length += F::bits;
      using V = typename F::value_type;
      const V v = V::from_raw(make_raw(src, V::top_raw, V::is_signed));
      m.*F::member = v;
      if (!v.fits() && first_bad == 0) first_bad = row;
    }
  });
  if constexpr (!n2k::description_of<P>::fixed_layout) {
    // Copy the strings that fit; those past the cut stay default.
    std::size_t bits = 0;
    seawire::nmea2000::pgn_table<P>.for_each([&](const auto& f, unsigned, std::uint16_t) {
      using F = std::remove_cvref_t<decltype(f)>;
      if constexpr (F::is_reserved) {
        bits += F::bits;
      } else {
        if constexpr (n2k::detail::row_is_variable<F>()) {
          bits += 8 * (m.*F::member).wire_size();
        } else {
          bits += F::bits;
        }
        if (bits <= 8 * n2k::description_of<P>::length) left_out.*F::member = m.*F::member;
      }
    });
  } else {
    left_out = m;
  }
  // encode checks the fixed rows in order, then a group's count against its capacity, then the
  // repetitions
  const bool over = count_over_capacity(m);
  if (first_bad == 0 && !over) first_bad = group_bad;
  const auto e = n2k::encode(m);
  if (over && first_bad == 0) {
    SEAWIRE_FUZZ_CHECK(!e && e.ec == errc::out_of_range,
                       "encode did not refuse a count over the group's capacity", pgn, name(e.ec));
    return;
  }
  if constexpr (!n2k::description_of<P>::fixed_layout) {
    if (first_too_long != 0 && first_bad == 0) {
      SEAWIRE_FUZZ_CHECK(!e && e.ec == errc::text_too_long && e.field == first_too_long,
                         "encode did not refuse the first string past a fast packet", pgn,
                         name(e.ec), number(e.field), number(first_too_long));
      return;
    }
  }
  if (first_bad != 0) {
    SEAWIRE_FUZZ_CHECK(!e && e.ec == errc::value_too_large && e.field == first_bad,
                       "encode did not refuse the first field that does not fit", pgn, name(e.ec),
                       number(e.field), number(first_bad));
    return;
  }
  if (odd_group != 0) {
    SEAWIRE_FUZZ_CHECK(!e && e.ec == errc::bad_length && e.field == odd_group,
                       "encode did not refuse sub-byte repetitions that no count counts and "
                       "that do not fill their byte",
                       pgn, name(e.ec), number(e.field));
    return;
  }
  SEAWIRE_FUZZ_CHECK(e.ok(), "encode refused fields that fit", pgn, name(e.ec), number(e.field));
  SEAWIRE_FUZZ_CHECK(n2k::decode<P>(e.value) == left_out,
                     "encode -> decode changed a built message", pgn, hex_of(e.value));
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
