// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/colormap/map_breakpoints.h"

#include "cmfilter/color/ciede2000.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

namespace cmfilter {

namespace {

double largest_component(const ColorMap& map)
{
    double m = 0;
    for (const Rgb& c : map.texels) m = std::max({m, std::abs(c.r), std::abs(c.g), std::abs(c.b)});
    return m;
}

double max_abs(const Rgb& c) { return std::max({std::abs(c.r), std::abs(c.g), std::abs(c.b)}); }

// The knot indices k with lo < v_k < hi (inclusive when `closed`), limited
// for a clamped map to the knots that can change slope (-1 .. n).
struct KnotRange {
    long first = 0, last = -1;  // empty when last < first
};

KnotRange knots_in(const ColorMap& map, double lo, double hi, bool closed)
{
    const double xl = map.node_coordinate(lo), xh = map.node_coordinate(hi);
    KnotRange r;
    double first = std::ceil(xl), last = std::floor(xh);
    if (!closed) {
        if (first == xl) first += 1;
        if (last == xh) last -= 1;
    }
    if (map.wrap == WrapMode::Clamp) {
        first = std::max(first, -1.0);
        last = std::min(last, static_cast<double>(map.size()));
    }
    if (!(first <= last)) return r;
    r.first = static_cast<long>(first);
    r.last = static_cast<long>(last);
    return r;
}

double knot_value(const ColorMap& map, long k) { return map.vmin + (static_cast<double>(k) + 0.5) * map.texel_width(); }

// The slope of C0 (per node) on the node segment [k, k + 1].
Rgb node_slope(const ColorMap& map, long k) { return map.node(k + 1) - map.node(k); }

void sort_unique(std::vector<double>& v)
{
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

// Sample points for comparing C0 with an interpolant on [lo, hi]: C0's knots,
// the breakpoints, lo and hi, and the midpoints between consecutive ones.
std::vector<double> fit_samples(const ColorMap& map, const std::vector<double>& breakpoints, double lo, double hi)
{
    std::vector<double> s{lo, hi};
    const KnotRange kr = knots_in(map, lo, hi, false);
    for (long k = kr.first; k <= kr.last; ++k) s.push_back(knot_value(map, k));
    for (double t : breakpoints)
        if (t >= lo && t <= hi) s.push_back(t);
    sort_unique(s);
    const std::size_t n = s.size();
    for (std::size_t i = 0; i + 1 < n; ++i) s.push_back(0.5 * (s[i] + s[i + 1]));
    sort_unique(s);
    return s;
}

// A driver value and how often it occurs (its share of the texels).
struct WeightedValue {
    double f = 0, weight = 0;
};

// The values the mean errors are taken over: the driver's texels in 8192
// bins of [lo, hi] (each bin at the mean of its texels), or without a driver
// the fit samples of every map, uniformly.
std::vector<WeightedValue> weighted_samples(const BreakpointSelectionOptions& options,
                                            const std::vector<double>& breakpoints)
{
    std::vector<WeightedValue> out;
    const double lo = options.lo, hi = options.hi;
    if (options.driver && !options.driver->empty()) {
        const DriverWeights bins = driver_weights(*options.driver, lo, hi, 8192);
        for (std::size_t i = 0; i < bins.values.size(); ++i) out.push_back({bins.values[i], bins.shares[i]});
        return out;
    }
    std::vector<double> all;
    for (const ColorMap* map : options.maps) {
        const std::vector<double> s = fit_samples(*map, breakpoints, lo, hi);
        all.insert(all.end(), s.begin(), s.end());
    }
    sort_unique(all);
    for (double f : all) out.push_back({f, 1.0});
    return out;
}

// Removes breakpoints one at a time while every map's weighted mean error
// stays within the tolerance: each removal merges two segments, and the one
// whose merge raises the largest mean least goes first. Segment i runs from
// knot i - 1 to knot i over knots -inf, t_0 .. t_K, +inf (flat beyond the
// ends, so the end breakpoints can go too).
std::vector<double> remove_breakpoints(const BreakpointSelectionOptions& options, const std::vector<double>& candidates,
                                       const std::vector<WeightedValue>& samples)
{
    const std::size_t M = options.maps.size();
    double total_weight = 0;
    for (const WeightedValue& v : samples) total_weight += v.weight;
    if (!(total_weight > 0)) return candidates;
    std::vector<double> t = candidates;  // alive knots, in order
    const double inf = std::numeric_limits<double>::infinity();
    // Weighted error sum of map m over samples in [a, b) with the interpolant
    // through C(a), C(b) (flat at C(b) when a = -inf, at C(a) when b = +inf).
    const auto segment_error = [&](std::size_t m, double a, double b) {
        const ColorMap& map = *options.maps[m];
        const Rgb ca = map.evaluate(std::isfinite(a) ? a : b), cb = map.evaluate(std::isfinite(b) ? b : a);
        double e = 0;
        auto it = std::lower_bound(samples.begin(), samples.end(), a,
                                   [](const WeightedValue& v, double x) { return v.f < x; });
        for (; it != samples.end() && it->f < b; ++it) {
            const double w = std::isfinite(a) && std::isfinite(b) ? (it->f - a) / (b - a) : 0.0;
            e += it->weight * ciede2000_linear_rgb(map.evaluate(it->f), (1 - w) * ca + w * cb);
        }
        return e / total_weight;
    };
    const auto knot = [&](std::ptrdiff_t i) {
        return i < 0 ? -inf : (i >= static_cast<std::ptrdiff_t>(t.size()) ? inf : t[i]);
    };
    // seg[m][i]: segment between knot(i - 1) and knot(i), i = 0 .. K + 1.
    std::vector<std::vector<double>> seg(M), merged(M);
    std::vector<double> total(M, 0.0);
    for (std::size_t m = 0; m < M; ++m) {
        for (std::size_t i = 0; i <= t.size(); ++i) {
            seg[m].push_back(segment_error(m, knot(static_cast<std::ptrdiff_t>(i) - 1), knot(i)));
            total[m] += seg[m].back();
        }
    }
    // merged[m][j]: the segment from knot(j - 1) to knot(j + 1) once knot j goes.
    const auto merge_cost = [&](std::size_t m, std::size_t j) {
        return segment_error(m, knot(static_cast<std::ptrdiff_t>(j) - 1), knot(j + 1));
    };
    for (std::size_t m = 0; m < M; ++m)
        for (std::size_t j = 0; j < t.size(); ++j) merged[m].push_back(merge_cost(m, j));
    while (t.size() > 2) {
        std::size_t best = t.size();
        double best_worst = inf;
        for (std::size_t j = 0; j < t.size(); ++j) {
            double worst = 0;
            for (std::size_t m = 0; m < M; ++m)
                worst = std::max(worst, total[m] - seg[m][j] - seg[m][j + 1] + merged[m][j]);
            if (worst < best_worst) {
                best_worst = worst;
                best = j;
            }
        }
        const bool over_cap = options.max_breakpoints > 0 && t.size() > options.max_breakpoints;
        if (!(best_worst <= options.tolerance_de) && !over_cap) break;
        const std::size_t j = best;
        t.erase(t.begin() + static_cast<std::ptrdiff_t>(j));
        for (std::size_t m = 0; m < M; ++m) {
            total[m] += merged[m][j] - seg[m][j] - seg[m][j + 1];
            seg[m][j] = merged[m][j];
            seg[m].erase(seg[m].begin() + static_cast<std::ptrdiff_t>(j) + 1);
            merged[m].erase(merged[m].begin() + static_cast<std::ptrdiff_t>(j));
            // The knots beside the removed one now merge other segments.
            if (j > 0) merged[m][j - 1] = merge_cost(m, j - 1);
            if (j < t.size()) merged[m][j] = merge_cost(m, j);
        }
    }
    return t;
}

}  // namespace

Expected<std::vector<double>> map_breakpoints(const ColorMap& map, double lo, double hi, std::size_t max_knots)
{
    if (auto st = validate(map, "map_breakpoints map"); !st) return st.error();
    if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi))
        return bad_input("map_breakpoints range [" + std::to_string(lo) + ", " + std::to_string(hi) +
                         "] is invalid (expected finite lo <= hi)");
    const KnotRange kr = knots_in(map, lo, hi, false);
    if (kr.last >= kr.first && static_cast<std::size_t>(kr.last - kr.first + 1) > max_knots)
        return bad_input("the colour map puts " + std::to_string(kr.last - kr.first + 1) +
                         " knots in the driver range [" + std::to_string(lo) + ", " + std::to_string(hi) +
                         "] (expected at most " + std::to_string(max_knots) + ": a periodic map over many periods)");
    const double eps = 1e-7 * std::max(largest_component(map), 1e-30);
    std::vector<double> out;
    if (lo == hi) return out;
    // Beside lo: the node segment just above it.
    if (max_abs(node_slope(map, static_cast<long>(std::floor(map.node_coordinate(lo))))) > eps) out.push_back(lo);
    for (long k = kr.first; k <= kr.last; ++k)
        if (max_abs(node_slope(map, k) - node_slope(map, k - 1)) > eps) out.push_back(knot_value(map, k));
    // Beside hi: the node segment just below it.
    if (max_abs(node_slope(map, static_cast<long>(std::ceil(map.node_coordinate(hi))) - 1)) > eps) out.push_back(hi);
    sort_unique(out);
    return out;
}

