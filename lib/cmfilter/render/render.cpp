#include "cmfilter/render/render.h"

#include "cmfilter/texture/anisotropic_probes.h"
#include "cmfilter/scene/camera.h"
#include "cmfilter/render/displaced_plane_sample.h"
#include "cmfilter/tables/gaussian_albedo.h"
#include "cmfilter/microsurface/height_filtered_albedo.h"
#include "cmfilter/microsurface/microsurface_albedo.h"
#include "cmfilter/microsurface/microsurface_footprint.h"
#include "cmfilter/noise/noise_lattice.h"
#include "cmfilter/util/parallel_for.h"
#include "cmfilter/scene/pixel_coverage.h"
#include "cmfilter/util/stopwatch.h"
#include "cmfilter/scene/surface_hit.h"
#include "cmfilter/render/texture_footprint.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <numeric>
#include <optional>
#include <variant>

namespace cmfilter {

const char* to_string(RenderMethod method)
{
    switch (method) {
    case RenderMethod::Naive: return "naive";
    case RenderMethod::Gaussian: return "gaussian";
    case RenderMethod::GaussianExact: return "gaussian-exact";
    case RenderMethod::Exact: return "exact";
    case RenderMethod::Supersample: return "supersample";
    case RenderMethod::Reference: return "reference";
    }
    return "gaussian";
}

Expected<RenderMethod> parse_render_method(const std::string& text)
{
    for (RenderMethod m : {RenderMethod::Naive, RenderMethod::Gaussian, RenderMethod::GaussianExact, RenderMethod::Exact,
                           RenderMethod::Supersample, RenderMethod::Reference})
        if (text == to_string(m)) return m;
    return bad_input("method '" + text +
                     "' is unknown (expected naive, gaussian, gaussian-exact, exact, supersample or reference)");
}

namespace {

constexpr double kPi = 3.14159265358979323846;

Rgb shade(const Rgb& albedo, const Vec3& normal, const SceneLight& light)
{
    const double lambert = std::max(0.0, dot(normal, light.direction));
    return {albedo.r * (light.radiance.r * lambert + light.ambient.r),
            albedo.g * (light.radiance.g * lambert + light.ambient.g),
            albedo.b * (light.radiance.b * lambert + light.ambient.b)};
}

// Sub-pixel positions in [0, 1)^2 for pixel `index`: a jittered n x n grid
// when count = n^2, else N rooks with shuffled columns.
void sample_positions(int count, std::uint64_t seed, std::uint64_t index, std::vector<double>& xs,
                      std::vector<double>& ys)
{
    std::uint64_t state = seed ^ (index * 0x9E3779B97F4A7C15ull);
    splitmix64(state);
    xs.resize(static_cast<std::size_t>(count));
    ys.resize(static_cast<std::size_t>(count));
    const int n = static_cast<int>(std::lround(std::sqrt(static_cast<double>(count))));
    if (n * n == count) {
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const auto k = static_cast<std::size_t>(j * n + i);
                xs[k] = (i + unit_interval(splitmix64(state))) / n;
                ys[k] = (j + unit_interval(splitmix64(state))) / n;
            }
        return;
    }
    std::vector<int> columns(static_cast<std::size_t>(count));
    std::iota(columns.begin(), columns.end(), 0);
    for (int k = count - 1; k > 0; --k)  // Fisher-Yates with the pixel's own stream
        std::swap(columns[static_cast<std::size_t>(k)],
                  columns[static_cast<std::size_t>(splitmix64(state) % static_cast<std::uint64_t>(k + 1))]);
    for (int k = 0; k < count; ++k) {
        ys[static_cast<std::size_t>(k)] = (k + unit_interval(splitmix64(state))) / count;
        xs[static_cast<std::size_t>(k)] = (columns[static_cast<std::size_t>(k)] + unit_interval(splitmix64(state))) / count;
    }
}

// A noise driver over the centre ray's footprint, as one width
// (footprint_width.h): its mean and sigma (sec. 4.2) and the footprint's LOD.
struct FilteredDriver {
    double mean = 0, sigma = 0, lod = 0;
};

FilteredDriver filter_driver(const SurfaceMaterial& m, const SurfaceHit& h, FootprintWidth choice)
{
    const double w = footprint_width(choice, h.du_dx, h.dv_dx, h.du_dy, h.dv_dy);
    const FilteredNoise::Parameters f = m.noise->filter(h.u, h.v, w);
    return {f.mean, f.sigma, m.noise->lod(w)};
}

// What a texture driver's probes colour for a method (texture_footprint.h):
// supersampled pixels take only the AOVs from them.
TextureColor texture_color(RenderMethod method)
{
    switch (method) {
    case RenderMethod::Naive: return TextureColor::Naive;
    case RenderMethod::Gaussian:
    case RenderMethod::GaussianExact: return TextureColor::Gaussian;
    case RenderMethod::Exact: return TextureColor::Exact;
    default: return TextureColor::None;
    }
}

// A hit's colour filtered over its footprint (rgb of the one-ray methods),
// and the driver's filtered mean, sigma and LOD there (the AOVs).
struct FilteredHit {
    Rgb colour;
    double mean = 0, sigma = 0, lod = 0;
};

// The driver at a point, for the supersampled methods.
double driver_value(const SurfaceMaterial& m, double u, double v)
{
    return m.texture ? m.texture->value(u, v) : m.noise->noise()(u, v);
}

// A pixel's rays that meet one microsurface: sum of C_h(h) <m, l>+ over the
// lit ones, of <m, l>+ over all, and how many.
struct MicrosurfaceSamples {
    Rgb lit_color;
    double light_cosine = 0;
    int count = 0;
    Vec3 normal;
};

// How a one-ray method represents a microsurface's height filtering
// distribution (height_filtered_albedo.h).
HeightRepresentation height_representation(RenderMethod method)
{
    switch (method) {
    case RenderMethod::Naive: return HeightRepresentation::Naive;
    case RenderMethod::GaussianExact: return HeightRepresentation::ExactMoments;
    case RenderMethod::Exact: return HeightRepresentation::Exact;
    default: return HeightRepresentation::PaperFit;
    }
}

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

// How the one-ray methods represent a microsurface's slope filtering
// distribution (microsurface_albedo.h).
SlopeRepresentation slope_representation(RenderMethod method)
{
    switch (method) {
    case RenderMethod::Naive: return SlopeRepresentation::Naive;
    case RenderMethod::Exact: return SlopeRepresentation::Exact;
    default: return SlopeRepresentation::Gaussian;
    }
}

// A microsurface over a hit's footprint: the parallelogram of the ray
// differentials cut along its longer edge into up to max_probes pieces
// (anisotropic_probes.h), each filtered exactly (microsurface_footprint.h)
// and its layers coloured (microsurface_albedo.h); V and the layers averaged
// and combined with the base layer's colour, if any (`base`).
struct MicrosurfaceFiltered {
    Rgb albedo;
    double mean = 0, sigma = 0, lod = 0;
};

MicrosurfaceFiltered filter_microsurface_hit(const SurfaceMaterial& m, const SurfaceHit& h,
                                             const HeightDirections& directions,
                                             const MicrosurfaceLayerOptions& layer_options, int max_probes,
                                             const HeightMomentTable& table, const std::optional<Rgb>& base,
                                             AlbedoCounts& counts)
{
    const FootprintProbes probes =
        footprint_probes(h.du_dx, h.dv_dx, h.du_dy, h.dv_dy, max_probes, FootprintWidth::Rms);
    const int count = probes.count;
    const double au = probes.step_u, av = probes.step_v, bu = probes.minor_u, bv = probes.minor_v;
    MicrosurfaceFiltered out;
    double visibility = 0;
    Rgb shadowed;
    for (int j = 0; j < count; ++j) {
        const double o = (j + 0.5) / count - 0.5;
        const double u = h.u + o * au, v = h.v + o * av;
        MicrosurfaceFootprint f;
        ResolvedSlope slope;
        if (m.microsurface) {
            f = filter_microsurface(*m.microsurface, u, v, au / count, av / count, bu, bv);
            if (m.slope_map) slope = resolved_slope(*m.microsurface, u, v, au / count, av / count, bu, bv);
        } else {
            // A displacement texture's moments over the piece: nothing it
            // resolves is taken as shadowing geometry (V_r = 1).
            const DisplacementFootprint d = m.displacement->footprint(u, v, au / count, av / count, bu, bv);
            f.mean_height = d.mean_height;
            f.sigma_h = d.sigma_h;
            f.slope_xx = d.slope_xx;
            f.slope_xy = d.slope_xy;
            f.slope_yy = d.slope_yy;
            slope = {d.slope_x, d.slope_y};
        }
        const FootprintPiece piece{u, v, au / count, av / count, bu, bv};
        const MicrosurfaceLayers a = microsurface_layers(m, f, slope, directions, layer_options, table, counts, &piece);
        visibility += a.visibility;
        shadowed += a.shadowed;
        out.mean += a.mean;
        out.sigma += a.sigma;
    }
    out.albedo = combine_microsurface_albedo(m.combine, visibility / count, (1.0 / count) * shadowed, base);
    out.mean /= count;
    out.sigma /= count;
    out.lod = std::log2(std::max({std::hypot(au, av) / count, std::hypot(bu, bv), 1e-300}));
    return out;
}

// A driver's colour over a hit's footprint (sec. 4): the albedo for a
// one-ray method (`colour`; supersampled pixels take only the AOVs) and the
// driver's filtered mean, sigma and LOD.
struct DriverAlbedo {
    Rgb albedo;
    double mean = 0, sigma = 0, lod = 0;
};

DriverAlbedo filter_driver_albedo(const SurfaceMaterial& m, const SurfaceHit& h, RenderMethod method, bool colour,
                                  const RenderOptions& options, const std::vector<Rgb>& bin_colors,
                                  std::vector<float>& weights, AlbedoCounts& counts)
{
    DriverAlbedo out;
    if (m.texture) {
        // A texture: its pyramids looked up by probes along the footprint's
        // major edge (texture_footprint.h).
        const TextureFootprint f = filter_texture_footprint(m, h, colour ? texture_color(method) : TextureColor::None,
                                                            options.footprint, options.max_probes, bin_colors, weights);
        counts.footprints += f.counts.footprints;
        counts.plain += f.counts.plain;
        return {f.albedo, f.mean, f.sigma, f.lod};
    }
    if (options.max_probes > 1) {
        // A noise over an anisotropic footprint: probes along its major edge
        // (anisotropic_probes.h), colours averaged.
        const FootprintProbes probes =
            footprint_probes(h.du_dx, h.dv_dx, h.du_dy, h.dv_dy, options.max_probes, options.footprint);
        for (int j = 0; j < probes.count; ++j) {
            const double o = (j + 0.5) / probes.count - 0.5;
            const FilteredNoise::Parameters f =
                m.noise->filter(h.u + o * probes.step_u, h.v + o * probes.step_v, probes.width);
            if (colour)
                out.albedo += method == RenderMethod::Naive ? m.map.evaluate(f.mean)
                                                            : gaussian_albedo(m, f.mean, f.sigma, counts);
            out.mean += f.mean;
            out.sigma += f.sigma;
        }
        out.albedo = (1.0 / probes.count) * out.albedo;
        out.mean /= probes.count;
        out.sigma /= probes.count;
        out.lod = m.noise->lod(probes.width);
        return out;
    }
    const FilteredDriver f = filter_driver(m, h, options.footprint);
    out.mean = f.mean;
    out.sigma = f.sigma;
    out.lod = f.lod;
    if (colour)
        out.albedo = method == RenderMethod::Naive ? m.map.evaluate(f.mean) : gaussian_albedo(m, f.mean, f.sigma, counts);
    return out;
}

// The supersampled methods read f at each ray's hit from a texture's level
// 0, which a moments driver whose recorded driver is gone lacks.
Status check_level0(const std::vector<SurfaceMaterial>& materials, RenderMethod method)
{
    if (method != RenderMethod::Supersample && method != RenderMethod::Reference) return ok();
    for (const SurfaceMaterial& material : materials)
        for (const SurfaceMaterial* m : {&material, material.base.get()})
            if (m && m->texture && !m->texture->has_level0())
                return io_error(m->missing_driver + "; " + to_string(method) +
                                " reads the driver's texels at each ray's hit (naive and gaussian need only the "
                                "moments): re-bake the moments from the driver where it is now, or name the "
                                "driver itself with driver/image");
    return ok();
}

}  // namespace

