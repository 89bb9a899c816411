// SPDX-License-Identifier: Apache-2.0
// cmfilter_coordinate_map.glsl: rendering through a coordinate map of
// `cmfilter synth` (Tong et al. 2002 via the second paper's sec. 4.2, "Using
// large BTFs for rendering": a large surface stored as, per output texel,
// the sample texel it copies; docs/synthesis.md): one more texture lookup,
// at full size and at a level of detail L (footprints of 2^L x 2^L
// full-size texels) by the library's methods `levels`, `point` and
// `patches` (coordinate_lookup.h; `synth-apply --lod-method`). A function
// library: no #version, no main. Needs cmfilter_bilinear.glsl before it.
//
// Uploading. A coordinate map is a driver: its integer textures are read
// with texelFetch only (averaging coordinates across a seam, what a mip or
// bilinear filter of the map does, lands in an unrelated part of the
// sample). Every pyramid here has level l of ceil(w / 2^l) x ceil(h / 2^l)
// texels (the synthesis's levels, the sample's pyramid of
// sample_image_pyramid.h, the patch levels), which is not OpenGL's MIP
// chain (floor(w / 2^l)) unless w and h are powers of two: each is uploaded
// as ONE texture, its levels stacked downwards from row 0 (level `first` at
// rows [0, h_first), the next level below it, ...), as wide as its first
// level (cmf_stacked_level finds a level's rows).
// - The map: the coordinate map EXR's parts (level 0, then `level-1` ..;
//   channels x, y as sample texel indices, floor(u W), floor(v H)) as a
//   GL_RG32I texture, levels stacked from 0, rows in file order.
// - The sample: its pyramid (sample_image_pyramid.h: 2 x 2 box means, an
//   odd edge repeating its last texel) as a float texture (RGBA32F for up
//   to four channels), levels stacked from 0, rows in file order. Level 0
//   alone serves the full-size lookup and `patches`.
// - `patches`: the patch levels of build_patch_level (L = 1 .. the level
//   of 1 x 1, or fewer) as a GL_RGB32F 2-D array texture, levels stacked
//   from 1, layer k holding each footprint's entry k (dx, dy, share); and
//   the sample's summed-area table as SampleBoxSums keeps it: (W + 1) x
//   (H + 1) texels of RGBA32F, texel (x, y) the sum over [0, x) x [0, y) of
//   the sample minus its per-channel mean (`sample_mean`).

#ifndef CMFILTER_COORDINATE_MAP_GLSL
#define CMFILTER_COORDINATE_MAP_GLSL

// The map and its sample, from the coordinate map file's metadata.
struct CmfCoordinateMap {
    int width, height;                // the full-size map (part 0)
    int levels;                       // its levels, part 0 included (cmfilter:levels)
    int sample_width, sample_height;  // the sample's level 0 (cmfilter:sample_width, _height)
    int sample_periodic;              // cmfilter:sample_periodic: 1 when reads beyond the sample wrap
};

// What `patches` reads beside the map: the stacked patch levels' count and
// entries per footprint, the sample's mean (of its summed-area table) and
// the mean of the full-size output (the sample's texels weighted by how
// often the map copies each), which stands for the pieces a footprint has
// beyond its `patches` kept ones.
struct CmfPatchLevels {
    vec4 sample_mean;
    vec4 output_mean;
    int patches;  // entries per footprint (LodOptions::patches, >= 1)
    int levels;   // patch levels stacked: L = 1 .. levels
};

// ceil(n / 2^level) for n >= 1 and 0 <= level <= 30.
int cmf_level_extent(int n, int level) { return ((n - 1) >> level) + 1; }

// Level `level` of a stacked pyramid whose level 0 is size0 and whose first
// stacked level is `first`: (0, its first row, its width, its height).
ivec4 cmf_stacked_level(ivec2 size0, int first, int level)
{
    int row = 0;
    for (int l = first; l < level; ++l) row += cmf_level_extent(size0.y, l);
    return ivec4(0, row, cmf_level_extent(size0.x, level), cmf_level_extent(size0.y, level));
}

