// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/scene/pixel_coverage.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cmfilter {

namespace {

// Bisection steps for a change of nearest surface within a piece of a strip:
// 2^-30 of the piece, far below any share that shows.
constexpr int kBisections = 30;
// A direction across an edge that the box's corners cannot tell.
constexpr double kUnknown = std::numeric_limits<double>::infinity();
// Parts smaller than this share of the pixel are rounding, not coverage.
constexpr double kMinShare = 1e-9;

// Whether two surfaces meet, so that their depth order can change across the
// image: two planes unless parallel, a sphere and a plane the sphere's
// centre is nearer than its radius, two spheres whose boundaries cross.
bool surfaces_meet(const Surface& a, const Surface& b)
{
    if (a.kind == SurfaceKind::Plane && b.kind == SurfaceKind::Plane) return length(cross(a.normal, b.normal)) > 0;
    if (a.kind == SurfaceKind::Sphere && b.kind == SurfaceKind::Sphere) {
        const double d = length(a.center - b.center);
        return d < a.radius + b.radius && d > std::fabs(a.radius - b.radius);
    }
    const Surface& sphere = a.kind == SurfaceKind::Sphere ? a : b;
    const Surface& plane = a.kind == SurfaceKind::Sphere ? b : a;
    return std::fabs(dot(sphere.center - plane.point, plane.normal)) < sphere.radius;
}

double bounded(double v) { return std::fmax(-kDerivativeLimit, std::fmin(v, kDerivativeLimit)); }

}  // namespace

// The integrals of 1, x, y, x^2, y^2 and xy over what one surface (or the
// background) covers, in the pixel's own coordinates ([0, 1]^2), and the
// longest piece of a strip it has.
struct PixelCoverage::Moments {
    double area = 0, x = 0, y = 0, xx = 0, yy = 0, xy = 0;
    double longest = 0, longest_x = 0, longest_y = 0;

    // The rectangle [mid - w/2, mid + w/2] x [a, b] (a strip along y), or
    // [a, b] x [mid - w/2, mid + w/2] (a strip along x: `rows`).
    void add(double mid, double w, double a, double b, bool rows)
    {
        const double l = b - a;
        if (!(l > 0)) return;
        const double across1 = w * l * mid, along1 = w * (b * b - a * a) / 2;
        const double across2 = l * (w * mid * mid + w * w * w / 12), along2 = w * (b * b * b - a * a * a) / 3;
        area += w * l;
        x += rows ? along1 : across1;
        y += rows ? across1 : along1;
        xx += rows ? along2 : across2;
        yy += rows ? across2 : along2;
        xy += mid * along1;
        if (l > longest) {
            longest = l;
            longest_x = rows ? 0.5 * (a + b) : mid;
            longest_y = rows ? mid : 0.5 * (a + b);
        }
    }
};

PixelCoverage::PixelCoverage(const Scene& scene, const Camera& camera)
    : scene_(&scene), camera_(&camera), image_(camera.image_plane())
{
    for (const Surface& s : scene.surfaces) outlines_.emplace_back(s, image_);
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i)
        for (std::size_t j = i + 1; j < scene.surfaces.size(); ++j)
            if (surfaces_meet(scene.surfaces[i], scene.surfaces[j]))
                meeting_.emplace_back(static_cast<int>(i), static_cast<int>(j));
    // Tiles of kTile x kTile pixels that may hold an edge: an outline may
    // cross the tile, or two surfaces that meet may both be seen in it.
    tiles_x_ = (camera.width() + kTile - 1) / kTile;
    const int tiles_y = (camera.height() + kTile - 1) / kTile;
    tiles_.assign(static_cast<std::size_t>(tiles_x_) * static_cast<std::size_t>(tiles_y), 0);
    for (int ty = 0; ty < tiles_y; ++ty)
        for (int tx = 0; tx < tiles_x_; ++tx) {
            const double x0 = tx * kTile, y0 = ty * kTile;
            bool edge = false;
            for (const SurfaceOutline& o : outlines_) edge = edge || o.may_cross(x0, y0, kTile);
            for (const auto& [i, j] : meeting_)
                edge = edge || (outlines_[static_cast<std::size_t>(i)].may_see(x0, y0, kTile) &&
                                outlines_[static_cast<std::size_t>(j)].may_see(x0, y0, kTile));
            tiles_[static_cast<std::size_t>(ty * tiles_x_ + tx)] = edge;
        }
}

