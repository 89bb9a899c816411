// SPDX-License-Identifier: Apache-2.0
// build_patch_level (coordinate_lookup.h): per footprint, the histogram of
// its texels' patch offsets c(p) - p. A piece copied whole from the sample
// (sec. 4.2: k-coherence grows patches, each texel continuing its
// neighbour's offset) has one offset, so a footprint inside it has one
// entry of share 1, and one across a seam a few.
#include "cmfilter/synthesis/coordinate_lookup.h"

#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace cmfilter {

namespace {

std::int64_t wrapped(std::int64_t v, std::int64_t n)
{
    const std::int64_t r = v % n;
    return r < 0 ? r + n : r;
}

}  // namespace

Expected<PatchLevel> build_patch_level(const CoordinateMap& map, int lod, int patches, bool periodic, int threads)
{
    if (lod < 0 || lod > 30)
        return bad_input("LodOptions::lod " + std::to_string(lod) + " is invalid: expected 0 .. 30", "LodOptions::lod");
    if (patches < 1)
        return bad_input("LodOptions::patches " + std::to_string(patches) + " is invalid: expected at least 1",
                         "LodOptions::patches");
    if (map.levels.empty() || map.width() < 1 || map.height() < 1)
        return bad_input("the coordinate map has no level 0 (expected a full-size map of at least 1 x 1)");
    const CoordinateLevel& full = map.full();
    if (full.coords.size() != full.texels() * 2)
        return bad_input("the coordinate map's level 0 holds " + std::to_string(full.coords.size()) +
                         " values, expected " + std::to_string(full.texels() * 2));
    if (periodic && (full.sample_width < 1 || full.sample_height < 1))
        return bad_input("the coordinate map's sample size " + std::to_string(full.sample_width) + " x " +
                         std::to_string(full.sample_height) + " is invalid: expected at least 1 x 1");

    const int step = 1 << lod;
    PatchLevel level;
    level.lod = lod;
    level.patches = patches;
    level.width = (full.width + step - 1) / step;
    level.height = (full.height + step - 1) / step;
    level.entries.assign(static_cast<std::size_t>(level.width) * level.height * patches * 3, 0.0f);

    parallel_for(level.height, threads, [&](int j) {
        // (dy, dx) of every texel of the footprint, sorted, counted in runs.
        std::vector<std::pair<std::int64_t, std::int64_t>> offsets;
        std::vector<std::pair<int, std::size_t>> runs;  // (count, index of the run's first offset)
        const int y0 = j * step, y1 = std::min(full.height, y0 + step);
        for (int i = 0; i < level.width; ++i) {
            const int x0 = i * step, x1 = std::min(full.width, x0 + step);
            offsets.clear();
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    const std::size_t t = static_cast<std::size_t>(y) * full.width + x;
                    std::int64_t dx = static_cast<std::int64_t>(full.x(t)) - x;
                    std::int64_t dy = static_cast<std::int64_t>(full.y(t)) - y;
                    if (periodic) {
                        dx = wrapped(dx, full.sample_width);
                        dy = wrapped(dy, full.sample_height);
                    }
                    offsets.emplace_back(dy, dx);
                }
            std::sort(offsets.begin(), offsets.end());
            runs.clear();
            for (std::size_t a = 0; a < offsets.size();) {
                std::size_t b = a + 1;
                while (b < offsets.size() && offsets[b] == offsets[a]) ++b;
                runs.emplace_back(static_cast<int>(b - a), a);
                a = b;
            }
            // Most common first; a tie keeps the lower (dy, dx), the earlier run.
            std::stable_sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
            const std::size_t kept = std::min<std::size_t>(runs.size(), static_cast<std::size_t>(patches));
            // Shares of the whole footprint: what the kept pieces leave is
            // read at the sample's mean (render_at_lod).
            const double total = static_cast<double>(offsets.size());
            float* out = level.entries.data() + (static_cast<std::size_t>(j) * level.width + i) * patches * 3;
            for (std::size_t k = 0; k < kept; ++k) {
                const auto& offset = offsets[runs[k].second];
                out[3 * k] = static_cast<float>(offset.second);
                out[3 * k + 1] = static_cast<float>(offset.first);
                out[3 * k + 2] = static_cast<float>(runs[k].first / total);
            }
        }
    });
    return level;
}

}  // namespace cmfilter
