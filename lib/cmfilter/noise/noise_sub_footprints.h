// SPDX-License-Identifier: Apache-2.0
// A noise filtered in the transition as a mixture of Gaussians over
// sub-footprints (docs/noise-accuracy.md, "Sub-footprints").
//
// Sec. 4.2 models the values of a noise over a footprint as one Gaussian
// N(mean, sigma^2) and colours it with T(mean, sigma). Where the footprint
// spans from about the finest octave's period to a few base periods (the
// transition), the partly resolved octaves make that distribution far from
// one Gaussian: even each footprint's own exact mean and standard deviation
// leave up to 3.8 mean CIEDE2000 for fBm (docs/noise-accuracy.md). Here the
// square footprint of width w centred at (x, y) is cut into n x n squares of
// width w / n (a parallelogram footprint, along its own edges), each filtered as sec. 4.2 filters a footprint
// (FilteredNoise::filter: its own filtered mean and the sigma table at its
// LOD), and the colour is the mean of their colours:
//     C(x, y, w) = (1 / n^2) sum_{a,b} T(mean_{w/n}(x_ab, y_ab), sigma(w / n)),
//     x_ab = x + w ((a + 1/2) / n - 1/2),  y_ab = y + w ((b + 1/2) / n - 1/2),
// a mixture of n^2 Gaussians. n = 1 is sec. 4.2's filtering exactly.
//
// How many: from the footprint's LOD L (log2 of w over the base period)
// against the finest octave's, L_N = log2(p_{N-1} / p_0), the level
//     s = (L - L_N + 2.5) / 1.5
// gives n = 2^ceil(s), clamped to [1, max_cells]: one Gaussian up to 2.5
// LODs below the finest octave's period, then a doubling every 1.5 LOD (about
// the widths where, for 6-octave gradient fBm and turbulence, each n's error
// passes 1 mean CIEDE2000 on the bundled maps, docs/noise-accuracy.md).
// From L = lod_last (three base periods and more, where the footprint holds
// enough noise cells that sub-footprints no longer help) n is 1 again.
// Across each change of n the two estimates are blended linearly, over the
// last quarter of a level below it and over the half LOD below lod_last, so
// that a colour changes continuously with w (no popping across LODs).
#pragma once

#include "cmfilter/noise/filtered_noise.h"
#include "cmfilter/util/error.h"

#include <cmath>

namespace cmfilter {

inline constexpr int kMaxSubFootprintCells = 16;

struct SubFootprintOptions {
    // The most squares per axis a footprint is cut into: 1 .. 16 (1: one
    // Gaussian, sec. 4.2). 8 by default: 64 Gaussians, where the errors of
    // docs/noise-accuracy.md for fBm come within 1.35 at every LOD up to 2
    // (within 1.0 up to LOD -1).
    int max_cells = 8;
    // From this LOD one Gaussian again (finite).
    double lod_last = 3.0;
};

// BadInput naming SubFootprintOptions::max_cells or lod_last.
Status check_sub_footprint_options(const SubFootprintOptions& options);

// The estimate at one LOD: (1 - blend) of the mixture over cells x cells
// squares plus blend of the one over blend_cells x blend_cells, and that
// (1 - one) of the whole plus `one` of the single Gaussian (the blend back
// to one Gaussian below lod_last).
struct SubFootprintPlan {
    int cells = 1;
    int blend_cells = 1;
    double blend = 0;  // in [0, 1)
    double one = 0;    // in [0, 1)
};

// The plan for footprints of LOD `lod` of `noise` (see above); a NaN or
// infinite LOD (a point, or no footprint) gets one Gaussian.
SubFootprintPlan plan_sub_footprints(const FractalNoise& noise, double lod, const SubFootprintOptions& options);

// A footprint's parallelogram in noise coordinates: the points
// c + s e1 + t e2, s and t in [-1/2, 1/2] (a pixel's footprint, or one
// anisotropic probe's piece of it). The square of width w is
// {w, 0, 0, w}.
struct FootprintEdges {
    double e1x = 0, e1y = 0, e2x = 0, e2y = 0;
    static FootprintEdges square(double w) { return {w, 0, 0, w}; }
};

// The colour of the footprint at (x, y) with edges e and width w (the one
// width its Gaussian is filtered at) as the mixture over n x n
// sub-footprints (n >= 2): the parallelogram cut along its own edges, so the
// pieces tile the region the footprint covers whatever its orientation;
// each piece filtered at width w / n. colour(parameters) is called with each
// piece's FilteredNoise::Parameters and returns its colour (any type with +=
// and scalar *, e.g. Rgb).
template <class Colour, class ColourOf>
Colour sub_footprint_mixture(const FilteredNoise& noise, double x, double y, double w, const FootprintEdges& e, int n,
                             ColourOf&& colour)
{
    const double cell = w / n;
    Colour sum{};
    for (int a = 0; a < n; ++a) {
        const double s = (a + 0.5) / n - 0.5;
        for (int b = 0; b < n; ++b) {
            const double t = (b + 0.5) / n - 0.5;
            sum += colour(noise.filter(x + s * e.e1x + t * e.e2x, y + s * e.e1y + t * e.e2y, cell));
        }
    }
    return (1.0 / (static_cast<double>(n) * n)) * sum;
}

// The same over the axis-aligned square of width w centred at (x, y): the
// squares of width w / n centred at
//     x_ab = x + w ((a + 1/2) / n - 1/2),  y_ab = y + w ((b + 1/2) / n - 1/2).
template <class Colour, class ColourOf>
Colour sub_footprint_mixture(const FilteredNoise& noise, double x, double y, double w, int n, ColourOf&& colour)
{
    return sub_footprint_mixture<Colour>(noise, x, y, w, FootprintEdges::square(w), n, colour);
}

// The colour of a footprint as its plan says (one or two mixtures, blended);
// `whole` is noise.filter(x, y, w), the one Gaussian's parameters, which the
// caller has already; e the footprint's edges (its square of width w
// by default).
template <class Colour, class ColourOf>
Colour sub_footprint_color(const FilteredNoise& noise, double x, double y, double w, const FootprintEdges& e,
                           const FilteredNoise::Parameters& whole, const SubFootprintOptions& options,
                           ColourOf&& colour)
{
    const SubFootprintPlan plan = plan_sub_footprints(noise.noise(), w > 0 ? noise.lod(w) : NAN, options);
    const auto mixture = [&](int n) {
        return n > 1 ? sub_footprint_mixture<Colour>(noise, x, y, w, e, n, colour) : Colour(colour(whole));
    };
    Colour c = mixture(plan.cells);
    if (plan.blend > 0) c = (1.0 - plan.blend) * c + plan.blend * mixture(plan.blend_cells);
    if (plan.one > 0) c = (1.0 - plan.one) * c + plan.one * Colour(colour(whole));
    return c;
}

template <class Colour, class ColourOf>
Colour sub_footprint_color(const FilteredNoise& noise, double x, double y, double w,
                           const FilteredNoise::Parameters& whole, const SubFootprintOptions& options,
                           ColourOf&& colour)
{
    return sub_footprint_color<Colour>(noise, x, y, w, FootprintEdges::square(w), whole, options, colour);
}

}  // namespace cmfilter
