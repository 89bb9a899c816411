// SPDX-License-Identifier: Apache-2.0
// Geometric coverage of box pixels (pixel_coverage.h, surface_outline.h)
// against dense sampling of each pixel with ray-surface tests written out
// here: a sphere's silhouette, a tilted horizon, a sphere in front of a
// plane across its horizon, and a sphere sunk into a plane (a meeting of
// surfaces). Every pixel the dense samples find mixed is on an edge, the
// shares match, and each share's representative point sees its surface.
// Then renders: with coverage, the far sphere's silhouette pixels match a
// supersampled reference as closely as its interior pixels do; without,
// they do not.
#include "cmfilter/scene/camera.h"
#include "cmfilter/color/ciede2000.h"
#include "cmfilter/color/color_config.h"
#include "cmfilter/scene/pixel_coverage.h"
#include "cmfilter/render/render.h"
#include "cmfilter/scene/scene_loading.h"
#include "cmfilter/scene/scene_materials.h"

#include "render_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

using namespace cmfilter;
using cmfilter_test::make_scene_camera;

namespace {

Surface sphere(const Vec3& centre, double radius)
{
    Surface s;
    s.kind = SurfaceKind::Sphere;
    s.center = centre;
    s.radius = radius;
    return s;
}

Surface plane(const Vec3& point, const Vec3& normal)
{
    Surface s;
    s.kind = SurfaceKind::Plane;
    s.point = point;
    s.normal = normalize(normal);
    return s;
}

// The nearest surface along a unit direction from o, from the textbook
// equations (not surface_hit.h): a sphere's far root must be ahead, its near
// root if ahead; a plane's t = <p0 - o, n> / <d, n> > 0. -1: none.
int nearest_surface(const Scene& scene, const Vec3& o, const Vec3& d)
{
    int best = -1;
    double best_t = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        const Surface& s = scene.surfaces[i];
        double t = -1;
        if (s.kind == SurfaceKind::Sphere) {
            const Vec3 oc = o - s.center;
            const double b = dot(oc, d), c = dot(oc, oc) - s.radius * s.radius, disc = b * b - c;
            if (disc < 0) continue;
            const double near = -b - std::sqrt(disc), far = -b + std::sqrt(disc);
            t = near > 0 ? near : far;
        } else {
            const double facing = dot(d, s.normal);
            if (facing == 0) continue;
            t = dot(s.point - o, s.normal) / facing;
        }
        if (t > 0 && t < best_t) {
            best_t = t;
            best = static_cast<int>(i);
        }
    }
    return best;
}

// Shares of pixel (x, y) by an n x n midpoint grid: id -> share (-1: background).
std::map<int, double> sampled_shares(const Scene& scene, const Camera& camera, int x, int y, int n)
{
    std::map<int, double> shares;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const CameraRay r = camera.ray(x + (i + 0.5) / n, y + (j + 0.5) / n);
            shares[nearest_surface(scene, r.origin, r.direction)] += 1.0 / (n * n);
        }
    return shares;
}

struct CoverageCheck {
    int mixed = 0;         // pixels the coarse grid finds mixed
    int edges = 0;         // pixels on_edge names
    int missed = 0;        // mixed but not on_edge
    double max_error = 0;  // largest share difference over the edge pixels
    double mean_error = 0;
    int misplaced = 0;  // representative points that see another surface
};

// Every pixel: coarse samples for mixed pixels; on the edge pixels, the
// shares against a dense grid.
CoverageCheck check_coverage(const Scene& scene, int coarse, int dense)
{
    auto camera = Camera::create(scene.camera);
    REQUIRE(camera);
    const PixelCoverage coverage(scene, *camera);
    CoverageCheck check;
    PixelCover cover;
    int compared = 0;
    for (int y = 0; y < camera->height(); ++y)
        for (int x = 0; x < camera->width(); ++x) {
            const bool mixed = sampled_shares(scene, *camera, x, y, coarse).size() > 1;
            const bool edge = coverage.on_edge(x, y);
            check.mixed += mixed;
            check.edges += edge;
            check.missed += mixed && !edge;
            if (!edge) continue;
            coverage.cover(x, y, cover);
            std::map<int, double> got{{-1, cover.background}};
            double total = cover.background;
            for (const CoveragePiece& piece : cover.pieces) {
                got[piece.surface] += piece.share;
                total += piece.share;
                const CameraRay r = camera->ray(piece.px, piece.py);
                check.misplaced += nearest_surface(scene, r.origin, r.direction) != piece.surface;
                CHECK(piece.px >= x);
                CHECK(piece.px <= x + 1);
                CHECK(piece.py >= y);
                CHECK(piece.py <= y + 1);
            }
            CHECK(total == doctest::Approx(1.0).epsilon(1e-12));
            std::map<int, double> want = sampled_shares(scene, *camera, x, y, dense);
            for (const auto& [id, share] : want) got[id] += 0;  // ids on either side
            for (const auto& [id, share] : got) {
                const double error = std::fabs(share - want[id]);
                check.max_error = std::max(check.max_error, error);
                check.mean_error += error;
                ++compared;
            }
        }
    if (compared > 0) check.mean_error /= compared;
    return check;
}

