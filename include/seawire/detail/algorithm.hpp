// SPDX-License-Identifier: BSL-1.0
#pragma once
// The standard algorithms the library uses (std::min, std::max, std::copy_n, std::sort,
// std::all_of, ...), without the rest of <algorithm>: in C++20, libstdc++'s <algorithm> also
// brings the std::ranges algorithms, which cost a translation unit about a sixth of what
// <variant>, <optional>, <string_view> and <chrono> cost together. libstdc++ declares the others
// in a header of their own; any other library gets <algorithm>, and so does libstdc++'s parallel
// mode, whose std::sort and others <parallel/algorithm> defines.

#if __has_include(<bits/stl_algo.h>) && !defined(_GLIBCXX_PARALLEL)
#include <bits/stl_algo.h>
#else
#include <algorithm>
#endif
