// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/tables/plain_lookup.h"

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/tables/gaussian_convolution.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cmfilter {

PlainLookupSigma::PlainLookupSigma(double v_first, double v_step, std::vector<float> cells)
    : v_first_(v_first), inv_step_(v_step > 0 ? 1 / v_step : 0), cells_(std::move(cells))
{
}

double PlainLookupSigma::smallest() const
{
    return cells_.empty() ? 0.0 : *std::min_element(cells_.begin(), cells_.end());
}

double PlainLookupSigma::largest() const
{
    return cells_.empty() ? 0.0 : *std::max_element(cells_.begin(), cells_.end());
}

double PlainLookupSigma::median() const
{
    if (cells_.empty()) return 0;
    std::vector<float> sorted = cells_;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    return sorted[sorted.size() / 2];
}

Expected<PlainLookupSigma> plain_lookup_sigma(const ColorMap& map, const PlainLookupOptions& options)
{
    if (auto st = validate(map, "the colour map"); !st) return st.error();
    if (!(std::isfinite(options.bound) && options.bound > 0)) {
        std::ostringstream msg;
        msg << "the small-sigma bound " << options.bound << " is invalid (expected a CIEDE2000 difference > 0)";
        return bad_input(msg.str());
    }
    if (!(std::isfinite(options.sigma_cap) && options.sigma_cap > 0)) {
        std::ostringstream msg;
        msg << "the small-sigma search's cap " << options.sigma_cap << " is invalid (expected a sigma > 0)";
        return bad_input(msg.str());
    }
    if (options.points_per_texel < 1)
        return bad_input("points per texel " + std::to_string(options.points_per_texel) +
                         " is invalid (expected >= 1)");

    // Points from one texel before the domain's first texel centre to one after its last.
    const int m = options.points_per_texel;
    const double h = map.texel_width();
    const double step = h / m;
    const double v_first = map.vmin - 0.5 * h;  // the centre of node -1
    const std::size_t count = static_cast<std::size_t>(map.size() + 1) * static_cast<std::size_t>(m) + 1;
    std::vector<double> v(count);
    std::vector<Lab> plain(count);
    for (std::size_t i = 0; i < count; ++i) {
        v[i] = v_first + static_cast<double>(i) * step;
        plain[i] = linear_rec709_to_lab(map.evaluate(v[i]));
    }

    // Each point's largest grid sigma that meets the bound at every grid sigma up to it.
    std::vector<double> passed(count, 0.0);
    std::vector<std::size_t> active(count);
    for (std::size_t i = 0; i < count; ++i) active[i] = i;
    std::vector<unsigned char> fails;
    const double ratio = std::pow(2.0, 0.125);
    for (double sigma = std::min(1e-3 * h, options.sigma_cap); !active.empty();
         sigma = std::min(sigma * ratio, options.sigma_cap)) {
        const GaussianConvolution filtered(map, sigma);  // T(., sigma), eq. 10
        fails.assign(active.size(), 0);
        parallel_for(static_cast<int>(active.size()), options.threads, [&](int k) {
            const std::size_t i = active[static_cast<std::size_t>(k)];
            fails[static_cast<std::size_t>(k)] = ciede2000(plain[i], linear_rec709_to_lab(filtered(v[i]))) >
                                                 options.bound;
        });
        std::size_t kept = 0;
        for (std::size_t k = 0; k < active.size(); ++k) {
            if (fails[k]) continue;
            passed[active[k]] = sigma;
            active[kept++] = active[k];
        }
        active.resize(kept);
        if (sigma >= options.sigma_cap) break;
    }

    std::vector<float> cells(count - 1);
    for (std::size_t c = 0; c + 1 < count; ++c) cells[c] = static_cast<float>(std::min(passed[c], passed[c + 1]));
    return PlainLookupSigma(v_first, step, std::move(cells));
}

}  // namespace cmfilter
