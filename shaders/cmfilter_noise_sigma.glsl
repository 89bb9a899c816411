// SPDX-License-Identifier: Apache-2.0
// cmfilter_noise_sigma.glsl: the noise sigma table of `cmfilter bake-noise`
// (Heitz et al. 2013, sec. 4.2: "For procedural functions such as Perlin
// noise, we precompute the noise standard deviation for different levels of
// detail and store it in a 1D texture"; docs/bake-noise.md). sigma(L) is
// sampled at L_k = lod_first + k lod_step, interpolated linearly in L and
// held at the end values beyond; L = log2(footprint width / base period).
// A function library: no #version, no main.
//
// Uploading. The table EXR is one row of cmfilter:lods texels with channels
// box_sigma, gaussian_sigma, box_ci, gaussian_ci: upload it as a lods x 1
// GL_RGBA32F texture in that channel order (R = box, G = Gaussian
// footprints), GL_LINEAR, GL_CLAMP_TO_EDGE, no mipmaps. Node k's centre is at
// s = (k + 0.5) / lods.

#ifndef CMFILTER_NOISE_SIGMA_GLSL
#define CMFILTER_NOISE_SIGMA_GLSL

// Which column of the table: the footprint's shape (docs/bake-noise.md).
const int CMF_FOOTPRINT_BOX = 0;       // channel box_sigma
const int CMF_FOOTPRINT_GAUSSIAN = 1;  // channel gaussian_sigma

struct CmfNoiseSigmaTable {
    float lod_first;    // cmfilter:lod_first
    float lod_step;     // cmfilter:lod_step
    float base_period;  // cmfilter:base_period: p_0, LOD 0 is one base period
    int lods;           // cmfilter:lods (texture width)
};

// L = log2(w / p_0) for a footprint of width w in noise units.
float cmf_noise_lod(CmfNoiseSigmaTable t, float footprint_width)
{
    return log2(footprint_width / t.base_period);
}

// The continuous node index of L, clamped to [0, lods - 1].
float cmf_noise_sigma_node(CmfNoiseSigmaTable t, float lod)
{
    return clamp((lod - t.lod_first) / t.lod_step, 0.0, float(t.lods - 1));
}

// sigma(L) through the hardware's linear filter. NaN L gives NaN.
float cmf_noise_sigma(sampler2D table, CmfNoiseSigmaTable t, int shape, float lod)
{
    if (isnan(lod)) return lod;
    vec2 s = textureLod(table, vec2((cmf_noise_sigma_node(t, lod) + 0.5) / float(t.lods), 0.5), 0.0).rg;
    return shape == CMF_FOOTPRINT_GAUSSIAN ? s.y : s.x;
}

// sigma(L) interpolated in the shader from texelFetch: the library's
// NoiseSigmaTable::sigma_at to float rounding.
float cmf_noise_sigma_exact(sampler2D table, CmfNoiseSigmaTable t, int shape, float lod)
{
    if (isnan(lod)) return lod;
    float u = cmf_noise_sigma_node(t, lod);
    int k = min(int(u), max(t.lods - 2, 0));
    float f = t.lods > 1 ? u - float(k) : 0.0;
    vec2 a = texelFetch(table, ivec2(k, 0), 0).rg;
    vec2 b = texelFetch(table, ivec2(min(k + 1, t.lods - 1), 0), 0).rg;
    vec2 s = a + f * (b - a);
    return shape == CMF_FOOTPRINT_GAUSSIAN ? s.y : s.x;
}

#endif  // CMFILTER_NOISE_SIGMA_GLSL
