// SPDX-License-Identifier: Apache-2.0
// A textured displacement: a periodic heightfield read from a one-channel
// image, with the slopes and the footprint statistics that slope- and
// height-coloured maps need (Heitz et al. 2013, sec. 5.2: the slope
// filtering distribution takes the resolved mean slope and the unresolved
// slope covariance of a footprint; sec. 5.1 the unresolved height deviation
// sigma_h), and its ray-traced ground truth (heightfield_tracer.h).
//
// Conventions (those of filtered_texture.h): one repeat, [0, 1]^2 in texture
// coordinates (u, v), is the whole image; texel (i, j), column i and row j
// (row 0 at the top), has its centre at ((i + 0.5) / N, (j + 0.5) / N); v
// grows downwards with the rows; the texture tiles the plane. The image must
// be square (N x N: a repeat is a square, and one texture unit is one repeat
// along u and along v alike). Texels are data, never colour-converted:
// channel 0 (or the one named) as float, 8- and 16-bit codes as code / 255,
// code / 65535 (driver_image.h).
//
// Units: heights are in texture units, texel value * height_scale (one
// texture unit = one repeat). The surface is the bilinear interpolant of the
// texel centres: height(u, v).
//
// Slopes: (sx, sy) = (dh/du, dh/dv) in texture units per texture unit
// (dimensionless; v downwards, so sy > 0 where the surface rises towards the
// rows below). At texel centres they are exactly what `maketx --bumpslopes`
// writes in its level-0 channels 1 and 2, a 3 x 3 Sobel gradient per texel,
//     sx(i, j) = [h(i+1, j-1) - h(i-1, j-1) + 2 (h(i+1, j) - h(i-1, j))
//                 + h(i+1, j+1) - h(i-1, j+1)] / 8 * N
// (sy the same with rows and columns swapped): central differences smoothed
// by [1 2 1] / 4 across, in height per texel, times N texels per texture
// unit; so slope = height_scale * (maketx channel with --uvslopes_scale 1)
// = height_scale * N * (maketx channel by default, per texel). The neighbours
// wrap periodically here (maketx clamps them at the image's edges whatever
// its --wrap, so the two agree everywhere only for images whose first and
// last rows and columns are equal). Between texel centres the slopes are
// interpolated bilinearly, like the heights: slope(u, v). They are smooth
// slopes for slope-coloured maps, not the bilinear patches' own gradients
// (which jump at texel edges).
//
// The pyramid: a MIP pyramid of the channels maketx --bumpslopes writes, in
// its order, (h, sx, sy, sx^2, sy^2, sx sy), plus h^2, baked in process:
// level k holds their exact box means over blocks of 2^k x 2^k texels
// (box_pyramid.h), each texel a point value held over its square; maketx
// --bumpslopes --filter box --uvslopes_scale 1 on a power-of-two image
// writes the same first six (times height_scale, height_scale^2). For a GPU
// or TextureSystem lookup, and the reference for the texel moments.
//
// Footprints: a parallelogram (centre (u, v), edges (e1u, e1v), (e2u, e2v)
// in texture units, points c + a e1 + b e2 for a, b in [-1/2, 1/2], as
// microsurface_footprint.h) is cut into up to max_probes pieces along its
// longer edge (anisotropic_probes.h), each of rms width w texels, and each
// piece, edges (a, b), reads
//   w >= 2   exact box means of the same seven channels over the axis-
//            aligned rectangle with the piece's second moments along u and
//            v (sides sqrt(a_u^2 + b_u^2), sqrt(a_v^2 + b_v^2): a square
//            piece at any angle has them), from summed-area tables of the
//            bilinear surface's own moments over each texel's square (exact
//            by Gauss-Legendre quadrature), so that any footprint costs the
//            same, and one of whole repeats gives the surface's moments
//            exactly. The texel moments of the pyramid are not those: over
//            a repeat they overstate the slope variance by what
//            interpolation between texel centres smooths (a few per cent on
//            a smooth relief, more on a sharp one), which the ray-traced
//            surface does not have;
//   w <= 1   the bilinear fields linearised about the piece's centre: a
//            field g with gradient G has mean g(c) and covariance with
//            another, f, ((F.a)(G.a) + (F.b)(G.b)) / 12 (a uniform
//            parallelogram's): the point's own height and slope, with a
//            spread that vanishes with the footprint;
//   between  the two's raw moments blended linearly in log2 w.
// The pieces' raw moments are averaged, then the resolved mean slope m =
// E[s] and the unresolved covariance E[s s^T] - m m^T (clamped positive
// semi-definite; the paper's Sigma of sec. 5.2), and sigma_h^2 = E[h^2] -
// E[h]^2 (sec. 5.1). Heights are taken about the texture's mean height and
// the tables' channels about their means, so small relief on a large offset
// and footprints of many repeats keep their precision.
//
// Ground truth: heightfield() is a Heightfield whose nodes are the texels
// (tile 1 texture unit, heights in texture units, node slopes the Sobel
// slopes above). Heightfield puts node (i, j) at (i, j) / N, texel (i, j)'s
// centre is at ((i, j) + 0.5) / N: texture (u, v) is the heightfield's
// (x, y) = (u - 0.5 / N, v - 0.5 / N) (heightfield_xy), and its heights and
// slopes there are height(u, v) and slope(u, v).
//
// Immutable once made, cheap to copy (the texels are shared); every query is
// thread-safe; no global state.
#pragma once

