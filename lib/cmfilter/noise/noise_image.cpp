// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/noise_image.h"

#include "cmfilter/io/artefact_file.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/io/metadata.h"
#include "cmfilter/util/parallel_for.h"
#include "cmfilter/util/version.h"

#include <OpenImageIO/imageio.h>

#include <cmath>

namespace cmfilter {

namespace {

constexpr int kFormatVersion = 1;

// The spec's noise and its pixels, after checking the options.
struct Rendered {
    FractalNoise noise;
    std::vector<float> pixels;
};

Expected<Rendered> render(const NoiseImageOptions& options)
{
    if (options.width < 1 || options.width > 65536 || options.height < 1 || options.height > 65536)
        return bad_input("noise image size " + std::to_string(options.width) + " x " + std::to_string(options.height) +
                         " is out of range (expected 1..65536 each)");
    if (!(options.scale > 0) || !std::isfinite(options.scale))
        return bad_input("noise image scale " + std::to_string(options.scale) +
                         " is invalid (expected a finite value > 0 noise units per pixel)");
    auto noise = make_noise(options.spec);
    if (!noise) return noise.error();
    const auto w = static_cast<std::size_t>(options.width);
    std::vector<float> pixels(w * static_cast<std::size_t>(options.height));
    const FractalNoise& f = *noise;
    parallel_for(options.height, options.threads, [&](int j) {
        const double y = options.scale * (j + 0.5);
        float* row = pixels.data() + w * static_cast<std::size_t>(j);
        for (std::size_t i = 0; i < w; ++i)
            row[i] = static_cast<float>(f(options.scale * (static_cast<double>(i) + 0.5), y));
    });
    return Rendered{std::move(*noise), std::move(pixels)};
}

}  // namespace

Expected<std::vector<float>> render_noise_image(const NoiseImageOptions& options)
{
    auto r = render(options);
    if (!r) return r.error();
    return std::move(r->pixels);
}

Status write_noise_image(const std::string& path, const NoiseImageOptions& options)
{
    if (auto st = check_output_path(path, ".exr"); !st) return st;
    auto rendered = render(options);
    if (!rendered) return rendered.error();
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();

    OIIO::ImageSpec spec(options.width, options.height, 1, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"Y"};
    spec.attribute("compression", "zip");
    spec.attribute("cmfilter:kind", kNoiseImageKind);
    spec.attribute("cmfilter:format_version", kFormatVersion);
    spec.attribute("cmfilter:version", version());
    spec.attribute("cmfilter:noise", to_string(options.spec));
    spec.attribute("cmfilter:layout", "data, no colour space; pixel (i, j) = noise(scale (i + 1/2), scale (j + 1/2)), "
                                      "row 0 at the top");
    set_double_attribute(spec, "cmfilter:scale", options.scale);
    set_double_attribute(spec, "cmfilter:base_period", rendered->noise.base_period());

    return write_float_artefact(*out, spec, rendered->pixels.data());
}

}  // namespace cmfilter
