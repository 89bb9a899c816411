// SPDX-License-Identifier: Apache-2.0
// How far the slope-filtered colour <C_s, D_s> of eq. 20 computed with the
// Gaussian of D_s's exact moments (gaussian_slope_color) is from the colour
// over the exact D_s (exact_slope_color), in CIEDE2000 (scene-linear
// Rec.709), for two slope colour maps made here (docs/slope.md):
//   grass-rock  a steepness map over the slope angle in degrees (36 texels
//               over 0..90): grass up to 25, rock from 35 to 60, dark cliff
//               from 70, linear blends between;
//   hue-wheel   a 64 x 64 slope-vector map over [-2, 2]^2: hue the slope's
//               direction atan2(s_y, s_x), saturation |s| (full from
//               |s| = 1), white on the flat.
// Slopes N(m, Sigma) of three shapes, sigma_s the standard deviation along x:
//   isotropic   Sigma = sigma_s^2 I, m = 0;
//   anisotropic sigma_s along x, sigma_s / 2 along y, correlation 0.5, m = 0;
//   tilted      Sigma = sigma_s^2 I, m = (0.3, -0.2).
// Sweeps (table 3): sigma_s = 0.1, 0.2, ..., 1.0; view azimuths 0, 45, ...,
// 315 degrees; theta_o = 0, 2, ..., 80 degrees, and separately 81, 82, ...,
// 89, 89.5, 89.9 degrees. Table 1 takes theta_o in {0, 40, 70, 80, 85, 89,
// 89.9}, sigma_s in {0.1, 0.4, 1.0}, azimuths {0, 60, 200}; table 2 theta_o
// in {0, 20, 40, 60, 70, 80, 85, 89}, sigma_s in {0.1, 0.2, 0.4, 0.7, 1.0},
// azimuths {0, 45, 150, 270}; each over the three shapes.
// Three tables:
//   1. the reference's convergence: exact_slope_color with 8 to 64 panels
//      per axis against 128;
//   2. the Gauss-Hermite points per axis: gaussian_slope_color with n points
//      against a dense quadrature over the same Gaussian, the one of D_s's
//      moments (exact_slope_color with 64 panels at normal incidence, where
//      D_s is the slope Gaussian itself), and that dense quadrature against
//      the exact D_s colour: what the Gaussian itself leaves;
//   3. the accuracy: the Gaussian-moment colour with n x n points (n = 6 to
//      24, the default marked) and with the dense quadrature (32 panels)
//      against the exact D_s colour (the default 32 panels), mean and max
//      over each sweep, and where the default's worst case lies; then the
//      default and the dense quadrature up to 80 degrees by sigma_s.
// Markdown on stdout; THREADS (default 1) share the cases.
//   build/tests/bench/cmfilter-slope-fit-accuracy [THREADS]
#include "cmfilter/color/ciede2000.h"
#include "cmfilter/util/parallel_for.h"
#include "cmfilter/microsurface/slope_color.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

using namespace cmfilter;

namespace {

constexpr double kPi = 3.14159265358979323846;

double srgb_to_linear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

Rgb linear_from_srgb(double r, double g, double b) { return {srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b)}; }

SteepnessColorMap grass_and_rock()
{
    const Rgb grass = linear_from_srgb(0.36, 0.58, 0.20), rock = linear_from_srgb(0.55, 0.50, 0.45),
              cliff = linear_from_srgb(0.25, 0.22, 0.20);
    const auto mix = [](const Rgb& a, const Rgb& b, double t) { return (1 - t) * a + t * b; };
    SteepnessColorMap map;
    map.by_angle.vmin = 0;
    map.by_angle.vmax = 90;
    for (int i = 0; i < 36; ++i) {
        const double angle = (i + 0.5) * 2.5;
        const Rgb c = angle < 25   ? grass
                      : angle < 35 ? mix(grass, rock, (angle - 25) / 10)
                      : angle < 60 ? rock
                      : angle < 70 ? mix(rock, cliff, (angle - 60) / 10)
                                   : cliff;
        map.by_angle.texels.push_back(c);
    }
    return map;
}

