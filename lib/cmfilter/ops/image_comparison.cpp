// SPDX-License-Identifier: Apache-2.0
// Image comparison: read, colour-manage, check, then one pass over the pixels
// for the squared differences and the per-pixel CIEDE2000.
#include "cmfilter/ops/image_comparison.h"

#include "cmfilter/util/atomic_output.h"
#include "cmfilter/color/ciede2000.h"
#include "cmfilter/ops/error_heatmap.h"
#include "cmfilter/io/image_colorspace.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/util/parallel_for.h"

#include <cmath>
#include <sstream>
#include <vector>

namespace cmfilter {

namespace {

struct LinearImage {
    ImageData data;  // size and metadata (its pixels are released once copied)
    ComparedImage info;
    std::vector<float> rgb;  // width * height * 3, scene-linear
};

// How many pixels of interleaved RGB hold a non-finite sample, and the index
// of the first such sample.
struct NonFinite {
    std::size_t pixels = 0;
    std::size_t first = 0;
};

NonFinite find_non_finite(const std::vector<float>& rgb)
{
    NonFinite nf;
    for (std::size_t i = 0; i < rgb.size(); i += 3) {
        for (std::size_t k = i; k < i + 3; ++k) {
            if (std::isfinite(rgb[k])) continue;
            if (nf.pixels == 0) nf.first = k;
            ++nf.pixels;
            break;
        }
    }
    return nf;
}

// The R, G, B samples of every pixel: grey (1-2 channels) replicated, channels
// beyond the third ignored.
std::vector<float> rgb_samples(const ImageData& img)
{
    const std::size_t n = static_cast<std::size_t>(img.width) * img.height;
    std::vector<float> rgb(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const float* p = img.pixels.data() + i * img.channels;
        for (int ch = 0; ch < 3; ++ch) rgb[3 * i + ch] = img.channels >= 3 ? p[ch] : p[0];
    }
    return rgb;
}

Expected<LinearImage> load_linear(const std::string& path, const std::string& requested, const std::string& option,
                                  const ColorConfig& config)
{
    auto image = read_image(path);
    if (!image) return image.error();
    LinearImage out;
    out.data = std::move(*image);
    const ImageData& img = out.data;
    out.info.path = path;
    out.info.channels = img.channels;
    out.info.pixel_type = img.pixel_type;
    out.rgb = rgb_samples(img);
    std::vector<float>().swap(out.data.pixels);  // only the RGB copy is needed from here

    if (const NonFinite nf = find_non_finite(out.rgb); nf.pixels > 0) {
        const std::size_t pixel = nf.first / 3;
        std::ostringstream msg;
        msg << "'" << path << "' has " << nf.pixels << " pixel" << (nf.pixels == 1 ? "" : "s")
            << " with non-finite values (the first at (" << pixel % img.width << ", " << pixel / img.width
            << ") channel " << nf.first % 3 << ": " << out.rgb[nf.first] << "); expected finite colours";
        return bad_input(msg.str());
    }

    auto space = decide_image_colorspace(img, path, requested, option, config);
    if (!space) return space.error();
    out.info.colorspace = space->colorspace;
    out.info.colorspace_rule = space->rule;
    if (auto st = image_rgb_to_scene_linear(out.rgb, *space, config); !st) return st.error();
    // A finite texel can still leave the conversion non-finite (a log curve
    // given a negative value, say): refuse it rather than measure it.
    if (const NonFinite nf = find_non_finite(out.rgb); nf.pixels > 0) {
        std::ostringstream msg;
        msg << "'" << path << "': " << nf.pixels << " pixel" << (nf.pixels == 1 ? "" : "s")
            << " become non-finite when converted from '" << space->colorspace
            << "' to scene-linear; expected colours that colour space can represent";
        return bad_input(msg.str());
    }
    return out;
}

}  // namespace

RgbDifference measure_rgb_difference(const float* a, const float* b, int width, int height, int threads)
{
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    RgbDifference result;
    result.de2000.resize(pixels);
    std::vector<std::array<double, 3>> row_sq(height);
    parallel_for(height, threads, [&](int y) {
        std::array<double, 3> sq{};
        for (int x = 0; x < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            const float* pa = a + 3 * i;
            const float* pb = b + 3 * i;
            for (int ch = 0; ch < 3; ++ch) {
                const double d = static_cast<double>(pa[ch]) - pb[ch];
                sq[ch] += d * d;
            }
            result.de2000[i] = ciede2000_linear_rgb({pa[0], pa[1], pa[2]}, {pb[0], pb[1], pb[2]});
        }
        row_sq[y] = sq;
    });
    std::array<double, 3> sum{};
    for (const auto& r : row_sq)
        for (int ch = 0; ch < 3; ++ch) sum[ch] += r[ch];
    const double n = static_cast<double>(pixels);
    for (int ch = 0; ch < 3; ++ch) result.rmse_rgb[ch] = std::sqrt(sum[ch] / n);
    result.rmse = std::sqrt((sum[0] + sum[1] + sum[2]) / (3.0 * n));
    return result;
}

Expected<ImageComparison> compare_images(const ImageComparisonOptions& options, const ColorConfig& config)
{
    if (!std::isfinite(options.heatmap_max) || !(options.heatmap_max > 0.0)) {
        std::ostringstream msg;
        msg << "ImageComparisonOptions::heatmap_max " << options.heatmap_max
            << " is invalid (expected a finite Delta E00 > 0)";
        return bad_input(msg.str(), "ImageComparisonOptions::heatmap_max");
    }
    const bool heatmap = !options.heatmap_path.empty();
    // Before any work, so a bad destination fails fast.
    if (heatmap)
        if (auto st = check_output_path(options.heatmap_path, ".png"); !st) return st.error();

    auto a = load_linear(options.path_a, options.colorspace_a, "ImageComparisonOptions::colorspace_a", config);
    if (!a) return a.error();
    auto b = load_linear(options.path_b, options.colorspace_b, "ImageComparisonOptions::colorspace_b", config);
    if (!b) return b.error();
    if (a->data.width != b->data.width || a->data.height != b->data.height) {
        std::ostringstream msg;
        msg << "'" << options.path_a << "' is " << a->data.width << " x " << a->data.height << " but '"
            << options.path_b << "' is " << b->data.width << " x " << b->data.height
            << "; expected images of the same size";
        return bad_input(msg.str());
    }

    ImageComparison result;
    result.width = a->data.width;
    result.height = a->data.height;
    result.pixels = static_cast<std::size_t>(result.width) * result.height;
    result.a = a->info;
    result.b = b->info;
    result.linear_space = config.scene_linear_name();
    result.ocio_config = config.source();

    RgbDifference d =
        measure_rgb_difference(a->rgb.data(), b->rgb.data(), result.width, result.height, options.threads);
    result.rmse = d.rmse;
    result.rmse_rgb = d.rmse_rgb;
    std::vector<double>& de = d.de2000;

    if (heatmap) {
        HeatmapImage image;
        image.width = result.width;
        image.height = result.height;
        image.errors = &de;
        image.max = options.heatmap_max;
        std::ostringstream description;
        description << "cmfilter compare: per-pixel CIEDE2000 of '" << options.path_a << "' vs '" << options.path_b
                    << "'; 0 black, " << options.heatmap_max / 3 << " red, " << 2 * options.heatmap_max / 3
                    << " yellow, " << options.heatmap_max << " and above white";
        image.description = description.str();
        if (auto st = write_heatmap_png(options.heatmap_path, image); !st) return st.error();
        result.heatmap_path = options.heatmap_path;
        result.heatmap_max = options.heatmap_max;
    }
    result.de2000 = summarize_errors(std::move(de));
    return result;
}

}  // namespace cmfilter
