// SPDX-License-Identifier: BSL-1.0
#pragma once
// Enumerated fields: a letter (an enum class E : char, its enumerators the letters) or a word (an
// enum and its enum_words), and their codecs.

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>

#include "seawire/detail/enum_names.hpp"
#include "seawire/detail/inline.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/codec.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"

namespace seawire::nmea {

// A single-letter field is an `enum class E : char` whose enumerators are its letters:
//   enum class rmc_status : char { active = 'A', warning = 'V' };
// The letters a field accepts and writes are those enumerators, read from the enum itself
// (enum_letters<E> below): an enumerator added is a letter accepted, and there is no second list
// to keep in step. Letters are the digits and ASCII letters, the only ones NMEA sentences use for
// such fields: an enumerator that is a space or punctuation is a compile error.
// A word field is an enum whose values index an array of its spellings, with
//   constexpr std::array<std::string_view, K> enum_words(E) { return {"ON", "OFF"}; }
// and optionally other spellings accepted on receive:
//   constexpr std::array<std::pair<std::string_view, E>, K> enum_aliases(E) { ... }

template <class E>
concept word_enum_like = std::is_enum_v<E> && requires(E e) {
  enum_words(e);
};
template <class E>
concept char_enum_like = std::is_enum_v<E> && std::is_same_v < std::underlying_type_t<E>,
char > &&!word_enum_like<E>;
template <class E>
concept has_enum_aliases = requires(E e) {
  enum_aliases(e);
};

namespace detail {

// An enum's letters are read from the compiler's listing of candidate values
// (seawire::detail::enum_listing): one instantiation with every candidate letter tells which are
// enumerators, one with the other printable bytes that none is. They are made only where a letter
// field is decoded, encoded or printed (about 10 ms of GCC's time, 25 of Clang's, an enum), never
// where a header is merely included.
inline constexpr std::string_view letter_candidates =
    "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";
// The other printable bytes: an enumerator that is one of them could be declared but never sent
// or read (most are NMEA's own delimiters), so it is a compile error, not a letter dropped.
inline constexpr std::string_view non_letter_candidates = " !\"#$%&'()*+,-./:;<=>?@[\\]^_`{|}~";

struct letter_set {
  std::array<char, 62> chars{};
  std::size_t size = 0;
  bool parsed = false;  ///< the listing had one element per candidate
};

// Which elements of `listing`'s argument list are names, in candidate order.
constexpr letter_set enumerators_among_candidates(std::string_view listing,
                                                  std::string_view candidates = letter_candidates) {
  letter_set out;
  std::size_t element = 0;
  bool too_many = false;
  const std::size_t n = seawire::detail::for_each_listed(listing, [&](std::string_view e) {
    if (element >= candidates.size()) {
      too_many = true;
      return;
    }
    if (!seawire::detail::is_cast_or_number(e)) out.chars[out.size++] = candidates[element];
    ++element;
  });
  out.parsed = !too_many && n == candidates.size();
  return out;
}

template <class E, std::size_t... I>
consteval letter_set probe_letters(std::index_sequence<I...>) {
  return enumerators_among_candidates(
      seawire::detail::enum_listing<static_cast<E>(letter_candidates[I])...>());
}
template <class E, std::size_t... I>
consteval letter_set probe_non_letters(std::index_sequence<I...>) {
  return enumerators_among_candidates(
      seawire::detail::enum_listing<static_cast<E>(non_letter_candidates[I])...>(),
      non_letter_candidates);
}

#if defined(__clang__)
// Clang prints every value of an enum declared in a class template as a cast, enumerators
// included, until one of them has been named in the translation unit: such an enum's letters
// cannot be read reliably, so it is refused (an explicit specialization's enum too).
template <class T>
constexpr std::string_view type_listing() noexcept {
  return __PRETTY_FUNCTION__;
}
template <class T>
constexpr bool declared_in_class_template() noexcept {
  const std::string_view s = type_listing<T>();
  const std::size_t at = s.find("T = ");
  return at != std::string_view::npos && s.find('<', at) != std::string_view::npos;
}
#endif

template <class E>
struct letters_of {
#if defined(__clang__)
  static_assert(!declared_in_class_template<E>(),
                "with Clang, a letter field's enum cannot be declared in a class template (Clang "
                "does not list its enumerators): declare it at namespace scope or in a class");
#endif
  static constexpr letter_set set =
      probe_letters<E>(std::make_index_sequence<letter_candidates.size()>{});
  static_assert(set.parsed,
                "seawire cannot read this compiler's listing of an enum's enumerators; please "
                "report the compiler and its version");
  static_assert(set.size > 0,
                "a letter field's enum (enum class E : char) needs at least one enumerator whose "
                "value is a digit or an ASCII letter");
  static constexpr letter_set others =
      probe_non_letters<E>(std::make_index_sequence<non_letter_candidates.size()>{});
  static_assert(others.parsed && others.size == 0,
                "a letter field's enumerators are digits and ASCII letters: one that is a space "
                "or punctuation could never be sent or read");
  // The letters alone, in an array of their exact size.
  static constexpr std::array<char, set.size> chars = [] {
    std::array<char, set.size> a{};
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = set.chars[i];
    return a;
  }();
};

}  // namespace detail

/// The letters of a letter field's enum E, in increasing order: "AV" for
/// `enum class rmc_status : char { active = 'A', warning = 'V' }`.
template <char_enum_like E>
inline constexpr std::string_view enum_letters{detail::letters_of<E>::chars.data(),
                                               detail::letters_of<E>::chars.size()};

/// Whether `c` is one of E's letters. (A loop, not string_view::find: GCC 12 cannot evaluate
/// that search over these letters in a constant expression.)
template <char_enum_like E>
[[nodiscard]] constexpr bool is_enum_letter(char c) noexcept {
  for (const char letter : enum_letters<E>) {
    if (letter == c) return true;
  }
  return false;
}

/// The wire spelling of an enum value ("A", "ON"); empty if the value is not one of its own.
template <class E>
requires char_enum_like<E> || word_enum_like<E>
[[nodiscard]] constexpr std::string_view to_string(const E& e) noexcept {
  if constexpr (char_enum_like<E>) {
    constexpr std::string_view chars = enum_letters<E>;
    for (std::size_t i = 0; i < chars.size(); ++i) {
      if (chars[i] == static_cast<char>(e)) return chars.substr(i, 1);
    }
    return {};
  } else {
    constexpr auto words = enum_words(E{});
    return seawire::detail::name_at(words, static_cast<std::size_t>(e));
  }
}

template <char_enum_like E>
struct codec<E> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = 1;
  static constexpr bool allows_blank = false;
  /// scan() refuses a blank field at its first byte (one_pass.hpp: scans_no_blank).
  static constexpr bool scan_refuses_blank = true;
  // Which bytes are letters of E: one lookup instead of a search through enum_letters.
  static constexpr std::array<bool, 256> letters = [] {
    std::array<bool, 256> t{};
    for (const char c : enum_letters<E>) t[static_cast<unsigned char>(c)] = true;
    return t;
  }();
  static constexpr errc read(field_reader& r, E& v) noexcept {
    const std::string_view s = r.take().text;
    if (s.size() != 1 || !letters[static_cast<unsigned char>(s[0])]) [[unlikely]]
      return errc::bad_enum;
    v = static_cast<E>(s[0]);
    return errc::ok;
  }
  /// The one-pass reader: one of E's letters (the caller checks that the field ends there).
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan(const char* p, const char*,
                                                          E& v) noexcept {
    if (!letters[static_cast<unsigned char>(*p)]) [[unlikely]]
      return nullptr;
    v = static_cast<E>(*p);
    return p + 1;
  }
  static constexpr errc check(const E& v) noexcept {
    return letters[static_cast<unsigned char>(static_cast<char>(v))] ? errc::ok : errc::bad_enum;
  }
  template <sentence_writer W>
  static constexpr void write(W& w, const E& v) noexcept {
    w.put(static_cast<char>(v));
  }
};

