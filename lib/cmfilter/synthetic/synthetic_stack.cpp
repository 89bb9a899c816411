// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthetic/synthetic_stack.h"

#include "cmfilter/util/parallel_for.h"
#include "cmfilter/util/stopwatch.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cmfilter {

namespace {

// The most floats the images of one stack may hold (4 GiB).
constexpr std::size_t kMaxStackFloats = std::size_t{1} << 30;

// SplitMix64 (Steele, Lea and Flood 2014).
struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next()
    {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
};

std::string vector_text(const Vec3& v)
{
    std::ostringstream s;
    s.precision(9);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The largest divisor of n not above sqrt(n).
int strata_columns(int n)
{
    int best = 1;
    for (int d = 1; static_cast<long long>(d) * d <= n; ++d)
        if (n % d == 0) best = d;
    return best;
}

}  // namespace

Status check_synthetic_size(int size, int samples, const std::string& owner)
{
    if (size < 1 || size > kMaxSyntheticSize)
        return bad_input(owner + "::size " + std::to_string(size) + " is invalid: expected 1 to " +
                             std::to_string(kMaxSyntheticSize) + " pixels per side",
                         owner + "::size");
    if (samples < 1 || samples > kMaxSyntheticSamples)
        return bad_input(owner + "::samples " + std::to_string(samples) + " is invalid: expected 1 to " +
                             std::to_string(kMaxSyntheticSamples) + " rays per pixel",
                         owner + "::samples");
    return ok();
}

Expected<SyntheticStack> render_synthetic_stack(const SyntheticSurface& surface, const std::vector<Vec3>& lights,
                                                const SyntheticStackOptions& options)
{
    const Vec3& w = options.view;
    if (!finite(w) || !(length(w) > 0))
        return bad_input("SyntheticStackOptions::view " + vector_text(w) +
                             " is invalid: expected a finite, nonzero direction towards the camera",
                         "SyntheticStackOptions::view");
    const Vec3 view = normalize(w);
    if (!(view.z > 0))
        return bad_input("SyntheticStackOptions::view " + vector_text(w) +
                             " is invalid: it is not above the horizon (expected z > 0: the camera sees the "
                             "surface from above)",
                         "SyntheticStackOptions::view");
    if (auto st = check_synthetic_size(options.size, options.samples, "SyntheticStackOptions"); !st) return st.error();
    if (auto st = check_specular_lobe(options.specular); !st) return st.error();
    if (lights.empty()) return bad_input("render_synthetic_stack: no lights");
    SyntheticStack out;
    out.size = options.size;
    out.view = view;
    for (std::size_t k = 0; k < lights.size(); ++k) {
        const Vec3& l = lights[k];
        if (!finite(l) || !(length(l) > 0))
            return bad_input("light " + std::to_string(k) + " " + vector_text(l) +
                             " is invalid: expected a finite, nonzero direction towards the light");
        const Vec3 u = normalize(l);
        if (u.z < 0)
            return bad_input("light " + std::to_string(k) + " " + vector_text(l) +
                             " is below the horizon (expected z >= 0)");
        out.lights.push_back(u);
    }
    const std::size_t texels = out.texels(), count = out.lights.size();
    if (count * texels * 3 > kMaxStackFloats)
        return bad_input("SyntheticStackOptions::size " + std::to_string(options.size) + " with " +
                             std::to_string(count) + " lights is too large: the images would hold more than " +
                             std::to_string(kMaxStackFloats) + " floats",
                         "SyntheticStackOptions::size");

    const Stopwatch clock;
    out.pixels.assign(count * texels * 3, 0.0f);
    out.normals.assign(texels * 3, 0.0f);
    if (options.albedo) out.albedo.assign(texels * 3, 0.0f);
    const int size = options.size, spp = options.samples;
    const int gx = strata_columns(spp), gy = spp / gx;
    const double step = surface.tile() / size;
    const Vec3 v_field = to_heightfield_frame(view);
    std::vector<Vec3> l_field;
    for (const Vec3& l : out.lights) l_field.push_back(to_heightfield_frame(l));
    const std::uint64_t seed_state = SplitMix64{options.seed}.next();
    std::vector<std::size_t> row_hits(size, 0);

    const auto render_row = [&](int j) {
        std::vector<SyntheticHit> hits;
        std::vector<double> sums(count * 3);
        hits.reserve(spp);
        for (int i = 0; i < size; ++i) {
            const std::size_t t = static_cast<std::size_t>(j) * size + i;
            SplitMix64 rng{seed_state ^ ((t + 1) * 0xD1B54A32D192ED03ULL)};
            hits.clear();
            for (int k = 0; k < spp; ++k) {
                const double ox = (k % gx + rng.uniform()) / gx, oy = (k / gx + rng.uniform()) / gy;
                if (auto hit = surface.trace((i + ox) * step, (j + oy) * step, v_field)) hits.push_back(*hit);
            }
            std::fill(sums.begin(), sums.end(), 0.0);
            Vec3 normal;
            Rgb color;
            for (const SyntheticHit& h : hits) {
                normal += h.normal;
                color += h.color;
                for (std::size_t k = 0; k < count; ++k) {
                    const Vec3& l = l_field[k];
                    if (!surface.lit(h, l)) continue;
                    const double c = dot(h.normal, l);
                    const double spec = specular_factor(options.specular, h.normal, l, v_field);
                    sums[3 * k] += c * (h.color.r + spec);
                    sums[3 * k + 1] += c * (h.color.g + spec);
                    sums[3 * k + 2] += c * (h.color.b + spec);
                }
            }
            for (std::size_t k = 0; k < count; ++k)
                for (int c = 0; c < 3; ++c)
                    out.pixels[(k * texels + t) * 3 + c] = static_cast<float>(sums[3 * k + c] / spp);
            const Vec3 n = hits.empty() || !(length(normal) > 0) ? Vec3{0, 0, 1} : to_stack_frame(normalize(normal));
            out.normals[3 * t] = static_cast<float>(n.x);
            out.normals[3 * t + 1] = static_cast<float>(n.y);
            out.normals[3 * t + 2] = static_cast<float>(n.z);
            if (options.albedo && !hits.empty()) {
                const double s = 1.0 / hits.size();
                out.albedo[3 * t] = static_cast<float>(s * color.r);
                out.albedo[3 * t + 1] = static_cast<float>(s * color.g);
                out.albedo[3 * t + 2] = static_cast<float>(s * color.b);
            }
            row_hits[j] += hits.size();
        }
    };
    // Rows in blocks, so that progress is reported from this thread.
    const int block = std::max(1, std::min(size, 4 * resolve_thread_count(options.threads)));
    for (int first = 0; first < size; first += block) {
        const int rows = std::min(block, size - first);
        parallel_for(rows, options.threads, [&](int r) { render_row(first + r); });
        if (options.progress) options.progress(static_cast<double>(first + rows) / size);
    }
    out.rays = texels * spp;
    for (std::size_t h : row_hits) out.hits += h;
    out.seconds = clock.elapsed_ms() / 1000;
    return out;
}

}  // namespace cmfilter
