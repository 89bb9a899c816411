// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/noise_sub_footprints.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace cmfilter {

namespace {

// s = (L - L_N + 2.5) / 1.5 (noise_sub_footprints.h).
constexpr double kLodsBelowFinest = 2.5;
constexpr double kLodsPerDoubling = 1.5;
// The blends: the last quarter of a level, the last half LOD before lod_last.
constexpr double kLevelBlend = 0.25;
constexpr double kTopBlend = 0.5;

}  // namespace

Status check_sub_footprint_options(const SubFootprintOptions& options)
{
    if (options.max_cells < 1 || options.max_cells > kMaxSubFootprintCells)
        return bad_input("SubFootprintOptions::max_cells " + std::to_string(options.max_cells) +
                             " is out of range (expected 1 to " + std::to_string(kMaxSubFootprintCells) + ")",
                         "SubFootprintOptions::max_cells");
    if (!std::isfinite(options.lod_last))
        return bad_input("SubFootprintOptions::lod_last " + std::to_string(options.lod_last) +
                             " is not finite (expected a finite LOD)",
                         "SubFootprintOptions::lod_last");
    return ok();
}

SubFootprintPlan plan_sub_footprints(const FractalNoise& noise, double lod, const SubFootprintOptions& options)
{
    SubFootprintPlan plan;
    if (!std::isfinite(lod) || options.max_cells <= 1 || lod >= options.lod_last) return plan;
    // L_N from the octaves' stored log2 periods: no log2 per footprint.
    const double finest = noise.octave_log2_period(noise.options().octaves - 1) - noise.octave_log2_period(0);
    const double s = (lod - finest + kLodsBelowFinest) / kLodsPerDoubling;
    if (s <= -kLevelBlend) return plan;
    // n = 2^ceil(s); over the last quarter of the level, towards 2n.
    const double k = std::ceil(s);
    const int max = options.max_cells;
    const int n = k <= 0 ? 1 : (k >= 5 ? max : std::min(max, 1 << static_cast<int>(k)));
    double t = (s - (k - 1) - (1 - kLevelBlend)) / kLevelBlend;
    plan.cells = n;
    if (t > 0 && n < max) {
        plan.blend_cells = std::min(max, 2 * n);
        if (t >= 1) {
            plan.cells = plan.blend_cells;
            t = 0;
        }
        plan.blend = t;
    }
    if (plan.blend <= 0) plan.blend_cells = plan.cells, plan.blend = 0;
    // Back to one Gaussian over the half LOD below lod_last, whatever the
    // counts blend there.
    const double top = (lod - (options.lod_last - kTopBlend)) / kTopBlend;
    if (top > 0) plan.one = top;
    return plan;
}

}  // namespace cmfilter
