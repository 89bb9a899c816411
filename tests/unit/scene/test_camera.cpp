// SPDX-License-Identifier: Apache-2.0
// The pinhole camera: its rays against the angles of the field of view, its
// ray differentials against finite differences of neighbouring rays, and the
// inputs Camera::create rejects.
#include "cmfilter/scene/camera.h"

#include "render_test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace cmfilter;
using cmfilter_test::angle_between;
using cmfilter_test::central_difference;
using cmfilter_test::make_scene_camera;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Oblique views: landscape, portrait and very wide.
std::vector<SceneCamera> test_cameras()
{
    return {make_scene_camera({1, 2, 3}, {4, 0, -1}, {0, 1, 0}, 50, 640, 360),
            make_scene_camera({-2, 0.5, 1}, {0, 0, 0}, {0.2, 1, 0.1}, 90, 100, 300),
            make_scene_camera({0, 0, 0}, {0, -1, -3}, {0, 0, -1}, 170, 33, 17)};
}

Camera create_camera(const SceneCamera& scene_camera)
{
    auto camera = Camera::create(scene_camera);
    REQUIRE(camera);
    return *camera;
}

// The message of the BadInput that create gives for `scene_camera`.
std::string rejection(const SceneCamera& scene_camera)
{
    auto camera = Camera::create(scene_camera);
    REQUIRE_FALSE(camera);
    CHECK(camera.error().kind == ErrorKind::BadInput);
    return camera.error().message;
}

}  // namespace

TEST_CASE("the centre pixel's ray starts at the camera and looks at look_at")
{
    for (const SceneCamera& sc : test_cameras()) {
        const Camera camera = create_camera(sc);
        const CameraRay ray = camera.ray(0.5 * sc.width, 0.5 * sc.height);
        CHECK(ray.origin == sc.position);
        CHECK(length(ray.direction - normalize(sc.look_at - sc.position)) < 1e-14);
    }
}

TEST_CASE("edge and corner rays make the angles of the field of view")
{
    for (const SceneCamera& sc : test_cameras()) {
        CAPTURE(sc.fov_degrees);
        const Camera camera = create_camera(sc);
        const double W = sc.width, H = sc.height;
        const Vec3 view = sc.look_at - sc.position;
        const double tan_half = std::tan(sc.fov_degrees * kPi / 360);
        const double aspect = W / H;
        const double vertical = sc.fov_degrees * kPi / 360;
        const double horizontal = std::atan(aspect * tan_half);
        const double diagonal = std::atan(tan_half * std::sqrt(1 + aspect * aspect));
        const auto angle_at = [&](double px, double py) { return angle_between(camera.ray(px, py).direction, view); };
        CHECK(angle_at(W / 2, 0) == doctest::Approx(vertical).epsilon(1e-12));
        CHECK(angle_at(W / 2, H) == doctest::Approx(vertical).epsilon(1e-12));
        CHECK(angle_at(0, H / 2) == doctest::Approx(horizontal).epsilon(1e-12));
        CHECK(angle_at(W, H / 2) == doctest::Approx(horizontal).epsilon(1e-12));
        for (double px : {0.0, W})
            for (double py : {0.0, H}) CHECK(angle_at(px, py) == doctest::Approx(diagonal).epsilon(1e-12));

        // px runs right, py runs down: right is view x up, the image's up the
        // part of the scene's up across the view direction.
        const Vec3 world_right = cross(view, sc.up);
        const Vec3 image_up = sc.up - dot(sc.up, normalize(view)) * normalize(view);
        CHECK(dot(camera.ray(W, H / 2).direction, world_right) > 0);
        CHECK(dot(camera.ray(0, H / 2).direction, world_right) < 0);
        CHECK(dot(camera.ray(W / 2, 0).direction, image_up) > 0);
        CHECK(dot(camera.ray(W / 2, H).direction, image_up) < 0);
    }
}

TEST_CASE("ray directions are unit length over the whole image")
{
    for (const SceneCamera& sc : test_cameras()) {
        const Camera camera = create_camera(sc);
        for (int j = 0; j <= 8; ++j)
            for (int i = 0; i <= 8; ++i) {
                const double px = sc.width * i / 8.0, py = sc.height * j / 8.0;
                CHECK(length(camera.ray(px, py).direction) == doctest::Approx(1.0).epsilon(1e-15));
            }
    }
}

