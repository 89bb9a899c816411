// SPDX-License-Identifier: Apache-2.0
// cmfilter_bilinear.glsl: bilinear interpolation between texel centres from
// four texelFetch reads, as the library's bilinear_texels.h (OpenImageIO's
// InterpBilinear inside one level): a block of w x h texels with texel
// (x, y) centred at ((x + 0.5) / w, (y + 0.5) / h), (0, 0) the block's first
// texel (its first row in file order: t grows down the image). Beyond the
// block the texels continue by clamping (the edge texels) or periodically.
// The block may be part of a larger texture (a level of a stacked pyramid,
// cmfilter_coordinate_map.glsl): `origin` is its first texel there. A
// function library: no #version, no main.

#ifndef CMFILTER_BILINEAR_GLSL
#define CMFILTER_BILINEAR_GLSL

// floor(a / n) for n > 0 (GLSL leaves / and % of negative integers
// undefined, so both operands are kept >= 0).
int cmf_floor_divide(int a, int n) { return a >= 0 ? a / n : -((n - 1 - a) / n); }

// Texel index i along an axis of n texels (the library's wrap_texel): i
// inside [0, n); beyond, the nearest edge texel or i mod n.
int cmf_wrap_texel(int i, int n, bool periodic)
{
    if (i >= 0 && i < n) return i;
    if (periodic) return i - n * cmf_floor_divide(i, n);
    return i < 0 ? 0 : n - 1;
}

// A coordinate brought near the block first, where texel indices fit an
// int: by whole repeats (periodic), else into [-1, 2], beyond which every
// neighbour is the same edge texel. Not finite: 0, as the library reads it.
float cmf_near_block(float s, bool periodic)
{
    if (isnan(s) || isinf(s)) return 0.0;
    return periodic ? s - floor(s) : clamp(s, -1.0, 2.0);
}

// The block interpolated at normalised coordinates st: two lerps along s,
// then one along t, each skipped where its weight is 0 (so that a texel
// centre reads its texel exactly).
vec4 cmf_bilinear_texels(sampler2D image, ivec2 origin, ivec2 size, vec2 st, bool periodic)
{
    vec2 p = vec2(cmf_near_block(st.x, periodic), cmf_near_block(st.y, periodic)) * vec2(size) - 0.5;
    vec2 f = floor(p);
    vec2 a = p - f;
    int x0 = cmf_wrap_texel(int(f.x), size.x, periodic), x1 = cmf_wrap_texel(int(f.x) + 1, size.x, periodic);
    int y0 = cmf_wrap_texel(int(f.y), size.y, periodic), y1 = cmf_wrap_texel(int(f.y) + 1, size.y, periodic);
    vec4 top = texelFetch(image, origin + ivec2(x0, y0), 0);
    if (a.x > 0.0) top += a.x * (texelFetch(image, origin + ivec2(x1, y0), 0) - top);
    if (!(a.y > 0.0)) return top;
    vec4 bottom = texelFetch(image, origin + ivec2(x0, y1), 0);
    if (a.x > 0.0) bottom += a.x * (texelFetch(image, origin + ivec2(x1, y1), 0) - bottom);
    return top + a.y * (bottom - top);
}

#endif  // CMFILTER_BILINEAR_GLSL
