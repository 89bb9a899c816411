// SPDX-License-Identifier: Apache-2.0
#include "bench/bench_chart.h"

#include "bench/gnuplot.h"
#include "cmfilter/util/atomic_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

namespace cmfilter::bench {

namespace {

// gnuplot strings in single quotes: a quote is doubled.
std::string quoted(const std::string& text)
{
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

std::string fixed(double value, int digits)
{
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << value;
    return s.str();
}

}  // namespace

std::string bench_chart_script(const SceneBench& bench, const std::string& data_path, const std::string& png_path,
                               ChartAxis axis)
{
    const bool time = axis == ChartAxis::Time;
    const bool has_exact = std::any_of(bench.rows.begin(), bench.rows.end(),
                                       [](const BenchRow& r) { return r.configuration.method == RenderMethod::Exact; });
    const bool has_gaussian_exact = std::any_of(bench.rows.begin(), bench.rows.end(), [](const BenchRow& r) {
        return r.configuration.method == RenderMethod::GaussianExact;
    });
    const bool has_mixture = std::any_of(bench.rows.begin(), bench.rows.end(), [](const BenchRow& r) {
        return r.configuration.method == RenderMethod::Mixture;
    });
    std::ostringstream s;
    s << "set terminal pngcairo size 900,760 font 'sans,11'\n"
      << "set output " << quoted(png_path) << "\n"
      << "set title "
      << quoted(std::filesystem::path(bench.scene).filename().string() + ", " +
                (bench.region == whole_frame(bench.width, bench.height)
                     ? ""
                     : "region " + to_string(bench.region) + " of ") +
                std::to_string(bench.width) + " x " + std::to_string(bench.height) + ": error against a " +
                std::to_string(bench.reference_samples) + "-ray reference (two agree to " +
                fixed(bench.reference_repeatability.all.mean, 2) + ")")
      << " noenhanced\n";
    if (time) s << "set xrange [*:" << 2 * bench.reference_seconds << "]\n";
    s << "set logscale xy\nset grid\nset bmargin 9\nset key outside below center horizontal maxcols 2 box noenhanced font 'sans,10'\n"
      << (time ? "set xlabel 'render time (s, pixel loop)' offset 0,0.4\n"
               : "set xlabel 'bytes read (colour tables + driver data; 1: procedural)' offset 0,0.4\n")
      << "set ylabel 'mean CIEDE2000 over the pixels a surface covers'\n"
      << "set datafile separator '\\t'\n";
    if (time)
        s << "set arrow from " << bench.reference_seconds << ", graph 0 to " << bench.reference_seconds
          << ", graph 1 nohead dt 3 lc rgb 'gray40'\n"
          << "set label 'reference time' at " << bench.reference_seconds
          << ", graph 0.95 right offset -0.5,0 tc rgb 'gray40'\n";
    s << "f(x) = 1.0\n"
      << "plot " << quoted(data_path)
      << " using ($1 == 0 ? $3 : 1/0):4 with points pt 9 ps 2 lc rgb 'red' title 'naive', \\\n"
      << (has_exact
              ? "     '' using ($1 == 6 ? $3 : 1/0):4 with points pt 8 ps 2 lc rgb 'black' title 'exact (texture histograms, or D_h)', \\\n"
              : "")
      << (has_gaussian_exact
              ? "     '' using ($1 == 7 ? $3 : 1/0):4 with points pt 4 ps 2 lc rgb 'dark-violet' title 'gaussian-exact (D_h moments)', \\\n"
              : "")
      << (has_mixture
              ? "     '' using ($1 == 8 ? $3 : 1/0):4 with points pt 6 ps 2 lc rgb 'brown' title 'mixture (textures: four moments; noise: sub-footprints)', \\\n"
              : "")
      << "     '' using ($1 == 1 ? $3 : 1/0):4 with points pt 7 ps 1.6 lc rgb 'blue' title 'gaussian, sqrt sigma spacing', \\\n"
      << "     '' using ($1 == 2 ? $3 : 1/0):4 with points pt 5 ps 1.4 lc rgb 'dark-cyan' title 'gaussian, linear sigma spacing', \\\n"
      << "     '' using ($1 == 3 ? $3 : 1/0):4 with linespoints pt 13 ps 1.4 lc rgb 'dark-green' title 'supersample, rays per pixel', \\\n"
      << "     '' using ($1 == 4 ? $3 : 1/0):4 with points pt 11 ps 1.4 lc rgb 'orange' title 'gaussian 256x256, area / major / minor width', \\\n"
      << "     '' using ($1 == 5 ? $3 : 1/0):4 with points pt 15 ps 1.4 lc rgb 'purple' title 'gaussian, fitted tables / shortcut', \\\n"
      << "     '' using ($6 == 1 && $5 != $4 ? $3 : 1/0):4:($3 * 0.3):($5 - $4) with vectors nohead lc rgb 'gray60' notitle, \\\n"
      << "     '' using ($6 == 1 ? $3 * 1.3 : 1/0):5:2 with labels offset 0.3,0 left font 'sans,9' notitle, \\\n"
      << "     f(x) with lines dt 2 lc rgb 'black' title 'target 1.0'\n";
    return s.str();
}

Status write_bench_chart(const SceneBench& bench, const std::string& png_path, ChartAxis axis)
{
    if (auto st = check_output_path(png_path, ".png"); !st) return st;
    auto out = AtomicOutput::begin(png_path);
    if (!out) return out.error();
    const std::string data = out->temp_path() + ".dat";
    std::string program;
    {
        // series: 0 naive, 1 gaussian sqrt, 2 gaussian linear, 3 supersample
        // (in rays order), 4 other footprint widths, 5 tolerance tables or
        // the small-sigma shortcut, 6 exact, 7 gaussian-exact, 8 mixture. Columns: series, label, time,
        // error, where its label goes, whether it is labelled.
        struct Point {
            int series = 0;
            std::string label;
            double x = 0, error = 0, label_y = 0;  // x: seconds or bytes (ChartAxis)
            bool labelled = true;
        };
        std::vector<Point> points;
        for (const BenchRow& r : bench.rows) {
            const BenchConfiguration& c = r.configuration;
            Point pt;
            pt.label = to_string(c.method);
            if (c.method == RenderMethod::Gaussian && (c.tolerance > 0 || c.shortcut > 0)) {
                pt.series = 5;
                pt.label = c.label().substr(std::string("gaussian ").size());
            } else if (c.method == RenderMethod::Gaussian && c.footprint != FootprintWidth::Rms) {
                pt.series = 4;  // named in the legend; their labels would sit on the 256x256 point
                pt.labelled = false;
            } else if (c.method == RenderMethod::Gaussian) {
                pt.series = c.spacing == SigmaSpacing::Sqrt ? 1 : 2;
                pt.label = std::to_string(c.table_values) + "x" + std::to_string(c.table_sigmas);
                pt.labelled = c.spacing == SigmaSpacing::Sqrt;  // the linear twin lies on it
            } else if (c.method == RenderMethod::Supersample) {
                pt.series = 3;
                pt.label = std::to_string(c.samples) + " spp";
            } else if (c.method == RenderMethod::Exact) {
                pt.series = 6;
            } else if (c.method == RenderMethod::GaussianExact) {
                pt.series = 7;
            } else if (c.method == RenderMethod::Mixture) {
                pt.series = 8;
            }
            pt.x = axis == ChartAxis::Time ? r.seconds
                                           : std::max(1.0, static_cast<double>(r.table_bytes + r.driver_bytes));
            pt.error = std::max(r.error.all.mean, 1e-4);
            pt.label_y = pt.error;
            points.push_back(pt);
        }
        // Labels sit right of their points (x 1.3 in time); those of points
        // close in time and error are stacked upwards, a line (x 1.18 in
        // error) apart, so none covers another, each joined to its point.
        std::vector<Point*> labelled;
        for (Point& pt : points)
            if (pt.labelled) labelled.push_back(&pt);
        std::sort(labelled.begin(), labelled.end(), [](const Point* a, const Point* b) { return a->error < b->error; });
        // A label's extent in decades of time: the plot is about 790 pixels
        // wide over the data's decades (to twice the reference's time, rounded
        // out to whole decades), a character of the labels' font about 6.5.
        double fastest = axis == ChartAxis::Time ? bench.reference_seconds : 1e300;
        double slowest = axis == ChartAxis::Time ? 2 * bench.reference_seconds : 1;
        for (const Point& pt : points) {
            fastest = std::min(fastest, pt.x);
            slowest = std::max(slowest, pt.x);
        }
        const double decades =
            std::max(1.0, std::ceil(std::log10(slowest)) - std::floor(std::log10(std::max(fastest, 1e-9))));
        const double decades_per_char = 7.0 * decades / 760;
        const auto extent = [&](const Point* pt) {
            const double start = std::log10(pt->x * 1.3);
            return std::make_pair(start, start + decades_per_char * (static_cast<double>(pt->label.size()) + 1));
        };
        // Lower labels stay, higher ones move up, until no two overlap.
        for (int pass = 0, moved = 1; moved && pass < 100; ++pass) {
            moved = 0;
            for (std::size_t i = 0; i < labelled.size(); ++i)
                for (std::size_t j = 0; j < i; ++j) {
                    const auto a = extent(labelled[i]), b = extent(labelled[j]);
                    const double lo = std::min(labelled[i]->label_y, labelled[j]->label_y);
                    const double hi = std::max(labelled[i]->label_y, labelled[j]->label_y);
                    if (a.first < b.second && b.first < a.second && hi < lo * 1.18) {
                        Point* upper = labelled[i]->label_y >= labelled[j]->label_y ? labelled[i] : labelled[j];
                        upper->label_y = lo * 1.18;
                        moved = 1;
                    }
                }
        }
        std::ofstream d(data);
        for (const Point& pt : points)
            d << pt.series << "\t" << pt.label << "\t" << pt.x << "\t" << pt.error << "\t" << pt.label_y << "\t"
              << (pt.labelled ? 1 : 0) << "\n";
        program = bench_chart_script(bench, data, out->temp_path(), axis);
    }
    auto drawn = run_gnuplot(program);
    std::remove(data.c_str());
    if (!drawn)
        return io_error("cannot draw '" + png_path +
                        "' with gnuplot (is it installed? apt-get install gnuplot-nox): " + drawn.error().message);
    return out->commit();
}

}  // namespace cmfilter::bench
