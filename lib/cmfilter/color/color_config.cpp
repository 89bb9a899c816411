// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/color/color_config.h"

#include "cmfilter/color/builtin_ocio_config.h"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <sstream>

namespace OCIO = OCIO_NAMESPACE;

namespace cmfilter {

struct ColorConfig::Impl {
    OCIO::ConstConfigRcPtr config;
    // cmfilter's built-in config, for the names cmfilter's own files and
    // OpenImageIO record (resolve, interop_id); the same as config when no
    // file is loaded.
    OCIO::ConstConfigRcPtr builtin;
};

namespace {

OCIO::ConstConfigRcPtr load_builtin()
{
    std::istringstream text(builtin_ocio_config_text());
    return OCIO::Config::CreateFromStream(text);
}

// A colour space's name and aliases, the name first.
std::vector<std::string> names_of(const OCIO::ColorSpace& cs)
{
    std::vector<std::string> out{cs.getName()};
    for (size_t a = 0; a < cs.getNumAliases(); ++a) out.emplace_back(cs.getAlias(a));
    return out;
}

}  // namespace

Expected<ColorConfig> ColorConfig::load(const std::string& path)
{
    ColorConfig result;
    auto impl = std::make_shared<Impl>();
    try {
        impl->builtin = load_builtin();
        if (path.empty()) {
            impl->config = impl->builtin;
            result.source_ = "built-in";
        } else {
            impl->config = OCIO::Config::CreateFromFile(path.c_str());
            result.source_ = path;
        }
        impl->config->validate();
    } catch (const OCIO::Exception& e) {
        return bad_input("OpenColorIO config '" + (path.empty() ? std::string("built-in") : path) +
                         "' cannot be used: " + e.what());
    }
    result.impl_ = std::move(impl);
    return result;
}

std::vector<std::string> ColorConfig::names() const
{
    std::vector<std::string> out;
    const auto& cfg = *impl_->config;
    for (int i = 0; i < cfg.getNumColorSpaces(); ++i) out.emplace_back(cfg.getColorSpaceNameByIndex(i));
    return out;
}

Expected<std::string> ColorConfig::resolve(const std::string& name) const
{
    const auto& cfg = *impl_->config;
    if (auto cs = cfg.getColorSpace(name.c_str())) return std::string(cs->getName());
    // A name of the built-in config: the same space under any name or alias
    // this config gives it.
    if (auto known = impl_->builtin->getColorSpace(name.c_str()))
        for (const std::string& other : names_of(*known))
            if (auto cs = cfg.getColorSpace(other.c_str())) return std::string(cs->getName());
    std::ostringstream msg;
    msg << "unknown colour space '" << name << "' in the " << source_ << " OpenColorIO config; known colour spaces:";
    for (int i = 0; i < cfg.getNumColorSpaces(); ++i) {
        auto cs = cfg.getColorSpace(cfg.getColorSpaceNameByIndex(i));
        msg << "\n  " << cs->getName();
        if (cs->getNumAliases() > 0) {
            msg << " (aliases:";
            for (size_t a = 0; a < cs->getNumAliases(); ++a) msg << (a ? ", " : " ") << cs->getAlias(a);
            msg << ")";
        }
    }
    return bad_input(msg.str());
}

bool ColorConfig::is_data(const std::string& canonical_name) const
{
    auto cs = impl_->config->getColorSpace(canonical_name.c_str());
    return cs && cs->isData();
}

std::string ColorConfig::role_space(const std::string& role) const
{
    const auto& cfg = *impl_->config;
    if (!cfg.hasRole(role.c_str())) return {};
    auto cs = cfg.getColorSpace(role.c_str());
    return cs ? std::string(cs->getName()) : std::string();
}

std::string ColorConfig::file_rule_space(const std::string& path) const
{
    const auto& cfg = *impl_->config;
    try {
        if (cfg.filepathOnlyMatchesDefaultRule(path.c_str())) return {};
        size_t rule = 0;
        const char* name = cfg.getColorSpaceFromFilepath(path.c_str(), rule);
        auto cs = name ? cfg.getColorSpace(name) : nullptr;
        return cs ? std::string(cs->getName()) : std::string();
    } catch (const OCIO::Exception&) {
        return {};  // a rule that names no colour space: as if none matched
    }
}

Expected<std::string> ColorConfig::srgb_texture_name() const
{
    if (auto srgb = resolve("sRGB")) return srgb;
    if (std::string picking = role_space(OCIO::ROLE_COLOR_PICKING); !picking.empty()) return picking;
    return bad_input("the " + source_ +
                     " OpenColorIO config has no sRGB texture space (none of the names of cmfilter's 'sRGB Encoded "
                     "Rec.709', and no color_picking role): name the colour space of integer images explicitly");
}

std::string ColorConfig::interop_id(const std::string& canonical_name) const
{
    auto cs = impl_->config->getColorSpace(canonical_name.c_str());
    if (!cs) return {};
    for (const std::string& name : names_of(*cs))
        if (auto known = impl_->builtin->getColorSpace(name.c_str()))
            for (const std::string& id : names_of(*known))
                if (id.size() > 6 && id.compare(id.size() - 6, 6, "_scene") == 0) return id;
    return {};
}

std::string ColorConfig::scene_linear_name() const
{
    auto cs = impl_->config->getColorSpace(OCIO::ROLE_SCENE_LINEAR);
    return cs ? cs->getName() : std::string(OCIO::ROLE_SCENE_LINEAR);
}

namespace {

Status apply(const OCIO::ConstConfigRcPtr& config, std::vector<float>& rgb, const std::string& src,
             const std::string& dst)
{
    if (rgb.empty()) return ok();
    try {
        auto processor = config->getProcessor(src.c_str(), dst.c_str());
        // LOSSLESS: no fast pow/log/exp approximations (they cost up to 1e-6
        // absolute on sRGB decoding, the whole accuracy budget of a table).
        auto cpu =
            processor->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_LOSSLESS);
        // In rows of at most 4096 pixels: OpenColorIO converts a row through
        // buffers of its own the row's width (a whole image as one row cost
        // about 50 bytes a pixel more).
        constexpr std::size_t kRow = 4096;
        const std::size_t pixels = rgb.size() / 3;
        for (std::size_t first = 0; first < pixels; first += kRow) {
            const std::size_t n = std::min(kRow, pixels - first);
            OCIO::PackedImageDesc desc(rgb.data() + 3 * first, static_cast<long>(n), 1, 3);
            cpu->apply(desc);
        }
    } catch (const OCIO::Exception& e) {
        return runtime_error("OpenColorIO cannot convert '" + src + "' to '" + dst + "': " + e.what());
    }
    return ok();
}

}  // namespace

Status ColorConfig::to_scene_linear(std::vector<float>& rgb, const std::string& from) const
{
    auto name = resolve(from);
    if (!name) return name.error();
    return apply(impl_->config, rgb, *name, OCIO::ROLE_SCENE_LINEAR);
}

Status ColorConfig::from_scene_linear(std::vector<float>& rgb, const std::string& to) const
{
    auto name = resolve(to);
    if (!name) return name.error();
    return apply(impl_->config, rgb, OCIO::ROLE_SCENE_LINEAR, *name);
}

}  // namespace cmfilter
