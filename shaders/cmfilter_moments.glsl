// SPDX-License-Identifier: Apache-2.0
// cmfilter_moments.glsl: the moment pyramid of `cmfilter bake-moments`
// (Heitz et al. 2013, sec. 4.2: "precompute the first two moments of f,
// mean f and mean f^2, at each level of detail in a mipmap hierarchy"; file
// layout in docs/moments-format.md), fetched at a level of detail and turned
// into the footprint's mean and standard deviation for the colour table
// T(mean, sigma) of eq. 10 (cmfilter_color_table.glsl). A function library:
// no #version, no main.
//
// Uploading. The EXR's MIP level k (subimage 0) is MIP level k of a GL_RG32F
// texture (channel m1 in R, m2 in G), rows in file order (row 0, the top row,
// first), so that texture coordinates (s, t) are the library's: (0, 0) the
// top-left corner, t downwards, texel x of level k centred at
// s = (x + 0.5) / w_k. Set GL_TEXTURE_MAX_LEVEL to cmfilter:levels - 1 and
// never call glGenerateMipmap (it would make means of means). Sampler:
// GL_LINEAR_MIPMAP_LINEAR min, GL_LINEAR mag; wrap from cmfilter:wrap:
// clamp -> GL_CLAMP_TO_EDGE, periodic -> GL_REPEAT, black ->
// GL_CLAMP_TO_BORDER with a zero border (m1 = m2 = 0: a point mass at
// f = reference). Linear filters only: bilinear, trilinear and anisotropic
// averages are means; bicubic is not.

#ifndef CMFILTER_MOMENTS_GLSL
#define CMFILTER_MOMENTS_GLSL

struct CmfMomentPyramid {
    float reference;  // cmfilter:reference: c, the moments are about f - c
    int levels;       // cmfilter:levels: L = floor(log2(max(W, H))) + 1
};

struct CmfMomentSample {
    float mean;      // c + m1
    float variance;  // max(0, m2 - m1^2)
    float sigma;     // sqrt(variance)
};

// Sec. 4.2: sigma_f^2 = mean (f - c)^2 - (mean (f - c))^2, clamped at 0
// (rounding makes it slightly negative where the footprint is constant).
CmfMomentSample cmf_moments_to_sample(CmfMomentPyramid p, vec2 m)
{
    CmfMomentSample s;
    s.mean = p.reference + m.x;
    s.variance = max(0.0, m.y - m.x * m.x);
    s.sigma = sqrt(s.variance);
    return s;
}

// Trilinear lookup at level of detail lod, the library's
// MomentTexture::lookup(s, t, lod): integer lod reads level lod alone
// (bilinear), fractional lod blends levels floor(lod) and floor(lod) + 1
// linearly; lod is clamped to [0, levels - 1] (a footprint beyond the
// pyramid reads its last level, the whole driver's mean and variance).
// For a square footprint of width w level-0 texels, lod = log2(w) (box) or
// log2(w / sqrt(3)) to match a box's variance (texture_lod.h).
CmfMomentSample cmf_moment_pyramid(sampler2D moments, CmfMomentPyramid p, vec2 st, float lod)
{
    float l = isnan(lod) ? 0.0 : clamp(lod, 0.0, float(p.levels - 1));
    return cmf_moments_to_sample(p, textureLod(moments, st, l).rg);
}

// Anisotropic lookup over the footprint spanned by the screen derivatives of
// (s, t), the hardware's own footprint (textureGrad; its anisotropic filter
// averages bilinear probes, so it stays a mean).
CmfMomentSample cmf_moment_pyramid_grad(sampler2D moments, CmfMomentPyramid p, vec2 st, vec2 dst_dx, vec2 dst_dy)
{
    return cmf_moments_to_sample(p, textureGrad(moments, st, dst_dx, dst_dy).rg);
}

#endif  // CMFILTER_MOMENTS_GLSL
