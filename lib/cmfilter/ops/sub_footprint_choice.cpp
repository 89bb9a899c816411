// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/ops/sub_footprint_choice.h"

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/noise/noise_lattice.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace cmfilter {

namespace {

Status bad(const std::string& field, const std::string& what)
{
    return bad_input("SubFootprintChoiceOptions::" + field + " " + what, "SubFootprintChoiceOptions::" + field);
}

}  // namespace

const SubFootprintTrial* SubFootprintChoice::best() const
{
    const SubFootprintTrial* b = nullptr;
    for (const SubFootprintTrial& t : trials)
        if (!b || t.worst < b->worst) b = &t;
    return b;
}

std::vector<double> sub_footprint_lods_between(const NoiseSigmaTable& table, double first, double last)
{
    const double lo = std::ceil(table.lod_first() - 1e-9), hi = std::floor(table.lod_last() + 1e-9);
    if (lo > hi) return {table.lod_first()};
    const double a = std::clamp(std::floor(first), lo, hi), b = std::clamp(std::ceil(last), lo, hi);
    std::vector<double> lods;
    for (double l = a; l <= b; l += 1) lods.push_back(l);
    return lods;
}

Expected<SubFootprintChoice> choose_sub_footprints(const FilteredNoise& noise, const ColorMap& map,
                                                   const std::function<Rgb(double, double)>& gaussian_colour,
                                                   const SubFootprintChoiceOptions& options)
{
    if (!(options.tolerance > 0) || !std::isfinite(options.tolerance))
        return bad("tolerance", std::to_string(options.tolerance) + " is invalid (expected a finite CIEDE2000 > 0)")
            .error();
    if (options.footprints < 1)
        return bad("footprints", std::to_string(options.footprints) + " is invalid (expected at least 1)").error();
    if (options.strata < 1)
        return bad("strata", std::to_string(options.strata) + " is invalid (expected at least 1)").error();
    // Default: every integer LOD of the sigma table.
    const NoiseSigmaTable& table = noise.table();
    std::vector<double> lods =
        options.lods.empty() ? sub_footprint_lods_between(table, table.lod_first(), table.lod_last()) : options.lods;
    for (double l : lods)
        if (!std::isfinite(l)) return bad("lods", "holds " + std::to_string(l) + " (expected finite LODs)").error();
    std::vector<int> candidates = options.candidates;
    if (candidates.empty()) candidates = {1, 2, 4, 8, 16};
    for (int c : candidates)
        if (c < 1 || c > kMaxSubFootprintCells)
            return bad("candidates",
                       "holds " + std::to_string(c) + " (expected 1 to " + std::to_string(kMaxSubFootprintCells) + ")")
                .error();
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

    SubFootprintChoice out;
    out.tolerance = options.tolerance;
    out.lods = lods;
    for (int c : candidates) out.trials.push_back({c, {}, 0, lods.front(), false});
    const double p0 = noise.noise().base_period();
    const int n = options.footprints, strata = options.strata;
    const std::size_t trials = out.trials.size();
    for (std::size_t k = 0; k < lods.size(); ++k) {
        const double w = p0 * std::exp2(lods[k]);
        // errors[trial * n + footprint]
        std::vector<double> errors(trials * static_cast<std::size_t>(n));
        parallel_for(n, options.threads, [&](int j) {
            std::uint64_t state = options.seed ^ (static_cast<std::uint64_t>(k) << 32) ^ static_cast<std::uint64_t>(j);
            splitmix64(state);
            const double x = 256.0 * p0 * unit_interval(splitmix64(state));
            const double y = 256.0 * p0 * unit_interval(splitmix64(state));
            // The reference: C0 of the noise itself over the square.
            Rgb reference;
            for (int a = 0; a < strata; ++a)
                for (int b = 0; b < strata; ++b)
                    reference +=
                        map.evaluate(noise.noise()(x + w * ((a + unit_interval(splitmix64(state))) / strata - 0.5),
                                                   y + w * ((b + unit_interval(splitmix64(state))) / strata - 0.5)));
            reference = (1.0 / (static_cast<double>(strata) * strata)) * reference;
            const FilteredNoise::Parameters whole = noise.filter(x, y, w);
            const auto colour = [&](const FilteredNoise::Parameters& p) { return gaussian_colour(p.mean, p.sigma); };
            for (std::size_t t = 0; t < trials; ++t) {
                SubFootprintOptions o;
                o.max_cells = out.trials[t].max_cells;
                const Rgb c = sub_footprint_color<Rgb>(noise, x, y, w, whole, o, colour);
                errors[t * static_cast<std::size_t>(n) + static_cast<std::size_t>(j)] =
                    ciede2000_linear_rgb(reference, c);
            }
        });
        for (std::size_t t = 0; t < trials; ++t) {
            double sum = 0;
            for (int j = 0; j < n; ++j) sum += errors[t * static_cast<std::size_t>(n) + static_cast<std::size_t>(j)];
            SubFootprintTrial& trial = out.trials[t];
            trial.errors.push_back(sum / n);
            if (trial.errors.back() > trial.worst || trial.errors.size() == 1) {
                trial.worst = trial.errors.back();
                trial.worst_lod = lods[k];
            }
        }
    }
    for (std::size_t t = 0; t < trials; ++t) {
        out.trials[t].meets = out.trials[t].worst <= options.tolerance;
        if (out.trials[t].meets && !out.chosen) out.chosen = t;
    }
    return out;
}

}  // namespace cmfilter
