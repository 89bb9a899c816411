// SPDX-License-Identifier: Apache-2.0
// Entry point of cmfilter_height.glsl (the numerical check on llvmpipe and
// the source of its HLSL). Point k: 2 vec4s, (theta_o, theta_i, sigma_s,
// azimuth difference) and (h, sigma_h, Lambda for eq. 2, Lambda sum L);
// results 4k .. 4k + 3:
//   (Lambda_o, Lambda_i, L uncorrelated, L correlated),
//   (V uncorrelated, V correlated, eq. 2's visibility, ln Phi(h / sigma_h)),
//   (fit mu_d, fit sigma_d, table mean, table sigma) for L and sigma_h,
//   the height colour V T(h + mu_d, sigma_d) with the table's moments and V = eq. 2's.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "cmfilter_color_table.glsl"
#include "cmfilter_height.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D height_moments;  // HeightMomentTable nodes, RG
layout(binding = 1) uniform sampler2D color_table;     // the height colour map's table
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; } points_in;
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; } results_out;
layout(std430, binding = 2) readonly buffer Parameters {
    CmfColorTable table;
    float s_max;  // ln(1 + max Lambda sum) of the height moment table
    int count;
} parameters;

void main()
{
    uint k = gl_GlobalInvocationID.x;
    if (k >= uint(parameters.count)) return;
    vec4 a = points_in.points[2 * k], b = points_in.points[2 * k + 1];
    float lo = cmf_smith_lambda(a.x, a.z), li = cmf_smith_lambda(a.y, a.z);
    results_out.results[4 * k + 0] = vec4(lo, li, cmf_lambda_sum(lo, li, a.w, CMF_UNCORRELATED),
                              cmf_lambda_sum(lo, li, a.w, CMF_DIRECTION_CORRELATED));
    float v = cmf_smith_height_visibility(b.x, b.y, b.z);
    results_out.results[4 * k + 1] = vec4(cmf_mean_visibility(lo, li, a.w, CMF_UNCORRELATED),
                              cmf_mean_visibility(lo, li, a.w, CMF_DIRECTION_CORRELATED), v,
                              cmf_log_normal_cdf(b.x / b.y));
    vec2 moments = cmf_height_moments_table(height_moments, parameters.s_max, b.w, b.y);
    results_out.results[4 * k + 2] = vec4(cmf_height_fit(b.w, b.y), moments);
    results_out.results[4 * k + 3] = vec4(cmf_height_color(color_table, parameters.table, b.x, moments, v), 0.0);
}