Vec3 PixelCoverage::direction(double px, double py) const
{
    return normalize(image_.corner + px * image_.step_x + py * image_.step_y);
}

int PixelCoverage::nearest(double px, double py) const
{
    const Vec3 d = direction(px, py);
    int best = -1;
    double best_t = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < scene_->surfaces.size(); ++i) {
        const std::optional<double> t = hit_distance(scene_->surfaces[i], image_.origin, d);
        if (t && *t < best_t) {
            best_t = *t;
            best = static_cast<int>(i);
        }
    }
    return best;
}

// Two surfaces that meet, both maybe seen in the box, where they may meet
// within it: their depth order differs between its corners and centre, or
// the outline of one crosses it (the meeting may run into a silhouette
// there). `across` gets the unit direction in which the depth difference
// changes, from the corners where all of them and the centre see both,
// (kUnknown, kUnknown) where the order differs but some miss one.
bool PixelCoverage::holds_meeting(const Box& box, std::vector<std::pair<double, double>>* across) const
{
    static constexpr double kPoints[5][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.5, 0.5}};
    bool found = false;
    for (const auto& [i, j] : meeting_) {
        const SurfaceOutline& outline_a = outlines_[static_cast<std::size_t>(i)];
        const SurfaceOutline& outline_b = outlines_[static_cast<std::size_t>(j)];
        if (!outline_a.may_see(box.x0, box.y0, box.size) || !outline_b.may_see(box.x0, box.y0, box.size)) continue;
        const bool outline = outline_a.may_cross(box.x0, box.y0, box.size) ||
                             outline_b.may_cross(box.x0, box.y0, box.size);
        if (outline && !across) return true;
        const Surface& a = scene_->surfaces[static_cast<std::size_t>(i)];
        const Surface& b = scene_->surfaces[static_cast<std::size_t>(j)];
        int in_front = 0, behind = 0;
        double depth[5] = {};
        for (int k = 0; k < 5; ++k) {
            const Vec3 d = direction(box.x0 + kPoints[k][0] * box.size, box.y0 + kPoints[k][1] * box.size);
            const auto ta = hit_distance(a, image_.origin, d);
            const auto tb = hit_distance(b, image_.origin, d);
            if (!ta || !tb) continue;
            depth[k] = *ta - *tb;
            (depth[k] < 0 ? in_front : behind) += 1;
        }
        const bool crossing = in_front > 0 && behind > 0;
        if (!crossing && !outline) continue;
        found = true;
        if (!across) return true;
        if (!crossing) continue;  // the outlines give the directions
        const double gx = 0.5 * (depth[1] + depth[3] - depth[0] - depth[2]);
        const double gy = 0.5 * (depth[2] + depth[3] - depth[0] - depth[1]);
        const double norm = std::hypot(gx, gy);
        if (in_front + behind == 5 && norm > 0 && std::isfinite(norm)) across->emplace_back(gx / norm, gy / norm);
        else across->emplace_back(kUnknown, kUnknown);
    }
    return found;
}

bool PixelCoverage::on_edge_in_tile(int x, int y) const
{
    for (const SurfaceOutline& o : outlines_)
        if (o.may_cross(x, y)) return true;
    return !meeting_.empty() && holds_meeting({static_cast<double>(x), static_cast<double>(y), 1.0}, nullptr);
}

