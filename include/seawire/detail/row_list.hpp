// SPDX-License-Identifier: BSL-1.0
#pragma once
// The rows of a message's table in wire order, for every wire (a sentence's field descriptors, a
// PGN's or a group repetition's rows, the 0xAB00 frame's fields): a flat aggregate with one base
// per row. std::tuple would do, but its recursive bases and constrained constructors cost most of
// the compile time of a header declaring many tables.

#include <cstddef>
#include <type_traits>
#include <utility>

namespace seawire::detail {

template <std::size_t I, class T>
struct row_slot {
  T value;
};

template <class Indices, class... Rows>
struct row_slots;
template <std::size_t... I, class... Rows>
struct row_slots<std::index_sequence<I...>, Rows...> : row_slot<I, Rows>... {};

/// A table's rows; `row_at<I>(list)` is row I (0-based), `apply(f)` calls f(rows...).
template <class... Rows>
struct row_list : row_slots<std::index_sequence_for<Rows...>, Rows...> {
  static constexpr std::size_t size = sizeof...(Rows);

  template <class F>
  constexpr decltype(auto) apply(F&& f) const {
    return [&]<std::size_t... I>(std::index_sequence<I...>)->decltype(auto) {
      return f(static_cast<const row_slot<I, Rows>&>(*this).value...);
    }
    (std::index_sequence_for<Rows...>{});
  }
  template <class F>
  constexpr decltype(auto) apply(F&& f) {
    return [&]<std::size_t... I>(std::index_sequence<I...>)->decltype(auto) {
      return f(static_cast<row_slot<I, Rows>&>(*this).value...);
    }
    (std::index_sequence_for<Rows...>{});
  }
};

/// The list of `rows`, in the order given.
template <class... Rows>
[[nodiscard]] constexpr row_list<Rows...> make_rows(Rows... rows) noexcept {
  return {{{rows}...}};
}

template <std::size_t I, class T>
[[nodiscard]] constexpr const T& row_at(const row_slot<I, T>& slot) noexcept {
  return slot.value;
}
template <std::size_t I, class T>
[[nodiscard]] constexpr T& row_at(row_slot<I, T>& slot) noexcept {
  return slot.value;
}

/// The type of row I of the row_list `List`.
template <std::size_t I, class List>
using row_type_t = std::remove_cvref_t<decltype(row_at<I>(std::declval<const List&>()))>;

template <class T>
inline constexpr bool is_row_list = false;
template <class... Rows>
inline constexpr bool is_row_list<row_list<Rows...>> = true;

}  // namespace seawire::detail
