// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthesis/candidate_search.h"

#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace cmfilter {

namespace {

int wrap_or_clamp(int v, int extent, bool periodic)
{
    if (periodic) return ((v % extent) + extent) % extent;
    return std::clamp(v, 0, extent - 1);
}

}  // namespace

std::vector<std::int32_t> find_candidate_sets(const CandidateSearch& s)
{
    const int texels = s.width * s.height;
    const int n = s.neighbourhood;
    // The window's offsets, nearest the centre first, so that a partial sum
    // passes the current m-th best as early as it can.
    std::vector<std::pair<int, int>> offsets;
    for (int dy = -n; dy <= n; ++dy)
        for (int dx = -n; dx <= n; ++dx) offsets.emplace_back(dx, dy);
    std::stable_sort(offsets.begin(), offsets.end(), [](const auto& a, const auto& b) {
        return a.first * a.first + a.second * a.second < b.first * b.first + b.second * b.second;
    });
    const int window = static_cast<int>(offsets.size());
    // Every texel's window of textons, in offset order.
    std::vector<std::int32_t> windows(static_cast<std::size_t>(texels) * window);
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x)
            for (int o = 0; o < window; ++o) {
                const int sx = wrap_or_clamp(x + offsets[static_cast<std::size_t>(o)].first, s.width, s.periodic);
                const int sy = wrap_or_clamp(y + offsets[static_cast<std::size_t>(o)].second, s.height, s.periodic);
                windows[(static_cast<std::size_t>(y) * s.width + x) * window + o] =
                    s.texton[static_cast<std::size_t>(sy) * s.width + sx];
            }

    const int m = s.candidates;
    std::vector<std::int32_t> similar(static_cast<std::size_t>(texels) * m);
    parallel_for(s.height, s.threads, [&](int y) {
        std::vector<const float*> rows(static_cast<std::size_t>(window));
        std::vector<float> best_sum(static_cast<std::size_t>(m));
        std::vector<std::int32_t> best_index(static_cast<std::size_t>(m));
        for (int x = 0; x < s.width; ++x) {
            const int p = y * s.width + x;
            const std::int32_t* wp = windows.data() + static_cast<std::size_t>(p) * window;
            for (int o = 0; o < window; ++o)
                rows[static_cast<std::size_t>(o)] = s.distance + static_cast<std::size_t>(wp[o]) * s.textons;
            int filled = 0;
            float threshold = std::numeric_limits<float>::infinity();
            for (int q = 0; q < texels; ++q) {
                if (q == p) continue;
                const std::int32_t* wq = windows.data() + static_cast<std::size_t>(q) * window;
                // Terms are >= 0, and every q already held has a lower index:
                // once the partial sum reaches the m-th best, q cannot enter.
                float sum = 0;
                int o = 0;
                for (; o < window; ++o) {
                    sum += rows[static_cast<std::size_t>(o)][wq[o]];
                    if (sum >= threshold) break;
                }
                if (o < window) continue;
                int at = std::min(filled, m - 1);
                while (at > 0 && best_sum[static_cast<std::size_t>(at) - 1] > sum) {
                    best_sum[static_cast<std::size_t>(at)] = best_sum[static_cast<std::size_t>(at) - 1];
                    best_index[static_cast<std::size_t>(at)] = best_index[static_cast<std::size_t>(at) - 1];
                    --at;
                }
                best_sum[static_cast<std::size_t>(at)] = sum;
                best_index[static_cast<std::size_t>(at)] = q;
                if (filled < m) ++filled;
                if (filled == m) threshold = best_sum[static_cast<std::size_t>(m) - 1];
            }
            std::copy(best_index.begin(), best_index.end(), similar.begin() + static_cast<std::ptrdiff_t>(p) * m);
        }
    });
    return similar;
}

}  // namespace cmfilter
