// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/displacement_texture.h"

#include "cmfilter/texture/anisotropic_probes.h"
#include "cmfilter/texture/box_pyramid.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

namespace cmfilter {

namespace {

// Probes of at most 2^kLinearLod texels wide read the linearised fields, of
// at least 2^(kLinearLod + 1) the box means; in between, a blend.
constexpr double kLinearLod = 0;
constexpr double kLowestLod = -64;
constexpr double kInfiniteLod = 1e9;
// The narrowest box side read from the summed-area table, in texels.
constexpr double kThinnest = 1e-3;

int wrap_index(long long i, int n)
{
    const long long m = i % n;
    return static_cast<int>(m < 0 ? m + n : m);
}

// Where (u, v) falls among the texel centres of an m x m periodic grid: the
// four texels around it and the bilinear weights, a along u, b along v.
struct Cell {
    int x0, x1, y0, y1;
    double a, b;
};

Cell cell_at(double u, double v, int m)
{
    const double s = (u - std::floor(u)) * m - 0.5, t = (v - std::floor(v)) * m - 0.5;
    const double fx = std::floor(s), fy = std::floor(t);
    const int x = static_cast<int>(fx), y = static_cast<int>(fy);
    return {wrap_index(x, m), wrap_index(x + 1LL, m), wrap_index(y, m), wrap_index(y + 1LL, m), s - fx, t - fy};
}

// A bilinear field over level 0 at a cell: its value and gradient (d/du,
// d/dv, texture units).
struct Linear {
    double value, du, dv;
};

Linear linear_at(const std::vector<double>& f, int n, const Cell& c)
{
    const double f00 = f[static_cast<std::size_t>(c.y0) * n + c.x0], f10 = f[static_cast<std::size_t>(c.y0) * n + c.x1];
    const double f01 = f[static_cast<std::size_t>(c.y1) * n + c.x0], f11 = f[static_cast<std::size_t>(c.y1) * n + c.x1];
    const double top = f00 + c.a * (f10 - f00), bottom = f01 + c.a * (f11 - f01);
    return {top + c.b * (bottom - top), ((f10 - f00) + c.b * ((f11 - f01) - (f10 - f00))) * n, (bottom - top) * n};
}

using Moments = std::array<double, kChannels>;

// The exact means of the channels of the bilinear surface (heights about
// `reference`, and its bilinear slopes) over each texel's square
// [i, i + 1] x [j, j + 1] / N, N x N x kChannels, row-major. The square is
// cut at the texel's centre into four quarters, each inside one bilinear
// patch, where a product of two fields is at most quadratic along each axis:
// 2-point Gauss-Legendre per half-axis is exact, 4 x 4 points of weight 1/16.
std::vector<double> cell_moments(const std::vector<double>& h, const std::vector<double>& sx,
                                 const std::vector<double>& sy, int n, double reference)
{
    const double g = 0.25 / std::sqrt(3.0);
    const double offsets[4] = {-0.25 - g, -0.25 + g, 0.25 - g, 0.25 + g};
    std::vector<double> cells(static_cast<std::size_t>(n) * n * kChannels, 0.0);
    const auto at = [n](const std::vector<double>& f, int i, int j) {
        return f[static_cast<std::size_t>(wrap_index(j, n)) * n + wrap_index(i, n)];
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double* out = cells.data() + (static_cast<std::size_t>(j) * n + i) * kChannels;
            for (const double dy : offsets)
                for (const double dx : offsets) {
                    // Bilinear between texel (i, j) and its neighbour towards (dx, dy).
                    const int ni = i + (dx < 0 ? -1 : 1), nj = j + (dy < 0 ? -1 : 1);
                    const double a = std::abs(dx), b = std::abs(dy);
                    const auto lerp = [&](const std::vector<double>& f) {
                        return (1 - b) * ((1 - a) * at(f, i, j) + a * at(f, ni, j)) +
                               b * ((1 - a) * at(f, i, nj) + a * at(f, ni, nj));
                    };
                    const double dh = lerp(h) - reference, x = lerp(sx), y = lerp(sy);
                    const double values[kChannels] = {dh, x, y, x * x, y * y, x * y, dh * dh};
                    for (int c = 0; c < kChannels; ++c) out[c] += values[c] / 16;
                }
        }
    return cells;
}

Status check_options(const DisplacementOptions& options, const std::string& name)
{
    if (!std::isfinite(options.height_scale) || options.height_scale < 0) {
        std::ostringstream msg;
        msg << name << ": height_scale " << options.height_scale << " is out of range (expected finite and >= 0)";
        return bad_input(msg.str());
    }
    if (options.max_probes < 1)
        return bad_input(name + ": max_probes " + std::to_string(options.max_probes) +
                         " is out of range (expected >= 1)");
    return ok();
}

}  // namespace

Expected<DisplacementTexture> DisplacementTexture::load(const DisplacementOptions& options)
{
    const std::string name = "displacement '" + options.path + "'";
    if (auto checked = check_options(options, name); !checked) return checked.error();
    DriverReadOptions read;
    read.path = options.path;
    read.channel = options.channel;
    read.nonfinite = options.nonfinite;
    read.threads = options.threads;
    auto image = read_driver(read);
    if (!image) return image.error();
    return from_texels(std::move(image->values), image->width, image->height, options);
}

Expected<DisplacementTexture> DisplacementTexture::from_texels(std::vector<float> texels, int width, int height,
                                                               const DisplacementOptions& options)
{
    const std::string name = "displacement '" + options.path + "'";
    if (auto checked = check_options(options, name); !checked) return checked.error();
    if (width < 1 || width != height)
        return bad_input(name + " is " + std::to_string(width) + " x " + std::to_string(height) +
                         " texels (expected a square image, width = height: one repeat is a square)");
    const int n = width;
    const std::size_t count = static_cast<std::size_t>(n) * n;
    if (texels.size() != count)
        return bad_input(name + ": " + std::to_string(texels.size()) + " texels for " + std::to_string(n) + " x " +
                         std::to_string(n) + " (expected " + std::to_string(count) + ")");
    auto data = std::make_shared<Data>();
    data->path = options.path;
    data->n = n;
    data->height_scale = options.height_scale;
    data->max_probes = options.max_probes;
    data->h.resize(count);
    double sum = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (!std::isfinite(texels[i])) {
            std::ostringstream msg;
            msg << name << ": texel (" << i % n << ", " << i / n << ") is " << texels[i]
                << " (expected finite heights)";
            return bad_input(msg.str());
        }
        data->h[i] = static_cast<double>(texels[i]) * options.height_scale;
        sum += data->h[i];
    }
    data->reference = sum / static_cast<double>(count);
    // The Sobel slopes of maketx --bumpslopes, neighbours wrapping, per texel
    // times N texels per texture unit.
    data->sx.resize(count);
    data->sy.resize(count);
    const auto& h = data->h;
    const auto at = [&](int i, int j) { return h[static_cast<std::size_t>(wrap_index(j, n)) * n + wrap_index(i, n)]; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double gx = (at(i + 1, j - 1) - at(i - 1, j - 1)) + 2 * (at(i + 1, j) - at(i - 1, j)) +
                              (at(i + 1, j + 1) - at(i - 1, j + 1));
            const double gy = (at(i - 1, j + 1) - at(i - 1, j - 1)) + 2 * (at(i, j + 1) - at(i, j - 1)) +
                              (at(i + 1, j + 1) - at(i + 1, j - 1));
            data->sx[static_cast<std::size_t>(j) * n + i] = gx / 8 * n;
            data->sy[static_cast<std::size_t>(j) * n + i] = gy / 8 * n;
        }
    // Level 0 and the box means above it.
    const auto channels_of = [&](std::size_t i, auto* out, std::size_t stride) {
        const double dh = h[i] - data->reference, sx = data->sx[i], sy = data->sy[i];
        const double values[kChannels] = {dh, sx, sy, sx * sx, sy * sy, sx * sy, dh * dh};
        for (int c = 0; c < kChannels; ++c)
            out[c * stride] = static_cast<std::remove_pointer_t<decltype(out)>>(values[c]);
    };
    std::vector<float> level0(count * kChannels);
    for (std::size_t i = 0; i < count; ++i) channels_of(i, level0.data() + i * kChannels, 1);
    data->levels.push_back(std::move(level0));
    if (n > 1) {
        BoxPyramidAccumulator pyramid(n, n, kChannels, options.threads);
        pyramid.add_rows(0, n, [&](int y, int, double* planes) {
            for (int x = 0; x < n; ++x) channels_of(static_cast<std::size_t>(y) * n + x, planes + x, n);
        });
        for (int k = 1; k < pyramid.levels(); ++k) data->levels.push_back(pyramid.take_level(k));
    }
    // The surface's own moments over each texel's square, and their
    // summed-area table, each channel centred on its mean.
    data->table = PeriodicSummedArea(cell_moments(data->h, data->sx, data->sy, n, data->reference), n, kChannels);
    data->masking = DisplacementMasking::from_texels(data->h, data->sx, data->sy, n);
    const DisplacementTexture surface(data);  // its height() and slope(), for the masked table
    data->masked = MaskedSlopeTable::build(
        [&](double u, double v, double& h, double& sx, double& sy) {
        h = surface.height(u, v);
        surface.slope(u, v, sx, sy);
        },
        n, data->masking);
    return DisplacementTexture(std::move(data));
}

