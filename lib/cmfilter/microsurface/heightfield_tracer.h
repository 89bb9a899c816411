// SPDX-License-Identifier: Apache-2.0
// A ray-traced heightfield: one tile of a periodic GaussianMicrosurface
// (gaussian_microsurface.h, tile > 0) tabulated at the nodes of an N x N grid
// (or any periodic grid of nodes given as they are, from_nodes: the texels of
// a displacement texture, displacement_texture.h) and repeated over the whole
// plane, the ground truth for what a viewer sees
// and a light reaches on the microsurface, independent of Smith's model.
//
// Frame: x, y in the microsurface's units, z the height. Node (i, j) lies at
// (i, j) * s with s = tile / N, the texel size, and holds the microsurface's
// exact height there (tabulated as a 2-D inverse DFT of its lattice spectrum,
// exact to rounding). Between nodes the surface is the bilinear interpolant of
// the 4 corners of the texel, wrapping periodically. N is the smallest power
// of two with s <= min_wavelength / texels_per_min_wavelength, where
// min_wavelength is 1 / (the largest |f| of the microsurface's cosines).
//
// Tracing is exact: along a ray inside one texel the bilinear height is a
// quadratic in t, solved in closed form. The texels a ray crosses are found
// by a hierarchical 2-D DDA over a maximum mipmap (max_mipmap.h): the ray is
// clipped to the slab [min_height, max_height], and any block whose maximum
// lies below the ray's lowest z over the block is skipped whole, so a grazing
// ray crossing thousands of texels inside the slab visits few of them.
//
// The surface is crossed where the ray passes strictly to the other side of
// it: a ray that only touches it (tangent at a point, or lying in a flat
// patch) goes on. A ray that starts on the surface (within a relative 1e-11
// of it: a point returned by trace) starts on the side the local patch's
// gradient puts its direction, never by an epsilon offset. A ray that stays
// inside the slab for more than kMaxTilesTravelled tiles horizontally without
// crossing is taken as not crossing (with a slab a tenth of a tile thick, only
// rays within 0.006 degrees of horizontal get that far).
//
// Immutable; const queries are thread-safe; no global state.
#pragma once

#include "cmfilter/util/error.h"
#include "cmfilter/microsurface/gaussian_microsurface.h"
#include "cmfilter/microsurface/max_mipmap.h"
#include "cmfilter/math/vec3.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace cmfilter {

struct HeightfieldOptions {
    int texels_per_min_wavelength = 8;  // >= 1
    int max_resolution = 4096;          // N must not exceed it; 1 to 16384
    int threads = 0;                    // for tabulation; <= 0: every hardware thread
    // Also tabulate the exact slopes (dh/dx, dh/dy) at the nodes, for slope().
    bool slopes = false;
};

struct HeightfieldHit {
    double t = 0;       // along the ray, in units of the direction's length
    Vec3 point;         // origin + t direction
    double height = 0;  // point.z, the surface's height there
    Vec3 normal;        // unit normal of the bilinear patch at the point, z > 0
};

class Heightfield {
public:
    // Horizontal travel inside the slab, in tiles, beyond which a ray is
    // taken as not crossing the surface.
    static constexpr double kMaxTilesTravelled = 1024;

    // BadInput naming the value and what was expected: a non-periodic
    // microsurface (tile 0), texels_per_min_wavelength < 1, max_resolution out
    // of range, or a resolution N over max_resolution.
    static Expected<Heightfield> create(const GaussianMicrosurface& surface, const HeightfieldOptions& options);

    // Any periodic n x n grid of nodes, one tile of side `tile`: heights[j * n
    // + i] is node (i, j), at (i, j) * tile / n as above, and slope_x, slope_y
    // (both empty, or n * n each, laid out the same) its slopes (dh/dx,
    // dh/dy) for slope(). Tracing, heights and slopes as for create. BadInput
    // naming the value and what was expected: n not a power of two from 1 to
    // 16384, a tile not finite and > 0, sizes that differ from n * n, or a
    // non-finite node.
    static Expected<Heightfield> from_nodes(std::vector<double> heights, int n, double tile,
                                            std::vector<double> slope_x = {}, std::vector<double> slope_y = {});

    int resolution() const { return n_; }  // N, nodes per side of a tile
    double tile() const { return tile_; }
    double texel_size() const { return tile_ / n_; }
    double min_height() const { return min_height_; }  // over all nodes
    double max_height() const { return max_height_; }
    // Node (i, j), wrapping: any integers.
    double node_height(std::int64_t i, std::int64_t j) const;
    // The bilinear surface at (x, y), anywhere on the plane.
    double height(double x, double y) const;
    // The microsurface's slopes (dh/dx, dh/dy) at (x, y): its exact slopes at
    // the nodes (HeightfieldOptions::slopes; from_nodes: those given),
    // bilinear between them: smooth slopes with the microsurface's
    // statistics, for slope-coloured maps (the bilinear patches' own
    // gradients jump at texel edges and are a little flatter). False, leaving
    // sx and sy alone, when they were not tabulated.
    bool slope(double x, double y, double& sx, double& sy) const;

    // The first crossing of the ray origin + t direction, 0 < t <= t_max.
    // direction: finite and nonzero (it need not be unit; t is in units of its
    // length). None for no crossing or a non-finite input.
    std::optional<HeightfieldHit> trace(const Vec3& origin, const Vec3& direction,
                                        double t_max = std::numeric_limits<double>::infinity()) const;

    // Whether the shadow ray from a point towards a light in direction
    // to_light (at infinity) is blocked: some point of it with t > 0 lies
    // strictly below the surface. A point on the surface whose patch faces
    // away from the light (or any direction below the horizontal) is
    // occluded at once. A point clearly above the surface may be given too;
    // one below it is occluded, and so is any non-finite or zero input.
    bool occluded(const Vec3& point, const Vec3& to_light) const;

private:
    struct Ray;
    struct Crossing;
    Heightfield() = default;
    // Where a ray that starts (at its t = 0) in the slab first passes strictly
    // to the other side of the surface from `side` (+1 above, -1 below; 0:
    // the side it starts on, deduced at its origin), before t_end.
    std::optional<Crossing> walk(const Ray& ray, double t_end, int side, bool at_origin) const;
    Ray local_ray(const Vec3& start, const Vec3& direction) const;
    double on_surface_tolerance(const Vec3& p) const;
    // The height range and maximum mipmap of nodes_, once they are set.
    void finish();

    int n_ = 0;
    int top_level_ = 0;  // the coarsest mipmap level the walk starts from
    double tile_ = 0;
    double min_height_ = 0, max_height_ = 0;
    std::vector<double> nodes_;              // (N + 1) x (N + 1), the last row and column repeating the first
    std::vector<double> slope_x_, slope_y_;  // the same for the slopes, when tabulated
    MaxMipmap mipmap_;
};

}  // namespace cmfilter
