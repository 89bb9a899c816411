// SPDX-License-Identifier: Apache-2.0
// Where a surface's image ends, in image coordinates (pixels, y down, as
// Camera::ray). The camera's unnormalised direction D(px, py) is affine in
// the image point (Camera::ImagePlane), so:
//   plane   a ray meets it (t > 0) where <D, n> has the sign of <p0 - o, n>:
//           a half-image bounded by the horizon line <D, n> = 0, linear in
//           (px, py) (none with the eye on the plane);
//   sphere  a ray meets it where the sphere's centre lies within r of the
//           ray's line and ahead of the eye, |D x C|^2 <= r^2 |D|^2 and
//           <D, C> > 0 (C = centre - eye): the inside of the silhouette, a
//           conic, quadratic in (px, py); everywhere with the eye inside.
// A box pixel [x, x + 1] x [y, y + 1] lies within half its diagonal of its
// centre, an angle at most `margin` = asin(h / |D|) <= asin(h) with h the
// half diagonal on the image plane at distance 1 (|D| >= 1; a box of side s:
// asin(s h)). The sphere's image is a cone
// of half-angle alpha = asin(r / |C|) about C, so a pixel whose centre ray is
// at angle theta from C can meet the silhouette only if |theta - alpha| <=
// margin: the test may_cross uses, never missing a pixel the silhouette
// crosses (it may name a few beyond it).
#pragma once

#include "cmfilter/scene/camera.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/math/vec3.h"

#include <utility>
#include <vector>

namespace cmfilter {

class SurfaceOutline {
public:
    SurfaceOutline(const Surface& surface, const Camera::ImagePlane& image);

    // Whether the outline may pass through the box [x0, x0 + size] x [y0,
    // y0 + size] (size 1: the box pixel): exact for a plane's horizon,
    // conservative for a sphere's silhouette.
    bool may_cross(double x0, double y0, double size = 1) const;
    // Whether some of the box may see the surface (nearer surfaces aside):
    // false only where the whole box misses it.
    bool may_see(double x0, double y0, double size = 1) const;
    // Appends the s in (0, 1) where the outline meets the image segment whose
    // directions are D = start + s step (Camera::ImagePlane's D), in no
    // particular order.
    void crossings(const Vec3& start, const Vec3& step, std::vector<double>& out) const;
    // The direction across the outline at image point (px, py): the
    // gradient of its implicit function in pixels, scaled to unit length
    // ((0, 0) for a surface with no outline).
    std::pair<double, double> across(double px, double py) const;

private:
    enum class Kind { Nowhere, Everywhere, HalfImage, Cone };
    Kind kind_ = Kind::Nowhere;
    Camera::ImagePlane image_;
    // HalfImage: <D, n> > 0 on the surface, n the plane's normal facing
    // away from the eye; s(px, py) = <D(px, py), n> = s0 + px sx + py sy.
    Vec3 normal_;
    double s0_ = 0, sx_ = 0, sy_ = 0;
    // Cone: the centre C relative to the eye, r^2, alpha, the half diagonal
    // of a pixel at distance 1, and for a box the cosines of alpha + margin
    // and max(0, alpha - margin) (pixel_: a box pixel's).
    struct ConeBounds {
        double cos_outer = -1, cos_inner = 1;
    };
    Vec3 centre_;
    double radius2_ = 0, centre2_ = 0, alpha_ = 0, half_diagonal_ = 0;
    ConeBounds pixel_;

    ConeBounds cone_bounds(double size) const;
    int side(double x0, double y0, double size) const;
};

}  // namespace cmfilter
