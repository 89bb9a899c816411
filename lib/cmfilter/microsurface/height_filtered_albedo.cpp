// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/height_filtered_albedo.h"

#include "cmfilter/microsurface/height_color.h"
#include "cmfilter/microsurface/height_filtering.h"
#include "cmfilter/math/normal_distribution.h"
#include "cmfilter/microsurface/smith_lambda.h"

#include <cmath>

namespace cmfilter {

double resolved_visibility(double height, double sigma_r, double lambda)
{
    if (!(lambda > 0) || !(sigma_r > 0)) return 1;
    const double log_phi = log_normal_cdf(height / sigma_r);
    if (std::isinf(lambda)) return log_phi < 0 ? 0.0 : 1.0;
    return std::exp(lambda * log_phi);  // eq. 2
}

MicrosurfaceVisibility microsurface_visibility(const MicrosurfaceFootprint& footprint, const HeightDirections& d,
                                               MaskingShadowing masking)
{
    MicrosurfaceVisibility v;
    // Smith's Lambda (eq. 3) for the unresolved slopes along each azimuth.
    v.lambda_o = smith_lambda_gaussian(d.theta_o, footprint.sigma_s(d.phi_o));
    v.lambda_i = smith_lambda_gaussian(d.theta_i, footprint.sigma_s(d.phi_i));
    v.lambda_sum = lambda_sum(v.lambda_o, v.lambda_i, d.phi_o - d.phi_i, masking);
    v.visibility = mean_visibility(v.lambda_o, v.lambda_i, d.phi_o - d.phi_i, masking);  // eq. 13
    v.resolved_visibility = resolved_visibility(footprint.mean_height, footprint.resolved_sigma_h,
                                                smith_lambda_gaussian(d.theta_i, footprint.resolved_sigma_s(d.phi_i)));
    return v;
}

HeightAlbedo height_filtered_albedo(const ColorLayer& heights, const MicrosurfaceFootprint& footprint,
                                    const HeightDirections& d, HeightRepresentation representation,
                                    const HeightMomentTable& table, AlbedoCounts& counts, MaskingShadowing masking)
{
    HeightAlbedo out;
    if (representation == HeightRepresentation::Naive) {
        out.albedo = heights.map.evaluate(footprint.mean_height);
        out.colour = out.albedo;
        out.mean = footprint.mean_height;
        return out;
    }
    const MicrosurfaceVisibility visibility = microsurface_visibility(footprint, d, masking);
    out.lambda_sum = visibility.lambda_sum;
    out.visibility = visibility.visibility;
    out.resolved_visibility = visibility.resolved_visibility;
    const double v = visibility.total();
    if (representation == HeightRepresentation::Exact) {
        // eq. 14: V <C_h, D_h>, D_h exactly (eq. 16).
        const HeightMoments moments = exact_height_moments(out.lambda_sum, footprint.sigma_h);
        out.mean = footprint.mean_height + moments.mean;
        out.sigma = moments.sigma;
        out.colour = exact_height_color(heights.map, footprint.sigma_h, out.lambda_sum, footprint.mean_height);
        out.albedo = v * out.colour;
        return out;
    }
    const HeightMoments moments = representation == HeightRepresentation::PaperFit
                                      ? paper_height_fit(out.lambda_sum, footprint.sigma_h)  // eqs. 17-18
                                      : table.lookup(out.lambda_sum, footprint.sigma_h);
    out.mean = footprint.mean_height + moments.mean;
    out.sigma = moments.sigma;
    out.colour = gaussian_albedo(heights, out.mean, out.sigma, counts);  // eq. 10
    out.albedo = v * out.colour;                                         // eq. 14
    return out;
}

}  // namespace cmfilter