// HSV (display values) to scene-linear.
Rgb hsv(double hue, double saturation, double value)
{
    const double h = 6 * (hue - std::floor(hue));
    const auto channel = [&](double n) {
        const double k = std::fmod(n + h, 6.0);
        return value - value * saturation * std::max(0.0, std::min({k, 4 - k, 1.0}));
    };
    return linear_from_srgb(channel(5), channel(3), channel(1));
}

SlopeVectorColorMap hue_wheel()
{
    SlopeVectorColorMap map;
    map.width = map.height = 64;
    map.s_max = 2;
    for (int j = 0; j < map.height; ++j) {
        for (int i = 0; i < map.width; ++i) {
            const double sx = -map.s_max + (i + 0.5) * 2 * map.s_max / map.width;
            const double sy = map.s_max - (j + 0.5) * 2 * map.s_max / map.height;
            map.texels.push_back(hsv(std::atan2(sy, sx) / (2 * kPi), std::min(1.0, std::hypot(sx, sy)), 1.0));
        }
    }
    return map;
}

struct Case {
    SlopeGaussian slopes;
    ViewAngles view;
    const char* shape;
    double sigma, degrees;
};

SlopeGaussian shaped(const std::string& shape, double sigma)
{
    if (shape == "anisotropic") return {0, 0, sigma * sigma, 0.5 * sigma * sigma / 2, sigma * sigma / 4};
    if (shape == "tilted") return {0.3, -0.2, sigma * sigma, 0, sigma * sigma};
    return {0, 0, sigma * sigma, 0, sigma * sigma};
}

const char* const kShapes[] = {"isotropic", "anisotropic", "tilted"};

// Gauss-Hermite points per axis in the accuracy table.
const int kAccuracyPoints[] = {6, 8, 10, 12, 16, 24};

std::vector<Case> sweep(const std::vector<double>& degrees, const std::vector<double>& sigmas,
                        const std::vector<double>& azimuths_degrees, const char* shape)
{
    std::vector<Case> out;
    for (double d : degrees)
        for (double s : sigmas)
            for (double p : azimuths_degrees)
                out.push_back({shaped(shape, s), {d * kPi / 180, p * kPi / 180}, shape, s, d});
    return out;
}

std::vector<double> range(double from, double to, double step)
{
    std::vector<double> v;
    for (double x = from; x <= to + 1e-9; x += step) v.push_back(x);
    return v;
}

struct Summary {
    double mean = 0, max = 0;
    const Case* worst = nullptr;
    std::vector<double> errors;  // per case
};

// One colouring of each case.
template <typename F>
std::vector<Rgb> color_each(const std::vector<Case>& cases, int threads, F&& colour)
{
    std::vector<Rgb> out(cases.size());
    parallel_for(static_cast<int>(cases.size()), threads, [&](int i) { out[i] = colour(cases[i]); });
    return out;
}

// CIEDE2000 between two colourings of each case.
Summary compare(const std::vector<Case>& cases, const std::vector<Rgb>& first, const std::vector<Rgb>& second)
{
    Summary s;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const double error = ciede2000_linear_rgb(first[i], second[i]);
        s.errors.push_back(error);
        s.mean += error / cases.size();
        if (error >= s.max) s.max = error, s.worst = &cases[i];
    }
    return s;
}

std::string where(const Summary& s)
{
    if (!s.worst) return "-";
    char text[96];
    std::snprintf(text, sizeof text, "%s, sigma_s %.1f, theta %.1f, phi %.0f", s.worst->shape, s.worst->sigma,
                  s.worst->degrees, s.worst->view.phi * 180 / kPi);
    return text;
}

