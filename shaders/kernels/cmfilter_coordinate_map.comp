// SPDX-License-Identifier: Apache-2.0
// Entry point of cmfilter_coordinate_map.glsl (the numerical check on
// llvmpipe and the source of its HLSL). Point k: (x, y, unused, unused), an
// output texel; result k: the output there.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "cmfilter_coordinate_map.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform isampler2D coordinate_map;  // level 0 of the map
layout(binding = 1) uniform sampler2D sample_image;     // the sample
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; } points_in;
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; } results_out;
layout(std430, binding = 2) readonly buffer Parameters { int count; } parameters;

void main()
{
    uint k = gl_GlobalInvocationID.x;
    if (k >= uint(parameters.count)) return;
    results_out.results[k] = cmf_through_coordinate_map(coordinate_map, sample_image, ivec2(points_in.points[k].xy));
}
