// SPDX-License-Identifier: BSL-1.0
#pragma once
// Decode by address: a set of message types, and the one a sentence is. Either into a
// std::variant, or straight into a visitor (no variant, one message type on the stack).
//
//   using from_vehicle = message_set<cpnvg, cpnvr, standard::rmc>;
//   auto r = from_vehicle::decode(line, policy);   // result<from_vehicle::variant>
//   from_vehicle::visit(sentence, policy, [](const auto& msg) { ... });

#include <array>
#include <cstddef>
#include <cstdint>
#include <new>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

#include "seawire/detail/byte_order.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"

namespace seawire::nmea {

namespace detail {

/// An address as its length and its first eight bytes packed in an integer (zero beyond the
/// end), so that finding the message of a set compares integers, not strings.
struct address_key {
  std::uint64_t head = 0;
  std::size_t size = 0;
};

[[nodiscard]] constexpr address_key key_of(std::string_view a) noexcept {
  address_key k{0, a.size()};
  for (std::size_t i = 0; i < a.size() && i < 8; ++i)
    k.head |= std::uint64_t{static_cast<unsigned char>(a[i])} << (8U * i);
  return k;
}

/// key_of(s.address), with one 8-byte load where the line is long enough to hold it. A '!'
/// sentence gets the key of no message (size 0: every address has a character), so that it is
/// never taken for a '$' message of the same address.
[[nodiscard]] constexpr address_key key_of(const sentence_view& s) noexcept {
  if (s.start != '$') return {};
  if (s.line.size() < 9 || s.address.data() != s.line.data() + 1) return key_of(s.address);
  std::uint64_t head = seawire::detail::load_le64(s.address.data());  // line[1, 9)
  const std::size_t n = s.address.size();
  if (n < 8) head &= (std::uint64_t{1} << (8U * n)) - 1U;
  return {head, n};
}

/// M::nmea.matches(a), given k == key_of(a): the length and one masked compare for addresses
/// of up to eight characters (all of seawire's but PAPGPSCTRL), the rest by string.
template <class M>
[[nodiscard]] constexpr bool key_matches(const address_key& k, std::string_view a) noexcept {
  using desc = std::remove_cvref_t<decltype(M::nmea)>;
  constexpr std::string_view want = desc::address;
  if (k.size != want.size()) return false;
  if constexpr (want.size() > 8) {
    return M::nmea.matches(a);
  } else if constexpr (desc::any_talker) {
    // Any talker: the first two bytes are not compared ("--" in the declaration).
    constexpr std::uint64_t mask = ~std::uint64_t{0xFFFF};
    constexpr std::uint64_t head = key_of(want).head & mask;
    return (k.head & mask) == head && a[0] != 'P';
  } else {
    constexpr std::uint64_t head = key_of(want).head;
    return k.head == head;
  }
}

/// Finding a sentence's message in a set without trying the set's messages in turn: the
/// addresses' keys hashed at compile time into two tables (exact addresses, and any-talker
/// addresses by the bytes after the talker), each with a multiplier that gives every key of the
/// table a slot of its own. A sentence's key then names at most one candidate in each table,
/// which key_matches confirms; of two, the one first in the set wins, as in the set's order.
struct dispatch_entry {
  std::uint64_t head = 0;  ///< key_of(address).head, the talker's bytes zero for any-talker
  std::size_t size = 0;
  bool any_talker = false;
  std::string_view address;  ///< as declared ("--RMC")

