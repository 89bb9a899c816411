// SPDX-License-Identifier: Apache-2.0
// Ray-surface intersection for the renderer's planes and spheres, with the
// hit's texture coordinates and their screen-space derivatives, transferred
// from the camera's ray differentials (Igehy 1999, eq. 10-12): for a hit at
// distance t with unit normal n,
//     dt/dx = -<dp_origin/dx + t dd/dx, n> / <d, n>,   dp/dx = t dd/dx + dt/dx d
// (the origin is fixed for a pinhole camera), then (du, dv)/dx from the
// mapping's Jacobian at p (planar: the axes; spherical: the derivatives of
// longitude and polar angle). The same for y.
//
// The derivatives are always finite. Each is capped at +-kDerivativeLimit:
// as a ray grazes a surface, <d, n> -> 0 and the footprint is unbounded. The
// spherical mapping's |d phi| is capped at a full turn, 2 pi (reached near and
// on the poles, where the footprint wraps around the axis and longitude is
// undefined), and |d theta| at the angle the step subtends, |dq| (reached on
// the poles). Across the seam phi = 0, u jumps by u_scale; its derivatives do
// not. A spherical mapping on a plane (which scene loading forbids) maps the
// direction of p from mapping.origin.
#pragma once

#include "cmfilter/scene/camera.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/math/vec3.h"

#include <optional>

namespace cmfilter {

// The cap on every derivative of a SurfaceHit, in scene or texture units per
// pixel: a renderer may read it as "the footprint covers everything".
inline constexpr double kDerivativeLimit = 1e30;

struct SurfaceHit {
    double t = 0;  // distance along the unit ray direction
    Vec3 point;
    Vec3 normal;          // unit, facing the ray's origin
    double u = 0, v = 0;  // texture coordinates (scene.h, TextureMapping)
    Vec3 dp_dx, dp_dy;    // world-space footprint of one pixel step
    double du_dx = 0, dv_dx = 0, du_dy = 0, dv_dy = 0;
};

// The nearest hit with t > t_min, or none. The derivatives are those of a
// camera ray (CameraRay's differentials).
std::optional<SurfaceHit> intersect(const Surface& surface, const CameraRay& ray, double t_min = 1e-9);

// Only the distance of intersect's hit along a unit direction from origin:
// no differentials, no mapping (coverage tests, pixel_coverage.h).
std::optional<double> hit_distance(const Surface& surface, const Vec3& origin, const Vec3& direction,
                                   double t_min = 1e-9);

// The nearest hit over all surfaces and its surface's index.
struct SceneHit {
    SurfaceHit hit;
    int surface = -1;
};
std::optional<SceneHit> intersect_scene(const Scene& scene, const CameraRay& ray);

}  // namespace cmfilter
