// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/lafortune_model.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace cmfilter {

const char* to_string(LafortuneVariant variant) { return variant == LafortuneVariant::Rgb ? "rgb" : "luminance"; }

std::optional<LafortuneVariant> parse_lafortune_variant(const std::string& name)
{
    if (name == "rgb") return LafortuneVariant::Rgb;
    if (name == "luminance") return LafortuneVariant::Luminance;
    return std::nullopt;
}

int max_lafortune_lobes(LafortuneVariant variant)
{
    return variant == LafortuneVariant::Rgb ? kLafortuneMaxRgbLobes : kLafortuneMaxLuminanceLobes;
}

std::vector<long long> LafortuneFit::lobe_histogram() const
{
    std::vector<long long> histogram(static_cast<std::size_t>(std::max(lobes, 0)) + 1, 0);
    for (unsigned char n : lobe_counts) ++histogram[std::min<std::size_t>(n, histogram.size() - 1)];
    return histogram;
}

Vec3 lafortune_axis_at_view(const Vec3& a, const Vec3& fitted_view, const Vec3& view)
{
    // Lafortune et al. 1997, eq. 5: the lobe is (C . (u * v))^n, so a = C * v
    // at the fitted view and C * w = a * w / v at another view w.
    auto scale = [](double ak, double vk, double wk) {
        return std::abs(vk) >= kLafortuneViewEpsilon ? ak * wk / vk : ak;
    };
    return {scale(a.x, fitted_view.x, view.x), scale(a.y, fitted_view.y, view.y), scale(a.z, fitted_view.z, view.z)};
}

double lafortune_lobe(const Vec3& a, double n, const Vec3& u)
{
    const double d = dot(a, u);
    if (!(d > 0)) return 0;
    const double value = std::pow(d, n);
    return std::isfinite(value) ? value : DBL_MAX;
}

double lafortune_reflectance(const float* scalar, int lobes, const Vec3& u, const Vec3& fitted_view, const Vec3& view)
{
    const bool same_view = fitted_view == view;
    double f = scalar[0];
    for (int i = 0; i < lobes; ++i) {
        const float* lobe = scalar + 1 + kLafortuneLobeFloats * i;
        Vec3 a{lobe[0], lobe[1], lobe[2]};
        if (!same_view) a = lafortune_axis_at_view(a, fitted_view, view);
        f += std::min(lafortune_lobe(a, lobe[3], u), static_cast<double>(FLT_MAX));
    }
    return std::clamp(f, 0.0, static_cast<double>(FLT_MAX));
}

void lafortune_texel_value(const LafortuneFit& fit, std::size_t t, const Vec3& light, const Vec3& view, float* out)
{
    const double uz = std::max(0.0, light.z);
    const float* p = fit.texel(t);
    if (fit.variant == LafortuneVariant::Luminance) {
        const double y = uz * lafortune_reflectance(p, fit.lobes, light, fit.view, view);
        const float* base = p + fit.scalar_stride();
        for (int c = 0; c < fit.channels; ++c)
            out[c] = static_cast<float>(
                std::clamp(base[c] * y, -static_cast<double>(FLT_MAX), static_cast<double>(FLT_MAX)));
        return;
    }
    for (int c = 0; c < fit.channels; ++c)
        out[c] = static_cast<float>(
            uz * lafortune_reflectance(p + c * fit.scalar_stride(), fit.lobes, light, fit.view, view));
}

}  // namespace cmfilter
