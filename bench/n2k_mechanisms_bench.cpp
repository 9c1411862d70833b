// SPDX-License-Identifier: BSL-1.0
// NMEA 2000: one row per field mechanism and per framing step, so that what each costs shows
// apart, beside a baseline that copies the same bytes and sums them. An item is a payload (of
// the first four rows, a CAN frame of 8 bytes), a PGN looked up, or a log line (a frame).
//
//   n2k/mechanism/baseline            each 8-byte payload copied to a buffer and summed
//   n2k/mechanism/numbers             decode of 8 bytes of four numbers (16 bits, signed and
//                                     unsigned, with resolutions), each read as a double
//   n2k/mechanism/lookups             decode of 2 bytes of four lookups (2, 3, 3 and 8 bits),
//                                     each read as its name
//   n2k/mechanism/flags               decode of 8 bytes of four 16-bit flag words, each bit
//                                     tested
//   n2k/mechanism/numbers64           decode of 32 bytes of four signed 64-bit numbers (1e-16 and
//                                     1e-6 resolutions, as 129029's latitude, longitude and
//                                     altitude), each read as a double
//   n2k/mechanism/strings/fixed       decode of 80 bytes of four 20-byte fixed_text strings (two
//                                     '@'-padded as AIS sends them, two 0xFF-padded), each read
//                                     as its text
//   n2k/mechanism/strings/counted_ascii  decode of PGN 126998 Configuration Information (three
//   n2k/mechanism/strings/counted_utf16  counted strings of 1..32 characters, ASCII or UTF-16),
//                                     each read as its text: the layout varies (decode_varying)
//   n2k/mechanism/groups/repeating    decode of PGN 129540 GNSS Sats in View with 12 satellites
//                                     (147 bytes: a count, then 12 bytes a satellite), every field
//                                     of every satellite read
//   n2k/mechanism/groups/repeating_to_end  decode of PGN 126464 PGN List with 30 PGNs (91 bytes:
//                                     24-bit PGNs to the end of the payload), every PGN read
//   n2k/mechanism/layouts/126208      registry::pgns::visit of PGN 126208 Group Function
//                                     payloads, a third each a request, a command (0..16 bytes of
//                                     parameter pairs, kept as bytes) and an acknowledgement
//                                     (0..8 4-bit codes): the layout picked by the function code
//                                     among the set's structs, decoded, every field read
//   n2k/mechanism/is_fast_packet_pgn  the standard's fast-packet list looked up (binary search)
//                                     for 1,000 PGNs of a bus
//   n2k/mechanism/fast_packet/undescribed  log_reader::read_line of `candump -L` lines of a
//                                     proprietary fast-packet PGN no PGN set declares (130842,
//                                     20 bytes in 3 frames): parsed, assembled by the list
//
// The string and group rows report time_per_element too: the time per string or per repetition
// of the group (the payload's time over their count, its other fields included).
//
// Adding a mechanism: a struct of four fields of that mechanism (`four_fields` below, or one of
// its own; a PGN number of the proprietary range, as no registry holds it) or a real PGN that
// has it, its corpus (`corpus_of`, from random raw values, with a `fill` for what is not a raw
// value: strings, a group's repetitions), a reader of its fields (`read`), and one BENCHMARK
// line naming the row `n2k/mechanism/<kind>`.

#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "corpus.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/fast_packet.hpp"
#include "seawire/nmea2000/fast_packets.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/nmea2000/reader.hpp"
#include "seawire/registry.hpp"
#include "support.hpp"

