// SPDX-License-Identifier: Apache-2.0
// cmfilter_color_table.glsl: the colour map C0 (Heitz et al. 2013, sec. 4)
// and the prefiltered Gaussian colour table of eq. 10,
//     T(v, sigma) = (C0 * N(0, sigma^2))(v),
// as written by `cmfilter bake-colormap` (docs/table-format.md). A function
// library: no #version, no main; include it after `#version 450`.
//
// Texel centres. A texture of N texels has texel i's centre at
// (i + 0.5) / N, not at i / (N - 1). A lookup that maps the first node to
// coordinate 0 and the last to 1 reads half a texel off at each end and
// drifts by up to half a texel across the axis (the "gradient map sampled at
// texel edges" bug of three.js issue 14558). Every coordinate below is
// (node index + 0.5) / texels.
//
// Uploading. The table EXR is values x sigmas texels of RGB float: upload it
// as GL_RGB32F (or RGBA32F) with rows in file order, row 0 (sigma = 0) first,
// so that t = 0 is sigma = 0; no flip. Sampler: GL_LINEAR min and mag, no
// mipmaps; wrap T (sigma) GL_CLAMP_TO_EDGE; wrap S (value) GL_REPEAT for
// `cmfilter:wrap = repeat`, GL_CLAMP_TO_EDGE otherwise. The *_exact variants
// read texels with texelFetch and interpolate in the shader, so they ignore
// the sampler and reproduce the library's lookup to float rounding (GPUs
// filter with 8-bit fractional weights; see docs/shaders.md).

#ifndef CMFILTER_COLOR_TABLE_GLSL
#define CMFILTER_COLOR_TABLE_GLSL

// cmfilter:wrap ("clamp", "mirror", "repeat").
const int CMF_WRAP_CLAMP = 0;
const int CMF_WRAP_MIRROR = 1;
const int CMF_WRAP_REPEAT = 2;
// cmfilter:sigma_spacing ("linear", "sqrt").
const int CMF_SIGMA_LINEAR = 0;
const int CMF_SIGMA_SQRT = 1;

// The table's axes, one field per metadata key of the table file.
struct CmfColorTable {
    float domain_min;   // cmfilter:domain_min
    float domain_max;   // cmfilter:domain_max
    float value_first;  // cmfilter:value_first (value of column 0)
    float value_last;   // cmfilter:value_last (value of column values - 1)
    float sigma_max;    // cmfilter:sigma_max
    int values;         // cmfilter:values (texture width)
    int sigmas;         // cmfilter:sigmas (texture height)
    int wrap;           // cmfilter:wrap: CMF_WRAP_*
    int sigma_spacing;  // cmfilter:sigma_spacing: CMF_SIGMA_*
};

// The colour map C0 (sec. 4) as a 1-D lookup: the map's n texels over the
// driver domain [domain_min, domain_max], texel i at
// domain_min + (i + 0.5) (domain_max - domain_min) / n, linear between
// texel centres, continued by the wrap (clamp: end colours; repeat: periodic;
// mirror: reflected). This is the `naive` method's C(mean f). The map is an
// n x 1 texture (the gradient's row or column, scene-linear); wrap S
// GL_CLAMP_TO_EDGE, GL_REPEAT or GL_MIRRORED_REPEAT as `wrap` says, GL_LINEAR.
float cmf_color_map_coordinate(float v, float domain_min, float domain_max)
{
    return (v - domain_min) / (domain_max - domain_min);  // texel centres already at (i + 0.5) / n
}

vec3 cmf_color_map(sampler2D map, float domain_min, float domain_max, float v)
{
    return textureLod(map, vec2(cmf_color_map_coordinate(v, domain_min, domain_max), 0.5), 0.0).rgb;
}

// The same interpolated in the shader from texelFetch (library's
// ColorMap::evaluate to float rounding, whatever the sampler).
vec3 cmf_color_map_exact(sampler2D map, float domain_min, float domain_max, int wrap, float v)
{
    int n = textureSize(map, 0).x;
    float x = cmf_color_map_coordinate(v, domain_min, domain_max) * float(n) - 0.5;  // node coordinate
    if (isnan(x)) return texelFetch(map, ivec2(0, 0), 0).rgb;
    if (wrap == CMF_WRAP_CLAMP) {
        if (!(x > 0.0)) return texelFetch(map, ivec2(0, 0), 0).rgb;
        if (x >= float(n - 1)) return texelFetch(map, ivec2(n - 1, 0), 0).rgb;
    } else {
        if (isinf(x)) return texelFetch(map, ivec2(0, 0), 0).rgb;
        float period = wrap == CMF_WRAP_REPEAT ? float(n) : 2.0 * float(n);
        x -= period * floor(x / period);
    }
    float k = floor(x);
    float t = x - k;
    int k0 = int(k), k1 = k0 + 1;
    // Node k stands for texel k mod n (repeat) or its reflection (mirror).
    if (wrap == CMF_WRAP_REPEAT) {
        k0 = k0 % n;
        k1 = k1 % n;
    } else if (wrap == CMF_WRAP_MIRROR) {
        k0 = k0 % (2 * n);
        k1 = k1 % (2 * n);
        k0 = k0 < n ? k0 : 2 * n - 1 - k0;
        k1 = k1 < n ? k1 : 2 * n - 1 - k1;
    }
    vec3 a = texelFetch(map, ivec2(k0, 0), 0).rgb;
    vec3 b = texelFetch(map, ivec2(k1, 0), 0).rgb;
    return (1.0 - t) * a + t * b;
}

