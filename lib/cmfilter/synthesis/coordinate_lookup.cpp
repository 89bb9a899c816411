// SPDX-License-Identifier: Apache-2.0
// Rendering through a coordinate map (Bosserhoff & Nicoll sec. 4.2, "Using
// large BTFs for rendering", and sec. 5: the output is one more texture
// lookup, through the map into the sample) at full size and at a level of
// detail, by the methods of coordinate_lookup.h.
#include "cmfilter/synthesis/coordinate_lookup.h"

#include "cmfilter/math/bilinear_texels.h"
#include "cmfilter/synthesis/sample_box_sums.h"
#include "cmfilter/synthesis/sample_image_pyramid.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>

namespace cmfilter {

namespace {

std::string size_text(int w, int h) { return std::to_string(w) + " x " + std::to_string(h); }

Status check_image(const SampleImage& sample)
{
    if (sample.width < 1 || sample.height < 1 || sample.channels < 1)
        return bad_input("the sample image is " + size_text(sample.width, sample.height) + " with " +
                         std::to_string(sample.channels) + " channels: expected at least 1 x 1 and 1 channel");
    const std::size_t expected = static_cast<std::size_t>(sample.width) * sample.height * sample.channels;
    if (sample.pixels.size() != expected)
        return bad_input("the sample image holds " + std::to_string(sample.pixels.size()) + " values, expected " +
                         std::to_string(expected) + " (" + size_text(sample.width, sample.height) + " x " +
                         std::to_string(sample.channels) + ")");
    return ok();
}

// A map level into a sample image of `width` x `height`: sizes and every
// coordinate inside it.
Status check_level(const CoordinateLevel& level, int index, int width, int height)
{
    const std::string name = "the coordinate map's level " + std::to_string(index);
    if (level.width < 1 || level.height < 1) return bad_input(name + " is " + size_text(level.width, level.height));
    if (level.coords.size() != level.texels() * 2)
        return bad_input(name + " holds " + std::to_string(level.coords.size()) + " values, expected " +
                         std::to_string(level.texels() * 2));
    if (level.sample_width != width || level.sample_height != height)
        return bad_input(name + " points into a sample of " + size_text(level.sample_width, level.sample_height) +
                         ", but the image it is rendered from is " + size_text(width, height));
    for (std::size_t t = 0; t < level.texels(); ++t) {
        if (level.x(t) < 0 || level.x(t) >= width || level.y(t) < 0 || level.y(t) >= height)
            return bad_input(name + " texel (" + std::to_string(t % level.width) + ", " +
                             std::to_string(t / level.width) + ") points at (" + std::to_string(level.x(t)) + ", " +
                             std::to_string(level.y(t)) + "), outside the image of " + size_text(width, height));
    }
    return ok();
}

Status check_full(const CoordinateMap& map, const SampleImage& sample)
{
    if (map.levels.empty()) return bad_input("the coordinate map has no level 0");
    if (auto s = check_image(sample); !s) return s;
    return check_level(map.full(), 0, sample.width, sample.height);
}

OutputImage blank_output(int width, int height, int channels)
{
    OutputImage out;
    out.width = width;
    out.height = height;
    out.channels = channels;
    out.pixels.assign(static_cast<std::size_t>(width) * height * channels, 0.0f);
    return out;
}

// A footprint of level L: full-size texels [x0, x1) x [y0, y1).
struct Footprint {
    int x0, y0, x1, y1;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
};

Footprint footprint(int i, int j, int step, int width, int height)
{
    return {i * step, j * step, std::min(width, (i + 1) * step), std::min(height, (j + 1) * step)};
}

// Bilinear read of `image` at a position in its own texel units (texel
// (x, y) centred at (x + 0.5, y + 0.5)), wrapping or clamping.
void read_bilinear(const SampleImage& image, double u, double v, float* out)
{
    const TextureWrap wrap = image.periodic ? TextureWrap::Periodic : TextureWrap::Clamp;
    const int c = image.channels;
    for (int k = 0; k < c; ++k) {
        out[k] = static_cast<float>(bilinear_texels<double>(
            u / image.width, v / image.height, image.width, image.height, wrap, 0.0, [&](int x, int y) {
                return static_cast<double>(image.pixels[(static_cast<std::size_t>(y) * image.width + x) * c + k]);
            }));
    }
}

// Reference: the full-size output box-filtered over each footprint.
OutputImage render_reference(const OutputImage& full, int step, int threads)
{
    const int c = full.channels;
    OutputImage out = blank_output((full.width + step - 1) / step, (full.height + step - 1) / step, c);
    parallel_for(out.height, threads, [&](int j) {
        std::vector<double> sum(c);
        for (int i = 0; i < out.width; ++i) {
            const Footprint f = footprint(i, j, step, full.width, full.height);
            std::fill(sum.begin(), sum.end(), 0.0);
            for (int y = f.y0; y < f.y1; ++y)
                for (int x = f.x0; x < f.x1; ++x)
                    for (int k = 0; k < c; ++k)
                        sum[k] += full.pixels[(static_cast<std::size_t>(y) * full.width + x) * c + k];
            const double area = static_cast<double>(f.width()) * f.height();
            for (int k = 0; k < c; ++k)
                out.pixels[(static_cast<std::size_t>(j) * out.width + i) * c + k] = static_cast<float>(sum[k] / area);
        }
    });
    return out;
}

// NaiveMip: the mean coordinate of the footprint (texel centres), read in
// the sample's level min(L, top): a mip of the map, wrong across seams.
OutputImage render_naive(const CoordinateMap& map, const std::vector<SampleImage>& pyramid, int lod, int threads)
{
    const CoordinateLevel& full = map.full();
    const int step = 1 << lod;
    const int level = std::min(lod, static_cast<int>(pyramid.size()) - 1);
    const SampleImage& image = pyramid[level];
    const double scale = 1.0 / (1 << level);
    OutputImage out = blank_output((full.width + step - 1) / step, (full.height + step - 1) / step, image.channels);
    parallel_for(out.height, threads, [&](int j) {
        for (int i = 0; i < out.width; ++i) {
            const Footprint f = footprint(i, j, step, full.width, full.height);
            double sx = 0, sy = 0;
            for (int y = f.y0; y < f.y1; ++y)
                for (int x = f.x0; x < f.x1; ++x) {
                    const std::size_t t = static_cast<std::size_t>(y) * full.width + x;
                    sx += full.x(t) + 0.5;
                    sy += full.y(t) + 0.5;
                }
            const double area = static_cast<double>(f.width()) * f.height();
            read_bilinear(image, sx / area * scale, sy / area * scale,
                          out.pixels.data() + (static_cast<std::size_t>(j) * out.width + i) * out.channels);
        }
    });
    return out;
}

// Point: the texel nearest the footprint's centre, its offset carried to the
// centre, read in the sample's level min(L, top).
OutputImage render_point(const CoordinateMap& map, const std::vector<SampleImage>& pyramid, int lod, int threads)
{
    const CoordinateLevel& full = map.full();
    const int step = 1 << lod;
    const int level = std::min(lod, static_cast<int>(pyramid.size()) - 1);
    const SampleImage& image = pyramid[level];
    const double scale = 1.0 / (1 << level);
    OutputImage out = blank_output((full.width + step - 1) / step, (full.height + step - 1) / step, image.channels);
    parallel_for(out.height, threads, [&](int j) {
        for (int i = 0; i < out.width; ++i) {
            const Footprint f = footprint(i, j, step, full.width, full.height);
            const double cx = f.x0 + 0.5 * f.width(), cy = f.y0 + 0.5 * f.height();
            const int px = std::min(f.x1 - 1, f.x0 + f.width() / 2), py = std::min(f.y1 - 1, f.y0 + f.height() / 2);
            const std::size_t t = static_cast<std::size_t>(py) * full.width + px;
            const double u = full.x(t) + (cx - px), v = full.y(t) + (cy - py);
            read_bilinear(image, u * scale, v * scale,
                          out.pixels.data() + (static_cast<std::size_t>(j) * out.width + i) * out.channels);
        }
    });
    return out;
}

// Levels: hierarchical synthesis's level-L map, each texel the sample
// level-L texel it names (sec. 4.2, figure 4).
Expected<OutputImage> render_levels(const CoordinateMap& map, const std::vector<SampleImage>& pyramid, int lod,
                                    int threads)
{
    if (lod >= static_cast<int>(map.levels.size()))
        return bad_input("LodOptions::lod " + std::to_string(lod) + " is beyond the coordinate map's levels: it has " +
                             std::to_string(map.levels.size()) + " (0 .. " + std::to_string(map.levels.size() - 1) +
                             "; the levels method reads the synthesis's own level-L map)",
                         "LodOptions::lod");
    if (lod >= static_cast<int>(pyramid.size()))
        return bad_input("LodOptions::lod " + std::to_string(lod) + " is beyond the sample's pyramid of " +
                             std::to_string(pyramid.size()) + " levels (down to 1 x 1)",
                         "LodOptions::lod");
    const SampleImage& image = pyramid[lod];
    const CoordinateLevel& level = map.levels[lod];
    if (auto s = check_level(level, lod, image.width, image.height); !s) return s.error();
    const CoordinateLevel& full = map.full();
    const int step = 1 << lod;
    const int c = image.channels;
    OutputImage out = blank_output((full.width + step - 1) / step, (full.height + step - 1) / step, c);
    parallel_for(out.height, threads, [&](int j) {
        const int ly = std::min(level.height - 1, static_cast<int>((j + 0.5) * level.height / out.height));
        for (int i = 0; i < out.width; ++i) {
            const int lx = std::min(level.width - 1, static_cast<int>((i + 0.5) * level.width / out.width));
            const std::size_t t = static_cast<std::size_t>(ly) * level.width + lx;
            const float* texel = image.pixels.data() +
                                 (static_cast<std::size_t>(level.y(t)) * image.width + level.x(t)) * c;
            std::copy(texel, texel + c, out.pixels.data() + (static_cast<std::size_t>(j) * out.width + i) * c);
        }
    });
    return out;
}

// Patches: each kept offset's footprint box read exactly from the sample's
// summed-area table, weighted by its share; the share of the pieces not kept
// (a footprint of more pieces than `patches`, at coarse LODs) at the mean of
// the full-size output, what a footprint of many pieces tends to.
Expected<OutputImage> render_patches(const CoordinateMap& map, const SampleImage& sample, int lod, int patches,
                                     int threads)
{
    auto level = build_patch_level(map, lod, patches, sample.periodic, threads);
    if (!level) return level.error();
    const SampleBoxSums sums(sample);
    const CoordinateLevel& full = map.full();
    const int step = 1 << lod;
    const int c = sample.channels;
    OutputImage out = blank_output(level->width, level->height, c);
    // The mean of the full-size output: the sample's texels weighted by how
    // often the map copies each.
    std::vector<double> mean(c, 0.0);
    for (std::size_t t = 0; t < full.texels(); ++t) {
        const float* v = sample.pixels.data() + (static_cast<std::size_t>(full.y(t)) * sample.width + full.x(t)) * c;
        for (int ch = 0; ch < c; ++ch) mean[ch] += v[ch];
    }
    for (double& m : mean) m /= static_cast<double>(std::max<std::size_t>(full.texels(), 1));
    parallel_for(out.height, threads, [&](int j) {
        std::vector<double> box(c), acc(c);
        for (int i = 0; i < out.width; ++i) {
            const Footprint f = footprint(i, j, step, full.width, full.height);
            const std::size_t texel = static_cast<std::size_t>(j) * out.width + i;
            std::fill(acc.begin(), acc.end(), 0.0);
            double rest = 1;
            for (int k = 0; k < patches; ++k) {
                const float* e = level->entry(texel, k);
                if (e[2] <= 0) break;
                rest -= e[2];
                sums.box_mean(static_cast<std::int64_t>(f.x0) + static_cast<std::int64_t>(e[0]),
                              static_cast<std::int64_t>(f.y0) + static_cast<std::int64_t>(e[1]), f.width(), f.height(),
                              box.data());
                for (int ch = 0; ch < c; ++ch) acc[ch] += e[2] * box[ch];
            }
            if (rest > 1e-6)
                for (int ch = 0; ch < c; ++ch) acc[ch] += rest * mean[ch];
            for (int ch = 0; ch < c; ++ch) out.pixels[texel * c + ch] = static_cast<float>(acc[ch]);
        }
    });
    return out;
}

}  // namespace

const char* to_string(LodMethod method)
{
    switch (method) {
    case LodMethod::Reference: return "reference";
    case LodMethod::NaiveMip: return "naive";
    case LodMethod::Point: return "point";
    case LodMethod::Levels: return "levels";
    case LodMethod::Patches: return "patches";
    }
    return "?";
}

Expected<LodMethod> parse_lod_method(const std::string& name)
{
    for (LodMethod m :
         {LodMethod::Reference, LodMethod::NaiveMip, LodMethod::Point, LodMethod::Levels, LodMethod::Patches})
        if (name == to_string(m)) return m;
    return bad_input("LodOptions::method '" + name +
                         "' is unknown: expected reference, naive, point, levels or patches",
                     "LodOptions::method");
}

Expected<OutputImage> render_through_map(const CoordinateMap& map, const SampleImage& sample, int threads)
{
    if (auto s = check_full(map, sample); !s) return s.error();
    const CoordinateLevel& full = map.full();
    const int c = sample.channels;
    OutputImage out = blank_output(full.width, full.height, c);
    parallel_for(full.height, threads, [&](int y) {
        for (int x = 0; x < full.width; ++x) {
            const std::size_t t = static_cast<std::size_t>(y) * full.width + x;
            const float* texel = sample.pixels.data() +
                                 (static_cast<std::size_t>(full.y(t)) * sample.width + full.x(t)) * c;
            std::copy(texel, texel + c, out.pixels.data() + t * c);
        }
    });
    return out;
}

Expected<OutputImage> render_at_lod(const CoordinateMap& map, const SampleImage& sample, const LodOptions& options)
{
    if (options.lod < 0 || options.lod > 30)
        return bad_input("LodOptions::lod " + std::to_string(options.lod) + " is invalid: expected 0 .. 30",
                         "LodOptions::lod");
    if (options.patches < 1)
        return bad_input("LodOptions::patches " + std::to_string(options.patches) +
                             " is invalid: expected at least 1 offset per footprint",
                         "LodOptions::patches");
    if (auto s = check_full(map, sample); !s) return s.error();
    const int lod = options.lod;
    switch (options.method) {
    case LodMethod::Reference: {
        auto full = render_through_map(map, sample, options.threads);
        if (!full) return full.error();
        return render_reference(*full, 1 << lod, options.threads);
    }
    case LodMethod::NaiveMip: return render_naive(map, sample_image_pyramid(sample, lod + 1), lod, options.threads);
    case LodMethod::Point: return render_point(map, sample_image_pyramid(sample, lod + 1), lod, options.threads);
    case LodMethod::Levels: return render_levels(map, sample_image_pyramid(sample, lod + 1), lod, options.threads);
    case LodMethod::Patches: return render_patches(map, sample, lod, options.patches, options.threads);
    }
    return runtime_error("unknown LodMethod");
}

}  // namespace cmfilter
