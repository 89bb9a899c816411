// SPDX-License-Identifier: Apache-2.0
// Entry point of cmfilter_segments.glsl (the numerical check on llvmpipe and
// the source of its HLSL). Point k: (s, t, lod, w); result 2k: (r, g, b,
// unused) at lod through the colours given; result 2k + 1: the same over the
// square footprint of side w (texture units) through textureGrad.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "cmfilter_segments.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2DArray ramps;  // the pyramid's channels, four a layer
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; } points_in;
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; } results_out;
layout(std430, binding = 2) readonly buffer Parameters {
    CmfSegments pyramid;
    int count;
    int unused;
    vec4 colors[CMF_SEGMENTS_MAX_CHANNELS + 1];  // C_k at the breakpoints (rgb)
} parameters;

void main()
{
    uint k = gl_GlobalInvocationID.x;
    if (k >= uint(parameters.count)) return;
    vec3 colors[CMF_SEGMENTS_MAX_CHANNELS + 1];
    for (int i = 0; i <= CMF_SEGMENTS_MAX_CHANNELS; ++i) colors[i] = parameters.colors[i].rgb;
    vec4 p = points_in.points[k];
    results_out.results[2 * k] = vec4(cmf_segments(ramps, parameters.pyramid, colors, p.xy, p.z), 0.0);
    results_out.results[2 * k + 1] =
        vec4(cmf_segments_grad(ramps, parameters.pyramid, colors, p.xy, vec2(p.w, 0.0), vec2(0.0, p.w)), 0.0);
}
