// SPDX-License-Identifier: Apache-2.0
// Summary statistics of a sample of non-negative errors (e.g. CIEDE2000
// differences): count, arithmetic mean, 95th percentile and maximum.
//
// The 95th percentile uses the nearest-rank definition: with the n values
// sorted ascending as v[1] <= ... <= v[n], p95 = v[ceil(0.95 n)]. It is always
// one of the sample values (no interpolation); for n = 100 it is the 95th
// smallest value, and for n < 20 it is the maximum. An empty sample gives all
// fields 0.
#pragma once

#include <cstddef>
#include <vector>

namespace cmfilter {

struct ErrorSummary {
    std::size_t count = 0;
    double mean = 0, p95 = 0, max = 0;
};

// Takes the values by value because it sorts them.
ErrorSummary summarize_errors(std::vector<double> values);

// The nearest-rank q-quantile, 0 < q <= 1: the value at rank ceil(q n) of the
// sorted sample (q = 0.95 is ErrorSummary::p95, q = 1 the maximum); 0 for an
// empty sample. The rank is computed with a relative slack of 1e-12 so that a
// q n meant to be an integer (0.999 x 20000) is not rounded up by its binary
// representation. Takes the values by value because it partially sorts them.
double nearest_rank_quantile(std::vector<double> values, double q);

}  // namespace cmfilter