  /// key_matches of the message with this entry, given k == key_of(a).
  [[nodiscard]] constexpr bool matches(const address_key& k, std::string_view a) const noexcept {
    if (k.size != size) return false;
    if (any_talker && a[0] == 'P') return false;  // proprietary, not a talker
    if (size <= 8) return (any_talker ? k.head & ~std::uint64_t{0xFFFF} : k.head) == head;
    for (std::size_t i = any_talker ? 2 : 0; i < size; ++i)
      if (a[i] != address[i]) return false;
    return true;
  }
};

template <class M>
[[nodiscard]] consteval dispatch_entry dispatch_entry_of() noexcept {
  using desc = std::remove_cvref_t<decltype(M::nmea)>;
  dispatch_entry e{key_of(desc::address).head, desc::address.size(), desc::any_talker,
                   desc::address};
  if (e.any_talker) e.head &= ~std::uint64_t{0xFFFF};
  return e;
}

/// The slot of key (head, size) in a table of 2^bits slots hashed with `mult`.
[[nodiscard]] constexpr std::size_t dispatch_slot(std::uint64_t head, std::size_t size,
                                                  std::uint64_t mult, unsigned bits) noexcept {
  const std::uint64_t x = (head + std::uint64_t{size} * 0x9E3779B97F4A7C15U) * mult;
  return static_cast<std::size_t>(x >> (64U - bits));
}

/// What a dispatch table is built from: its size (2^bits slots in each of its two tables) and
/// each table's multiplier; not usable when some keys cannot be separated.
struct dispatch_plan {
  static constexpr unsigned max_bits = 9;
  bool usable = false;
  unsigned bits = 1;
  std::uint64_t mult[2] = {0, 0};  ///< [0] exact addresses, [1] any-talker addresses
};

/// Tries multipliers (a fixed sequence) and table sizes until every key of each table has a slot
/// of its own. Keys that are equal (two long addresses alike in their first eight bytes and
/// their length) can never be told apart: the plan is then not usable.
template <std::size_t N>
[[nodiscard]] consteval dispatch_plan plan_dispatch(
    const std::array<dispatch_entry, N>& entries) noexcept {
  static_assert(N < 255, "a set of at most 254 messages");
  dispatch_plan plan;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j)
      if (entries[i].any_talker == entries[j].any_talker && entries[i].head == entries[j].head &&
          entries[i].size == entries[j].size)
        return plan;
  unsigned bits = 1;
  while ((std::size_t{1} << bits) < 2 * N) ++bits;
  for (; bits <= dispatch_plan::max_bits; ++bits) {
    bool both = true;
    for (unsigned table = 0; table < 2 && both; ++table) {
      bool found = false;
      std::uint64_t state = 0x243F6A8885A308D3U + table;
      for (int attempt = 0; attempt < 64 && !found; ++attempt) {
        // splitmix64: the candidate multiplier, made odd.
        state += 0x9E3779B97F4A7C15U;
        std::uint64_t z = state;
        z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9U;
        z = (z ^ (z >> 27U)) * 0x94D049BB133111EBU;
        const std::uint64_t mult = (z ^ (z >> 31U)) | 1U;
        std::array<bool, std::size_t{1} << dispatch_plan::max_bits> taken{};
        found = true;
        for (std::size_t i = 0; i < N && found; ++i) {
          if (entries[i].any_talker != (table == 1)) continue;
          bool& slot = taken[dispatch_slot(entries[i].head, entries[i].size, mult, bits)];
          found = !slot;
          slot = true;
        }
        if (found) plan.mult[table] = mult;
      }
      both = found;
    }
    if (both) {
      plan.bits = bits;
      plan.usable = true;
      return plan;
    }
  }
  return dispatch_plan{};
}

/// One slot of a dispatch table: the key a sentence has when it is the message at `index` (an
/// empty slot has a size no key has).
struct dispatch_slot_entry {
  std::uint64_t head = 0;  ///< the key's head; in the any-talker table, the talker's bytes zero
  std::uint64_t size = ~std::uint64_t{0};
  std::uint8_t index = 0xFF;
};

template <std::size_t N, unsigned Bits>
struct dispatch_table {
  std::array<dispatch_entry, N> entries{};
  bool usable = false;      ///< false: some keys could not be separated (the set is tried in turn)
  bool any_talker = false;  ///< some message of the set takes any talker
  /// A sentence whose address is in the exact table is that message: no any-talker message
  /// before it in the set matches its address.
  bool exact_final = true;
  std::uint64_t mult[2] = {0, 0};  ///< [0] exact addresses, [1] any-talker addresses
  std::array<dispatch_slot_entry, std::size_t{1} << Bits> slots[2] = {};

