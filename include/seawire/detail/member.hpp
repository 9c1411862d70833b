// SPDX-License-Identifier: BSL-1.0
#pragma once
// Member pointers (internal): the class and member type a member pointer names, and whether two
// member pointers of any types name the same member.

#include <type_traits>

namespace seawire::detail {

template <class M>
struct member_pointer;
template <class C, class T>
struct member_pointer<T C::*> {
  using class_type = C;
  using member_type = T;
};

/// The class of member pointer M (`&C::m` gives C).
template <auto M>
using member_class_t = typename member_pointer<std::remove_cv_t<decltype(M)>>::class_type;
/// The type of the member M names (`&C::m` gives the declared type of m).
template <auto M>
using member_type_t = typename member_pointer<std::remove_cv_t<decltype(M)>>::member_type;

template <auto A, auto B>
inline constexpr bool same_member = [] {
  if constexpr (std::is_same_v<decltype(A), decltype(B)>) {
    return A == B;
  } else {
    return false;
  }
}();

}  // namespace seawire::detail
