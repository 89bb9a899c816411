// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/heightfield_tracer.h"

#include "cmfilter/math/fft.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <utility>

namespace cmfilter {

// A ray in texel units: u = x / s and v = y / s, reduced into one tile, and
// z; t as the caller's (the direction is divided by s along x and y only).
struct Heightfield::Ray {
    double u = 0, v = 0, z = 0;     // at t = 0
    double du = 0, dv = 0, dz = 0;  // per unit t
    double on_surface = 0;          // |z - h| within it at t = 0: on the surface
};

struct Heightfield::Crossing {
    double t = 0;                 // from the ray's start
    std::int64_t ix = 0, iy = 0;  // the texel crossed in
};

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A point within this share of (tile + |x| + |y| + |z| + slab) of the
// surface is on it: rounding of a hit point computed as origin + t direction
// is some 1e-16 of those.
constexpr double kOnSurface = 1e-11;

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// floor(i / 2^k) for any sign of i.
std::int64_t floor_shift(std::int64_t i, int k) { return i >= 0 ? i >> k : ~((~i) >> k); }

// A texel's bilinear patch over (fu, fv) in [0, 1]^2:
// h = h00 + a fu + b fv + c fu fv.
struct Patch {
    double h00, a, b, c, top;  // top: the largest corner
    double at(double fu, double fv) const { return h00 + a * fu + b * fv + c * fu * fv; }
    double du(double fv) const { return a + c * fv; }  // dh/dfu
    double dv(double fu) const { return b + c * fu; }  // dh/dfv
};

Patch load_patch(const std::vector<double>& nodes, int n, std::int64_t ix, std::int64_t iy)
{
    const std::int64_t m = n - 1;
    const double* r0 = nodes.data() + static_cast<std::size_t>((iy & m) * (n + 1) + (ix & m));
    const double* r1 = r0 + (n + 1);
    const double h00 = r0[0], h10 = r0[1], h01 = r1[0], h11 = r1[1];
    return {h00, h10 - h00, h01 - h00, h00 - h10 - h01 + h11, std::max(std::max(h00, h10), std::max(h01, h11))};
}

int sign_of(double x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

// The root in [a, b] of f(x) = c0 + c1 x + c2 x^2, monotone there with a sign
// change; `left`: [a, b] lies left of the vertex (the smaller root).
double root_between(double c0, double c1, double c2, double a, double b, bool left)
{
    double r;
    if (c2 == 0) {
        r = -c0 / c1;
    } else {
        // Without cancellation: q = -(c1 + sign(c1) sqrt(disc)) / 2, roots q / c2 and c0 / q.
        const double disc = std::max(c1 * c1 - 4 * c2 * c0, 0.0);
        const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
        double r1 = q / c2, r2 = q != 0 ? c0 / q : r1;
        if (r1 > r2) std::swap(r1, r2);
        r = left ? r1 : r2;
    }
    if (!(r >= a)) r = a;  // NaN too
    return std::min(r, b);
}

// The first x in [0, end] past which f(x) = c0 + c1 x + c2 x^2 is strictly
// on the other side of 0 from `side`: f is cut at its vertex into monotone
// pieces, each checked at its end.
std::optional<double> first_sign_change(double c0, double c1, double c2, double end, int side)
{
    const auto f = [&](double x) { return c0 + x * (c1 + x * c2); };
    if (side * c0 < 0) return 0.0;
    double a = 0;
    const double vertex = c2 != 0 ? -c1 / (2 * c2) : kInfinity;
    if (vertex > 0 && vertex < end) {
        if (side * f(vertex) < 0) return root_between(c0, c1, c2, 0, vertex, true);
        a = vertex;
    }
    if (side * f(end) < 0) return root_between(c0, c1, c2, a, end, 0.5 * (a + end) < vertex);
    return std::nullopt;
}

// What tabulate_nodes tabulates: the heights or their derivative along x or y.
enum class NodeValue { Height, SlopeX, SlopeY };

// The microsurface's exact heights (or slopes) at the n x n nodes of a tile,
// closed into (n + 1) x (n + 1): each cosine a cos(2 pi (i x + j y) / tile +
// phase) is the DFT coefficient a e^(i phase) at (i mod n, j mod n), and the
// node heights the real part of the inverse 2-D DFT (exact at the nodes
// whatever i and j); its derivative along x has the coefficient
// 2 pi i (i / tile) a e^(i phase) (y: j / tile).
Expected<std::vector<double>> tabulate_nodes(const GaussianMicrosurface& surface, int n, int threads,
                                             NodeValue value = NodeValue::Height)
{
    const double tile = surface.tile();
    std::vector<int> row_of(static_cast<std::size_t>(n), -1);
    std::vector<std::vector<std::complex<double>>> rows;  // the spectrum's nonzero rows
    std::vector<int> row_index;
    for (const GaussianMicrosurface::Cosine& c : surface.cosines()) {
        const double fi = c.fx * tile, fj = c.fy * tile;
        const double i = std::round(fi), j = std::round(fj);
        if (std::abs(fi - i) > 1e-6 * std::max(1.0, std::abs(fi)) ||
            std::abs(fj - j) > 1e-6 * std::max(1.0, std::abs(fj)))
            return bad_input("heightfield cosine frequency (" + std::to_string(c.fx) + ", " + std::to_string(c.fy) +
                             ") is off the tile's lattice (expected multiples of 1 / " + std::to_string(tile) + ")");
        const auto wrap = [n](double k) {
            const auto m = static_cast<std::int64_t>(k) % n;
            return static_cast<int>(m < 0 ? m + n : m);
        };
        const int ii = wrap(i), jj = wrap(j);
        if (row_of[jj] < 0) {
            row_of[jj] = static_cast<int>(rows.size());
            rows.emplace_back(static_cast<std::size_t>(n));
            row_index.push_back(jj);
        }
        const double two_pi = 6.28318530717958647692;
        const std::complex<double> weight = value == NodeValue::SlopeX   ? std::complex<double>(0, two_pi * c.fx)
                                            : value == NodeValue::SlopeY ? std::complex<double>(0, two_pi * c.fy)
                                                                         : std::complex<double>(1, 0);
        rows[row_of[jj]][ii] += weight * std::polar(c.amplitude, c.phase);
    }
    const Fft fft(static_cast<std::size_t>(n));
    for (auto& row : rows) fft.inverse(row.data());
    const std::size_t stride = static_cast<std::size_t>(n) + 1;
    std::vector<double> nodes(stride * stride);
    constexpr int kColumns = 16;
    const int blocks = (n + kColumns - 1) / kColumns;
    parallel_for(blocks, threads, [&](int block) {
        std::vector<std::complex<double>> column(static_cast<std::size_t>(n));
        for (int x = block * kColumns; x < std::min(n, (block + 1) * kColumns); ++x) {
            std::fill(column.begin(), column.end(), std::complex<double>());
            for (std::size_t r = 0; r < rows.size(); ++r) column[row_index[r]] = rows[r][x];
            fft.inverse(column.data());
            for (int y = 0; y < n; ++y) nodes[y * stride + x] = column[y].real();
        }
    });
    for (int y = 0; y < n; ++y) nodes[y * stride + n] = nodes[y * stride];
    for (std::size_t x = 0; x < stride; ++x) nodes[n * stride + x] = nodes[x];
    return nodes;
}

}  // namespace

Expected<Heightfield> Heightfield::create(const GaussianMicrosurface& surface, const HeightfieldOptions& options)
{
    if (!(surface.tile() > 0))
        return bad_input("heightfield microsurface tile " + std::to_string(surface.tile()) +
                         " is not periodic (expected a microsurface with tile > 0)");
    if (options.texels_per_min_wavelength < 1)
        return bad_input("heightfield texels_per_min_wavelength " + std::to_string(options.texels_per_min_wavelength) +
                         " is out of range (expected >= 1)");
    constexpr int kLargestResolution = 16384;
    if (options.max_resolution < 1 || options.max_resolution > kLargestResolution)
        return bad_input("heightfield max_resolution " + std::to_string(options.max_resolution) +
                         " is out of range (expected 1 to " + std::to_string(kLargestResolution) + ")");
    double top_frequency = 0;
    for (const GaussianMicrosurface::Cosine& c : surface.cosines())
        top_frequency = std::max(top_frequency, std::hypot(c.fx, c.fy));
    // Texel tile / N <= min_wavelength / texels_per_min_wavelength.
    const double needed = surface.tile() * options.texels_per_min_wavelength * top_frequency;
    std::int64_t n = 1;
    while (static_cast<double>(n) < needed * (1 - 1e-12) && n <= kLargestResolution) n *= 2;
    if (n > options.max_resolution)
        return bad_input("heightfield resolution " + std::to_string(n) + " (texels_per_min_wavelength " +
                         std::to_string(options.texels_per_min_wavelength) + " over min wavelength " +
                         std::to_string(1 / top_frequency) + " in tile " + std::to_string(surface.tile()) +
                         ") is over max_resolution " + std::to_string(options.max_resolution) +
                         " (expected fewer texels per wavelength or a larger max_resolution)");
    Heightfield h;
    h.n_ = static_cast<int>(n);
    h.tile_ = surface.tile();
    auto nodes = tabulate_nodes(surface, h.n_, options.threads);
    if (!nodes) return nodes.error();
    h.nodes_ = std::move(nodes.value());
    if (options.slopes) {
        auto sx = tabulate_nodes(surface, h.n_, options.threads, NodeValue::SlopeX);
        if (!sx) return sx.error();
        auto sy = tabulate_nodes(surface, h.n_, options.threads, NodeValue::SlopeY);
        if (!sy) return sy.error();
        h.slope_x_ = std::move(sx.value());
        h.slope_y_ = std::move(sy.value());
    }
    h.finish();
    return h;
}

Expected<Heightfield> Heightfield::from_nodes(std::vector<double> heights, int n, double tile,
                                              std::vector<double> slope_x, std::vector<double> slope_y)
{
    constexpr int kLargestResolution = 16384;
    if (n < 1 || n > kLargestResolution || (n & (n - 1)) != 0)
        return bad_input("heightfield node grid " + std::to_string(n) + " x " + std::to_string(n) +
                         " is not a power of two from 1 to " + std::to_string(kLargestResolution));
    if (!(tile > 0) || !std::isfinite(tile))
        return bad_input("heightfield tile " + std::to_string(tile) + " is out of range (expected finite and > 0)");
    const std::size_t count = static_cast<std::size_t>(n) * n;
    if (heights.size() != count)
        return bad_input("heightfield has " + std::to_string(heights.size()) + " node heights for a " +
                         std::to_string(n) + " x " + std::to_string(n) + " grid (expected " + std::to_string(count) +
                         ")");
    if (slope_x.size() != slope_y.size() || (!slope_x.empty() && slope_x.size() != count))
        return bad_input("heightfield node slopes: " + std::to_string(slope_x.size()) + " along x and " +
                         std::to_string(slope_y.size()) + " along y (expected none, or " + std::to_string(count) +
                         " of each)");
    // The grid closed into (n + 1) x (n + 1), the last row and column repeating the first.
    const auto close = [n](const std::vector<double>& grid, const char* what) -> Expected<std::vector<double>> {
        const std::size_t stride = static_cast<std::size_t>(n) + 1;
        std::vector<double> closed(stride * stride);
        for (std::size_t j = 0; j < stride; ++j)
            for (std::size_t i = 0; i < stride; ++i) {
                const double value = grid[(j % n) * n + i % n];
                if (!std::isfinite(value))
                    return bad_input(std::string("heightfield node ") + what + " at (" + std::to_string(i % n) + ", " +
                                     std::to_string(j % n) + ") is not finite (expected finite values)");
                closed[j * stride + i] = value;
            }
        return closed;
    };
    Heightfield h;
    h.n_ = n;
    h.tile_ = tile;
    auto nodes = close(heights, "height");
    if (!nodes) return nodes.error();
    h.nodes_ = std::move(nodes.value());
    if (!slope_x.empty()) {
        auto sx = close(slope_x, "slope x");
        if (!sx) return sx.error();
        auto sy = close(slope_y, "slope y");
        if (!sy) return sy.error();
        h.slope_x_ = std::move(sx.value());
        h.slope_y_ = std::move(sy.value());
    }
    h.finish();
    return h;
}

void Heightfield::finish()
{
    const auto [lo, hi] = std::minmax_element(nodes_.begin(), nodes_.end());
    min_height_ = *lo;
    max_height_ = *hi;
    mipmap_ = MaxMipmap(nodes_.data(), n_);
    top_level_ = std::max(0, mipmap_.top_level() - 1);  // the top level, the whole tile, never skips
}

double Heightfield::node_height(std::int64_t i, std::int64_t j) const
{
    const std::int64_t m = n_ - 1;
    return nodes_[static_cast<std::size_t>((j & m) * (n_ + 1) + (i & m))];
}

double Heightfield::height(double x, double y) const
{
    const Ray r = local_ray({x, y, 0}, {0, 0, 1});
    const double fx = std::floor(r.u), fy = std::floor(r.v);
    return load_patch(nodes_, n_, static_cast<std::int64_t>(fx), static_cast<std::int64_t>(fy)).at(r.u - fx, r.v - fy);
}

bool Heightfield::slope(double x, double y, double& sx, double& sy) const
{
    if (slope_x_.empty()) return false;
    const Ray r = local_ray({x, y, 0}, {0, 0, 1});
    const double fx = std::floor(r.u), fy = std::floor(r.v);
    const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
    sx = load_patch(slope_x_, n_, ix, iy).at(r.u - fx, r.v - fy);
    sy = load_patch(slope_y_, n_, ix, iy).at(r.u - fx, r.v - fy);
    return true;
}

double Heightfield::on_surface_tolerance(const Vec3& p) const
{
    return kOnSurface * (tile_ + std::abs(p.x) + std::abs(p.y) + std::abs(p.z) + (max_height_ - min_height_));
}

Heightfield::Ray Heightfield::local_ray(const Vec3& start, const Vec3& direction) const
{
    const auto reduce = [this](double x) {
        const double periods = x / tile_;
        return (periods - std::floor(periods)) * n_;
    };
    Ray r;
    r.u = reduce(start.x);
    r.v = reduce(start.y);
    r.z = start.z;
    r.du = direction.x * n_ / tile_;
    r.dv = direction.y * n_ / tile_;
    r.dz = direction.z;
    r.on_surface = on_surface_tolerance(start);
    return r;
}

std::optional<Heightfield::Crossing> Heightfield::walk(const Ray& r, double t_end, int side, bool at_origin) const
{
    // The texel the ray starts in: on a texel edge, the one it goes into.
    const auto start_texel = [](double u, double du) {
        const double f = std::floor(u);
        return static_cast<std::int64_t>(f) - (u == f && du < 0 ? 1 : 0);
    };
    std::int64_t ix = start_texel(r.u, r.du), iy = start_texel(r.v, r.dv);
    // At an origin on the surface the side is the local patch's: where its
    // height minus the surface's, f(t) = c1 t + c2 t^2 near 0, goes first.
    bool origin_on_surface = false;
    if (at_origin) {
        const Patch p = load_patch(nodes_, n_, ix, iy);
        const double fu = r.u - ix, fv = r.v - iy;
        const double f0 = r.z - p.at(fu, fv);
        int local = sign_of(f0);
        if (std::abs(f0) <= r.on_surface) {
            origin_on_surface = true;
            const double c1 = r.dz - (p.du(fv) * r.du + p.dv(fu) * r.dv), c2 = -p.c * r.du * r.dv;
            local = c1 != 0 ? sign_of(c1) : (c2 != 0 ? sign_of(c2) : 1);
        }
        if (side == 0) side = local;
        else if (local != side) return Crossing{0, ix, iy};
    }
    const double inv_du = r.du != 0 ? 1 / r.du : 0, inv_dv = r.dv != 0 ? 1 / r.dv : 0;
    int k = top_level_;
    double t = 0;
    for (;;) {
        const std::int64_t size = std::int64_t(1) << k;
        const std::int64_t cx = floor_shift(ix, k), cy = floor_shift(iy, k);
        // Where the ray leaves the level-k cell (cx, cy) through an x face, a y face.
        const std::int64_t fx = r.du > 0 ? (cx + 1) * size : cx * size, fy = r.dv > 0 ? (cy + 1) * size : cy * size;
        const double tx = r.du != 0 ? (static_cast<double>(fx) - r.u) * inv_du : kInfinity;
        const double ty = r.dv != 0 ? (static_cast<double>(fy) - r.v) * inv_dv : kInfinity;
        const double te = std::max(t, std::min(std::min(tx, ty), t_end));
        // A ray above the surface skips a block with no node above its
        // lowest point: none of the block is strictly above the ray.
        const double lowest = side > 0 ? r.z + r.dz * (r.dz < 0 ? te : t) : -kInfinity;
        if (k > 0) {
            if (lowest < mipmap_.block_max(k, cx, cy)) {
                --k;  // the same texel in a smaller block
                continue;
            }
        } else {
            const Patch p = load_patch(nodes_, n_, ix, iy);
            if (lowest < p.top) {
                // f(tau) = z - h along the ray from t: c0 + c1 tau + c2 tau^2.
                const double fu = r.u + r.du * t - ix, fv = r.v + r.dv * t - iy;
                const double c0 = origin_on_surface ? 0 : r.z + r.dz * t - p.at(fu, fv);
                const double c1 = r.dz - (p.du(fv) * r.du + p.dv(fu) * r.dv), c2 = -p.c * r.du * r.dv;
                if (const auto tau = first_sign_change(c0, c1, c2, te - t, side)) return Crossing{t + *tau, ix, iy};
            }
        }
        if (te >= t_end) return std::nullopt;
        // Into the next cell: the face crossed exactly, the other coordinate
        // from the point, kept inside the cell it left.
        std::int64_t face;
        if (tx <= ty) {
            face = fx;
            ix = r.du > 0 ? fx : fx - 1;
            if (ty == tx) iy = r.dv > 0 ? fy : fy - 1;
            else
                iy =
                    std::clamp(static_cast<std::int64_t>(std::floor(r.v + r.dv * te)), cy * size, cy * size + size - 1);
        } else {
            face = fy;
            iy = r.dv > 0 ? fy : fy - 1;
            ix = std::clamp(static_cast<std::int64_t>(std::floor(r.u + r.du * te)), cx * size, cx * size + size - 1);
        }
        t = te;
        origin_on_surface = false;
        // Up while the face crossed is a face of the coarser level too.
        while (k < top_level_ && (face & ((std::int64_t(2) << k) - 1)) == 0) ++k;
    }
}

std::optional<HeightfieldHit> Heightfield::trace(const Vec3& origin, const Vec3& direction, double t_max) const
{
    if (!finite(origin) || !finite(direction) || direction == Vec3{} || !(t_max > 0)) return std::nullopt;
    // The slab, widened by the on-surface tolerance: a ray leaving it
    // downwards from above is strictly below every node, so the crossing
    // lies inside it, even where the slab is flat (sigma_h = 0).
    const double tol = on_surface_tolerance(origin);
    const double lo = min_height_ - tol, hi = max_height_ + tol, dz = direction.z;
    // [t0, t1]: inside the slab; side: where the ray enters it from.
    double t0 = 0, t1 = kInfinity;
    int side = 0;
    const bool at_origin = origin.z >= lo && origin.z <= hi;
    if (at_origin) {
        if (dz != 0) t1 = std::max(0.0, ((dz < 0 ? lo : hi) - origin.z) / dz);
    } else if (origin.z > hi && dz < 0) {
        t0 = (hi - origin.z) / dz;
        t1 = (lo - origin.z) / dz;
        side = 1;
    } else if (origin.z < lo && dz > 0) {
        t0 = (lo - origin.z) / dz;
        t1 = (hi - origin.z) / dz;
        side = -1;
    } else {
        return std::nullopt;  // outside the slab, going away from it
    }
    const double horizontal = std::hypot(direction.x, direction.y);
    if (horizontal > 0) t1 = std::min(t1, t0 + kMaxTilesTravelled * tile_ / horizontal);
    t1 = std::min(t1, t_max);
    if (!(t1 >= t0)) return std::nullopt;
    const Ray r = local_ray(at_origin ? origin : origin + t0 * direction, direction);
    const auto crossing = walk(r, t1 - t0, side, at_origin);
    if (!crossing) return std::nullopt;
    HeightfieldHit hit;
    hit.t = t0 + crossing->t;
    if (!(hit.t > 0) || hit.t > t_max) return std::nullopt;
    hit.point = origin + hit.t * direction;
    hit.height = hit.point.z;
    const Patch p = load_patch(nodes_, n_, crossing->ix, crossing->iy);
    const double fu = std::clamp(r.u + r.du * crossing->t - crossing->ix, 0.0, 1.0);
    const double fv = std::clamp(r.v + r.dv * crossing->t - crossing->iy, 0.0, 1.0);
    const double per_unit = n_ / tile_;  // texels per unit length
    hit.normal = normalize(Vec3{-p.du(fv) * per_unit, -p.dv(fu) * per_unit, 1});
    return hit;
}

bool Heightfield::occluded(const Vec3& point, const Vec3& to_light) const
{
    if (!finite(point) || !finite(to_light) || to_light == Vec3{}) return true;
    if (to_light.z < 0) return true;  // it ends below every node
    const double tol = on_surface_tolerance(point);
    if (point.z > max_height_ + tol) return false;
    if (point.z < min_height_ - tol) return true;
    double t_end = to_light.z > 0 ? std::max(0.0, (max_height_ - point.z) / to_light.z) : kInfinity;
    const double horizontal = std::hypot(to_light.x, to_light.y);
    if (horizontal > 0) t_end = std::min(t_end, kMaxTilesTravelled * tile_ / horizontal);
    return walk(local_ray(point, to_light), t_end, 1, true).has_value();
}

}  // namespace cmfilter