Scene scene_with(const SceneCamera& camera, std::vector<Surface> surfaces)
{
    Scene s;
    s.camera = camera;
    s.surfaces = std::move(surfaces);
    return s;
}

// The dense grid (256 x 256) is itself off by up to about 1/512 of a pixel
// along an edge parallel to its rows; the strips add at most 1/2048 per
// corner cut and a little curvature. 0.004 fails a strip count off by a
// factor of two for a steep edge (1/32 for the worst vertical edge with
// strips the wrong way round).
constexpr double kShareTolerance = 0.004;

// What every scene must show: no mixed pixel missed, the shares within
// kShareTolerance of the dense grid's (0.0005 on average), and every
// representative point on its own surface.
void check_accurate(const CoverageCheck& c)
{
    MESSAGE("mixed " << c.mixed << ", on edge " << c.edges << ", missed " << c.missed << ", share error max "
                     << c.max_error << " mean " << c.mean_error << ", misplaced " << c.misplaced);
    CHECK(c.missed == 0);
    CHECK(c.max_error <= kShareTolerance);
    CHECK(c.mean_error <= 0.0005);
    CHECK(c.misplaced == 0);
}

}  // namespace

TEST_CASE("pixel coverage: a sphere's silhouette against dense sampling of each pixel")
{
    // Off-axis, so the silhouette is an ellipse; about 20 pixels across.
    const Scene s =
        scene_with(make_scene_camera({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 30, 48, 40), {sphere({1.2, -0.5, 10}, 1.3)});
    const CoverageCheck c = check_coverage(s, 16, 256);
    check_accurate(c);
    CHECK(c.mixed > 40);
    CHECK(c.edges <= 2 * c.mixed);  // the cheap test names few pixels beyond the silhouette
}

TEST_CASE("pixel coverage: a tilted horizon against dense sampling of each pixel")
{
    const Scene s = scene_with(make_scene_camera({0, 1.5, 0}, {0, 0.9, 10}, {0.35, 1, 0}, 50, 40, 30),
                               {plane({0, 0, 0}, {0, 1, 0})});
    const CoverageCheck c = check_coverage(s, 16, 256);
    check_accurate(c);
    CHECK(c.mixed >= 40);  // the horizon crosses the image
    CHECK(c.edges <= 2 * c.mixed);
}

TEST_CASE("pixel coverage: a sphere in front of a plane, across its horizon, takes the nearest surface")
{
    const Scene s = scene_with(make_scene_camera({0, 1.5, 0}, {0, 1.2, 10}, {0.1, 1, 0}, 40, 48, 36),
                               {plane({0, 0, 0}, {0, 1, 0}), sphere({0.5, 1.6, 9}, 1.0)});
    check_accurate(check_coverage(s, 16, 256));
}

TEST_CASE("pixel coverage: a sphere sunk into a plane, where the surfaces meet")
{
    // The circle where they meet is an edge no outline names.
    const Scene s = scene_with(make_scene_camera({0, 2.5, 0}, {0, 0, 8}, {0, 1, 0}, 40, 40, 32),
                               {plane({0, 0, 0}, {0, 1, 0}), sphere({0.3, 0.4, 8}, 1.2)});
    const CoverageCheck c = check_coverage(s, 16, 256);
    check_accurate(c);
    CHECK(c.mixed > 40);
}

TEST_CASE("pixel coverage: a pixel wholly on one surface has the whole box as its footprint")
{
    const Scene s = scene_with(make_scene_camera({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 30, 48, 40), {sphere({0, 0, 10}, 2)});
    auto camera = Camera::create(s.camera);
    REQUIRE(camera);
    const PixelCoverage coverage(s, *camera);
    CHECK_FALSE(coverage.on_edge(24, 20));  // the middle of the disc
    CHECK_FALSE(coverage.on_edge(0, 0));    // the corner, far outside
    PixelCover cover;
    coverage.cover(24, 20, cover);
    REQUIRE(cover.pieces.size() == 1);
    CHECK(cover.background == 0);
    CHECK(cover.pieces[0].share == doctest::Approx(1.0));
    CHECK(cover.pieces[0].m00 == doctest::Approx(1.0).epsilon(1e-9));
    CHECK(cover.pieces[0].m11 == doctest::Approx(1.0).epsilon(1e-9));
    CHECK(std::fabs(cover.pieces[0].m01) < 1e-9);
    // Its hit carries the centre ray's differentials.
    const auto h = coverage.hit(cover.pieces[0]);
    const auto centre = intersect(s.surfaces[0], camera->ray(24.5, 20.5));
    REQUIRE(h);
    REQUIRE(centre);
    CHECK(h->du_dx == doctest::Approx(centre->du_dx).epsilon(1e-6));
    CHECK(h->dv_dy == doctest::Approx(centre->dv_dy).epsilon(1e-6));
}

TEST_CASE(
    "render: with edge coverage the far sphere's silhouette pixels match a supersampled render as the interior does")
{
    // examples/scenes/sphere-fbm-far.json at 64 x 64 with the field of view
    // narrowed to keep the sphere 34 pixels across, as at 480 x 480, and its
    // noise 128 times coarser (a few pixels per base period), so that a
    // 1024-ray reference is exact enough and the texture filtering's own
    // error stays below the silhouette's.
    auto scene = load_scene(std::string(CMFILTER_SOURCE_DIR) + "/examples/scenes/sphere-fbm-far.json");
    REQUIRE(scene);
    scene->surfaces[0].mapping.u_scale = 16;
    scene->surfaces[0].mapping.v_scale = 8;
    const double kPi = 3.14159265358979323846;
    scene->camera.fov_degrees = 2 * std::atan(std::tan(20 * kPi / 180) * 64 / 480) * 180 / kPi;
    scene->camera.width = scene->camera.height = 64;
    auto config = ColorConfig::load("");
    REQUIRE(config);
    auto materials = prepare_materials(*scene, *config, MaterialOptions{});
    REQUIRE(materials);
    auto camera = Camera::create(scene->camera);
    REQUIRE(camera);

    RenderOptions options;
    options.method = RenderMethod::Reference;
    options.seed = 5;
    auto reference = render(*scene, *materials, options);
    REQUIRE(reference);
    // Silhouette pixels: those the dense grid finds between 5% and 95%
    // covered; interior pixels: wholly on the sphere.
    std::vector<std::size_t> silhouette, interior;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const double background = sampled_shares(*scene, *camera, x, y, 32)[-1];
            const auto p = static_cast<std::size_t>(y * 64 + x);
            if (background > 0.05 && background < 0.95) silhouette.push_back(p);
            if (background == 0) interior.push_back(p);
        }
    CHECK(silhouette.size() > 80);
    CHECK(interior.size() > 600);
    const auto mean_error = [&](const RenderedImage& image, const std::vector<std::size_t>& pixels) {
        double sum = 0;
        for (std::size_t p : pixels) {
            const Rgb a{reference->rgb[3 * p], reference->rgb[3 * p + 1], reference->rgb[3 * p + 2]};
            const Rgb b{image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]};
            sum += ciede2000_linear_rgb(a, b);
        }
        return sum / static_cast<double>(pixels.size());
    };
    for (RenderMethod method : {RenderMethod::Gaussian, RenderMethod::Naive}) {
        CAPTURE(to_string(method));
        options.method = method;
        options.edge_coverage = true;
        auto covered = render(*scene, *materials, options);
        options.edge_coverage = false;
        auto centre_only = render(*scene, *materials, options);
        REQUIRE(covered);
        REQUIRE(centre_only);
        const double with = mean_error(*covered, silhouette), without = mean_error(*centre_only, silhouette);
        const double inside = mean_error(*covered, interior);
        MESSAGE(std::string(to_string(method)) << ": silhouette mean CIEDE2000 " << with << " with coverage, "
                                               << without << " without; interior " << inside);
        // As close as the interior, where only the texture filtering errs
        // (about 1.7 against 2.0 for gaussian, 3.0 against 3.1 for naive),
        // and far closer than without coverage (8.8, 10.8).
        CHECK(with <= 1.25 * inside);
        CHECK(with <= 0.4 * without);
        // Interior pixels are untouched: the AOVs are the centre ray's.
        CHECK(covered->hit == centre_only->hit);
        CHECK(covered->mean == centre_only->mean);
    }
}
