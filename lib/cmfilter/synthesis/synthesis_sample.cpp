// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthesis/synthesis_sample.h"

#include "cmfilter/stack/btf_manifest.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/light_file.h"
#include "cmfilter/synthesis/image_selection.h"
#include "cmfilter/synthesis/sample_pyramid.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/parallel_for.h"
#include "cmfilter/util/sha256.h"

#include <cmath>
#include <optional>

namespace cmfilter {

namespace {

SampleKind kind_of_path(const std::string& path)
{
    const std::string ext = lowercase_extension(path);
    if (ext == ".lp") return SampleKind::Stack;
    if (ext == ".json") return SampleKind::Btf;
    return SampleKind::Image;
}

Status append_light_file_images(const std::string& lp, std::vector<std::string>& files)
{
    auto lights = read_light_file(lp);
    if (!lights) return lights.error();
    for (std::size_t k = 0; k < lights->lights.size(); ++k) files.push_back(lights->image_path(k));
    return ok();
}

// Levels 1 .. levels - 1 of the pyramid from level 0 (sample_pyramid.h).
void build_sample_pyramid(SynthesisSample& sample, int levels)
{
    sample.levels.resize(1);
    for (int l = 1; l < levels; ++l) {
        const SampleLevel& finer = sample.levels.back();
        SampleLevel half;
        half.width = pyramid_level_extent(finer.width, 1);
        half.height = pyramid_level_extent(finer.height, 1);
        half.features = halve_features(finer.features.data(), finer.width, finer.height, sample.dims);
        sample.levels.push_back(std::move(half));
    }
}

}  // namespace

const char* to_string(SampleKind kind)
{
    switch (kind) {
    case SampleKind::Image: return "image";
    case SampleKind::Stack: return "stack";
    case SampleKind::Btf: return "btf";
    }
    return "image";
}

Expected<std::vector<std::string>> sample_image_files(const std::string& path)
{
    if (path.empty())
        return bad_input("SampleOptions::path is empty; expected an image, a .lp or a BTF manifest",
                         "SampleOptions::path");
    std::vector<std::string> files;
    switch (kind_of_path(path)) {
    case SampleKind::Image: files.push_back(path); break;
    case SampleKind::Stack:
        if (auto st = append_light_file_images(path, files); !st) return st.error();
        break;
    case SampleKind::Btf: {
        auto manifest = read_btf_manifest(path);
        if (!manifest) return manifest.error();
        for (std::size_t v = 0; v < manifest->views.size(); ++v)
            if (auto st = append_light_file_images(manifest->light_file_path(v), files); !st) return st.error();
        break;
    }
    }
    return files;
}

Expected<std::string> sample_content_hash(const std::vector<std::string>& files)
{
    std::string digests;
    for (const std::string& file : files) {
        auto digest = sha256_file_hex(file);
        if (!digest) return digest.error();
        digests += *digest;
    }
    return sha256_hex(digests.data(), digests.size());
}

Expected<SynthesisSample> load_synthesis_sample(const SampleOptions& options, const ColorConfig& config)
{
    if (options.select_images < 0)
        return bad_input("SampleOptions::select_images " + std::to_string(options.select_images) +
                             " is invalid: expected >= 0 (0 keeps every image)",
                         "SampleOptions::select_images");
    if (options.levels < 1)
        return bad_input("SampleOptions::levels " + std::to_string(options.levels) + " is invalid: expected >= 1",
                         "SampleOptions::levels");
    auto files = sample_image_files(options.path);
    if (!files) return files.error();
    if (files->empty()) return bad_input("sample '" + options.path + "' holds no images; expected at least one");
    auto hash = sample_content_hash(*files);
    if (!hash) return hash.error();

    // Every image at full resolution (the selection compares whole images).
    const int n = static_cast<int>(files->size());
    std::vector<std::optional<Expected<StackImage>>> loaded(static_cast<std::size_t>(n));
    StackLoadOptions load;
    load.colorspace = options.colorspace;
    parallel_for(n, options.threads, [&](int k) {
        loaded[static_cast<std::size_t>(k)] = load_stack_image((*files)[static_cast<std::size_t>(k)], load, config);
    });
    std::vector<std::vector<float>> images(static_cast<std::size_t>(n));
    int width = 0, height = 0, channels = 0;
    for (int k = 0; k < n; ++k) {
        Expected<StackImage>& image = *loaded[static_cast<std::size_t>(k)];
        if (!image) return image.error();
        const ImageData& data = image->data;
        if (k == 0) {
            width = data.width;
            height = data.height;
            channels = data.channels;
            if (auto st = check_pyramid_levels("sample '" + options.path + "'", width, height, options.levels); !st)
                return st.error();
        } else if (auto st = check_stack_image_shape((*files)[static_cast<std::size_t>(k)], data, (*files)[0], width,
                                                     height, channels);
                   !st)
            return st.error();
        images[static_cast<std::size_t>(k)] = std::move(image->data.pixels);
        loaded[static_cast<std::size_t>(k)].reset();
    }

    SynthesisSample sample;
    sample.path = options.path;
    sample.kind = kind_of_path(options.path);
    sample.hash = *hash;
    sample.channels = channels;
    sample.images = n;
    sample.used = select_representative_images(images, options.select_images, options.threads);
    sample.dims = static_cast<int>(sample.used.size()) * channels;
    sample.periodic = options.periodic;
    SampleLevel level0;
    level0.width = width;
    level0.height = height;
    level0.features.resize(level0.texels() * static_cast<std::size_t>(sample.dims));
    const std::size_t texels = level0.texels();
    for (std::size_t j = 0; j < sample.used.size(); ++j) {
        std::vector<float>& image = images[static_cast<std::size_t>(sample.used[j])];
        for (std::size_t t = 0; t < texels; ++t)
            for (int c = 0; c < channels; ++c)
                level0.features[t * sample.dims + j * channels + c] = image[t * channels + c];
        std::vector<float>().swap(image);
    }
    sample.levels.push_back(std::move(level0));
    build_sample_pyramid(sample, options.levels);
    return sample;
}

Expected<SynthesisSample> sample_from_features(int width, int height, int dims, std::vector<float> features, int levels,
                                               bool periodic)
{
    if (dims < 1) return bad_input("sample features of " + std::to_string(dims) + " dimensions; expected >= 1");
    if (auto st = check_pyramid_levels("the sample in memory", width, height, levels); !st) return st.error();
    const std::size_t expected = static_cast<std::size_t>(width) * height * dims;
    if (features.size() != expected)
        return bad_input("the sample in memory has " + std::to_string(features.size()) + " feature values; expected " +
                         std::to_string(expected) + " (" + std::to_string(width) + " x " + std::to_string(height) +
                         " texels of " + std::to_string(dims) + ")");
    for (std::size_t i = 0; i < features.size(); ++i)
        if (!std::isfinite(features[i]))
            return bad_input("the sample in memory has a non-finite value at texel " + std::to_string(i / dims) +
                             " dimension " + std::to_string(i % dims) + "; expected finite values");
    SynthesisSample sample;
    sample.kind = SampleKind::Image;
    sample.hash = sha256_hex(features.data(), features.size() * sizeof(float));
    sample.channels = dims;
    sample.images = 1;
    sample.used = {0};
    sample.dims = dims;
    sample.periodic = periodic;
    SampleLevel level0;
    level0.width = width;
    level0.height = height;
    level0.features = std::move(features);
    sample.levels.push_back(std::move(level0));
    build_sample_pyramid(sample, levels);
    return sample;
}

}  // namespace cmfilter
