// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/microsurface_method_choice.h"

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/render/make_surface_renderer.h"
#include "cmfilter/render/surface_renderer.h"
#include "cmfilter/scene/camera.h"
#include "cmfilter/scene/surface_hit.h"
#include "cmfilter/util/parallel_for.h"
#include "cmfilter/util/stopwatch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <sstream>
#include <string>

namespace cmfilter {

namespace {

// Pixels coloured per task of the parallel loop.
constexpr int kPixelsPerTask = 64;

Status check_options(const MicrosurfaceChoiceOptions& o)
{
    if (!(std::isfinite(o.tolerance) && o.tolerance > 0)) {
        std::ostringstream msg;
        msg << "MicrosurfaceChoiceOptions::tolerance " << o.tolerance
            << " is invalid (expected a CIEDE2000 difference > 0)";
        return bad_input(msg.str(), "MicrosurfaceChoiceOptions::tolerance");
    }
    if (auto st = check_microsurface_methods(o.candidates); !st)
        return bad_input("MicrosurfaceChoiceOptions::candidates: " + st.error().message,
                         "MicrosurfaceChoiceOptions::candidates");
    if (o.max_pixels < 1)
        return bad_input("MicrosurfaceChoiceOptions::max_pixels " + std::to_string(o.max_pixels) +
                             " is out of range (expected >= 1)",
                         "MicrosurfaceChoiceOptions::max_pixels");
    return ok();
}

// A measured pixel: its centre ray's hit on the surface.
struct MeasuredPixel {
    SurfaceHit hit;
    int band = 0;  // index into the choice's LOD bands
};

// Each measured pixel's shaded colour by `method`, and the seconds it took.
Expected<std::vector<Rgb>> colour_pixels(const Scene& scene, const Material& material, std::size_t surface,
                                         RenderOptions options, RenderMethod method, const HeightMomentTable& table,
                                         const std::vector<MeasuredPixel>& pixels, std::vector<double>* lods,
                                         double& seconds)
{
    options.method = method;
    options.microsurface_methods.clear();
    auto renderer = make_surface_renderer(material, surface, options);
    if (!renderer) return renderer.error();
    MicrosurfaceLayerOptions layers;
    layers.masking = options.masking;
    layers.slope_shading = options.slope_shading;
    const RenderContext context{scene, options, false, layers, &table};
    std::vector<Rgb> colours(pixels.size());
    if (lods) lods->assign(pixels.size(), 0.0);
    const int tasks = static_cast<int>((pixels.size() + kPixelsPerTask - 1) / kPixelsPerTask);
    const Stopwatch clock;
    parallel_for(tasks, options.threads, [&](int task) {
        HitScratch scratch;
        const std::size_t first = static_cast<std::size_t>(task) * kPixelsPerTask;
        const std::size_t last = std::min(pixels.size(), first + kPixelsPerTask);
        for (std::size_t p = first; p < last; ++p) {
            const SurfaceHit& hit = pixels[p].hit;
            const FilteredHit f = (*renderer)->filter(hit, context, scratch);
            colours[p] = shade(f.albedo, hit.normal, scene.light);
            if (lods) (*lods)[p] = f.lod;
        }
    });
    seconds = clock.elapsed_ms() / 1000.0;
    return colours;
}

}  // namespace

const MicrosurfaceTrial* MicrosurfaceMethodChoice::best() const
{
    const MicrosurfaceTrial* b = nullptr;
    for (const MicrosurfaceTrial& t : trials)
        if (!b || t.worst < b->worst) b = &t;
    return b;
}

Expected<std::vector<SurfaceMicrosurfaceChoice>> choose_microsurface_methods(const Scene& scene,
                                                                             const std::vector<Material>& materials,
                                                                             const MicrosurfaceChoiceOptions& options)
{
    if (auto st = check_options(options); !st) return st.error();
    if (materials.size() != scene.surfaces.size())
        return bad_input("choose_microsurface_methods: " + std::to_string(materials.size()) + " materials for " +
                         std::to_string(scene.surfaces.size()) + " surfaces");
    if (std::none_of(materials.begin(), materials.end(), is_microsurface))
        return std::vector<SurfaceMicrosurfaceChoice>{};
    if (auto st = check_render_probes(options.render.max_probes); !st) return st.error();
    auto camera = Camera::create(scene.camera);
    if (!camera) return camera.error();

    // Which surface each pixel's centre ray hits (-1: none), as render
    // traces it.
    const int width = camera->width(), height = camera->height();
    std::vector<std::int32_t> seen(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), -1);
    parallel_for(height, options.render.threads, [&](int y) {
        for (int x = 0; x < width; ++x) {
            const auto hit = intersect_scene(scene, camera->ray(x + 0.5, y + 0.5));
            if (hit)
                seen[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] =
                    static_cast<std::int32_t>(hit->surface);
        }
    });