TEST_CASE("ray differentials equal central differences of neighbouring rays")
{
    const double h = 1e-4;
    for (const SceneCamera& sc : test_cameras()) {
        CAPTURE(sc.fov_degrees);
        const Camera camera = create_camera(sc);
        const double W = sc.width, H = sc.height;
        for (const auto& pixel : {std::pair{0.5, 0.5}, std::pair{W - 0.5, H / 3}, std::pair{0.37 * W, H - 0.5},
                                  std::pair{0.5 * W, 0.5 * H}}) {
            // Named copies, not structured bindings: the checks' lambdas capture them.
            const double px = pixel.first, py = pixel.second;
            CAPTURE(px);
            CAPTURE(py);
            const CameraRay ray = camera.ray(px, py);
            const Vec3 fd_x = central_difference([&](double s) { return camera.ray(px + s, py).direction; }, h);
            const Vec3 fd_y = central_difference([&](double s) { return camera.ray(px, py + s).direction; }, h);
            CAPTURE(ray.d_direction_dx);
            CAPTURE(fd_x);
            CHECK(length(ray.d_direction_dx - fd_x) <= 1e-7 * length(fd_x));
            CAPTURE(ray.d_direction_dy);
            CAPTURE(fd_y);
            CHECK(length(ray.d_direction_dy - fd_y) <= 1e-7 * length(fd_y));
        }
    }
}

TEST_CASE("create rejects a degenerate view, naming the value")
{
    SceneCamera sc = make_scene_camera({1, 2, 3}, {1, 2, 3}, {0, 1, 0}, 60, 64, 48);
    std::string message = rejection(sc);
    CHECK(message.find("(1, 2, 3)") != std::string::npos);
    CHECK(message.find("zero") != std::string::npos);

    sc.look_at = {1, 2, 0};
    sc.up = {0, 0, 0};
    message = rejection(sc);
    CHECK(message.find("up (0, 0, 0)") != std::string::npos);

    for (const Vec3& parallel_up : {Vec3{0, 0, 2}, Vec3{0, 0, -0.5}, Vec3{0, 1e-12, 1}}) {
        sc.up = parallel_up;
        message = rejection(sc);
        CAPTURE(message);
        CHECK(message.find("up (0, ") != std::string::npos);
        CHECK(message.find("parallel") != std::string::npos);
    }
    sc.up = {0, 1e-6, 1};  // nearly parallel is still a camera
    CHECK(Camera::create(sc));

    sc.up = {std::nan(""), 1, 0};
    message = rejection(sc);
    CHECK(message.find("up (nan, 1, 0)") != std::string::npos);
}

TEST_CASE("create rejects a field of view outside (0, 180), naming the value")
{
    SceneCamera sc = make_scene_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, 64, 48);
    for (double fov : {0.0, 180.0, -30.0, 200.0}) {
        sc.fov_degrees = fov;
        const std::string message = rejection(sc);
        CAPTURE(message);
        std::ostringstream value;
        value << "fov_degrees " << fov;
        CHECK(message.find(value.str()) != std::string::npos);
    }
    for (double fov : {1e-3, 179.9}) {
        sc.fov_degrees = fov;
        CHECK(Camera::create(sc));
    }
}

TEST_CASE("create rejects a resolution outside the limits, naming the value")
{
    SceneCamera sc = make_scene_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, 64, 48);
    const auto rejected_with = [&](int width, int height, const std::string& expected) {
        sc.width = width;
        sc.height = height;
        const std::string message = rejection(sc);
        CAPTURE(message);
        CHECK(message.find(expected) != std::string::npos);
    };
    rejected_with(0, 48, "width 0");
    rejected_with(64, 0, "height 0");
    rejected_with(-3, 48, "width -3");
    rejected_with(kMaxImageSide + 1, 1, "width 16385");
    rejected_with(1, kMaxImageSide + 1, "height 16385");
    rejected_with(kMaxImageSide, kMaxImageSide / 2, "16384 x 8192");  // 2^27 pixels

    for (const auto& [width, height] : {std::pair{1, 1}, std::pair{kMaxImageSide, 1}, std::pair{8192, 8192}}) {
        sc.width = width;
        sc.height = height;
        const auto camera = Camera::create(sc);
        REQUIRE(camera);
        CHECK(camera->width() == width);
        CHECK(camera->height() == height);
    }
}