Rgb breakpoint_interpolant(const ColorMap& map, const std::vector<double>& t, double f)
{
    if (!(f > t.front())) return map.evaluate(t.front());
    if (f >= t.back()) return map.evaluate(t.back());
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), f) - t.begin());
    const double w = (f - t[k - 1]) / (t[k] - t[k - 1]);
    return (1 - w) * map.evaluate(t[k - 1]) + w * map.evaluate(t[k]);
}

namespace {

// The largest over the maps of the weighted mean CIEDE2000 between C0 and
// its least-squares curve through `t` (fitted with `weights`, measured over
// `samples`).
double fitted_mean_error(const BreakpointSelectionOptions& options, const std::vector<double>& t,
                         const DriverWeights& weights, const std::vector<WeightedValue>& samples, double total_weight)
{
    double worst = 0;
    for (const ColorMap* map : options.maps) {
        const std::vector<Rgb> c = breakpoint_colors(*map, t, &weights);
        double sum = 0;
        for (const WeightedValue& v : samples)
            sum += v.weight * ciede2000_linear_rgb(map->evaluate(v.f), breakpoint_curve(t, c, v.f));
        worst = std::max(worst, sum / total_weight);
    }
    return worst;
}

// BreakpointSelectionOptions::fit_colors: with least-squares colours, remove
// breakpoints (the one whose removal raises the error least) while within
// the tolerance, then move each breakpoint in turn to the best of 12 places
// between its neighbours (within [lo, hi]), and remove again, until a pass
// removes none.
std::vector<double> refit_breakpoints(const BreakpointSelectionOptions& options, std::vector<double> t,
                                      const DriverWeights& weights, const std::vector<WeightedValue>& samples)
{
    double total_weight = 0;
    for (const WeightedValue& v : samples) total_weight += v.weight;
    if (!(total_weight > 0)) return t;
    const auto cost = [&](const std::vector<double>& k) {
        return fitted_mean_error(options, k, weights, samples, total_weight);
    };
    double current = cost(t);
    for (int pass = 0; pass < 6; ++pass) {
        bool removed = false;
        while (t.size() > 2) {
            std::size_t best = t.size();
            double best_cost = std::numeric_limits<double>::infinity();
            for (std::size_t j = 0; j < t.size(); ++j) {
                std::vector<double> without = t;
                without.erase(without.begin() + static_cast<std::ptrdiff_t>(j));
                const double c = cost(without);
                if (c < best_cost) {
                    best_cost = c;
                    best = j;
                }
            }
            if (!(best_cost <= options.tolerance_de)) break;
            t.erase(t.begin() + static_cast<std::ptrdiff_t>(best));
            current = best_cost;
            removed = true;
        }
        if (pass > 0 && !removed) break;
        constexpr int kPlaces = 12;
        for (std::size_t j = 0; j < t.size(); ++j) {
            const double a = j > 0 ? t[j - 1] : options.lo, b = j + 1 < t.size() ? t[j + 1] : options.hi;
            if (!(b > a)) continue;
            const double keep = t[j];
            double best_at = keep;
            for (int p = 1; p <= kPlaces; ++p) {
                const double at = a + (b - a) * p / (kPlaces + 1.0);
                if (!(at > a && at < b) || at == keep) continue;
                t[j] = at;
                const double c = cost(t);
                if (c < current) {
                    current = c;
                    best_at = at;
                }
            }
            t[j] = best_at;
        }
    }
    return t;
}

}  // namespace

