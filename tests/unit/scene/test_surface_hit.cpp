// SPDX-License-Identifier: Apache-2.0
// Ray-plane and ray-sphere hits, their texture coordinates and the ray
// differentials transferred to them, each against an independent computation:
// analytic hits, and central differences of the hit point and (u, v) of
// neighbouring camera rays, intersected and mapped by the test's own formulas
// (the textbook ray-plane and quadratic ray-sphere solutions, scene.h's
// mapping formulas as written).
#include "cmfilter/scene/surface_hit.h"

#include "render_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

using namespace cmfilter;
using cmfilter_test::central_difference;
using cmfilter_test::is_finite;

namespace {

constexpr double kPi = 3.14159265358979323846;

Surface make_plane(const Vec3& point, const Vec3& normal, const TextureMapping& mapping = {})
{
    Surface s;
    s.kind = SurfaceKind::Plane;
    s.point = point;
    s.normal = normal;
    s.mapping = mapping;
    return s;
}

Surface make_sphere(const Vec3& center, double radius, const TextureMapping& mapping = {})
{
    Surface s;
    s.kind = SurfaceKind::Sphere;
    s.center = center;
    s.radius = radius;
    s.mapping = mapping;
    return s;
}

TextureMapping planar_mapping(const Vec3& origin, const Vec3& u_axis, const Vec3& v_axis)
{
    TextureMapping m;
    m.kind = MappingKind::Planar;
    m.origin = origin;
    m.u_axis = u_axis;
    m.v_axis = v_axis;
    return m;
}

TextureMapping spherical_mapping(double u_scale, double v_scale)
{
    TextureMapping m;
    m.kind = MappingKind::Spherical;
    m.u_scale = u_scale;
    m.v_scale = v_scale;
    return m;
}

// A ray with the given (not necessarily unit) direction and differentials.
CameraRay make_ray(const Vec3& origin, const Vec3& direction, const Vec3& d_direction_dx = {},
                   const Vec3& d_direction_dy = {})
{
    return {origin, normalize(direction), d_direction_dx, d_direction_dy};
}

// A 640 x 360 camera.
Camera make_camera(const Vec3& position, const Vec3& look_at, const Vec3& up, double fov_degrees = 60)
{
    auto camera = Camera::create(cmfilter_test::make_scene_camera(position, look_at, up, fov_degrees, 640, 360));
    REQUIRE(camera);
    return *camera;
}

// The reference hit point: t = <point - o, n> / <d, n> for a plane, the
// nearest positive root of t^2 + 2 <o - c, d> t + |o - c|^2 - r^2 for a sphere.
Vec3 reference_hit_point(const Surface& s, const CameraRay& ray)
{
    double t = 0;
    if (s.kind == SurfaceKind::Plane) {
        t = dot(s.point - ray.origin, s.normal) / dot(ray.direction, s.normal);
    } else {
        const Vec3 oc = ray.origin - s.center;
        const double b = dot(oc, ray.direction), c = dot(oc, oc) - s.radius * s.radius;
        const double root = std::sqrt(b * b - c);
        t = -b - root > 0 ? -b - root : -b + root;
    }
    return ray.origin + t * ray.direction;
}

struct Uv {
    double u = 0, v = 0;
};

// scene.h's mapping formulas as written (spherical about the sphere's centre).
Uv reference_uv(const Surface& s, const Vec3& p)
{
    const TextureMapping& m = s.mapping;
    if (m.kind == MappingKind::Planar) return {dot(p - m.origin, m.u_axis), dot(p - m.origin, m.v_axis)};
    const Vec3 q = (p - s.center) / s.radius;
    double phi = std::atan2(q.z, q.x);
    if (phi < 0) phi += 2 * kPi;
    const double theta = std::acos(std::clamp(q.y, -1.0, 1.0));
    return {m.u_scale * phi / (2 * kPi), m.v_scale * theta / kPi};
}

// The hit of the camera ray through (px, py), its differentials checked
// against central differences of the reference hit points and (u, v) of the
// rays through (px +- h, py) and (px, py +- h).
void check_differentials(const Camera& camera, const Surface& surface, double px, double py)
{
    CAPTURE(px);
    CAPTURE(py);
    const double h = 1e-3;
    const std::optional<SurfaceHit> hit = intersect(surface, camera.ray(px, py));
    REQUIRE(hit);
    const auto point_at = [&](double dx, double dy) {
        return reference_hit_point(surface, camera.ray(px + dx, py + dy));
    };
    const auto uv_at = [&](double dx, double dy) { return reference_uv(surface, point_at(dx, dy)); };

    const Vec3 dp_dx = central_difference([&](double s) { return point_at(s, 0); }, h);
    const Vec3 dp_dy = central_difference([&](double s) { return point_at(0, s); }, h);
    CAPTURE(hit->dp_dx);
    CAPTURE(dp_dx);
    CHECK(length(hit->dp_dx - dp_dx) <= 1e-6 * length(dp_dx));
    CAPTURE(hit->dp_dy);
    CAPTURE(dp_dy);
    CHECK(length(hit->dp_dy - dp_dy) <= 1e-6 * length(dp_dy));

    const double du_dx = central_difference([&](double s) { return uv_at(s, 0).u; }, h);
    const double dv_dx = central_difference([&](double s) { return uv_at(s, 0).v; }, h);
    const double du_dy = central_difference([&](double s) { return uv_at(0, s).u; }, h);
    const double dv_dy = central_difference([&](double s) { return uv_at(0, s).v; }, h);
    // Relative to the size of the pixel step in texture space.
    const double scale_x = std::hypot(du_dx, dv_dx), scale_y = std::hypot(du_dy, dv_dy);
    CHECK(std::fabs(hit->du_dx - du_dx) <= 1e-6 * scale_x);
    CHECK(std::fabs(hit->dv_dx - dv_dx) <= 1e-6 * scale_x);
    CHECK(std::fabs(hit->du_dy - du_dy) <= 1e-6 * scale_y);
    CHECK(std::fabs(hit->dv_dy - dv_dy) <= 1e-6 * scale_y);
}

bool derivatives_finite(const SurfaceHit& hit)
{
    return is_finite(hit.dp_dx) && is_finite(hit.dp_dy) && std::isfinite(hit.du_dx) && std::isfinite(hit.dv_dx) &&
           std::isfinite(hit.du_dy) && std::isfinite(hit.dv_dy);
}

}  // namespace

