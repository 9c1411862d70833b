// SPDX-License-Identifier: BSL-1.0
#pragma once
// An enum's names as a table indexed by its values (internal): enum_words, lookup_names, status
// texts. A value the table does not name has an empty entry or lies past its end.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

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

}  // namespace seawire::detail