  /// The index in the set of the first message whose address is `a` (k == key_of(a)), or N: at
  /// most one candidate in each table, confirmed by the whole key (and the address beyond its
  /// eighth byte).
  [[nodiscard]] constexpr std::size_t find(const address_key& k,
                                           std::string_view a) const noexcept {
    std::size_t best = N;
    const dispatch_slot_entry& e = slots[0][dispatch_slot(k.head, k.size, mult[0], Bits)];
    if (e.head == k.head && e.size == k.size && (k.size <= 8 || entries[e.index].matches(k, a))) {
      if (exact_final) return e.index;
      best = e.index;
    }
    if (!any_talker) return best;
    const std::uint64_t masked = k.head & ~std::uint64_t{0xFFFF};
    const dispatch_slot_entry& t = slots[1][dispatch_slot(masked, k.size, mult[1], Bits)];
    if (t.index < best && t.head == masked && t.size == k.size && a[0] != 'P' &&
        (k.size <= 8 || entries[t.index].matches(k, a)))
      best = t.index;
    return best;
  }
};

/// The table of `entries` by `plan` (plan_dispatch's for them).
template <std::size_t N, unsigned Bits>
[[nodiscard]] consteval dispatch_table<N, Bits> make_dispatch_table(
    const std::array<dispatch_entry, N>& entries, const dispatch_plan& plan) noexcept {
  dispatch_table<N, Bits> t;
  t.entries = entries;
  if (!plan.usable) return t;
  t.usable = true;
  t.mult[0] = plan.mult[0];
  t.mult[1] = plan.mult[1];
  for (std::size_t i = 0; i < N; ++i) {
    const dispatch_entry& e = entries[i];
    const unsigned table = e.any_talker ? 1U : 0U;
    t.any_talker = t.any_talker || e.any_talker;
    dispatch_slot_entry& slot =
        t.slots[table][dispatch_slot(e.head, e.size, plan.mult[table], Bits)];
    slot = {e.head, e.size, static_cast<std::uint8_t>(i)};
    // An any-talker message before an exact one that matches its address takes it.
    if (e.any_talker) continue;
    for (std::size_t j = 0; j < i; ++j) {
      const dispatch_entry& before = entries[j];
      if (!before.any_talker) continue;
      const address_key k{e.head, e.size};
      if (before.matches(k, e.address)) t.exact_final = false;
    }
  }
  return t;
}

/// Sets this large or larger find a message by the tables; smaller ones try each in turn, which
/// costs less there: a few instructions a message tried, and the message's decoder inlined
/// where it is found, against a fixed ~40 (callgrind: 8 messages tried in turn take 22 fewer
/// instructions a sentence to visit and 44 fewer to decode; 36, 38 more to visit).
inline constexpr std::size_t dispatch_by_table_from = 16;

template <class... Ms>
inline constexpr std::array<dispatch_entry, sizeof...(Ms)> dispatch_entries_of = {
    dispatch_entry_of<Ms>()...};
template <class... Ms>
inline constexpr dispatch_plan dispatch_plan_of = plan_dispatch(dispatch_entries_of<Ms...>);
template <class... Ms>
inline constexpr dispatch_table<sizeof...(Ms), dispatch_plan_of<Ms...>.bits> dispatch_table_of =
    make_dispatch_table<sizeof...(Ms), dispatch_plan_of<Ms...>.bits>(dispatch_entries_of<Ms...>,
                                                                     dispatch_plan_of<Ms...>);

/// Whether message_set<Ms...> finds a sentence's message by its table rather than in turn.
template <class... Ms>
[[nodiscard]] consteval bool use_dispatch_table() noexcept {
  if constexpr (sizeof...(Ms) >= dispatch_by_table_from) {
    return dispatch_table_of<Ms...>.usable;
  } else {
    return false;
  }
}

/// The first of a list of types.
template <class First, class...>
struct first_type {
  using type = First;
};

}  // namespace detail

