// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/noise_sigma_table_file.h"

#include "cmfilter/io/artefact_file.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/io/metadata.h"
#include "cmfilter/util/version.h"

#include <OpenImageIO/imageio.h>

#include <charconv>
#include <cmath>
#include <fstream>

namespace cmfilter {

namespace {

constexpr int kFormatVersion = 1;
constexpr int kChannels = 4;  // box_sigma, gaussian_sigma, box_ci, gaussian_ci

std::string shortest(double v)
{
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

// "a,b,c" of one integer per LOD.
template <typename Get>
std::string join_counts(const NoiseSigmaBake& bake, Get get)
{
    std::string s;
    for (const auto& r : bake.rows) s += (s.empty() ? "" : ",") + std::to_string(get(r));
    return s;
}

}  // namespace

Status write_noise_sigma_table(const std::string& path, const NoiseSigmaBake& bake, const std::string& noise_spec,
                               double base_period, const ExrOutputOptions& storage)
{
    if (bake.rows.empty()) return bad_input("noise sigma table '" + path + "' has no LODs");
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();
    const int width = static_cast<int>(bake.rows.size());
    std::vector<float> pixels;
    pixels.reserve(static_cast<std::size_t>(width) * kChannels);
    for (const auto& r : bake.rows)
        for (double v : {r.box.sigma, r.gaussian.sigma, r.box.half_width, r.gaussian.half_width})
            pixels.push_back(static_cast<float>(v));

    OIIO::ImageSpec spec(width, 1, kChannels, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"box_sigma", "gaussian_sigma", "box_ci", "gaussian_ci"};
    spec.attribute("compression", "zip");
    spec.attribute("cmfilter:kind", kNoiseSigmaTableKind);
    spec.attribute("cmfilter:format_version", kFormatVersion);
    spec.attribute("cmfilter:version", version());
    spec.attribute("cmfilter:noise", noise_spec);
    spec.attribute("cmfilter:layout",
                   "column k = LOD lod_first + k lod_step, LOD = log2(w / base_period); sigma linear in "
                   "LOD between columns; box: square of side w; gaussian: N(c, (w/2)^2 I); *_ci: 95% "
                   "confidence half-width of sigma");
    const auto dbl = [&](const char* name, double v) { set_double_attribute(spec, name, v); };
    dbl("cmfilter:base_period", base_period);
    dbl("cmfilter:lod_first", bake.lod_first);
    dbl("cmfilter:lod_step", bake.lod_step);
    spec.attribute("cmfilter:lods", width);
    spec.attribute("cmfilter:box_footprints", join_counts(bake, [](const auto& r) { return r.box.footprints; }));
    spec.attribute("cmfilter:box_samples_per_footprint", bake.rows.front().box.samples_per_footprint);
    spec.attribute("cmfilter:gaussian_footprints",
                   join_counts(bake, [](const auto& r) { return r.gaussian.footprints; }));
    spec.attribute("cmfilter:gaussian_samples_per_footprint", bake.rows.front().gaussian.samples_per_footprint);
    spec.attribute("cmfilter:global_samples", bake.global.samples);
    dbl("cmfilter:global_mean", bake.global.mean);
    dbl("cmfilter:global_sigma", bake.global.sigma);
    dbl("cmfilter:global_skewness", bake.global.skewness);
    dbl("cmfilter:global_excess_kurtosis", bake.global.excess_kurtosis);

    return write_float_artefact(*out, spec, pixels.data(), storage);
}

Status write_noise_sigma_csv(const std::string& path, const NoiseSigmaBake& bake, double base_period)
{
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();
    {
        std::ofstream csv(out->temp_path());
        csv << "lod,width,box_sigma,box_ci,box_footprints,box_samples,gaussian_sigma,gaussian_ci,"
               "gaussian_footprints,gaussian_samples\n";
        for (const auto& r : bake.rows)
            csv << shortest(r.lod) << ',' << shortest(base_period * std::exp2(r.lod)) << ',' << shortest(r.box.sigma)
                << ',' << shortest(r.box.half_width) << ',' << r.box.footprints << ',' << r.box.samples_per_footprint
                << ',' << shortest(r.gaussian.sigma) << ',' << shortest(r.gaussian.half_width) << ','
                << r.gaussian.footprints << ',' << r.gaussian.samples_per_footprint << '\n';
        csv.close();
        if (!csv) return out->write_error("");
    }
    return out->commit();
}

Expected<LoadedNoiseSigmaTable> read_noise_sigma_table(const std::string& path, FootprintShape shape)
{
    // One row of a pixel per LOD, before any pixel is read.
    const auto shape_fits = [&](const OIIO::ImageSpec& header) -> Status {
        const int lods = header.get_int_attribute("cmfilter:lods", 0);
        if (header.nchannels != kChannels || header.height != 1 || lods != header.width)
            return bad_input("'" + path + "' has inconsistent cmfilter metadata (" + std::to_string(lods) +
                             " LODs for " + std::to_string(header.width) + " x " + std::to_string(header.height) +
                             " pixels of " + std::to_string(header.nchannels) + " channels)");
        return ok();
    };
    auto artefact = read_artefact_image(path, kNoiseSigmaTableKind, "noise sigma table", kFormatVersion, shape_fits);
    if (!artefact) return artefact.error();
    const OIIO::ImageSpec& spec = artefact->spec;
    const ImageData* image = &artefact->image;
    const int lods = spec.get_int_attribute("cmfilter:lods", 0);
    if (image->channels != kChannels || image->height != 1 || lods != image->width)
        return bad_input("'" + path + "' has inconsistent cmfilter metadata (" + std::to_string(lods) + " LODs for " +
                         std::to_string(image->width) + " x " + std::to_string(image->height) + " pixels of " +
                         std::to_string(image->channels) + " channels)");
    // OpenEXR stores channels sorted by name: find the column by its name.
    const std::string want = std::string(to_string(shape)) + "_sigma";
    int c = -1;
    for (int i = 0; i < image->channels; ++i)
        if (image->channel_names[static_cast<std::size_t>(i)] == want) c = i;
    if (c < 0) return bad_input("'" + path + "' has no channel " + want);
    std::vector<double> sigmas;
    for (int k = 0; k < image->width; ++k) sigmas.push_back(image->pixels[static_cast<std::size_t>(k * kChannels + c)]);
    auto table = NoiseSigmaTable::create(double_attribute(spec, "cmfilter:lod_first"),
                                         double_attribute(spec, "cmfilter:lod_step"), std::move(sigmas));
    if (!table) return bad_input("'" + path + "': " + table.error().message);
    LoadedNoiseSigmaTable out{std::move(*table), spec.get_string_attribute("cmfilter:noise"),
                              double_attribute(spec, "cmfilter:base_period")};
    return out;
}

}  // namespace cmfilter