TEST_CASE("a plane hit lies on the plane and on the ray, its normal facing the ray")
{
    const Vec3 normal = normalize({0.1, 1, 0.2});
    const Surface plane = make_plane({0.5, -0.2, 0.1}, normal);
    const Camera camera = make_camera({1, 3, 2}, {0, 0, -4}, {0, 1, 0});
    for (const auto& [px, py] : {std::pair{320.0, 180.0}, std::pair{10.5, 300.5}, std::pair{600.25, 250.75}}) {
        const CameraRay ray = camera.ray(px, py);
        const std::optional<SurfaceHit> hit = intersect(plane, ray);
        REQUIRE(hit);
        CHECK(std::fabs(dot(hit->point - plane.point, normal)) < 1e-13);
        CHECK(length(hit->point - (ray.origin + hit->t * ray.direction)) < 1e-13);
        CHECK(length(hit->normal - normal) < 1e-15);  // the camera is above the plane
        CHECK(dot(hit->normal, ray.direction) < 0);
    }
}

TEST_CASE("a plane hit is at the analytic distance from either side")
{
    const Surface ground = make_plane({3, 0, -7}, {0, 1, 0});
    std::optional<SurfaceHit> hit = intersect(ground, make_ray({0, 2, 0}, {0, -1, 0}));
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(2.0).epsilon(1e-15));
    CHECK(length(hit->point - Vec3{0, 0, 0}) < 1e-15);

    hit = intersect(ground, make_ray({0, 2, 0}, {1, -1, 0}));
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(2 * std::sqrt(2.0)).epsilon(1e-15));
    CHECK(length(hit->point - Vec3{2, 0, 0}) < 1e-15);

    hit = intersect(ground, make_ray({1, -3, 1}, {0, 1, 0}));  // from below
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(3.0).epsilon(1e-15));
    CHECK(hit->normal == Vec3{0, -1, 0});

    // A normal of any length is normalised.
    hit = intersect(make_plane({0, 0, 0}, {0, 5, 0}), make_ray({0, 2, 0}, {0, -1, 0}));
    REQUIRE(hit);
    CHECK(hit->normal == Vec3{0, 1, 0});
}

