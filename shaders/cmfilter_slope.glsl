// SPDX-License-Identifier: Apache-2.0
// cmfilter_slope.glsl: slope-correlated colour (Heitz et al. 2013, sec. 5.2;
// docs/slope.md): the exact mean and covariance of the slope filtering
// distribution of eq. 20,
//     D_s(s) = max(0, cos t - sin t <s, d>) p(s) / Z,   s ~ N(m, Sigma),
// (the slopes a viewer at omega_o = (sin t cos p, sin t sin p, cos t) sees,
// weighted by their foreshortened area; d = (cos p, sin p)), and the
// slope colour <C_s, D_s> of eq. 20 with D_s replaced by the Gaussian of
// those moments (the paper's single Gaussian, fig. 9), integrated by a
// tensor Gauss-Hermite rule along the covariance's principal axes, for
// either kind of slope colour map C_s (slope_color_map.h): a steepness map
// (C_s by the slope angle atan |s| in degrees) or a slope-vector map (C_s
// by the 2-D slope). A function library: no #version, no main. Needs
// cmfilter_color_table.glsl (the colour map C0), cmfilter_height.glsl
// (erfc, erfcx) and cmfilter_bilinear.glsl before it.
//
// The Gauss-Hermite rule: the library's gauss_hermite_rule(n) (nodes z_i
// and weights w_i, summing to 1, for the standard normal; `render` uses
// n = 12), passed in as uniforms.
//
// Uploading. A steepness map: a ColorMap over [domain_min, domain_max]
// degrees, an n x 1 texture as for cmf_color_map. A slope-vector map: the
// image (`slope_map` of a scene's material, its `max_slope` s_max) as a
// GL_RGB32F texture of its width x height, rows in file order (row 0, the
// top, is s_y = +s_max; column 0 is s_x = -s_max), GL_LINEAR,
// GL_CLAMP_TO_EDGE on both axes, no mipmaps. Its texel (i, j) has its centre
// at s_x = -s_max + (i + 0.5) 2 s_max / width,
// s_y = s_max - (j + 0.5) 2 s_max / height; slopes steeper than the outer
// centres along an axis take the edge texels.

#ifndef CMFILTER_SLOPE_GLSL
#define CMFILTER_SLOPE_GLSL

const int CMF_MAX_HERMITE_POINTS = 16;

// Slopes s = grad h ~ N(mean, Sigma), Sigma = [[xx, xy], [xy, yy]]; also a
// mean and covariance of D_s in the same layout.
struct CmfSlopeGaussian {
    vec2 mean;
    float xx, xy, yy;
};

// D_s in the view's frame: u = <s, d>, v = <s, e>, e = (-sin p, cos p);
// v = mean_v + regression (u - mean_u) + r, r independent of u.
struct CmfSlopeViewFrame {
    float cos_theta, sin_theta;
    vec2 d;
    float mean_u, mean_v, sigma_u, regression, residual_variance;
};

CmfSlopeViewFrame cmf_slope_view_frame(CmfSlopeGaussian s, float theta, float phi)
{
    CmfSlopeViewFrame f;
    float t = isnan(theta) ? 0.0 : theta;
    f.cos_theta = 1.0;
    f.sin_theta = 0.0;
    if (t >= 0.5 * CMF_PI) {
        f.cos_theta = 0.0;
        f.sin_theta = 1.0;
    } else if (t > 0.0) {
        f.cos_theta = cos(t);
        f.sin_theta = sin(t);
    }
    float p = (isnan(phi) || isinf(phi)) ? 0.0 : phi;
    float c = cos(p), sn = sin(p);
    f.d = vec2(c, sn);
    float xx = max(0.0, s.xx), yy = max(0.0, s.yy);
    float bound = sqrt(xx * yy);
    float xy = clamp(s.xy, -bound, bound);
    f.mean_u = s.mean.x * c + s.mean.y * sn;
    f.mean_v = -s.mean.x * sn + s.mean.y * c;
    float uu = max(0.0, xx * c * c + 2.0 * xy * c * sn + yy * sn * sn);
    float uv = (yy - xx) * c * sn + xy * (c * c - sn * sn);
    float vv = max(0.0, xx * sn * sn - 2.0 * xy * c * sn + yy * c * c);
    f.sigma_u = sqrt(uu);
    f.regression = 0.0;
    f.residual_variance = vv;
    if (uu > 0.0) {
        f.regression = uv / uu;
        float residual = (xx * yy - xy * xy) / uu;  // det Sigma / d^T Sigma d
        f.residual_variance = residual >= 0.0 ? min(residual, vv) : 0.0;
    }
    return f;
}

