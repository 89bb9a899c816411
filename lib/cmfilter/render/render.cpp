// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/render.h"

#include "cmfilter/microsurface/height_filtered_albedo.h"
#include "cmfilter/microsurface/microsurface_albedo.h"
#include "cmfilter/noise/noise_lattice.h"
#include "cmfilter/render/make_surface_renderer.h"
#include "cmfilter/render/surface_renderer.h"
#include "cmfilter/scene/camera.h"
#include "cmfilter/scene/pixel_coverage.h"
#include "cmfilter/scene/surface_hit.h"
#include "cmfilter/util/memory_budget.h"
#include "cmfilter/util/parallel_for.h"
#include "cmfilter/util/stopwatch.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>

namespace cmfilter {

namespace {

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
        xs[static_cast<std::size_t>(k)] = (columns[static_cast<std::size_t>(k)] + unit_interval(splitmix64(state))) /
                                          count;
    }
}

void store_rgb(std::vector<float>& rgb, std::size_t p, const Rgb& c)
{
    rgb[3 * p] = static_cast<float>(c.r);
    rgb[3 * p + 1] = static_cast<float>(c.g);
    rgb[3 * p + 2] = static_cast<float>(c.b);
}

// One row of the image, the region's part of it: each pixel's centre ray
// (geometry, footprint and the AOVs), its edge coverage (the one-ray
// methods) or its rays (supersample, reference). Pixels are addressed in the
// whole frame (x, y and the sub-pixel samples' stream, keyed by the pixel's
// index in the frame), so a region's pixels are the frame's, bit for bit.
struct RowRenderer {
    const RenderContext& context;
    const Camera& camera;
    const std::vector<std::unique_ptr<SurfaceRenderer>>& surfaces;
    const std::optional<PixelCoverage>& coverage;
    RenderedImage& image;

    const SurfaceRenderer& surface(int i) const { return *surfaces[static_cast<std::size_t>(i)]; }

    void operator()(int y, HitScratch& scratch) const
    {
        const Scene& scene = context.scene;
        std::vector<double> xs, ys;
        PixelSamples samples;
        PixelCover cover;
        for (int x = image.x0; x < image.x0 + image.width; ++x) {
            // The pixel's index in the frame (its samples' stream) and in the image.
            const std::size_t frame_index = static_cast<std::size_t>(y) * static_cast<std::size_t>(image.frame_width) +
                                            static_cast<std::size_t>(x);
            const std::size_t p = static_cast<std::size_t>(y - image.y0) * static_cast<std::size_t>(image.width) +
                                  static_cast<std::size_t>(x - image.x0);
            const CameraRay centre = camera.ray(x + 0.5, y + 0.5);
            const auto hit = intersect_scene(scene, centre);
            Rgb colour = scene.background;
            if (hit) {
                const FilteredHit f = surface(hit->surface).filter(hit->hit, context, scratch);
                image.hit[p] = 1;
                image.distance[p] = static_cast<float>(hit->hit.t);
                image.mean[p] = static_cast<float>(f.mean);
                image.sigma[p] = static_cast<float>(f.sigma);
                image.lod[p] = static_cast<float>(f.lod);
                if (!image.surface.empty()) image.surface[p] = static_cast<std::int32_t>(hit->surface);
                colour = context.supersampled ? Rgb{} : shade(f.albedo, hit->hit.normal, scene.light);
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
                              (piece_hit ? shade(surface(piece.surface).filter(*piece_hit, context, scratch).albedo,
                                                 piece_hit->normal, scene.light)
                                         : scene.background);
                }
            }
            if (context.supersampled) colour = supersample(x, y, frame_index, p, xs, ys, samples);
            store_rgb(image.rgb, p, colour);
        }
    }

    // The pixel's rays, each hit coloured by its surface: the colour, and
    // the shaded image and coverage AOVs.
    Rgb supersample(int x, int y, std::size_t frame_index, std::size_t p, std::vector<double>& xs,
                    std::vector<double>& ys, PixelSamples& samples) const
    {
        const Scene& scene = context.scene;
        sample_positions(image.samples, context.options.seed, frame_index, xs, ys);
        samples.sum = samples.shaded_sum = Rgb{};
        samples.hits = 0;
        samples.distance = 0;
        samples.microsurfaces.assign(surfaces.size(), MicrosurfaceSamples{});
        for (int s = 0; s < image.samples; ++s) {
            const CameraRay ray = camera.ray(x + xs[static_cast<std::size_t>(s)], y + ys[static_cast<std::size_t>(s)]);
            const auto sample_hit = intersect_scene(scene, ray);
            if (!sample_hit) samples.add_background(scene.background);
            else surface(sample_hit->surface).sample(ray, sample_hit->hit, context, samples);
        }
        // Each microsurface's share of the pixel: the albedo of eq. 14
        // estimated from its rays (the lit colour over the light cosine,
        // microsurface.md), shaded with the plane's normal.
        Rgb sum = samples.sum;
        for (const MicrosurfaceSamples& acc : samples.microsurfaces)
            if (acc.count > 0)
                sum += static_cast<double>(acc.count) *
                       shade(acc.light_cosine > 0 ? (1.0 / acc.light_cosine) * acc.lit_color : Rgb{}, acc.normal,
                             scene.light);
        if (!image.shaded.empty()) store_rgb(image.shaded, p, (1.0 / image.samples) * samples.shaded_sum);
        image.covered[p] = static_cast<float>(samples.hits) / static_cast<float>(image.samples);
        image.covered_distance[p] = samples.hits > 0 ? static_cast<float>(samples.distance / samples.hits) : 0.0f;
        return (1.0 / image.samples) * sum;
    }
};

}  // namespace

