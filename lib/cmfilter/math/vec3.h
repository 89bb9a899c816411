// SPDX-License-Identifier: Apache-2.0
// A 3-D vector of doubles: points, directions and their derivatives in the
// renderer's world space.
#pragma once

#include <cmath>

namespace cmfilter {

struct Vec3 {
    double x = 0, y = 0, z = 0;

    Vec3& operator+=(const Vec3& o)
    {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    Vec3& operator-=(const Vec3& o)
    {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    friend Vec3 operator+(Vec3 a, const Vec3& b) { return a += b; }
    friend Vec3 operator-(Vec3 a, const Vec3& b) { return a -= b; }
    friend Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
    friend Vec3 operator*(double s, const Vec3& v) { return {s * v.x, s * v.y, s * v.z}; }
    friend Vec3 operator*(const Vec3& v, double s) { return s * v; }
    friend Vec3 operator/(const Vec3& v, double s) { return (1.0 / s) * v; }
    friend bool operator==(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
};

inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& v) { return std::sqrt(dot(v, v)); }
// v / |v|; the caller guarantees |v| > 0.
inline Vec3 normalize(const Vec3& v) { return v / length(v); }
// The derivative of normalize(v) along a change dv of v:
// (|v|^2 dv - <v, dv> v) / |v|^3; the caller guarantees |v| > 0.
inline Vec3 normalize_derivative(const Vec3& v, const Vec3& dv)
{
    const double length2 = dot(v, v);
    return (length2 * dv - dot(v, dv) * v) / (length2 * std::sqrt(length2));
}

}  // namespace cmfilter