/// A well-formed sentence that no message of the set describes: an address the set does not
/// know, or any '!' sentence (!AIVDM: messages are '$' sentences; sentence.start says which
/// start it had). Views into the input: it is valid as long as the line it came from.
struct unknown_sentence {
  sentence_view sentence;
};

namespace detail {
/// Whether Set's decoder is compiled once, by <seawire/impl/src.hpp> (SEAWIRE_SEPARATE_COMPILATION;
/// a family header says so for its sets with SEAWIRE_COMPILED_SET).
template <class Set>
inline constexpr bool compiled_set = false;
/// Set::decode, not inline: where it is declared `extern template`, callers only reference it.
template <class Set>
[[nodiscard]] result<typename Set::variant> compiled_set_decode(const sentence_view& s,
                                                                const parse_policy& p) noexcept;
/// Set::decode of a line (the parse, then compiled_set_decode), likewise: a role decoder's
/// caller compiles neither.
template <class Set>
[[nodiscard]] result<typename Set::variant> compiled_set_decode_line(
    std::string_view line, const parse_policy& p) noexcept;
}  // namespace detail

template <message_like... Ms>
struct message_set {
  using variant = std::variant<unknown_sentence, Ms...>;
  static constexpr std::size_t size = sizeof...(Ms);

  /// Whether some message of the set has this address.
  [[nodiscard]] static constexpr bool knows(std::string_view address) noexcept {
    return index_of(address) < size;
  }

  /// The declared name of wire field `n` of the message with this address ("" if unknown);
  /// `field_count` as nmea::field_name's (the sentence's, for a sentence with a shorter form).
  [[nodiscard]] static constexpr std::string_view field_name(
      std::string_view address, std::size_t n,
      std::size_t field_count = static_cast<std::size_t>(-1)) noexcept {
    return about_field(address, n, field_count).name;
  }

  /// What the description of the message with this address says of its wire field `n`.
  [[nodiscard]] static constexpr field_about about_field(
      std::string_view address, std::size_t n,
      std::size_t field_count = static_cast<std::size_t>(-1)) noexcept {
    field_about a;
    with_message(index_of(address), [&]<class M>() { a = nmea::about_field<M>(n, field_count); });
    return a;
  }

  /// Decode into whichever message the address names; an address the set does not know, or a
  /// '!' sentence, gives unknown_sentence (not an error: receivers are told to ignore such
  /// messages).
  [[nodiscard]] static constexpr result<variant> decode(const sentence_view& s,
                                                        const parse_policy& p = {}) noexcept {
    if constexpr (detail::compiled_set<message_set>) {
      return detail::compiled_set_decode<message_set>(s, p);
    } else {
      return decode_here(s, p);
    }
  }
  [[nodiscard]] static constexpr result<variant> decode(std::string_view line,
                                                        const parse_policy& p = {}) noexcept {
    if constexpr (detail::compiled_set<message_set>) {
      return detail::compiled_set_decode_line<message_set>(line, p);
    } else {
      return decode_line_here(line, p);
    }
  }

  /// decode(line) here, not in a separately compiled set: a line in the plain form of a
  /// message that has one-pass readers is read in one pass (one_pass.hpp); any other line, and
  /// any the one-pass path gives up on, through parse() and decode_here().
  [[nodiscard]] static constexpr result<variant> decode_line_here(std::string_view line,
                                                                  const parse_policy& p) noexcept {
    // Every path returns a result it builds in its return statement, so that the result is
    // built where the caller wants it, never copied there and never cleared first (GCC clears
    // a result<variant> it builds from a constant, or emplaces a message into: a `rep stos`
    // over the largest message, ~15 ns a sentence).
    if constexpr ((detail::plain_decodable<Ms> || ...)) {
      detail::plain_line l;
      if (detail::frame_plain(line, p, l)) {
        auto read = [&]<class M>() SEAWIRE_INLINE_LAMBDA { return read_plain_one<M>(l, line, p); };
        auto otherwise = [&]() SEAWIRE_INLINE_LAMBDA { return decode_general(line, p); };
        return dispatch(find(detail::address_key{l.head, l.address.size()}, l.address), read,
                        otherwise);
      }
    }
    return decode_general(line, p);
  }