// One box of pixel (x, y) (the pixel itself, or a quarter, ... of it) into
// `parts`, in the pixel's own coordinates.
void PixelCoverage::cover_box(int x, int y, const Box& box, bool sampled, int depth, std::vector<Moments>& parts) const
{
    const auto part = [&](int surface) -> Moments& { return parts[static_cast<std::size_t>(surface + 1)]; };
    // The directions across the edges in the box; the strips run along x
    // (rows) or y, whichever makes the steepest edge's slope against them
    // the smaller; a box with edges steep both ways (a silhouette's side
    // meeting a horizon), or with a meeting of surfaces whose direction its
    // corners cannot tell, is cut in four, up to kMaxDepth times.
    std::vector<std::pair<double, double>> across;
    for (const SurfaceOutline& o : outlines_)
        if (o.may_cross(box.x0, box.y0, box.size))
            across.push_back(o.across(box.x0 + 0.5 * box.size, box.y0 + 0.5 * box.size));
    if (sampled) holds_meeting(box, &across);
    if (across.empty() && !sampled) {  // no edge within: one surface
        part(nearest(box.x0 + 0.5 * box.size, box.y0 + 0.5 * box.size))
            .add(box.x0 - x + 0.5 * box.size, box.size, box.y0 - y, box.y0 - y + box.size, false);
        return;
    }
    double steep_columns = 0, steep_rows = 0;
    for (const auto& [gx, gy] : across) {
        if (gx == kUnknown) {  // a meeting whose direction the corners cannot tell: smaller boxes may
            steep_columns = steep_rows = kUnknown;
            break;
        }
        steep_columns = std::max(steep_columns, std::fabs(gx) / std::max(std::fabs(gy), 1e-300));
        steep_rows = std::max(steep_rows, std::fabs(gy) / std::max(std::fabs(gx), 1e-300));
    }
    if (std::min(steep_columns, steep_rows) > kMaxSlope && depth < kMaxDepth) {
        const double half = 0.5 * box.size;
        for (int k = 0; k < 4; ++k)
            cover_box(x, y, {box.x0 + (k % 2) * half, box.y0 + (k / 2) * half, half}, sampled, depth + 1, parts);
        return;
    }
    const bool rows = steep_rows < steep_columns;
    // Strip c's middle line runs along `along` from `start` (D at s = 0);
    // s in [0, 1] spans the box.
    const Vec3 corner = image_.corner + box.x0 * image_.step_x + box.y0 * image_.step_y;
    const Vec3 along = box.size * (rows ? image_.step_x : image_.step_y);
    const Vec3 step = box.size * (rows ? image_.step_y : image_.step_x);
    const double across_origin = rows ? box.y0 - y : box.x0 - x;  // the pixel's own coordinates
    const double along_origin = rows ? box.x0 - x : box.y0 - y;
    const auto nearest_at = [&](double mid, double s) {
        const double a = along_origin + s * box.size, c = across_origin + mid * box.size;
        return rows ? nearest(x + a, y + c) : nearest(x + c, y + a);
    };
    const auto add = [&](int surface, double mid, double a, double b) {
        part(surface).add(across_origin + mid * box.size, box.size / kColumns, along_origin + a * box.size,
                          along_origin + b * box.size, rows);
    };
    std::vector<double> cuts;
    for (int c = 0; c < kColumns; ++c) {
        const double mid = (c + 0.5) / kColumns;
        const Vec3 start = corner + mid * step;
        cuts.assign({0.0, 1.0});
        for (const SurfaceOutline& o : outlines_) o.crossings(start, along, cuts);
        std::sort(cuts.begin(), cuts.end());
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
            const double a = cuts[k], b = cuts[k + 1];
            if (!(b > a)) continue;
            if (!sampled) {
                add(nearest_at(mid, 0.5 * (a + b)), mid, a, b);
                continue;
            }
            // Where two surfaces meet, the nearest one may change inside the
            // piece: sample it from end to end (just inside), and bisect
            // every change.
            const auto sample_at = [&](int k2) {
                const double f = k2 == 0               ? 1e-9
                                 : k2 == kDepthSamples ? 1 - 1e-9
                                                       : static_cast<double>(k2) / kDepthSamples;
                return a + f * (b - a);
            };
            double from = a, previous = sample_at(0);
            int current = nearest_at(mid, previous);
            for (int k2 = 1; k2 <= kDepthSamples; ++k2) {
                const double s = sample_at(k2);
                const int id = nearest_at(mid, s);
                if (id != current) {
                    double lo = previous, hi = s;
                    for (int step_count = 0; step_count < kBisections; ++step_count) {
                        const double half = 0.5 * (lo + hi);
                        (nearest_at(mid, half) == current ? lo : hi) = half;
                    }
                    const double change = 0.5 * (lo + hi);
                    add(current, mid, from, change);
                    from = change;
                    current = id;
                }
                previous = s;
            }
            add(current, mid, from, b);
        }
    }
}

