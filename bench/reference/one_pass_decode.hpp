// SPDX-License-Identifier: BSL-1.0
// A contender of the benchmark, not part of the library: the floor a decoder generated from
// seawire's descriptions is held to (bench/README.md, "The one-pass reference").
// Hand-written, straight-line RMC/GGA decoder: what a one-pass design can reach.
//
// Same output types as seawire (standard::rmc / standard::gga, so the same reading code and the
// same comparison), same rules as seawire's default parse_policy as read from its headers:
//   - '$', address [A-Z][A-Z0-9]{RMC|GGA} (not 'P'), CR/LF stripped, at most 1024 bytes,
//     "*hh" checked (either case) against the XOR of the body; no '*': checksum absent, then
//     fields missing at the end are too_few_fields instead of blank (absent_as_blank);
//   - every byte of the body printable and no '$' or '*' (checked by the field parsers
//     themselves: a byte no parser accepts is an error; skipped and extra fields are scanned);
//   - every field typed and range-checked exactly as seawire's codecs do (decimal mantissa,
//     places, sign, zero-padding width; DDMM.m positions with degree digits; time with 0-9
//     fraction digits and leap second only at 23:59:60; ddmmyy 1980-2079 with days per month;
//     magnetic variation with its "nothing" cases; mode / nav status may be absent with the
//     wire_fields bookkeeping; GGA's unit letters; integers' type ranges; dgps station 0-1023).
// One pass over the fields: each parser reads its bytes and stops at ',' or at the end of the
// body, where the '*' (a byte no parser accepts) is the sentinel, so no digit loop tests a
// length. No split, no offsets array. The checksum is an XOR of 8-byte words.
// Namespace hw by default; HW_NS / HW_SWAR select ablations
// (HW_SWAR 0 = every number bytewise, 1 = 8 bytes at a time for positions and hhmmss/ddmmyy
// only (default), 2 = for every decimal too).
#pragma once
// Its field parsers are lambdas whose cursor parameter has the name of the caller's.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#ifndef HW_NS
#define HW_NS hw
#endif
#ifndef HW_SWAR
#define HW_SWAR 1
#endif

#include <seawire/standard/gga.hpp>
#include <seawire/standard/rmc.hpp>

#include <cstdint>
#include <cstring>
#include <string_view>

namespace HW_NS {

namespace sws = seawire::standard;
namespace swn = seawire::nmea;

#ifndef HW_INLINE
#define HW_INLINE inline __attribute__((always_inline))
#define HW_LIKELY(x) __builtin_expect(!!(x), 1)
#define HW_UNLIKELY(x) __builtin_expect(!!(x), 0)
#endif

inline constexpr std::uint64_t p10[20] = {1ull,
                                          10ull,
                                          100ull,
                                          1000ull,
                                          10000ull,
                                          100000ull,
                                          1000000ull,
                                          10000000ull,
                                          100000000ull,
                                          1000000000ull,
                                          10000000000ull,
                                          100000000000ull,
                                          1000000000000ull,
                                          10000000000000ull,
                                          100000000000000ull,
                                          1000000000000000ull,
                                          10000000000000000ull,
                                          100000000000000000ull,
                                          1000000000000000000ull,
                                          10000000000000000000ull};

struct out {
  enum kind : std::uint8_t { none, rmc, gga } k = none;
  sws::rmc r;
  sws::gga g;
};

HW_INLINE unsigned dig(char c) {
  return static_cast<unsigned>(static_cast<unsigned char>(c)) - 48u;
}
HW_INLINE std::uint64_t load64(const char* p) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  return v;
}

// The run of digits at q onto m; q past it. Ends at the first non-digit: at the latest the
// '*' (or sentinel) at the end of the body.
HW_INLINE std::uint64_t run(const char*& q, std::uint64_t m) {
  unsigned d;
  while ((d = dig(*q)) < 10) {
    m = m * 10 + d;
    ++q;
  }
  return m;
}