    auto table = HeightMomentTable::create();
    if (!table) return table.error();
    const std::vector<RenderMethod> candidates =
        options.candidates.empty() ? std::vector<RenderMethod>{RenderMethod::Naive, RenderMethod::Gaussian,
                                                               RenderMethod::GaussianExact, RenderMethod::Exact}
                                   : options.candidates;

    std::vector<SurfaceMicrosurfaceChoice> out;
    for (std::size_t s = 0; s < materials.size(); ++s) {
        if (!is_microsurface(materials[s])) continue;
        const std::string where = scene.path + ": /surfaces/" + std::to_string(s) + ": ";
        std::vector<std::size_t> frame_pixels;
        for (std::size_t p = 0; p < seen.size(); ++p)
            if (seen[p] == static_cast<std::int32_t>(s)) frame_pixels.push_back(p);
        if (frame_pixels.empty()) continue;  // no pixel sees it
        // Up to max_pixels of them, evenly spread in scan order.
        const std::size_t count = std::min(frame_pixels.size(), static_cast<std::size_t>(options.max_pixels));
        std::vector<MeasuredPixel> pixels(count);
        for (std::size_t k = 0; k < count; ++k) {
            const std::size_t p = frame_pixels[(2 * k + 1) * frame_pixels.size() / (2 * count)];
            const int x = static_cast<int>(p % static_cast<std::size_t>(width));
            const int y = static_cast<int>(p / static_cast<std::size_t>(width));
            pixels[k].hit = intersect_scene(scene, camera->ray(x + 0.5, y + 0.5))->hit;
        }

        // The reference first: exact, and each pixel's LOD (geometry: the
        // same for every method).
        std::vector<double> lods;
        double exact_seconds = 0;
        auto exact = colour_pixels(scene, materials[s], s, options.render, RenderMethod::Exact, *table, pixels, &lods,
                                   exact_seconds);
        if (!exact) return prefixed(where, exact.error());

        MicrosurfaceMethodChoice choice;
        choice.tolerance = options.tolerance;
        choice.surface_pixels = frame_pixels.size();
        choice.pixels = count;
        std::map<int, std::size_t> bands;  // floor(LOD) -> band index
        for (double lod : lods) bands.emplace(static_cast<int>(std::floor(lod)), 0);
        for (auto& [lod, index] : bands) {
            index = choice.lods.size();
            choice.lods.push_back(lod);
        }
        choice.band_pixels.assign(bands.size(), 0);
        for (std::size_t k = 0; k < count; ++k) {
            pixels[k].band = static_cast<int>(bands[static_cast<int>(std::floor(lods[k]))]);
            ++choice.band_pixels[static_cast<std::size_t>(pixels[k].band)];
        }

        for (RenderMethod method : candidates) {
            MicrosurfaceTrial t;
            t.method = method;
            std::vector<Rgb> colours;
            if (method == RenderMethod::Exact) {
                colours = *exact;
                t.seconds = exact_seconds;
            } else {
                auto c =
                    colour_pixels(scene, materials[s], s, options.render, method, *table, pixels, nullptr, t.seconds);
                if (!c) return prefixed(where, c.error());
                colours = std::move(*c);
            }
            std::vector<double> sums(bands.size(), 0.0);
            double total = 0;
            for (std::size_t k = 0; k < count; ++k) {
                const double e = ciede2000_linear_rgb(colours[k], (*exact)[k]);
                sums[static_cast<std::size_t>(pixels[k].band)] += e;
                total += e;
            }
            t.mean = total / static_cast<double>(count);
            for (std::size_t b = 0; b < sums.size(); ++b) {
                t.errors.push_back(sums[b] / static_cast<double>(choice.band_pixels[b]));
                if (b == 0 || t.errors.back() > t.worst) {
                    t.worst = t.errors.back();
                    t.worst_lod = choice.lods[b];
                }
            }
            t.meets = t.worst <= options.tolerance;
            if (t.meets && !choice.chosen) choice.chosen = choice.trials.size();
            choice.trials.push_back(std::move(t));
        }
        out.push_back({s, std::move(choice)});
    }
    return out;
}

}  // namespace cmfilter