  /// decode(s, p) compiled where it is called (what a set compiled once runs in that one place).
  [[nodiscard]] static constexpr result<variant> decode_here(const sentence_view& s,
                                                             const parse_policy& p) noexcept {
    auto read = [&]<class M>() SEAWIRE_INLINE_LAMBDA { return decode_one<M>(s, p); };
    auto otherwise = [&]() SEAWIRE_INLINE_LAMBDA {
      return result<variant>{variant(std::in_place_type<unknown_sentence>, unknown_sentence{s})};
    };
    return dispatch(find(detail::key_of(s), s.address), read, otherwise);
  }

  /// The index in the set of the message a sentence with this address decodes as (the first
  /// whose address it is), or size: what decode and visit dispatch on.
  [[nodiscard]] static constexpr std::size_t index_of(std::string_view address) noexcept {
    return find(detail::key_of(address), address);
  }

  /// visit() of a line: a line in the plain form of a message with one-pass readers is read in
  /// one pass and handed over; any other through parse() and visit() of its sentence_view, and
  /// a line parse() refuses is the error (on_message is not called).
  template <class F>
  static constexpr result<bool> visit(std::string_view line, const parse_policy& p,
                                      F&& on_message) {
    if constexpr (!detail::compiled_set<message_set> && (detail::plain_decodable<Ms> || ...)) {
      if (read_plain(line, p, [&]<class M>(const detail::plain_line& l) {
            bool done = false;
            detail::with_default_initialized<M>([&](M& m) {
              done = detail::decode_plain(l, p, m);
              if (done) on_message(static_cast<const M&>(m));
            });
            return done;
          }))
        return result<bool>{true};
    }
    const result<sentence_view> s = parse(line, p);
    if (!s) return detail::parse_failure<bool>(s);
    return visit(s.value, p, on_message);
  }

  /// Decode and call `on_message(const M&)` for the matching message, or
  /// `on_message(const unknown_sentence&)`. Returns the decode error (visitor not called) or
  /// success.
  template <class F>
  static constexpr result<bool> visit(const sentence_view& s, const parse_policy& p,
                                      F&& on_message) {
    if constexpr (detail::compiled_set<message_set>) {
      // The set's decoder is compiled once: decode through it, then call on_message here.
      const result<variant> r = detail::compiled_set_decode<message_set>(s, p);
      const result<bool> told{r.value.index() != 0 || !r, r.ec, r.field, r.column};
      if (r) std::visit([&](const auto& m) { on_message(m); }, r.value);
      return told;
    } else {
      result<bool> out;
      const std::size_t i = find(detail::key_of(s), s.address);
      with_message(i, [&]<class M>() { visit_one<M>(out, s, p, on_message); });
      if (i == size) {
        on_message(unknown_sentence{s});
        out.value = false;
      }
      return out;
    }
  }

 private:
  /// The index in the set of the first message whose address `a` is (k == key_of(a)), or size:
  /// by the set's compile-time table (dispatch_table) when it has one, else by trying the
  /// messages in the set's order.
  [[nodiscard]] static constexpr std::size_t find(const detail::address_key& k,
                                                  std::string_view a) noexcept {
    if constexpr (detail::use_dispatch_table<Ms...>()) {
      return detail::dispatch_table_of<Ms...>.find(k, a);
    } else {
      std::size_t i = 0;
      (void)((detail::key_matches<Ms>(k, a) || (++i, false)) || ...);
      return i;
    }
  }