// The end of a field: ',' (another follows) or the end of the body (it was the last; q then
// points past the body, e + 1, which every field takes as "not present"). Either way one byte.
HW_INLINE bool finish(const char*& q, const char* e) {
  const bool ok = (*q == ',') | (q == e);
  ++q;
  return ok;
}
HW_INLINE bool blank(const char* q, const char* e) { return *q == ',' || q == e; }

// Past one field without reading it, checking its bytes as parse() would (printable, no '$'
// or '*'). q <= e.
inline bool skip(const char*& q, const char* e) {
  while (q != e && *q != ',') {
    const unsigned char c = static_cast<unsigned char>(*q);
    if (c < 0x20 || c > 0x7E || c == '$' || c == '*') return false;
    ++q;
  }
  ++q;
  return true;
}

// Decimal, the general way (more than 19 digits: leading zeros do not count), as seawire's
// parse_decimal_long. [ib, fe) the text after the sign.
__attribute__((noinline)) inline bool dec_long(const char* ib, const char* fe, bool neg,
                                               swn::decimal& d) {
  std::uint64_t m = 0;
  unsigned sig = 0, places = 0, iw = 0;
  bool point = false, any = false;
  for (const char* s = ib; s != fe; ++s) {
    const char c = *s;
    if (c >= '0' && c <= '9') {
      any = true;
      if (point)
        ++places;
      else
        ++iw;
      if (m != 0 || c != '0') {
        if (++sig > 19) return false;
        m = m * 10 + static_cast<std::uint64_t>(c - '0');
      }
    } else if (c == '.' && !point) {
      point = true;
    } else {
      return false;
    }
  }
  if (!any || places > 19) return false;
  d.mantissa = m;
  d.places = static_cast<std::uint8_t>(places);
  d.negative = neg;
  std::uint64_t whole = m / p10[places];
  unsigned natural = 1;
  while (whole >= 10) {
    whole /= 10;
    ++natural;
  }
  d.int_width = static_cast<std::uint8_t>(iw > natural && iw <= 20 ? iw : 0);
  return true;
}

// ---- eight bytes at a time ----------------------------------------------------------------
// 0x80 in each byte of w that is not an ASCII digit.
HW_INLINE std::uint64_t nondigit(std::uint64_t w) {
  const std::uint64_t x = w ^ 0x3030303030303030ull;  // a digit becomes 0..9
  const std::uint64_t t = (x & 0x7F7F7F7F7F7F7F7Full) + 0x7676767676767676ull;  // bit 7: >= 10
  return (t | x) & 0x8080808080808080ull;
}
// The number the first k (1..8) digit values of x spell (x: bytes 0..9, first byte first).
HW_INLINE std::uint64_t swar_value(std::uint64_t x, unsigned k) {
  x <<= 8 * (8 - k);  // the k digits to the top: leading zeros below
  x = (x * 10 + (x >> 8)) & 0x00FF00FF00FF00FFull;
  x = (x * 100 + (x >> 16)) & 0x0000FFFF0000FFFFull;
  return (x * 10000 + (x >> 32)) & 0xFFFFFFFFull;
}
HW_INLINE unsigned byte_at(std::uint64_t w, unsigned i) {
  return static_cast<unsigned>(w >> (8 * i)) & 0xFF;
}

// ---- field parsers: each returns where the next field starts (past its ',', or e + 1 after
// the last field), or nullptr if the field is not one it reads (the caller then looks whether
// it was blank: blank fields cost nothing on the common path).

