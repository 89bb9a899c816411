// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/scene/driver_sigma_range.h"

#include "cmfilter/util/atomic_output.h"

#include "cmfilter/io/driver_image.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/texture/moment_pyramid_info.h"
#include "cmfilter/noise/noise_sigma_bake.h"
#include "cmfilter/noise/noise_sigma_table_file.h"
#include "cmfilter/noise/noise_spec.h"
#include "cmfilter/scene/scene_loading.h"
#include "cmfilter/texture/texture_lod.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <vector>

namespace cmfilter {

namespace fs = std::filesystem;

namespace {

std::string number(double x)
{
    std::ostringstream s;
    s << x;
    return s.str();
}

Status check_positive(double sigma, const std::string& path, const char* what)
{
    if (!(std::isfinite(sigma) && sigma > 0))
        return bad_input("'" + path + "' holds no positive " + what + " (largest " + number(sigma) +
                         "): a constant driver needs no filtered table");
    return ok();
}

bool ends_with_json(const std::string& path) { return lowercase_extension(path) == ".json"; }

// The largest variance m2 - m1^2 of the box means of (f - c), level by level:
// level 0 holds f - c itself (variance 0); each next level averages 2 x 2
// blocks (2 x 1 or 1 x 2 once an axis is 1), dropping a last odd row or column.
double largest_block_variance(const DriverImage& image)
{
    int w = image.width, h = image.height;
    std::vector<double> m1(image.values.size()), m2(image.values.size());
    double sum1 = 0, sum2 = 0;
    for (std::size_t i = 0; i < image.values.size(); ++i) {
        m1[i] = image.values[i] - image.mean;
        m2[i] = m1[i] * m1[i];
        sum1 += m1[i];
        sum2 += m2[i];
    }
    const double n = static_cast<double>(image.values.size());
    double largest = std::max(0.0, sum2 / n - (sum1 / n) * (sum1 / n));  // the whole image
    while (w > 1 || h > 1) {
        const int fx = w > 1 ? 2 : 1, fy = h > 1 ? 2 : 1;
        const int nw = w / fx, nh = h / fy;
        std::vector<double> n1(static_cast<std::size_t>(nw) * nh), n2(n1.size());
        for (int y = 0; y < nh; ++y)
            for (int x = 0; x < nw; ++x) {
                double a = 0, b = 0;
                for (int dy = 0; dy < fy; ++dy)
                    for (int dx = 0; dx < fx; ++dx) {
                        const std::size_t k = static_cast<std::size_t>(y * fy + dy) * w + (x * fx + dx);
                        a += m1[k];
                        b += m2[k];
                    }
                const std::size_t o = static_cast<std::size_t>(y) * nw + x;
                n1[o] = a / (fx * fy);
                n2[o] = b / (fx * fy);
                largest = std::max(largest, n2[o] - n1[o] * n1[o]);
            }
        m1 = std::move(n1);
        m2 = std::move(n2);
        w = nw;
        h = nh;
    }
    return largest;
}

Expected<DriverSigmaRange> noise_global_sigma(const std::string& spec_text, int threads)
{
    auto spec = parse_noise_spec(spec_text);
    if (!spec) return spec.error();
    auto noise = make_noise(*spec);
    if (!noise) return noise.error();
    const NoiseSigmaBakeOptions defaults;
    const NoiseGlobalStats stats = measure_global_stats(*noise, defaults.global_samples, defaults.seed, threads);
    DriverSigmaRange out;
    out.sigma_max = std::sqrt(stats.variance + stats.variance_half_width);
    out.kind = "noise";
    out.how = "the global sigma of the noise '" + spec_text + "' (no sigma_table; upper end of its 95% interval, " +
              std::to_string(stats.samples) + " samples)";
    return out;
}

}  // namespace

Expected<DriverSigmaRange> largest_noise_table_sigma(const std::string& path)
{
    auto loaded = read_noise_sigma_table(path, FootprintShape::Box);
    if (!loaded) return loaded.error();
    const std::vector<double>& sigmas = loaded->table.sigmas();
    const double largest = *std::max_element(sigmas.begin(), sigmas.end());
    if (auto st = check_positive(largest, path, "box sigma"); !st) return st.error();
    DriverSigmaRange out;
    out.sigma_max = largest;
    out.kind = kNoiseSigmaTableKind;
    out.how = "the largest box sigma of the noise sigma table '" + path + "' (" + std::to_string(sigmas.size()) +
              " LODs)";
    return out;
}

Expected<DriverSigmaRange> largest_moment_pyramid_sigma(const std::string& path)
{
    auto in = open_image_input(path);
    if (!in) return in.error();
    auto info = get_moment_pyramid_metadata((*in)->spec(), path);
    if (!info) return info.error();
    if (auto st = check_tiled_mipmap(**in, info->levels, path); !st) return st.error();
    const int levels = reachable_texture_levels(info->width, info->height, info->levels);
    double largest = 0;
    std::vector<float> m;
    for (int level = 0; level < levels; ++level) {
        const OIIO::ImageSpec spec = (*in)->spec(0, level);
        if (auto fits = check_image_allocation(spec, path, 2); !fits) return fits.error();
        m.resize(static_cast<std::size_t>(spec.width) * spec.height * 2);
        if (!read_float_pixels(**in, 0, level, 0, 2, m.data()))
            return io_error("cannot read level " + std::to_string(level) + " of '" + path + "': " + (*in)->geterror());
        for (std::size_t i = 0; i < m.size(); i += 2) {
            const double m1 = m[i], m2 = m[i + 1];
            if (std::isfinite(m1) && std::isfinite(m2)) largest = std::max(largest, m2 - m1 * m1);
        }
    }
    const double sigma = std::sqrt(largest);
    if (auto st = check_positive(sigma, path, "footprint sigma"); !st) return st.error();
    DriverSigmaRange out;
    out.sigma_max = sigma;
    out.kind = kMomentPyramidKind;
    out.how = "the largest footprint sigma over " + std::to_string(levels) + " levels of the moment pyramid '" + path +
              "'";
    return out;
}

Expected<DriverSigmaRange> largest_driver_image_sigma(const std::string& path, int threads)
{
    DriverReadOptions read;
    read.path = path;
    read.threads = threads;
    auto image = read_driver(read);
    if (!image) return image.error();
    const double sigma = std::sqrt(largest_block_variance(*image));
    if (auto st = check_positive(sigma, path, "footprint sigma"); !st) return st.error();
    DriverSigmaRange out;
    out.sigma_max = sigma;
    out.kind = "driver-image";
    out.how = "the largest sigma over the aligned 2^k blocks of the driver image '" + path + "'";
    return out;
}

Expected<DriverSigmaRange> largest_surface_sigma(const Scene& scene, std::size_t surface, int threads)
{
    if (surface >= scene.surfaces.size())
        return bad_input(scene.path + ": surface " + std::to_string(surface) + " does not exist (the scene has " +
                         std::to_string(scene.surfaces.size()) + ")");
    const DriverSource& driver = scene.surfaces[surface].material.driver;
    if (scene.surfaces[surface].material.displacement)
        return bad_input(scene.path + ": /surfaces/" + std::to_string(surface) +
                         "/material/colormap: a displacement's height map takes the default table (no tolerance: "
                         "its heights are not Gaussian, so no sigma range is derived for them)");
    if (const auto& micro = scene.surfaces[surface].material.microsurface) {
        // D_h's sigma never exceeds the microsurface's sigma_h (eq. 18).
        if (!(micro->sigma_h > 0))
            return bad_input(scene.path + ": /surfaces/" + std::to_string(surface) +
                             "/material/microsurface/sigma_h: a flat microsurface (sigma_h 0) has no sigma range");
        DriverSigmaRange out;
        out.sigma_max = micro->sigma_h;
        out.kind = "microsurface";
        out.how = "the microsurface's sigma_h (the height filtering distribution is never wider)";
        return out;
    }
    Expected<DriverSigmaRange> range = [&]() -> Expected<DriverSigmaRange> {
        switch (driver.kind) {
        case DriverKind::Noise:
            if (!driver.sigma_table_path.empty()) return largest_noise_table_sigma(driver.sigma_table_path);
            return noise_global_sigma(driver.noise_spec, threads);
        case DriverKind::Moments: return largest_moment_pyramid_sigma(driver.moments_path);
        case DriverKind::Image: return largest_driver_image_sigma(driver.image_path, threads);
        }
        return runtime_error("unknown driver kind (internal error)");
    }();
    if (!range)
        return Error{range.error().kind, scene.path + ": /surfaces/" + std::to_string(surface) +
                                             "/material/driver: " + range.error().message};
    return range;
}

Expected<DriverSigmaRange> largest_scene_sigma(const Scene& scene, const DriverSigmaOptions& options)
{
    std::vector<std::size_t> chosen;
    std::error_code ec;
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        const std::string& image = scene.surfaces[i].material.colormap.image_path;
        if (!image.empty() && !options.map_path.empty() && fs::equivalent(image, options.map_path, ec))
            chosen.push_back(i);
    }
    const bool all = chosen.empty();
    if (all)
        for (std::size_t i = 0; i < scene.surfaces.size(); ++i) chosen.push_back(i);
    if (chosen.empty()) return bad_input(scene.path + ": the scene has no surfaces, so no driver sigma");