// The last level of a pyramid from size0 down to 1 x 1.
int cmf_top_level(ivec2 size0)
{
    int l = 0;
    while (cmf_level_extent(size0.x, l) > 1 || cmf_level_extent(size0.y, l) > 1) ++l;
    return l;
}

// The full-size output's texel: the sample texel its coordinate names
// (the library's render_through_map).
vec4 cmf_through_coordinate_map(isampler2D map, sampler2D sample_image, ivec2 texel)
{
    ivec2 source = texelFetch(map, texel, 0).xy;
    return texelFetch(sample_image, source, 0);
}

// `levels`: texel `texel` of the output at LOD `lod` is the sample level-L
// texel that hierarchical synthesis's level-L map names at the same place
// (render_at_lod, LodMethod::Levels; bit for bit). The library refuses an L
// beyond the map's levels; here it reads the map's last level there (point
// sampled onto the coarser output), and L < 0 reads as 0.
vec4 cmf_coordinate_map_levels(isampler2D map, sampler2D sample_pyramid, CmfCoordinateMap m, ivec2 texel, int lod)
{
    int out_level = clamp(lod, 0, 30), l = min(out_level, m.levels - 1);
    ivec4 level = cmf_stacked_level(ivec2(m.width, m.height), 0, l);
    ivec2 extent = ivec2(cmf_level_extent(m.width, out_level), cmf_level_extent(m.height, out_level));
    // Output texel centre (texel + 0.5) / extent in the level's texels.
    ivec2 t = min(level.zw - 1, ((2 * texel + 1) * level.zw) / (2 * extent));
    ivec2 source = texelFetch(map, level.xy + t, 0).xy;
    ivec4 sample_level = cmf_stacked_level(ivec2(m.sample_width, m.sample_height), 0, l);
    return texelFetch(sample_pyramid, sample_level.xy + source, 0);
}

// The footprint of output texel `texel` at LOD l in full-size texels:
// (x0, y0, x1, y1), cut to the map (footprints beyond its last level are
// the whole map, as at that level).
ivec4 cmf_footprint(CmfCoordinateMap m, ivec2 texel, int l)
{
    int step = 1 << min(l, cmf_top_level(ivec2(m.width, m.height)));
    ivec2 lo = texel * step;
    return ivec4(lo, min(ivec2(m.width, m.height), lo + step));
}

// `point`: the coordinate of the texel nearest the footprint's centre, its
// offset carried to the centre, read bilinearly in the sample's level
// min(L, top) (render_at_lod, LodMethod::Point; float rounding).
vec4 cmf_coordinate_map_point(isampler2D map, sampler2D sample_pyramid, CmfCoordinateMap m, ivec2 texel, int lod)
{
    int l = clamp(lod, 0, 30);
    ivec4 f = cmf_footprint(m, texel, l);
    ivec2 extent = f.zw - f.xy;
    ivec2 p = min(f.zw - 1, f.xy + extent / 2);
    vec2 centre = vec2(f.xy) + 0.5 * vec2(extent);
    vec2 source = vec2(texelFetch(map, p, 0).xy) + (centre - vec2(p));
    ivec2 size0 = ivec2(m.sample_width, m.sample_height);
    int sample_l = min(l, cmf_top_level(size0));
    ivec4 level = cmf_stacked_level(size0, 0, sample_l);
    vec2 uv = source * (1.0 / float(1 << sample_l)) / vec2(level.zw);
    return cmf_bilinear_texels(sample_pyramid, level.xy, level.zw, uv, m.sample_periodic != 0);
}

