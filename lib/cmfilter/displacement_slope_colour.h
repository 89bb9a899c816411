// The slope-filtered colour <C_s, D_s> of eq. 20 (Heitz et al. 2013, sec.
// 5.2) on a textured displacement (displacement_texture.h), from its own
// slopes rather than a Gaussian: D_s is the distribution of the slopes over
// the footprint weighted by their visible projected area,
//     w(s) = max(0, cos t - sin t <s, d>)        (slope_filtering.h),
// so for slopes s_k sampled uniformly over the footprint
//     <C_s, D_s> ~ sum_k C_s(s_k) w(s_k) / sum_k w(s_k).
// The samples lie on a rank-2 Kronecker (golden-ratio) lattice over the
// parallelogram, c + (a_k - 1/2) e1 + (b_k - 1/2) e2 with (a_k, b_k) =
// frac((k + 1/2) (alpha1, alpha2)), alpha the plastic-number lattice: no
// period of the texture is commensurate with it, so a footprint of many
// repeats samples the whole pattern evenly; a point footprint samples its
// one slope. A textured relief's slopes are seldom Gaussian (scales: flat
// tops and steep rims), which a Gaussian D_s cannot represent, whatever its
// moments; this is the `exact` method's colour there. Where every slope is
// hidden (w = 0 throughout: at 90 degrees), the unweighted mean.
#pragma once

#include "cmfilter/color.h"
#include "cmfilter/displacement_texture.h"
#include "cmfilter/slope_color_map.h"
#include "cmfilter/slope_filtering.h"

namespace cmfilter {

struct DisplacementSlopeColourOptions {
    int samples = 4096;  // >= 1
};

// SlopeMap: SteepnessColorMap or SlopeVectorColorMap. The footprint: centre
// (u, v), edges (e1u, e1v) and (e2u, e2v), texture units.
template <typename SlopeMap>
Rgb displacement_slope_colour(const DisplacementTexture& texture, const SlopeMap& map, double u, double v,
                              double e1u, double e1v, double e2u, double e2v, const ViewAngles& view,
                              const DisplacementSlopeColourOptions& options = {});

extern template Rgb displacement_slope_colour(const DisplacementTexture&, const SteepnessColorMap&, double, double,
                                              double, double, double, double, const ViewAngles&,
                                              const DisplacementSlopeColourOptions&);
extern template Rgb displacement_slope_colour(const DisplacementTexture&, const SlopeVectorColorMap&, double, double,
                                              double, double, double, double, const ViewAngles&,
                                              const DisplacementSlopeColourOptions&);

}  // namespace cmfilter