TEST_CASE("a ray parallel to a plane or pointing away misses it")
{
    const Surface ground = make_plane({0, 0, 0}, {0, 1, 0});
    CHECK_FALSE(intersect(ground, make_ray({0, 2, 0}, {1, 0, 0})));
    CHECK_FALSE(intersect(ground, make_ray({0, 0, 0}, {1, 0, 1})));  // in the plane
    CHECK_FALSE(intersect(ground, make_ray({0, 2, 0}, {0, 1, 0})));
    CHECK_FALSE(intersect(ground, make_ray({0, -2, 0}, {0.3, -1, 0})));
    CHECK_FALSE(intersect(ground, make_ray({0, 2, 0}, {0, -1, 0}), 2.5));  // nearer than t_min
}

TEST_CASE("plane differentials equal central differences of neighbouring hits")
{
    const Surface plane = make_plane({0.5, -0.2, 0.1}, normalize({0.1, 1, 0.2}),
                                     planar_mapping({0.3, 0, -1}, {0.5, 0, 0.1}, {0, 0.2, 0.7}));
    const Camera camera = make_camera({1, 3, 2}, {0, 0, -4}, {0, 1, 0});
    for (const auto& [px, py] :
         {std::pair{320.0, 180.0}, std::pair{10.5, 300.5}, std::pair{600.25, 250.75}, std::pair{100.0, 120.0}})
        check_differentials(camera, plane, px, py);
}

TEST_CASE("a ground plane near the horizon has large, finite derivatives")
{
    // Eye at height 1 looking along -z: the ray through (W/2, H/2 + delta)
    // slopes down by k T (k = 2 py / H - 1, T = tan(fov/2)) and meets the
    // ground at z = -1 / (k T); so dz/dpy = (2 / H) / (k^2 T), and along x,
    // x = (2 px / W - 1) a / k gives dx/dpx = 2 / (H k).
    const Surface ground = make_plane({0, 0, 0}, {0, 1, 0}, planar_mapping({0, 0, 0}, {1, 0, 0}, {0, 0, 1}));
    const Camera camera = make_camera({0, 1, 0}, {0, 1, -1}, {0, 1, 0}, 60);
    const double H = 360, T = std::tan(kPi / 6);
    for (double delta : {0.5, 1e-3, 1e-6}) {
        CAPTURE(delta);
        const double py = H / 2 + delta;
        const double k = 2 * py / H - 1;
        const std::optional<SurfaceHit> hit = intersect(ground, camera.ray(320, py));
        REQUIRE(hit);
        REQUIRE(derivatives_finite(*hit));
        CHECK(hit->point.z == doctest::Approx(-1 / (k * T)).epsilon(1e-9));
        CHECK(hit->dp_dy.z == doctest::Approx((2 / H) / (k * k * T)).epsilon(1e-9));
        CHECK(hit->dv_dy == doctest::Approx((2 / H) / (k * k * T)).epsilon(1e-9));
        CHECK(hit->du_dx == doctest::Approx(2 / (H * k)).epsilon(1e-9));
        CHECK(hit->dv_dy > 1e3);
    }
    CHECK_FALSE(intersect(ground, camera.ray(320, H / 2)));  // the horizon itself

    // A hit 1e300 away: the footprint overflows; its derivatives stay finite.
    const std::optional<SurfaceHit> far =
        intersect(ground, make_ray({0, 1, 0}, {0, -1e-300, -1}, {1e-3, 0, 0}, {0, -1e-3, 0}));
    REQUIRE(far);
    CHECK(far->t == doctest::Approx(1e300));
    CHECK(derivatives_finite(*far));
    CHECK(std::fabs(far->dv_dy) > 1e20);
}

