// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthetic/light_dome.h"

#include "cmfilter/stack/light_file.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <sstream>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180;

Vec3 direction(double elevation, double azimuth)
{
    const double c = std::cos(elevation);
    return {c * std::cos(azimuth), c * std::sin(azimuth), std::sin(elevation)};
}

// Light k of the golden-angle spiral of `count` above z0.
std::vector<Vec3> fibonacci_dome(int count, double min_elevation)
{
    const double z0 = std::sin(min_elevation);
    const double golden_angle = kPi * (3 - std::sqrt(5.0));
    std::vector<Vec3> lights;
    lights.reserve(count);
    for (int k = 0; k < count; ++k) {
        const double z = z0 + (1 - z0) * (k + 0.5) / count;
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        const double phi = std::fmod(golden_angle * k, 2 * kPi);
        lights.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    return lights;
}

// Integer counts >= 1 proportional to `weights`, summing to `total` (>=
// weights.size()), by largest remainder.
std::vector<int> apportion(const std::vector<double>& weights, int total)
{
    const double sum = std::accumulate(weights.begin(), weights.end(), 0.0);
    const std::size_t n = weights.size();
    std::vector<double> quota(n);
    std::vector<int> counts(n);
    int assigned = 0;
    for (std::size_t k = 0; k < n; ++k) {
        quota[k] = total * weights[k] / sum;
        counts[k] = std::max(1, static_cast<int>(std::floor(quota[k])));
        assigned += counts[k];
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    // Largest remainder first; ties by ring index, so the result is fixed.
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return quota[a] - counts[a] > quota[b] - counts[b]; });
    for (std::size_t i = 0; assigned < total; i = (i + 1) % n) {
        ++counts[order[i]];
        ++assigned;
    }
    for (std::size_t i = n; assigned > total;) {
        i = (i == 0 ? n : i) - 1;
        if (counts[order[i]] > 1) {
            --counts[order[i]];
            --assigned;
        }
    }
    return counts;
}

std::vector<Vec3> regular_dome(int count, double min_elevation)
{
    if (count == 1) return {{0, 0, 1}};
    const int on_rings = count - 1;  // one light at the zenith
    const double span = 0.5 * kPi - min_elevation;
    int best_rings = 1;
    double best_score = 1e300;
    for (int rings = 1; rings <= on_rings; ++rings) {
        const double step = span / rings;
        double weight = 0;
        for (int k = 0; k < rings; ++k) weight += std::cos(min_elevation + k * step);
        const double scale = on_rings / weight;  // lights per unit cosine
        const double score = std::abs(std::log(2 * kPi / scale / step));
        if (score < best_score) {
            best_score = score;
            best_rings = rings;
        }
    }
    const double step = span / best_rings;
    std::vector<double> weights(best_rings);
    for (int k = 0; k < best_rings; ++k) weights[k] = std::cos(min_elevation + k * step);
    const std::vector<int> counts = apportion(weights, on_rings);
    std::vector<Vec3> lights;
    lights.reserve(count);
    for (int k = 0; k < best_rings; ++k) {
        const double elevation = min_elevation + k * step;
        for (int j = 0; j < counts[k]; ++j)
            lights.push_back(direction(elevation, 2 * kPi * (j + 0.5 * (k % 2)) / counts[k]));
    }
    lights.push_back({0, 0, 1});
    return lights;
}

std::vector<Vec3> stage_dome(int count, double min_elevation)
{
    const int dense = count / 2;
    const double rings[2] = {min_elevation, min_elevation + (0.5 * kPi - min_elevation) / 6};
    std::vector<Vec3> lights;
    lights.reserve(count);
    for (int j = 0; j < dense; ++j) {
        const double azimuth = (-75 + 150 * (j + 0.5) / dense) * kDegree;
        lights.push_back(direction(rings[j % 2], azimuth));
    }
    for (const Vec3& l : fibonacci_dome(count - dense, min_elevation)) lights.push_back(l);
    return lights;
}

std::string number_text(double v)
{
    std::ostringstream s;
    s << v;
    return s.str();
}

Error bad_dome(const std::string& text, const std::string& why)
{
    return bad_input("dome '" + text + "' " + why +
                         " (expected regular:N, fibonacci:N, stage:N or file:PATH.lp, N a whole number of lights)",
                     "DomeOptions::kind");
}

}  // namespace

const char* to_string(DomeKind kind)
{
    switch (kind) {
    case DomeKind::Regular: return "regular";
    case DomeKind::Fibonacci: return "fibonacci";
    case DomeKind::Stage: return "stage";
    case DomeKind::File: return "file";
    }
    return "?";
}

Expected<DomeOptions> parse_dome(const std::string& text)
{
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos) return bad_dome(text, "has no ':'");
    const std::string kind = text.substr(0, colon), rest = text.substr(colon + 1);
    DomeOptions o;
    if (kind == "file") {
        if (rest.empty()) return bad_dome(text, "names no file");
        o.kind = DomeKind::File;
        o.path = rest;
        return o;
    }
    if (kind == "regular") o.kind = DomeKind::Regular;
    else if (kind == "fibonacci") o.kind = DomeKind::Fibonacci;
    else if (kind == "stage") o.kind = DomeKind::Stage;
    else return bad_dome(text, "is of an unknown kind '" + kind + "'");
    if (rest.empty() || rest.find_first_not_of("0123456789") != std::string::npos || rest.size() > 9)
        return bad_dome(text, "has no whole number of lights after the ':'");
    o.count = std::atoi(rest.c_str());
    return o;
}

std::string dome_text(const DomeOptions& options)
{
    if (options.kind == DomeKind::File) return "file:" + options.path;
    return std::string(to_string(options.kind)) + ":" + std::to_string(options.count);
}

Expected<std::vector<Vec3>> make_dome(const DomeOptions& options)
{
    if (options.kind == DomeKind::File) {
        auto file = read_light_file(options.path);
        if (!file) return file.error();
        std::vector<Vec3> lights;
        for (const LightEntry& e : file->lights) lights.push_back(e.direction);
        return lights;
    }
    if (options.count < 1 || options.count > kMaxDomeLights)
        return bad_input("DomeOptions::count " + std::to_string(options.count) + " is invalid: expected 1 to " +
                             std::to_string(kMaxDomeLights) + " lights",
                         "DomeOptions::count");
    const double e = options.min_elevation_degrees;
    const bool fibonacci = options.kind == DomeKind::Fibonacci;
    if (!(std::isfinite(e) && e >= 0 && (fibonacci ? e < 90 : e <= 80)))
        return bad_input("DomeOptions::min_elevation_degrees " + number_text(e) + " is invalid: expected 0 <= e " +
                             (fibonacci ? "< 90" : "<= 80") + " degrees for a " + to_string(options.kind) + " dome",
                         "DomeOptions::min_elevation_degrees");
    switch (options.kind) {
    case DomeKind::Regular: return regular_dome(options.count, e * kDegree);
    case DomeKind::Fibonacci: return fibonacci_dome(options.count, e * kDegree);
    case DomeKind::Stage: return stage_dome(options.count, e * kDegree);
    case DomeKind::File: break;
    }
    return runtime_error("make_dome: unknown dome kind");
}

}  // namespace cmfilter