  /// f.template operator()<M>() for the i-th message M of the set, otherwise() for i == size:
  /// whatever they return (the same type, void included), built where the caller wants it (a
  /// decode's result<variant>). A set with a table calls through an array of one function per
  /// message; a set tried in turn compares i with each index, where the compiler can fold it
  /// into the search before.
  template <class F, class Otherwise>
  SEAWIRE_ALWAYS_INLINE static constexpr decltype(auto) dispatch(std::size_t i, F& f,
                                                                 Otherwise&& otherwise) {
    if constexpr (detail::use_dispatch_table<Ms...>()) {
      if (i < size) return by_index<F>::fn[i](f);
      return otherwise();
    } else {
      return dispatch_from<0, Ms...>(i, f, otherwise);
    }
  }
  template <std::size_t I, class M, class... Rest, class F, class Otherwise>
  SEAWIRE_ALWAYS_INLINE static constexpr decltype(auto) dispatch_from(std::size_t i, F& f,
                                                                      Otherwise& otherwise) {
    if (i == I) return f.template operator()<M>();
    if constexpr (sizeof...(Rest) > 0) {
      return dispatch_from<I + 1, Rest...>(i, f, otherwise);
    } else {
      return otherwise();
    }
  }
  /// f.template operator()<M>() where the table calls it (one function per message).
  template <class M, class F>
  static constexpr decltype(auto) call_one(F& f) {
    return f.template operator()<M>();
  }
  // call_one<M> of each message, by index in the set (defined once the set is).
  template <class F>
  struct by_index {
    using fn_type =
        decltype(&message_set::template call_one<typename detail::first_type<Ms...>::type, F>);
    // With its bound: Clang 14 refuses, in a constant expression, the first read of an array
    // whose bound it has not yet deduced.
    static constexpr fn_type fn[sizeof...(Ms)] = {&message_set::template call_one<Ms, F>...};
  };
  /// dispatch() of a callable that returns nothing, nothing done for an unknown index.
  template <class F>
  static constexpr void with_message(std::size_t i, F&& f) {
    dispatch(i, f, [] {});
  }

  /// M read in one pass from l into a default-initialized M of its own (not into the result:
  /// emplacing a message into a variant clears it whole first), then copied into the result it
  /// returns; the general path when M has no one-pass reader or its reader gives the line up.
  template <class M>
  [[nodiscard]] static constexpr result<variant> read_plain_one(const detail::plain_line& l,
                                                                std::string_view line,
                                                                const parse_policy& p) noexcept {
    if constexpr (detail::plain_decodable<M>) {
      return detail::with_default_initialized<M>([&](M& m) SEAWIRE_INLINE_LAMBDA {
        if (detail::decode_plain(l, p, m))
          return result<variant>{variant(std::in_place_type<M>, std::as_const(m))};
        return decode_general(line, p);
      });
    } else {
      return decode_general(line, p);
    }
  }

  /// decode(line) through parse() and decode_here(): a line not in its plain form, or one the
  /// one-pass path gave up on.
  [[nodiscard]] static constexpr result<variant> decode_general(std::string_view line,
                                                                const parse_policy& p) noexcept {
    const result<sentence_view> s = parse(line, p);
    if (!s) return detail::parse_failure<variant>(s);
    return decode_here(s.value, p);
  }

  /// The one-pass path of decode(line) and visit(line): when the line is in its plain form and
  /// the message its address names has one-pass readers, `read.template operator()<M>(l)` reads
  /// it and says whether it did; false (not read) sends the line to the general path.
  template <class Read>
  SEAWIRE_ALWAYS_INLINE static constexpr bool read_plain(std::string_view line,
                                                         const parse_policy& p, Read&& read) {
    detail::plain_line l;
    if (!detail::frame_plain(line, p, l)) return false;
    bool done = false;
    with_message(find(detail::address_key{l.head, l.address.size()}, l.address), [&]<class M>() {
      if constexpr (detail::plain_decodable<M>)
        done = read.template operator()<M>(static_cast<const detail::plain_line&>(l));
    });
    return done;
  }

