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

/// The name of enumerator V as declared ("missing_frame"); empty when V is no enumerator. Read
/// from the compiler's name for this function, which spells its template argument: an
/// enumerator by its qualified name, another value as a cast ("(ns::E)7") or a number.
template <auto V>
[[nodiscard]] consteval std::string_view enumerator_name() noexcept {
#if defined(__clang__) || defined(__GNUC__)
  // GCC "... [with auto V = ns::E::name]", Clang "... [V = ns::E::name]".
  const std::string_view signature = __PRETTY_FUNCTION__;
  const std::size_t at = signature.rfind("V = ");
  if (at == std::string_view::npos) return {};
  std::string_view arg = signature.substr(at + 4);
  arg = arg.substr(0, arg.find_first_of(";]"));
#elif defined(_MSC_VER)
  // "... enumerator_name<ns::E::name>(void) noexcept".
  const std::string_view signature = __FUNCSIG__;
  const std::size_t open = signature.find("enumerator_name<");
  const std::size_t close = signature.rfind(">(");
  if (open == std::string_view::npos || close == std::string_view::npos) return {};
  std::string_view arg = signature.substr(open + 16, close - open - 16);
#else
#error "seawire: enumerator names need GCC, Clang or MSVC"
#endif
  // "(anonymous namespace)::E::name" is an enumerator; "(ns::E)7", "0x7" and "-1" are not.
  const std::size_t colon = arg.rfind("::");
  const std::string_view name = colon == std::string_view::npos ? arg : arg.substr(colon + 2);
  if (name.empty() || name[0] == '-' || (name[0] >= '0' && name[0] <= '9') ||
      name.find_first_of("()") != std::string_view::npos)
    return {};
  return name;
}

/// The names of E's enumerators 0 to Count - 1, in value order. A compile error unless each of
/// those values is an enumerator and Count is none: the table is the enum, whole.
template <class E, std::size_t Count>
inline constexpr std::array<std::string_view, Count> enumerator_names = [
]<std::size_t... I>(std::index_sequence<I...>) {
  constexpr std::array<std::string_view, Count> names{enumerator_name<static_cast<E>(I)>()...};
  static_assert(((!names[I].empty()) && ...), "a value below Count is no enumerator");
  static_assert(enumerator_name<static_cast<E>(Count)>().empty(),
                "Count is an enumerator: the enum has more values");
  return names;
}
(std::make_index_sequence<Count>{});

/// The name of `e`, an enumerator of E with values 0 to Count - 1, as declared ("out_of_range");
/// `other` for a value that is none (a cast from a stray integer).
template <std::size_t Count, class E>
[[nodiscard]] constexpr std::string_view enumerator_name_of(
    E e, std::string_view other = "unknown") noexcept {
  const std::string_view n = name_at(enumerator_names<E, Count>, static_cast<std::uint64_t>(e));
  return n.empty() ? other : n;
}

}  // namespace seawire::detail
