// SPDX-License-Identifier: Apache-2.0
// Helpers shared by the unit tests: a library colour map paired with its
// independent test-side twin, and the built-in colour config.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/colormap/color_map.h"

#include "reference_convolution.h"

#include <doctest/doctest.h>

#include <random>
#include <string>

namespace cmfilter_test {

// The same texels as a libcmfilter ColorMap and as a ReferenceMap.
struct MapPair {
    cmfilter::ColorMap map;
    ReferenceMap ref;
};

// n random texels (blue up to 4: HDR maps too) over [vmin, vmax].
inline MapPair random_map(std::mt19937_64& rng, int n, cmfilter::WrapMode wrap, double vmin, double vmax)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    MapPair p;
    p.map.vmin = p.ref.vmin = vmin;
    p.map.vmax = p.ref.vmax = vmax;
    p.map.wrap = wrap;
    p.ref.wrap = cmfilter::to_string(wrap);
    for (int i = 0; i < n; ++i) {
        const double r = unit(rng), g = unit(rng), b = 4.0 * unit(rng);
        p.map.texels.push_back({r, g, b});
        p.ref.texels.push_back({r, g, b});
    }
    return p;
}

inline cmfilter::ColorConfig builtin_color_config()
{
    auto config = cmfilter::ColorConfig::load("");
    REQUIRE(config);
    return *config;
}

}  // namespace cmfilter_test
