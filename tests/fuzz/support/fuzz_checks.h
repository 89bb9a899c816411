// SPDX-License-Identifier: Apache-2.0
// What a harness asserts about a reader's result: a reader that accepts its
// input must hand back only finite values (NaN and Inf never leak); a
// failed check aborts, which libFuzzer reports as a crash with the input.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace cmfilter::fuzz {

inline void require(bool condition, const char* what)
{
    if (!condition) {
        std::fprintf(stderr, "fuzz check failed: %s\n", what);
        std::abort();
    }
}

template <typename Range>
void require_finite(const Range& values, const char* what)
{
    for (const auto& v : values) require(std::isfinite(static_cast<double>(v)), what);
}

// Set once per harness process, before the first input: readers refuse
// what does not fit in 16 MB (CMFILTER_MEMORY_LIMIT, util/memory_budget.h),
// far under libFuzzer's own 2 GB limit, so a reader that allocates what an
// input declares before checking it is reported, and no input takes long.
void limit_memory_for_fuzzing();

}  // namespace cmfilter::fuzz
