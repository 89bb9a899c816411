// SPDX-License-Identifier: Apache-2.0
// Benchmark for bake-moments against maketx, printed as Markdown for
// docs/benchmarks.md.
//   cmfilter-bench-bake-moments SIZE DIR [RUNS]
// Writes a SIZE x SIZE float32 driver (value noise, ZIP scanline EXR) into
// DIR, then runs, as child processes in this same run, `cmfilter
// bake-moments` and `maketx --filter box` with the same data type (float),
// tile size (64) and compression (zip), and reports for each the wall time
// and the peak resident memory (getrusage ru_maxrss of the child, via wait4).
#include <OpenImageIO/imageio.h>

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include "bench_timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

extern char** environ;

using cmfilter_bench::cpu_name;

namespace {

struct Run {
    double seconds = 0;
    double cpu_seconds = 0;  // user + system
    double peak_mib = 0;
};

Run run_child(const std::vector<std::string>& argv)
{
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const auto t0 = std::chrono::steady_clock::now();
    pid_t pid;
    if (posix_spawn(&pid, args[0], nullptr, nullptr, args.data(), environ) != 0) {
        std::cerr << "cannot run " << argv[0] << "\n";
        std::exit(1);
    }
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    Run r;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.cpu_seconds = usage.ru_utime.tv_sec + usage.ru_utime.tv_usec * 1e-6 + usage.ru_stime.tv_sec +
                    usage.ru_stime.tv_usec * 1e-6;
    r.peak_mib = usage.ru_maxrss / 1024.0;  // Linux reports KiB
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::cerr << argv[0] << " failed\n";
        std::exit(1);
    }
    return r;
}

// Smooth value noise plus fine detail, written scanline by scanline so this
// process never holds the driver.
bool write_driver(const std::string& path, int size)
{
    auto out = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(size, size, 1, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    if (!out || !out->open(path, spec)) return false;
    std::vector<float> row(size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const unsigned h = (unsigned(x) * 73856093u) ^ (unsigned(y) * 19349663u);
            row[x] = 0.5f + 0.3f * std::sin(x * 0.01f) * std::cos(y * 0.013f) + 0.2f * float(h % 1024) / 1024.0f;
        }
        if (!out->write_scanline(y, 0, OIIO::TypeDesc::FLOAT, row.data())) return false;
    }
    return out->close();
}

void keep_best(Run& b, const Run& r)
{
    b.seconds = std::min(b.seconds, r.seconds);
    b.cpu_seconds = std::min(b.cpu_seconds, r.cpu_seconds);
    b.peak_mib = std::max(b.peak_mib, r.peak_mib);
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 3) {
        std::cerr << "usage: cmfilter-bench-bake-moments SIZE DIR [RUNS]\n";
        return 2;
    }
    const int size = std::atoi(argv[1]);
    const std::string dir = argv[2];
    const int runs = argc > 3 ? std::max(1, std::atoi(argv[3])) : 1;
    const std::string driver = dir + "/bench-driver-" + std::to_string(size) + ".exr";
    const std::string ours = dir + "/bench-moments-" + std::to_string(size) + ".exr";
    const std::string theirs = dir + "/bench-maketx-" + std::to_string(size) + ".exr";
    if (!write_driver(driver, size)) {
        std::cerr << "cannot write " << driver << "\n";
        return 1;
    }
    const double driver_mib = double(size) * size * 4 / (1024.0 * 1024.0);
    const std::vector<std::string> bake = {CMFILTER_BINARY, "bake-moments", driver, "-o", ours, "-q"};
    const std::vector<std::string> maketx = {MAKETX_BINARY, driver,   "-o",     theirs, "--filter", "box",
                                             "-d",          "float",  "--tile", "64",   "64",       "--compression",
                                             "zip",         "--wrap", "clamp"};
    Run a{1e300, 1e300, 0}, b{1e300, 1e300, 0};
    for (int i = 0; i < runs; ++i) {  // alternate, so both see the same load
        keep_best(a, run_child(bake));
        keep_best(b, run_child(maketx));
    }
    std::printf("Machine: %s, %u hardware threads. Driver %d x %d float32 (%.0f MiB in memory); "
                "best of %d run(s).\n\n",
                cpu_name().c_str(), std::max(1u, std::thread::hardware_concurrency()), size, size, driver_mib, runs);
    std::printf("| program | wall s | CPU s | peak RSS MiB | peak / driver |\n|---|---:|---:|---:|---:|\n");
    for (const auto& [name, r] : {std::pair<const char*, Run>{"cmfilter bake-moments", a},
                                  std::pair<const char*, Run>{"maketx --filter box", b}})
        std::printf("| %s | %.2f | %.2f | %.0f | %.2f |\n", name, r.seconds, r.cpu_seconds, r.peak_mib,
                    r.peak_mib / driver_mib);
    std::printf("\nbake-moments / maketx wall time: %.2f (target <= 1.5); CPU time: %.2f\n", a.seconds / b.seconds,
                a.cpu_seconds / b.cpu_seconds);
    std::remove(ours.c_str());
    std::remove(theirs.c_str());
    std::remove(driver.c_str());
    return 0;
}
