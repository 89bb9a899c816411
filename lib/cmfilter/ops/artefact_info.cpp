// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/ops/artefact_info.h"

#include "cmfilter/io/method_tolerance_record.h"

#include "cmfilter/ops/filtered_image_file.h"
#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/texture/color_pyramid_file.h"
#include "cmfilter/texture/segment_pyramid_file.h"
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/texture/moment_pyramid_info.h"
#include "cmfilter/noise/noise_image.h"
#include "cmfilter/noise/noise_sigma_table_file.h"
#include "cmfilter/ops/stack_info.h"
#include "cmfilter/stack/lafortune_file.h"
#include "cmfilter/synthesis/analysis_file.h"
#include "cmfilter/synthesis/coordinate_map_file.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>

namespace cmfilter {

namespace {

std::string describe_kind(const std::string& kind, int width, int height)
{
    if (kind == kGaussianColorTableKind)
        return "prefiltered colour-map table T(v, sigma) = (C0 * N(0, sigma^2))(v) (Heitz et al. "
               "2013, eq. 10): " +
               std::to_string(width) + " value nodes x " + std::to_string(height) + " sigma nodes, scene-linear RGB";
    if (kind == kMomentPyramidKind)
        return "moment pyramid of a driver f (Heitz et al. 2013, sec. 4.2): " + std::to_string(width) + " x " +
               std::to_string(height) +
               " level 0, tiled MIP-map; channels m1, m2 = box means of (f - c) and (f - c)^2 "
               "about the reference value c; mean = c + m1, variance = max(0, m2 - m1^2)";
    if (kind == kHistogramPyramidKind)
        return "histogram pyramid of a driver with few distinct values (Heitz et al. 2013, sec. "
               "4.1, exact solutions): " +
               std::to_string(width) + " x " + std::to_string(height) +
               " level 0, tiled MIP-map; channel b = fraction of the footprint where f = v_b "
               "(cmfilter:values)";
    if (kind == kColorPyramidKind)
        return "colour pyramid of a driver through one colour map (apply --method color-pyramid): " +
               std::to_string(width) + " x " + std::to_string(height) +
               " level 0, tiled MIP-map; channels R, G, B = box mean of C0(f) over each texel's footprint, "
               "scene-linear (cmfilter:linear_space), exact for a box filter; for the map whose digest is "
               "cmfilter:map_sha256 only";
    if (kind == kSegmentPyramidKind)
        return "segment pyramid of a driver for the breakpoints t_0..t_K of colour maps (apply --method segments): " +
               std::to_string(width) + " x " + std::to_string(height) +
               " level 0, tiled MIP-map; channel k = box mean R_k of the ramp clamp((f - t_{k-1}) / (t_k - "
               "t_{k-1}), 0, 1) (cmfilter:breakpoints); mean C(f) = C(t_0) + sum_k (C(t_k) - C(t_{k-1})) R_k for "
               "any map linear between them, within cmfilter:segment_tolerance (CIEDE2000) of the maps it was "
               "baked for";
    if (kind == kFilteredImageKind)
        return "filtered colour image of a colour-mapped driver (cmfilter apply): " + std::to_string(width) + " x " +
               std::to_string(height) + " RGB";
    if (kind == kNoiseImageKind)
        return "procedural noise driver (cmfilter noise-image): " + std::to_string(width) + " x " +
               std::to_string(height) +
               ", channel Y = the noise (cmfilter:noise) at pixel centres, "
               "data (no colour space)";
    if (kind == kNoiseSigmaTableKind)
        return "noise sigma table (Heitz et al. 2013, sec. 4.2: the noise standard deviation per level "
               "of detail, a 1D texture): " +
               std::to_string(width) +
               " LODs from cmfilter:lod_first in "
               "steps of cmfilter:lod_step; channels box_sigma, gaussian_sigma (unresolved standard "
               "deviation inside a box of width w = base_period 2^LOD / a Gaussian of standard deviation "
               "w/2) and box_ci, gaussian_ci (95% confidence half-widths)";
    if (kind == "linear-fit") return describe_linear_fit(width, height);
    if (kind == kCoordinateMapKind)
        return "coordinate map of a synthesised surface (Bosserhoff & Nicoll sec. 4.2): " + std::to_string(width) +
               " x " + std::to_string(height) +
               " texels, channels u, v = the centre of the sample texel each copies (normalised; "
               "cmfilter:sample_width x cmfilter:sample_height), further subimages the hierarchical levels' maps";
    if (kind == kSynthesisAnalysisKind)
        return "synthesis analysis of a sample (Bosserhoff & Nicoll sec. 4.1): per pyramid level the texels' "
               "textons and candidate sets and the textons' dot products; level 0 " +
               std::to_string(width) + " x " + std::to_string(height);
    return "cmfilter artefact of an unknown kind (made by a newer cmfilter?)";
}

std::string format_value(const OIIO::ParamValue& p)
{
    const OIIO::TypeDesc t = p.type();
    if (t == OIIO::TypeDesc::DOUBLE || t == OIIO::TypeDesc::FLOAT) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.17g",
                      t == OIIO::TypeDesc::DOUBLE ? p.get<double>() : static_cast<double>(p.get<float>()));
        return buf;
    }
    return p.get_string();
}

}  // namespace

Expected<ArtefactInfo> read_artefact_info(const std::string& path)
{
    // Stacks, BTF manifests and .ptm/.rti fits are not single EXRs.
    if (auto stack = read_stack_file_info(path)) return std::move(*stack);
    // read_image gives the Io/BadInput distinction for missing and non-image files.
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        auto img = read_image(path);
        if (!img) return img.error();
        return bad_input("'" + path + "' is not an image OpenImageIO can read");
    }
    const OIIO::ImageSpec& spec = in->spec();
    ArtefactInfo info;
    info.path = path;
    info.format = in->format_name();
    info.width = spec.width;
    info.height = spec.height;
    info.channels = spec.nchannels;
    for (const auto& p : spec.extra_attribs) {
        const std::string name = p.name().string();
        if (name.rfind("cmfilter:", 0) != 0) continue;
        const std::string key = name.substr(9);
        if (key == "kind") info.kind = p.get_string();
        info.parameters.emplace_back(key, format_value(p));
        const OIIO::TypeDesc t = p.type();
        if (t.aggregate == OIIO::TypeDesc::SCALAR && t.arraylen == 0 &&
            (t.basetype == OIIO::TypeDesc::FLOAT || t.basetype == OIIO::TypeDesc::DOUBLE ||
             t.basetype == OIIO::TypeDesc::INT || t.basetype == OIIO::TypeDesc::UINT) &&
            format_value(p).find_first_of("ni") == std::string::npos)  // not nan or inf
            info.numeric.push_back(key);
    }
    if (info.kind.empty())
        return bad_input("'" + path +
                         "' is an image but not a cmfilter artefact (no cmfilter:kind "
                         "metadata)");
    info.description = info.kind == kLafortuneFitKind ? describe_lafortune_fit(info)
                                                      : describe_kind(info.kind, info.width, info.height);
    if (info.kind == kMomentPyramidKind && spec.get_int_attribute("cmfilter:moment_order", 2) == 4)
        info.description += "; m3, m4 = box means of (f - c)^3 and (f - c)^4 (order 4, the mixture method)";
    if (const auto choice = get_method_tolerance_metadata(spec))  // bake-moments / apply --tolerance
        info.description += "; " + choice->method + " chosen as the cheapest method within mean CIEDE2000 " +
                            format_value(*spec.find_attribute("cmfilter:method_tolerance")) + " at LOD " + choice->lods;
    return info;
}

}  // namespace cmfilter
