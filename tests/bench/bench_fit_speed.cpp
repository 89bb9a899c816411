// SPDX-License-Identifier: Apache-2.0
// The linear fits' speed and memory (docs/stacks.md#speed): a 256 x 256,
// 64-light RGB stack of 8-bit PNGs (smooth random relief under a Fibonacci
// dome, written once), read alone, fitted alone (in memory), read and
// fitted, and fitted streamed from the files (streamed_fit.h), by each
// model, each the fastest of 9 interleaved rounds in this process; the fit's
// cost is reported as the ratio against reading the images alone, and in
// ms. The peak memory of reading and fitting, held and streamed, is each
// measured in a fresh process (this program run again with --peak-memory):
// its peak resident set (VmHWM, /proc/self/status) above its resident set
// once the colour config is loaded, and set against the stack's size as
// float and the streamed fit's accumulators and coefficients by design.
//   cmfilter-bench-fit-speed [SIZE] [LIGHTS] [DIR]
#include "bench_timing.h"

#include "cmfilter/color/color_config.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/light_file.h"
#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/stack/streamed_fit.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
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

// A field of /proc/self/status in bytes ("VmHWM", "VmRSS"; 0 if absent).
double status_bytes(const std::string& field)
{
    std::ifstream in("/proc/self/status");
    for (std::string line; std::getline(in, line);)
        if (line.rfind(field + ":", 0) == 0) return 1024.0 * std::atof(line.c_str() + field.size() + 1);
    return 0;
}

// Child mode: one read and fit of `lp` by `model`, held or streamed; prints
// the peak resident bytes above those at the start of the work.
int peak_memory(const std::string& variant, const std::string& model_name, const std::string& lp)
{
    auto config = ColorConfig::load("");
    auto model = parse_linear_model(model_name);
    if (!config || !model) return 2;
    // The peak so far reset to the resident set now (Linux >= 4.0).
    std::ofstream("/proc/self/clear_refs") << "5";
    const double start = status_bytes("VmRSS");
    StackLoadOptions load;
    load.light_file = lp;
    LinearFitOptions options;
    options.model = *model;
    if (variant == "held") {
        auto stack = load_image_stack(load, *config);
        if (!stack || !fit_linear(*stack, options)) return 3;
    } else if (!fit_linear_from_files(load, options, *config)) return 3;
    std::printf("%.0f\n", status_bytes("VmHWM") - start);
    return 0;
}

// Runs this program's child mode and reads its answer in bytes.
double measure_peak(const char* self, const std::string& variant, LinearModel model, const std::string& lp)
{
    const std::string command = std::string("'") + self + "' --peak-memory " + variant + " " + to_string(model) + " '" +
                                lp + "'";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    double bytes = -1;
    if (!pipe || std::fscanf(pipe.get(), "%lf", &bytes) != 1) {
        std::fprintf(stderr, "cannot measure %s\n", command.c_str());
        std::exit(5);
    }
    return bytes;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc == 5 && std::string(argv[1]) == "--peak-memory") return peak_memory(argv[2], argv[3], argv[4]);
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
    // Memory first, each in its own process.
    std::vector<double> held_peak, streamed_peak;
    for (LinearModel m : models) {
        held_peak.push_back(measure_peak(argv[0], "held", m, load.light_file));
        streamed_peak.push_back(measure_peak(argv[0], "streamed", m, load.light_file));
    }
    double read_ms = 1e300;
    std::vector<double> fit_ms(models.size(), 1e300), both_ms(models.size(), 1e300), streamed_ms(models.size(), 1e300);
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
            streamed_ms[m] = std::min(streamed_ms[m], cmfilter_bench::time_ms([&] {
                                          if (!fit_linear_from_files(load, options, *config)) std::exit(4);
                                      }));
        }
    }
    std::printf("machine: %s, %u hardware threads; fastest of %d interleaved rounds\n",
                cmfilter_bench::cpu_name().c_str(), std::thread::hardware_concurrency(), rounds);
    std::printf("stack: %d x %d, %d lights, RGB 8-bit PNG (%s)\n", size, size, lights, dir.c_str());
    std::printf("| model | read ms | fit ms | read + fit ms | streamed ms | fit / read | streamed / (read + fit) |\n"
                "|---|---:|---:|---:|---:|---:|---:|\n");
    for (std::size_t m = 0; m < models.size(); ++m)
        std::printf("| %s | %.1f | %.1f | %.1f | %.1f | %.2f | %.2f |\n", to_string(models[m]), read_ms, fit_ms[m],
                    both_ms[m], streamed_ms[m], fit_ms[m] / read_ms, streamed_ms[m] / both_ms[m]);
    // By design: the stack as float; the streamed fit's double accumulators
    // and float coefficients (streamed_fit.h).
    const double mb = 1e6, texels = double(size) * size;
    std::printf("\npeak resident memory above the process's own, MB (stack as float: %.1f MB)\n",
                texels * 3 * lights * 4 / mb);
    std::printf("| model | held: read + fit | streamed | streamed accumulators + coefficients by design |\n"
                "|---|---:|---:|---:|\n");
    for (std::size_t m = 0; m < models.size(); ++m) {
        const int terms = basis_terms(models[m]);
        const bool lrgb = models[m] == LinearModel::PtmLrgb;
        const double accumulators = texels * 8 * (lrgb ? 3 * (terms + 1) + 1 : 3 * terms);
        const double coefficients = texels * 4 * (lrgb ? terms + 3 : 3 * terms);
        std::printf("| %s | %.1f | %.1f | %.1f |\n", to_string(models[m]), held_peak[m] / mb, streamed_peak[m] / mb,
                    (accumulators + coefficients) / mb);
    }
    return 0;
}
