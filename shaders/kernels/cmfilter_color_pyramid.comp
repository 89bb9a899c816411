// SPDX-License-Identifier: Apache-2.0
// Entry point of cmfilter_color_pyramid.glsl (the numerical check on
// llvmpipe and the source of its HLSL). Point k: (s, t, lod, w); result 2k:
// (r, g, b, unused) at lod; result 2k + 1: the same over the square footprint
// of side w (texture units) through textureGrad.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "cmfilter_color_pyramid.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D colors;  // the pyramid, its levels as MIP levels
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; } points_in;
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; } results_out;
layout(std430, binding = 2) readonly buffer Parameters {
    CmfColorPyramid pyramid;
    int count;
} parameters;

void main()
{
    uint k = gl_GlobalInvocationID.x;
    if (k >= uint(parameters.count)) return;
    vec4 p = points_in.points[k];
    results_out.results[2 * k] = vec4(cmf_color_pyramid(colors, parameters.pyramid, p.xy, p.z), 0.0);
    results_out.results[2 * k + 1] = vec4(cmf_color_pyramid_grad(colors, p.xy, vec2(p.w, 0.0), vec2(0.0, p.w)), 0.0);
}