// The standard normal z weighted by (k - z)_+ (docs/slope.md, steps 2-4):
// returns (shift, variance), shift = E[z] for k >= 0 and E[z] - k below.
vec2 cmf_clamped_linear_normal(float k)
{
    if (k >= 0.0) {
        if (isinf(k)) return vec2(0.0, 1.0);
        float h = sqrt(2.0 / CMF_PI) * exp(-0.5 * k * k) / cmf_erfc(-k / sqrt(2.0));
        float q1 = k + h;
        return vec2(-1.0 / q1, 1.0 + h / q1 - 1.0 / (q1 * q1));
    }
    float x = -k;
    if (isinf(x)) return vec2(0.0, 0.0);
    if (x < 3.0) {
        float R = sqrt(0.5 * CMF_PI) * cmf_erfcx(x / sqrt(2.0));  // the Mills ratio
        float h = 1.0 / R, q1 = h - x;
        return vec2(x - 1.0 / q1, 1.0 + h / q1 - 1.0 / (q1 * q1));
    }
    // q_n = n / (x + q_{n+1}) from 80 levels down (continued fraction).
    float tail = 0.0, q3 = 0.0, q4 = 0.0;
    for (int n = 80; n >= 2; --n) {
        tail = float(n) / (x + tail);
        if (n == 4) q4 = tail;
        if (n == 3) q3 = tail;
    }
    float q2 = tail;
    return vec2(-q2, q2 * ((x + 3.0 * q3 - 2.0 * q4) / (x + q3)) / (x + q4));
}

// Eq. 20: the exact mean and covariance of D_s for slopes N(m, Sigma) and
// the view at angles (theta, phi) radians from the plane's normal and x axis.
CmfSlopeGaussian cmf_slope_filtering_moments(CmfSlopeGaussian slopes, float theta, float phi)
{
    CmfSlopeViewFrame f = cmf_slope_view_frame(slopes, theta, phi);
    // u's law under D_s: the weight (a - b u)_+ = scale (k - z)_+.
    float a = f.cos_theta, b = f.sin_theta;
    float margin = a - b * f.mean_u, scale = b * f.sigma_u;
    float mean_u, var_u;
    if (!(scale > 0.0)) {
        if (margin > 0.0) {
            mean_u = f.mean_u;
            var_u = f.sigma_u * f.sigma_u;
        } else {
            mean_u = a / b;  // no facet faces the viewer: the limit at the horizon
            var_u = 0.0;
        }
    } else {
        float k = margin / scale;
        vec2 z = cmf_clamped_linear_normal(k);
        var_u = f.sigma_u * f.sigma_u * z.y;
        mean_u = k >= 0.0 ? f.mean_u + f.sigma_u * z.x : a / b + f.sigma_u * z.x;
    }
    float mean_v = f.mean_v + f.regression * (mean_u - f.mean_u);
    float uv = f.regression * var_u;
    float vv = f.residual_variance + f.regression * uv;
    float c = f.d.x, sn = f.d.y;
    CmfSlopeGaussian m;
    m.mean = vec2(mean_u * c - mean_v * sn, mean_u * sn + mean_v * c);
    m.xx = max(0.0, var_u * c * c - 2.0 * uv * c * sn + vv * sn * sn);
    m.xy = (var_u - vv) * c * sn + uv * (c * c - sn * sn);
    m.yy = max(0.0, var_u * sn * sn + 2.0 * uv * c * sn + vv * c * c);
    return m;
}

// C_s of a steepness map: C0 of the slope angle atan |s| in degrees.
vec3 cmf_steepness_color(sampler2D map, float domain_min, float domain_max, int wrap, vec2 s)
{
    return cmf_color_map_exact(map, domain_min, domain_max, wrap, degrees(atan(length(s))));
}

