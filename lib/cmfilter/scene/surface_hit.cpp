// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/scene/surface_hit.h"

#include <cmath>
#include <utility>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;

// x within +-kDerivativeLimit (surface_hit.h); NaN becomes the limit (fmin
// and fmax ignore a NaN argument).
double bounded(double x) { return std::fmax(-kDerivativeLimit, std::fmin(x, kDerivativeLimit)); }
Vec3 bounded(const Vec3& v) { return {bounded(v.x), bounded(v.y), bounded(v.z)}; }

// num / den with its magnitude capped at `cap` >= 0: a zero denominator (or a
// NaN numerator) gives +-cap, its sign that of num / den.
double capped_ratio(double num, double den, double cap)
{
    if (std::fabs(num) < cap * std::fabs(den)) return num / den;
    return std::signbit(num) == std::signbit(den) ? cap : -cap;
}

// Where a ray meets a surface, before the differentials and the mapping.
struct RayHit {
    double t = 0;
    Vec3 normal;  // unit, facing the ray's origin
};

std::optional<RayHit> hit_plane(const Vec3& point, const Vec3& plane_normal, const CameraRay& ray, double t_min)
{
    if (!(length(plane_normal) > 0)) return std::nullopt;
    const Vec3 n = normalize(plane_normal);
    const double cosine = dot(ray.direction, n);
    if (cosine == 0) return std::nullopt;  // parallel
    const double t = dot(point - ray.origin, n) / cosine;
    if (!(t > t_min) || !std::isfinite(t)) return std::nullopt;
    return RayHit{t, cosine < 0 ? n : -n};
}

// The roots of t^2 + 2 b t + c = 0 (|o + t d - center|^2 = r^2, d unit) as in
// Haines et al., "Precision improvements for ray/sphere intersection" (Ray
// Tracing Gems, 2019): the discriminant from the centre's distance to the
// ray's line, the root of larger magnitude q without cancellation, the other
// as c / q.
std::optional<RayHit> hit_sphere(const Vec3& center, double radius, const CameraRay& ray, double t_min)
{
    if (!(radius > 0)) return std::nullopt;
    const Vec3 to_origin = ray.origin - center;
    const double b = dot(to_origin, ray.direction);
    const Vec3 off_line = to_origin - b * ray.direction;
    const double discriminant = radius * radius - dot(off_line, off_line);
    if (discriminant < 0) return std::nullopt;
    const double c = dot(to_origin, to_origin) - radius * radius;
    const double q = -(b + std::copysign(std::sqrt(discriminant), b));
    double near = q, far = q == 0 ? 0 : c / q;
    if (near > far) std::swap(near, far);
    const double t = near > t_min ? near : far;
    if (!(t > t_min) || !std::isfinite(t)) return std::nullopt;
    const Vec3 outward = normalize(ray.origin + t * ray.direction - center);
    return RayHit{t, dot(outward, ray.direction) > 0 ? -outward : outward};
}

std::optional<RayHit> hit_surface(const Surface& surface, const CameraRay& ray, double t_min)
{
    return surface.kind == SurfaceKind::Sphere ? hit_sphere(surface.center, surface.radius, ray, t_min)
                                               : hit_plane(surface.point, surface.normal, ray, t_min);
}

// The surface point's derivative for a ray direction's derivative dd (Igehy
// 1999): with the pinhole's fixed origin, dP/dx = 0 and
//     dt/dx = -<t dd/dx, n> / <d, n>          (eq. 12)
//     dp/dx = t dd/dx + dt/dx d               (eq. 10)
Vec3 surface_derivative(const CameraRay& ray, const RayHit& hit, const Vec3& d_direction)
{
    const Vec3 swept = hit.t * d_direction;
    const double dt = capped_ratio(-dot(swept, hit.normal), dot(ray.direction, hit.normal), kDerivativeLimit);
    return bounded(swept + dt * ray.direction);
}

// Planar mapping (scene.h): u and v are linear in p, their derivatives the
// axes' components of dp.
void map_planar(const TextureMapping& mapping, SurfaceHit& hit)
{
    const Vec3 offset = hit.point - mapping.origin;
    hit.u = dot(offset, mapping.u_axis);
    hit.v = dot(offset, mapping.v_axis);
    hit.du_dx = bounded(dot(hit.dp_dx, mapping.u_axis));
    hit.dv_dx = bounded(dot(hit.dp_dx, mapping.v_axis));
    hit.du_dy = bounded(dot(hit.dp_dy, mapping.u_axis));
    hit.dv_dy = bounded(dot(hit.dp_dy, mapping.v_axis));
}

