// SPDX-License-Identifier: Apache-2.0
// ErrorSummary (error_summary.h) of a sample too large to hold, such as the
// CIEDE2000 difference of every texel under every light of a stack: count,
// mean and maximum as the values stream past, and the exact nearest-rank
// 95th percentile by radix selection over the values' bit patterns (a
// double's bits, sign-adjusted, order as its value). Each pass counts the
// values under a prefix of bits fixed so far in 2^16 bins of the next 16
// bits and keeps the values themselves, up to `retained_limit`, in a window
// of bins around the percentile's running estimate; when the percentile's
// bin lies in that window the pass ends the selection, otherwise its bin
// becomes the prefix of another pass over the same values (at most four in
// all; 16 bits each). A sample of at most retained_limit values, or one
// whose estimate stays in the window, takes one pass.
// Memory: 512 KiB of counts and at most retained_limit doubles.
#pragma once

#include "cmfilter/color/error_summary.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cmfilter {

class StreamedErrorSummary {
public:
    explicit StreamedErrorSummary(std::size_t retained_limit = std::size_t(1) << 23);

    // The pass's next values (every pass feeds the same values; the order
    // may differ, but a pass after the first must feed each value once).
    void add(const double* values, std::size_t count);

    // Ends a pass: true when the summary is known, false when the same
    // values must be fed again.
    bool end_pass();

    ErrorSummary summary() const { return summary_; }

private:
    void shrink_window();

    std::size_t limit_;
    int level_ = 0;             // bits fixed: 16 * level_
    std::uint64_t prefix_ = 0;  // their value
    std::size_t rank_ = 0;      // the percentile's rank among values with the prefix (level_ > 0)
    std::vector<std::uint64_t> bins_;
    std::vector<double> retained_;
    bool retaining_ = true;
    int window_lo_ = 0, window_hi_ = 0xffff;
    std::size_t seen_ = 0;  // values with the prefix this pass
    double sum_ = 0;
    ErrorSummary summary_;
};

}  // namespace cmfilter
