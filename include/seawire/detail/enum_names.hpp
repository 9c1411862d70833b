// SPDX-License-Identifier: BSL-1.0
#pragma once
// An enum's names as a table indexed by its values (internal): enum_words, lookup_names, status
// texts, and the names of enumerators as the compiler spells them (enumerator_names). A value the
// table does not name has an empty entry or lies past its end.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>

namespace seawire::detail {

/// The name of value `v`: names[v], empty past the table's end.
template <class Names>
[[nodiscard]] constexpr std::string_view name_at(const Names& names, std::uint64_t v) noexcept {
  return v < names.size() ? std::string_view(names[v]) : std::string_view{};
}

/// The index of the first entry `name`; nullopt when none (an empty entry is never found).
template <class Names>
[[nodiscard]] constexpr std::optional<std::size_t> index_of_name(const Names& names,
                                                                 std::string_view name) noexcept {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (!names[i].empty() && names[i] == name) return i;
  return std::nullopt;
}

// C++20 cannot list an enum's enumerators, but every compiler prints a template's arguments in
// its function-name string, an enumerator by its name and any other value as a cast:
//   GCC    "... [with auto ...V = {ns::e::a, (ns::e)66}; ...]"
//   Clang  "... [V = <ns::e::a, (ns::e)66>]", "<(anonymous namespace)::e::a, ...>"
//   MSVC   "... enum_listing<ns::e::a,(enum ns::e)0x42>(void)"
// One instantiation lists as many values as it is given.
template <auto... V>
constexpr std::string_view enum_listing() noexcept {
#if defined(_MSC_VER) && !defined(__clang__)
  return __FUNCSIG__;
#else
  return __PRETTY_FUNCTION__;
#endif
}

/// Whether one element of a listing is a cast ("(ns::e)66", "((anonymous namespace)::e)66") or a
/// bare number ("0x42"), which is no enumerator, rather than a name ("(anonymous
/// namespace)::e::a").
[[nodiscard]] constexpr bool is_cast_or_number(std::string_view element) noexcept {
  const auto digit = [](char c) { return c == '-' || (c >= '0' && c <= '9'); };
  if (element.empty() || digit(element[0])) return true;
  if (element[0] != '(') return false;
  int depth = 0;
  for (std::size_t i = 0; i < element.size(); ++i) {
    if (element[i] == '(') ++depth;
    if (element[i] == ')' && --depth == 0) return i + 1 < element.size() && digit(element[i + 1]);
  }
  return true;
}

/// The enumerator an element of a listing names, unqualified ("a" of "ns::e::a"); empty for a
/// cast or a number.
[[nodiscard]] constexpr std::string_view listed_name(std::string_view element) noexcept {
  if (is_cast_or_number(element)) return {};
  const std::size_t colon = element.rfind("::");
  return colon == std::string_view::npos ? element : element.substr(colon + 2);
}

/// Calls fn(element) for each element of `listing`'s argument list, in order. Returns the number
/// of elements, or 0 when the listing cannot be read (no list, or one that does not end).
template <class Fn>
constexpr std::size_t for_each_listed(std::string_view listing, Fn&& fn) {
  std::size_t at = listing.find("V = ");
  if (at != std::string_view::npos) {
    at += 5;  // past "V = {" or "V = <"
  } else if ((at = listing.find("enum_listing<")) != std::string_view::npos) {
    at += 13;
  } else {
    return 0;
  }
  std::size_t count = 0;
  while (at < listing.size()) {
    while (at < listing.size() && listing[at] == ' ') ++at;
    // To the ',' that ends this element, or the bracket that ends the list.
    const std::size_t begin = at;
    int depth = 0;
    bool last = false;
    for (; at < listing.size(); ++at) {
      const char c = listing[at];
      if (c == '(' || c == '<' || c == '[' || c == '{') {
        ++depth;
      } else if (c == ')' || c == '>' || c == ']' || c == '}') {
        if (depth == 0) {
          last = true;
          break;
        }
        --depth;
      } else if (c == ',' && depth == 0) {
        break;
      }
    }
    if (at >= listing.size()) return 0;
    fn(listing.substr(begin, at - begin));
    ++count;
    if (last) return count;
    ++at;
  }
  return 0;
}

/// The name of enumerator V as declared ("missing_frame"); empty when V is no enumerator.
template <auto V>
[[nodiscard]] consteval std::string_view enumerator_name() noexcept {
  std::string_view name;
  (void)for_each_listed(enum_listing<V>(), [&](std::string_view e) { name = listed_name(e); });
  return name;
}

template <class E, std::size_t Count>
struct enumerator_table {
  std::array<std::string_view, Count> names{};
  std::size_t listed = 0;    ///< elements read from the listing: Count + 1 when it was read
  bool count_named = false;  ///< the value Count is an enumerator too
};

template <class E, std::size_t Count, std::size_t... I>
consteval enumerator_table<E, Count> read_enumerators(std::index_sequence<I...>) {
  enumerator_table<E, Count> t;
  t.listed = for_each_listed(enum_listing<static_cast<E>(I)..., static_cast<E>(Count)>(),
                             [&](std::string_view e) {
                               if (t.listed < Count) {
                                 t.names[t.listed++] = listed_name(e);
                               } else {
                                 t.count_named = !listed_name(e).empty();
                               }
                             });
  return t;
}

/// The names of E's enumerators 0 to Count - 1, in value order, from one listing. A compile
/// error unless each of those values is an enumerator and Count is none: the table is the enum,
/// whole.
template <class E, std::size_t Count>
inline constexpr std::array<std::string_view, Count> enumerator_names = [] {
  constexpr enumerator_table<E, Count> t =
      read_enumerators<E, Count>(std::make_index_sequence<Count>{});
  static_assert(t.listed == Count + 1,
                "seawire cannot read this compiler's listing of an enum's enumerators; please "
                "report the compiler and its version");
  static_assert(
      [&] {
        for (const std::string_view n : t.names)
          if (n.empty()) return false;
        return true;
      }(),
      "a value below Count is no enumerator");
  static_assert(!t.count_named, "Count is an enumerator: the enum has more values");
  return t.names;
}();

/// The name of `e`, an enumerator of E with values 0 to Count - 1, as declared ("out_of_range");
/// `other` for a value that is none (a cast from a stray integer).
template <std::size_t Count, class E>
[[nodiscard]] constexpr std::string_view enumerator_name_of(
    E e, std::string_view other = "unknown") noexcept {
  const std::string_view n = name_at(enumerator_names<E, Count>, static_cast<std::uint64_t>(e));
  return n.empty() ? other : n;
}

}  // namespace seawire::detail