Status check_render_samples(int samples)
{
    if (samples < 1 || samples > kMaxSamples)
        return bad_input("--spp " + std::to_string(samples) + " is out of range (expected 1 to " +
                             std::to_string(kMaxSamples) + ")",
                         "RenderOptions::samples");
    return ok();
}

Expected<RenderedImage> render(const Scene& scene, const std::vector<SurfaceMaterial>& materials,
                               const RenderOptions& options)
{
    if (materials.size() != scene.surfaces.size())
        return bad_input("render: " + std::to_string(materials.size()) + " materials for " +
                         std::to_string(scene.surfaces.size()) + " surfaces");
    if (auto st = check_render_samples(options.samples); !st) return st.error();
    for (const SurfaceMaterial& m : materials)
        if (!m.noise && !m.texture && !m.layered())
            return bad_input("render: every surface needs a driver (a noise or a texture) or a microsurface");
    if (auto st = check_level0(materials, options.method); !st) return st.error();
    // The exact method: C0 at each material's distinct driver values.
    std::vector<std::vector<Rgb>> bin_colors(materials.size());
    if (options.method == RenderMethod::Exact)
        for (std::size_t i = 0; i < materials.size(); ++i) {
            const SurfaceMaterial& m = materials[i];
            if (m.layered()) continue;  // <C_h, D_h> exactly (height_color.h)
            if (!m.texture)
                return bad_input("render: surface " + std::to_string(i) + ": exact needs a texture driver with at most " +
                                 std::to_string(kHistogramMaxValues) +
                                 " distinct values; noise drivers have no exact filtering distribution");
            if (!m.histograms)
                return bad_input("render: surface " + std::to_string(i) +
                                 ": exact needs the texture's histogram pyramid (MaterialOptions::histograms)");
            for (double v : m.histograms->info().values) bin_colors[i].push_back(m.map.evaluate(v));
        }
    auto camera = Camera::create(scene.camera);
    if (!camera) return camera.error();
    // D_h's exact moments for gaussian-exact (height_moment_table.h), made
    // only for a scene with a microsurface.
    std::optional<HeightMomentTable> height_table;
    if (std::any_of(materials.begin(), materials.end(),
                    [](const SurfaceMaterial& m) { return m.layered(); })) {
        auto table = HeightMomentTable::create();  // 512 exact moments: about 15 ms
        if (!table) return table.error();
        height_table.emplace(std::move(*table));
    }

    RenderedImage image;
    image.width = camera->width();
    image.height = camera->height();
    image.method = options.method;
    const bool supersampled = options.method == RenderMethod::Supersample || options.method == RenderMethod::Reference;
    image.samples = options.method == RenderMethod::Reference ? std::max(options.samples, kReferenceSamples)
                    : supersampled                            ? options.samples
                                                              : 1;
    const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    image.rgb.assign(3 * pixels, 0.0f);
    image.hit.assign(pixels, 0);
    image.distance.assign(pixels, 0.0f);
    image.mean.assign(pixels, 0.0f);
    image.sigma.assign(pixels, 0.0f);
    image.lod.assign(pixels, 0.0f);
    if (supersampled) {
        image.covered.assign(pixels, 0.0f);
        image.covered_distance.assign(pixels, 0.0f);
    }
    // The ray-traced methods trace each microsurface's tabulated heightfield
    // (heightfield_tracer.h) and shade it fully as well.
    std::vector<std::optional<Heightfield>> heightfields(materials.size());
    std::vector<double> heightfield_shift(materials.size(), 0.0);  // trace_displaced_plane's shift
    if (supersampled)
        for (std::size_t i = 0; i < materials.size(); ++i)
            if (materials[i].layered()) {
                HeightfieldOptions ho;
                ho.threads = options.threads;
                ho.slopes = materials[i].slope_map.has_value();  // the slope map reads them at each hit
                auto field = materials[i].microsurface ? Heightfield::create(*materials[i].microsurface, ho)
                                                       : materials[i].displacement->heightfield(options.threads);
                if (materials[i].displacement) heightfield_shift[i] = 0.5 / materials[i].displacement->size();
                if (!field)
                    return Error{field.error().kind,
                                 scene.path + ": /surfaces/" + std::to_string(i) +
                                     (materials[i].microsurface
                                          ? "/material/microsurface: " + std::string(to_string(options.method)) +
                                                " traces one tile tabulated at 8 texels per shortest wavelength, at "
                                                "most 4096 per side (a shorter tile or a longer min_wavelength fits): "
                                          : "/material/displacement: " + std::string(to_string(options.method)) +
                                                " traces the texels as a heightfield, which needs a power-of-two "
                                                "size: ") +
                                     field.error().message};
                heightfields[i].emplace(std::move(*field));
                image.shaded.assign(3 * pixels, 0.0f);
            }

    // Geometric coverage of pixels on edges, for the one-ray methods.
    std::optional<PixelCoverage> coverage;
    if (!supersampled && options.edge_coverage) coverage.emplace(scene, *camera);

    MicrosurfaceLayerOptions layer_options;
    layer_options.heights = height_representation(options.method);
    layer_options.slopes = slope_representation(options.method);
    layer_options.masking = options.masking;
    layer_options.slope_shading = options.slope_shading;

    std::atomic<int> rows_done{0};
    std::atomic<std::size_t> footprints{0}, plain_footprints{0};
    std::mutex progress_mutex;
    const Stopwatch clock;
    parallel_for(image.height, options.threads, [&](int y) {
        std::vector<double> xs, ys;
        std::vector<float> weights;
        std::vector<MicrosurfaceSamples> micro_samples(materials.size());
        PixelCover cover;
        AlbedoCounts counts;
        // The colour of a surface hit, filtered over its footprint, and the
        // driver's filtered mean, sigma and LOD there (supersampled pixels
        // take only the latter).
        const auto filter_hit = [&](const SceneHit& hit) {
            FilteredHit out;
            const SurfaceHit& h = hit.hit;
            const SurfaceMaterial& m = materials[static_cast<std::size_t>(hit.surface)];
            if (m.layered()) {
                // Height- and slope-correlated colour and a base layer (secs.
                // 5-6), masked and shadowed.
                const HeightDirections directions = height_directions(
                    scene.surfaces[static_cast<std::size_t>(hit.surface)], h, normalize(scene.camera.position - h.point),
                    scene.light.direction);
                std::optional<Rgb> base;
                if (m.base && !supersampled)
                    base = filter_driver_albedo(*m.base, h,
                                                options.method == RenderMethod::Naive ? RenderMethod::Naive
                                                                                      : RenderMethod::Gaussian,
                                                true, options, {}, weights, counts)
                               .albedo;
                const MicrosurfaceFiltered f = filter_microsurface_hit(m, h, directions, layer_options,
                                                                       options.max_probes, *height_table, base, counts);
                out.mean = f.mean;
                out.sigma = f.sigma;
                out.lod = f.lod;
                if (!supersampled) out.colour = shade(f.albedo, h.normal, scene.light);
            } else {
                const DriverAlbedo f = filter_driver_albedo(m, h, options.method, !supersampled, options,
                                                            bin_colors[static_cast<std::size_t>(hit.surface)], weights,
                                                            counts);
                out.mean = f.mean;
                out.sigma = f.sigma;
                out.lod = f.lod;
                if (!supersampled) out.colour = shade(f.albedo, h.normal, scene.light);
            }
            return out;
        };
        for (int x = 0; x < image.width; ++x) {
            const std::size_t p = static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                  static_cast<std::size_t>(x);
            // The centre ray: geometry, footprint and the AOVs.
            const CameraRay centre = camera->ray(x + 0.5, y + 0.5);
            const auto hit = intersect_scene(scene, centre);
            Rgb colour = scene.background;
            if (hit) {
                const FilteredHit f = filter_hit(*hit);
                image.hit[p] = 1;
                image.distance[p] = static_cast<float>(hit->hit.t);
                image.mean[p] = static_cast<float>(f.mean);
                image.sigma[p] = static_cast<float>(f.sigma);
                image.lod[p] = static_cast<float>(f.lod);
                colour = f.colour;
            }
            if (coverage && coverage->on_edge(x, y)) {
                // A silhouette, a horizon or a meeting of surfaces crosses the
                // pixel: each surface's share, filtered over its own part
                // (pixel_coverage.h); the AOVs stay the centre ray's.
                coverage->cover(x, y, cover);
                colour = cover.background * scene.background;
                for (const CoveragePiece& piece : cover.pieces) {
                    const std::optional<SurfaceHit> piece_hit = coverage->hit(piece);
                    colour += piece.share *
                              (piece_hit ? filter_hit({*piece_hit, piece.surface}).colour : scene.background);
                }
            }
            if (supersampled) {
                sample_positions(image.samples, options.seed, p, xs, ys);
                Rgb sum, shaded_sum;
                int hits = 0;
                double distance = 0;
                for (MicrosurfaceSamples& m : micro_samples) m = {};
                for (int s = 0; s < image.samples; ++s) {
                    const CameraRay ray = camera->ray(x + xs[static_cast<std::size_t>(s)], y + ys[static_cast<std::size_t>(s)]);
                    const auto sample_hit = intersect_scene(scene, ray);
                    if (!sample_hit) {
                        sum += scene.background;
                        shaded_sum += scene.background;
                        continue;
                    }
                    const SurfaceHit& h = sample_hit->hit;
                    const auto surface = static_cast<std::size_t>(sample_hit->surface);
                    const SurfaceMaterial& m = materials[surface];
                    if (m.layered()) {
                        // The displaced plane, ray traced (displaced_plane_sample.h).
                        const auto traced =
                            trace_displaced_plane(scene.surfaces[surface], *heightfields[surface], ray.origin,
                                                  ray.direction, scene.light.direction, heightfield_shift[surface]);
                        if (!traced) {
                            sum += scene.background;
                            shaded_sum += scene.background;
                            continue;
                        }
                        // The material's colour at the hit (microsurface_albedo.h).
                        std::optional<Rgb> base, height, slope;
                        if (m.base) base = m.base->map.evaluate(driver_value(*m.base, traced->x, traced->y));
                        if (m.height_map) height = m.map.evaluate(traced->height);
                        if (m.slope_map)
                            slope = std::visit(
                                [&](const auto& map) { return map.evaluate(traced->slope_x, traced->slope_y); },
                                *m.slope_map);
                        const Rgb c = combine_point_color(m.combine, base, height, slope);
                        MicrosurfaceSamples& acc = micro_samples[surface];
                        const double lit = traced->lit ? traced->light_cosine : 0.0;
                        acc.lit_color += lit * c;
                        acc.light_cosine += traced->light_cosine;
                        acc.normal = h.normal;
                        ++acc.count;
                        shaded_sum += Rgb{c.r * (scene.light.radiance.r * lit + scene.light.ambient.r),
                                          c.g * (scene.light.radiance.g * lit + scene.light.ambient.g),
                                          c.b * (scene.light.radiance.b * lit + scene.light.ambient.b)};
                        ++hits;
                        distance += traced->t;
                        continue;
                    }
                    const Rgb c = shade(m.map.evaluate(driver_value(m, h.u, h.v)), h.normal, scene.light);
                    sum += c;
                    shaded_sum += c;
                    ++hits;
                    distance += h.t;
                }
                // Each microsurface's share of the pixel: the albedo of eq. 14
                // estimated from its rays (the lit colour over the light
                // cosine, microsurface.md), shaded with the plane's normal.
                for (const MicrosurfaceSamples& acc : micro_samples)
                    if (acc.count > 0)
                        sum += static_cast<double>(acc.count) *
                               shade(acc.light_cosine > 0 ? (1.0 / acc.light_cosine) * acc.lit_color : Rgb{},
                                     acc.normal, scene.light);
                colour = (1.0 / image.samples) * sum;
                if (!image.shaded.empty()) {
                    const Rgb shaded = (1.0 / image.samples) * shaded_sum;
                    image.shaded[3 * p] = static_cast<float>(shaded.r);
                    image.shaded[3 * p + 1] = static_cast<float>(shaded.g);
                    image.shaded[3 * p + 2] = static_cast<float>(shaded.b);
                }
                image.covered[p] = static_cast<float>(hits) / static_cast<float>(image.samples);
                image.covered_distance[p] = hits > 0 ? static_cast<float>(distance / hits) : 0.0f;
            }
            image.rgb[3 * p] = static_cast<float>(colour.r);
            image.rgb[3 * p + 1] = static_cast<float>(colour.g);
            image.rgb[3 * p + 2] = static_cast<float>(colour.b);
        }
        footprints += counts.footprints;
        plain_footprints += counts.plain;
        const int done = ++rows_done;
        if (options.progress) {
            const std::lock_guard<std::mutex> lock(progress_mutex);
            options.progress(static_cast<double>(done) / image.height);
        }
    });
    image.seconds = clock.elapsed_ms() / 1000.0;
    image.footprints = footprints;
    image.plain_footprints = plain_footprints;
    return image;
}

}  // namespace cmfilter
