// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/ops/stack_info.h"

#include "cmfilter/stack/btf_manifest.h"
#include "cmfilter/stack/fit_loading.h"
#include "cmfilter/stack/light_file.h"
#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/util/atomic_output.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace cmfilter {

namespace {

std::string number(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

double elevation_degrees(const Vec3& d)
{
    return std::asin(std::clamp(d.z, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

Expected<ArtefactInfo> stack_info(const std::string& path)
{
    auto lp = read_light_file(path);
    if (!lp) return lp.error();
    ArtefactInfo info;
    info.path = path;
    info.kind = "image-stack";
    info.format = "lp";
    if (!lp->lights.empty()) {
        auto in = OIIO::ImageInput::open(lp->image_path(0));
        if (in) {
            info.width = in->spec().width;
            info.height = in->spec().height;
            info.channels = in->spec().nchannels;
            info.parameters.emplace_back("first_image_format", in->format_name());
        } else {
            info.parameters.emplace_back("first_image", "unreadable: " + lp->image_path(0));
        }
    }
    std::vector<Vec3> lights;
    double lo = 90, hi = 0;
    for (const LightEntry& l : lp->lights) {
        lights.push_back(l.direction);
        lo = std::min(lo, elevation_degrees(l.direction));
        hi = std::max(hi, elevation_degrees(l.direction));
    }
    info.parameters.emplace_back("lights", std::to_string(lights.size()));
    info.numeric.push_back("lights");
    info.parameters.emplace_back("elevation_min_degrees", number(lo));
    info.parameters.emplace_back("elevation_max_degrees", number(hi));
    info.numeric.insert(info.numeric.end(), {"elevation_min_degrees", "elevation_max_degrees"});
    for (LinearModel m : {LinearModel::PtmRgb, LinearModel::Hsh2, LinearModel::Hsh3}) {
        auto c = check_light_set(lights, m);
        const std::string key = std::string("condition_number_") + to_string(m);
        info.parameters.emplace_back(key, c ? number(c->condition_number) : "unusable: " + c.error().message);
        if (c && std::isfinite(c->condition_number)) info.numeric.push_back(key);
    }
    info.description = "image stack (one view slot of a BTF): " + std::to_string(lights.size()) +
                       " images of one surface, each under one light of the .lp file";
    return info;
}

Expected<ArtefactInfo> manifest_info(const std::string& path)
{
    auto m = read_btf_manifest(path);
    if (!m) return m.error();
    ArtefactInfo info;
    info.path = path;
    info.kind = "btf-manifest";
    info.format = "json";
    info.description = "BTF manifest: " + std::to_string(m->views.size()) + " view slots, each an image stack";
    for (std::size_t k = 0; k < m->views.size(); ++k) {
        const BtfView& v = m->views[k];
        info.parameters.emplace_back("view_" + std::to_string(k), v.lights + " from (" + number(v.view.x) + ", " +
                                                                      number(v.view.y) + ", " + number(v.view.z) + ")");
    }
    return info;
}

Expected<ArtefactInfo> interchange_info(const std::string& path, FitFileFormat format)
{
    auto fit = load_fit(path);
    if (!fit) return fit.error();
    ArtefactInfo info;
    info.path = path;
    info.kind = format == FitFileFormat::Ptm ? "ptm" : "rti";
    info.format = to_string(format);
    info.width = fit->width;
    info.height = fit->height;
    info.channels = fit->channels;
    info.description = std::string(format == FitFileFormat::Ptm ? "Polynomial Texture Map (PTM 1.2)"
                                                                : "hemispherical-harmonics RTI (HSH)") +
                       ", " + to_string(fit->model) +
                       ": 8-bit quantised coefficients fitted to display-encoded (sRGB) values, as RTI viewers "
                       "expect; relight decodes them to scene-linear";
    info.parameters.emplace_back("model", to_string(fit->model));
    info.parameters.emplace_back("terms_per_channel", std::to_string(fit->terms()));
    info.numeric.push_back("terms_per_channel");
    info.parameters.emplace_back("encoding", to_string(fit->encoding));
    return info;
}

bool is_btf_manifest(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head.find("\"cmfilter-btf\"") != std::string::npos;
}

}  // namespace

std::string describe_linear_fit(int width, int height)
{
    return "linear relighting fit of an image stack (cmfilter fit; PTM: Malzbender et al. 2001, HSH: Gautron et "
           "al. 2004): " +
           std::to_string(width) + " x " + std::to_string(height) +
           ", one float channel per coefficient (cmfilter:model), unquantised";
}

std::string describe_lafortune_fit(const ArtefactInfo& info)
{
    auto parameter = [&](const std::string& key) -> std::string {
        for (const auto& [k, v] : info.parameters)
            if (k == key) return v;
        return "?";
    };
    auto coordinate = [&](const std::string& key) {
        const std::string text = parameter(key);
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        return end != text.c_str() ? number(v) : text;
    };
    const bool rgb = parameter("variant") == "rgb";
    const std::string lobes = parameter("lobes");
    return std::string("per-texel Lafortune lobes of an image stack (cmfilter fit --model ") +
           (rgb ? "lafortune-rgb" : "lafortune") +
           "; Lafortune et al. 1997, per texel McAllister et al. 2002): " + std::to_string(info.width) + " x " +
           std::to_string(info.height) + ", " +
           (rgb ? "variant rgb, a diffuse term and " : "variant luminance, a diffuse term and ") +
           (parameter("auto_lobes") == "1" ? "at most " + lobes + " lobes chosen per texel"
                                           : lobes + (lobes == "1" ? " lobe" : " lobes")) +
           (rgb ? " per channel" : " times a base colour") + ", fitted at the view (" + coordinate("view_x") + ", " +
           coordinate("view_y") + ", " + coordinate("view_z") +
           "); each lobe's stored axis a = (Cx vx, Cy vy, Cz vz) and exponent n, one float channel per parameter";
}

std::optional<Expected<ArtefactInfo>> read_stack_file_info(const std::string& path)
{
    const std::string ext = lowercase_extension(path);
    if (ext == ".lp") return stack_info(path);
    if (ext == ".ptm") return interchange_info(path, FitFileFormat::Ptm);
    if (ext == ".rti") return interchange_info(path, FitFileFormat::Rti);
    if (ext == ".json" && is_btf_manifest(path)) return manifest_info(path);
    return std::nullopt;
}

}  // namespace cmfilter