#include "cmfilter/microsurface/displacement_masking.h"
#include "cmfilter/io/driver_image.h"
#include "cmfilter/util/error.h"
#include "cmfilter/microsurface/heightfield_tracer.h"
#include "cmfilter/microsurface/masked_slope_table.h"
#include "cmfilter/math/periodic_summed_area.h"

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cmfilter {

struct DisplacementOptions {
    std::string path;     // any image OpenImageIO reads
    std::string channel;  // a name or 0-based index; empty: the image must have one channel
    NonFinitePolicy nonfinite = NonFinitePolicy::Error;
    double height_scale = 1;  // texture units per texel value; finite, >= 0
    int max_probes = 8;       // squares an anisotropic footprint is cut into; >= 1
    int threads = 0;          // for baking the pyramid; 0: all cores
};

// What a footprint resolves and what it does not.
struct DisplacementFootprint {
    double mean_height = 0;                           // E[h], texture units
    double sigma_h = 0;                               // sqrt(E[h^2] - E[h]^2)
    double slope_x = 0, slope_y = 0;                  // resolved: E[s]
    double slope_xx = 0, slope_xy = 0, slope_yy = 0;  // unresolved: E[s s^T] - E[s] E[s]^T
    double lod = 0;  // log2 of the probes' width in texels, >= -64 (a point); 1e9 for infinite edges
};

// The slopes over a footprint weighted by Smith's G1 = F(h)^Lambda from each
// point's height (masked_slope_table.h): the mean of G1 and the weighted
// slope mean and covariance.
struct MaskedFootprint {
    double g1 = 1;
    double slope_x = 0, slope_y = 0;
    double slope_xx = 0, slope_xy = 0, slope_yy = 0;
};

// The pyramid's channels, in maketx --bumpslopes's order, then h^2.
enum DisplacementChannel { kHeight, kSlopeX, kSlopeY, kSlopeXX, kSlopeYY, kSlopeXY, kHeightSquared, kChannels };

class DisplacementTexture {
public:
    // BadInput naming the file: not square, more than one channel with none
    // chosen, non-finite texels (unless replaced), height_scale not finite
    // and >= 0, max_probes < 1. Io: a missing or unreadable file.
    static Expected<DisplacementTexture> load(const DisplacementOptions& options);
    // The same from texels in memory: width * height values, row-major, top
    // row first (options.path names them in messages, and is not read).
    static Expected<DisplacementTexture> from_texels(std::vector<float> texels, int width, int height,
                                                     const DisplacementOptions& options);

    int size() const { return data_->n; }  // N, texels per side
    double height_scale() const { return data_->height_scale; }
    const std::string& path() const { return data_->path; }

    // Texel (i, j)'s height and Sobel slopes, wrapping: any integers.
    double texel_height(int i, int j) const;
    std::pair<double, double> texel_slope(int i, int j) const;

    // The bilinear surface and its slopes at (u, v), anywhere on the plane.
    double height(double u, double v) const;
    void slope(double u, double v, double& sx, double& sy) const;

    // Statistics over the parallelogram footprint (texture units); zero
    // edges: a point. Non-finite edges read as an infinite footprint.
    DisplacementFootprint footprint(double u, double v, double e1u, double e1v, double e2u, double e2v) const;

    // The pyramid: levels(), each level_size(k) texels per side, and the box
    // means of texel (x, y) of level k (heights in texture units).
    int levels() const { return static_cast<int>(data_->levels.size()); }
    int level_size(int k) const;
    std::array<double, kChannels> pyramid_texel(int k, int x, int y) const;

    // The ray-tracing ground truth; BadInput unless N is a power of two.
    Expected<Heightfield> heightfield(int threads) const;
    // Texture (u, v) in the heightfield's frame, and back.
    std::pair<double, double> heightfield_xy(double u, double v) const;
    std::pair<double, double> texture_uv(double x, double y) const;

    // Smith's masking from the texels' own heights and slopes.
    const DisplacementMasking& masking() const { return data_->masking; }
    // The footprint's slopes weighted by G1 for this Lambda (0: footprint()'s
    // slopes, g1 = 1): the masked table's box means over each piece where
    // the piece spans a cell of it or more, the footprint's own moments and
    // G1 of its mean height below a cell, blended linearly in log2 of the
    // width between.
    MaskedFootprint masked_footprint(double u, double v, double e1u, double e1v, double e2u, double e2v,
                                     double lambda) const;

private:
    struct Data {
        std::string path;
        int n = 0;
        double height_scale = 1;
        int max_probes = 8;
        double reference = 0;                    // mean height, subtracted in the pyramid
        std::vector<double> h, sx, sy;           // level 0, N x N, row-major
        std::vector<std::vector<float>> levels;  // kChannels interleaved; h about `reference`
        PeriodicSummedArea table;                // of the texel squares' moments, kChannels
        DisplacementMasking masking;
        MaskedSlopeTable masked;
    };
    explicit DisplacementTexture(std::shared_ptr<const Data> data) : data_(std::move(data)) {}
    std::shared_ptr<const Data> data_;
};

}  // namespace cmfilter
