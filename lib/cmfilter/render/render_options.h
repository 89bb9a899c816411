// SPDX-License-Identifier: Apache-2.0
// The methods and options of `render` (render.h).
#pragma once

#include "cmfilter/microsurface/light_weighted_slope_map.h"
#include "cmfilter/microsurface/smith_lambda.h"
#include "cmfilter/noise/noise_sub_footprints.h"
#include "cmfilter/render/pixel_region.h"
#include "cmfilter/texture/footprint_width.h"
#include "cmfilter/util/error.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cmfilter {

// Mixture: texture drivers with four moments (math/moment_mixture.h, as
// apply's); noise drivers as a mixture over sub-footprints in the transition
// (noise/noise_sub_footprints.h); every other driver as Gaussian.
// ColorPyramid: texture drivers alone, from the box means of C0(f) of their
// level 0 (texture/color_pyramid.h); refused for any other driver.
// Segments: texture drivers alone, from the ramp means of their segment
// pyramid (texture/segment_pyramid_file.h: the scene's, or one baked in
// process for the material's map) weighed by the map's colours through its
// breakpoints; refused for any other driver.
enum class RenderMethod {
    Naive,
    Gaussian,
    GaussianExact,
    Exact,
    Supersample,
    Reference,
    Mixture,
    ColorPyramid,
    Segments
};
const char* to_string(RenderMethod method);
Expected<RenderMethod> parse_render_method(const std::string& text);

inline constexpr int kReferenceSamples = 1024;
inline constexpr int kMaxSamples = 1 << 16;
// The most probes an anisotropic footprint is cut into (RenderOptions::max_probes).
inline constexpr int kMaxProbes = 64;

struct RenderOptions {
    RenderMethod method = RenderMethod::Gaussian;
    int samples = 16;  // supersample: N >= 1; reference: max(N, 1024)
    std::uint64_t seed = 0;
    int threads = 0;  // 0: all cores
    FootprintWidth footprint = FootprintWidth::Rms;
    // Naive, gaussian and exact: filter an anisotropic footprint as up to
    // this many probes along its major edge (anisotropic_probes.h; textures:
    // texture_footprint.h); 1: one footprint. 16 by default: on the bundled
    // ground planes the error stops falling there (docs/render.md).
    int max_probes = 16;
    // naive, gaussian, exact: where a silhouette, a horizon or a meeting of
    // two surfaces crosses the pixel, mix each surface seen (filtered over
    // its own part) and the background by their shares of the box pixel
    // (pixel_coverage.h), as the supersampled methods do; false: the centre
    // ray's surface (or the background) for the whole pixel.
    bool edge_coverage = true;
    // Microsurfaces: how masking and shadowing combine (smith_lambda.h):
    // correlated by azimuth (the default: gaussian-exact within 0.5 mean
    // CIEDE2000 of the ray-traced reference up to 80 degrees in every set-up
    // of docs/microsurface.md, where with eq. 13 it is 2.2 from it with the
    // light from the viewer), or independent as in the paper's eq. 13.
    MaskingShadowing masking = MaskingShadowing::DirectionCorrelated;
    // Microsurfaces coloured by slope: weighted by each facet's cosine to the
    // light (the default, light_weighted_slope_map.h: from up to 25 mean
    // CIEDE2000 to under 2 on a slope-vector map lit from the side,
    // docs/slope.md), or eq. 19's colour (the facets' shading uncorrelated
    // with it).
    SlopeShading slope_shading = SlopeShading::Correlated;
    // The pixels to compute (pixel_region.h; within the camera's frame):
    // each exactly as the whole frame's render computes it, whatever the
    // thread count, since every pixel's rays are seeded by its index in the
    // whole frame. Empty: the whole frame.
    std::optional<PixelRegion> region;
    // The one-ray method of each surface with a texture driver, by surface
    // index (render --method auto: chosen per material); empty, or a surface
    // past its end: `method`. Other drivers take `method`.
    std::vector<RenderMethod> texture_methods;
    // The one-ray method of each surface with a microsurface material (a
    // Gaussian microsurface or a textured displacement), by surface index
    // (render --method auto: chosen per material,
    // microsurface_method_choice.h): naive, gaussian, gaussian-exact or
    // exact; empty, or a surface past its end: `method`. Other materials
    // take `method`.
    std::vector<RenderMethod> microsurface_methods;
    // Mixture, noise drivers: how many sub-footprints a footprint (or each
    // probe of one) is cut into (noise_sub_footprints.h).
    SubFootprintOptions sub_footprints;
    // The most squares per axis of each surface with a noise driver, by
    // surface index (render --method auto: chosen per material): a count >= 1
    // renders that surface by mixture with it (1: as gaussian); empty, 0 or
    // past its end: `method` with `sub_footprints`.
    std::vector<int> noise_sub_footprints;
    // The most probes of each surface's footprints, by surface index
    // (render --method auto: chosen per surface, surface_probe_choice.h);
    // 0, or a surface past its end: max_probes. A surface's base layer and
    // its pieces on edges take its own.
    std::vector<int> surface_probes;
    // Also fill RenderedImage::surface (which surface each pixel's centre ray
    // hits): what surface_lod_ranges (surface_lods.h) needs.
    bool surface_indices = false;
    std::function<void(double)> progress;  // fraction of rows done, may be empty
};

// BadInput (field RenderOptions::samples) for a sample count outside
// 1 .. kMaxSamples: the one check of a count of rays per pixel.
Status check_render_samples(int samples);

// BadInput (field RenderOptions::microsurface_methods) for a method there
// other than naive, gaussian, gaussian-exact or exact.
Status check_microsurface_methods(const std::vector<RenderMethod>& methods);

// BadInput (field RenderOptions::max_probes) for a probe count outside
// 1 .. kMaxProbes.
Status check_render_probes(int probes);

// BadInput (field RenderOptions::surface_probes) for a count there outside
// 0 .. kMaxProbes.
Status check_surface_probes(const std::vector<int>& probes);

// The most probes of surface `surface`'s footprints: its entry of
// surface_probes when > 0, else max_probes.
int max_probes_of(const RenderOptions& options, std::size_t surface);

}  // namespace cmfilter