// [sign] digits [. digits], the field's whole text.
template <bool Signed = true>
HW_INLINE const char* dec(const char* q, const char* e, swn::decimal& d) {
  bool neg = false;
  if constexpr (HW_SWAR >= 2) {
    // [digits][.digits] within the eight bytes at q, then ',' or the end of the body.
    if (HW_LIKELY(e - q >= 5)) {
      const std::uint64_t w = load64(q);
      const std::uint64_t nd = nondigit(w);
      const unsigned i1 = static_cast<unsigned>(__builtin_ctzll(nd | (1ull << 63))) >> 3;
      const std::uint64_t x = w ^ 0x3030303030303030ull;
      unsigned end = i1, k = i1, pl = 0;
      std::uint64_t digits = x;
      if (byte_at(w, i1) == '.') {
        const std::uint64_t nd2 = nd & (nd - 1);
        if (HW_LIKELY(nd2 != 0)) {
          end = static_cast<unsigned>(__builtin_ctzll(nd2)) >> 3;
          pl = end - i1 - 1;
          k = end - 1;
          const std::uint64_t lo = (1ull << (8 * i1)) - 1;  // i1 < 8
          const std::uint64_t hi = k < 8 ? (1ull << (8 * k)) - 1 : ~0ull;
          digits = (x & lo) | ((x >> 8) & hi & ~lo);
        } else {
          end = 8;  // not within the word: bytewise below
        }
      }
      if (HW_LIKELY(end < 8 && k > 0 && nd != 0)) {
        const unsigned t = byte_at(w, end);
        if (HW_UNLIKELY(!((t == ',') | (q + end == e)))) return nullptr;
        d.mantissa = swar_value(digits, k);
        d.places = static_cast<std::uint8_t>(pl);
        d.negative = false;
        d.int_width = static_cast<std::uint8_t>(i1 > 1 && *q == '0' ? i1 : 0);
        return q + end + 1;
      }
    }
  }
  const char* ib = q;
  std::uint64_t m = run(q, 0);
  std::size_t iw = static_cast<std::size_t>(q - ib);
  if (HW_UNLIKELY(iw == 0)) {  // a sign, or no integer digits, or blank
    const char c = *q;
    if (c == '-' || c == '+') {
      if constexpr (!Signed) return nullptr;
      neg = c == '-';
      ib = ++q;
      m = run(q, 0);
      iw = static_cast<std::size_t>(q - ib);
    }
  }
  std::size_t pl = 0;
  if (*q == '.') {
    ++q;
    const char* const fb = q;
    m = run(q, m);
    pl = static_cast<std::size_t>(q - fb);
  }
  if (HW_UNLIKELY(iw + pl - 1 >= 19)) {  // none, or more than 19 digits
    if (iw + pl == 0) return nullptr;
    const char* fe = q;
    while (fe != e && *fe != ',') ++fe;
    if (!dec_long(ib, fe, neg, d)) return nullptr;
    return fe + 1;
  }
  if (HW_UNLIKELY(!((*q == ',') | (q == e)))) return nullptr;
  d.mantissa = m;
  d.places = static_cast<std::uint8_t>(pl);
  d.negative = neg;
  d.int_width = static_cast<std::uint8_t>(iw > 1 && *ib == '0' ? iw : 0);
  return q + 1;
}

HW_INLINE bool not_below_zero(const swn::decimal& d) { return !(d.negative && d.mantissa != 0); }
// d <= hi (hi a whole number below 1000; d not negative)
HW_INLINE bool at_most(const swn::decimal& d, std::uint64_t hi) {
  return d.places > 16 || d.mantissa <= hi * p10[d.places];
}

template <class T>
HW_INLINE const char* whole(const char* q, const char* e, std::uint64_t max, T& v) {
  swn::decimal d;
  q = dec(q, e, d);
  if (!q) return nullptr;
  if (d.places != 0 || (d.negative && d.mantissa != 0) || d.mantissa > max) return nullptr;
  v = static_cast<T>(d.mantissa);
  return q;
}

