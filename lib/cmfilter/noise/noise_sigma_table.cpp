// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/noise_sigma_table.h"

#include <cmath>
#include <string>

namespace cmfilter {

Expected<NoiseSigmaTable> NoiseSigmaTable::create(double lod_first, double lod_step, std::vector<double> sigmas)
{
    if (!std::isfinite(lod_first))
        return bad_input("noise sigma table: first LOD must be finite, got " + std::to_string(lod_first));
    if (!(lod_step > 0) || !std::isfinite(lod_step))
        return bad_input("noise sigma table: LOD step must be positive and finite, got " + std::to_string(lod_step));
    if (sigmas.empty()) return bad_input("noise sigma table: no sigma values");
    for (std::size_t k = 0; k < sigmas.size(); ++k)
        if (!(sigmas[k] >= 0) || !std::isfinite(sigmas[k]))
            return bad_input("noise sigma table: sigma " + std::to_string(k) + " must be finite and >= 0, got " +
                             std::to_string(sigmas[k]));
    NoiseSigmaTable t;
    t.lod_first_ = lod_first;
    t.lod_step_ = lod_step;
    t.sigmas_ = std::move(sigmas);
    return t;
}

double NoiseSigmaTable::sigma_at(double lod) const
{
    if (std::isnan(lod)) return lod;
    const double u = (lod - lod_first_) / lod_step_;
    const double last = static_cast<double>(sigmas_.size() - 1);
    if (!(u > 0)) return sigmas_.front();
    if (u >= last) return sigmas_.back();
    const auto k = static_cast<std::size_t>(u);
    const double t = u - static_cast<double>(k);
    return sigmas_[k] + t * (sigmas_[k + 1] - sigmas_[k]);
}

}  // namespace cmfilter
