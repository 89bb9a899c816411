// SPDX-License-Identifier: Apache-2.0
// Entry point of cmfilter_slope.glsl (the numerical check on llvmpipe and
// the source of its HLSL). Point k: 3 vec4s, (mean x, mean y, theta, phi),
// (xx, xy, yy, unused) and (a slope x, y, unused, unused); results 5k: D_s's
// mean (x, y) and (xx, xy); 5k + 1: (yy, the Gaussian slope colour's RGB by
// the steepness map); 5k + 2: the same by the slope-vector map (RGB, 0);
// 5k + 3 and 5k + 4: the slope-vector map at the third vec4's slope,
// texelFetch then sampler (RGB, 0).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "cmfilter_color_table.glsl"
#include "cmfilter_height.glsl"
#include "cmfilter_bilinear.glsl"
#include "cmfilter_slope.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D steepness_map;     // C_s over the slope angle in degrees, n x 1
layout(binding = 1) uniform sampler2D slope_vector_map;  // C_s over [-s_max, s_max]^2
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; } points_in;
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; } results_out;
layout(std430, binding = 2) readonly buffer Parameters {
    float domain_min, domain_max;  // the steepness map's domain, degrees
    int wrap;                      // its wrap: CMF_WRAP_*
    float s_max;                   // the slope-vector map's s_max
    int hermite_points;            // <= CMF_MAX_HERMITE_POINTS
    float nodes[CMF_MAX_HERMITE_POINTS];
    float weights[CMF_MAX_HERMITE_POINTS];
    int count;
} parameters;

void main()
{
    uint k = gl_GlobalInvocationID.x;
    if (k >= uint(parameters.count)) return;
    vec4 a = points_in.points[3 * k], b = points_in.points[3 * k + 1], lookup = points_in.points[3 * k + 2];
    CmfSlopeGaussian s;
    s.mean = a.xy;
    s.xx = b.x;
    s.xy = b.y;
    s.yy = b.z;
    CmfSlopeGaussian m = cmf_slope_filtering_moments(s, a.z, a.w);
    // The rule element by element: spirv-cross's HLSL for a whole-array load
    // from a storage buffer does not compile.
    float nodes[CMF_MAX_HERMITE_POINTS], weights[CMF_MAX_HERMITE_POINTS];
    for (int i = 0; i < CMF_MAX_HERMITE_POINTS; ++i) {
        nodes[i] = parameters.nodes[i];
        weights[i] = parameters.weights[i];
    }
    CmfSlopeMap steepness = CmfSlopeMap(CMF_SLOPE_MAP_STEEPNESS, parameters.domain_min, parameters.domain_max,
                                        parameters.wrap, 0.0);
    CmfSlopeMap vector_map = CmfSlopeMap(CMF_SLOPE_MAP_VECTOR, 0.0, 0.0, CMF_WRAP_CLAMP, parameters.s_max);
    int n = parameters.hermite_points;
    vec3 by_steepness = cmf_gaussian_slope_color(steepness_map, steepness, s, a.z, a.w, n, nodes, weights);
    vec3 by_vector = cmf_gaussian_slope_color(slope_vector_map, vector_map, s, a.z, a.w, n, nodes, weights);
    results_out.results[5 * k] = vec4(m.mean, m.xx, m.xy);
    results_out.results[5 * k + 1] = vec4(m.yy, by_steepness);
    results_out.results[5 * k + 2] = vec4(by_vector, 0.0);
    vec3 fetched = cmf_slope_vector_color_exact(slope_vector_map, parameters.s_max, lookup.xy);
    vec3 sampled = cmf_slope_vector_color(slope_vector_map, parameters.s_max, lookup.xy);
    results_out.results[5 * k + 3] = vec4(fetched, 0.0);
    results_out.results[5 * k + 4] = vec4(sampled, 0.0);
}
