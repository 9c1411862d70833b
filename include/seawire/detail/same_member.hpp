// SPDX-License-Identifier: BSL-1.0
#pragma once
// Whether two member pointers, of any types, name the same member (internal): how a description
// finds the row or field of a member it is given.

#include <type_traits>

namespace seawire::detail {

template <auto A, auto B>
inline constexpr bool same_member = [] {
  if constexpr (std::is_same_v<decltype(A), decltype(B)>) {
    return A == B;
  } else {
    return false;
  }
}();

}  // namespace seawire::detail
