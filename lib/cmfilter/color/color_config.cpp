// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/color/color_config.h"

#include "cmfilter/color/builtin_ocio_config.h"

#include <OpenColorIO/OpenColorIO.h>

#include <sstream>

namespace OCIO = OCIO_NAMESPACE;

namespace cmfilter {

struct ColorConfig::Impl {
    OCIO::ConstConfigRcPtr config;
};

Expected<ColorConfig> ColorConfig::load(const std::string& path)
{
    ColorConfig result;
    auto impl = std::make_shared<Impl>();
    try {
        if (path.empty()) {
            std::istringstream text(builtin_ocio_config_text());
            impl->config = OCIO::Config::CreateFromStream(text);
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
    if (auto cs = impl_->config->getColorSpace(name.c_str())) return std::string(cs->getName());
    std::ostringstream msg;
    msg << "unknown colour space '" << name << "' in the " << source_ << " OpenColorIO config; known colour spaces:";
    const auto& cfg = *impl_->config;
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
        OCIO::PackedImageDesc desc(rgb.data(), static_cast<long>(rgb.size() / 3), 1, 3);
        cpu->apply(desc);
    } catch (const OCIO::Exception& e) {
        return runtime_error("OpenColorIO cannot convert '" + src + "' to '" + dst + "': " + e.what());
    }
    return ok();
}

}  // namespace

Status ColorConfig::to_scene_linear(std::vector<float>& rgb, const std::string& from) const
{
    return apply(impl_->config, rgb, from, OCIO::ROLE_SCENE_LINEAR);
}

Status ColorConfig::from_scene_linear(std::vector<float>& rgb, const std::string& to) const
{
    return apply(impl_->config, rgb, OCIO::ROLE_SCENE_LINEAR, to);
}

}  // namespace cmfilter
