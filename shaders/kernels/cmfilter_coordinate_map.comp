// SPDX-License-Identifier: Apache-2.0
// Entry point of cmfilter_coordinate_map.glsl (the numerical check on
// llvmpipe and the source of its HLSL). Point k: (i, j, L, unused), an
// output texel at LOD L; results 4k .. 4k + 3: the full-size output at
// texel (i, j), then texel (i, j) at LOD L by `levels`, `point` and
// `patches`.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "cmfilter_bilinear.glsl"
#include "cmfilter_coordinate_map.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform isampler2D coordinate_map;    // the map's levels, stacked
layout(binding = 1) uniform sampler2D sample_pyramid;     // the sample's pyramid, stacked (level 0 first)
layout(binding = 2) uniform sampler2DArray patch_levels;  // patch levels 1 .., stacked; layer k: entry k
layout(binding = 3) uniform sampler2D sample_sums;        // the sample's summed-area table, (W + 1) x (H + 1)
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; } points_in;
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; } results_out;
layout(std430, binding = 2) readonly buffer Parameters {
    CmfPatchLevels patches;
    CmfCoordinateMap map;
    int count;
} parameters;

void main()
{
    uint k = gl_GlobalInvocationID.x;
    if (k >= uint(parameters.count)) return;
    vec4 point = points_in.points[k];
    ivec2 texel = ivec2(point.xy);
    int lod = int(point.z);
    CmfCoordinateMap m = parameters.map;
    results_out.results[4 * k] = cmf_through_coordinate_map(coordinate_map, sample_pyramid, texel);
    results_out.results[4 * k + 1] = cmf_coordinate_map_levels(coordinate_map, sample_pyramid, m, texel, lod);
    results_out.results[4 * k + 2] = cmf_coordinate_map_point(coordinate_map, sample_pyramid, m, texel, lod);
    results_out.results[4 * k + 3] = cmf_coordinate_map_patches(coordinate_map, sample_pyramid, patch_levels,
                                                                sample_sums, m, parameters.patches, texel, lod);
}
