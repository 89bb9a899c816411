// SPDX-License-Identifier: Apache-2.0
// Entry point of cmfilter_relight.glsl (the numerical check on llvmpipe and
// the source of its HLSL). Point k: (lu, lv, lw, texel index); result k: the
// fit's value there.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "cmfilter_relight.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2DArray coefficients;  // one layer per coefficient
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; } points_in;
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; } results_out;
layout(std430, binding = 2) readonly buffer Parameters {
    int model;     // cmfilter:model: CMF_PTM_RGB, CMF_PTM_LRGB, CMF_HSH2, CMF_HSH3
    int channels;  // cmfilter:channels
    int width;     // the fit's width
    int count;
} parameters;

void main()
{
    uint k = gl_GlobalInvocationID.x;
    if (k >= uint(parameters.count)) return;
    vec4 p = points_in.points[k];
    int t = int(p.w);
    results_out.results[k] = vec4(cmf_relight(coefficients, parameters.model, parameters.channels, ivec2(t % parameters.width, t / parameters.width), p.xyz), 0.0);
}
