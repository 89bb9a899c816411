// SPDX-License-Identifier: Apache-2.0
// Entry point of cmfilter_color_table.glsl: evaluates every function of the
// library over a buffer of points (the numerical check on llvmpipe,
// tests/shaders/, and the source of shaders/hlsl/cmfilter_color_table.hlsl).
// Point k: (mean, sigma, colour map value, unused); results 4k .. 4k + 3:
// T exact, T through the sampler, C0 exact, C0 through the sampler.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "cmfilter_color_table.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D color_table;  // the table EXR
layout(binding = 1) uniform sampler2D color_map;    // the colour map's texels, n x 1
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; } points_in;
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; } results_out;
layout(std430, binding = 2) readonly buffer Parameters {
    CmfColorTable table;
    int count;
} parameters;

void main()
{
    uint k = gl_GlobalInvocationID.x;
    if (k >= uint(parameters.count)) return;
    vec4 p = points_in.points[k];
    results_out.results[4 * k + 0] = vec4(cmf_color_table_exact(color_table, parameters.table, p.x, p.y), 0.0);
    results_out.results[4 * k + 1] = vec4(cmf_color_table(color_table, parameters.table, p.x, p.y), 0.0);
    results_out.results[4 * k + 2] = vec4(cmf_color_map_exact(color_map, parameters.table.domain_min, parameters.table.domain_max, parameters.table.wrap, p.z), 0.0);
    results_out.results[4 * k + 3] = vec4(cmf_color_map(color_map, parameters.table.domain_min, parameters.table.domain_max, p.z), 0.0);
}