TEST_CASE("a sphere hit through the centre is at the analytic distance")
{
    std::optional<SurfaceHit> hit = intersect(make_sphere({0, 0, -5}, 1), make_ray({0, 0, 0}, {0, 0, -1}));
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(4.0).epsilon(1e-15));
    CHECK(length(hit->point - Vec3{0, 0, -4}) < 1e-15);
    CHECK(length(hit->normal - Vec3{0, 0, 1}) < 1e-15);

    // Oblique: the centre 5 away along (3, -4, 0), radius 2.
    const Vec3 origin{1, 2, 3}, center{4, -2, 3};
    hit = intersect(make_sphere(center, 2), make_ray(origin, center - origin));
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(3.0).epsilon(1e-15));
    CHECK(length(hit->normal - Vec3{-0.6, 0.8, 0}) < 1e-15);

    // t_min between the roots: the far side, its outward normal flipped.
    hit = intersect(make_sphere({0, 0, -5}, 1), make_ray({0, 0, 0}, {0, 0, -1}), 4.5);
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(6.0).epsilon(1e-15));
    CHECK(length(hit->normal - Vec3{0, 0, 1}) < 1e-15);
}

TEST_CASE("from inside a sphere the far hit is found, its normal facing inwards")
{
    const Surface sphere = make_sphere({0, 0, -5}, 1);
    std::optional<SurfaceHit> hit = intersect(sphere, make_ray({0, 0, -5}, {0, 0, -1}));
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(1.0).epsilon(1e-15));
    CHECK(length(hit->point - Vec3{0, 0, -6}) < 1e-15);
    CHECK(length(hit->normal - Vec3{0, 0, 1}) < 1e-15);

    hit = intersect(sphere, make_ray({0.5, 0, -5}, {0, 0, 1}));
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(std::sqrt(0.75)).epsilon(1e-15));
    CHECK(length(hit->normal - normalize({-0.5, 0, -std::sqrt(0.75)})) < 1e-15);
}

TEST_CASE("a sphere behind the ray or beside it is missed")
{
    const Surface sphere = make_sphere({0, 0, -5}, 1);
    CHECK_FALSE(intersect(sphere, make_ray({0, 0, 0}, {0, 0, 1})));
    CHECK_FALSE(intersect(sphere, make_ray({0, 0, 0}, {0, 1, 0})));
    CHECK_FALSE(intersect(sphere, make_ray({0, 1.5, 0}, {0, 0, -1})));
    CHECK_FALSE(intersect(sphere, make_ray({0, 0, 0}, {0, 0, -1}), 7));
}

TEST_CASE("rays grazing a sphere hit it with finite derivatives")
{
    const Surface sphere = make_sphere({0, 0, -5}, 1, spherical_mapping(1, 1));
    const Vec3 ddx{1e-3, 0, 0}, ddy{0, -1e-3, 0};

    // Exactly tangent: <d, n> = 0, the transfer's denominator (Igehy eq. 12).
    std::optional<SurfaceHit> hit = intersect(sphere, make_ray({1, 0, 0}, {0, 0, -1}, ddx, ddy));
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(5.0).epsilon(1e-15));
    CHECK(length(hit->point - Vec3{1, 0, -5}) < 1e-15);
    CHECK(derivatives_finite(*hit));

    for (double offset : {1 - 1e-8, 1 - 1e-12}) {
        CAPTURE(offset);
        hit = intersect(sphere, make_ray({offset, 0, 0}, {0, 0, -1}, ddx, ddy));
        REQUIRE(hit);
        CHECK(hit->t == doctest::Approx(5 - std::sqrt(1 - offset * offset)).epsilon(1e-12));
        CHECK(std::fabs(length(hit->point - sphere.center) - 1) < 1e-14);
        CHECK(derivatives_finite(*hit));
    }
    CHECK_FALSE(intersect(sphere, make_ray({1 + 1e-12, 0, 0}, {0, 0, -1})));
}