// Reflects v into [domain_min, domain_max] (mirror wrap; T is symmetric
// about both ends of the domain).
float cmf_mirror_into_domain(float v, float domain_min, float domain_max)
{
    float period = domain_max - domain_min;
    float m = mod(v - domain_min, 2.0 * period);  // GLSL mod: x - y floor(x / y), in [0, 2 period)
    return domain_min + (m <= period ? m : 2.0 * period - m);
}

// The table's continuous node coordinates (column x in [0, values), row y
// in [0, sigmas - 1]) for a footprint's mean and sigma: docs/table-format.md,
// "Looking it up". sigma < 0 reads as 0, sigma > sigma_max as sigma_max.
vec2 cmf_color_table_nodes(CmfColorTable t, float mean, float sigma)
{
    float u = clamp(max(sigma, 0.0) / t.sigma_max, 0.0, 1.0);
    if (t.sigma_spacing == CMF_SIGMA_SQRT) u = sqrt(u);
    float y = u * float(t.sigmas - 1);
    float x;
    if (t.wrap == CMF_WRAP_REPEAT) {
        float period = t.domain_max - t.domain_min;
        x = mod(mean - t.domain_min, period) / period * float(t.values);
        if (x >= float(t.values)) x = 0.0;
    } else {
        float v = t.wrap == CMF_WRAP_MIRROR ? cmf_mirror_into_domain(mean, t.domain_min, t.domain_max)
                                            : clamp(mean, t.value_first, t.value_last);
        x = clamp((v - t.value_first) / (t.value_last - t.value_first) * float(t.values - 1), 0.0,
                  float(t.values - 1));
    }
    return vec2(x, y);
}

// Texture coordinates of T(mean, sigma) for a GL_LINEAR sampler: node
// (x, y) sits at the texel centre ((x + 0.5) / values, (y + 0.5) / sigmas).
vec2 cmf_color_table_uv(CmfColorTable t, float mean, float sigma)
{
    vec2 node = cmf_color_table_nodes(t, mean, sigma);
    return (node + 0.5) / vec2(t.values, t.sigmas);
}

bool cmf_color_table_invalid(CmfColorTable t, float mean, float sigma)
{
    return isnan(mean) || isnan(sigma) || (t.wrap != CMF_WRAP_CLAMP && isinf(mean));
}

// T(mean, sigma) of eq. 10 through the hardware's bilinear filter. NaN
// mean or sigma (or an infinite mean with a periodic wrap) gives black, as
// the library's lookup does.
vec3 cmf_color_table(sampler2D table, CmfColorTable t, float mean, float sigma)
{
    if (cmf_color_table_invalid(t, mean, sigma)) return vec3(0.0);
    return textureLod(table, cmf_color_table_uv(t, mean, sigma), 0.0).rgb;
}

// T(mean, sigma) of eq. 10 with the bilinear interpolation done in the
// shader from four texelFetch reads: the library's GaussianColorTable::lookup
// to float rounding.
vec3 cmf_color_table_exact(sampler2D table, CmfColorTable t, float mean, float sigma)
{
    if (cmf_color_table_invalid(t, mean, sigma)) return vec3(0.0);
    vec2 node = cmf_color_table_nodes(t, mean, sigma);
    int i0, i1;
    if (t.wrap == CMF_WRAP_REPEAT) {
        i0 = min(int(node.x), t.values - 1);
        i1 = i0 + 1 == t.values ? 0 : i0 + 1;  // column values - 1 interpolates towards column 0
    } else {
        i0 = min(int(node.x), t.values - 2);
        i1 = i0 + 1;
    }
    int j0 = min(int(node.y), t.sigmas - 2);
    float fx = node.x - float(i0), fy = node.y - float(j0);
    vec3 a = texelFetch(table, ivec2(i0, j0), 0).rgb, b = texelFetch(table, ivec2(i1, j0), 0).rgb;
    vec3 c = texelFetch(table, ivec2(i0, j0 + 1), 0).rgb, d = texelFetch(table, ivec2(i1, j0 + 1), 0).rgb;
    vec3 top = a + fx * (b - a), bottom = c + fx * (d - c);
    return top + fy * (bottom - top);
}

#endif  // CMFILTER_COLOR_TABLE_GLSL
