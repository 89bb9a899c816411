// SPDX-License-Identifier: Apache-2.0
// A texture driver (filtered_texture.h) over the footprint of a pixel's
// centre ray, for the one-ray methods of `render` (render.h). The footprint
// is the parallelogram c + s e1 + t e2, s, t in [-1/2, 1/2], of the ray
// differentials (surface_hit.h); like a noise driver, it is cut along its
// major edge into up to max_probes pieces (anisotropic_probes.h), each a
// square of the chosen FootprintWidth, and each probe gives its own colour:
//   naive     C0(mean_j), mean_j the probe's box mean of f;
//   gaussian  T(mean_j, sigma_j) (eq. 10; C0(mean_j) below the small-sigma
//             shortcut's threshold, gaussian_albedo.h) with the probe's moments (sec. 4.2:
//             mean = c + m1, sigma^2 = m2 - m1^2), an isotropic trilinear
//             lookup of the moment pyramid (FilteredTexture::filter) at the
//             LOD whose kernel has the variance of the probe's box
//             (trilinear_lod_for_box, texture_lod.h);
//   mixture   p T(a, s) + (1 - p) T(b, s), the two Gaussians of one width
//             with the probe's four moments (a pyramid of order 4,
//             math/moment_mixture.h), each through gaussian_albedo;
//   exact     sum_b h_b C0(v_b) (sec. 4.1), h_b the probe's histogram, a
//             trilinear lookup of the histogram pyramid at the same LOD
//             (needs the texture's histogram pyramid);
//   color-pyramid  mean C0(f) over the probe, a trilinear lookup of the
//             driver's colour pyramid (texture/color_pyramid.h: the box
//             means of C0(f) of its level 0) at the same LOD;
//   segments  c_0 + sum_k c_k R_k, R_k the probe's ramp means, a trilinear
//             lookup of the driver's segment pyramid
//             (texture/segment_pyramid_file.h) at the same LOD, c_k the
//             map's ramp colours through its breakpoints (ramp_colors,
//             colormap/map_breakpoints.h): the box mean of C0 over the probe
//             for a map linear between them.
// The pixel's albedo is the mean of its probes' colours: a thin footprint
// near the horizon keeps what varies across it. For a footprint made of
// squares aligned with a pyramid level (a probe width of 2^k level-0 texels
// centred on level-k texels) each probe reads one texel of level k, and
// exact is the box mean of C0 over the footprint's texels.
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/texture/footprint_width.h"
#include "cmfilter/scene/surface_hit.h"
#include "cmfilter/tables/color_layer.h"
#include "cmfilter/tables/gaussian_albedo.h"
#include "cmfilter/texture/color_pyramid.h"
#include "cmfilter/texture/filtered_texture.h"
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/texture/segment_pyramid_texture.h"

#include <vector>

namespace cmfilter {

enum class TextureColor { None, Naive, Gaussian, Mixture, Exact, ColorPyramid, Segments };

// Segments: the texture's segment pyramid and the colours its ramp means
// are weighed by for the material's map (ramp_colors: c_0, then the steps).
struct TextureSegments {
    const SegmentPyramidTexture* pyramid = nullptr;
    std::vector<Rgb> ramp_colors;
};

struct TextureFootprint {
    Rgb albedo;        // mean of the probes' colours (black for TextureColor::None)
    double mean = 0;   // mean of the probes' means: the footprint's mean of f
    double sigma = 0;  // mean of the probes' sigmas
    double lod = 0;    // LOD of one probe's width, log2 of it in level-0 texels
    int probes = 1;
    AlbedoCounts counts;  // gaussian: probes coloured, and those that took C0(mean) (gaussian_albedo.h)
};

// `color`: C0 and its table over the texture's values; `histograms`: the
// texture's histogram pyramid (Exact only); `bin_colors`: C0(v_b) for its
// values (Exact only); `weights`: scratch space for the histogram weights;
// `color_pyramid`: the texture's colour pyramid through C0 (ColorPyramid
// only); `segments`: its segment pyramid and ramp colours (Segments only;
// `weights` holds the ramp means).
TextureFootprint filter_texture_footprint(const ColorLayer& color, const FilteredTexture& texture,
                                          const HistogramTexture* histograms, const SurfaceHit& h, TextureColor colour,
                                          FootprintWidth width, int max_probes, const std::vector<Rgb>& bin_colors,
                                          std::vector<float>& weights, const ColorPyramid* color_pyramid = nullptr,
                                          const TextureSegments* segments = nullptr);

}  // namespace cmfilter
