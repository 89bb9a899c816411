// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/lafortune_file.h"

#include "cmfilter/io/recorded_path.h"
#include "cmfilter/io/artefact_file.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/io/metadata.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/version.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

namespace cmfilter {

namespace {

constexpr int kFormatVersion = 1;

std::string channel_label(int c, int channels)
{
    if (channels == 1) return "Y";
    return std::string(1, "RGB"[c]);
}

bool channels_allowed(LafortuneVariant variant, int channels)
{
    return variant == LafortuneVariant::Rgb ? channels == 3 : channels == 1 || channels == 3;
}

int scalars(const LafortuneFit& fit) { return fit.variant == LafortuneVariant::Luminance ? 1 : fit.channels; }

std::string histogram_text(const std::vector<long long>& histogram)
{
    std::string text;
    for (std::size_t i = 0; i < histogram.size(); ++i) text += (i ? "," : "") + std::to_string(histogram[i]);
    return text;
}

}  // namespace

std::vector<std::string> lafortune_channel_names(LafortuneVariant variant, int channels, int lobes)
{
    std::vector<std::string> names;
    auto scalar = [&](const std::string& prefix) {
        names.push_back(prefix + ".rho");
        for (int i = 0; i < lobes; ++i)
            for (const char* p : {"ax", "ay", "az", "n"}) names.push_back(prefix + "." + std::to_string(i) + "." + p);
    };
    if (variant == LafortuneVariant::Luminance) {
        scalar("L");
        for (int c = 0; c < channels; ++c) names.push_back(channel_label(c, channels));
        names.push_back("L.lobes");
        return names;
    }
    for (int c = 0; c < channels; ++c) scalar(channel_label(c, channels));
    for (int c = 0; c < channels; ++c) names.push_back(channel_label(c, channels) + ".lobes");
    return names;
}

Status write_lafortune_exr(const std::string& path, const LafortuneFit& fit, const std::string& source)
{
    const std::string what = "Lafortune fit for '" + path + "'";
    if (fit.width <= 0 || fit.height <= 0 || !channels_allowed(fit.variant, fit.channels) || fit.lobes < 1 ||
        fit.lobes > max_lafortune_lobes(fit.variant) || fit.parameters.size() != fit.texels() * fit.stride() ||
        fit.lobe_counts.size() != fit.texels() * scalars(fit))
        return bad_input(what + " is inconsistent: " + std::to_string(fit.parameters.size()) + " parameters and " +
                         std::to_string(fit.lobe_counts.size()) + " lobe counts for " + std::to_string(fit.width) +
                         " x " + std::to_string(fit.height) + " texels, " + std::to_string(fit.channels) +
                         " channels and " + std::to_string(fit.lobes) + " lobes of a " + to_string(fit.variant) +
                         " fit");
    if (!(std::isfinite(fit.view.x) && std::isfinite(fit.view.y) && fit.view.z > 0))
        return bad_input(what + " has a view below the horizon");
    for (float v : fit.parameters)
        if (!std::isfinite(v)) return bad_input(what + " holds non-finite parameters");
    for (unsigned char n : fit.lobe_counts)
        if (n > fit.lobes)
            return bad_input(what + " has a lobe count above its " + std::to_string(fit.lobes) + " lobes");
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();

    const int params = fit.stride(), counts = scalars(fit), total = params + counts;
    std::vector<float> pixels(fit.texels() * total);
    for (std::size_t t = 0; t < fit.texels(); ++t) {
        std::copy(fit.texel(t), fit.texel(t) + params, pixels.begin() + t * total);
        for (int c = 0; c < counts; ++c) pixels[t * total + params + c] = fit.lobe_counts[t * counts + c];
    }
    OIIO::ImageSpec spec(fit.width, fit.height, total, OIIO::TypeDesc::FLOAT);
    spec.channelnames = lafortune_channel_names(fit.variant, fit.channels, fit.lobes);
    spec.attribute("compression", "zip");
    spec.attribute("cmfilter:kind", kLafortuneFitKind);
    spec.attribute("cmfilter:format_version", kFormatVersion);
    spec.attribute("cmfilter:version", version());
    spec.attribute("cmfilter:variant", to_string(fit.variant));
    spec.attribute("cmfilter:channels", fit.channels);
    spec.attribute("cmfilter:lobes", fit.lobes);
    spec.attribute("cmfilter:auto_lobes", fit.auto_lobes ? 1 : 0);
    spec.attribute("cmfilter:lobe_histogram", histogram_text(fit.lobe_histogram()));
    spec.attribute("cmfilter:fallbacks", std::to_string(fit.fallbacks));
    set_double_attribute(spec, "cmfilter:view_x", fit.view.x);
    set_double_attribute(spec, "cmfilter:view_y", fit.view.y);
    set_double_attribute(spec, "cmfilter:view_z", fit.view.z);
    spec.attribute("cmfilter:encoding", to_string(fit.encoding));
    spec.attribute("cmfilter:colorspace", fit.colorspace);
    spec.attribute("cmfilter:source", path_for_record(source, path));
    spec.attribute("cmfilter:layout",
                   fit.variant == LafortuneVariant::Luminance
                       ? "value_c(u) = c * uz * (L.rho + sum_i max(0, L.i.a . u)^L.i.n) (c: the base colour channel)"
                       : "value_c(u) = uz * (c.rho + sum_i max(0, c.i.a . u)^c.i.n)");
    return write_float_artefact(*out, spec, pixels.data());
}

Expected<LafortuneFit> read_lafortune_exr(const std::string& path, std::string* source)
{
    auto artefact = read_artefact_image(path, kLafortuneFitKind, "Lafortune fit", kFormatVersion);
    if (!artefact) return artefact.error();
    const OIIO::ImageSpec& spec = artefact->spec;
    ImageData* image = &artefact->image;

    LafortuneFit fit;
    const std::string variant = spec.get_string_attribute("cmfilter:variant");
    const auto parsed = parse_lafortune_variant(variant);
    if (!parsed)
        return bad_input("'" + path + "' has an unknown Lafortune variant '" + variant +
                         "' (expected rgb or luminance)");
    fit.variant = *parsed;
    fit.width = image->width;
    fit.height = image->height;
    fit.channels = spec.get_int_attribute("cmfilter:channels", 0);
    if (!channels_allowed(fit.variant, fit.channels))
        return bad_input("'" + path + "' has cmfilter:channels " + std::to_string(fit.channels) + ", expected " +
                         (fit.variant == LafortuneVariant::Rgb ? "3 for rgb" : "1 or 3 for luminance"));
    fit.lobes = spec.get_int_attribute("cmfilter:lobes", 0);
    if (fit.lobes < 1 || fit.lobes > max_lafortune_lobes(fit.variant))
        return bad_input("'" + path + "' has cmfilter:lobes " + std::to_string(fit.lobes) + ", expected 1 to " +
                         std::to_string(max_lafortune_lobes(fit.variant)) + " for " + variant);
    fit.auto_lobes = spec.get_int_attribute("cmfilter:auto_lobes", 0) != 0;
    fit.view = {double_attribute(spec, "cmfilter:view_x"), double_attribute(spec, "cmfilter:view_y"),
                double_attribute(spec, "cmfilter:view_z")};
    if (!(std::isfinite(fit.view.x) && std::isfinite(fit.view.y) && fit.view.z > 0))
        return bad_input("'" + path + "' has no view above the horizon (cmfilter:view_x, _y, _z)");
    const std::string encoding = spec.get_string_attribute("cmfilter:encoding");
    if (encoding == to_string(StackEncoding::SceneLinear)) fit.encoding = StackEncoding::SceneLinear;
    else if (encoding == to_string(StackEncoding::DisplayEncoded)) fit.encoding = StackEncoding::DisplayEncoded;
    else
        return bad_input("'" + path + "' has an unknown cmfilter:encoding '" + encoding + "' (expected " +
                         to_string(StackEncoding::SceneLinear) + " or " + to_string(StackEncoding::DisplayEncoded) +
                         ")");
    fit.colorspace = spec.get_string_attribute("cmfilter:colorspace");
    const std::string fallbacks = spec.get_string_attribute("cmfilter:fallbacks", "0");
    char* end = nullptr;
    fit.fallbacks = std::strtoll(fallbacks.c_str(), &end, 10);
    if (fallbacks.empty() || *end != '\0' || fit.fallbacks < 0)
        return bad_input("'" + path + "' has cmfilter:fallbacks '" + fallbacks + "', expected a count");

    const std::vector<std::string> names = lafortune_channel_names(fit.variant, fit.channels, fit.lobes);
    if (image->channels != static_cast<int>(names.size()))
        return bad_input("'" + path + "' has " + std::to_string(image->channels) + " channels, expected " +
                         std::to_string(names.size()) + " for a " + variant + " fit of " +
                         std::to_string(fit.channels) + " channels and " + std::to_string(fit.lobes) + " lobes");
    std::map<std::string, int> column;
    for (int i = 0; i < image->channels; ++i) column[image->channel_names[static_cast<std::size_t>(i)]] = i;
    std::vector<int> from(names.size());
    for (std::size_t j = 0; j < names.size(); ++j) {
        const auto it = column.find(names[j]);
        if (it == column.end()) return bad_input("'" + path + "' has no channel " + names[j]);
        from[j] = it->second;
    }
    const int params = fit.stride(), counts = scalars(fit), total = params + counts;
    const std::size_t texels = fit.texels();
    fit.parameters.resize(texels * params);
    fit.lobe_counts.resize(texels * counts);
    for (std::size_t t = 0; t < texels; ++t)
        for (int j = 0; j < total; ++j) {
            const float v = image->pixels[t * total + static_cast<std::size_t>(from[j])];
            auto where = [&] {
                return " (channel " + names[j] + ", texel " + std::to_string(t % fit.width) + ", " +
                       std::to_string(t / fit.width) + ")";
            };
            if (!std::isfinite(v)) return bad_input("'" + path + "' holds a non-finite parameter" + where());
            if (j >= params) {
                if (!(v >= 0 && v <= fit.lobes && v == std::floor(v)))
                    return bad_input("'" + path + "' has a lobe count " + std::to_string(v) + where() +
                                     ", expected a whole number in 0 to " + std::to_string(fit.lobes));
                fit.lobe_counts[t * counts + (j - params)] = static_cast<unsigned char>(v);
                continue;
            }
            const int in_scalar = j % fit.scalar_stride();
            const bool exponent = (fit.variant == LafortuneVariant::Rgb || j < fit.scalar_stride()) && in_scalar > 0 &&
                                  (in_scalar - 1) % kLafortuneLobeFloats == 3;
            if (exponent && !(v >= kLafortuneMinExponent))
                return bad_input("'" + path + "' has a lobe exponent " + std::to_string(v) + where() +
                                 ", expected at least 1");
            fit.parameters[t * params + j] = v;
        }
    if (source) *source = path_from_record(spec.get_string_attribute("cmfilter:source"), path);
    return fit;
}

}  // namespace cmfilter
