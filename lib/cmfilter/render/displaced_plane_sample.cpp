// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/displaced_plane_sample.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

std::optional<DisplacedPlaneSample> trace_displaced_plane(const Surface& plane, const Heightfield& heightfield,
                                                          const Vec3& origin, const Vec3& direction,
                                                          const Vec3& to_light, double shift)
{
    const TextureMapping& m = plane.mapping;
    const double k = length(m.u_axis);
    // Heights along the normal facing the ray's origin.
    const Vec3 n = dot(origin - plane.point, plane.normal) >= 0 ? plane.normal : -1.0 * plane.normal;
    const auto local_point = [&](const Vec3& p) {
        return Vec3{dot(p - m.origin, m.u_axis) - shift, dot(p - m.origin, m.v_axis) - shift,
                    k * dot(p - plane.point, n)};
    };
    // Directions scale by k on every axis: the local ray's t is k times the scene's.
    const auto local_direction = [&](const Vec3& d) { return Vec3{dot(d, m.u_axis), dot(d, m.v_axis), k * dot(d, n)}; };
    const Vec3 d = local_direction(direction);
    if (!(d.z < 0)) return std::nullopt;
    const auto hit = heightfield.trace(local_point(origin), d);
    if (!hit) return std::nullopt;
    DisplacedPlaneSample s;
    s.t = hit->t;  // d has length k, so local t is the scene distance
    s.height = hit->height;
    s.x = hit->point.x + shift;
    s.y = hit->point.y + shift;
    if (!heightfield.slope(hit->point.x, hit->point.y, s.slope_x, s.slope_y)) {
        s.slope_x = -hit->normal.x / hit->normal.z;
        s.slope_y = -hit->normal.y / hit->normal.z;
    }
    const Vec3 l = normalize(local_direction(to_light));
    s.light_cosine = std::max(0.0, dot(hit->normal, l));
    s.lit = s.light_cosine > 0 && !heightfield.occluded(hit->point, l);
    return s;
}

}  // namespace cmfilter