namespace {

using namespace seawire;
namespace n2k = seawire::nmea2000;
namespace sb = seawire::bench;

constexpr std::size_t frame_count = 1000;

// ---------------------------------------------------------------------------------------------
// one struct per mechanism (PGN numbers of the proprietary ranges: no registry holds them)

/// Four fields of types A-D (the payload as long as they are).
template <class A, class B, class C, class D, std::uint32_t Pgn,
          n2k::framing Framing = n2k::framing::single_frame>
struct four_fields {
  A a;
  B b;
  C c;
  D d;
  static constexpr auto n2k = n2k::describe_pgn(
      n2k::pgn_info{Pgn, "four_fields", "four fields", 6, Framing, 0},
      n2k::field<&four_fields::a>("a", "a"), n2k::field<&four_fields::b>("b", "b"),
      n2k::field<&four_fields::c>("c", "c"), n2k::field<&four_fields::d>("d", "d"));
  [[nodiscard]] constexpr bool operator==(const four_fields&) const noexcept = default;
};

using mechanism_numbers = four_fields<n2k::signed_number<16, n2k::res::radian>,
                                      n2k::unsigned_number<16, n2k::res::hundredth>,
                                      n2k::signed_number<16, n2k::res::thousandth>,
                                      n2k::unsigned_number<16, n2k::res::radian>, 65280>;
using mechanism_lookups =
    four_fields<n2k::lookup<n2k::heading_reference, 2>, n2k::lookup<n2k::rudder_direction, 3>,
                n2k::lookup<n2k::wind_reference, 3>, n2k::lookup<n2k::temperature_source, 8>,
                65281>;
using mechanism_flags =
    four_fields<n2k::flags<n2k::engine_status_1, 16>, n2k::flags<n2k::engine_status_2, 16>,
                n2k::flags<n2k::engine_status_1, 16>, n2k::flags<n2k::engine_status_2, 16>, 65282>;
using degrees64 = n2k::signed_number<64, n2k::resolution{1, -16}>;
using metres64 = n2k::signed_number<64, n2k::resolution{1, -6}>;
using mechanism_numbers64 =
    four_fields<degrees64, degrees64, metres64, metres64, 130960, n2k::framing::fast_packet>;
using mechanism_fixed_text = four_fields<n2k::ais_text<20>, n2k::fixed_text<20>, n2k::ais_text<20>,
                                         n2k::fixed_text<20>, 130961, n2k::framing::fast_packet>;

// ---------------------------------------------------------------------------------------------
// corpora: random raw values of every field (10% not available), written by the library's
// encoder, deterministic (splitmix64)

/// A random raw value of a number, lookup or flag set type V; not available one time in ten.
template <class V>
V random_value(sb::rng& r) noexcept {
  const auto top = static_cast<std::uint64_t>(V::top_raw);
  std::int64_t raw = static_cast<std::int64_t>(r.next() % (top + 1));
  if constexpr (requires { V::max_valid_raw; }) {
    raw = static_cast<std::int64_t>(r.next() % (static_cast<std::uint64_t>(V::max_valid_raw) + 1));
  }
  if constexpr (V::is_signed) raw -= static_cast<std::int64_t>((top + 1) / 2);
  return r.chance(0.1) ? V{} : V::from_raw(raw);
}

/// Whether row type F of a table holds a raw value (not reserved bits, a string, a group or
/// bytes).
template <class F>
constexpr bool is_raw_row() noexcept {
  if constexpr (
      F::is_reserved || requires { F::is_group; } || requires { F::is_bytes; }) {
    return false;
  } else {
    return !n2k::text_value<typename F::value_type>;
  }
}

/// Every raw-valued field of `m` (a PGN, or a group's repetition with its table `table`) random.
template <class T, class Table>
void randomize(sb::rng& r, T& m, const Table& table) noexcept {
  table.for_each([&](const auto& f, unsigned, std::uint16_t) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (is_raw_row<F>()) m.*F::member = random_value<typename F::value_type>(r);
  });
}

/// What a PGN of raw values alone needs besides randomize(): nothing.
struct raw_values_only {
  template <class P>
  void operator()(sb::rng&, P&) const noexcept {}
};

