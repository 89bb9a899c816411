// SPDX-License-Identifier: Apache-2.0
// Geometric coverage of a box pixel by the scene's surfaces, for the one-ray
// methods (render.h): which share of the pixel sees each surface (nearest
// first) and which share sees the background, where a silhouette, a horizon
// or a line where two surfaces meet crosses the pixel.
//
// on_edge is the cheap test every pixel takes (first a lookup of its 16 x 16
// tile, marked by the same tests on the tile's box): a surface's outline
// (surface_outline.h) may cross the box, or two surfaces that meet each
// other (a sphere through a plane, two overlapping spheres, two planes that
// are not parallel) are both seen and their depth order differs between the
// box's corners and centre. Only such pixels are covered:
//   - the box is cut into kColumns strips across its edges: along x or y,
//     whichever makes the steepest edge's slope against the strips the
//     smaller (from the outlines' gradients and the depth difference's), a
//     box with edges steep both ways (a silhouette's side meeting a horizon)
//     being cut in four first, up to kMaxDepth times. On each strip's middle
//     line the points where an outline crosses are found analytically (a
//     root of the horizon's line or of the silhouette's conic), and each
//     piece of the line between them is given to the surface its middle ray
//     meets first (or the background). Within a piece nothing changes but
//     where two surfaces meet; where the pixel may hold such a meeting (the
//     depth order differs, or the outline of one of the two crosses it),
//     the piece is sampled at kDepthSamples + 1 points end to end and every
//     change of nearest surface is found by bisection. The strips' midpoint
//     rule is exact for a straight edge that crosses two opposite sides of
//     the box (the usual horizon) and off by at most s w^2 / 8 (w = 1 /
//     kColumns, s <= kMaxSlope the edge's slope against the strips) of the
//     pixel for each kink of the covered length where a straight edge cuts
//     a corner; a curved silhouette adds its curvature's share;
//   - each surface seen gets its share of the area, a representative image
//     point (the centroid of its part, or, when the centroid sees another
//     surface, the middle of its longest piece) and the part's own
//     footprint: the parallelogram M [-1/2, 1/2]^2 with M M^T = 12 Sigma,
//     Sigma the covariance of the part's points (the whole box gives M = I;
//     a thin part a thin footprint), so that the part is filtered over what
//     it covers, with the same second moments (the rms width's argument in
//     footprint_width.h).
// The pixel's colour is then sum_i share_i C_i + share_background
// background, C_i the surface's colour filtered over its part: the pixel's
// integral over its box (eq. 1, w_P the box) split by what each part sees,
// as the reference's rays split it.
#pragma once

#include "cmfilter/scene/camera.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/scene/surface_hit.h"
#include "cmfilter/scene/surface_outline.h"

#include <optional>
#include <utility>
#include <vector>

namespace cmfilter {

struct CoveragePiece {
    int surface = -1;       // index into Scene::surfaces
    double share = 0;       // of the box pixel's area
    double px = 0, py = 0;  // representative image point, seeing the surface
    // The part's footprint in pixels: the image steps (m00, m10) and (m01,
    // m11) take the place of one pixel along x and along y.
    double m00 = 1, m01 = 0, m10 = 0, m11 = 1;
};

struct PixelCover {
    std::vector<CoveragePiece> pieces;  // one per surface seen, by surface index
    double background = 0;              // the share that sees no surface
};

class PixelCoverage {
public:
    static constexpr int kColumns = 16;
    static constexpr int kDepthSamples = 8;
    // A box whose edges are steeper than this against strips either way is
    // cut in four, at most kMaxDepth times (a pixel 1/8 wide at the end).
    static constexpr double kMaxSlope = 4;
    static constexpr int kMaxDepth = 3;
    // on_edge first looks up the pixel's tile of kTile x kTile pixels, which
    // the constructor marks where an edge may lie (the same tests on the
    // tile's box), so most pixels cost one lookup.
    static constexpr int kTile = 16;

    // Keeps references to both: they must outlive it.
    PixelCoverage(const Scene& scene, const Camera& camera);

    // Whether the box pixel (x, y) may see more than one surface, or a
    // surface and the background.
    bool on_edge(int x, int y) const
    {
        return tiles_[static_cast<std::size_t>((y / kTile) * tiles_x_ + x / kTile)] && on_edge_in_tile(x, y);
    }
    // The shares of the box pixel (x, y); `out` is overwritten.
    void cover(int x, int y, PixelCover& out) const;
    // The hit at a piece's representative point, its differentials those of
    // the piece's footprint (dp/dx, du/dx, ... along M's columns); none if
    // rounding lets the ray miss.
    std::optional<SurfaceHit> hit(const CoveragePiece& piece) const;

private:
    const Scene* scene_;
    const Camera* camera_;
    Camera::ImagePlane image_;
    std::vector<SurfaceOutline> outlines_;
    std::vector<std::pair<int, int>> meeting_;  // pairs of surfaces that meet each other
    int tiles_x_ = 0;
    std::vector<unsigned char> tiles_;  // per tile: whether an edge may lie in it

    struct Box {
        double x0, y0, size;  // [x0, x0 + size] x [y0, y0 + size], image coordinates
    };
    struct Moments;

    bool on_edge_in_tile(int x, int y) const;
    Vec3 direction(double px, double py) const;
    int nearest(double px, double py) const;  // -1: background
    bool holds_meeting(const Box& box, std::vector<std::pair<double, double>>* across) const;
    void cover_box(int x, int y, const Box& box, bool sampled, int depth, std::vector<Moments>& parts) const;
};

}  // namespace cmfilter