template <typename Map>
void reference_convergence(const char* name, const Map& map, int threads)
{
    std::vector<Case> cases;
    for (const char* shape : kShapes) {
        const auto part = sweep({0, 40, 70, 80, 85, 89, 89.9}, {0.1, 0.4, 1.0}, {0, 60, 200}, shape);
        cases.insert(cases.end(), part.begin(), part.end());
    }
    const std::vector<Rgb> reference =
        color_each(cases, threads, [&](const Case& c) { return exact_slope_color(map, c.slopes, c.view, {128}); });
    for (int panels : {8, 16, 32, 64}) {
        const Summary s =
            compare(cases,
                    color_each(cases, threads,
                               [&](const Case& c) { return exact_slope_color(map, c.slopes, c.view, {panels}); }),
                    reference);
        std::printf("| %s | %d | %.5f | %.5f | %s |\n", name, panels, s.mean, s.max, where(s).c_str());
    }
}

template <typename Map>
void hermite_points(const char* name, const Map& map, int threads)
{
    std::vector<Case> cases;
    for (const char* shape : kShapes) {
        const auto part = sweep({0, 20, 40, 60, 70, 80, 85, 89}, {0.1, 0.2, 0.4, 0.7, 1.0}, {0, 45, 150, 270}, shape);
        cases.insert(cases.end(), part.begin(), part.end());
    }
    // The Gaussian of D_s's moments, as a slope Gaussian seen head-on.
    const auto moment_gaussian = [](const Case& c) {
        const SlopeMoments m = exact_slope_moments(c.slopes, c.view);
        return SlopeGaussian{m.mean_x, m.mean_y, m.xx, m.xy, m.yy};
    };
    const std::vector<Rgb> dense = color_each(cases, threads, [&](const Case& c) {
        return exact_slope_color(map, moment_gaussian(c), {0, 0}, {64});
    });
    for (int n : {2, 3, 4, 5, 6, 8, 10, 12, 16, 20, 24, 32}) {
        const Summary s = compare(
            cases,
            color_each(cases, threads, [&](const Case& c) { return gaussian_slope_color(map, c.slopes, c.view, {n}); }),
            dense);
        std::printf("| %s | %d | %.5f | %.5f | %s |\n", name, n, s.mean, s.max, where(s).c_str());
    }
    // What the Gaussian itself leaves: the dense quadrature over it against
    // the exact D_s colour.
    const Summary g = compare(cases, dense, color_each(cases, threads, [&](const Case& c) {
                                  return exact_slope_color(map, c.slopes, c.view, {64});
                              }));
    std::printf("| %s | dense Gaussian vs exact D_s | %.5f | %.5f | %s |\n", name, g.mean, g.max, where(g).c_str());
}

// Errors up to 80 degrees by sigma_s (0.1, ..., 1.0): the default
// Gauss-Hermite count and the dense quadrature over the Gaussian.
struct BySigma {
    double sum_default[10] = {}, max_default[10] = {}, sum_dense[10] = {}, max_dense[10] = {};
    int count[10] = {};

    void add(const std::vector<Case>& cases, const Summary& by_default, const Summary& dense)
    {
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const int k = std::clamp(static_cast<int>(std::lround(cases[i].sigma * 10)) - 1, 0, 9);
            sum_default[k] += by_default.errors[i];
            max_default[k] = std::max(max_default[k], by_default.errors[i]);
            sum_dense[k] += dense.errors[i];
            max_dense[k] = std::max(max_dense[k], dense.errors[i]);
            ++count[k];
        }
    }
};

