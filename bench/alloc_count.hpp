// SPDX-License-Identifier: BSL-1.0
#pragma once
// The count of heap allocations of a program linked with alloc_count.cpp, which replaces the
// global operator new: the benchmarks' allocs_per_msg and the allocation test's regions.

#include <cstdint>

namespace seawire::bench {

/// Heap allocations so far in this process (every operator new, any thread).
[[nodiscard]] std::uint64_t allocation_count() noexcept;

}  // namespace seawire::bench
