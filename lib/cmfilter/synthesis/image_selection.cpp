// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthesis/image_selection.h"

#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <limits>

namespace cmfilter {

namespace {

double variance(const std::vector<float>& values)
{
    if (values.empty()) return 0;
    double mean = 0;
    for (float v : values) mean += v;
    mean /= static_cast<double>(values.size());
    double sum = 0;
    for (float v : values) sum += (v - mean) * (v - mean);
    return sum / static_cast<double>(values.size());
}

double squared_distance(const std::vector<float>& a, const std::vector<float>& b)
{
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double d = static_cast<double>(a[i]) - b[i];
        sum += d * d;
    }
    return sum;
}

}  // namespace

std::vector<int> select_representative_images(const std::vector<std::vector<float>>& images, int count, int threads)
{
    const int n = static_cast<int>(images.size());
    std::vector<int> chosen;
    if (count <= 0 || count >= n) {
        for (int i = 0; i < n; ++i) chosen.push_back(i);
        return chosen;
    }
    std::vector<double> score(static_cast<std::size_t>(n));
    parallel_for(n, threads,
                 [&](int i) { score[static_cast<std::size_t>(i)] = variance(images[static_cast<std::size_t>(i)]); });
    std::vector<bool> taken(static_cast<std::size_t>(n), false);
    std::vector<double> nearest(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
    // The first: the largest variance; afterwards `score` is each image's
    // smallest squared distance to those chosen.
    while (static_cast<int>(chosen.size()) < count) {
        int best = -1;
        for (int i = 0; i < n; ++i)
            if (!taken[static_cast<std::size_t>(i)] &&
                (best < 0 || score[static_cast<std::size_t>(i)] > score[static_cast<std::size_t>(best)]))
                best = i;
        chosen.push_back(best);
        taken[static_cast<std::size_t>(best)] = true;
        parallel_for(n, threads, [&](int i) {
            if (taken[static_cast<std::size_t>(i)]) return;
            const double d =
                squared_distance(images[static_cast<std::size_t>(i)], images[static_cast<std::size_t>(best)]);
            nearest[static_cast<std::size_t>(i)] = std::min(nearest[static_cast<std::size_t>(i)], d);
        });
        score = nearest;
    }
    std::sort(chosen.begin(), chosen.end());
    return chosen;
}

}  // namespace cmfilter
