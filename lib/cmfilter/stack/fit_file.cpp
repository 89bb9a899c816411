// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/fit_file.h"

#include "cmfilter/io/recorded_path.h"
#include "cmfilter/io/artefact_file.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/io/metadata.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/version.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace cmfilter {

namespace {

constexpr int kFormatVersion = 1;

// The attributes this format defines; every other cmfilter:* text
// attribute is FitFileInfo::extra.
const char* const kOwnAttributes[] = {
    "cmfilter:kind",
    "cmfilter:format_version",
    "cmfilter:version",
    "cmfilter:model",
    "cmfilter:channels",
    "cmfilter:encoding",
    "cmfilter:colorspace",
    "cmfilter:source",
    "cmfilter:layout",
    "cmfilter:lights",
    "cmfilter:terms",
    "cmfilter:largest_singular",
    "cmfilter:smallest_singular",
    "cmfilter:condition_number",
    "cmfilter:clamped_singular",
};

const char* encoding_name(StackEncoding encoding)
{
    return encoding == StackEncoding::SceneLinear ? "scene-linear" : "display-encoded";
}

bool parse_encoding(const std::string& name, StackEncoding* encoding)
{
    if (name == "scene-linear") *encoding = StackEncoding::SceneLinear;
    else if (name == "display-encoded") *encoding = StackEncoding::DisplayEncoded;
    else return false;
    return true;
}

std::string channel_label(int c, int channels)
{
    if (channels == 1) return "Y";
    if (channels <= 4) return std::string(1, "RGBA"[c]);
    return "C" + std::to_string(c);
}

char term_letter(LinearModel model) { return model == LinearModel::Hsh2 || model == LinearModel::Hsh3 ? 'h' : 'a'; }

}  // namespace

std::vector<std::string> fit_channel_names(LinearModel model, int channels)
{
    std::vector<std::string> names;
    const int terms = basis_terms(model);
    const std::string letter(1, term_letter(model));
    if (model == LinearModel::PtmLrgb) {
        for (int k = 0; k < terms; ++k) names.push_back("L." + letter + std::to_string(k));
        for (int c = 0; c < channels; ++c) names.push_back(channel_label(c, channels));
        return names;
    }
    for (int c = 0; c < channels; ++c)
        for (int k = 0; k < terms; ++k) names.push_back(channel_label(c, channels) + "." + letter + std::to_string(k));
    return names;
}

Status write_fit_exr(const std::string& path, const LinearFit& fit, const FitFileInfo& info)
{
    if (fit.width <= 0 || fit.height <= 0 || fit.channels <= 0 ||
        fit.coefficients.size() != fit.texels() * static_cast<std::size_t>(fit.stride()))
        return bad_input("linear fit for '" + path + "' is inconsistent: " + std::to_string(fit.coefficients.size()) +
                         " coefficients for " + std::to_string(fit.width) + " x " + std::to_string(fit.height) +
                         " texels of " + std::to_string(fit.stride()));
    for (float v : fit.coefficients)
        if (!std::isfinite(v)) return bad_input("linear fit for '" + path + "' holds non-finite coefficients");
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();

    OIIO::ImageSpec spec(fit.width, fit.height, fit.stride(), OIIO::TypeDesc::FLOAT);
    spec.channelnames = fit_channel_names(fit.model, fit.channels);
    spec.attribute("compression", "zip");
    spec.attribute("cmfilter:kind", kLinearFitKind);
    spec.attribute("cmfilter:format_version", kFormatVersion);
    spec.attribute("cmfilter:version", version());
    spec.attribute("cmfilter:model", to_string(fit.model));
    spec.attribute("cmfilter:channels", fit.channels);
    spec.attribute("cmfilter:encoding", encoding_name(fit.encoding));
    spec.attribute("cmfilter:colorspace", fit.colorspace);
    spec.attribute("cmfilter:source", path_for_record(info.source, path));
    spec.attribute("cmfilter:layout",
                   fit.model == LinearModel::PtmLrgb
                       ? "value_c(l) = c * sum_k L.ak basis_k(l) (c: the base colour channel; basis_k: linear_model.h)"
                       : "value_c(l) = sum_k c.ak basis_k(l) (c.hk for HSH; basis_k: linear_model.h)");
    const LightSetConditioning& c = fit.conditioning;
    spec.attribute("cmfilter:lights", c.lights);
    spec.attribute("cmfilter:terms", c.terms);
    if (std::isfinite(c.largest_singular)) set_double_attribute(spec, "cmfilter:largest_singular", c.largest_singular);
    if (std::isfinite(c.smallest_singular))
        set_double_attribute(spec, "cmfilter:smallest_singular", c.smallest_singular);
    // An infinite condition number (a clamped singular value) is not
    // written: cmfilter:clamped_singular > 0 says it.
    if (std::isfinite(c.condition_number)) set_double_attribute(spec, "cmfilter:condition_number", c.condition_number);
    spec.attribute("cmfilter:clamped_singular", c.clamped);
    for (const auto& [name, value] : info.extra) {
        const std::string full = name.rfind("cmfilter:", 0) == 0 ? name : "cmfilter:" + name;
        if (std::find(std::begin(kOwnAttributes), std::end(kOwnAttributes), full) != std::end(kOwnAttributes))
            return bad_input("linear fit for '" + path + "': the extra attribute " + full +
                             " is one the format defines itself");
        spec.attribute(full, value);
    }
    return write_float_artefact(*out, spec, fit.coefficients.data());
}