Expected<RenderedImage> render(const Scene& scene, const std::vector<Material>& materials, const RenderOptions& options)
{
    if (materials.size() != scene.surfaces.size())
        return bad_input("render: " + std::to_string(materials.size()) + " materials for " +
                         std::to_string(scene.surfaces.size()) + " surfaces");
    if (auto st = check_render_samples(options.samples); !st) return st.error();
    if (auto st = check_render_probes(options.max_probes); !st) return st.error();
    if (auto st = check_sub_footprint_options(options.sub_footprints); !st) return st.error();
    for (int n : options.noise_sub_footprints)
        if (n < 0 || n > kMaxSubFootprintCells)
            return bad_input("RenderOptions::noise_sub_footprints holds " + std::to_string(n) + " (expected 0 to " +
                                 std::to_string(kMaxSubFootprintCells) + ")",
                             "RenderOptions::noise_sub_footprints");
    if (auto st = check_microsurface_methods(options.microsurface_methods); !st) return st.error();
    if (auto st = check_surface_probes(options.surface_probes); !st) return st.error();
    // One renderer per surface, for its driver's kind (surface_renderer.h).
    std::vector<std::unique_ptr<SurfaceRenderer>> surfaces;
    for (std::size_t i = 0; i < materials.size(); ++i) {
        auto made = make_surface_renderer(materials[i], i, options);
        if (!made) return made.error();
        surfaces.push_back(std::move(*made));
    }
    auto camera = Camera::create(scene.camera);
    if (!camera) return camera.error();
    const PixelRegion region = options.region.value_or(whole_frame(camera->width(), camera->height()));
    if (auto st = check_pixel_region(region, camera->width(), camera->height()); !st) return st.error();
    // The image and its per-pixel AOVs (RenderedImage), and the copies the
    // output files are written from: at most kRenderBytesPerPixel, for the
    // region's pixels only.
    if (auto fits = check_allocation(double(region.width()) * region.height() * kRenderBytesPerPixel,
                                     "the render of '" + scene.path + "' (" + std::to_string(region.width()) + " x " +
                                         std::to_string(region.height()) + " pixels)");
        !fits)
        return fits.error();
    // D_h's exact moments for gaussian-exact (height_moment_table.h), made
    // only for a scene with a microsurface.
    const bool microsurfaces = std::any_of(materials.begin(), materials.end(), is_microsurface);
    std::optional<HeightMomentTable> height_table;
    if (microsurfaces) {
        auto table = HeightMomentTable::create();  // 512 exact moments: about 15 ms
        if (!table) return table.error();
        height_table.emplace(std::move(*table));
    }

    // How D_h and D_s are represented is each layered surface's own
    // (layered_surface.h, RenderOptions::microsurface_methods).
    MicrosurfaceLayerOptions layers;
    layers.masking = options.masking;
    layers.slope_shading = options.slope_shading;
    const RenderContext context{
        scene, options, options.method == RenderMethod::Supersample || options.method == RenderMethod::Reference,
        layers, height_table ? &*height_table : nullptr};

    RenderedImage image;
    image.width = region.width();
    image.height = region.height();
    image.x0 = region.x0;
    image.y0 = region.y0;
    image.frame_width = camera->width();
    image.frame_height = camera->height();
    image.method = options.method;
    image.samples = options.method == RenderMethod::Reference ? std::max(options.samples, kReferenceSamples)
                    : context.supersampled                    ? options.samples
                                                              : 1;
    const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    image.rgb.assign(3 * pixels, 0.0f);
    image.hit.assign(pixels, 0);
    image.distance.assign(pixels, 0.0f);
    image.mean.assign(pixels, 0.0f);
    image.sigma.assign(pixels, 0.0f);
    image.lod.assign(pixels, 0.0f);
    if (options.surface_indices) image.surface.assign(pixels, -1);
    if (context.supersampled) {
        image.covered.assign(pixels, 0.0f);
        image.covered_distance.assign(pixels, 0.0f);
        // The ray-traced methods trace each microsurface's heightfield
        // (heightfield_tracer.h) and shade it fully as well.
        for (const std::unique_ptr<SurfaceRenderer>& surface : surfaces)
            if (auto st = surface->prepare_tracing(context); !st) return st.error();
        if (microsurfaces) image.shaded.assign(3 * pixels, 0.0f);
    }

    // Geometric coverage of pixels on edges, for the one-ray methods.
    std::optional<PixelCoverage> coverage;
    if (!context.supersampled && options.edge_coverage) coverage.emplace(scene, *camera);

    const RowRenderer row{context, *camera, surfaces, coverage, image};
    std::atomic<int> rows_done{0};
    std::atomic<std::size_t> footprints{0}, plain_footprints{0};
    std::mutex progress_mutex;
    const Stopwatch clock;
    parallel_for(image.height, options.threads, [&](int row_index) {
        HitScratch scratch;
        row(image.y0 + row_index, scratch);
        footprints += scratch.counts.footprints;
        plain_footprints += scratch.counts.plain;
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

void set_method_materials(RenderMethod method, MaterialOptions& options)
{
    options.histograms = method == RenderMethod::Exact;
    options.segments = method == RenderMethod::Segments;
    options.moment_order = method == RenderMethod::Mixture ? 4 : 2;
}

}  // namespace cmfilter