// The texture coordinates of slope s in a slope-vector map over
// [-s_max, s_max]^2 (texel centres already at (i + 0.5) / width); a
// coordinate that is not finite reads as 0, as the library reads it (an
// infinite or NaN slope gives the left or top edge).
vec2 cmf_slope_vector_uv(float s_max, vec2 s)
{
    vec2 uv = vec2(s.x + s_max, s_max - s.y) / (2.0 * s_max);
    return vec2(isnan(uv.x) || isinf(uv.x) ? 0.0 : uv.x, isnan(uv.y) || isinf(uv.y) ? 0.0 : uv.y);
}

// C_s of a slope-vector map through the sampler's bilinear filter (one fetch;
// GL_CLAMP_TO_EDGE continues the edge texels as the library does).
vec3 cmf_slope_vector_color(sampler2D map, float s_max, vec2 s)
{
    return textureLod(map, cmf_slope_vector_uv(s_max, s), 0.0).rgb;
}

// The same interpolated in the shader from texelFetch: the library's
// SlopeVectorColorMap::evaluate to float rounding, whatever the sampler.
vec3 cmf_slope_vector_color_exact(sampler2D map, float s_max, vec2 s)
{
    return cmf_bilinear_texels(map, ivec2(0), textureSize(map, 0), cmf_slope_vector_uv(s_max, s), false).rgb;
}

// A slope colour map C_s of either kind (the library's SlopeMap), as its
// texture's parameters.
const int CMF_SLOPE_MAP_STEEPNESS = 0;
const int CMF_SLOPE_MAP_VECTOR = 1;
struct CmfSlopeMap {
    int kind;                     // CMF_SLOPE_MAP_*
    float domain_min, domain_max;  // steepness: the map's domain, degrees
    int wrap;                     // steepness: CMF_WRAP_*
    float s_max;                  // vector: the largest slope along each axis, > 0
};

// C_s(s) by the texelFetch forms.
vec3 cmf_slope_map_color(sampler2D map, CmfSlopeMap m, vec2 s)
{
    if (m.kind == CMF_SLOPE_MAP_VECTOR) return cmf_slope_vector_color_exact(map, m.s_max, s);
    return cmf_steepness_color(map, m.domain_min, m.domain_max, m.wrap, s);
}

// <C_s, D_s> of eq. 20 with D_s replaced by the Gaussian of its exact
// moments (`render --method gaussian` for slope layers, the library's
// gaussian_slope_color): a points x points Gauss-Hermite rule along the
// principal axes of the covariance, C_s read at each node by
// cmf_slope_map_color.
vec3 cmf_gaussian_slope_color(sampler2D map, CmfSlopeMap slope_map, CmfSlopeGaussian slopes, float theta, float phi,
                              int points, float nodes[CMF_MAX_HERMITE_POINTS], float weights[CMF_MAX_HERMITE_POINTS])
{
    CmfSlopeGaussian m = cmf_slope_filtering_moments(slopes, theta, phi);
    float angle = 0.5 * atan(2.0 * m.xy, m.xx - m.yy);
    if (m.xy == 0.0 && m.xx - m.yy == 0.0) angle = 0.0;  // atan(0, 0) is undefined in GLSL
    float c = cos(angle), s = sin(angle);
    float major = sqrt(max(0.0, m.xx * c * c + 2.0 * m.xy * c * s + m.yy * s * s));
    float minor = sqrt(max(0.0, m.xx * s * s - 2.0 * m.xy * c * s + m.yy * c * c));
    vec3 sum = vec3(0.0);
    for (int i = 0; i < points; ++i) {
        float p = major * nodes[i];
        vec3 row = vec3(0.0);
        for (int j = 0; j < points; ++j) {
            float q = minor * nodes[j];
            row += weights[j] * cmf_slope_map_color(map, slope_map, m.mean + vec2(p * c - q * s, p * s + q * c));
        }
        sum += weights[i] * row;
    }
    return sum;
}

#endif  // CMFILTER_SLOPE_GLSL
