// SPDX-License-Identifier: Apache-2.0
// Entry point of cmfilter_slope.glsl (the numerical check on llvmpipe and
// the source of its HLSL). Point k: 2 vec4s, (mean x, mean y, theta, phi)
// and (xx, xy, yy, unused); results 2k: D_s's mean (x, y) and (xx, xy);
// 2k + 1: (yy, the Gaussian slope colour's RGB).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "cmfilter_color_table.glsl"
#include "cmfilter_height.glsl"
#include "cmfilter_slope.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D steepness_map;  // C_s over the slope angle in degrees, n x 1
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; } points_in;
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; } results_out;
layout(std430, binding = 2) readonly buffer Parameters {
    float domain_min, domain_max;  // the steepness map's domain, degrees
    int wrap;                      // its wrap: CMF_WRAP_*
    int hermite_points;            // <= CMF_MAX_HERMITE_POINTS
    float nodes[CMF_MAX_HERMITE_POINTS];
    float weights[CMF_MAX_HERMITE_POINTS];
    int count;
} parameters;

void main()
{
    uint k = gl_GlobalInvocationID.x;
    if (k >= uint(parameters.count)) return;
    vec4 a = points_in.points[2 * k], b = points_in.points[2 * k + 1];
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
    vec3 colour = cmf_gaussian_slope_color(steepness_map, parameters.domain_min, parameters.domain_max,
                                           parameters.wrap, s, a.z, a.w, parameters.hermite_points, nodes, weights);
    results_out.results[2 * k] = vec4(m.mean, m.xx, m.xy);
    results_out.results[2 * k + 1] = vec4(m.yy, colour);
}
