// SPDX-License-Identifier: BSL-1.0
#pragma once
// Enumerated fields: a letter (an enum class E : char and its enum_chars) or a word (an enum and
// its enum_words), and their codecs.

#include <array>
#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

#include "seawire/detail/inline.hpp"
#include "seawire/error.hpp"
#include "seawire/nmea/codec.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"

namespace seawire::nmea {

// A single-letter field is an `enum class E : char` whose enumerators are the letters, with a
// function found by ADL listing them:   constexpr std::string_view enum_chars(E) { return "AV"; }
// (C++20 cannot list an enum's enumerators without parsing compiler-specific text, which costs
// every translation unit about 7 ms an enum with GCC and 18 ms with Clang; seawire's tests check
// that each enum_chars lists exactly its enum's enumerators instead.)
// A word field is an enum whose values index an array of its spellings, with
//   constexpr std::array<std::string_view, K> enum_words(E) { return {"ON", "OFF"}; }
// and optionally other spellings accepted on receive:
//   constexpr std::array<std::pair<std::string_view, E>, K> enum_aliases(E) { ... }

template <class E>
concept char_enum_like = std::is_enum_v<E> && requires(E e) {
  { enum_chars(e) } -> std::convertible_to<std::string_view>;
};
template <class E>
concept word_enum_like = std::is_enum_v<E> && requires(E e) {
  enum_words(e);
};
template <class E>
concept has_enum_aliases = requires(E e) {
  enum_aliases(e);
};

/// The wire spelling of an enum value ("A", "ON"); empty if the value is not one of its own.
template <class E>
requires char_enum_like<E> || word_enum_like<E>
[[nodiscard]] constexpr std::string_view to_string(const E& e) noexcept {
  if constexpr (char_enum_like<E>) {
    constexpr std::string_view chars = enum_chars(E{});
    const std::size_t pos = chars.find(static_cast<char>(e));
    return pos == std::string_view::npos ? std::string_view{} : chars.substr(pos, 1);
  } else {
    constexpr auto words = enum_words(E{});
    const auto i = static_cast<std::size_t>(e);
    return i < words.size() ? words[i] : std::string_view{};
  }
}

template <char_enum_like E>
struct codec<E> {
  static constexpr unsigned width = 1;
  static constexpr std::size_t max_chars = 1;
  static constexpr bool allows_blank = false;
  // Which bytes are letters of E: one lookup instead of a search through enum_chars.
  static constexpr std::array<bool, 256> letters = [] {
    std::array<bool, 256> t{};
    for (const char c : std::string_view(enum_chars(E{}))) t[static_cast<unsigned char>(c)] = true;
    return t;
  }();
  SEAWIRE_ALWAYS_INLINE static constexpr errc read(field_reader& r, E& v) noexcept {
    const std::string_view s = r.take().text;
    if (s.size() != 1 || !letters[static_cast<unsigned char>(s[0])]) [[unlikely]]
      return errc::bad_enum;
    v = static_cast<E>(s[0]);
    return errc::ok;
  }
  static constexpr errc check(const E& v) noexcept {
    return letters[static_cast<unsigned char>(static_cast<char>(v))] ? errc::ok : errc::bad_enum;
  }
  static constexpr void write(writer& w, const E& v) noexcept { w.put(static_cast<char>(v)); }
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
  SEAWIRE_ALWAYS_INLINE static constexpr errc read(field_reader& r, E& v) noexcept {
    const std::string_view s = r.take().text;
    constexpr auto words = enum_words(E{});
    for (std::size_t i = 0; i < words.size(); ++i) {
      if (words[i] == s) {
        v = static_cast<E>(i);
        return errc::ok;
      }
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
  static constexpr void write(writer& w, const E& v) noexcept { w.put(to_string(v)); }
};

}  // namespace seawire::nmea