TEST_CASE("spherical texture coordinates at known points")
{
    // u = u_scale phi / 2 pi with phi from +x towards +z; v = v_scale theta / pi from +y.
    const Vec3 c{1, 2, 3};
    const Surface sphere = make_sphere(c, 2, spherical_mapping(3, 2));
    struct Known {
        Vec3 axis;
        double u, v;
    };
    for (const Known& k : {Known{{1, 0, 0}, 0, 1}, Known{{0, 0, 1}, 0.75, 1}, Known{{-1, 0, 0}, 1.5, 1},
                           Known{{0, 0, -1}, 2.25, 1}, Known{normalize({1, 1, 0}), 0, 0.5}}) {
        CAPTURE(k.axis);
        const std::optional<SurfaceHit> hit = intersect(sphere, make_ray(c + 10 * k.axis, -k.axis));
        REQUIRE(hit);
        CHECK(length(hit->point - (c + 2 * k.axis)) < 1e-14);
        CHECK(hit->u == doctest::Approx(k.u).epsilon(1e-14));
        CHECK(hit->v == doctest::Approx(k.v).epsilon(1e-14));
    }
    // The poles: theta = 0 on top, pi at the bottom; u is arbitrary there but in range.
    for (const auto& axis_v : {std::pair{Vec3{0, 1, 0}, 0.0}, std::pair{Vec3{0, -1, 0}, 2.0}}) {
        const Vec3 axis = axis_v.first;
        const double v = axis_v.second;
        CAPTURE(axis);
        const std::optional<SurfaceHit> pole = intersect(sphere, make_ray(c + 10 * axis, -axis));
        REQUIRE(pole);
        CHECK(pole->v == v);
        CHECK(pole->u >= 0);
        CHECK(pole->u < 3);
    }
}

TEST_CASE("a plane's spherical mapping uses the direction from the mapping origin")
{
    TextureMapping mapping = spherical_mapping(1, 1);
    mapping.origin = {0, 0, 0};
    const Surface plane = make_plane({0, -1, 0}, {0, 1, 0}, mapping);
    const std::optional<SurfaceHit> hit = intersect(plane, make_ray({1, 1, 0}, {0, -1, 0}, {1e-3, 0, 0}, {0, 0, 1e-3}));
    REQUIRE(hit);
    CHECK(hit->u == doctest::Approx(0.0));
    CHECK(hit->v == doctest::Approx(0.75).epsilon(1e-14));  // theta = 3 pi / 4
    CHECK(derivatives_finite(*hit));
}

TEST_CASE("sphere differentials equal central differences away from the seam and the poles")
{
    const Camera camera = make_camera({0.4, 0.6, 4}, {0, 0, 0}, {0, 1, 0}, 40);
    const Surface spherical = make_sphere({0, 0, 0}, 1, spherical_mapping(4, 2));
    const Surface planar = make_sphere({0, 0, 0}, 1, planar_mapping({0.1, 0, 0}, {1, 0.5, 0}, {0, 0.3, -2}));
    for (const auto& [px, py] :
         {std::pair{320.0, 180.0}, std::pair{280.0, 150.0}, std::pair{360.5, 220.5}, std::pair{330.3, 170.7}}) {
        check_differentials(camera, spherical, px, py);
        check_differentials(camera, planar, px, py);
    }
}

