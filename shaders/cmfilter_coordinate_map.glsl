// SPDX-License-Identifier: Apache-2.0
// cmfilter_coordinate_map.glsl: rendering through a coordinate map of
// `cmfilter synth` (Tong et al. 2002 via the second paper's sec. 4.2, "Using
// large BTFs for rendering": a large surface stored as, per output texel,
// the sample texel it copies; docs/synthesis.md): one more texture lookup.
// A function library: no #version, no main.
//
// Uploading. Level l of the coordinate map EXR (channels x, y: sample texel
// indices, int32) is MIP level l of a GL_RG32I texture (rows in file order);
// the sample's pyramid level l is MIP level l of the sample texture, rows in
// file order. Integer textures are read with texelFetch only: a coordinate
// map is a driver, and averaging coordinates across a seam (what a mip or
// bilinear filter of the map does) lands in an unrelated part of the sample.

#ifndef CMFILTER_COORDINATE_MAP_GLSL
#define CMFILTER_COORDINATE_MAP_GLSL

// The full-size output's texel: the sample texel its coordinate names
// (the library's render_through_map).
vec4 cmf_through_coordinate_map(isampler2D map, sampler2D sample_image, ivec2 texel)
{
    ivec2 source = texelFetch(map, texel, 0).xy;
    return texelFetch(sample_image, source, 0);
}

#endif  // CMFILTER_COORDINATE_MAP_GLSL
