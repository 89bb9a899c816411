// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/scene/surface_outline.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Slack on the tests' comparisons: they must stay conservative under rounding.
constexpr double kSlack = 1e-12;

void keep_inside(double s, std::vector<double>& out)
{
    if (std::isfinite(s) && s > 0 && s < 1) out.push_back(s);
}

std::pair<double, double> unit(double x, double y)
{
    const double norm = std::hypot(x, y);
    if (!(norm > 0) || !std::isfinite(norm)) return {0, 0};
    return {x / norm, y / norm};
}

// Whether dc < c sqrt(dd) (dd >= 0), without the root: the cosine of an
// angle below c.
bool below_cosine(double dc, double dd, double c)
{
    if (c >= 0) return dc < 0 || dc * dc < c * c * dd;
    return dc < 0 && dc * dc > c * c * dd;
}

}  // namespace

SurfaceOutline::SurfaceOutline(const Surface& surface, const Camera::ImagePlane& image) : image_(image)
{
    if (surface.kind == SurfaceKind::Plane) {
        const double side = dot(surface.point - image.origin, surface.normal);
        if (!(side != 0)) return;  // the eye on the plane: rays run along it or leave it
        normal_ = side > 0 ? surface.normal : -surface.normal;
        kind_ = Kind::HalfImage;
        s0_ = dot(image.corner, normal_);
        sx_ = dot(image.step_x, normal_);
        sy_ = dot(image.step_y, normal_);
        return;
    }
    centre_ = surface.center - image.origin;
    radius2_ = surface.radius * surface.radius;
    centre2_ = dot(centre_, centre_);
    const double distance = length(centre_);
    if (!(distance > surface.radius)) {
        kind_ = Kind::Everywhere;
        return;
    }
    kind_ = Kind::Cone;
    alpha_ = std::asin(surface.radius / distance);
    half_diagonal_ = 0.5 * std::sqrt(dot(image.step_x, image.step_x) + dot(image.step_y, image.step_y));
    pixel_ = cone_bounds(1.0);
}

SurfaceOutline::ConeBounds SurfaceOutline::cone_bounds(double size) const
{
    const double margin = std::asin(std::min(1.0, size * half_diagonal_));
    return {alpha_ + margin >= kPi ? -1.0 : std::cos(alpha_ + margin),
            alpha_ - margin <= 0 ? 1.0 : std::cos(alpha_ - margin)};
}

// Where the box [x0, x0 + size] x [y0, y0 + size] may lie: -1 wholly off the
// surface, 1 wholly on it, 0 across the outline.
int SurfaceOutline::side(double x0, double y0, double size) const
{
    switch (kind_) {
    case Kind::Nowhere: return -1;
    case Kind::Everywhere: return 1;
    case Kind::HalfImage: {
        // s is affine: over the box it spans its centre value +- size (|sx| + |sy|) / 2.
        const double centre = s0_ + (x0 + 0.5 * size) * sx_ + (y0 + 0.5 * size) * sy_;
        const double half_range = 0.5 * size * (std::fabs(sx_) + std::fabs(sy_)) + kSlack;
        return centre > half_range ? 1 : centre < -half_range ? -1 : 0;
    }
    case Kind::Cone: {
        // cos theta = <d, C> / sqrt(|d|^2 |C|^2), compared without the root.
        const ConeBounds bounds = size == 1 ? pixel_ : cone_bounds(size);
        const Vec3 d = image_.corner + (x0 + 0.5 * size) * image_.step_x + (y0 + 0.5 * size) * image_.step_y;
        const double dc = dot(d, centre_), dd = dot(d, d) * centre2_;
        if (below_cosine(dc, dd, bounds.cos_outer - kSlack)) return -1;
        return below_cosine(dc, dd, bounds.cos_inner + kSlack) ? 0 : 1;
    }
    }
    return -1;
}

bool SurfaceOutline::may_cross(double x0, double y0, double size) const { return side(x0, y0, size) == 0; }

bool SurfaceOutline::may_see(double x0, double y0, double size) const { return side(x0, y0, size) >= 0; }

void SurfaceOutline::crossings(const Vec3& start, const Vec3& step, std::vector<double>& out) const
{
    if (kind_ == Kind::HalfImage) {
        const double slope = dot(step, normal_);
        if (slope != 0) keep_inside(-dot(start, normal_) / slope, out);
        return;
    }
    if (kind_ != Kind::Cone) return;
    // Along the segment D(s) = P + s Q: |D x C|^2 - r^2 |D|^2 = a s^2 + 2 b s + c,
    // and the plane through the eye facing C, <D, C> = 0, which cuts off the
    // cone's backward nappe.
    const Vec3& P = start;
    const Vec3& Q = step;
    const Vec3 PxC = cross(P, centre_), QxC = cross(Q, centre_);
    const double a = dot(QxC, QxC) - radius2_ * dot(Q, Q);
    const double b = dot(PxC, QxC) - radius2_ * dot(P, Q);
    const double c = dot(PxC, PxC) - radius2_ * dot(P, P);
    if (a == 0) {
        if (b != 0) keep_inside(-c / (2 * b), out);
    } else {
        const double discriminant = b * b - a * c;
        if (discriminant >= 0) {
            // The root of larger magnitude without cancellation, the other as c / (a root).
            const double q = -(b + std::copysign(std::sqrt(discriminant), b));
            keep_inside(q / a, out);
            if (q != 0) keep_inside(c / q, out);
        }
    }
    const double facing = dot(Q, centre_);
    if (facing != 0) keep_inside(-dot(P, centre_) / facing, out);
}

std::pair<double, double> SurfaceOutline::across(double px, double py) const
{
    if (kind_ == Kind::HalfImage) return unit(sx_, sy_);
    if (kind_ != Kind::Cone) return {0, 0};
    // The gradient of |D x C|^2 - r^2 |D|^2 along the image steps.
    const Vec3 d = image_.corner + px * image_.step_x + py * image_.step_y;
    const Vec3 dxc = cross(d, centre_);
    return unit(dot(dxc, cross(image_.step_x, centre_)) - radius2_ * dot(d, image_.step_x),
                dot(dxc, cross(image_.step_y, centre_)) - radius2_ * dot(d, image_.step_y));
}

}  // namespace cmfilter