/// 1,000 payloads of P: its raw values random, then `fill(rng, message)` for the rest (strings,
/// a group's repetitions). Each one checked to decode back to the message it was encoded from.
template <n2k::pgn_like P, class Fill = raw_values_only>
std::vector<std::vector<std::uint8_t>> corpus_of(std::uint64_t seed, Fill fill = {}) {
  sb::rng r(seed);
  std::vector<std::vector<std::uint8_t>> out;
  while (out.size() < frame_count) {
    P m{};
    randomize(r, m, n2k::pgn_table<P>);
    fill(r, m);
    const auto e = n2k::encode(m);
    if (!e) continue;  // a value the encoder refuses (a sentinel of a signed number): draw again
    if (!(n2k::decode<P>(e.value.view()) == m)) std::abort();  // not the message measured
    out.emplace_back(e.value.begin(), e.value.end());
  }
  return out;
}

/// A text of 1..`most` characters drawn from `alphabet` (UTF-8 characters), not ending in
/// padding (a last space becomes alphabet[0]); "" (not available) one time in ten.
template <std::size_t N>
std::string random_text(sb::rng& r, std::size_t most,
                        const std::array<std::string_view, N>& alphabet) {
  std::string text;
  if (r.chance(0.1)) return text;
  const auto length = static_cast<std::size_t>(r.between(1, static_cast<int>(most)));
  for (std::size_t i = 0; i < length; ++i) {
    const std::string_view c = r.pick(alphabet);
    text += i + 1 == length && c == " " ? alphabet[0] : c;
  }
  return text;
}

/// Sets `v` (a fixed_text or counted_text) to `text`; aborts if the type refuses it.
template <class V>
void set_text(V& v, std::string_view text) {
  const auto t = V::from_text(text);
  if (!t) std::abort();
  v = t.value;
}

// Names as AIS sends them (upper case, digits, spaces), and the free text of the rest of the bus.
constexpr std::array<std::string_view, 39> ais_alphabet = {
    "A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K", "L", "M",
    "N", "O", "P", "Q", "R", "S", "T", "U", "V", "W", "X", "Y", "Z",
    "0", "1", "2", "3", "4", "5", "6", "7", "8", "9", " ", " ", "-"};
constexpr std::array<std::string_view, 40> ascii_alphabet = {
    "a", "b", "c", "d", "e", "f", "g", "h", "i", "j", "k", "l", "m", "n",
    "o", "p", "q", "r", "s", "t", "u", "v", "w", "x", "y", "z", "A", "B",
    "C", "D", "E", "F", "0", "1", "2", "3", " ", " ", ".", "/"};
// Greek and Cyrillic, every letter past U+00FE: the string goes as UTF-16.
constexpr std::array<std::string_view, 20> utf16_alphabet = {"Ω", "α", "β", "γ", "δ", "ε", "λ",
                                                             "π", "ρ", "σ", "Ж", "а", "д", "и",
                                                             "к", "м", "р", "я", " ", " "};

void fixed_texts(sb::rng& r, mechanism_fixed_text& m) {
  set_text(m.a, random_text(r, 20, ais_alphabet));
  set_text(m.b, random_text(r, 20, ascii_alphabet));
  set_text(m.c, random_text(r, 20, ais_alphabet));
  set_text(m.d, random_text(r, 20, ascii_alphabet));
}

template <std::size_t N>
auto counted_texts(const std::array<std::string_view, N>& alphabet) {
  return [&alphabet](sb::rng& r, n2k::configuration_information& m) {
    set_text(m.installation_description_1, random_text(r, 32, alphabet));
    set_text(m.installation_description_2, random_text(r, 32, alphabet));
    set_text(m.manufacturer_information, random_text(r, 32, alphabet));
  };
}

/// 129540 with 12 satellites (the count says 12), each field of each random.
void twelve_satellites(sb::rng& r, n2k::gnss_sats_in_view& m) {
  using satellite = n2k::gnss_sats_in_view::satellite;
  m.sats_in_view = decltype(m.sats_in_view)::from_raw(12);
  for (int i = 0; i < 12; ++i) {
    satellite s{};
    randomize(r, s, satellite::n2k_item);
    (void)m.satellites.push_back(s);
  }
}

/// 126464 with 30 PGNs, each random.
void thirty_pgns(sb::rng& r, n2k::pgn_list_message& m) {
  using entry = n2k::pgn_list_message::entry;
  for (int i = 0; i < 30; ++i) {
    entry e{};
    randomize(r, e, entry::n2k_item);
    (void)m.pgns.push_back(e);
  }
}

