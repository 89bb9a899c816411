// SPDX-License-Identifier: Apache-2.0
// Writes the inputs the command-line tests need, including the bad ones that
// no image tool would write on purpose: a NaN texel, an Inf texel, a text
// file named .png, an empty file, a 2-D grid, an 8-bit ramp (plain, and
// tagged gamma 2.2 the way a PNG gAMA chunk is), a pair of float images to
// compare (with HDR and negative values) plus one of another size; and drivers
// for bake-moments: a non-power-of-two 8-bit grey one and a float one with two
// NaN texels and one Inf texel; for apply, a 32 x 32 float driver reaching
// a little beyond [0, 1], a float (linear) 8-texel colour map with its values
// also as oiiotool --colormap knots in a text file, and a driver entirely
// outside [0, 1].
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

bool write(const std::string& path, int w, int h, int ch, OIIO::TypeDesc type, const void* data, float gamma = 0)
{
    auto out = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(w, h, ch, type);
    if (gamma > 0) {  // a PNG gAMA chunk, as OpenImageIO names it
        spec.attribute("oiio:ColorSpace", "GammaCorrected");
        spec.attribute("oiio:Gamma", gamma);
    }
    if (!out || !out->open(path, spec) || !out->write_image(type, data) || !out->close()) {
        std::cerr << "make_fixtures: cannot write " << path << "\n";
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: make_fixtures DIR\n";
        return 2;
    }
    const std::string dir = argv[1];
    bool ok = true;
    std::vector<float> nan_map = {0.1f, 0.2f, 0.3f, NAN, 0.5f, 0.6f, 0.7f, 0.8f, 0.9f};
    ok &= write(dir + "/nan.exr", 3, 1, 3, OIIO::TypeDesc::FLOAT, nan_map.data());
    std::vector<float> inf_map = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f, INFINITY};
    ok &= write(dir + "/inf.exr", 3, 1, 3, OIIO::TypeDesc::FLOAT, inf_map.data());
    std::vector<unsigned char> grid(4 * 3 * 3);
    for (std::size_t i = 0; i < grid.size(); ++i) grid[i] = static_cast<unsigned char>(i * 7);
    ok &= write(dir + "/grid.png", 4, 3, 3, OIIO::TypeDesc::UINT8, grid.data());
    std::vector<unsigned char> ramp(64 * 3);
    for (int i = 0; i < 64; ++i) {
        ramp[3 * i] = static_cast<unsigned char>(i * 4);
        ramp[3 * i + 1] = static_cast<unsigned char>(255 - i * 4);
        ramp[3 * i + 2] = static_cast<unsigned char>((i * 37) % 256);
    }
    ok &= write(dir + "/ramp.png", 64, 1, 3, OIIO::TypeDesc::UINT8, ramp.data());
    ok &= write(dir + "/ramp-gamma22.png", 64, 1, 3, OIIO::TypeDesc::UINT8, ramp.data(), 2.2f);
    std::vector<float> cmp_a(16 * 8 * 3), cmp_b(16 * 8 * 3);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) {
            float* a = &cmp_a[3 * (y * 16 + x)];
            float* b = &cmp_b[3 * (y * 16 + x)];
            a[0] = (x - 3) * 0.25f;
            a[1] = y * 0.5f;
            a[2] = static_cast<float>((x * 7 + y * 3) % 11) / 4.0f;
            b[0] = a[0] + 0.01f * static_cast<float>(x % 3);
            b[1] = a[1] - 0.2f * static_cast<float>(y % 2);
            b[2] = a[2] * 1.5f;
        }
    ok &= write(dir + "/cmp-a.exr", 16, 8, 3, OIIO::TypeDesc::FLOAT, cmp_a.data());
    ok &= write(dir + "/cmp-b.exr", 16, 8, 3, OIIO::TypeDesc::FLOAT, cmp_b.data());
    ok &= write(dir + "/cmp-small.exr", 8, 8, 3, OIIO::TypeDesc::FLOAT, cmp_a.data());
    std::vector<unsigned char> driver(37 * 23);
    for (std::size_t i = 0; i < driver.size(); ++i) driver[i] = static_cast<unsigned char>((i * 53) % 256);
    ok &= write(dir + "/driver-37x23.png", 37, 23, 1, OIIO::TypeDesc::UINT8, driver.data());
    // Four distinct values in blocks of 8 x 8 texels (render --method exact).
    std::vector<unsigned char> quantised(64 * 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            quantised[static_cast<std::size_t>(y * 64 + x)] =
                static_cast<unsigned char>(40 + 60 * ((((x / 8) * 7 + (y / 8) * 5) ^ (x / 16)) % 4));
    ok &= write(dir + "/driver-4values.png", 64, 64, 1, OIIO::TypeDesc::UINT8, quantised.data());
    std::vector<float> nan_driver = {0.1f, 0.2f, NAN, 0.4f, 0.5f, INFINITY, 0.7f, 0.8f, 0.9f, NAN, 1.1f, 1.2f};
    ok &= write(dir + "/driver-nan.exr", 4, 3, 1, OIIO::TypeDesc::FLOAT, nan_driver.data());
    std::vector<float> apply_driver(32 * 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)  // smooth waves plus texel-scale detail, in [-0.1, 1.1]
            apply_driver[y * 32 + x] =
                static_cast<float>(0.5 + 0.35 * std::sin(0.4 * x + 0.1 * y) + 0.25 * std::cos(1.7 * x * y + 0.3 * y));
    ok &= write(dir + "/apply-driver.exr", 32, 32, 1, OIIO::TypeDesc::FLOAT, apply_driver.data());
    const std::vector<float> apply_map = {0.02f, 0.05f, 0.4f, 0.9f, 0.1f, 0.05f, 0.1f,  0.8f, 0.2f, 2.5f, 2.2f,  0.3f,
                                          0.0f,  0.0f,  0.0f, 0.6f, 0.6f, 0.6f,  0.05f, 0.9f, 0.3f, 1.0f, 0.95f, 0.9f};
    ok &= write(dir + "/apply-map.exr", 8, 1, 3, OIIO::TypeDesc::FLOAT, apply_map.data());
    {
        std::ofstream knots(dir + "/apply-map-knots.txt");
        knots.precision(9);
        for (std::size_t i = 0; i < apply_map.size(); ++i) knots << (i ? "," : "") << apply_map[i];
        knots << "\n";
    }
    std::vector<float> far_driver(4 * 4);
    for (std::size_t i = 0; i < far_driver.size(); ++i) far_driver[i] = 5.0f + 0.0625f * i;
    ok &= write(dir + "/apply-driver-far.exr", 4, 4, 1, OIIO::TypeDesc::FLOAT, far_driver.data());
    std::ofstream(dir + "/not-an-image.png") << "this is text, not a PNG\n";
    std::ofstream(dir + "/empty.png");
    return ok ? 0 : 1;
}
