// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/tables/gaussian_color_table_file.h"

#include "cmfilter/io/recorded_path.h"
#include "cmfilter/io/artefact_file.h"
#include "cmfilter/io/linear_space_attributes.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/io/metadata.h"
#include "cmfilter/util/version.h"

#include <OpenImageIO/imageio.h>

#include <cmath>

namespace cmfilter {

namespace {

constexpr int kFormatVersion = 1;

}  // namespace

Status write_gaussian_color_table(const std::string& path, const GaussianColorTable& table,
                                  const GaussianColorTableInfo& info, const ExrOutputOptions& storage)
{
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();
    const TableAxes& ax = table.axes();

    OIIO::ImageSpec spec(ax.values, ax.sigmas, 3, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    set_linear_space_attributes(spec, info.source.linear_space, info.source.linear_interop_id);
    spec.attribute("cmfilter:kind", kGaussianColorTableKind);
    spec.attribute("cmfilter:format_version", kFormatVersion);
    spec.attribute("cmfilter:version", version());
    spec.attribute("cmfilter:equation", "T(v, sigma) = (C0 * N(0, sigma^2))(v), Heitz et al. 2013 eq. 10");
    spec.attribute("cmfilter:layout", "columns = value nodes, rows = sigma nodes, row 0 = sigma 0; bilinear lookup");
    const auto dbl = [&](const char* name, double v) { set_double_attribute(spec, name, v); };
    dbl("cmfilter:domain_min", ax.vmin);
    dbl("cmfilter:domain_max", ax.vmax);
    spec.attribute("cmfilter:wrap", to_string(ax.wrap));
    dbl("cmfilter:margin", ax.margin);
    spec.attribute("cmfilter:values", ax.values);
    dbl("cmfilter:value_first", ax.value_first());
    dbl("cmfilter:value_last", ax.value_last());
    spec.attribute("cmfilter:sigmas", ax.sigmas);
    dbl("cmfilter:sigma_max", ax.sigma_max);
    spec.attribute("cmfilter:sigma_spacing", to_string(ax.spacing));
    const ColorMapProvenance& src = info.source;
    spec.attribute("cmfilter:source", path_for_record(src.path, path));
    spec.attribute("cmfilter:source_sha256", src.sha256);
    spec.attribute("cmfilter:source_size", std::to_string(src.image_width) + "x" + std::to_string(src.image_height));
    spec.attribute("cmfilter:source_selection", src.selection);
    spec.attribute("cmfilter:colorspace", src.colorspace);
    spec.attribute("cmfilter:colorspace_rule", src.colorspace_rule);
    spec.attribute("cmfilter:ocio_config", src.ocio_config);
    if (info.lookup_error) {
        spec.attribute("cmfilter:lookup_error_samples", info.lookup_error_samples);
        dbl("cmfilter:lookup_de2000_mean", info.lookup_error->mean);
        dbl("cmfilter:lookup_de2000_p95", info.lookup_error->p95);
        dbl("cmfilter:lookup_de2000_max", info.lookup_error->max);
    }
    if (!info.sigma_max_source.empty()) spec.attribute("cmfilter:sigma_max_source", info.sigma_max_source);
    if (info.tolerance) {
        dbl("cmfilter:tolerance_de2000", info.tolerance->tolerance);
        spec.attribute("cmfilter:tolerance_statistic", info.tolerance->statistic);
        dbl("cmfilter:tolerance_error", info.tolerance->error);
        spec.attribute("cmfilter:tolerance_samples", info.tolerance->samples);
        spec.attribute("cmfilter:tolerance_search", info.tolerance->search);
    }

    return write_float_artefact(*out, spec, table.data().data(), storage);
}

Expected<LoadedGaussianColorTable> read_gaussian_color_table(const std::string& path)
{
    // The axes' sizes before any pixel is read.
    const auto axes_fit = [&](const OIIO::ImageSpec& header) -> Status {
        if (header.get_int_attribute("cmfilter:values", 0) != header.width ||
            header.get_int_attribute("cmfilter:sigmas", 0) != header.height || header.nchannels != 3)
            return bad_input("'" + path + "' has inconsistent cmfilter metadata (axes do not match " +
                             std::to_string(header.width) + " x " + std::to_string(header.height) + " pixels of " +
                             std::to_string(header.nchannels) + " channels, expected 3)");
        return ok();
    };
    auto artefact = read_artefact_image(path, kGaussianColorTableKind, "colour table", kFormatVersion, axes_fit);
    if (!artefact) return artefact.error();
    const OIIO::ImageSpec& spec = artefact->spec;
    ImageData* image = &artefact->image;

    const auto dbl = [&](const char* name) { return double_attribute(spec, name); };
    TableAxes ax;
    ax.values = spec.get_int_attribute("cmfilter:values", 0);
    ax.sigmas = spec.get_int_attribute("cmfilter:sigmas", 0);
    ax.vmin = dbl("cmfilter:domain_min");
    ax.vmax = dbl("cmfilter:domain_max");
    ax.margin = dbl("cmfilter:margin");
    ax.sigma_max = dbl("cmfilter:sigma_max");
    auto wrap = parse_wrap_mode(spec.get_string_attribute("cmfilter:wrap"));
    auto spacing = parse_sigma_spacing(spec.get_string_attribute("cmfilter:sigma_spacing"));
    if (!wrap || !spacing || ax.values != image->width || ax.sigmas != image->height || image->channels != 3 ||
        !(ax.vmin < ax.vmax) || !(ax.sigma_max > 0) || !std::isfinite(ax.margin) || ax.values < 2 || ax.sigmas < 2)
        return bad_input("'" + path + "' has inconsistent cmfilter metadata (axes do not match " +
                         std::to_string(image->width) + " x " + std::to_string(image->height) +
                         " pixels, or a value is missing)");
    ax.wrap = *wrap;
    ax.spacing = *spacing;
    for (float v : image->pixels)
        if (!std::isfinite(v)) return bad_input("'" + path + "' holds non-finite table values");

    LoadedGaussianColorTable out{GaussianColorTable(ax, std::move(image->pixels)), {}};
    GaussianColorTableInfo& info = out.info;
    info.baked_by = spec.get_string_attribute("cmfilter:version");
    info.source.path = path_from_record(spec.get_string_attribute("cmfilter:source"), path);
    info.source.sha256 = spec.get_string_attribute("cmfilter:source_sha256");
    info.source.selection = spec.get_string_attribute("cmfilter:source_selection");
    info.source.colorspace = spec.get_string_attribute("cmfilter:colorspace");
    info.source.colorspace_rule = spec.get_string_attribute("cmfilter:colorspace_rule");
    info.source.linear_space = spec.get_string_attribute("cmfilter:linear_space");
    info.source.linear_interop_id = spec.get_string_attribute("colorInteropID");
    info.source.ocio_config = spec.get_string_attribute("cmfilter:ocio_config");
    info.lookup_error_samples = spec.get_int_attribute("cmfilter:lookup_error_samples", 0);
    if (info.lookup_error_samples > 0) {
        ErrorSummary e;
        e.count = static_cast<std::size_t>(info.lookup_error_samples);
        e.mean = dbl("cmfilter:lookup_de2000_mean");
        e.p95 = dbl("cmfilter:lookup_de2000_p95");
        e.max = dbl("cmfilter:lookup_de2000_max");
        info.lookup_error = e;
    }
    info.sigma_max_source = spec.get_string_attribute("cmfilter:sigma_max_source");
    if (spec.find_attribute("cmfilter:tolerance_de2000")) {
        TableToleranceRecord t;
        t.tolerance = dbl("cmfilter:tolerance_de2000");
        t.statistic = spec.get_string_attribute("cmfilter:tolerance_statistic");
        t.error = dbl("cmfilter:tolerance_error");
        t.samples = spec.get_int_attribute("cmfilter:tolerance_samples", 0);
        t.search = spec.get_string_attribute("cmfilter:tolerance_search");
        info.tolerance = t;
    }
    return out;
}

}  // namespace cmfilter