// Three two-digit numbers from the six digits at q (hhmmss, ddmmyy); false if any is not a
// digit. q[0, 8) readable.
HW_INLINE bool six_digits(const char* q, unsigned& a, unsigned& b, unsigned& c) {
  if constexpr (HW_SWAR == 0) {
    const unsigned d0 = dig(q[0]), d1 = dig(q[1]), d2 = dig(q[2]), d3 = dig(q[3]), d4 = dig(q[4]),
                   d5 = dig(q[5]);
    if (HW_UNLIKELY((d0 > 9) | (d1 > 9) | (d2 > 9) | (d3 > 9) | (d4 > 9) | (d5 > 9))) return false;
    a = d0 * 10 + d1;
    b = d2 * 10 + d3;
    c = d4 * 10 + d5;
    return true;
  }
  const std::uint64_t w = load64(q);
  if (HW_UNLIKELY(nondigit(w) & 0x0000808080808080ull)) return false;
  const std::uint64_t x = w ^ 0x3030303030303030ull;
  const std::uint64_t y = x * 10 + (x >> 8);  // byte 0: first pair, 2: second, 4: third
  a = static_cast<unsigned>(y) & 0xFF;
  b = static_cast<unsigned>(y >> 16) & 0xFF;
  c = static_cast<unsigned>(y >> 32) & 0xFF;
  return true;
}

// hhmmss[.f{1,9}]
HW_INLINE const char* tod(const char* q, const char* e, swn::time_of_day& t) {
  if (HW_UNLIKELY(e - q < 6)) return nullptr;
  unsigned hh, mm, ss;
  if (!six_digits(q, hh, mm, ss)) return nullptr;
  q += 6;
  std::uint64_t frac = 0;
  std::size_t pl = 0;
  if (*q == '.') {
    ++q;
    const char* const fb = q;
    frac = run(q, 0);
    pl = static_cast<std::size_t>(q - fb);
    if (HW_UNLIKELY(pl - 1 >= 9)) return nullptr;
  }
  if (HW_UNLIKELY(!((*q == ',') | (q == e)))) return nullptr;
  if (HW_UNLIKELY(hh > 23 || mm > 59 || ss > 60)) return nullptr;
  if (HW_UNLIKELY(ss == 60 && !(hh == 23 && mm == 59))) return nullptr;
  t.hour = static_cast<std::uint8_t>(hh);
  t.minute = static_cast<std::uint8_t>(mm);
  t.second = static_cast<std::uint8_t>(ss);
  t.fraction = static_cast<std::uint32_t>(frac);
  t.places = static_cast<std::uint8_t>(pl);
  return q + 1;
}

