// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/view_pixels.h"

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/render/make_surface_renderer.h"
#include "cmfilter/render/surface_renderer.h"
#include "cmfilter/scene/camera.h"
#include "cmfilter/util/parallel_for.h"
#include "cmfilter/util/stopwatch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>

namespace cmfilter {

namespace {

// Pixels coloured per task of the parallel loop.
constexpr std::size_t kPixelsPerTask = 64;

}  // namespace

Expected<std::vector<SurfacePixels>> sample_surface_pixels(const Scene& scene, std::size_t max_pixels, int threads)
{
    auto camera = Camera::create(scene.camera);
    if (!camera) return camera.error();
    // Which surface each pixel's centre ray hits (-1: none), as render
    // traces it.
    const int width = camera->width(), height = camera->height();
    std::vector<std::int32_t> seen(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), -1);
    parallel_for(height, threads, [&](int y) {
        for (int x = 0; x < width; ++x) {
            const auto hit = intersect_scene(scene, camera->ray(x + 0.5, y + 0.5));
            if (hit)
                seen[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] =
                    static_cast<std::int32_t>(hit->surface);
        }
    });
    std::vector<std::vector<std::size_t>> frame_pixels(scene.surfaces.size());
    for (std::size_t p = 0; p < seen.size(); ++p)
        if (seen[p] >= 0) frame_pixels[static_cast<std::size_t>(seen[p])].push_back(p);
    std::vector<SurfacePixels> out(scene.surfaces.size());
    for (std::size_t s = 0; s < out.size(); ++s) {
        const std::vector<std::size_t>& all = frame_pixels[s];
        out[s].surface_pixels = all.size();
        const std::size_t count = std::min(all.size(), max_pixels);
        out[s].hits.resize(count);
        for (std::size_t k = 0; k < count; ++k) {  // evenly spread in scan order
            const std::size_t p = all[(2 * k + 1) * all.size() / (2 * count)];
            const int x = static_cast<int>(p % static_cast<std::size_t>(width));
            const int y = static_cast<int>(p / static_cast<std::size_t>(width));
            out[s].hits[k] = intersect_scene(scene, camera->ray(x + 0.5, y + 0.5))->hit;
        }
    }
    return out;
}

Expected<ColouredPixels> colour_surface_pixels(const Scene& scene, const Material& material, std::size_t surface,
                                               const RenderOptions& options, const HeightMomentTable* table,
                                               const std::vector<SurfaceHit>& hits)
{
    auto renderer = make_surface_renderer(material, surface, options);
    if (!renderer) return renderer.error();
    MicrosurfaceLayerOptions layers;
    layers.masking = options.masking;
    layers.slope_shading = options.slope_shading;
    const RenderContext context{scene, options, false, layers, table};
    ColouredPixels out;
    out.colours.resize(hits.size());
    out.lods.resize(hits.size());
    const int tasks = static_cast<int>((hits.size() + kPixelsPerTask - 1) / kPixelsPerTask);
    const Stopwatch clock;
    parallel_for(tasks, options.threads, [&](int task) {
        HitScratch scratch;
        const std::size_t first = static_cast<std::size_t>(task) * kPixelsPerTask;
        const std::size_t last = std::min(hits.size(), first + kPixelsPerTask);
        for (std::size_t p = first; p < last; ++p) {
            const FilteredHit f = (*renderer)->filter(hits[p], context, scratch);
            out.colours[p] = shade(f.albedo, hits[p].normal, scene.light);
            out.lods[p] = f.lod;
        }
    });
    out.seconds = clock.elapsed_ms() / 1000.0;
    return out;
}

LodBands lod_bands(const std::vector<double>& lods)
{
    std::map<int, std::size_t> index;  // floor(LOD) -> band
    for (double lod : lods) index.emplace(static_cast<int>(std::floor(lod)), 0);
    LodBands b;
    for (auto& [lod, i] : index) {
        i = b.lods.size();
        b.lods.push_back(lod);
    }
    b.pixels.assign(b.lods.size(), 0);
    b.band.resize(lods.size());
    for (std::size_t k = 0; k < lods.size(); ++k) {
        b.band[k] = index[static_cast<int>(std::floor(lods[k]))];
        ++b.pixels[b.band[k]];
    }
    return b;
}

BandedError banded_error(const LodBands& bands, const std::vector<Rgb>& colours, const std::vector<Rgb>& reference)
{
    BandedError e;
    std::vector<double> sums(bands.lods.size(), 0.0);
    double total = 0;
    for (std::size_t k = 0; k < colours.size(); ++k) {
        const double d = ciede2000_linear_rgb(colours[k], reference[k]);
        sums[bands.band[k]] += d;
        total += d;
    }
    e.mean = colours.empty() ? 0 : total / static_cast<double>(colours.size());
    for (std::size_t b = 0; b < sums.size(); ++b) {
        e.errors.push_back(sums[b] / static_cast<double>(bands.pixels[b]));
        if (b == 0 || e.errors.back() > e.worst) {
            e.worst = e.errors.back();
            e.worst_lod = bands.lods[b];
        }
    }
    return e;
}

ViewTrial measure_trial(const LodBands& bands, const ColouredPixels& coloured, const ColouredPixels& reference,
                        double tolerance)
{
    const BandedError e = banded_error(bands, coloured.colours, reference.colours);
    ViewTrial t;
    t.errors = e.errors;
    t.mean = e.mean;
    t.worst = e.worst;
    t.worst_lod = e.worst_lod;
    t.seconds = coloured.seconds;
    t.meets = t.worst <= tolerance;
    return t;
}

ViewMeasurement view_measurement(double tolerance, const SurfacePixels& pixels, const LodBands& bands)
{
    return {tolerance, pixels.surface_pixels, pixels.hits.size(), bands.lods, bands.pixels};
}

Status check_view_choice(const std::string& options, double tolerance, int max_pixels)
{
    if (!(std::isfinite(tolerance) && tolerance > 0)) {
        std::ostringstream msg;
        msg << options << "::tolerance " << tolerance << " is invalid (expected a CIEDE2000 difference > 0)";
        return bad_input(msg.str(), options + "::tolerance");
    }
    if (max_pixels < 1)
        return bad_input(options + "::max_pixels " + std::to_string(max_pixels) + " is out of range (expected >= 1)",
                         options + "::max_pixels");
    return ok();
}

}  // namespace cmfilter
