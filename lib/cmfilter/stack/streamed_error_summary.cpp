// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/streamed_error_summary.h"

#include <algorithm>
#include <cstring>

namespace cmfilter {

namespace {

constexpr int kBinBits = 16;
constexpr int kBins = 1 << kBinBits;
constexpr int kLevels = 64 / kBinBits;

// A double's bits as an unsigned key in the order of the values: positive
// values with the sign bit set, negative ones inverted.
std::uint64_t order_key(double v)
{
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return bits >> 63 ? ~bits : bits | (std::uint64_t(1) << 63);
}

double from_order_key(std::uint64_t key)
{
    const std::uint64_t bits = key >> 63 ? key & ~(std::uint64_t(1) << 63) : ~key;
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

// The nearest rank of the 95th percentile among n values (error_summary.cpp).
std::size_t p95_rank(std::size_t n) { return std::max<std::size_t>(1, (19 * n + 19) / 20); }

}  // namespace

StreamedErrorSummary::StreamedErrorSummary(std::size_t retained_limit)
    : limit_(std::max<std::size_t>(retained_limit, 2)), bins_(kBins, 0)
{
}

void StreamedErrorSummary::add(const double* values, std::size_t count)
{
    const int shift = 64 - kBinBits * (level_ + 1);
    for (std::size_t i = 0; i < count; ++i) {
        const double v = values[i];
        const std::uint64_t key = order_key(v);
        if (level_ == 0) {
            sum_ += v;
            if (summary_.count == 0 || v > summary_.max) summary_.max = v;
            ++summary_.count;
        } else if (key >> (shift + kBinBits) != prefix_) continue;
        const int bin = static_cast<int>((key >> shift) & (kBins - 1));
        ++bins_[static_cast<std::size_t>(bin)];
        ++seen_;
        if (retaining_ && bin >= window_lo_ && bin <= window_hi_) {
            retained_.push_back(v);
            if (retained_.size() > limit_) shrink_window();
        }
    }
}

// The window narrowed to the bins around the percentile's bin as estimated
// from the values seen so far, holding at most half the limit; the values
// outside it dropped. When the estimate's bin alone is over that, the pass
// keeps nothing more.
void StreamedErrorSummary::shrink_window()
{
    const std::size_t rank = level_ == 0 ? p95_rank(seen_) : std::min(rank_, seen_);
    std::size_t below = 0;
    int b = 0;
    while (b < kBins - 1 && below + bins_[static_cast<std::size_t>(b)] < rank) below += bins_[b++];
    std::size_t kept = bins_[static_cast<std::size_t>(b)];
    int lo = b, hi = b;
    const std::size_t budget = limit_ / 2;
    if (kept > budget || b < window_lo_ || b > window_hi_) {
        retaining_ = false;
        retained_.clear();
        retained_.shrink_to_fit();
        return;
    }
    // Grow towards both sides while within the budget and the old window.
    for (bool grown = true; grown;) {
        grown = false;
        if (hi < window_hi_ && kept + bins_[static_cast<std::size_t>(hi + 1)] <= budget) {
            kept += bins_[static_cast<std::size_t>(++hi)];
            grown = true;
        }
        if (lo > window_lo_ && kept + bins_[static_cast<std::size_t>(lo - 1)] <= budget) {
            kept += bins_[static_cast<std::size_t>(--lo)];
            grown = true;
        }
    }
    window_lo_ = lo;
    window_hi_ = hi;
    const int shift = 64 - kBinBits * (level_ + 1);
    auto outside = [&](double v) {
        const int bin = static_cast<int>((order_key(v) >> shift) & (kBins - 1));
        return bin < lo || bin > hi;
    };
    retained_.erase(std::remove_if(retained_.begin(), retained_.end(), outside), retained_.end());
}

bool StreamedErrorSummary::end_pass()
{
    if (level_ == 0) {
        if (summary_.count == 0) return true;
        summary_.mean = sum_ / static_cast<double>(summary_.count);
        rank_ = p95_rank(summary_.count);
    }
    std::size_t below = 0;
    int b = 0;
    while (b < kBins - 1 && below + bins_[static_cast<std::size_t>(b)] < rank_) below += bins_[b++];
    const std::size_t rank_in_bin = rank_ - below;
    const int shift = 64 - kBinBits * (level_ + 1);
    if (retaining_ && b >= window_lo_ && b <= window_hi_) {
        std::vector<double> in_bin;
        for (double v : retained_)
            if (static_cast<int>((order_key(v) >> shift) & (kBins - 1)) == b) in_bin.push_back(v);
        auto kth = in_bin.begin() + static_cast<std::ptrdiff_t>(rank_in_bin - 1);
        std::nth_element(in_bin.begin(), kth, in_bin.end());
        summary_.p95 = *kth;
        return true;
    }
    prefix_ = (prefix_ << kBinBits) | static_cast<std::uint64_t>(b);
    ++level_;
    if (level_ == kLevels) {  // every bit fixed: the value itself
        summary_.p95 = from_order_key(prefix_);
        return true;
    }
    rank_ = rank_in_bin;
    std::fill(bins_.begin(), bins_.end(), 0);
    retained_.clear();
    retaining_ = true;
    window_lo_ = 0;
    window_hi_ = kBins - 1;
    seen_ = 0;
    return false;
}

}  // namespace cmfilter
