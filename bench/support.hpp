// SPDX-License-Identifier: BSL-1.0
#pragma once
// What every seawire benchmark shares: the baseline it is measured against, the reader that
// touches every decoded field, line framing over a corpus, and the counters each one reports.

#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>
#include <type_traits>

#include "alloc_count.hpp"
#include "seawire/detail/ascii.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/variation.hpp"

namespace seawire::bench {

// ---------------------------------------------------------------------------------------------
// the baseline: frame, verify the XOR checksum, split the fields -- and nothing else

/// Where each field of a sentence starts and ends; what a minimal splitter hands out.
struct split_sentence {
  std::array<std::string_view, 64> fields;  ///< [0] is the address
  std::size_t count = 0;
};

/// The least work any NMEA decoder must do: check '$', XOR every byte up to '*' while noting the
/// commas, compare with the two hex digits. No field is converted. False for a bad sentence.
/// Written plainly, as a careful hand-written splitter would be; no tricks the library could not
/// also use.
[[nodiscard]] inline bool baseline_split(std::string_view line, split_sentence& out) noexcept {
  const char* const p = line.data();
  const std::size_t n = line.size();
  if (n < 4 || p[0] != '$') return false;
  std::uint8_t x = 0;
  std::size_t start = 1;
  std::size_t count = 0;
  std::size_t i = 1;
  for (; i < n; ++i) {
    const char c = p[i];
    if (c == '*') break;
    x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(c));
    if (c == ',') {
      if (count + 1 >= out.fields.size()) return false;
      out.fields[count++] = std::string_view(p + start, i - start);
      start = i + 1;
    }
  }
  out.fields[count++] = std::string_view(p + start, i - start);
  out.count = count;
  if (i + 2 >= n) return false;
  const int hi = seawire::detail::hex_value(p[i + 1]);
  const int lo = seawire::detail::hex_value(p[i + 2]);
  return hi >= 0 && lo >= 0 && (hi << 4 | lo) == x;
}

// ---------------------------------------------------------------------------------------------
// framing a corpus: both the baseline and the decoders see lines the same way

/// Calls f(line) for each LF-terminated line of `bytes`, the line with its CR LF.
template <class F>
inline void for_each_line(std::string_view bytes, F&& f) {
  const char* p = bytes.data();
  const char* const end = p + bytes.size();
  while (p < end) {
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    const char* const stop = nl != nullptr ? static_cast<const char*>(nl) + 1 : end;
    f(std::string_view(p, static_cast<std::size_t>(stop - p)));
    p = stop;
  }
}

// ---------------------------------------------------------------------------------------------
// reading every field of a decoded message, the way a user would

/// Where the field values go, so that the compiler cannot drop the work that made them.
struct sink {
  double sum = 0;
  std::uint64_t bits = 0;
};

template <class V>
inline void read_value(sink& s, const V& v) noexcept {
  if constexpr (requires { v.has_value(); }) {
    if (v.has_value()) {
      read_value(s, *v);
    } else {
      ++s.bits;
    }
  } else if constexpr (std::is_same_v<V, nmea::decimal>) {
    s.sum += v.to_double();
  } else if constexpr (std::is_same_v<V, nmea::magnetic_variation>) {
    s.sum += v.degrees().value_or(0.0);
  } else if constexpr (requires { v.degrees(); }) {
    s.sum += v.degrees();
  } else if constexpr (requires { v.since_midnight(); }) {
    s.bits += static_cast<std::uint64_t>(v.since_midnight().count());
  } else if constexpr (std::is_same_v<V, nmea::date>) {
    s.bits += v.year * 10'000U + v.month * 100U + v.day;
  } else if constexpr (requires { v.view(); }) {
    s.bits += v.size() + (v.empty() ? 0U : static_cast<unsigned char>(v.view()[0]));
  } else if constexpr (std::is_enum_v<V> || std::is_integral_v<V>) {
    s.bits += static_cast<std::uint64_t>(v);
  } else if constexpr (nmea::is_integer_wrapper<V>) {
    s.bits += static_cast<std::uint64_t>(v.value());
  } else if constexpr (requires { v.colors; }) {
    s.bits += static_cast<unsigned char>(v.colors[0]);
  } else {
    static_assert(sizeof(V) == 0, "read_value: unknown field type");
  }
}

/// Every field of `m`: decimals and positions as doubles, times, dates, text, enums.
template <class T>
inline void read_all(sink& s, const T& m) noexcept {
  if constexpr (nmea::message_like<T>) {
    nmea::for_each_field(m, [&s](std::string_view, const auto& v) { read_value(s, v); });
  } else {
    ++s.bits;  // unknown_sentence
  }
}

// ---------------------------------------------------------------------------------------------
// counters

/// Per-message figures every benchmark reports: items (so items_per_second, and time_per_msg =
/// its inverse), bytes/s, and heap allocations per message (must be 0).
inline void report(benchmark::State& state, std::size_t messages_per_iteration,
                   std::size_t bytes_per_iteration, std::uint64_t allocations) {
  const auto iterations = static_cast<std::int64_t>(state.iterations());
  const auto messages =
      static_cast<double>(iterations) * static_cast<double>(messages_per_iteration);
  state.SetItemsProcessed(iterations * static_cast<std::int64_t>(messages_per_iteration));
  state.SetBytesProcessed(iterations * static_cast<std::int64_t>(bytes_per_iteration));
  state.counters["time_per_msg"] =
      benchmark::Counter(messages, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["allocs_per_msg"] =
      benchmark::Counter(messages > 0 ? static_cast<double>(allocations) / messages : 0.0);
}

}  // namespace seawire::bench
