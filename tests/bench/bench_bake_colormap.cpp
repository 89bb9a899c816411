// SPDX-License-Identifier: Apache-2.0
// Benchmarks for bake-colormap, printed as Markdown for docs/benchmarks.md.
//   cmfilter-bench-bake-colormap timing LUTS_DIR   bake time / EXR write time
//   cmfilter-bench-bake-colormap spacing LUTS_DIR  lookup error, linear vs sqrt sigma axis
// Times are the fastest of repeated runs in this process (the least disturbed
// by other work on the machine); the baseline (writing
// the same table to EXR with cmfilter's own writer) runs in the same process,
// so the ratio, not the milliseconds, is the figure to compare across machines.
#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/tables/table_lookup_error.h"

#include "bench_timing.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_bench;
namespace fs = std::filesystem;

namespace {

const char* kMaps[] = {"terrain", "stripes", "step", "narrow-band", "hue-ramp"};

LoadedColorMap load(const std::string& dir, const std::string& name, const ColorConfig& config)
{
    ColorMapLoadOptions opt;
    opt.path = dir + "/" + name + ".png";
    auto m = load_color_map(opt, config);
    if (!m) {
        std::cerr << m.error().message << "\n";
        std::exit(1);
    }
    return *m;
}

int timing(const std::string& dir, const ColorConfig& config)
{
    const fs::path tmp = fs::temp_directory_path() / "cmfilter-bench";
    fs::create_directories(tmp);
    std::cout << "Machine: " << cpu_name() << ", " << std::thread::hardware_concurrency()
              << " hardware threads (bake uses all). Fastest of 9 runs each.\n\n"
              << "| map | table | bake ms | write ms (zip EXR) | bake / write |\n"
              << "|---|---|---:|---:|---:|\n";
    for (const char* name : kMaps) {
        const LoadedColorMap m = load(dir, name, config);
        for (int values : {256, 1024}) {
            GaussianColorTableOptions opt;
            opt.values = values;
            GaussianColorTable table;
            const double bake = fastest_ms(9, [&] { table = *GaussianColorTable::bake(m.map, opt); });
            GaussianColorTableInfo info;
            info.source = m.provenance;
            const std::string path = (tmp / "t.exr").string();
            const double write = fastest_ms(9, [&] { (void)write_gaussian_color_table(path, table, info); });
            char row[200];
            std::snprintf(row, sizeof row, "| %s | %d x %d | %.1f | %.1f | %.2f |\n", name, values, opt.sigmas, bake,
                          write, bake / write);
            std::cout << row;
        }
    }
    fs::remove_all(tmp);
    return 0;
}

int spacing(const std::string& dir, const ColorConfig& config)
{
    struct Size {
        int values, sigmas;
    };
    const Size sizes[] = {{256, 256}, {1024, 64}, {1024, 16}, {4096, 16}};
    std::cout << "CIEDE2000 between bilinear lookups and the exact T(v, sigma) at 20000 random (v, sigma)"
                 " (v uniform on the domain, sigma = sigma_max u^2), default domain 0:1, clamp,"
                 " sigma_max 0.25, margin 0.75.\n\n"
              << "| map | table | linear mean | sqrt mean | linear p95 | sqrt p95 | linear max | sqrt max |\n"
              << "|---|---|---:|---:|---:|---:|---:|---:|\n";
    for (const char* name : kMaps) {
        const LoadedColorMap m = load(dir, name, config);
        for (const Size& size : sizes) {
            ErrorSummary e[2];
            for (int k = 0; k < 2; ++k) {
                GaussianColorTableOptions opt;
                opt.values = size.values;
                opt.sigmas = size.sigmas;
                opt.spacing = k == 0 ? SigmaSpacing::Linear : SigmaSpacing::Sqrt;
                const GaussianColorTable table = *GaussianColorTable::bake(m.map, opt);
                e[k] = measure_lookup_error(table, m.map, {});
            }
            char row[300];
            std::snprintf(row, sizeof row, "| %s | %d x %d | %.4f | %.4f | %.4f | %.4f | %.3f | %.3f |\n", name,
                          size.values, size.sigmas, e[0].mean, e[1].mean, e[0].p95, e[1].p95, e[0].max, e[1].max);
            std::cout << row;
        }
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::cerr << "usage: cmfilter-bench-bake-colormap timing|spacing LUTS_DIR\n";
        return 1;
    }
    auto config = ColorConfig::load("");
    if (!config) return 1;
    const std::string mode = argv[1];
    if (mode == "timing") return timing(argv[2], *config);
    if (mode == "spacing") return spacing(argv[2], *config);
    std::cerr << "unknown mode " << mode << "\n";
    return 1;
}