double DisplacementTexture::texel_height(int i, int j) const
{
    const int n = data_->n;
    return data_->h[static_cast<std::size_t>(wrap_index(j, n)) * n + wrap_index(i, n)];
}

std::pair<double, double> DisplacementTexture::texel_slope(int i, int j) const
{
    const int n = data_->n;
    const std::size_t k = static_cast<std::size_t>(wrap_index(j, n)) * n + wrap_index(i, n);
    return {data_->sx[k], data_->sy[k]};
}

double DisplacementTexture::height(double u, double v) const
{
    if (!std::isfinite(u) || !std::isfinite(v)) u = v = 0;
    return linear_at(data_->h, data_->n, cell_at(u, v, data_->n)).value;
}

void DisplacementTexture::slope(double u, double v, double& sx, double& sy) const
{
    if (!std::isfinite(u) || !std::isfinite(v)) u = v = 0;
    const Cell c = cell_at(u, v, data_->n);
    sx = linear_at(data_->sx, data_->n, c).value;
    sy = linear_at(data_->sy, data_->n, c).value;
}

int DisplacementTexture::level_size(int k) const { return box_level_extent(data_->n, k); }

std::array<double, kChannels> DisplacementTexture::pyramid_texel(int k, int x, int y) const
{
    const int m = level_size(k);
    const float* t = data_->levels[k].data() +
                     (static_cast<std::size_t>(wrap_index(y, m)) * m + wrap_index(x, m)) * kChannels;
    std::array<double, kChannels> out;
    for (int c = 0; c < kChannels; ++c) out[c] = t[c];
    // Back from heights about the mean: E[h] = E[dh] + r, E[h^2] = E[dh^2] + 2 r E[dh] + r^2.
    const double r = data_->reference;
    out[kHeightSquared] += 2 * r * out[kHeight] + r * r;
    out[kHeight] += r;
    return out;
}

