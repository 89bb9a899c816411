// SPDX-License-Identifier: Apache-2.0
// cmfilter_color_pyramid.glsl: the colour pyramid of `cmfilter bake-moments
// --method color-pyramid` (texture/color_pyramid_file.h): the box mean of
// C0(f) over each texel's footprint at every MIP level, baked for one colour
// map. The filtered colour is one texture read: no moments, no colour table
// (the exact answer for a box filter, sec. 3, eq. 1, where the map is fixed).
// A function library: no #version, no main.
//
// Uploading. The EXR's MIP level k (subimage 0) is MIP level k of a
// GL_RGB32F (or GL_RGB16F for a half file) texture, rows in file order (row
// 0, the top row, first), so that (s, t) are the library's: (0, 0) the
// top-left corner, t downwards. Set GL_TEXTURE_MAX_LEVEL to cmfilter:levels
// - 1 and never call glGenerateMipmap (means of means for sizes that are not
// powers of two). Sampler: GL_LINEAR_MIPMAP_LINEAR min, GL_LINEAR mag; wrap
// from cmfilter:wrap (clamp -> GL_CLAMP_TO_EDGE, periodic -> GL_REPEAT,
// black -> GL_CLAMP_TO_BORDER, black border). The colours are scene-linear
// in cmfilter:linear_space: no sRGB texture format.

#ifndef CMFILTER_COLOR_PYRAMID_GLSL
#define CMFILTER_COLOR_PYRAMID_GLSL

struct CmfColorPyramid {
    int levels;  // cmfilter:levels: floor(log2(max(W, H))) + 1
};

// Trilinear lookup at level of detail lod, the library's
// ColorPyramidTexture::lookup(s, t, lod): integer lod reads level lod alone
// (bilinear), fractional lod blends levels floor(lod) and floor(lod) + 1;
// lod is clamped to [0, levels - 1]. For a square footprint of width w
// level-0 texels, lod = log2(w) (box) or log2(w / sqrt(3)) to match a box's
// variance (texture_lod.h).
vec3 cmf_color_pyramid(sampler2D colors, CmfColorPyramid p, vec2 st, float lod)
{
    float l = isnan(lod) ? 0.0 : clamp(lod, 0.0, float(p.levels - 1));
    return textureLod(colors, st, l).rgb;
}

// Anisotropic lookup over the footprint spanned by the screen derivatives
// of (s, t): the GPU's own filter over the pyramid, as for any colour
// texture (the means stay means: every linear filter averages them).
vec3 cmf_color_pyramid_grad(sampler2D colors, vec2 st, vec2 dst_dx, vec2 dst_dy)
{
    return textureGrad(colors, st, dst_dx, dst_dy).rgb;
}

#endif
