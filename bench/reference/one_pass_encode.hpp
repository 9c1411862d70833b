// SPDX-License-Identifier: BSL-1.0
// A contender of the benchmark, not part of the library (see one_pass_decode.hpp).
// Hand-written RMC/GGA writer (no snprintf): the same bytes as seawire's encode_to, with the
// same value checks (time, date, positions, decimals' limits and ranges, letters, talker),
// into a caller's buffer of at least 256 bytes. Returns the length, 0 on a refused value.
#pragma once
// (namespace hw: uses the default one_pass_decode.hpp)

#ifndef HW_NS
#include "one_pass_decode.hpp"
#endif

namespace hw {

inline constexpr char pairs[201] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

HW_INLINE unsigned ndigits(std::uint64_t v) {
  const std::uint64_t w = v | 1u;
  const unsigned t = static_cast<unsigned>(64 - __builtin_clzll(w)) * 1233u >> 12;
  return t + (w >= p10[t] ? 1u : 0u);
}
// The last `count` digits of v ending just before `end`, two at a time.
HW_INLINE std::uint64_t digits_back(char* end, std::uint64_t v, unsigned count) {
  for (; count >= 2; count -= 2) {
    std::memcpy(end - 2, pairs + (v % 100) * 2, 2);
    v /= 100;
    end -= 2;
  }
  if (count) {
    end[-1] = static_cast<char>('0' + v % 10);
    v /= 10;
  }
  return v;
}
HW_INLINE void two(char*& w, unsigned v) {
  std::memcpy(w, pairs + v * 2, 2);
  w += 2;
}
// scaled / 10^places with at least min_int integer digits (at most 20).
HW_INLINE void fixed(char*& w, std::uint64_t scaled, unsigned places, unsigned min_int) {
  const unsigned n = ndigits(scaled);
  unsigned own = n > places ? n - places : 1;
  if (own < min_int) own = min_int < 20 ? min_int : 20;
  char* const int_end = w + own;
  if (places) {
    scaled = digits_back(int_end + 1 + places, scaled, places);
    *int_end = '.';
    w = int_end + 1 + places;
  } else {
    w = int_end;
  }
  digits_back(int_end, scaled, own);
}
HW_INLINE bool dec_ok(const swn::decimal& d) {
  return d.places <= 19 && d.mantissa <= 9'999'999'999'999'999'999ULL && d.int_width <= 20;
}
HW_INLINE void put_dec(char*& w, const swn::decimal& d) {
  if (d.negative) *w++ = '-';
  fixed(w, d.mantissa, d.places, d.int_width);
}
HW_INLINE bool put_time(char*& w, const swn::time_of_day& t) {
  if (t.hour > 23 || t.minute > 59 || t.second > 60 ||
      (t.second == 60 && !(t.hour == 23 && t.minute == 59)) || t.places > 9 ||
      t.fraction >= p10[t.places])
    return false;
  two(w, t.hour);
  two(w, t.minute);
  two(w, t.second);
  if (t.places) {
    *w++ = '.';
    fixed(w, t.fraction, 0, t.places);
  }
  return true;
}
HW_INLINE bool put_date(char*& w, const swn::date& d) {
  if (d.year < 1980 || d.year > 2079 || d.month < 1 || d.month > 12 || d.day < 1) return false;
  static constexpr unsigned char dim[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const unsigned y = d.year;
  const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
  if (d.day > (d.month == 2 && leap ? 29u : dim[d.month - 1])) return false;
  two(w, d.day);
  two(w, d.month);
  two(w, y % 100);
  return true;
}
template <unsigned W, unsigned MaxDeg, char Pos, char Neg, class C>
HW_INLINE bool put_coord(char*& w, const C& v) {
  const swn::decimal& m = v.minutes;
  if (m.negative || m.places > 12 || m.mantissa >= 60 * p10[m.places]) return false;
  if (v.whole_degrees > MaxDeg || (v.whole_degrees == MaxDeg && m.mantissa != 0) ||
      v.degree_digits > W)
    return false;
  const char h = static_cast<char>(v.hemi);
  if (h != Pos && h != Neg) return false;
  fixed(w, v.whole_degrees, 0, v.degree_digits);
  if (m.places == 0)
    fixed(w, m.mantissa * 10, 1, 2);
  else
    fixed(w, m.mantissa, m.places, 2);
  *w++ = ',';
  *w++ = h;
  return true;
}
HW_INLINE char* seal(char* b, char* w) {
  // XOR of b[1, w), 8 bytes at a time
  const unsigned x = xor_range(b + 1, w);
  static constexpr char hex[] = "0123456789ABCDEF";
  w[0] = '*';
  w[1] = hex[x >> 4];
  w[2] = hex[x & 15];
  w[3] = '\r';
  w[4] = '\n';
  return w + 5;
}
HW_INLINE bool put_talker(char*& w, const swn::talker_id& t) {
  const std::string_view s = t.view();
  if (s.size() != 2 || !(s[0] >= 'A' && s[0] <= 'Z') || s[0] == 'P' ||
      !((s[1] >= 'A' && s[1] <= 'Z') || (s[1] >= '0' && s[1] <= '9')))
    return false;
  w[0] = '$';
  w[1] = s[0];
  w[2] = s[1];
  w += 3;
  return true;
}

inline std::size_t encode_rmc(const sws::rmc& m, char* b) {
  char* w = b;
  if (!put_talker(w, m.talker)) return 0;
  std::memcpy(w, "RMC,", 4);
  w += 4;
  if (m.time && !put_time(w, *m.time)) return 0;
  *w++ = ',';
  const char st = static_cast<char>(m.status);
  if (st != 'A' && st != 'V') return 0;
  *w++ = st;
  *w++ = ',';
  if (m.lat) {
    if (!put_coord<2, 90, 'N', 'S'>(w, *m.lat)) return 0;
  } else {
    *w++ = ',';
  }
  *w++ = ',';
  if (m.lon) {
    if (!put_coord<3, 180, 'E', 'W'>(w, *m.lon)) return 0;
  } else {
    *w++ = ',';
  }
  *w++ = ',';
  if (m.speed_knots) {
    const auto& d = *m.speed_knots;
    if (!dec_ok(d) || (d.negative && d.mantissa)) return 0;
    put_dec(w, d);
  }
  *w++ = ',';
  if (m.course_true) {
    const auto& d = *m.course_true;
    if (!dec_ok(d) || (d.negative && d.mantissa) || !at_most(d, 360)) return 0;
    put_dec(w, d);
  }
  *w++ = ',';
  if (m.date && !put_date(w, *m.date)) return 0;
  *w++ = ',';
  if (m.magnetic_variation) {
    const auto& v = *m.magnetic_variation;
    const char dir = static_cast<char>(v.direction);
    if (dir != 'E' && dir != 'W') return 0;
    if (v.value) {
      if (!dec_ok(*v.value) || v.value->negative || !at_most(*v.value, 180)) return 0;
      put_dec(w, *v.value);
    }
    *w++ = ',';
    *w++ = dir;
  } else {
    *w++ = ',';
  }
  // Mode and navigational status: left out at the end when empty, unless the sentence they were
  // decoded from had them (wire_fields: 12 keeps the mode's field, 13 both).
  const unsigned wire = m.wire_fields;
  const bool nav = m.navigational_status.has_value() || wire > 12;
  const bool mode = m.mode.has_value() || nav || wire > 11;
  if (mode) {
    *w++ = ',';
    if (m.mode) {
      const char c = static_cast<char>(*m.mode);
      if (!(c == 'A' || c == 'D' || c == 'E' || c == 'F' || c == 'M' || c == 'N' || c == 'P' ||
            c == 'R' || c == 'S'))
        return 0;
      *w++ = c;
    }
  }
  if (nav) {
    *w++ = ',';
    if (m.navigational_status) {
      const char c = static_cast<char>(*m.navigational_status);
      if (!(c == 'C' || c == 'S' || c == 'U' || c == 'V')) return 0;
      *w++ = c;
    }
  }
  return static_cast<std::size_t>(seal(b, w) - b);
}

inline std::size_t encode_gga(const sws::gga& m, char* b) {
  char* w = b;
  if (!put_talker(w, m.talker)) return 0;
  std::memcpy(w, "GGA,", 4);
  w += 4;
  if (m.time && !put_time(w, *m.time)) return 0;
  *w++ = ',';
  if (m.lat) {
    if (!put_coord<2, 90, 'N', 'S'>(w, *m.lat)) return 0;
  } else {
    *w++ = ',';
  }
  *w++ = ',';
  if (m.lon) {
    if (!put_coord<3, 180, 'E', 'W'>(w, *m.lon)) return 0;
  } else {
    *w++ = ',';
  }
  *w++ = ',';
  if (m.quality) {
    const char c = static_cast<char>(*m.quality);
    if (c < '0' || c > '8') return 0;
    *w++ = c;
  }
  *w++ = ',';
  if (m.satellites) {
    if (!m.satellites->fits()) return 0;
    fixed(w, static_cast<std::uint64_t>(m.satellites->value()), 0, 2);
  }
  *w++ = ',';
  if (m.hdop) {
    const auto& d = *m.hdop;
    if (!dec_ok(d) || (d.negative && d.mantissa)) return 0;
    put_dec(w, d);
  }
  *w++ = ',';
  if (m.altitude_m) {
    if (!dec_ok(*m.altitude_m)) return 0;
    put_dec(w, *m.altitude_m);
  }
  std::memcpy(w, ",M,", 3);
  w += 3;
  if (m.geoid_separation_m) {
    if (!dec_ok(*m.geoid_separation_m)) return 0;
    put_dec(w, *m.geoid_separation_m);
  }
  std::memcpy(w, ",M,", 3);
  w += 3;
  if (m.dgps_age_s) {
    const auto& d = *m.dgps_age_s;
    if (!dec_ok(d) || (d.negative && d.mantissa)) return 0;
    put_dec(w, d);
  }
  *w++ = ',';
  if (m.dgps_station) {
    if (!m.dgps_station->fits() || m.dgps_station->value() > 1023) return 0;
    fixed(w, static_cast<std::uint64_t>(m.dgps_station->value()), 0, 4);
  }
  return static_cast<std::size_t>(seal(b, w) - b);
}

}  // namespace hw
