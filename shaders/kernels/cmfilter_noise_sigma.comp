// SPDX-License-Identifier: Apache-2.0
// Entry point of cmfilter_noise_sigma.glsl (the numerical check on llvmpipe
// and the source of its HLSL). Point k: (LOD, footprint width, unused,
// unused); result 2k: sigma(LOD) box and Gaussian through the sampler, then
// exact; result 2k + 1: (LOD of the width, unused...).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "cmfilter_noise_sigma.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D sigma_table;  // the table EXR, one row
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; } points_in;
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; } results_out;
layout(std430, binding = 2) readonly buffer Parameters {
    CmfNoiseSigmaTable table;
    int count;
} parameters;

void main()
{
    uint k = gl_GlobalInvocationID.x;
    if (k >= uint(parameters.count)) return;
    float lod = points_in.points[k].x;
    results_out.results[2 * k] = vec4(cmf_noise_sigma(sigma_table, parameters.table, CMF_FOOTPRINT_BOX, lod),
                          cmf_noise_sigma(sigma_table, parameters.table, CMF_FOOTPRINT_GAUSSIAN, lod),
                          cmf_noise_sigma_exact(sigma_table, parameters.table, CMF_FOOTPRINT_BOX, lod),
                          cmf_noise_sigma_exact(sigma_table, parameters.table, CMF_FOOTPRINT_GAUSSIAN, lod));
    results_out.results[2 * k + 1] = vec4(cmf_noise_lod(parameters.table, points_in.points[k].y), 0.0, 0.0, 0.0);
}