template <typename Map>
BySigma accuracy(const char* name, const Map& map, int threads)
{
    const std::vector<double> sigmas = range(0.1, 1.0, 0.1), azimuths = range(0, 315, 45);
    const std::vector<double> up_to_80 = range(0, 80, 2);
    const std::vector<double> beyond_80 = {81, 82, 83, 84, 85, 86, 87, 88, 89, 89.5, 89.9};
    BySigma by_sigma;
    for (const char* shape : kShapes) {
        for (int part = 0; part < 2; ++part) {
            const std::vector<Case> cases = sweep(part == 0 ? up_to_80 : beyond_80, sigmas, azimuths, shape);
            const std::vector<Rgb> exact =
                color_each(cases, threads, [&](const Case& c) { return exact_slope_color(map, c.slopes, c.view); });
            std::printf("| %s | %s | %s | %zu |", name, shape, part == 0 ? "0..80" : "81..89.9", cases.size());
            Summary by_default;
            for (int n : kAccuracyPoints) {
                Summary s =
                    compare(cases,
                            color_each(cases, threads,
                                       [&](const Case& c) { return gaussian_slope_color(map, c.slopes, c.view, {n}); }),
                            exact);
                std::printf(" %.3f | %.3f |", s.mean, s.max);
                if (n == GaussianSlopeColorOptions{}.points_per_axis) by_default = std::move(s);
            }
            // The Gaussian alone: a dense quadrature over it.
            const Summary g = compare(cases,
                                      color_each(
                                          cases, threads,
                                          [&](const Case& c) {
                const SlopeMoments m = exact_slope_moments(c.slopes, c.view);
                return exact_slope_color(map, {m.mean_x, m.mean_y, m.xx, m.xy, m.yy}, {0, 0});
                                          }),
                                      exact);
            std::printf(" %.3f | %.3f | %s |\n", g.mean, g.max, where(by_default).c_str());
            if (part == 0) by_sigma.add(cases, by_default, g);
        }
    }
    return by_sigma;
}

void print_by_sigma(const char* name, const BySigma& b)
{
    for (int k = 0; k < 10; ++k) {
        const double n = b.count[k];
        std::printf("| %s | %.1f | %.0f | %.3f | %.3f | %.3f | %.3f |\n", name, 0.1 * (k + 1), n, b.sum_default[k] / n,
                    b.max_default[k], b.sum_dense[k] / n, b.max_dense[k]);
    }
}

}  // namespace

int main(int argc, char** argv)
{
    const int threads = argc > 1 ? std::atoi(argv[1]) : 1;
    const SteepnessColorMap rock = grass_and_rock();
    const SlopeVectorColorMap wheel = hue_wheel();

    std::printf("Reference convergence: exact_slope_color with P panels per axis against 128 (CIEDE2000)\n\n");
    std::printf("| map | panels | mean | max | worst at |\n|---|---:|---:|---:|---|\n");
    reference_convergence("grass-rock", rock, threads);
    reference_convergence("hue-wheel", wheel, threads);

    std::printf(
        "\nGauss-Hermite points per axis over the moment Gaussian against dense quadrature of it (CIEDE2000)\n\n");
    std::printf("| map | points | mean | max | worst at |\n|---|---:|---:|---:|---|\n");
    hermite_points("grass-rock", rock, threads);
    hermite_points("hue-wheel", wheel, threads);

    ExactSlopeColorOptions exact_defaults;
    std::printf("\nThe Gaussian-moment colour with n x n Gauss-Hermite points, and with a dense quadrature over the "
                "same Gaussian, against the exact D_s colour (%d panels) (CIEDE2000, mean | max)\n\n",
                exact_defaults.panels);
    std::printf("| map | slopes | theta_o (degrees) | cases |");
    const int default_points = GaussianSlopeColorOptions{}.points_per_axis;
    for (int n : kAccuracyPoints) std::printf(" n = %d%s mean | max |", n, n == default_points ? " (default)" : "");
    std::printf(" dense mean | max | worst at, n = %d |\n|---|---|---|---:|", default_points);
    for (std::size_t i = 0; i < std::size(kAccuracyPoints); ++i) std::printf("---:|---:|");
    std::printf("---:|---:|---|\n");
    const BySigma rock_by_sigma = accuracy("grass-rock", rock, threads);
    const BySigma wheel_by_sigma = accuracy("hue-wheel", wheel, threads);

    std::printf("\nUp to 80 degrees by sigma_s, the three shapes together: the default %d x %d points and the dense "
                "quadrature over the Gaussian against the exact D_s colour (CIEDE2000)\n\n",
                default_points, default_points);
    std::printf(
        "| map | sigma_s | cases | n = %d mean | max | dense mean | max |\n|---|---:|---:|---:|---:|---:|---:|\n",
        default_points);
    print_by_sigma("grass-rock", rock_by_sigma);
    print_by_sigma("hue-wheel", wheel_by_sigma);
    return 0;
}
