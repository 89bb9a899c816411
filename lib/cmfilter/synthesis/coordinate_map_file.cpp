// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthesis/coordinate_map_file.h"

#include "cmfilter/io/recorded_path.h"
#include "cmfilter/io/artefact_file.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/io/metadata.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/version.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>

namespace cmfilter {

namespace {

constexpr int kFormatVersion = 1;

std::string level_name(std::size_t level) { return "level-" + std::to_string(level); }

std::string texel_text(std::size_t t, int width)
{
    return "(" + std::to_string(t % static_cast<std::size_t>(width)) + ", " +
           std::to_string(t / static_cast<std::size_t>(width)) + ")";
}

Status check_level(const std::string& path, std::size_t l, const CoordinateLevel& level)
{
    if (level.width < 1 || level.height < 1 || level.sample_width < 1 || level.sample_height < 1 ||
        level.coords.size() != 2 * level.texels())
        return bad_input("the coordinate map for '" + path + "' is inconsistent at level " + std::to_string(l) + ": " +
                         std::to_string(level.width) + " x " + std::to_string(level.height) + " texels into a " +
                         std::to_string(level.sample_width) + " x " + std::to_string(level.sample_height) +
                         " sample, " + std::to_string(level.coords.size()) + " coordinates");
    for (std::size_t t = 0; t < level.texels(); ++t)
        if (level.x(t) < 0 || level.x(t) >= level.sample_width || level.y(t) < 0 || level.y(t) >= level.sample_height)
            return bad_input("the coordinate map for '" + path + "' copies sample texel (" +
                             std::to_string(level.x(t)) + ", " + std::to_string(level.y(t)) + ") at level " +
                             std::to_string(l) + " texel " + texel_text(t, level.width) + "; expected within the " +
                             std::to_string(level.sample_width) + " x " + std::to_string(level.sample_height) +
                             " sample");
    return ok();
}

// cmfilter:seed is written as decimal text (every 64-bit seed exactly); an
// int attribute, as other tools write it, reads too.
bool read_seed(const OIIO::ImageSpec& spec, std::uint64_t* seed)
{
    const OIIO::ParamValue* p = spec.find_attribute("cmfilter:seed");
    if (!p) return false;
    if (p->type() == OIIO::TypeDesc::STRING) {
        const std::string text = p->get_string();
        if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return false;
        char* end = nullptr;
        *seed = std::strtoull(text.c_str(), &end, 10);
        return *end == '\0';
    }
    const int value = spec.get_int_attribute("cmfilter:seed", -1);
    if (value < 0) return false;
    *seed = static_cast<std::uint64_t>(value);
    return true;
}

// A text attribute; one another tool wrote as a number (oiiotool's
// `--attrib name 0`) as its text.
std::string text_attribute(const OIIO::ImageSpec& spec, const char* name)
{
    const OIIO::ParamValue* p = spec.find_attribute(name);
    if (!p) return {};
    return p->type() == OIIO::TypeDesc::STRING ? std::string(p->get_ustring().string()) : std::string(p->get_string());
}

// What read_coordinate_map_exr requires of a map's record, checked before
// writing so that every file written reads back.
Status check_info(const std::string& path, const CoordinateMapInfo& info)
{
    const auto bad = [&](const std::string& what) {
        return bad_input("the coordinate map for '" + path + "' has " + what);
    };
    if (info.sample_kind != "image" && info.sample_kind != "stack" && info.sample_kind != "btf")
        return bad("CoordinateMapInfo::sample_kind '" + info.sample_kind + "' (expected image, stack or btf)");
    if (info.k < 1 || info.neighbourhood < 1 || info.levels < 1)
        return bad("CoordinateMapInfo::k " + std::to_string(info.k) + ", CoordinateMapInfo::neighbourhood " +
                   std::to_string(info.neighbourhood) + " and CoordinateMapInfo::levels " +
                   std::to_string(info.levels) + " (expected each >= 1)");
    return ok();
}

}  // namespace

Status write_coordinate_map_exr(const std::string& path, const CoordinateMap& map)
{
    if (map.levels.empty()) return bad_input("the coordinate map for '" + path + "' has no levels");
    if (auto st = check_info(path, map.info); !st) return st;
    for (std::size_t l = 0; l < map.levels.size(); ++l)
        if (auto st = check_level(path, l, map.levels[l]); !st) return st;
    if (!std::isfinite(map.info.seconds) || map.info.seconds < 0)
        return bad_input("the coordinate map for '" + path + "' has a synthesis time of " +
                         std::to_string(map.info.seconds) + " s; expected a time >= 0");
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();

    std::vector<OIIO::ImageSpec> specs;
    std::vector<std::vector<float>> pixels;
    for (std::size_t l = 0; l < map.levels.size(); ++l) {
        const CoordinateLevel& level = map.levels[l];
        OIIO::ImageSpec spec(level.width, level.height, 2, OIIO::TypeDesc::FLOAT);
        spec.channelnames = {"u", "v"};
        spec.attribute("oiio:subimagename", level_name(l));
        spec.attribute("compression", "zip");
        spec.attribute("cmfilter:sample_width", level.sample_width);
        spec.attribute("cmfilter:sample_height", level.sample_height);
        if (l == 0) {
            const CoordinateMapInfo& info = map.info;
            spec.attribute("cmfilter:kind", kCoordinateMapKind);
            spec.attribute("cmfilter:format_version", kFormatVersion);
            spec.attribute("cmfilter:version", version());
            spec.attribute("cmfilter:sample", path_for_record(info.sample_path, path));
            spec.attribute("cmfilter:sample_hash", info.sample_hash);
            spec.attribute("cmfilter:sample_kind", info.sample_kind);
            spec.attribute("cmfilter:sample_periodic", info.sample_periodic ? 1 : 0);
            spec.attribute("cmfilter:k", info.k);
            spec.attribute("cmfilter:neighbourhood", info.neighbourhood);
            spec.attribute("cmfilter:levels", info.levels);
            spec.attribute("cmfilter:toroidal", info.toroidal ? 1 : 0);
            spec.attribute("cmfilter:seed", std::to_string(info.seed));
        }
        // Each texel the centre of the sample texel it copies, normalised.
        std::vector<float> uv(2 * level.texels());
        for (std::size_t t = 0; t < level.texels(); ++t) {
            uv[2 * t] = static_cast<float>((level.x(t) + 0.5) / level.sample_width);
            uv[2 * t + 1] = static_cast<float>((level.y(t) + 0.5) / level.sample_height);
        }
        specs.push_back(spec);
        pixels.push_back(std::move(uv));
    }
    return write_float_artefact_parts(*out, std::move(specs), pixels);
}

Expected<CoordinateMap> read_coordinate_map_exr(const std::string& path)
{
    auto opened = open_image_input(path);
    if (!opened) return opened.error();
    std::unique_ptr<OIIO::ImageInput> in = std::move(*opened);
    const OIIO::ImageSpec spec0 = in->spec();
    if (auto st = check_artefact_kind(spec0, path, kCoordinateMapKind, "coordinate map", kFormatVersion); !st)
        return st.error();
    auto bad = [&](const std::string& what) { return bad_input("'" + path + "' " + what); };

    CoordinateMap map;
    CoordinateMapInfo& info = map.info;
    info.sample_path = path_from_record(text_attribute(spec0, "cmfilter:sample"), path);
    info.sample_hash = text_attribute(spec0, "cmfilter:sample_hash");
    info.sample_kind = text_attribute(spec0, "cmfilter:sample_kind");
    if (info.sample_kind != "image" && info.sample_kind != "stack" && info.sample_kind != "btf")
        return bad("has an unknown cmfilter:sample_kind '" + info.sample_kind + "' (expected image, stack or btf)");
    auto flag = [&](const char* name, bool* value) -> Status {
        const int v = spec0.get_int_attribute(name, -1);
        if (v != 0 && v != 1) return bad("has " + std::string(name) + " " + std::to_string(v) + "; expected 0 or 1");
        *value = v == 1;
        return ok();
    };
    if (auto st = flag("cmfilter:sample_periodic", &info.sample_periodic); !st) return st.error();
    if (auto st = flag("cmfilter:toroidal", &info.toroidal); !st) return st.error();
    info.k = spec0.get_int_attribute("cmfilter:k", 0);
    info.neighbourhood = spec0.get_int_attribute("cmfilter:neighbourhood", 0);
    info.levels = spec0.get_int_attribute("cmfilter:levels", 0);
    if (info.k < 1 || info.neighbourhood < 1 || info.levels < 1)
        return bad("has cmfilter:k " + std::to_string(info.k) + ", cmfilter:neighbourhood " +
                   std::to_string(info.neighbourhood) + " and cmfilter:levels " + std::to_string(info.levels) +
                   "; expected each >= 1");
    if (!read_seed(spec0, &info.seed)) return bad("has no valid cmfilter:seed; expected a non-negative integer");
    // The synthesis time is optional (0 when another tool wrote the map).
    if (spec0.find_attribute("cmfilter:seconds")) {
        info.seconds = double_attribute(spec0, "cmfilter:seconds");
        if (!std::isfinite(info.seconds) || info.seconds < 0)
            return bad("has cmfilter:seconds " + std::to_string(info.seconds) + "; expected a time >= 0");
    }

    for (int s = 0; in->seek_subimage(s, 0); ++s) {
        const std::size_t l = static_cast<std::size_t>(s);
        const OIIO::ImageSpec spec = in->spec();
        const std::string name = level_name(l);
        CoordinateLevel level;
        level.width = spec.width;
        level.height = spec.height;
        level.sample_width = spec.get_int_attribute("cmfilter:sample_width", 0);
        level.sample_height = spec.get_int_attribute("cmfilter:sample_height", 0);
        if (level.sample_width < 1 || level.sample_height < 1)
            return bad("has cmfilter:sample_width " + std::to_string(level.sample_width) +
                       " and cmfilter:sample_height " + std::to_string(level.sample_height) + " on subimage " +
                       std::to_string(s) + " (" + name + "); expected a sample size of at least 1 x 1");
        int cu = -1, cv = -1;
        for (int c = 0; c < spec.nchannels; ++c) {
            if (spec.channelnames[static_cast<std::size_t>(c)] == "u") cu = c;
            if (spec.channelnames[static_cast<std::size_t>(c)] == "v") cv = c;
        }
        if (cu < 0 || cv < 0)
            return bad("has no channels u and v on subimage " + std::to_string(s) + " (" + name + ")");
        if (auto fits = check_image_allocation(spec, path, spec.nchannels, 2); !fits) return fits.error();
        std::vector<float> px(level.texels() * static_cast<std::size_t>(spec.nchannels));
        if (!read_float_pixels(*in, s, 0, 0, spec.nchannels, px.data()))
            return io_error("cannot read '" + path + "': " + in->geterror());
        level.coords.resize(2 * level.texels());
        for (std::size_t t = 0; t < level.texels(); ++t) {
            const float u = px[t * spec.nchannels + static_cast<std::size_t>(cu)];
            const float v = px[t * spec.nchannels + static_cast<std::size_t>(cv)];
            for (int axis = 0; axis < 2; ++axis) {
                const float value = axis == 0 ? u : v;
                const char* channel = axis == 0 ? "u" : "v";
                if (!std::isfinite(value))
                    return bad("has a non-finite " + std::string(channel) + " at texel " + texel_text(t, level.width) +
                               " of " + name);
                if (value < 0.0f || value >= 1.0f)
                    return bad("has " + std::string(channel) + " " + std::to_string(value) + " at texel " +
                               texel_text(t, level.width) + " of " + name + ", outside the sample; expected [0, 1)");
            }
            // Any u in [0, 1) falls in sample texel floor(u * W) < W.
            level.coords[2 * t] =
                std::min(level.sample_width - 1, static_cast<std::int32_t>(std::floor(double(u) * level.sample_width)));
            level.coords[2 * t + 1] = std::min(level.sample_height - 1,
                                               static_cast<std::int32_t>(std::floor(double(v) * level.sample_height)));
        }
        map.levels.push_back(std::move(level));
    }
    if (map.levels.empty()) return bad("has no coordinate map subimage");
    return map;
}

}  // namespace cmfilter
