// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/tables/gaussian_color_table.h"

#include "cmfilter/tables/cosine_series_rows.h"
#include "cmfilter/tables/gaussian_convolution.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cmfilter {

namespace {

// Largest bound on the cosine series' dropped harmonics at which a row takes
// that path: 600 times below float32 rounding of a unit value (6e-8).
constexpr double kSeriesTolerance = 1e-10;

}  // namespace

const char* to_string(SigmaSpacing spacing) { return spacing == SigmaSpacing::Sqrt ? "sqrt" : "linear"; }

Expected<SigmaSpacing> parse_sigma_spacing(const std::string& name)
{
    if (name == "linear") return SigmaSpacing::Linear;
    if (name == "sqrt") return SigmaSpacing::Sqrt;
    return bad_input("unknown sigma spacing '" + name + "' (expected linear or sqrt)");
}

double TableAxes::value_first() const { return wrap == WrapMode::Clamp ? vmin - margin : vmin; }

double TableAxes::value_last() const
{
    switch (wrap) {
    case WrapMode::Clamp: return vmax + margin;
    case WrapMode::Mirror: return vmax;
    case WrapMode::Repeat: return vmin + (vmax - vmin) * (values - 1) / values;
    }
    return vmax;
}

double TableAxes::value_at(int i) const
{
    if (wrap == WrapMode::Repeat) return vmin + (vmax - vmin) * i / values;
    if (i == values - 1) return value_last();
    return value_first() + (value_last() - value_first()) * i / (values - 1);
}

double TableAxes::sigma_at(int j) const
{
    if (j == sigmas - 1) return sigma_max;
    const double t = static_cast<double>(j) / (sigmas - 1);
    return sigma_max * (spacing == SigmaSpacing::Sqrt ? t * t : t);
}

Expected<TableAxes> make_table_axes(const ColorMap& map, const GaussianColorTableOptions& options)
{
    constexpr int kMaxNodes = 1 << 16;
    auto check_count = [&](int n, const char* field) -> Status {
        if (n < 2 || n > kMaxNodes) {
            std::ostringstream msg;
            msg << field << " " << n << " is out of range (expected 2.." << kMaxNodes << " samples on the axis)";
            return bad_input(msg.str(), field);
        }
        return ok();
    };
    if (auto st = check_count(options.values, "GaussianColorTableOptions::values"); !st) return st.error();
    if (auto st = check_count(options.sigmas, "GaussianColorTableOptions::sigmas"); !st) return st.error();

    TableAxes axes;
    axes.values = options.values;
    axes.sigmas = options.sigmas;
    axes.vmin = map.vmin;
    axes.vmax = map.vmax;
    axes.wrap = map.wrap;
    axes.spacing = options.spacing;
    axes.sigma_max = options.sigma_max.value_or((map.vmax - map.vmin) / 4.0);
    if (!std::isfinite(axes.sigma_max) || axes.sigma_max <= 0) {
        std::ostringstream msg;
        msg << "GaussianColorTableOptions::sigma_max " << axes.sigma_max << " is invalid (expected a finite value > 0)";
        return bad_input(msg.str(), "GaussianColorTableOptions::sigma_max");
    }
    if (map.wrap == WrapMode::Clamp) {
        axes.margin = options.margin.value_or(3.0 * axes.sigma_max);
        if (!std::isfinite(axes.margin) || axes.margin < 0) {
            std::ostringstream msg;
            msg << "GaussianColorTableOptions::margin " << axes.margin << " is invalid (expected a finite value >= 0)";
            return bad_input(msg.str(), "GaussianColorTableOptions::margin");
        }
    }
    return axes;
}

GaussianColorTable::GaussianColorTable(TableAxes axes, std::vector<float> rgb) : axes_(axes), rgb_(std::move(rgb))
{
    value_scale_ = axes_.wrap == WrapMode::Repeat ? axes_.values / (axes_.vmax - axes_.vmin)
                                                  : (axes_.values - 1) / (axes_.value_last() - axes_.value_first());
    inv_sigma_max_ = 1.0 / axes_.sigma_max;
}

