// SPDX-License-Identifier: Apache-2.0
// The linear fits' speed (docs/stacks.md#speed): a 256 x 256, 64-light RGB
// stack of 8-bit PNGs (smooth random relief under a Fibonacci dome, written
// once), read alone, fitted alone (in memory), and read and fitted, by each
// model, each the fastest of 9 interleaved rounds in this process; the fit's
// cost is reported as the ratio against reading the images alone, and in ms.
//   cmfilter-bench-fit-speed [SIZE] [LIGHTS] [DIR]
#include "bench_timing.h"

#include "cmfilter/color/color_config.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/light_file.h"
#include "cmfilter/stack/linear_fit.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

// A smooth relief's normals lit from each light, times a slowly varying
// colour: a Lambertian surface, as a PTM models it.
void write_stack(const std::string& dir, int size, int lights)
{
    std::vector<LightEntry> entries;
    const double golden = 3.14159265358979323846 * (3 - std::sqrt(5.0));
    for (int k = 0; k < lights; ++k) {
        const double z = 1 - (k + 0.5) / lights * 0.9;  // elevations above about 6 degrees
        const double r = std::sqrt(1 - z * z);
        entries.push_back(
            {"light-" + std::to_string(k) + ".png", {r * std::cos(golden * k), r * std::sin(golden * k), z}, 0});
    }
    std::vector<unsigned char> px(static_cast<std::size_t>(size) * size * 3);
    for (int k = 0; k < lights; ++k) {
        const Vec3 l = entries[k].direction;
        for (int j = 0; j < size; ++j)
            for (int i = 0; i < size; ++i) {
                const double u = 6.2831853 * i / size, v = 6.2831853 * j / size;
                Vec3 n{0.4 * std::cos(3 * u) * std::sin(v), -0.3 * std::sin(2 * v + u), 1};
                n = normalize(n);
                const double shade = std::max(0.0, dot(n, l));
                const double c[3] = {0.6 + 0.3 * std::sin(u), 0.5, 0.4 + 0.3 * std::cos(v)};
                for (int ch = 0; ch < 3; ++ch) {
                    const double lin = std::min(1.0, c[ch] * shade);
                    const double enc = lin <= 0.0031308 ? 12.92 * lin : 1.055 * std::pow(lin, 1 / 2.4) - 0.055;
                    px[(static_cast<std::size_t>(j) * size + i) * 3 + ch] =
                        static_cast<unsigned char>(std::lround(255 * enc));
                }
            }
        auto out = OIIO::ImageOutput::create("png");
        const std::string path = dir + "/" + entries[k].image;
        OIIO::ImageSpec spec(size, size, 3, OIIO::TypeDesc::UINT8);
        if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, px.data()) || !out->close()) {
            std::fprintf(stderr, "cannot write %s\n", path.c_str());
            std::exit(2);
        }
    }
    if (!write_light_file(dir + "/stack.lp", entries)) {
        std::fprintf(stderr, "cannot write %s/stack.lp\n", dir.c_str());
        std::exit(2);
    }
}

}  // namespace

int main(int argc, char** argv)
{
    const int size = argc > 1 ? std::atoi(argv[1]) : 256;
    const int lights = argc > 2 ? std::atoi(argv[2]) : 64;
    const std::string dir = argc > 3 ? argv[3]
                                     : (std::filesystem::temp_directory_path() /
                                        ("cmfilter-bench-fit-" + std::to_string(size) + "-" + std::to_string(lights)))
                                           .string();
    std::filesystem::create_directories(dir);
    if (!std::filesystem::exists(dir + "/stack.lp")) write_stack(dir, size, lights);
    auto config = ColorConfig::load("");
    if (!config) return 2;
    StackLoadOptions load;
    load.light_file = dir + "/stack.lp";
    // Rounds interleave every timing, so drift in the machine's load
    // touches all of them alike; each figure is the fastest of the rounds.
    const int rounds = 9;
    const std::vector<LinearModel> models = {LinearModel::PtmRgb, LinearModel::PtmLrgb, LinearModel::Hsh2,
                                             LinearModel::Hsh3};
    double read_ms = 1e300;
    std::vector<double> fit_ms(models.size(), 1e300), both_ms(models.size(), 1e300);
    auto stack = load_image_stack(load, *config);
    if (!stack) return 3;
    for (int r = 0; r < rounds; ++r) {
        read_ms = std::min(read_ms, cmfilter_bench::time_ms([&] {
                               if (!load_image_stack(load, *config)) std::exit(3);
                           }));
        for (std::size_t m = 0; m < models.size(); ++m) {
            LinearFitOptions options;
            options.model = models[m];
            fit_ms[m] = std::min(fit_ms[m], cmfilter_bench::time_ms([&] {
                                     if (!fit_linear(*stack, options)) std::exit(4);
                                 }));
            both_ms[m] = std::min(both_ms[m], cmfilter_bench::time_ms([&] {
                                      auto s = load_image_stack(load, *config);
                                      if (!s || !fit_linear(*s, options)) std::exit(4);
                                  }));
        }
    }
    std::printf("machine: %s, %u hardware threads; fastest of %d interleaved rounds\n",
                cmfilter_bench::cpu_name().c_str(), std::thread::hardware_concurrency(), rounds);
    std::printf("stack: %d x %d, %d lights, RGB 8-bit PNG (%s)\n", size, size, lights, dir.c_str());
    std::printf("| model | read ms | fit ms | read + fit ms | fit / read |\n|---|---:|---:|---:|---:|\n");
    for (std::size_t m = 0; m < models.size(); ++m)
        std::printf("| %s | %.1f | %.1f | %.1f | %.2f |\n", to_string(models[m]), read_ms, fit_ms[m], both_ms[m],
                    fit_ms[m] / read_ms);
    return 0;
}