// ---------------------------------------------------------------------------------------------
// reading every field as a user would

template <class T, class Table>
void read_fields(sb::sink& s, const T& m, const Table& table) noexcept;

/// One field's value. Always inlined: a reader shared by many rows (the satellites' numbers are
/// the numbers row's types) would otherwise be called out of line, and each row's figure would
/// depend on which other rows the file has (the numbers row: 4.8 -> 7.0 ns).
template <class V>
[[gnu::always_inline]] inline void read(sb::sink& s, const V& v) noexcept {
  if constexpr (requires { v.name(); }) {
    s.bits += v.name().size();  // a lookup: its name
  } else if constexpr (requires { v.test_bit(0U); }) {
    for (unsigned b = 0; b < V::bits; ++b) s.bits += v.test_bit(b) ? b : 0U;  // flags
  } else if constexpr (n2k::text_value<V>) {
    const std::string_view t = v.text();  // a string: its text
    s.bits += t.size() + (t.empty() ? 0U : static_cast<unsigned char>(t[0]));
  } else if constexpr (requires { v.items(); }) {
    for (const auto& item : v) read_fields(s, item, item.n2k_item);  // a group: every repetition
  } else if constexpr (requires { v.bytes(); }) {
    for (const std::uint8_t b : v.bytes()) s.bits += b;  // bytes kept as sent
  } else {
    s.sum += v.value().value_or(0.0);  // a number in its unit
  }
}

/// Every field of `m` (a PGN, or a group's repetition with its table `table`).
template <class T, class Table>
void read_fields(sb::sink& s, const T& m, const Table& table) noexcept {
  table.for_each([&](const auto& f, unsigned, std::uint16_t) {
    using F = std::remove_cvref_t<decltype(f)>;
    if constexpr (!F::is_reserved) read(s, m.*F::member);
  });
}

/// decode<P> of every payload of `corpus`, every field read; `elements` strings or repetitions
/// a payload (0: no time_per_element).
template <n2k::pgn_like P>
void decode_row(benchmark::State& state, const std::vector<std::vector<std::uint8_t>>& corpus,
                std::size_t elements = 0) {
  sb::sink s;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const std::vector<std::uint8_t>& payload : corpus) {
      const P m = n2k::decode<P>(payload);
      read_fields(s, m, n2k::pgn_table<P>);
      benchmark::DoNotOptimize(s);
    }
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  std::size_t bytes = 0;
  for (const std::vector<std::uint8_t>& payload : corpus) bytes += payload.size();
  sb::report(state, corpus.size(), bytes, allocations);
  if (elements > 0) {
    const auto count =
        static_cast<double>(state.iterations()) * static_cast<double>(corpus.size() * elements);
    state.counters["time_per_element"] =
        benchmark::Counter(count, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  }
  if (allocations != 0) state.SkipWithError("decode allocated");
}

void baseline(benchmark::State& state) {
  const std::vector<std::vector<std::uint8_t>> corpus = corpus_of<mechanism_numbers>(65280);
  std::array<std::uint8_t, 8> copy{};
  std::uint64_t sum = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const std::vector<std::uint8_t>& payload : corpus) {
      std::memcpy(copy.data(), payload.data(), copy.size());
      benchmark::DoNotOptimize(copy);
      for (const std::uint8_t b : copy) sum += b;
    }
    benchmark::DoNotOptimize(sum);
  }
  sb::report(state, corpus.size(), corpus.size() * 8, sb::allocation_count() - before);
}

