#include "cmfilter/bench_chart.h"

#include "cmfilter/atomic_output.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace cmfilter {

namespace {

// gnuplot strings in single quotes: a quote is doubled.
std::string quoted(const std::string& text)
{
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

}  // namespace

std::string bench_chart_script(const SceneBench& bench, const std::string& data_path, const std::string& png_path)
{
    std::ostringstream s;
    s << "set terminal pngcairo size 900,650 font 'sans,11'\n"
      << "set output " << quoted(png_path) << "\n"
      << "set title " << quoted(std::filesystem::path(bench.scene).filename().string() + ", " +
                                std::to_string(bench.width) + " x " + std::to_string(bench.height) +
                                ": error against a " + std::to_string(bench.reference_samples) +
                                "-ray reference")
      << " noenhanced\n"
      << "set xrange [*:" << 2 * bench.reference_seconds << "]\n"
      << "set logscale xy\nset grid\nset key inside left bottom box opaque noenhanced font 'sans,10'\n"
      << "set xlabel 'render time (s, pixel loop)'\nset ylabel 'mean CIEDE2000 over hit pixels'\n"
      << "set datafile separator '\\t'\n"
      << "set arrow from " << bench.reference_seconds << ", graph 0 to " << bench.reference_seconds
      << ", graph 1 nohead dt 3 lc rgb 'gray40'\n"
      << "set label 'reference time' at " << bench.reference_seconds << ", graph 0.95 right offset -0.5,0 tc rgb 'gray40'\n"
      << "f(x) = 1.0\n"
      << "plot " << quoted(data_path) << " using ($1 == 0 ? $3 : 1/0):4 with points pt 9 ps 2 lc rgb 'red' title 'naive', \\\n"
      << "     '' using ($1 == 1 ? $3 : 1/0):4 with points pt 7 ps 1.6 lc rgb 'blue' title 'gaussian (sqrt sigma spacing)', \\\n"
      << "     '' using ($1 == 2 ? $3 : 1/0):4 with points pt 5 ps 1.4 lc rgb 'dark-cyan' title 'gaussian (linear sigma spacing)', \\\n"
      << "     '' using ($1 == 3 ? $3 : 1/0):4 with linespoints pt 13 ps 1.4 lc rgb 'dark-green' title 'supersample (rays per pixel)', \\\n"
      << "     '' using ($1 == 4 ? $3 : 1/0):4 with points pt 11 ps 1.4 lc rgb 'orange' title 'gaussian 256x256, other footprint widths', \\\n"
      << "     '' using ($1 == 5 ? $3 : 1/0):4 with points pt 15 ps 1.4 lc rgb 'purple' title 'gaussian, tolerance tables or small-sigma shortcut', \\\n"
      << "     '' using ($1 == 2 ? 1/0 : $3):4:2 with labels offset 0.8,0.6 left font 'sans,9' notitle, \\\n"
      << "     f(x) with lines dt 2 lc rgb 'black' title 'target 1.0'\n";
    return s.str();
}

Status write_bench_chart(const SceneBench& bench, const std::string& png_path)
{
    if (auto st = check_output_path(png_path, ".png"); !st) return st;
    auto out = AtomicOutput::begin(png_path);
    if (!out) return out.error();
    const std::string data = out->temp_path() + ".dat", script = out->temp_path() + ".gp";
    {
        // series: 0 naive, 1 gaussian sqrt, 2 gaussian linear, 3 supersample (in rays order),
        // 4 other footprint widths, 5 tolerance tables or the small-sigma shortcut
        std::ofstream d(data);
        for (const BenchRow& r : bench.rows) {
            const BenchConfiguration& c = r.configuration;
            int series = 0;
            std::string label = "naive";
            if (c.method == RenderMethod::Gaussian && (c.tolerance > 0 || c.shortcut > 0)) {
                series = 5;
                label = c.label().substr(std::string("gaussian ").size());
            } else if (c.method == RenderMethod::Gaussian && c.footprint != FootprintWidth::Rms) {
                series = 4;
                label = to_string(c.footprint);
            } else if (c.method == RenderMethod::Gaussian) {
                series = c.spacing == SigmaSpacing::Sqrt ? 1 : 2;
                label = std::to_string(c.table_values) + "x" + std::to_string(c.table_sigmas);
            } else if (c.method == RenderMethod::Supersample) {
                series = 3;
                label = std::to_string(c.samples) + " spp";
            }
            d << series << "\t" << label << "\t" << r.seconds << "\t" << std::max(r.error.all.mean, 1e-4) << "\n";
        }
        std::ofstream g(script);
        g << bench_chart_script(bench, data, out->temp_path());
    }
    const std::string command = "gnuplot " + quoted(script) + " 2>&1";
    std::string output;
    int status = -1;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[256];
        while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
        status = pclose(pipe);
    }
    std::remove(data.c_str());
    std::remove(script.c_str());
    if (status != 0)
        return io_error("cannot draw '" + png_path + "' with gnuplot (is it installed? apt-get install gnuplot-nox)" +
                        (output.empty() ? std::string() : ": " + output));
    return out->commit();
}

}  // namespace cmfilter
