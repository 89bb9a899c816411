// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/layered_surface.h"

#include "cmfilter/render/displaced_plane_sample.h"
#include "cmfilter/render/make_driver_renderer.h"
#include "cmfilter/texture/anisotropic_probes.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The view and light directions in a microsurface plane's frame: its unit
// mapping axes and the normal facing the viewer (scene.h).
HeightDirections height_directions(const Surface& surface, const SurfaceHit& h, const Vec3& view, const Vec3& light)
{
    const Vec3 x = normalize(surface.mapping.u_axis), y = normalize(surface.mapping.v_axis);
    HeightDirections d;
    const auto angles = [&](const Vec3& w, double& theta, double& phi) {
        const double c = dot(w, h.normal);
        theta = c > 0 ? std::acos(std::min(1.0, c)) : 0.5 * kPi;
        phi = std::atan2(dot(w, y), dot(w, x));
    };
    angles(view, d.theta_o, d.phi_o);
    angles(light, d.theta_i, d.phi_i);
    return d;
}

}  // namespace

LayeredSurfaceRenderer::LayeredSurfaceRenderer(std::size_t surface, const MicrosurfaceColors& colors,
                                               std::unique_ptr<DriverRenderer> base,
                                               const DisplacementTexture* displacement, RenderMethod method)
    : surface_(surface), colors_(colors), base_(std::move(base)), displacement_(displacement),
      heights_(height_representation(method)), slopes_(slope_representation(method))
{
}

FilteredHit LayeredSurfaceRenderer::filter(const SurfaceHit& h, const RenderContext& context, HitScratch& scratch) const
{
    const Scene& scene = context.scene;
    // Height- and slope-correlated colour and a base layer (secs. 5-6),
    // masked and shadowed.
    const HeightDirections directions = height_directions(
        scene.surfaces[surface_], h, normalize(scene.camera.position - h.point), scene.light.direction);
    std::optional<Rgb> base;
    if (base_ && !context.supersampled) base = base_->filter(h, context, scratch).albedo;

    const FootprintProbes probes = footprint_probes(h.du_dx, h.dv_dx, h.du_dy, h.dv_dy,
                                                    max_probes_of(context.options, surface_), FootprintWidth::Rms);
    const int count = probes.count;
    const double au = probes.step_u, av = probes.step_v, bu = probes.minor_u, bv = probes.minor_v;
    MicrosurfaceLayerOptions layers = context.layers;
    layers.heights = heights_;
    layers.slopes = slopes_;
    FilteredHit out;
    double visibility = 0;
    Rgb shadowed;
    for (int j = 0; j < count; ++j) {
        const double o = (j + 0.5) / count - 0.5;
        const double u = h.u + o * au, v = h.v + o * av;
        const FootprintPiece piece{u, v, au / count, av / count, bu, bv};
        MicrosurfaceFootprint f;
        ResolvedSlope slope;
        filter_piece(piece, f, slope);
        const MicrosurfaceLayers a = microsurface_layers(colors_, f, slope, directions, layers, *context.height_table,
                                                         scratch.counts, displacement_, &piece);
        visibility += a.visibility;
        shadowed += a.shadowed;
        out.mean += a.mean;
        out.sigma += a.sigma;
    }
    out.albedo = combine_microsurface_albedo(colors_.combine, visibility / count, (1.0 / count) * shadowed, base);
    out.mean /= count;
    out.sigma /= count;
    out.lod = std::log2(std::max({std::hypot(au, av) / count, std::hypot(bu, bv), 1e-300}));
    return out;
}

void LayeredSurfaceRenderer::sample(const CameraRay& ray, const SurfaceHit& h, const RenderContext& context,
                                    PixelSamples& pixel) const
{
    const Scene& scene = context.scene;
    // The displaced plane, ray traced (displaced_plane_sample.h).
    const auto traced = trace_displaced_plane(scene.surfaces[surface_], *heightfield_, ray.origin, ray.direction,
                                              scene.light.direction, heightfield_shift_);
    if (!traced) {
        pixel.add_background(scene.background);
        return;
    }
    // The material's colour at the hit (microsurface_albedo.h).
    std::optional<Rgb> base, height, slope;
    if (base_) base = base_->point_albedo(traced->x, traced->y);
    if (colors_.height) height = colors_.height->map.evaluate(traced->height);
    if (colors_.slope)
        slope =
            std::visit([&](const auto& map) { return map.evaluate(traced->slope_x, traced->slope_y); }, *colors_.slope);
    const Rgb c = combine_point_color(colors_.combine, base, height, slope);
    MicrosurfaceSamples& acc = pixel.microsurfaces[surface_];
    const double lit = traced->lit ? traced->light_cosine : 0.0;
    acc.lit_color += lit * c;
    acc.light_cosine += traced->light_cosine;
    acc.normal = h.normal;
    ++acc.count;
    const SceneLight& light = scene.light;
    pixel.shaded_sum += Rgb{c.r * (light.radiance.r * lit + light.ambient.r),
                            c.g * (light.radiance.g * lit + light.ambient.g),
                            c.b * (light.radiance.b * lit + light.ambient.b)};
    ++pixel.hits;
    pixel.distance += traced->t;
}

RenderMethod layered_method(const RenderOptions& options, std::size_t surface)
{
    return surface < options.microsurface_methods.size() ? options.microsurface_methods[surface] : options.method;
}

HeightRepresentation height_representation(RenderMethod method)
{
    switch (method) {
    case RenderMethod::Naive: return HeightRepresentation::Naive;
    case RenderMethod::GaussianExact: return HeightRepresentation::ExactMoments;
    case RenderMethod::Exact: return HeightRepresentation::Exact;
    default: return HeightRepresentation::PaperFit;
    }
}

SlopeRepresentation slope_representation(RenderMethod method)
{
    switch (method) {
    case RenderMethod::Naive: return SlopeRepresentation::Naive;
    case RenderMethod::Exact: return SlopeRepresentation::Exact;
    default: return SlopeRepresentation::Gaussian;
    }
}

Expected<std::unique_ptr<DriverRenderer>> make_base_renderer(const std::shared_ptr<const Material>& base,
                                                             std::size_t surface, const RenderOptions& options,
                                                             RenderMethod method)
{
    if (!base) return std::unique_ptr<DriverRenderer>();
    return make_driver_renderer(*base, surface,
                                method == RenderMethod::Naive ? RenderMethod::Naive : RenderMethod::Gaussian, options);
}

}  // namespace cmfilter