DisplacementFootprint DisplacementTexture::footprint(double u, double v, double e1u, double e1v, double e2u,
                                                     double e2v) const
{
    const Data& d = *data_;
    const int n = d.n;
    if (!std::isfinite(u) || !std::isfinite(v)) u = v = 0;
    const bool infinite = !std::isfinite(e1u) || !std::isfinite(e1v) || !std::isfinite(e2u) || !std::isfinite(e2v);
    if (infinite) e1u = e1v = e2u = e2v = 0;
    const FootprintProbes probes = footprint_probes(e1u, e1v, e2u, e2v, d.max_probes, FootprintWidth::Rms);
    // Each piece: edges (a, b) = (major / count, minor).
    const double au = probes.step_u / probes.count, av = probes.step_v / probes.count;
    const double bu = probes.minor_u, bv = probes.minor_v;
    const double lod = infinite ? kInfiniteLod : std::max(kLowestLod, std::log2(probes.width * n));
    // Between the linearised fields (0) and the box means (1).
    const double box_weight = std::clamp(lod - kLinearLod, 0.0, 1.0);
    Moments total{};
    if (infinite)
        std::copy(d.table.means().begin(), d.table.means().end(), total.begin());  // the whole texture's means
    for (int j = 0; j < (infinite ? 0 : probes.count); ++j) {
        const double offset = (j + 0.5) / probes.count - 0.5;
        const double cu = u + offset * probes.step_u, cv = v + offset * probes.step_v;
        Moments m{};
        if (box_weight > 0) {
            // The exact box means over the piece's rectangle, with the
            // piece's second moments along u and v (its rms widths).
            const double wu = std::max(kThinnest, std::hypot(au, bu) * n);
            const double wv = std::max(kThinnest, std::hypot(av, bv) * n);
            const double x0 = (cu - std::floor(cu)) * n - 0.5 * wu, y0 = (cv - std::floor(cv)) * n - 0.5 * wv;
            d.table.box_mean(x0, y0, wu, wv, m.data());
        }
        if (box_weight < 1) {
            // The linearised fields: means at the centre, covariances (eq. of
            // a uniform parallelogram) ((F.a)(G.a) + (F.b)(G.b)) / 12.
            const Cell c = cell_at(cu, cv, n);
            Linear h = linear_at(d.h, n, c);
            h.value -= d.reference;
            const Linear sx = linear_at(d.sx, n, c), sy = linear_at(d.sy, n, c);
            const auto cov = [&](const Linear& f, const Linear& g) {
                return ((f.du * au + f.dv * av) * (g.du * au + g.dv * av) +
                        (f.du * bu + f.dv * bv) * (g.du * bu + g.dv * bv)) /
                       12;
            };
            const Moments linear = {h.value,
                                    sx.value,
                                    sy.value,
                                    sx.value * sx.value + cov(sx, sx),
                                    sy.value * sy.value + cov(sy, sy),
                                    sx.value * sy.value + cov(sx, sy),
                                    h.value * h.value + cov(h, h)};
            for (int ch = 0; ch < kChannels; ++ch) m[ch] = box_weight * m[ch] + (1 - box_weight) * linear[ch];
        }
        for (int ch = 0; ch < kChannels; ++ch) total[ch] += m[ch];
    }
    if (!infinite)
        for (double& t : total) t /= probes.count;
    DisplacementFootprint out;
    out.lod = lod;
    out.mean_height = total[kHeight] + d.reference;
    out.sigma_h = std::sqrt(std::max(0.0, total[kHeightSquared] - total[kHeight] * total[kHeight]));
    out.slope_x = total[kSlopeX];
    out.slope_y = total[kSlopeY];
    out.slope_xx = std::max(0.0, total[kSlopeXX] - out.slope_x * out.slope_x);
    out.slope_yy = std::max(0.0, total[kSlopeYY] - out.slope_y * out.slope_y);
    const double bound = std::sqrt(out.slope_xx * out.slope_yy);
    out.slope_xy = std::clamp(total[kSlopeXY] - out.slope_x * out.slope_y, -bound, bound);
    return out;
}