template <word_enum_like E>
struct codec<E> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = [] {
    std::size_t n = 0;
    for (const std::string_view w : enum_words(E{})) n = w.size() > n ? w.size() : n;
    return n;
  }();
  static constexpr bool allows_blank = false;
  /// scan() refuses a blank field at its first byte (one_pass.hpp: scans_no_blank).
  static constexpr bool scan_refuses_blank = true;
  static constexpr errc read(field_reader& r, E& v) noexcept { return from_word(r.take().text, v); }
  /// The one-pass reader: the word at `p`, up to the next ',' or `end`.
  SEAWIRE_ALWAYS_INLINE static constexpr const char* scan(const char* p, const char* end,
                                                          E& v) noexcept {
    const char* q = p;
    while (q != end && *q != ',') ++q;
    return from_word(std::string_view(p, static_cast<std::size_t>(q - p)), v) == errc::ok ? q
                                                                                          : nullptr;
  }
  /// E's value named `s`, by one of its words or aliases.
  static constexpr errc from_word(std::string_view s, E& v) noexcept {
    constexpr auto words = enum_words(E{});
    if (const std::optional<std::size_t> i = seawire::detail::index_of_name(words, s)) {
      v = static_cast<E>(*i);
      return errc::ok;
    }
    if constexpr (has_enum_aliases<E>) {
      for (const auto& [word, value] : enum_aliases(E{})) {
        if (word == s) {
          v = value;
          return errc::ok;
        }
      }
    }
    return errc::bad_enum;
  }
  static constexpr errc check(const E& v) noexcept {
    return to_string(v).empty() ? errc::bad_enum : errc::ok;
  }
  template <sentence_writer W>
  static constexpr void write(W& w, const E& v) noexcept {
    w.put(to_string(v));
  }
};

}  // namespace seawire::nmea