TEST_CASE("on the spherical seam u jumps and du/dx stays continuous and finite")
{
    // The eye on +x: the centre pixel meets the sphere at phi = 0; px runs
    // towards -z, so u drops through 0 and wraps to u_scale.
    const Camera camera = make_camera({5, 0, 0}, {0, 0, 0}, {0, 1, 0});
    const Surface sphere = make_sphere({0, 0, 0}, 1, spherical_mapping(1, 1));
    const std::optional<SurfaceHit> seam = intersect(sphere, camera.ray(320, 180));
    REQUIRE(seam);
    CHECK(std::fabs(seam->u) < 1e-15);
    REQUIRE(derivatives_finite(*seam));
    CHECK(seam->du_dx < 0);

    const auto u_at = [&](double dx) { return intersect(sphere, camera.ray(320 + dx, 180))->u; };
    CHECK(u_at(0.5) > 0.99);
    CHECK(u_at(-0.5) < 0.01);
    const double h = 1e-3;
    double step = u_at(h) - u_at(-h);
    step -= std::round(step);  // unwrapped across the seam
    CHECK(seam->du_dx == doctest::Approx(step / (2 * h)).epsilon(1e-6));
    for (double dx : {-1e-3, 1e-3})
        CHECK(intersect(sphere, camera.ray(320 + dx, 180))->du_dx == doctest::Approx(seam->du_dx).epsilon(1e-5));
}

TEST_CASE("at a spherical pole the derivatives are finite and capped")
{
    // Looking straight down at the top pole: longitude is undefined there and
    // |du| is capped at one full turn, u_scale; |dv| is the step's angle.
    const double u_scale = 4, v_scale = 2;
    const Camera camera = make_camera({0, 5, 0}, {0, 0, 0}, {0, 0, -1});
    const Surface sphere = make_sphere({0, 0, 0}, 1, spherical_mapping(u_scale, v_scale));
    const std::optional<SurfaceHit> pole = intersect(sphere, camera.ray(320, 180));
    REQUIRE(pole);
    CHECK(pole->v == 0);
    REQUIRE(derivatives_finite(*pole));
    CHECK(std::fabs(pole->du_dx) == doctest::Approx(u_scale));
    CHECK(std::fabs(pole->du_dy) == doctest::Approx(u_scale));
    CHECK(std::fabs(pole->dv_dx) == doctest::Approx(v_scale * length(pole->dp_dx) / kPi).epsilon(1e-12));
    CHECK(std::fabs(pole->dv_dy) == doctest::Approx(v_scale * length(pole->dp_dy) / kPi).epsilon(1e-12));

    for (const auto& [px, py] : {std::pair{320.25, 180.0}, std::pair{320.0, 180.5}, std::pair{320.001, 179.999}}) {
        const std::optional<SurfaceHit> near = intersect(sphere, camera.ray(px, py));
        REQUIRE(near);
        CHECK(derivatives_finite(*near));
        CHECK(std::fabs(near->du_dx) <= u_scale * (1 + 1e-12));
        CHECK(std::fabs(near->dv_dx) <= v_scale * length(near->dp_dx) / kPi * (1 + 1e-12));
    }
}

TEST_CASE("intersect_scene returns the nearest surface")
{
    Scene scene;
    scene.surfaces = {make_plane({0, -1, 0}, {0, 1, 0}), make_sphere({0, -0.5, -5}, 1)};
    const Vec3 to_center{0, -0.5, -5};
    std::optional<SceneHit> hit = intersect_scene(scene, make_ray({0, 0, 0}, to_center));
    REQUIRE(hit);
    CHECK(hit->surface == 1);
    CHECK(hit->hit.t == doctest::Approx(length(to_center) - 1).epsilon(1e-14));
    REQUIRE(intersect(scene.surfaces[0], make_ray({0, 0, 0}, to_center)));  // the plane is behind it

    std::swap(scene.surfaces[0], scene.surfaces[1]);
    hit = intersect_scene(scene, make_ray({0, 0, 0}, to_center));
    REQUIRE(hit);
    CHECK(hit->surface == 0);

    hit = intersect_scene(scene, make_ray({0, 0, 0}, {0, -1, 1}));  // misses the sphere
    REQUIRE(hit);
    CHECK(hit->surface == 1);
    CHECK(hit->hit.t == doctest::Approx(std::sqrt(2.0)).epsilon(1e-14));

    CHECK_FALSE(intersect_scene(scene, make_ray({0, 0, 0}, {0, 1, 0})));
    CHECK_FALSE(intersect_scene(Scene{}, make_ray({0, 0, 0}, {0, -1, 0})));
}