MaskedFootprint DisplacementTexture::masked_footprint(double u, double v, double e1u, double e1v, double e2u,
                                                      double e2v, double lambda) const
{
    const Data& d = *data_;
    const DisplacementFootprint plain = footprint(u, v, e1u, e1v, e2u, e2v);
    MaskedFootprint out{1, plain.slope_x, plain.slope_y, plain.slope_xx, plain.slope_xy, plain.slope_yy};
    if (!(lambda > 0)) return out;
    const int m = d.masked.cells();
    // Below a cell of the table: the footprint's own slopes, seen alike, and
    // G1 of its mean height.
    const double small_g1 = std::pow(d.masking.height_cdf(plain.mean_height), lambda);
    const double table_weight = std::clamp(plain.lod - std::log2(static_cast<double>(d.n) / m), 0.0, 1.0);
    if (table_weight <= 0 || m == 0) {
        out.g1 = small_g1;
        return out;
    }
    // The pieces' box means, as footprint() cuts them.
    MaskedMoments total{};
    if (plain.lod >= kInfiniteLod) {
        total = d.masked.repeat(lambda);
    } else {
        if (!std::isfinite(u) || !std::isfinite(v)) u = v = 0;
        const FootprintProbes probes = footprint_probes(e1u, e1v, e2u, e2v, d.max_probes, FootprintWidth::Rms);
        const double au = probes.step_u / probes.count, av = probes.step_v / probes.count;
        const double bu = probes.minor_u, bv = probes.minor_v;
        const double wu = std::max(kThinnest / d.n, std::hypot(au, bu));
        const double wv = std::max(kThinnest / d.n, std::hypot(av, bv));
        for (int j = 0; j < probes.count; ++j) {
            const double offset = (j + 0.5) / probes.count - 0.5;
            const double cu = u + offset * probes.step_u, cv = v + offset * probes.step_v;
            const MaskedMoments piece = d.masked.box(cu - 0.5 * wu, cv - 0.5 * wv, wu, wv, lambda);
            for (int k = 0; k < 6; ++k) total[k] += piece[k] / probes.count;
        }
    }
    // Blend the normalised moments; the weight itself linearly. A box's
    // weight is a difference of sums over the repeat: below a millionth of
    // the repeat's mean weight it is rounding (a footprint of a cell or two
    // on low ground at a grazing angle), and the point's own G1 and slopes
    // stand.
    const double w = total[0];
    if (!(w > 1e-6 * d.masked.repeat(lambda)[0])) {
        out.g1 = small_g1;
        return out;
    }
    out.g1 = table_weight * w + (1 - table_weight) * small_g1;
    const double mx = total[1] / w, my = total[2] / w;
    const double raw_xx = table_weight * total[3] / w +
                          (1 - table_weight) * (plain.slope_xx + plain.slope_x * plain.slope_x);
    const double raw_yy = table_weight * total[4] / w +
                          (1 - table_weight) * (plain.slope_yy + plain.slope_y * plain.slope_y);
    const double raw_xy = table_weight * total[5] / w +
                          (1 - table_weight) * (plain.slope_xy + plain.slope_x * plain.slope_y);
    out.slope_x = table_weight * mx + (1 - table_weight) * plain.slope_x;
    out.slope_y = table_weight * my + (1 - table_weight) * plain.slope_y;
    out.slope_xx = std::max(0.0, raw_xx - out.slope_x * out.slope_x);
    out.slope_yy = std::max(0.0, raw_yy - out.slope_y * out.slope_y);
    const double bound = std::sqrt(out.slope_xx * out.slope_yy);
    out.slope_xy = std::clamp(raw_xy - out.slope_x * out.slope_y, -bound, bound);
    return out;
}

Expected<Heightfield> DisplacementTexture::heightfield(int threads) const
{
    (void)threads;  // the nodes are the texels as they are: nothing to tabulate
    const int n = data_->n;
    if ((n & (n - 1)) != 0)
        return bad_input("displacement '" + data_->path + "' is " + std::to_string(n) + " x " + std::to_string(n) +
                         " texels; its heightfield needs a power of two");
    return Heightfield::from_nodes(data_->h, n, 1.0, data_->sx, data_->sy);
}

std::pair<double, double> DisplacementTexture::heightfield_xy(double u, double v) const
{
    const double half = 0.5 / data_->n;
    return {u - half, v - half};
}

std::pair<double, double> DisplacementTexture::texture_uv(double x, double y) const
{
    const double half = 0.5 / data_->n;
    return {x + half, y + half};
}

}  // namespace cmfilter
