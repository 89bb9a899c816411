// SPDX-License-Identifier: Apache-2.0
// cmfilter_relight.glsl: relighting a linear fit of an image stack
// (`cmfilter fit`, docs/stacks.md): a texel's value under the light
// direction l = (lu, lv, lw) (unit, in the stack's frame) is the weighted sum
// of basis functions of l,
//   PTM (Malzbender et al. 2001, eq. 2): a0 lu^2 + a1 lv^2 + a2 lu lv + a3 lu + a4 lv + a5,
//   HSH (Gautron et al. 2004) of order 2 (4 terms) or 3 (9 terms), in
//   RTIViewer's closed form and order,
// per channel (ptm-rgb, hsh2, hsh3), or the PTM luminance polynomial times
// a per-texel base colour (ptm-lrgb). A function library: no #version, no main.
//
// Uploading. A fit EXR holds one channel per coefficient, in the order of
// LinearFit::coefficients: channel c's term k at c * terms + k (ptm-rgb,
// hsh2, hsh3), or the 6 luminance terms then the base colour (ptm-lrgb).
// Upload coefficient j as layer j of a GL_R32F 2D array texture
// (width x height x stride layers, rows in file order); read with
// texelFetch, so no filter or wrap applies.

#ifndef CMFILTER_RELIGHT_GLSL
#define CMFILTER_RELIGHT_GLSL

// cmfilter:model of the fit file.
const int CMF_PTM_RGB = 0;
const int CMF_PTM_LRGB = 1;
const int CMF_HSH2 = 2;
const int CMF_HSH3 = 3;

// Basis functions per channel: 6, 6, 4, 9.
int cmf_basis_terms(int model)
{
    return model == CMF_HSH2 ? 4 : (model == CMF_HSH3 ? 9 : 6);
}

// The basis at light l (unit, lw >= 0), terms 0 .. cmf_basis_terms - 1 in
// the order the files store them; unused entries are 0.
void cmf_evaluate_basis(int model, vec3 l, out float b[9])
{
    for (int k = 0; k < 9; ++k) b[k] = 0.0;
    if (model == CMF_PTM_RGB || model == CMF_PTM_LRGB) {
        b[0] = l.x * l.x;  // Malzbender et al. 2001, eq. 2
        b[1] = l.y * l.y;
        b[2] = l.x * l.y;
        b[3] = l.x;
        b[4] = l.y;
        b[5] = 1.0;
        return;
    }
    // HSH: theta the light's angle from the normal, phi its azimuth from +x
    // towards +y, c = cos theta, s = sqrt(c - c^2) (unclamped).
    const float pi = 3.14159265358979;
    float c = clamp(l.z, 0.0, 1.0);
    float phi = (l.x == 0.0 && l.y == 0.0) ? 0.0 : atan(l.y, l.x);
    float s = sqrt(max(0.0, c - c * c));
    b[0] = 1.0 / sqrt(2.0 * pi);
    b[1] = sqrt(6.0 / pi) * cos(phi) * s;
    b[2] = sqrt(3.0 / (2.0 * pi)) * (-1.0 + 2.0 * c);
    b[3] = sqrt(6.0 / pi) * s * sin(phi);
    if (model == CMF_HSH2) return;
    b[4] = sqrt(30.0 / pi) * cos(2.0 * phi) * (-c + c * c);
    b[5] = sqrt(30.0 / pi) * cos(phi) * (-1.0 + 2.0 * c) * s;
    b[6] = sqrt(5.0 / (2.0 * pi)) * (1.0 - 6.0 * c + 6.0 * c * c);
    b[7] = sqrt(30.0 / pi) * (-1.0 + 2.0 * c) * s * sin(phi);
    b[8] = sqrt(30.0 / pi) * (-c + c * c) * sin(2.0 * phi);
}

// The fit's value at `texel` under light l, channels 0 .. channels - 1 (1 or
// 3; a grey fit returns its value in .x): the library's relight().
vec3 cmf_relight(sampler2DArray coefficients, int model, int channels, ivec2 texel, vec3 l)
{
    float b[9];
    cmf_evaluate_basis(model, l, b);
    int terms = cmf_basis_terms(model);
    vec3 out_value = vec3(0.0);
    if (model == CMF_PTM_LRGB) {
        float luminance = 0.0;
        for (int k = 0; k < terms; ++k) luminance += texelFetch(coefficients, ivec3(texel, k), 0).r * b[k];
        for (int c = 0; c < channels; ++c) out_value[c] = texelFetch(coefficients, ivec3(texel, terms + c), 0).r * luminance;
        return out_value;
    }
    for (int c = 0; c < channels; ++c) {
        float v = 0.0;
        for (int k = 0; k < terms; ++k) v += texelFetch(coefficients, ivec3(texel, c * terms + k), 0).r * b[k];
        out_value[c] = v;
    }
    return out_value;
}

#endif  // CMFILTER_RELIGHT_GLSL