Expected<LinearFit> read_fit_exr(const std::string& path, FitFileInfo* info)
{
    auto artefact = read_artefact_image(path, kLinearFitKind, "linear fit", kFormatVersion);
    if (!artefact) return artefact.error();
    const OIIO::ImageSpec& spec = artefact->spec;
    ImageData* image = &artefact->image;

    const std::string model_name = spec.get_string_attribute("cmfilter:model");
    const auto model = parse_linear_model(model_name);
    if (!model)
        return bad_input("'" + path + "' has an unknown linear model '" + model_name +
                         "' (expected ptm-rgb, ptm-lrgb, hsh2 or hsh3)");
    LinearFit fit;
    fit.model = *model;
    fit.width = image->width;
    fit.height = image->height;
    fit.channels = spec.get_int_attribute("cmfilter:channels", 0);
    if (fit.channels <= 0 || (fit.model == LinearModel::PtmLrgb && fit.channels != 1 && fit.channels != 3))
        return bad_input("'" + path + "' has cmfilter:channels " + std::to_string(fit.channels) + ", expected " +
                         (fit.model == LinearModel::PtmLrgb ? "1 or 3 for ptm-lrgb" : "a positive count"));
    // In 64 bits: channels x terms past INT_MAX must be refused, not wrap.
    const long long declared_stride = linear_fit_stride(fit.model, fit.channels);
    if (image->channels != declared_stride)
        return bad_input("'" + path + "' has " + std::to_string(image->channels) + " channels, expected " +
                         std::to_string(declared_stride) + " for a " + model_name + " fit of " +
                         std::to_string(fit.channels) + " channel" + (fit.channels == 1 ? "" : "s"));
    const int stride = fit.stride();
    const std::string encoding = spec.get_string_attribute("cmfilter:encoding");
    if (!parse_encoding(encoding, &fit.encoding))
        return bad_input("'" + path + "' has an unknown cmfilter:encoding '" + encoding +
                         "' (expected scene-linear or display-encoded)");
    fit.colorspace = spec.get_string_attribute("cmfilter:colorspace");

    // OpenEXR stores channels sorted by name: find each coefficient's
    // channel by its name.
    std::map<std::string, int> column;
    for (int i = 0; i < image->channels; ++i) column[image->channel_names[static_cast<std::size_t>(i)]] = i;
    const std::vector<std::string> names = fit_channel_names(fit.model, fit.channels);
    std::vector<int> source(names.size());
    for (std::size_t j = 0; j < names.size(); ++j) {
        const auto it = column.find(names[j]);
        if (it == column.end()) return bad_input("'" + path + "' has no channel " + names[j]);
        source[j] = it->second;
    }
    const std::size_t texels = fit.texels();
    fit.coefficients.resize(texels * static_cast<std::size_t>(stride));
    for (std::size_t t = 0; t < texels; ++t)
        for (int j = 0; j < stride; ++j) {
            const float v = image->pixels[t * stride + static_cast<std::size_t>(source[static_cast<std::size_t>(j)])];
            if (!std::isfinite(v))
                return bad_input("'" + path + "' holds a non-finite coefficient (channel " +
                                 names[static_cast<std::size_t>(j)] + ", texel " + std::to_string(t % fit.width) +
                                 ", " + std::to_string(t / fit.width) + ")");
            fit.coefficients[t * stride + static_cast<std::size_t>(j)] = v;
        }

    LightSetConditioning& c = fit.conditioning;
    c.lights = spec.get_int_attribute("cmfilter:lights", 0);
    c.terms = spec.get_int_attribute("cmfilter:terms", fit.terms());
    c.largest_singular = double_attribute(spec, "cmfilter:largest_singular");
    c.smallest_singular = double_attribute(spec, "cmfilter:smallest_singular");
    c.clamped = spec.get_int_attribute("cmfilter:clamped_singular", 0);
    c.condition_number = c.clamped > 0 ? std::numeric_limits<double>::infinity()
                                       : double_attribute(spec, "cmfilter:condition_number");

    if (info) {
        info->source = path_from_record(spec.get_string_attribute("cmfilter:source"), path);
        info->extra.clear();
        for (const OIIO::ParamValue& p : spec.extra_attribs) {
            const std::string name = p.name().string();
            if (name.rfind("cmfilter:", 0) != 0 || p.type() != OIIO::TypeDesc::STRING) continue;
            if (std::find(std::begin(kOwnAttributes), std::end(kOwnAttributes), name) != std::end(kOwnAttributes))
                continue;
            info->extra.emplace_back(name, p.get_string());
        }
    }
    return fit;
}

}  // namespace cmfilter