void numbers(benchmark::State& state) {
  decode_row<mechanism_numbers>(state, corpus_of<mechanism_numbers>(65280));
}
void lookups(benchmark::State& state) {
  decode_row<mechanism_lookups>(state, corpus_of<mechanism_lookups>(65281));
}
void flag_words(benchmark::State& state) {
  decode_row<mechanism_flags>(state, corpus_of<mechanism_flags>(65282));
}
void numbers64(benchmark::State& state) {
  decode_row<mechanism_numbers64>(state, corpus_of<mechanism_numbers64>(130960));
}
void fixed_strings(benchmark::State& state) {
  decode_row<mechanism_fixed_text>(state, corpus_of<mechanism_fixed_text>(130961, fixed_texts), 4);
}
void counted_ascii(benchmark::State& state) {
  decode_row<n2k::configuration_information>(
      state, corpus_of<n2k::configuration_information>(126998, counted_texts(ascii_alphabet)), 3);
}
void counted_utf16(benchmark::State& state) {
  decode_row<n2k::configuration_information>(
      state, corpus_of<n2k::configuration_information>(126999, counted_texts(utf16_alphabet)), 3);
}
void repeating(benchmark::State& state) {
  decode_row<n2k::gnss_sats_in_view>(
      state, corpus_of<n2k::gnss_sats_in_view>(129540, twelve_satellites), 12);
}
void repeating_to_end(benchmark::State& state) {
  decode_row<n2k::pgn_list_message>(state, corpus_of<n2k::pgn_list_message>(126464, thirty_pgns),
                                    30);
}

/// The fields a group function's layout does not draw as raw values: its own function code,
/// 0..16 bytes of parameter pairs or 0..8 acknowledgement codes.
struct group_function_fill {
  template <class P>
  void operator()(sb::rng& r, P& m) const {
    m.function_code = P{}.function_code;
    const auto n = static_cast<std::size_t>(r.between(0, 8));
    m.number_of_parameters =
        decltype(m.number_of_parameters)::from_raw(static_cast<std::int64_t>(n));
    if constexpr (requires { m.parameters.bytes(); }) {
      std::array<std::uint8_t, 16> b{};
      for (std::size_t i = 0; i < 2 * n; ++i) b[i] = static_cast<std::uint8_t>(r.next());
      m.parameters = decltype(m.parameters)::from_bytes(std::span(b).first(2 * n)).value;
    } else {
      m.parameters.clear();
      for (std::size_t i = 0; i < n; ++i) {
        typename decltype(m.parameters)::item_type item;
        item.parameter = decltype(item.parameter)::from_raw(r.between(0, 6));
        (void)m.parameters.push_back(item);
      }
    }
  }
};

void layouts(benchmark::State& state) {
  const auto requests = corpus_of<n2k::group_function_request>(126208, group_function_fill{});
  const auto commands = corpus_of<n2k::group_function_command>(126209, group_function_fill{});
  const auto acks = corpus_of<n2k::group_function_acknowledge>(126210, group_function_fill{});
  std::vector<std::vector<std::uint8_t>> corpus;
  for (std::size_t i = 0; i < frame_count; ++i)
    corpus.push_back(i % 3 == 0 ? requests[i] : i % 3 == 1 ? commands[i] : acks[i]);
  sb::sink s;
  std::size_t unmatched = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const std::vector<std::uint8_t>& payload : corpus) {
      const bool known = registry::pgns::visit(126208, payload, [&](const auto& m) {
        if constexpr (requires { m.function_code; })
          read_fields(s, m, n2k::pgn_table<std::remove_cvref_t<decltype(m)>>);  // 126208's
      });
      unmatched += known ? 0 : 1;
      benchmark::DoNotOptimize(s);
    }
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  std::size_t bytes = 0;
  for (const std::vector<std::uint8_t>& payload : corpus) bytes += payload.size();
  sb::report(state, corpus.size(), bytes, allocations);
  if (unmatched != 0) state.SkipWithError("a payload matched no layout");
  if (allocations != 0) state.SkipWithError("decode allocated");
}

// ---------------------------------------------------------------------------------------------
// framing

