// SPDX-License-Identifier: Apache-2.0
// `cmfilter render`: a scene (scene.h) seen through its pinhole camera, each
// pixel's colour-mapped surface filtered over the pixel's own footprint
// (docs/render.md). Every method uses the same box pixel:
//   naive        one ray through the pixel centre; C0(mean), the colour map
//                of the driver's filtered mean over the footprint;
//   gaussian     the same ray; T(mean, sigma) (eq. 10), sigma from the
//                noise's table at the footprint's LOD, or from a texture's
//                moment pyramid (sec. 4.2);
//   exact        the same ray; sum_b h_b C0(v_b) (sec. 4.1) for a texture
//                driver with at most 256 distinct values v_b, the weights h_b
//                from its histogram pyramid (histogram_pyramid.h), averaged
//                over the footprint's probes (texture_footprint.h): exact for
//                a footprint made of squares aligned with a pyramid level;
//                materials need their histograms
//                (MaterialOptions::histograms), and noise drivers are refused;
//   supersample  N rays per pixel (a jittered N = n x n grid when N is a
//                square, else N rooks: one sample per row and column of an
//                N x N grid, columns shuffled), each point-evaluating C0(f(x))
//                (a texture: f bilinear in its level 0) and shaded on its
//                own; misses count as background;
//   reference    supersample with at least 1024 rays (the paper's 32 x 32).
// A microsurface material (scene.h; secs. 5-6: a Gaussian microsurface or a
// textured displacement) is coloured by its layers instead
// (microsurface_albedo.h): by height, naive C_h of the footprint's mean
// height, gaussian V T(mean + mu_d, sigma_d) with the paper's fit (eqs. 13,
// 17-18), gaussian-exact the same with D_h's exact moments, exact V <C_h,
// D_h> (height_filtered_albedo.h, over the heights the footprint does not
// resolve, microsurface_footprint.h); by slope, naive C_s of the resolved
// slope, gaussian and gaussian-exact V <C_s, Gaussian of D_s's moments>,
// exact V <C_s, D_s> (slope_color.h; a displacement's own slopes,
// displacement_slope_color.h); a base layer C0 filtered as gaussian does;
// the layers summed with weights or multiplied. supersample and reference
// trace the displaced plane and its shadow rays (displaced_plane_sample.h),
// colour each hit by the combination and estimate the albedo per pixel
// (docs/microsurface.md). gaussian-exact on a driver surface is gaussian.
// The footprint is the parallelogram of the ray differentials in texture
// space (surface_hit.h), cut along its major edge into up to max_probes
// pieces (anisotropic_probes.h), each reduced to one width
// (footprint_width.h): a noise filters each piece at that width, a texture
// looks its pyramids up isotropically at the width's LOD, log2 of the width
// in level-0 texels (texture_footprint.h). A pixel's colour is the mean of
// its probes' colours.
// The one-ray methods cover the pixels on silhouettes, horizons and meetings
// of surfaces geometrically (RenderOptions::edge_coverage, pixel_coverage.h).
// Shading: Lambertian, albedo x (radiance max(0, <n, l>) + ambient).
// Deterministic for a given seed, whatever the thread count; a region of the
// frame (RenderOptions::region) holds the same pixels, bit for bit, as the
// whole frame's render.
#pragma once

#include "cmfilter/render/render_options.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/scene/scene_materials.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cmfilter {

// What a render holds per pixel at most: RenderedImage's 12 floats and a
// byte (49 bytes), and the rows its output files are written through. The
// peaks measured are 29 to 37 bytes a pixel (docs/reliability.md).
inline constexpr double kRenderBytesPerPixel = 64;

struct RenderedImage {
    // The pixels computed: width x height from (x0, y0) of the camera's
    // frame_width x frame_height frame (the whole frame unless
    // RenderOptions::region asked for less). Every vector below holds those
    // pixels only, top row first.
    int width = 0, height = 0;
    int x0 = 0, y0 = 0;
    int frame_width = 0, frame_height = 0;
    std::vector<float> rgb;  // scene-linear
    // Per pixel, from the ray through its centre (every method): whether it
    // hit a surface, its distance, and the filtered mean, sigma and LOD of
    // the driver there (0 where nothing is hit).
    std::vector<unsigned char> hit;
    std::vector<float> distance, mean, sigma, lod;
    // With RenderOptions::surface_indices (else empty): the index of the
    // surface the centre ray hits, -1 where it hits none.
    std::vector<std::int32_t> surface;
    // supersample and reference only (empty otherwise): the share of the
    // pixel's rays that hit a surface, and their mean distance (0 where none
    // does): the pixels a surface covers in part, whose centre ray may miss.
    std::vector<float> covered, covered_distance;
    // supersample and reference on a scene with a microsurface (else empty):
    // the fully shaded image, each ray's hit lit by the light through its own
    // micro-normal and shadow ray, C_h(h) (radiance <m, l>+ V + ambient),
    // where rgb holds the eq. 14 albedo shaded by the plane's normal.
    std::vector<float> shaded;
    RenderMethod method = RenderMethod::Gaussian;
    int samples = 1;  // rays per pixel
    // gaussian: footprints (pixels or probes) coloured, and how many took
    // C0(mean) directly (the small-sigma shortcut, gaussian_albedo.h).
    std::size_t footprints = 0, plain_footprints = 0;
    double seconds = 0;  // wall time of the pixel loop
};

// Each surface is coloured by its material's driver kind
// (surface_renderer.h). BadInput for a sample count outside 1 .. kMaxSamples,
// a material count that does not match the scene, or, for the exact method,
// a noise driver or a texture without its histogram pyramid, or a
// RenderOptions::region that is empty or outside the camera's frame;
// Io for supersample or reference on a texture without its level 0 (a
// moments driver whose recorded driver is gone, naming it).
Expected<RenderedImage> render(const Scene& scene, const std::vector<Material>& materials,
                               const RenderOptions& options);

// What `method` needs of the materials prepared for it (scene_materials.h):
// exact the histogram pyramids of texture drivers, segments their segment
// pyramids, mixture four moments in the pyramids baked in process. Sets
// those fields of `options`.
void set_method_materials(RenderMethod method, MaterialOptions& options);

}  // namespace cmfilter