Expected<GaussianColorTable> GaussianColorTable::bake(const ColorMap& map, const GaussianColorTableOptions& options)
{
    if (auto st = validate(map, "colour map"); !st) return st.error();
    auto axes = make_table_axes(map, options);
    if (!axes) return axes.error();
    const TableAxes& ax = *axes;

    std::vector<float> rgb(static_cast<std::size_t>(ax.values) * ax.sigmas * 3);
    auto row_data = [&](int j) { return rgb.data() + static_cast<std::size_t>(j) * ax.values * 3; };

    // Rows with sigma of a few value nodes or more: the cosine series of the
    // mirrored map, two rows per FFT (clamp maps; cosine_series_rows.h), where
    // its bound on the dropped harmonics is below kSeriesTolerance and it is
    // estimated cheaper than the exact step / kink-block sum.
    struct Task {
        bool series = false;
        int row_a = 0, row_b = -1;
    };
    std::vector<Task> tasks;
    std::vector<int> series_rows;
    std::optional<CosineSeriesRows> series;
    if (ax.wrap == WrapMode::Clamp) {
        series.emplace(map, ax.value_first(), (ax.value_last() - ax.value_first()) / (ax.values - 1), ax.values,
                       ax.sigma_max);
    }
    for (int j = 0; j < ax.sigmas; ++j) {
        const double sigma = ax.sigma_at(j);
        if (series && series->error_bound(sigma) <= kSeriesTolerance &&
            series->row_cost() < ax.values * GaussianConvolution::estimated_cost(map, sigma))
            series_rows.push_back(j);
        else tasks.push_back({false, j, -1});
    }
    for (std::size_t k = 0; k < series_rows.size(); k += 2)
        tasks.push_back({true, series_rows[k], k + 1 < series_rows.size() ? series_rows[k + 1] : -1});
    if (!series_rows.empty()) series->compute_coefficients(options.threads);

    std::vector<double> value_nodes(ax.values);
    for (int i = 0; i < ax.values; ++i) value_nodes[i] = ax.value_at(i);
    parallel_for(static_cast<int>(tasks.size()), options.threads, [&](int t) {
        const Task& task = tasks[t];
        if (task.series) {
            series->evaluate(ax.sigma_at(task.row_a), row_data(task.row_a),
                             task.row_b >= 0 ? ax.sigma_at(task.row_b) : 0.0,
                             task.row_b >= 0 ? row_data(task.row_b) : nullptr);
            return;
        }
        const GaussianConvolution row(map, ax.sigma_at(task.row_a));  // eq. 10 for sigma_j
        float* out = row_data(task.row_a);
        for (int i = 0; i < ax.values; ++i) {
            const Rgb c = row(value_nodes[i]);
            out[3 * i + 0] = static_cast<float>(c.r);
            out[3 * i + 1] = static_cast<float>(c.g);
            out[3 * i + 2] = static_cast<float>(c.b);
        }
    });
    for (float x : rgb)
        if (!std::isfinite(x)) return runtime_error("baking produced a non-finite table value (internal error)");
    return GaussianColorTable(ax, std::move(rgb));
}

Rgb GaussianColorTable::node(int i, int j) const
{
    const float* p = rgb_.data() + (static_cast<std::size_t>(j) * axes_.values + i) * 3;
    return {p[0], p[1], p[2]};
}

Rgb GaussianColorTable::lookup(double mean, double sigma, LookupCounters* counters) const
{
    LookupCounters dummy;
    LookupCounters& count = counters ? *counters : dummy;
    ++count.lookups;
    const TableAxes& ax = axes_;
    const bool periodic = ax.wrap != WrapMode::Clamp;
    if (std::isnan(mean) || std::isnan(sigma) || (periodic && !std::isfinite(mean))) {
        ++count.invalid;
        return {};
    }

    // Row coordinate (sigma < 0 is treated as 0; beyond sigma_max clamps).
    double t = std::max(0.0, sigma) * inv_sigma_max_;
    if (t > 1.0) {
        ++count.sigma_clamped;
        t = 1.0;
    }
    if (ax.spacing == SigmaSpacing::Sqrt) t = std::sqrt(t);
    const double y = t * (ax.sigmas - 1);

    // Column coordinate, following the wrap rule beyond the axis.
    double x;
    int i0, i1;
    if (ax.wrap == WrapMode::Repeat) {
        const double period = ax.vmax - ax.vmin;
        x = wrap_coordinate(mean - ax.vmin, period, WrapMode::Repeat) * value_scale_;
        i0 = std::min(static_cast<int>(x), ax.values - 1);
        i1 = i0 + 1 == ax.values ? 0 : i0 + 1;
    } else {
        double v = mean;
        if (ax.wrap == WrapMode::Mirror) {
            v = ax.vmin + wrap_coordinate(mean - ax.vmin, ax.vmax - ax.vmin, WrapMode::Mirror);
        } else if (!(v >= ax.value_first() && v <= ax.value_last())) {
            ++count.value_clamped;
            v = std::clamp(v, ax.value_first(), ax.value_last());
        }
        x = std::clamp((v - ax.value_first()) * value_scale_, 0.0, static_cast<double>(ax.values - 1));
        i0 = std::min(static_cast<int>(x), ax.values - 2);
        i1 = i0 + 1;
    }
    const double fx = x - i0;
    const int j0 = std::min(static_cast<int>(y), ax.sigmas - 2);
    const double fy = y - j0;

    const float* row0 = rgb_.data() + static_cast<std::size_t>(j0) * ax.values * 3;
    const float* row1 = row0 + static_cast<std::size_t>(ax.values) * 3;
    const float *a = row0 + 3 * i0, *b = row0 + 3 * i1, *c = row1 + 3 * i0, *d = row1 + 3 * i1;
    double out[3];
    for (int ch = 0; ch < 3; ++ch) {
        const double top = a[ch] + fx * (double{b[ch]} - a[ch]);
        const double bottom = c[ch] + fx * (double{d[ch]} - c[ch]);
        out[ch] = top + fy * (bottom - top);
    }
    return {out[0], out[1], out[2]};
}

}  // namespace cmfilter