// The sum over [0, x) x [0, y) of the (periodic) sample minus its mean: with
// x = q_x W + r_x and y = q_y H + r_y, q_x q_y S(W, H) + q_x S(W, r_y) +
// q_y S(r_x, H) + S(r_x, r_y).
vec4 cmf_sample_corner_sum(sampler2D sums, ivec2 size, bool periodic, ivec2 corner)
{
    ivec2 q = ivec2(0);
    if (periodic) q = ivec2(cmf_floor_divide(corner.x, size.x), cmf_floor_divide(corner.y, size.y));
    ivec2 r = corner - q * size;
    vec4 v = texelFetch(sums, r, 0);
    if (q.x != 0) v += float(q.x) * texelFetch(sums, ivec2(size.x, r.y), 0);
    if (q.y != 0) v += float(q.y) * texelFetch(sums, ivec2(r.x, size.y), 0);
    if (q.x != 0 && q.y != 0) v += float(q.x) * float(q.y) * texelFetch(sums, size, 0);
    return v;
}

// The sample's mean over the box [lo, lo + extent) (SampleBoxSums::box_mean):
// wrapping (a periodic sample, its origin first brought into the sample,
// which keeps the float sums small), else moved inside the sample and cut
// to it where wider.
vec4 cmf_sample_box_mean(sampler2D sums, vec4 sample_mean, ivec2 size, bool periodic, ivec2 lo, ivec2 extent)
{
    if (periodic) {
        lo = ivec2(cmf_wrap_texel(lo.x, size.x, true), cmf_wrap_texel(lo.y, size.y, true));
    } else {
        lo = ivec2(extent.x >= size.x ? 0 : clamp(lo.x, 0, size.x - extent.x),
                   extent.y >= size.y ? 0 : clamp(lo.y, 0, size.y - extent.y));
        extent = min(extent, size);
    }
    ivec2 hi = lo + extent;
    vec4 s = cmf_sample_corner_sum(sums, size, periodic, hi);
    s -= cmf_sample_corner_sum(sums, size, periodic, ivec2(lo.x, hi.y));
    s -= cmf_sample_corner_sum(sums, size, periodic, ivec2(hi.x, lo.y));
    s += cmf_sample_corner_sum(sums, size, periodic, lo);
    return sample_mean + s / (float(extent.x) * float(extent.y));
}

// `patches` (the library's default; render_at_lod, LodMethod::Patches):
// per footprint its kept patch offsets c(p) - p with their shares, each
// offset's footprint box read exactly from the summed-area table, weighted
// by its share; the share left at the full-size output's mean. L <= 0 is the
// full-size lookup; L beyond the stacked levels reads the last (exact when
// they run to 1 x 1: every footprint beyond it is the whole map).
vec4 cmf_coordinate_map_patches(isampler2D map, sampler2D sample_image, sampler2DArray patch_levels,
                                sampler2D sample_sums, CmfCoordinateMap m, CmfPatchLevels p, ivec2 texel, int lod)
{
    if (lod <= 0 || p.levels < 1) return cmf_through_coordinate_map(map, sample_image, texel);
    int l = min(lod, p.levels);
    ivec4 f = cmf_footprint(m, texel, l);
    ivec4 level = cmf_stacked_level(ivec2(m.width, m.height), 1, l);
    ivec2 size = ivec2(m.sample_width, m.sample_height);
    bool periodic = m.sample_periodic != 0;
    vec4 sum = vec4(0.0);
    float rest = 1.0;
    for (int k = 0; k < p.patches; ++k) {
        vec3 e = texelFetch(patch_levels, ivec3(level.xy + texel, k), 0).xyz;
        if (!(e.z > 0.0)) break;
        rest -= e.z;
        sum += e.z * cmf_sample_box_mean(sample_sums, p.sample_mean, size, periodic, f.xy + ivec2(e.xy), f.zw - f.xy);
    }
    if (rest > 1e-6) sum += rest * p.output_mean;
    return sum;
}

#endif  // CMFILTER_COORDINATE_MAP_GLSL