BreakpointFit breakpoint_fit(const ColorMap& map, const std::vector<double>& breakpoints, double lo, double hi,
                             const DriverWeights* weights)
{
    BreakpointFit fit;
    fit.worst_f = lo;
    const std::vector<Rgb> colors = breakpoint_colors(map, breakpoints, weights);
    for (double f : fit_samples(map, breakpoints, lo, hi)) {
        const double de = ciede2000_linear_rgb(map.evaluate(f), breakpoint_curve(breakpoints, colors, f));
        if (de > fit.max_de) {
            fit.max_de = de;
            fit.worst_f = f;
        }
    }
    if (weights)
        for (std::size_t i = 0; i < weights->values.size(); ++i) {
            const double f = weights->values[i];
            fit.mean_de += weights->shares[i] *
                           ciede2000_linear_rgb(map.evaluate(f), breakpoint_curve(breakpoints, colors, f));
        }
    return fit;
}

Expected<BreakpointSelection> select_breakpoints(const BreakpointSelectionOptions& options)
{
    if (options.maps.empty())
        return bad_input("BreakpointSelectionOptions::maps is empty (expected at least one colour map)",
                         "BreakpointSelectionOptions::maps");
    const double lo = options.lo, hi = options.hi;
    BreakpointSelection sel;
    std::vector<double> candidates;
    for (std::size_t m = 0; m < options.maps.size(); ++m) {
        if (!options.maps[m])
            return bad_input("BreakpointSelectionOptions::maps[" + std::to_string(m) + "] is missing",
                             "BreakpointSelectionOptions::maps");
        auto b = map_breakpoints(*options.maps[m], lo, hi);
        if (!b) return b.error();
        candidates.insert(candidates.end(), b->begin(), b->end());
    }
    sort_unique(candidates);
    sel.candidates = candidates.size();
    std::vector<double>& out = sel.breakpoints;
    const bool capped = options.max_breakpoints > 0 && candidates.size() > options.max_breakpoints;
    if (candidates.size() > 2 && (options.tolerance_de > 0 || capped)) {
        const std::vector<WeightedValue> samples = weighted_samples(options, candidates);
        out = remove_breakpoints(options, candidates, samples);
        if (options.fit_colors && options.tolerance_de > 0 && options.driver && !options.driver->empty()) {
            sel.color_weights = driver_weights(*options.driver, lo, hi);
            out = refit_breakpoints(options, std::move(out), sel.color_weights, samples);
        }
    } else {
        out = candidates;
    }
    // Two at least: a flat map, or one breakpoint, is padded with the range's ends.
    if (out.size() < 2) {
        const double a = lo, b = hi > lo ? hi : lo + 1;
        if (out.empty()) out = {a, b};
        else if (out[0] > a) out.insert(out.begin(), a);
        else out.push_back(b);
    }
    const std::vector<WeightedValue> samples = weighted_samples(options, out);
    const DriverWeights* weights = sel.weights();
    for (const ColorMap* map : options.maps) {
        sel.fits.push_back(breakpoint_fit(*map, out, lo, hi, weights));
        sel.max_de = std::max(sel.max_de, sel.fits.back().max_de);
        const std::vector<Rgb> colors = breakpoint_colors(*map, out, weights);
        double sum = 0, weight = 0;
        for (const WeightedValue& v : samples) {
            sum += v.weight * ciede2000_linear_rgb(map->evaluate(v.f), breakpoint_curve(out, colors, v.f));
            weight += v.weight;
        }
        sel.mean_de.push_back(weight > 0 ? sum / weight : 0.0);
        sel.max_mean_de = std::max(sel.max_mean_de, sel.mean_de.back());
    }
    return sel;
}

void ramp_weights(const std::vector<double>& t, double f, double* ramps)
{
    for (std::size_t k = 1; k < t.size(); ++k)
        ramps[k - 1] = std::clamp((f - t[k - 1]) / (t[k] - t[k - 1]), 0.0, 1.0);  // r_k(f)
}

std::vector<Rgb> ramp_colors(const ColorMap& map, const std::vector<double>& t, const DriverWeights* weights)
{
    const std::vector<Rgb> at = breakpoint_colors(map, t, weights);
    std::vector<Rgb> c{at.front()};
    for (std::size_t k = 1; k < t.size(); ++k) c.push_back(at[k] - at[k - 1]);
    return c;
}

Rgb ramp_color(const std::vector<Rgb>& colors, const float* ramps)
{
    Rgb c = colors.front();
    for (std::size_t k = 1; k < colors.size(); ++k) c += static_cast<double>(ramps[k - 1]) * colors[k];
    return c;
}

}  // namespace cmfilter