// ddmmyy
HW_INLINE const char* ymd(const char* q, const char* e, swn::date& v) {
  if (HW_UNLIKELY(e - q < 6)) return nullptr;
  unsigned dd, mo, yy;
  if (!six_digits(q, dd, mo, yy)) return nullptr;
  q += 6;
  if (HW_UNLIKELY(!((*q == ',') | (q == e)))) return nullptr;
  const unsigned year = yy < 80 ? 2000 + yy : 1900 + yy;
  if (HW_UNLIKELY(mo - 1 >= 12)) return nullptr;
  static constexpr unsigned char dim[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  unsigned days = dim[mo - 1];
  if (HW_UNLIKELY(mo == 2 && ((year % 4 == 0 && year % 100 != 0) || year % 400 == 0))) days = 29;
  if (HW_UNLIKELY(dd - 1 >= days)) return nullptr;
  v.year = static_cast<std::uint16_t>(year);
  v.month = static_cast<std::uint8_t>(mo);
  v.day = static_cast<std::uint8_t>(dd);
  return q + 1;
}

// DDMM.m,H (two fields). Eight bytes at a time where the body is long enough, else bytewise.
template <unsigned W, unsigned MaxDeg, char Pos, char Neg, class C>
HW_INLINE const char* coord(const char* q, const char* e, C& v) {
  std::uint64_t ddmm, frac = 0;
  std::size_t point, pl = 0;
  const char* f;  // the byte after the number
  if (HW_SWAR >= 1 && HW_LIKELY(e - q >= 11)) {
    const std::uint64_t w1 = load64(q);
    const std::uint64_t nd1 = nondigit(w1);
    point = static_cast<std::size_t>(__builtin_ctzll(nd1 | (1ull << 63))) >> 3;
    if (HW_UNLIKELY(point < 3 || point - 2 > W)) return nullptr;
    ddmm = swar_value(w1 ^ 0x3030303030303030ull, static_cast<unsigned>(point));
    f = q + point;
    if (byte_at(w1, static_cast<unsigned>(point)) == '.') {
      ++f;
      const std::uint64_t w2 = load64(f);
      const std::uint64_t nd2 = nondigit(w2);
      if (HW_LIKELY(nd2 != 0)) {
        pl = static_cast<std::size_t>(__builtin_ctzll(nd2)) >> 3;
        if (pl) frac = swar_value(w2 ^ 0x3030303030303030ull, static_cast<unsigned>(pl));
        f += pl;
      } else {  // eight or more fraction digits
        const char* const fb = f;
        frac = run(f, 0);
        pl = static_cast<std::size_t>(f - fb);
        if (HW_UNLIKELY(pl > 12)) return nullptr;
      }
    }
  } else {
    f = q;
    ddmm = run(f, 0);
    point = static_cast<std::size_t>(f - q);
    if (HW_UNLIKELY(point < 3 || point - 2 > W)) return nullptr;
    if (*f == '.') {
      ++f;
      const char* const fb = f;
      frac = run(f, 0);
      pl = static_cast<std::size_t>(f - fb);
      if (HW_UNLIKELY(pl > 12)) return nullptr;
    }
  }
  if (HW_UNLIKELY(*f != ',')) return nullptr;  // the hemisphere field must follow
  if (HW_UNLIKELY(pl == 0)) pl = 1;            // "4221" reads as 4221.0
  const unsigned dm = static_cast<unsigned>(ddmm);
  const unsigned deg = dm / 100;
  const unsigned wm = dm - deg * 100;
  if (HW_UNLIKELY(wm >= 60)) return nullptr;
  const std::uint64_t mant = wm * p10[pl] + frac;
  if (HW_UNLIKELY(deg > MaxDeg || (deg == MaxDeg && mant != 0))) return nullptr;
  const char h = f[1];  // the '*' at e if the field is missing: not a letter
  if (HW_UNLIKELY(!((h == Pos) | (h == Neg)))) return nullptr;
  if (HW_UNLIKELY(!((f[2] == ',') | (f + 2 == e)))) return nullptr;
  v.whole_degrees = static_cast<std::uint16_t>(deg);
  v.minutes.mantissa = mant;
  v.minutes.places = static_cast<std::uint8_t>(pl);
  v.minutes.negative = false;
  v.minutes.int_width = 0;
  v.hemi = static_cast<swn::hemisphere>(h);
  v.degree_digits = static_cast<std::uint8_t>(point - 2);
  return f + 3;
}

// An optional field: nullopt when absent (allowed only when the checksum vouches for the end)
// or blank, else what `parse` reads. Width 2 (a position): a blank number passes over its
// letter too (its bytes still checked).
template <unsigned Width, class O, class F>
HW_INLINE bool opt(const char*& q, const char* e, bool absent_ok, O& o, F&& parse) {
  if (HW_UNLIKELY(q > e)) {
    o.reset();
    return absent_ok;
  }
  typename O::value_type v;
  if (const char* r = parse(q, v); HW_LIKELY(r != nullptr)) {
    o.emplace(v);
    q = r;
    return true;
  }
  if (!blank(q, e)) return false;
  o.reset();
  ++q;
  if constexpr (Width == 2) {
    if (q <= e) return skip(q, e);
  }
  return true;
}
#ifndef HW_PARSE
#define HW_PARSE(...) \
  [&](const char* q, auto& v) __attribute__((always_inline))->const char* { return __VA_ARGS__; }
#define HW_BODY(...) \
  [&](const char* q, auto& v) __attribute__((always_inline))->const char* __VA_ARGS__
#endif

// A letter enum that may be absent (RMC mode, nav status): wire_fields as seawire keeps it.
template <class E, class L>
HW_INLINE bool opt_letter(const char*& q, const char* e, std::optional<E>& o, std::uint8_t& wire,
                          const char* body, L&& is_letter) {
  if (q > e) {
    o.reset();
    return true;
  }
  const char c = *q;
  if (HW_LIKELY(is_letter(c) && ((q[1] == ',') | (q + 1 == e)))) {
    o = static_cast<E>(c);
    wire = 0;
    q += 2;
    return true;
  }
  if (!blank(q, e)) return false;
  o.reset();
  unsigned fc = 0;  // the sentence's field count: commas before the end of the body
  for (const char* s = body - 1; s != e; ++s) fc += *s == ',';
  wire = static_cast<std::uint8_t>(fc < 255 ? fc : 255);
  ++q;
  return true;
}

// RMC fields 10-11 (magnetic variation), with seawire's "nothing there" cases.
HW_INLINE bool variation(const char*& q, const char* e, bool absent_ok,
                         std::optional<swn::magnetic_variation>& o) {
  if (q > e) {
    o.reset();
    return absent_ok;
  }
  swn::decimal d;
  bool nblank = false;
  if (const char* r = dec<false>(q, e, d); HW_LIKELY(r != nullptr)) {
    q = r;
  } else if (blank(q, e)) {
    nblank = true;
    ++q;
  } else {
    return false;  // bad_variation, whatever the letter
  }
  if (q > e) {  // no letter field: nothing there
    o.reset();
    return true;
  }
  const char c = *q;
  if (HW_LIKELY((c == 'E' || c == 'W') && ((q[1] == ',') | (q + 1 == e)))) {
    swn::magnetic_variation v;
    if (!nblank && at_most(d, 180)) v.value = d;
    v.direction = static_cast<swn::hemisphere>(c);
    o.emplace(v);
    q += 2;
    return true;
  }
  if (blank(q, e)) {  // no letter: nothing there
    o.reset();
    ++q;
    return true;
  }
  // Not a direction: left out (the mode in its place) only if it is the sentence's last field.
  const char* s = q;
  while (s != e && *s != ',') ++s;
  if (s != e) return false;  // bad_variation_direction
  o.reset();                 // q stays: that field is the mode
  return true;
}

HW_INLINE bool unit_m(const char*& q, const char* e, bool value_present) {
  if (q > e) return !value_present;
  const char c = *q;
  if (HW_LIKELY(c == 'M' && ((q[1] == ',') | (q + 1 == e)))) {
    q += 2;
    return true;
  }
  if (blank(q, e)) {
    ++q;
    return true;
  }
  return false;
}

// An optional decimal with its unit letter ('M'): GGA 9-10, 11-12.
HW_INLINE bool dec_unit(const char*& q, const char* e, bool absent_ok,
                        std::optional<swn::decimal>& o) {
  if (q > e) {
    o.reset();
    return absent_ok;  // the unit then is not present either
  }
  swn::decimal d;
  if (const char* r = dec(q, e, d); HW_LIKELY(r != nullptr)) {
    o.emplace(d);
    q = r;
    return unit_m(q, e, true);
  }
  if (!blank(q, e)) return false;
  o.reset();
  ++q;
  return unit_m(q, e, false);
}

// Extra fields past the last defined one are ignored, their bytes still checked.
HW_INLINE bool rest(const char*& q, const char* e) {
  while (q <= e)
    if (!skip(q, e)) return false;
  return true;
}

HW_INLINE bool decode_rmc(const char* q, const char* e, bool ok_absent, sws::rmc& m) {
  const char* const body = q;
  m.wire_fields = 0;
  if (!opt<1>(q, e, ok_absent, m.time, HW_PARSE(tod(q, e, v)))) return false;
  // status: required
  if (q > e) return false;
  {
    const char c = *q;
    if (!((c == 'A') | (c == 'V'))) return false;
    if (!((q[1] == ',') | (q + 1 == e))) return false;
    m.status = static_cast<sws::rmc_status>(c);
    q += 2;
  }
  if (!opt<2>(q, e, ok_absent, m.lat, HW_PARSE((coord<2, 90, 'N', 'S'>(q, e, v))))) return false;
  if (!opt<2>(q, e, ok_absent, m.lon, HW_PARSE((coord<3, 180, 'E', 'W'>(q, e, v))))) return false;
  if (!opt<1>(q, e, ok_absent, m.speed_knots, HW_BODY({
                const char* r = dec(q, e, v);
                return r && not_below_zero(v) ? r : nullptr;
              })))
    return false;
  if (!opt<1>(q, e, ok_absent, m.course_true, HW_BODY({
                const char* r = dec(q, e, v);
                return r && not_below_zero(v) && at_most(v, 360) ? r : nullptr;
              })))
    return false;
  if (!opt<1>(q, e, ok_absent, m.date, HW_PARSE(ymd(q, e, v)))) return false;
  if (!variation(q, e, ok_absent, m.magnetic_variation)) return false;
  if (!opt_letter(
          q, e, m.mode, m.wire_fields, body, [](char c) __attribute__((always_inline)) {
            return c == 'A' || c == 'D' || c == 'E' || c == 'F' || c == 'M' || c == 'N' ||
                   c == 'P' || c == 'R' || c == 'S';
          }))
    return false;
  if (!opt_letter(
          q, e, m.navigational_status, m.wire_fields, body,
          [](char c) __attribute__((always_inline)) {
            return c == 'C' || c == 'S' || c == 'U' || c == 'V';
          }))
    return false;
  return rest(q, e);
}

HW_INLINE bool decode_gga(const char* q, const char* e, bool ok_absent, sws::gga& m) {
  if (!opt<1>(q, e, ok_absent, m.time, HW_PARSE(tod(q, e, v)))) return false;
  if (!opt<2>(q, e, ok_absent, m.lat, HW_PARSE((coord<2, 90, 'N', 'S'>(q, e, v))))) return false;
  if (!opt<2>(q, e, ok_absent, m.lon, HW_PARSE((coord<3, 180, 'E', 'W'>(q, e, v))))) return false;
  if (!opt<1>(q, e, ok_absent, m.quality, HW_BODY({
                const char c = *q;
                if (dig(c) > 8 || !((q[1] == ',') | (q + 1 == e))) return nullptr;
                v = static_cast<sws::gps_quality>(c);
                return q + 2;
              })))
    return false;
  if (!opt<1>(q, e, ok_absent, m.satellites, HW_BODY({
                std::uint8_t n = 0;
                const char* r = whole(q, e, 255, n);
                v = n;
                return r;
              })))
    return false;
  if (!opt<1>(q, e, ok_absent, m.hdop, HW_BODY({
                const char* r = dec(q, e, v);
                return r && not_below_zero(v) ? r : nullptr;
              })))
    return false;
  if (!dec_unit(q, e, ok_absent, m.altitude_m)) return false;
  if (!dec_unit(q, e, ok_absent, m.geoid_separation_m)) return false;
  if (!opt<1>(q, e, ok_absent, m.dgps_age_s, HW_BODY({
                const char* r = dec(q, e, v);
                return r && not_below_zero(v) ? r : nullptr;
              })))
    return false;
  if (!opt<1>(q, e, ok_absent, m.dgps_station, HW_BODY({
                std::uint16_t n = 0;
                const char* r = whole(q, e, 1023, n);
                v = n;
                return r;
              })))
    return false;
  return rest(q, e);
}

// Address and fields; p[0] == '$', e the end of the body, p[e - p] readable and not a digit,
// ',' or letter ('*' or a sentinel). false: not an RMC/GGA, or an error.
HW_INLINE bool decode_body(const char* p, const char* e, bool ok_absent, out& o) {
  if (HW_UNLIKELY(e - p < 6)) return false;
  const char t0 = p[1], t1 = p[2];
  if (!(t0 >= 'A' && t0 <= 'Z' && t0 != 'P')) return false;
  if (!((t1 >= 'A' && t1 <= 'Z') || (t1 >= '0' && t1 <= '9'))) return false;
  const char* q;
  if (p[6] == ',')
    q = p + 7;
  else if (p + 6 == e)
    q = e + 1;  // no fields at all
  else
    return false;
  std::uint32_t a;
  std::memcpy(&a, p + 3, 4);
  a &= 0xFFFFFF;
  if (a == ('R' | 'M' << 8 | 'C' << 16)) {
    o.k = out::rmc;
    o.r.talker.assign(std::string_view(p + 1, 2));
    return decode_rmc(q, e, ok_absent, o.r);
  }
  if (a == ('G' | 'G' << 8 | 'A' << 16)) {
    o.k = out::gga;
    o.g.talker.assign(std::string_view(p + 1, 2));
    return decode_gga(q, e, ok_absent, o.g);
  }
  return false;
}

HW_INLINE int hexv(char c) {
  const unsigned u = static_cast<unsigned char>(c);
  if (u - '0' < 10) return static_cast<int>(u - '0');
  const unsigned l = (u | 0x20) - 'a';
  return l < 6 ? static_cast<int>(l + 10) : -1;
}

// XOR of p[b, e), 8 bytes at a time (two words a step).
HW_INLINE unsigned xor_range(const char* b, const char* e) {
  const std::size_t len = static_cast<std::size_t>(e - b);
  if (HW_LIKELY(len >= 8)) {
    std::uint64_t x = 0, y = 0;
    std::size_t i = 0;
    for (; i + 16 <= len; i += 16) {
      x ^= load64(b + i);
      y ^= load64(b + i + 8);
    }
    if (i + 8 <= len) {
      x ^= load64(b + i);
      i += 8;
    }
    const std::size_t left = len - i;
    if (left) y ^= load64(e - 8) >> (8 * (8 - left));
    x ^= y;
    x ^= x >> 32;
    x ^= x >> 16;
    x ^= x >> 8;
    return static_cast<unsigned>(x & 0xFF);
  }
  unsigned c = 0;
  for (const char* s = b; s != e; ++s) c ^= static_cast<unsigned char>(*s);
  return c;
}

__attribute__((noinline)) inline bool decode_no_checksum(std::string_view l, out& o) {
  // No "*hh" at the end. A '*' anywhere is a checksum cut off or misplaced: an error.
  if (l.find('*') != std::string_view::npos) return false;
  char buf[1024 + 4];
  std::memcpy(buf, l.data(), l.size());
  buf[l.size()] = '*';  // the sentinel that ends every field parser's loop
  buf[l.size() + 1] = 0;
  buf[l.size() + 2] = 0;
  return decode_body(buf, buf + l.size(), false, o);
}

// The whole decode of one line (with or without its line ending).
HW_INLINE bool decode(std::string_view l, out& o) {
  std::size_t n = l.size();
  const char* p = l.data();
  if (n >= 1 && (p[n - 1] == '\n' || p[n - 1] == '\r')) {
    if (n >= 2 && p[n - 2] == '\r' && p[n - 1] == '\n')
      n -= 2;
    else
      n -= 1;
  }
  if (HW_UNLIKELY(n < 9 || n > 1024 || p[0] != '$')) {
    if (n == 0 || n > 1024 || p[0] != '$') return false;
    return p[n >= 3 ? n - 3 : 0] == '*' && n >= 3
               ? false  // "*hh" in a line too short for an address: no RMC/GGA
               : decode_no_checksum(std::string_view(p, n), o);
  }
  if (HW_UNLIKELY(p[n - 3] != '*')) return decode_no_checksum(std::string_view(p, n), o);
  const int hi = hexv(p[n - 2]), lo = hexv(p[n - 1]);
  if (HW_UNLIKELY((hi | lo) < 0)) return false;
  const char* const e = p + n - 3;
  if (HW_UNLIKELY(xor_range(p + 1, e) != static_cast<unsigned>(hi << 4 | lo))) return false;
  return decode_body(p, e, true, o);
}

}  // namespace HW_NS
#pragma GCC diagnostic pop