// The longitude's derivative d phi = (q.x dq.z - q.z dq.x) / (q.x^2 + q.z^2)
// for a unit q. Near the poles a pixel's footprint wraps around the axis:
// |d phi| is capped at one full turn, 2 pi (and is 2 pi on the axis itself).
double longitude_derivative(const Vec3& q, const Vec3& dq)
{
    return capped_ratio(q.x * dq.z - q.z * dq.x, q.x * q.x + q.z * q.z, 2 * kPi);
}

// The polar angle's derivative d theta = -dq.y / sqrt(1 - q.y^2) for a unit q
// and a dq tangent to the unit sphere, with sqrt(1 - q.y^2) taken as
// sqrt(q.x^2 + q.z^2) (accurate near the poles). The polar angle is a
// great-circle distance, so |d theta| <= |dq|: the cap, reached on the axis,
// where theta has no derivative and |dq| is the footprint's angular size.
double polar_angle_derivative(const Vec3& q, const Vec3& dq)
{
    return capped_ratio(-dq.y, std::sqrt(q.x * q.x + q.z * q.z), length(dq));
}

// Spherical mapping (scene.h) about `center`: q is the unit direction of p
// from the centre (for a sphere, (p - center) / radius), dq its derivative
// (tangent to the unit sphere, as a unit vector's derivative is).
// phi = atan2(q.z, q.x) in [0, 2 pi) and theta = atan2(sqrt(q.x^2 + q.z^2), q.y)
// (acos(q.y), accurate near the poles). u jumps by u_scale across the seam
// at phi = 0; its derivative does not.
void map_spherical(const TextureMapping& mapping, const Vec3& center, SurfaceHit& hit)
{
    const Vec3 radial = hit.point - center;
    if (!(length(radial) > 0)) {  // only a plane's mapping origin can lie on the surface
        hit.u = hit.v = 0;
        hit.du_dx = hit.dv_dx = hit.du_dy = hit.dv_dy = kDerivativeLimit;
        return;
    }
    const Vec3 q = normalize(radial);
    double phi = std::atan2(q.z, q.x);
    if (phi < 0) phi += 2 * kPi;
    if (phi >= 2 * kPi) phi = 0;  // -tiny + 2 pi rounds up to 2 pi
    const double theta = std::atan2(std::sqrt(q.x * q.x + q.z * q.z), q.y);
    hit.u = mapping.u_scale * phi / (2 * kPi);
    hit.v = mapping.v_scale * theta / kPi;

    const Vec3 dq_dx = normalize_derivative(radial, hit.dp_dx);
    const Vec3 dq_dy = normalize_derivative(radial, hit.dp_dy);
    hit.du_dx = bounded(mapping.u_scale * longitude_derivative(q, dq_dx) / (2 * kPi));
    hit.du_dy = bounded(mapping.u_scale * longitude_derivative(q, dq_dy) / (2 * kPi));
    hit.dv_dx = bounded(mapping.v_scale * polar_angle_derivative(q, dq_dx) / kPi);
    hit.dv_dy = bounded(mapping.v_scale * polar_angle_derivative(q, dq_dy) / kPi);
}

}  // namespace

std::optional<SurfaceHit> intersect(const Surface& surface, const CameraRay& ray, double t_min)
{
    const bool sphere = surface.kind == SurfaceKind::Sphere;
    const std::optional<RayHit> found = hit_surface(surface, ray, t_min);
    if (!found) return std::nullopt;

    SurfaceHit hit;
    hit.t = found->t;
    hit.point = ray.origin + found->t * ray.direction;
    hit.normal = found->normal;
    hit.dp_dx = surface_derivative(ray, *found, ray.d_direction_dx);
    hit.dp_dy = surface_derivative(ray, *found, ray.d_direction_dy);
    if (surface.mapping.kind == MappingKind::Planar) map_planar(surface.mapping, hit);
    else  // a plane's spherical mapping: directions from the mapping's origin
        map_spherical(surface.mapping, sphere ? surface.center : surface.mapping.origin, hit);
    return hit;
}

std::optional<double> hit_distance(const Surface& surface, const Vec3& origin, const Vec3& direction, double t_min)
{
    CameraRay ray;
    ray.origin = origin;
    ray.direction = direction;
    const std::optional<RayHit> found = hit_surface(surface, ray, t_min);
    if (!found) return std::nullopt;
    return found->t;
}

std::optional<SceneHit> intersect_scene(const Scene& scene, const CameraRay& ray)
{
    std::optional<SceneHit> nearest;
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        std::optional<SurfaceHit> hit = intersect(scene.surfaces[i], ray);
        if (hit && (!nearest || hit->t < nearest->hit.t)) nearest = SceneHit{*hit, static_cast<int>(i)};
    }
    return nearest;
}

}  // namespace cmfilter
