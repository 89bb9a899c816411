// SPDX-License-Identifier: Apache-2.0
// k-means clustering (Lloyd's iteration) from a k-means++ start (Arthur &
// Vassilvitskii 2007): the texton clustering of sec. 4.1. Deterministic for
// a seed, whatever the thread count: points are assigned independently and
// centres summed in a fixed order.
#pragma once

#include "cmfilter/util/error.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cmfilter {

struct KMeansOptions {
    int clusters = 0;         // >= 1 and <= the number of points
    int max_iterations = 30;  // Lloyd iterations after the start; stops early once no label changes
    std::uint64_t seed = 1;
    int threads = 0;
};

struct KMeansResult {
    int clusters = 0;  // may be fewer than asked when the points hold fewer distinct values
    int dims = 0;
    std::vector<float> centres;  // clusters * dims: each cluster's mean (its appearance vector)
    std::vector<int> labels;     // per point, in [0, clusters)
    int iterations = 0;
    double inertia = 0;  // sum of squared distances of the points to their centres
};

// BadInput naming KMeansOptions::clusters when it is < 1 or more than the
// points (the count), KMeansOptions::max_iterations < 0, or non-finite points.
Expected<KMeansResult> kmeans(const float* points, std::size_t count, int dims, const KMeansOptions& options);

}  // namespace cmfilter
