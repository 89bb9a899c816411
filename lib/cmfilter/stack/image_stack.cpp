// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/image_stack.h"

#include "cmfilter/stack/color_channels.h"
#include "cmfilter/util/memory_budget.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <optional>
#include <sstream>
#include <vector>

namespace cmfilter {

const char* to_string(StackEncoding encoding)
{
    return encoding == StackEncoding::SceneLinear ? "scene-linear" : "display-encoded";
}

Expected<StackImage> load_stack_image(const std::string& path, const StackLoadOptions& options,
                                      const ColorConfig& config)
{
    auto image = read_image(path);
    if (!image) return image.error();
    StackImage out{std::move(*image), {}};
    ImageData& img = out.data;
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
        if (!std::isfinite(img.pixels[i])) {
            const std::size_t texel = i / img.channels;
            std::ostringstream msg;
            msg << "stack image '" << path << "' has a non-finite value at (" << texel % img.width << ", "
                << texel / img.width << ") channel " << i % img.channels << "; expected finite values";
            return bad_input(msg.str());
        }
    auto space = decide_image_colorspace(img, path, options.colorspace, "StackLoadOptions::colorspace", config);
    if (!space) return space.error();
    out.space = *space;
    if (config.is_data(space->colorspace)) {
        // Data is never colour-converted, so it has no display encoding.
        if (options.encoding == StackEncoding::DisplayEncoded)
            return bad_input("stack image '" + path + "' is in the data colour space '" + space->colorspace + "' (" +
                                 space->rule +
                                 "): its values cannot be display-encoded (as .ptm and .rti hold them); expected "
                                 "colour images, or a scene-linear fit",
                             "StackLoadOptions::encoding");
        return out;
    }
    if (auto st = convert_color_channels(
            img.pixels, img.channels,
            [&](std::vector<float>& rgb) { return image_rgb_to_scene_linear(rgb, *space, config); });
        !st)
        return st.error();
    if (options.encoding == StackEncoding::DisplayEncoded) {
        auto srgb = config.srgb_texture_name();
        if (!srgb) return srgb.error();
        if (auto st =
                convert_color_channels(img.pixels, img.channels,
                                       [&](std::vector<float>& rgb) { return config.from_scene_linear(rgb, *srgb); });
            !st)
            return st.error();
    }
    return out;
}

Status check_stack_light_count(const LightFile& lights)
{
    const int n = static_cast<int>(lights.lights.size());
    if (n < kMinStackLights)
        return bad_input("light file '" + lights.path + "' has " + std::to_string(n) + " light" + (n == 1 ? "" : "s") +
                         "; a stack needs at least " + std::to_string(kMinStackLights) +
                         " (a PTM has 6 coefficients per channel)");
    return ok();
}

Status check_stack_image_shape(const std::string& path, const ImageData& image, const std::string& first_path,
                               int width, int height, int channels)
{
    if (image.width != width || image.height != height) {
        std::ostringstream msg;
        msg << "stack image '" << path << "' is " << image.width << "x" << image.height << " but '" << first_path
            << "' is " << width << "x" << height << "; every image of a stack must have the same size";
        return bad_input(msg.str());
    }
    if (image.channels != channels) {
        std::ostringstream msg;
        msg << "stack image '" << path << "' has " << image.channels << " channel" << (image.channels == 1 ? "" : "s")
            << " but '" << first_path << "' has " << channels << "; every image of a stack must have the same channels";
        return bad_input(msg.str());
    }
    return ok();
}

std::string stack_colorspace(const ImageColorSpace& first, const StackLoadOptions& options, const ColorConfig& config)
{
    if (config.is_data(first.colorspace)) return first.colorspace;
    if (options.encoding == StackEncoding::SceneLinear) return config.scene_linear_name();
    // Display-encoded: the values are now in the config's sRGB encoding.
    auto srgb = config.srgb_texture_name();
    return srgb ? *srgb : first.colorspace;
}

Expected<ImageStack> load_image_stack(const StackLoadOptions& options, const ColorConfig& config)
{
    auto lights = read_light_file(options.light_file);
    if (!lights) return lights.error();
    const LightFile& lp = *lights;
    const int n = static_cast<int>(lp.lights.size());
    if (auto st = check_stack_light_count(lp); !st) return st.error();

    ImageStack stack;
    stack.light_file = lp.path;
    stack.encoding = options.encoding;
    for (int k = 0; k < n; ++k) {
        stack.lights.push_back(lp.lights[k].direction);
        stack.images.push_back(lp.image_path(k));
    }

    // The first image fixes the size and channels; the rest are read in
    // parallel into their slots and checked against it.
    auto first = load_stack_image(stack.images[0], options, config);
    if (!first) return first.error();
    stack.width = first->data.width;
    stack.height = first->data.height;
    stack.channels = first->data.channels;
    stack.colorspace = stack_colorspace(first->space, options, config);
    const std::size_t per_image = stack.texels() * stack.channels;
    if (auto fits = check_allocation(double(per_image) * n * sizeof(float),
                                     "the stack '" + lp.path + "' (" + std::to_string(n) + " images of " +
                                         std::to_string(stack.width) + " x " + std::to_string(stack.height) + " x " +
                                         std::to_string(stack.channels) + ")");
        !fits)
        return fits.error();
    stack.pixels.resize(per_image * n);
    std::copy(first->data.pixels.begin(), first->data.pixels.end(), stack.pixels.begin());

    std::mutex mutex;
    std::optional<std::pair<int, Error>> failure;  // the first failing image, by index
    auto fail = [&](int k, Error e) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure || k < failure->first) failure.emplace(k, std::move(e));
    };
    parallel_for(n - 1, options.threads, [&](int i) {
        const int k = i + 1;
        auto img = load_stack_image(stack.images[k], options, config);
        if (!img) return fail(k, img.error());
        const ImageData& d = img->data;
        if (auto st =
                check_stack_image_shape(stack.images[k], d, stack.images[0], stack.width, stack.height, stack.channels);
            !st)
            return fail(k, st.error());
        std::copy(d.pixels.begin(), d.pixels.end(), stack.image(k));
    });
    if (failure) return failure->second;
    return stack;
}

}  // namespace cmfilter
