// SPDX-License-Identifier: Apache-2.0
// Helpers for the microsurface tests: angles, a test microsurface, a small
// clamp colour map whose channels
// all lie strictly inside (0, 1), a colour layer built from it by hand
// with a Gaussian table whose value nodes fall on the map's texel centres (so
// the table's sigma = 0 row is C0 itself, up to float32 storage), an
// independent piecewise-linear C0, the per-channel colour range, and
// footprints made by hand.
#pragma once

#include "cmfilter/colormap/color_map.h"
#include "cmfilter/tables/gaussian_color_table.h"
#include "cmfilter/microsurface/gaussian_microsurface.h"
#include "cmfilter/microsurface/microsurface_footprint.h"
#include "cmfilter/microsurface/microsurface_colors.h"
#include "cmfilter/tables/color_layer.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace cmfilter_test {

inline constexpr double kPi = 3.14159265358979323846;
inline const double kInf = std::numeric_limits<double>::infinity();

inline double degrees(double d) { return d * kPi / 180; }

// A periodic microsurface like the bundled example's: wavelengths 0.05 to
// 0.4, tile 3.2 (8 longest wavelengths).
inline cmfilter::GaussianMicrosurface test_microsurface(double sigma_h, int cosines, std::uint64_t seed)
{
    cmfilter::GaussianMicrosurfaceOptions o;
    o.cosines = cosines;
    o.sigma_h = sigma_h;
    o.min_wavelength = 0.05;
    o.max_wavelength = 0.4;
    o.seed = seed;
    o.tile = 3.2;
    auto surface = cmfilter::GaussianMicrosurface::create(o);
    REQUIRE(surface);
    return *surface;
}

// Six texels over [-0.03, 0.03]: centres -0.025 .. 0.025, 0.01 apart, from a
// dark sand to a bluish snow (every channel in [0.05, 0.95]).
inline cmfilter::ColorMap microsurface_test_map()
{
    cmfilter::ColorMap map;
    map.texels = {{0.30, 0.20, 0.08}, {0.45, 0.33, 0.15}, {0.62, 0.50, 0.30},
                  {0.70, 0.68, 0.60}, {0.85, 0.88, 0.90}, {0.93, 0.95, 0.95}};
    map.vmin = -0.03;
    map.vmax = 0.03;
    map.wrap = cmfilter::WrapMode::Clamp;
    return map;
}

// C0(v) by hand: the texels' centres joined by straight lines, the end
// colours beyond them (clamp).
inline cmfilter::Rgb reference_map_color(const cmfilter::ColorMap& map, double v)
{
    const int n = static_cast<int>(map.texels.size());
    const double width = (map.vmax - map.vmin) / n;
    const double first = map.vmin + 0.5 * width, last = map.vmax - 0.5 * width;
    if (!(v > first)) return map.texels.front();
    if (v >= last) return map.texels.back();
    const double x = (v - first) / width;
    const int i = std::min(n - 2, static_cast<int>(std::floor(x)));
    const double f = x - i;
    return (1 - f) * map.texels[static_cast<std::size_t>(i)] + f * map.texels[static_cast<std::size_t>(i + 1)];
}

// The largest |dC0/dv| over the channels (the steepest segment).
inline double steepest_map_slope(const cmfilter::ColorMap& map)
{
    const double width = (map.vmax - map.vmin) / static_cast<double>(map.texels.size());
    double steepest = 0;
    for (std::size_t i = 0; i + 1 < map.texels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            steepest = std::max(steepest, std::fabs(map.texels[i + 1][c] - map.texels[i][c]) / width);
    return steepest;
}

struct ColorRange {
    cmfilter::Rgb lo, hi;
};

inline ColorRange color_range(const cmfilter::ColorMap& map)
{
    ColorRange r{map.texels.front(), map.texels.front()};
    for (const cmfilter::Rgb& t : map.texels) {
        r.lo = {std::min(r.lo.r, t.r), std::min(r.lo.g, t.g), std::min(r.lo.b, t.b)};
        r.hi = {std::max(r.hi.r, t.r), std::max(r.hi.g, t.g), std::max(r.hi.b, t.b)};
    }
    return r;
}

// Whether every channel of c lies in [scale lo, scale hi], with a relative slack.
inline bool within_scaled_range(const cmfilter::Rgb& c, const ColorRange& range, double scale, double slack)
{
    for (int k = 0; k < 3; ++k) {
        const double lo = scale * range.lo[k], hi = scale * range.hi[k];
        if (!(c[k] >= lo - slack * (1 + hi) && c[k] <= hi + slack * (1 + hi))) return false;
    }
    return true;
}

inline bool is_finite(const cmfilter::Rgb& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

// The test map with a table of `nodes_per_texel` (even) value nodes per texel
// over [vmin - 0.03, vmax + 0.03] (margin 0.03: node 3.5 k is the first texel
// centre) and `sigmas` sigma nodes (sqrt spacing) up to sigma_max; no
// small-sigma shortcut.
inline cmfilter::ColorLayer microsurface_test_layer(int nodes_per_texel, int sigmas, double sigma_max)
{
    cmfilter::ColorLayer m;
    m.map = microsurface_test_map();
    cmfilter::GaussianColorTableOptions o;
    o.values = 12 * nodes_per_texel + 1;  // (0.06 + 0.06) / (0.01 / k) intervals
    o.sigmas = sigmas;
    o.sigma_max = sigma_max;
    o.margin = 0.03;
    o.threads = 1;
    auto table = cmfilter::GaussianColorTable::bake(m.map, o);
    REQUIRE(table);
    m.table = std::move(*table);
    return m;
}

// A footprint given by hand: the resolved mean height, the unresolved height
// deviation and isotropic unresolved slopes of deviation sigma_s, and the
// resolved surface's height and (isotropic) slope deviations.
inline cmfilter::MicrosurfaceFootprint hand_footprint(double mean_height, double sigma_h, double sigma_s,
                                                      double resolved_sigma_h = 0, double resolved_sigma_s = 0)
{
    cmfilter::MicrosurfaceFootprint f;
    f.mean_height = mean_height;
    f.sigma_h = sigma_h;
    f.slope_xx = f.slope_yy = sigma_s * sigma_s;
    f.slope_xy = 0;
    f.resolved_sigma_h = resolved_sigma_h;
    f.resolved_xx = f.resolved_yy = resolved_sigma_s * resolved_sigma_s;
    f.resolved_xy = 0;
    return f;
}

}  // namespace cmfilter_test
