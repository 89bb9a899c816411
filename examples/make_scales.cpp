// SPDX-License-Identifier: Apache-2.0
// Writes a seamless snake-skin displacement: overlapping rounded scales in
// offset rows, one channel of heights in texture units (one repeat = 1, so
// height_scale 1), as half-float OpenEXR. The bundled
// examples/scenes/snake-scales.exr is
//     build/examples/make_scales examples/scenes/snake-scales.exr 256
//
// Rows of 8 scales, 8 rows a repeat, every other row shifted by half a scale.
// Scale k, centred at c_k, is a dome h_k = H (1 - q^3) over the elliptical
// radius q = |((u - c_u) / R_u, (v - c_v) / R_v)|, with R_v shorter in front
// (towards the next row, v growing) than behind, and the surface is the
// highest dome at each point: each scale rises gently from under the one
// behind it, is flat on top and falls steeply at its front rim onto the next
// row, a crease where two domes meet. The dome's slope 3 H q^2 / R runs from
// 0 on top to 3 H / R_front = tan 70 degrees at q = 1 in front; the next row
// cuts it a little before, so the texels' slopes span 0 to about 60 degrees
// (the program prints them), and a slope colour map shows a pattern that
// changes with the view (Heitz et al. 2013, fig. 10, the snake). Distances
// wrap, so the texture tiles.
#include "cmfilter/microsurface/displacement_texture.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

constexpr int kScalesPerRow = 8;
constexpr int kRows = 8;
constexpr double kPi = 3.14159265358979323846;
constexpr double kRadiusU = 0.075;      // half-width of a scale (texture units), a little over half the spacing
constexpr double kRadiusFront = 0.065;  // towards the next row
constexpr double kRadiusBack = 0.14;    // under the row behind
const double kHeight = std::tan(70 * kPi / 180) * kRadiusFront / 3;  // 70 degrees at q = 1 in front

// The signed distance from a to b on a circle of circumference 1, in [-0.5, 0.5).
double wrapped(double a, double b)
{
    const double d = a - b;
    return d - std::floor(d + 0.5);
}

double scales_height(double u, double v)
{
    double best = -1e30;
    for (int r = 0; r < kRows; ++r) {
        const double cv = (r + 0.5) / kRows;
        const double dv = wrapped(v, cv);
        const double rv = dv > 0 ? kRadiusFront : kRadiusBack;
        for (int c = 0; c < kScalesPerRow; ++c) {
            const double cu = (c + 0.5 + 0.5 * (r % 2)) / kScalesPerRow;
            const double du = wrapped(u, cu);
            const double q = std::hypot(du / kRadiusU, dv / rv);
            best = std::max(best, kHeight * (1 - q * q * q));
        }
    }
    return best;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: make_scales OUTPUT.exr [SIZE (default 256)]\n");
        return 1;
    }
    const std::string path = argv[1];
    const int n = argc == 3 ? std::atoi(argv[2]) : 256;
    if (n < 8 || n > 8192) {
        std::fprintf(stderr, "make_scales: size %s is out of range (expected 8 to 8192)\n", argv[2]);
        return 1;
    }
    std::vector<float> texels(static_cast<std::size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            texels[static_cast<std::size_t>(j) * n + i] =
                static_cast<float>(scales_height((i + 0.5) / n, (j + 0.5) / n));

    auto out = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(n, n, 1, OIIO::TypeDesc::HALF);
    spec.channelnames = {"Y"};
    spec.attribute("compression", "zip");
    spec.attribute("ImageDescription", "snake-skin displacement: heights in texture units (height_scale 1)");
    if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, texels.data()) || !out->close()) {
        std::fprintf(stderr, "make_scales: cannot write '%s': %s\n", path.c_str(),
                     out ? out->geterror().c_str() : OIIO::geterror().c_str());
        return 2;
    }

    // What a slope colour map will see: the slope angles of the written texels.
    cmfilter::DisplacementOptions options;
    options.path = path;
    auto texture = cmfilter::DisplacementTexture::load(options);
    if (!texture) {
        std::fprintf(stderr, "make_scales: %s\n", texture.error().message.c_str());
        return 2;
    }
    std::vector<double> angles;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const auto [sx, sy] = texture->texel_slope(i, j);
            angles.push_back(std::atan(std::hypot(sx, sy)) * 180 / kPi);
        }
    std::sort(angles.begin(), angles.end());
    const auto at = [&](double p) { return angles[static_cast<std::size_t>(p * (angles.size() - 1))]; };
    std::printf("%s: %d x %d, relief %.4f texture units; slope angle (degrees) min %.1f, median %.1f, "
                "p95 %.1f, max %.1f\n",
                path.c_str(), n, n, kHeight, at(0), at(0.5), at(0.95), at(1));
    return 0;
}
