// SPDX-License-Identifier: Apache-2.0
// Synthetic stack images (synthetic_stack.h) against closed forms and
// quadrature of the traced surface, computed here from the texel heights:
// a flat displacement gives colour x cos exactly (with each specular lobe
// evaluated here from its formula); a 1-D sinusoid relief, the bilinear
// (here piecewise-linear) interpolant of its texel centres, gives per pixel
// the colour times the exact mean of <n, l> over the pixel's square (4 x 4
// strata each lie inside one linear piece, so the estimate is exact); at a
// low light the shadowed pixels match a brute-force 1-D horizon test; the
// frames (a light from +y lights the slopes facing the top row); the true
// mean normals; the same images for 1 and 2 threads.
#include "cmfilter/synthetic/synthetic_stack.h"

#include "synthetic_test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kTexels = 64;  // displacement texels per side
constexpr int kSize = 32;    // pixels per side

// The piecewise-linear profile through texel centres (k + 1/2) / N of
// heights H[k], periodic with period 1: slope of the piece holding x.
struct Profile {
    std::vector<double> h;
    int n() const { return static_cast<int>(h.size()); }
    double at_node(long k) const { return h[((k % n()) + n()) % n()]; }
    // The piece [ (k + 1/2) / N, (k + 3/2) / N ] holding x.
    long piece(double x) const { return static_cast<long>(std::floor(x * n() - 0.5)); }
    double slope(double x) const
    {
        const long k = piece(x);
        return (at_node(k + 1) - at_node(k)) * n();
    }
    double height(double x) const
    {
        const long k = piece(x);
        const double x0 = (k + 0.5) / n();
        return at_node(k) + (x - x0) * (at_node(k + 1) - at_node(k)) * n();
    }
    // The integral of f(slope) over [a, b], split at the nodes.
    double integral(double a, double b, const std::function<double(double)>& f) const
    {
        double sum = 0;
        for (double x = a; x < b;) {
            const double next = std::min(b, (piece(x) + 1.5) / n());
            sum += (next - x) * f(slope(0.5 * (x + next)));
            x = next;
        }
        return sum;
    }
};

Profile sinusoid(double amplitude)
{
    Profile p;
    for (int k = 0; k < kTexels; ++k) p.h.push_back(amplitude * std::sin(2 * kPi * (k + 0.5) / kTexels));
    return p;
}

SyntheticStack render(const SyntheticSurface& s, const std::vector<Vec3>& lights, const Vec3& view = {0, 0, 1},
                      int threads = 2, SpecularLobe lobe = {})
{
    SyntheticStackOptions o;
    o.size = kSize;
    o.samples = 16;
    o.view = view;
    o.threads = threads;
    o.seed = 5;
    o.specular = lobe;
    auto stack = render_synthetic_stack(s, lights, o);
    REQUIRE_MESSAGE(stack, (stack ? "" : stack.error().message));
    return std::move(*stack);
}

double channel(const SyntheticStack& s, std::size_t light, int i, int j, int c)
{
    return s.image(light)[(static_cast<std::size_t>(j) * s.size + i) * 3 + c];
}

Vec3 unit(double x, double y, double z) { return normalize(Vec3{x, y, z}); }

}  // namespace

TEST_CASE("synthetic stack: a flat surface under any light and view gives colour x cos, plus each lobe's formula")
{
    const std::string dir = temp_dir("cmfilter-synthetic-flat");
    const SyntheticSurface s =
        load_synthetic_surface(write_displacement_scene(dir, "flat", 16, [](int, int) { return 0.1; }));
    const std::vector<Vec3> lights = {unit(0, 0, 1), unit(0.7, 0.2, 0.4), unit(-0.3, 0.9, 0.2), unit(0.1, -0.5, 0.8)};
    const Vec3 view = unit(0.3, 0.2, 0.9);
    const Rgb c = synthetic_test_color();

    // Blinn-Phong's normalisation by quadrature over the hemisphere (view
    // along the normal), independent of the closed form.
    const double n = 20;
    double bp_norm = 0;
    const int steps = 20000;
    for (int k = 0; k < steps; ++k) {
        const double theta = 0.5 * kPi * (k + 0.5) / steps;
        bp_norm += std::pow(std::cos(0.5 * theta), n) * std::cos(theta) * std::sin(theta) * (0.5 * kPi / steps);
    }
    bp_norm *= 2 * kPi;
    const auto blinn = [&](const Vec3& l) {
        const Vec3 h = normalize(l + view);
        return 0.3 * kPi * std::pow(h.z, n) / bp_norm;
    };
    // GGX (Walter et al. 2007) for m = z.
    const double alpha = 0.3, f0 = 0.04;
    const auto ggx = [&](const Vec3& l) {
        const Vec3 h = normalize(l + view);
        const double a2 = alpha * alpha;
        const double d = a2 / (kPi * std::pow(h.z * h.z * (a2 - 1) + 1, 2));
        const auto g1 = [&](double c) { return 2 * c / (c + std::sqrt(a2 + (1 - a2) * c * c)); };
        const double f = f0 + (1 - f0) * std::pow(1 - dot(h, l), 5);
        return kPi * d * g1(l.z) * g1(view.z) * f / (4 * l.z * view.z);
    };
    struct Case {
        SpecularLobe lobe;
        std::function<double(const Vec3&)> spec;
    };
    const std::vector<Case> cases = {{{}, [](const Vec3&) { return 0.0; }},
                                     {{SpecularKind::BlinnPhong, 0.3, n, 0.2}, blinn},
                                     {{SpecularKind::Ggx, f0, 32, alpha}, ggx}};
    for (const Case& k : cases) {
        const SyntheticStack stack = render(s, lights, view, 2, k.lobe);
        for (std::size_t l = 0; l < lights.size(); ++l) {
            const double spec = k.spec(lights[l]);
            for (int j = 0; j < kSize; j += 7)
                for (int i = 0; i < kSize; i += 5)
                    for (int ch = 0; ch < 3; ++ch)
                        CHECK(channel(stack, l, i, j, ch) ==
                              doctest::Approx(lights[l].z * (c[ch] + spec)).epsilon(1e-5));
        }
        for (float v : stack.normals) CHECK(std::abs(v) == doctest::Approx(v > 0.5f ? 1.0 : 0.0).epsilon(1e-6));
    }
}

