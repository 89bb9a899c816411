// Helpers for the renderer's unit tests: printing a Vec3 in doctest messages,
// finiteness, angles, central differences, and a scene camera.
#pragma once

#include "cmfilter/scene.h"
#include "cmfilter/vec3.h"

#include <doctest/doctest.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace doctest {
template <>
struct StringMaker<cmfilter::Vec3> {
    static String convert(const cmfilter::Vec3& v)
    {
        std::ostringstream s;
        s << std::setprecision(17) << "(" << v.x << ", " << v.y << ", " << v.z << ")";
        return s.str().c_str();
    }
};
}  // namespace doctest

namespace cmfilter_test {

inline bool is_finite(const cmfilter::Vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The angle between two non-zero vectors, accurate for small and large angles.
inline double angle_between(const cmfilter::Vec3& a, const cmfilter::Vec3& b)
{
    return std::atan2(cmfilter::length(cmfilter::cross(a, b)), cmfilter::dot(a, b));
}

// (f(h) - f(-h)) / 2h for f(s), a Vec3 or a double at an offset s.
template <typename F>
auto central_difference(const F& f, double h)
{
    return (f(h) - f(-h)) / (2 * h);
}

inline cmfilter::SceneCamera make_scene_camera(const cmfilter::Vec3& position, const cmfilter::Vec3& look_at,
                                               const cmfilter::Vec3& up, double fov_degrees, int width, int height)
{
    cmfilter::SceneCamera c;
    c.position = position;
    c.look_at = look_at;
    c.up = up;
    c.fov_degrees = fov_degrees;
    c.width = width;
    c.height = height;
    return c;
}

}  // namespace cmfilter_test
