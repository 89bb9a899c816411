// SPDX-License-Identifier: Apache-2.0
// How `render` (render.h) colours one surface: one renderer per kind of
// material driver (material.h), made once per surface by
// make_surface_renderer (make_surface_renderer.h), the one place that tells
// the kinds apart:
//   noise         noise_surface.h
//   texture       texture_surface.h
//   microsurface  microsurface_surface.h (Gaussian microsurface)
//   displacement  displacement_surface.h (textured displacement)
// Each filters a centre ray's hit over its footprint for the one-ray methods
// (its albedo, and the driver's filtered mean, sigma and LOD there: the
// AOVs, all that supersampled pixels take) and adds one supersampled ray's
// hit to its pixel's sums.
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/math/vec3.h"
#include "cmfilter/microsurface/height_moment_table.h"
#include "cmfilter/microsurface/microsurface_albedo.h"
#include "cmfilter/render/render_options.h"
#include "cmfilter/scene/camera.h"
#include "cmfilter/scene/material.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/scene/surface_hit.h"
#include "cmfilter/tables/gaussian_albedo.h"
#include "cmfilter/util/error.h"

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace cmfilter {

// Lambertian: albedo x (radiance max(0, <n, l>) + ambient).
inline Rgb shade(const Rgb& albedo, const Vec3& normal, const SceneLight& light)
{
    const double lambert = std::max(0.0, dot(normal, light.direction));
    return {albedo.r * (light.radiance.r * lambert + light.ambient.r),
            albedo.g * (light.radiance.g * lambert + light.ambient.g),
            albedo.b * (light.radiance.b * lambert + light.ambient.b)};
}

// What every surface of one render shares.
struct RenderContext {
    const Scene& scene;
    const RenderOptions& options;
    bool supersampled = false;                        // supersample or reference
    MicrosurfaceLayerOptions layers;                  // microsurfaces: masking and slope shading (each layered
                                                      // surface sets its own D_h and D_s representations)
    const HeightMomentTable* height_table = nullptr;  // D_h's exact moments; set when a microsurface is present
};

// One thread's scratch space and counts.
struct HitScratch {
    std::vector<float> weights;  // histogram weights (exact)
    AlbedoCounts counts;         // gaussian_albedo's
};

// A hit's albedo filtered over its footprint (the one-ray methods), and the
// driver's filtered mean, sigma and LOD there (the AOVs).
struct FilteredHit {
    Rgb albedo;
    double mean = 0, sigma = 0, lod = 0;
};

// A pixel's rays that meet one microsurface: sum of C_h(h) <m, l>+ over the
// lit ones, of <m, l>+ over all, and how many.
struct MicrosurfaceSamples {
    Rgb lit_color;
    double light_cosine = 0;
    int count = 0;
    Vec3 normal;
};

// A supersampled pixel's sums over its rays: the albedo-shaded colour, the
// fully shaded one, the rays that hit a surface and their distances, and
// each microsurface's rays (by surface).
struct PixelSamples {
    Rgb sum, shaded_sum;
    int hits = 0;
    double distance = 0;
    std::vector<MicrosurfaceSamples> microsurfaces;

    void add_background(const Rgb& background)
    {
        sum += background;
        shaded_sum += background;
    }
};

class SurfaceRenderer {
public:
    virtual ~SurfaceRenderer() = default;
    // What the ray-traced methods need beyond the material (a microsurface's
    // heightfield); called once before the pixel loop when supersampled.
    virtual Status prepare_tracing(const RenderContext&) { return ok(); }
    // The hit's albedo over its footprint (the one-ray methods; supersampled
    // pixels take only the AOVs) and the AOVs.
    virtual FilteredHit filter(const SurfaceHit& hit, const RenderContext& context, HitScratch& scratch) const = 0;
    // One supersampled ray's hit, added to its pixel's sums.
    virtual void sample(const CameraRay& ray, const SurfaceHit& hit, const RenderContext& context,
                        PixelSamples& pixel) const = 0;
};

// A noise or texture driver's renderer: C0 of the driver f, also read at a
// point (a microsurface's base layer).
class DriverRenderer : public SurfaceRenderer {
public:
    // C0(f(u, v)), f point-evaluated (a texture: bilinear in its level 0).
    virtual Rgb point_albedo(double u, double v) const = 0;
    // C0(f) at the hit, shaded on its own.
    void sample(const CameraRay& ray, const SurfaceHit& hit, const RenderContext& context,
                PixelSamples& pixel) const override;
};

}  // namespace cmfilter