TEST_CASE("synthetic stack: a sinusoid relief lit without shadows gives colour x the pixel's mean <n, l> by quadrature")
{
    const Profile p = sinusoid(0.05);
    const std::string dir = temp_dir("cmfilter-synthetic-sinusoid");
    const SyntheticSurface s =
        load_synthetic_surface(write_displacement_scene(dir, "sin-u", kTexels, [&](int i, int) { return p.h[i]; }));
    const std::vector<Vec3> lights = {unit(0, 0, 1), unit(0.5, 0, 0.866), unit(-0.4, 0.3, 0.866)};
    const SyntheticStack stack = render(s, lights);
    const Rgb c = synthetic_test_color();
    for (std::size_t l = 0; l < lights.size(); ++l)
        for (int i = 0; i < kSize; ++i) {
            const double a = double(i) / kSize, b = double(i + 1) / kSize;
            const Vec3 L = lights[l];
            const double mean = p.integral(a, b, [&](double sl) {
                return std::max(0.0, (-sl * L.x + L.z) / std::sqrt(1 + sl * sl));
            }) / (b - a);
            for (int j = 0; j < kSize; j += 9)
                for (int ch = 0; ch < 3; ++ch)
                    CHECK(channel(stack, l, i, j, ch) == doctest::Approx(c[ch] * mean).epsilon(1e-5));
        }
    // The true mean normal: the normalised mean of the pieces' normals.
    for (int i = 0; i < kSize; ++i) {
        const double a = double(i) / kSize, b = double(i + 1) / kSize;
        const double nx = p.integral(a, b, [](double sl) { return -sl / std::sqrt(1 + sl * sl); });
        const double nz = p.integral(a, b, [](double sl) { return 1 / std::sqrt(1 + sl * sl); });
        const Vec3 n = normalize(Vec3{nx, 0, nz});
        const std::size_t t = static_cast<std::size_t>(3) * kSize + i;
        CHECK(stack.normals[3 * t] == doctest::Approx(n.x).epsilon(1e-5));
        CHECK(stack.normals[3 * t + 1] == doctest::Approx(0).epsilon(1e-6));
        CHECK(stack.normals[3 * t + 2] == doctest::Approx(n.z).epsilon(1e-5));
    }
}

TEST_CASE("synthetic stack: a light from +y lights the slopes that face the top row")
{
    // Heights vary along the rows (v, downwards); in the stack's frame y = -v,
    // so the slope facing +y is where the height rises towards the rows
    // below: n = (0, dh/dv, 1) / |.|.
    const Profile p = sinusoid(0.05);
    const std::string dir = temp_dir("cmfilter-synthetic-frame");
    const SyntheticSurface s =
        load_synthetic_surface(write_displacement_scene(dir, "sin-v", kTexels, [&](int, int j) { return p.h[j]; }));
    const Vec3 from_top = unit(0, 0.5, 0.866);
    const SyntheticStack stack = render(s, {from_top});
    const Rgb c = synthetic_test_color();
    int brighter = 0, darker = 0;
    for (int j = 0; j < kSize; ++j) {
        const double a = double(j) / kSize, b = double(j + 1) / kSize;
        const double mean = p.integral(a, b, [&](double sv) {
            return (sv * from_top.y + from_top.z) / std::sqrt(1 + sv * sv);
        }) / (b - a);
        const double value = channel(stack, 0, 11, j, 0);
        CHECK(value == doctest::Approx(c.r * mean).epsilon(1e-5));
        const double rise = p.integral(a, b, [](double sv) { return sv; });  // h(b) - h(a)
        if (rise > 1e-3) {
            CHECK(value > c.r * from_top.z);
            CHECK(stack.normals[3 * (static_cast<std::size_t>(j) * kSize + 11) + 1] > 0);
            ++brighter;
        } else if (rise < -1e-3) {
            CHECK(value < c.r * from_top.z);
            CHECK(stack.normals[3 * (static_cast<std::size_t>(j) * kSize + 11) + 1] < 0);
            ++darker;
        }
    }
    CHECK(brighter > 8);
    CHECK(darker > 8);
}

