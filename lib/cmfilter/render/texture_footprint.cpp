// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/texture_footprint.h"

#include "cmfilter/colormap/map_breakpoints.h"
#include "cmfilter/math/moment_mixture.h"

#include "cmfilter/texture/anisotropic_probes.h"
#include "cmfilter/texture/texture_lod.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

namespace {

// sum_b h_b C0(v_b) (sec. 4.1), the inner product of eq. 8 over the
// histogram at (u, v) and the trilinear lookup LOD lod (below 0: level 0). A
// failed lookup leaves zero weights (black), as apply's exact method.
Rgb histogram_color(const HistogramTexture& histograms, double u, double v, double lod, const std::vector<Rgb>& colors,
                    std::vector<float>& weights)
{
    weights.resize(colors.size());
    if (histograms.info().wrap == TextureWrap::Periodic) {
        u -= std::floor(u);
        v -= std::floor(v);
    }
    const float level = std::isfinite(lod) ? static_cast<float>(std::max(0.0, lod)) : 0.0f;
    histograms.lookup(static_cast<float>(u), static_cast<float>(v), level, weights.data());
    Rgb albedo;
    for (std::size_t b = 0; b < colors.size(); ++b) albedo += static_cast<double>(weights[b]) * colors[b];
    return albedo;
}

// c_0 + sum_k c_k R_k over the ramp means at (u, v) and the trilinear lookup
// LOD lod, wrapped as histogram_color's; a failed lookup reads zero means
// (C(t_0)).
Rgb segments_color(const TextureSegments& segments, double u, double v, double lod, std::vector<float>& ramps)
{
    const SegmentPyramidTexture& pyramid = *segments.pyramid;
    ramps.resize(static_cast<std::size_t>(pyramid.channels()));
    if (pyramid.info().wrap == TextureWrap::Periodic) {
        u -= std::floor(u);
        v -= std::floor(v);
    }
    const float level = std::isfinite(lod) ? static_cast<float>(std::max(0.0, lod)) : 0.0f;
    pyramid.lookup(static_cast<float>(u), static_cast<float>(v), level, ramps.data());
    return ramp_color(segments.ramp_colors, ramps.data());
}

}  // namespace

TextureFootprint filter_texture_footprint(const ColorLayer& color, const FilteredTexture& texture,
                                          const HistogramTexture* histograms, const SurfaceHit& h, TextureColor colour,
                                          FootprintWidth width, int max_probes, const std::vector<Rgb>& bin_colors,
                                          std::vector<float>& weights, const ColorPyramid* color_pyramid,
                                          const TextureSegments* segments)
{
    TextureFootprint out;
    const FootprintProbes probes = footprint_probes(h.du_dx, h.dv_dx, h.du_dy, h.dv_dy, max_probes, width);
    out.probes = probes.count;
    out.lod = texture.lod(probes.width);
    const double lookup_lod = trilinear_lod_for_box(out.lod);  // as FilteredTexture::filter's
    const MomentPyramidInfo& info = texture.moments().info();
    const MomentMixtureOptions mixture = pyramid_mixture_options(info.driver_min, info.driver_max);
    for (int j = 0; j < probes.count; ++j) {
        const double o = (j + 0.5) / probes.count - 0.5;
        const double u = h.u + o * probes.step_u, v = h.v + o * probes.step_v;
        const MomentSample f = texture.filter(u, v, probes.width);
        out.mean += f.mean;
        out.sigma += f.sigma;
        switch (colour) {
        case TextureColor::None: break;
        case TextureColor::Naive: out.albedo += color.map.evaluate(f.mean); break;
        case TextureColor::Gaussian: out.albedo += gaussian_albedo(color, f.mean, f.sigma, out.counts); break;
        case TextureColor::Mixture: {
            const MomentMixture mix = moment_mixture(f.mean, f.variance, f.mu3, f.mu4, mixture);
            out.albedo += mix.weight * gaussian_albedo(color, mix.lower, mix.sigma, out.counts);
            if (mix.weight < 1)
                out.albedo += (1 - mix.weight) * gaussian_albedo(color, mix.upper, mix.sigma, out.counts);
            break;
        }
        case TextureColor::Exact:
            out.albedo += histogram_color(*histograms, u, v, lookup_lod, bin_colors, weights);
            break;
        case TextureColor::ColorPyramid: {
            // The reachable levels, as the pyramids' TextureSystem lookups.
            const double top = texture.moments().reachable_levels() - 1;
            const double level = std::isfinite(lookup_lod) ? std::clamp(lookup_lod, 0.0, top) : 0.0;
            out.albedo += color_pyramid->lookup(u, v, level);
            break;
        }
        case TextureColor::Segments: out.albedo += segments_color(*segments, u, v, lookup_lod, weights); break;
        }
    }
    const double n = probes.count;
    out.albedo = (1.0 / n) * out.albedo;
    out.mean /= n;
    out.sigma /= n;
    return out;
}

}  // namespace cmfilter