/// The PGNs of a bus as they come: the declared ones and the proprietary and standard ones
/// around them, single-frame and fast.
void is_fast(benchmark::State& state) {
  constexpr std::array<std::uint32_t, 16> bus = {127250, 127251, 127257, 129025, 129026, 127245,
                                                 65359,  126720, 129029, 129540, 130842, 128259,
                                                 130306, 59392,  127489, 126208};
  std::vector<std::uint32_t> pgns;
  sb::rng r(126720);
  for (std::size_t i = 0; i < frame_count; ++i) pgns.push_back(r.pick(bus));
  std::uint64_t fast = 0;
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    for (const std::uint32_t pgn : pgns) {
      benchmark::DoNotOptimize(pgn);
      fast += n2k::is_fast_packet_pgn(pgn) ? 1U : 0U;
    }
    benchmark::DoNotOptimize(fast);
  }
  sb::report(state, pgns.size(), pgns.size() * 4, sb::allocation_count() - before);
}

/// `candump -L` lines of a proprietary fast-packet PGN (130842, 20 bytes: 3 frames), from two
/// sources interleaved, 10 ms apart.
std::string undescribed_lines() {
  std::string text;
  sb::rng r(130842);
  n2k::log_record rec;
  (void)rec.interface.assign("can0");
  std::size_t lines = 0;
  for (std::size_t packet = 0; lines < frame_count; ++packet) {
    std::array<std::uint8_t, 20> payload{};
    for (std::uint8_t& b : payload) b = static_cast<std::uint8_t>(r.next());
    const auto frames = n2k::split_fast_packet(payload, static_cast<std::uint8_t>(packet % 8));
    if (!frames) std::abort();
    for (const n2k::frame_data& f : frames.value.view()) {
      rec.id = {7, 130842, static_cast<std::uint8_t>(packet % 2 == 0 ? 0x0C : 0x0D), 255};
      rec.time_us = 1'720'021'378'000'000 + static_cast<std::int64_t>(lines) * 10'000;
      nmea::json_buffer<128> line;
      if (!rec.assign(f.view()) ||
          n2k::write_log_line(line, rec, n2k::log_format::candump_log) != errc::ok)
        std::abort();
      text += line.view();
      ++lines;
    }
  }
  return text;
}

void undescribed_fast(benchmark::State& state) {
  const std::string text = undescribed_lines();
  n2k::log_reader<registry::pgns> reader;
  std::uint64_t bytes = 0;
  std::size_t lines = 0;
  sb::for_each_line(text, [&](std::string_view) { ++lines; });
  const std::uint64_t before = sb::allocation_count();
  for (auto _ : state) {
    sb::for_each_line(text, [&](std::string_view line) {
      (void)reader.read_line(
          line, [&](const n2k::message_header&, std::span<const std::uint8_t> payload) {
            bytes += payload.size() + payload[0];
          });
    });
    benchmark::DoNotOptimize(bytes);
  }
  const std::uint64_t allocations = sb::allocation_count() - before;
  if (reader.assembler().frames_dropped() != 0 || reader.assembler().packets() == 0)
    state.SkipWithError("undescribed: a frame was dropped, or nothing assembled");
  sb::report(state, lines, text.size(), allocations);
}

BENCHMARK(baseline)->Name("n2k/mechanism/baseline");
BENCHMARK(numbers)->Name("n2k/mechanism/numbers");
BENCHMARK(lookups)->Name("n2k/mechanism/lookups");
BENCHMARK(flag_words)->Name("n2k/mechanism/flags");
BENCHMARK(numbers64)->Name("n2k/mechanism/numbers64");
BENCHMARK(fixed_strings)->Name("n2k/mechanism/strings/fixed");
BENCHMARK(counted_ascii)->Name("n2k/mechanism/strings/counted_ascii");
BENCHMARK(counted_utf16)->Name("n2k/mechanism/strings/counted_utf16");
BENCHMARK(repeating)->Name("n2k/mechanism/groups/repeating");
BENCHMARK(repeating_to_end)->Name("n2k/mechanism/groups/repeating_to_end");
BENCHMARK(layouts)->Name("n2k/mechanism/layouts/126208");
BENCHMARK(is_fast)->Name("n2k/mechanism/is_fast_packet_pgn");
BENCHMARK(undescribed_fast)->Name("n2k/mechanism/fast_packet/undescribed");

}  // namespace