TEST_CASE("synthetic stack: hard shadows at a low light match a brute-force 1-D horizon test")
{
    const Profile p = sinusoid(0.08);
    const std::string dir = temp_dir("cmfilter-synthetic-shadow");
    const SyntheticSurface s = load_synthetic_surface(
        write_displacement_scene(dir, "sin-shadow", kTexels, [&](int i, int) { return p.h[i]; }));
    const double elevation = 15 * kPi / 180;
    const Vec3 L{std::cos(elevation), 0, std::sin(elevation)};
    const SyntheticStack stack = render(s, {L});
    const Rgb c = synthetic_test_color();
    // A point is lit when its piece faces the light and no node ahead along
    // +u rises above the ray (the profile is linear between nodes, so its
    // highest point over the ray's path is a node).
    const auto lit = [&](double x) {
        const double sl = p.slope(x);
        if (-sl * L.x + L.z <= 0) return false;
        const double h0 = p.height(x), rise = std::tan(elevation);
        for (long k = p.piece(x) + 1; (k + 0.5) / kTexels - x < 1.5; ++k) {
            const double d = (k + 0.5) / kTexels - x;
            if (d > 0 && p.at_node(k) > h0 + d * rise) return false;
        }
        return true;
    };
    int dark = 0, bright = 0;
    for (int i = 0; i < kSize; ++i) {
        int count = 0;
        const int fine = 256;
        for (int f = 0; f < fine; ++f) count += lit((i + (f + 0.5) / fine) / kSize);
        const double value = channel(stack, 0, i, 4, 1);
        if (count == 0) {
            CHECK(value == 0);
            ++dark;
        } else if (count == fine) {
            const double a = double(i) / kSize, b = double(i + 1) / kSize;
            const double mean =
                p.integral(a, b, [&](double sl) { return (-sl * L.x + L.z) / std::sqrt(1 + sl * sl); }) / (b - a);
            CHECK(value == doctest::Approx(c.g * mean).epsilon(1e-5));
            ++bright;
        } else {
            CHECK(value >= 0);
            CHECK(value < c.g);
        }
    }
    CHECK(dark >= 3);
    CHECK(bright >= 3);
}

TEST_CASE("synthetic stack: a Gaussian microsurface's images are the same for 1 and 2 threads")
{
    const std::string dir = temp_dir("cmfilter-synthetic-threads");
    const std::string path = dir + "/micro.json";
    std::ofstream(path) << R"({
      "camera": {"position": [0, 1, 0], "look_at": [0, 0, 4], "resolution": [8, 8]},
      "light": {"direction": [0, 1, 0]},
      "surfaces": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
        "mapping": {"type": "planar", "u_axis": [1, 0, 0], "v_axis": [0, 0, 1]},
        "material": {"slope_colormap": {"image": ")" +
                               std::string(CMFILTER_SOURCE_DIR) + R"(/luts/grass-rock.png", "by": "steepness"},
          "microsurface": {"sigma_h": 0.02, "min_wavelength": 0.1, "max_wavelength": 0.4, "cosines": 64}}}]})";
    const SyntheticSurface s = load_synthetic_surface(path);
    CHECK(s.kind() == SyntheticSurfaceKind::Microsurface);
    CHECK(s.tile() == doctest::Approx(3.2));
    const std::vector<Vec3> lights = {unit(0, 0, 1), unit(0.8, 0.1, 0.3), unit(-0.2, -0.9, 0.3)};
    SpecularLobe lobe{SpecularKind::Ggx, 0.04, 32, 0.2};
    const SyntheticStack one = render(s, lights, unit(0.2, 0.1, 1), 1, lobe);
    const SyntheticStack two = render(s, lights, unit(0.2, 0.1, 1), 2, lobe);
    CHECK(one.pixels == two.pixels);
    CHECK(one.normals == two.normals);
    // Relief: the images are not flat, and the low lights cast shadows.
    int zeros = 0;
    for (std::size_t t = 0; t < one.texels(); ++t) zeros += one.image(1)[3 * t] == 0;
    CHECK(zeros > 0);
    CHECK(one.hits == one.rays);
}
