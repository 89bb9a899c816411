// SPDX-License-Identifier: Apache-2.0
// The chart of a SceneBench (render_benchmark.h): mean CIEDE2000 against the
// reference over wall time, log-log, one point per configuration, labelled;
// supersampling joined as a curve (more rays: right and down), the gaussian
// tables by spacing, naive alone, the target 1.0 as a line and the
// reference's own time as a vertical line. Drawn by gnuplot (pngcairo),
// started without a shell (gnuplot.h), which must be on the PATH; written
// atomically.
#pragma once

#include "cmfilter/util/error.h"
#include "bench/render_benchmark.h"

#include <string>

namespace cmfilter::bench {

// What a chart's x axis is: each configuration's render time, or the bytes
// it reads (BenchRow::table_bytes + driver_bytes; 1 for none).
enum class ChartAxis { Time, Bytes };

// The gnuplot program that draws `bench` into `png_path` from `data_path`
// (written by write_bench_chart beside it).
std::string bench_chart_script(const SceneBench& bench, const std::string& data_path, const std::string& png_path,
                               ChartAxis axis = ChartAxis::Time);

// Io when gnuplot cannot be run or fails; the PNG is not left half-written.
Status write_bench_chart(const SceneBench& bench, const std::string& png_path, ChartAxis axis = ChartAxis::Time);

}  // namespace cmfilter::bench