  /// M decoded from a split sentence into a default-initialized M of its own, then copied into
  /// the result it returns; on an error, unknown_sentence with the error's field and column.
  template <class M>
  [[nodiscard]] static constexpr result<variant> decode_one(const sentence_view& s,
                                                            const parse_policy& p) noexcept {
    return detail::with_default_initialized<M>([&](M& m) SEAWIRE_INLINE_LAMBDA {
      const detail::decode_status d = detail::decode_into(s, p, m);
      if (d.ec == errc::ok)
        return result<variant>{variant(std::in_place_type<M>, std::as_const(m))};
      return result<variant>{variant(std::in_place_type<unknown_sentence>, unknown_sentence{s}),
                             d.ec, d.field, d.column};
    });
  }
  template <class M, class F>
  static constexpr void visit_one(result<bool>& out, const sentence_view& s, const parse_policy& p,
                                  F& on_message) {
    detail::with_default_initialized<M>([&](M& m) {
      detail::decode_into(s, p, m).copy_to(out);
      out.value = true;
      if (out) on_message(static_cast<const M&>(m));
    });
  }
};

namespace detail {
template <class Set>
result<typename Set::variant> compiled_set_decode(const sentence_view& s,
                                                  const parse_policy& p) noexcept {
  return Set::decode_here(s, p);
}
template <class Set>
result<typename Set::variant> compiled_set_decode_line(std::string_view line,
                                                       const parse_policy& p) noexcept {
  return Set::decode_line_here(line, p);
}

// Appends each of Ms to Set unless it is already there.
template <class Set, class... Ms>
struct append_unique {
  using type = Set;
};
template <class... A, class M, class... Rest>
struct append_unique<message_set<A...>, M, Rest...> {
  using type = typename append_unique<
      std::conditional_t<(std::is_same_v<A, M> || ...), message_set<A...>, message_set<A..., M>>,
      Rest...>::type;
};
}  // namespace detail

/// `lazy<T, N>` is `T` (a message set, a message, an enum), named so that it depends on `N`. A
/// role decoder is a function template of nothing (`template <int N = 0>`) whose body calls
/// `lazy<Set, N>::decode` and whose return type is `result<typename lazy<Set, N>::variant>`: the
/// set's decoder and variant are then compiled only where the role decoder is called. (What does
/// not depend on a template parameter is compiled where the header is read: Clang instantiates
/// the constexpr functions a template definition names, and the types its signature names, at
/// once.) The
/// RobotX scheduler and validator and the Sandshark sessions name their messages the same way.
template <class Set, int>
struct lazy_set {
  using type = Set;
};
template <class Set, int N>
using lazy = typename lazy_set<Set, N>::type;

/// The union of several sets (a decoder for every family at once). A message in more than one
/// set (standard::rmc is in kingfisher::from_vehicle and anello::nmea_outputs) appears once, at
/// its first place, so the union can still decode into a variant.
template <class... Sets>
struct merge_sets;
template <message_like... A>
struct merge_sets<message_set<A...>> {
  using type = typename detail::append_unique<message_set<>, A...>::type;
};
template <message_like... A, message_like... B, class... Rest>
struct merge_sets<message_set<A...>, message_set<B...>, Rest...> {
  using type = typename merge_sets<message_set<A..., B...>, Rest...>::type;
};

}  // namespace seawire::nmea

// In a family header, at global scope: the set's decoder is compiled once, by
// <seawire/impl/src.hpp>, when SEAWIRE_SEPARATE_COMPILATION is defined; otherwise nothing.
#if defined(SEAWIRE_SEPARATE_COMPILATION)
#define SEAWIRE_COMPILED_SET(Set)                                                                \
  template <>                                                                                    \
  inline constexpr bool seawire::nmea::detail::compiled_set<Set> = true;                         \
  extern template seawire::result<Set::variant> seawire::nmea::detail::compiled_set_decode<Set>( \
      const seawire::nmea::sentence_view&, const seawire::nmea::parse_policy&) noexcept;         \
  extern template seawire::result<Set::variant>                                                  \
  seawire::nmea::detail::compiled_set_decode_line<Set>(                                          \
      std::string_view, const seawire::nmea::parse_policy&) noexcept;
#else
#define SEAWIRE_COMPILED_SET(Set)
#endif
