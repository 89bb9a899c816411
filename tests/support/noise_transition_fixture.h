// SPDX-License-Identifier: Apache-2.0
// Shared by the tests of noise in the transition: 6-octave gradient fBm, its
// sigma table (a small bake: 256 footprints per LOD, LOD -9 to 3.5) and a
// hue cycle over its mean +- 2.78 standard deviations, as
// docs/noise-accuracy.md lays its maps.
#pragma once

#include "cmfilter/colormap/color_map.h"
#include "cmfilter/noise/filtered_noise.h"
#include "cmfilter/noise/noise_sigma_bake.h"
#include "cmfilter/noise/noise_sub_footprints.h"
#include "cmfilter/noise/noise_spec.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

namespace cmfilter_test {

struct NoiseTransitionFixture {
    cmfilter::FilteredNoise noise;
    cmfilter::ColorMap map;
};

inline const NoiseTransitionFixture& noise_transition_fixture()
{
    using namespace cmfilter;
    static const NoiseTransitionFixture f = [] {
        auto spec = parse_noise_spec("fbm:base=gradient,octaves=6");
        REQUIRE(spec);
        auto noise = make_noise(*spec);
        REQUIRE(noise);
        NoiseSigmaBakeOptions options;
        options.lod_step = 0.5;
        options.lod_last = 3.5;
        options.initial_footprints = 256;
        options.max_footprints = 256;
        options.global_samples = 1 << 14;
        auto bake = bake_noise_sigma(*noise, options);
        REQUIRE(bake);
        auto table = bake->table(FootprintShape::Box);
        REQUIRE(table);
        ColorMap map;
        const int n = 64;
        for (int i = 0; i < n; ++i) {
            const double a = 2 * M_PI * (i + 0.5) / n;
            map.texels.push_back(
                {0.5 + 0.45 * std::cos(a), 0.5 + 0.45 * std::cos(a - 2.0944), 0.5 + 0.45 * std::cos(a + 2.0944)});
        }
        map.vmin = bake->global.mean - 2.78 * bake->global.sigma;
        map.vmax = bake->global.mean + 2.78 * bake->global.sigma;
        return NoiseTransitionFixture{FilteredNoise(*noise, *table), map};
    }();
    return f;
}

// The reference colour of the footprint with edges e centred at (x, y) (the
// points (x, y) + s e1 + t e2, s and t in [-1/2, 1/2]): the mean of C0 of the
// noise itself at strata x strata jittered-stratified points in (s, t),
// drawn from rng.
template <class Rng>
cmfilter::Rgb supersampled_colour(const NoiseTransitionFixture& f, double x, double y,
                                  const cmfilter::FootprintEdges& e, int strata, Rng& rng)
{
    std::uniform_real_distribution<double> u(0, 1);
    cmfilter::Rgb sum;
    for (int a = 0; a < strata; ++a)
        for (int b = 0; b < strata; ++b) {
            const double s = (a + u(rng)) / strata - 0.5, t = (b + u(rng)) / strata - 0.5;
            sum += f.map.evaluate(f.noise.noise()(x + s * e.e1x + t * e.e2x, y + s * e.e1y + t * e.e2y));
        }
    return (1.0 / (static_cast<double>(strata) * strata)) * sum;
}

// The same over the square footprint of width w.
template <class Rng>
cmfilter::Rgb supersampled_colour(const NoiseTransitionFixture& f, double x, double y, double w, int strata, Rng& rng)
{
    return supersampled_colour(f, x, y, cmfilter::FootprintEdges::square(w), strata, rng);
}

}  // namespace cmfilter_test