void PixelCoverage::cover(int x, int y, PixelCover& out) const
{
    const std::size_t n = scene_->surfaces.size();
    std::vector<Moments> parts(n + 1);  // [0]: the background, [i + 1]: surface i
    const Box pixel{static_cast<double>(x), static_cast<double>(y), 1.0};
    cover_box(x, y, pixel, !meeting_.empty() && holds_meeting(pixel, nullptr), 0, parts);

    out.pieces.clear();
    double total = parts[0].area;
    for (std::size_t i = 0; i < n; ++i) {
        const Moments& m = parts[i + 1];
        if (!(m.area > kMinShare)) continue;
        total += m.area;
        CoveragePiece piece;
        piece.surface = static_cast<int>(i);
        piece.share = m.area;
        const double cx = m.x / m.area, cy = m.y / m.area;
        if (nearest(x + cx, y + cy) == piece.surface) {
            piece.px = x + cx;
            piece.py = y + cy;
        } else {
            piece.px = x + m.longest_x;
            piece.py = y + m.longest_y;
        }
        // M = sqrt(12 Sigma), the symmetric square root of [[p, q], [q, r]]:
        // (Sigma' + s I) / t with s = sqrt(det), t = sqrt(trace + 2 s).
        const double p = 12 * std::max(0.0, m.xx / m.area - cx * cx);
        const double r = 12 * std::max(0.0, m.yy / m.area - cy * cy);
        const double q = 12 * (m.xy / m.area - cx * cy);
        const double sq = std::sqrt(std::max(0.0, p * r - q * q));
        const double t = std::sqrt(p + r + 2 * sq);
        if (t > 0) {
            piece.m00 = (p + sq) / t;
            piece.m11 = (r + sq) / t;
            piece.m01 = piece.m10 = q / t;
        } else {
            piece.m00 = piece.m01 = piece.m10 = piece.m11 = 0;
        }
        out.pieces.push_back(piece);
    }
    // The strips tile the box: total is 1 up to rounding and the parts dropped.
    for (CoveragePiece& piece : out.pieces) piece.share /= total;
    out.background = parts[0].area / total;
}

std::optional<SurfaceHit> PixelCoverage::hit(const CoveragePiece& piece) const
{
    if (piece.surface < 0 || static_cast<std::size_t>(piece.surface) >= scene_->surfaces.size()) return std::nullopt;
    std::optional<SurfaceHit> h =
        intersect(scene_->surfaces[static_cast<std::size_t>(piece.surface)], camera_->ray(piece.px, piece.py));
    if (!h) return std::nullopt;
    // The chain rule: d/ds = m00 d/dx + m10 d/dy, d/dt = m01 d/dx + m11 d/dy.
    const auto along = [](double m_x, double m_y, double d_dx, double d_dy) {
        return bounded(m_x * d_dx + m_y * d_dy);
    };
    const Vec3 dp_dx = h->dp_dx, dp_dy = h->dp_dy;
    h->dp_dx = {along(piece.m00, piece.m10, dp_dx.x, dp_dy.x), along(piece.m00, piece.m10, dp_dx.y, dp_dy.y),
                along(piece.m00, piece.m10, dp_dx.z, dp_dy.z)};
    h->dp_dy = {along(piece.m01, piece.m11, dp_dx.x, dp_dy.x), along(piece.m01, piece.m11, dp_dx.y, dp_dy.y),
                along(piece.m01, piece.m11, dp_dx.z, dp_dy.z)};
    const double du_dx = h->du_dx, du_dy = h->du_dy, dv_dx = h->dv_dx, dv_dy = h->dv_dy;
    h->du_dx = along(piece.m00, piece.m10, du_dx, du_dy);
    h->dv_dx = along(piece.m00, piece.m10, dv_dx, dv_dy);
    h->du_dy = along(piece.m01, piece.m11, du_dx, du_dy);
    h->dv_dy = along(piece.m01, piece.m11, dv_dx, dv_dy);
    return h;
}

}  // namespace cmfilter
