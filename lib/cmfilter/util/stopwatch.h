// SPDX-License-Identifier: Apache-2.0
// Wall-clock time of a phase, for the timings commands report (never for
// tests: speed is measured by the benchmarks, docs/benchmarks.md).
#pragma once

#include <chrono>

namespace cmfilter {

class Stopwatch {
public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    double elapsed_ms() const
    {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace cmfilter
