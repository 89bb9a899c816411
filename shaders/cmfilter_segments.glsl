// SPDX-License-Identifier: Apache-2.0
// cmfilter_segments.glsl: the segment pyramid of `cmfilter bake-moments
// --segments` (texture/segment_pyramid_file.h), recoloured in the shader.
// Channel k (k = 1..K) holds R_k, the box mean over each texel's footprint
// of the ramp r_k(f) = clamp((f - t_{k-1}) / (t_k - t_{k-1}), 0, 1) of the
// breakpoints t_0 < ... < t_K (cmfilter:breakpoints); for colours C_k at
// those breakpoints the filtered colour is
//     mean C(f) = C_0 + sum_k (C_k - C_{k-1}) R_k,
// exact for a box filter (sec. 3, eq. 1) for every map linear between the
// breakpoints, whatever its colours: edit the colours live, no re-bake.
// A tolerance bake (cmfilter:segment_colors least-squares) holds fewer
// breakpoints than the map has: there C_k are the map's least-squares
// colours over the driver, not its colours at t_k (Python's
// cmfilter.segment_colors(pyramid, table) computes them, as apply does).
// A function library: no #version, no main.
//
// Uploading. The K channels, four at a time (s001..s004 in layer 0, s005..
// in layer 1, the last layer padded with zeros), are the layers of a
// GL_RGBA32F (or GL_RGBA16F for a half file) GL_TEXTURE_2D_ARRAY; the EXR's
// MIP level k (subimage 0) is MIP level k of every layer, rows in file order
// (row 0, the top row, first), so that (s, t) are the library's: (0, 0) the
// top-left corner, t downwards. Set GL_TEXTURE_MAX_LEVEL to cmfilter:levels
// - 1 and never call glGenerateMipmap. Sampler: GL_LINEAR_MIPMAP_LINEAR min,
// GL_LINEAR mag; wrap from cmfilter:wrap (clamp -> GL_CLAMP_TO_EDGE,
// periodic -> GL_REPEAT, black -> GL_CLAMP_TO_BORDER, black border; a black
// border reads C_0). Colours are scene-linear.

#ifndef CMFILTER_SEGMENTS_GLSL
#define CMFILTER_SEGMENTS_GLSL

// The most channels a shader compiled with this library reads (override
// before including it); a file of more is refused by cmf_segments_fits.
#ifndef CMF_SEGMENTS_MAX_CHANNELS
#define CMF_SEGMENTS_MAX_CHANNELS 16
#endif
#define CMF_SEGMENTS_LAYERS ((CMF_SEGMENTS_MAX_CHANNELS + 3) / 4)

struct CmfSegments {
    int levels;    // cmfilter:levels: floor(log2(max(W, H))) + 1
    int channels;  // K: the number of breakpoints in cmfilter:breakpoints minus 1
};

bool cmf_segments_fits(CmfSegments p) { return p.channels >= 1 && p.channels <= CMF_SEGMENTS_MAX_CHANNELS; }

// C_0 + sum_k (C_k - C_{k-1}) R_k for the ramp means of one footprint
// (ramps[j] holds R_{4j+1} .. R_{4j+4}) and colours[k] = C_k, k = 0..K.
vec3 cmf_segments_color(vec4 ramps[CMF_SEGMENTS_LAYERS], int channels, vec3 colors[CMF_SEGMENTS_MAX_CHANNELS + 1])
{
    vec3 c = colors[0];
    for (int k = 1; k <= CMF_SEGMENTS_MAX_CHANNELS; ++k) {
        if (k > channels) break;
        c += (colors[k] - colors[k - 1]) * ramps[(k - 1) / 4][(k - 1) % 4];
    }
    return c;
}

// Trilinear lookup at level of detail lod, the library's
// SegmentPyramidTexture::lookup(s, t, lod) and ramp_color: integer lod reads
// level lod alone (bilinear), fractional lod blends levels floor(lod) and
// floor(lod) + 1; lod is clamped to [0, levels - 1].
vec3 cmf_segments(sampler2DArray ramps, CmfSegments p, vec3 colors[CMF_SEGMENTS_MAX_CHANNELS + 1], vec2 st, float lod)
{
    float l = isnan(lod) ? 0.0 : clamp(lod, 0.0, float(p.levels - 1));
    vec4 r[CMF_SEGMENTS_LAYERS];
    for (int j = 0; j < CMF_SEGMENTS_LAYERS; ++j)
        r[j] = j * 4 < p.channels ? clamp(textureLod(ramps, vec3(st, float(j)), l), 0.0, 1.0) : vec4(0.0);
    return cmf_segments_color(r, p.channels, colors);
}

// Anisotropic lookup over the footprint spanned by the screen derivatives
// of (s, t): the GPU's own filter over the means, then the same sum (the
// ramps' means stay means under every linear filter).
vec3 cmf_segments_grad(sampler2DArray ramps, CmfSegments p, vec3 colors[CMF_SEGMENTS_MAX_CHANNELS + 1], vec2 st,
                       vec2 dst_dx, vec2 dst_dy)
{
    vec4 r[CMF_SEGMENTS_LAYERS];
    for (int j = 0; j < CMF_SEGMENTS_LAYERS; ++j)
        r[j] = j * 4 < p.channels ? clamp(textureGrad(ramps, vec3(st, float(j)), dst_dx, dst_dy), 0.0, 1.0)
                                  : vec4(0.0);
    return cmf_segments_color(r, p.channels, colors);
}

#endif
