// SPDX-License-Identifier: Apache-2.0
// What the benchmark programs share: the machine's name for their reports,
// and timings taken as the fastest of repeated runs in the same process (the
// runs least disturbed by other work on a shared machine). Speed is reported
// as ratios of two such timings from the same run (docs/benchmarks.md).
#pragma once

#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>
#include <utility>

namespace cmfilter_bench {

inline std::string cpu_name()
{
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

// Wall time of one call of f, in ms.
template <typename F>
double time_ms(F&& f)
{
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The fastest of `runs` calls of f, in ms.
template <typename F>
double fastest_ms(int runs, F&& f)
{
    double best = 1e300;
    for (int r = 0; r < runs; ++r) best = std::min(best, time_ms(f));
    return best;
}

// a and b called alternately `runs` times each, so that both see the same
// conditions; the fastest time of each, in ms.
template <typename A, typename B>
std::pair<double, double> fastest_pair_ms(int runs, A&& a, B&& b)
{
    double best_a = 1e300, best_b = 1e300;
    for (int r = 0; r < runs; ++r) {
        best_a = std::min(best_a, time_ms(a));
        best_b = std::min(best_b, time_ms(b));
    }
    return {best_a, best_b};
}

}  // namespace cmfilter_bench