    DriverSigmaRange best;
    std::size_t best_surface = 0;
    for (std::size_t i : chosen) {
        auto range = largest_surface_sigma(scene, i, options.threads);
        if (!range) return range.error();
        if (range->sigma_max > best.sigma_max) {
            best = *range;
            best_surface = i;
        }
    }
    DriverSigmaRange out;
    out.sigma_max = best.sigma_max;
    out.kind = "scene";
    out.how = "scene '" + scene.path + "', surface " + std::to_string(best_surface) + ": " + best.how +
              " (the largest of " +
              (all ? "all " + std::to_string(chosen.size()) + " surfaces; none uses this map"
                   : std::to_string(chosen.size()) + " of " + std::to_string(scene.surfaces.size()) +
                         " surfaces, those using this map") +
              ")";
    return out;
}

Expected<DriverSigmaRange> largest_driver_sigma(const std::string& path, const DriverSigmaOptions& options)
{
    if (ends_with_json(path)) {
        auto scene = load_scene(path);
        if (!scene) return scene.error();
        return largest_scene_sigma(*scene, options);
    }
    std::string kind;
    {
        auto in = open_image_input(path);
        if (!in) return in.error();
        kind = (*in)->spec().get_string_attribute("cmfilter:kind");
    }
    if (kind == kNoiseSigmaTableKind) return largest_noise_table_sigma(path);
    if (kind == kMomentPyramidKind) return largest_moment_pyramid_sigma(path);
    return bad_input("'" + path + "' is not a driver to take sigma from (" +
                     (kind.empty() ? std::string("it has no cmfilter:kind") : "cmfilter:kind is '" + kind + "'") +
                     "; expected a noise sigma table from bake-noise, a moment pyramid from bake-moments, or a "
                     "scene .json)");
}

}  // namespace cmfilter
