// SPDX-License-Identifier: Apache-2.0
// Speed of the heightfield tracer (heightfield_tracer.h) on one thread: a
// camera ray traced from above the slab and, where it hits, a shadow ray
// from the hit towards a light at the same angle from the normal, mirrored
// (the specular direction, grazing as much as the camera ray), as pairs per
// second at 0, 45, 80 and 89 degrees; and the same with the light at the
// camera (each shadow ray retraces its camera ray out of the slab). The baseline is a brute-force march
// on the same rays, timed in the same process: steps of a quarter texel
// through the slab with bisection at the first sign change, and the shadow
// ray marched likewise. Each time is the fastest of 5 runs.
//   build/tests/bench/cmfilter-bench-heightfield-trace
#include "cmfilter/microsurface/heightfield_tracer.h"

#include "bench_timing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <vector>

namespace {

using cmfilter::Heightfield;
using cmfilter::Vec3;

constexpr double kPi = 3.14159265358979323846;

struct Pair {
    Vec3 origin, direction, light;
};

// The marched answer, by the heightfield's bilinear height() alone.
struct March {
    const Heightfield& h;
    double step;

    double gap(const Vec3& o, const Vec3& d, double t) const
    {
        const Vec3 p = o + t * d;
        return p.z - h.height(p.x, p.y);
    }
    bool slab(const Vec3& o, const Vec3& d, double& t0, double& t1) const
    {
        t0 = 0;
        t1 = 1e300;
        if (d.z == 0) return o.z >= h.min_height() && o.z <= h.max_height();
        const double a = (h.min_height() - o.z) / d.z, b = (h.max_height() - o.z) / d.z;
        t0 = std::max(0.0, std::min(a, b));
        t1 = std::max(a, b);
        return t0 <= t1;
    }
    // The first crossing from above, or a negative t for none.
    double trace(const Vec3& o, const Vec3& d) const
    {
        double t0, t1;
        if (!slab(o, d, t0, t1)) return -1;
        for (double a = t0; a < t1; a += step) {
            const double b = std::min(a + step, t1);
            if (gap(o, d, b) < 0) {
                double lo = a, hi = b;
                for (int i = 0; i < 50; ++i) {
                    const double mid = 0.5 * (lo + hi);
                    (gap(o, d, mid) < 0 ? hi : lo) = mid;
                }
                return 0.5 * (lo + hi);
            }
        }
        return -1;
    }
    bool occluded(const Vec3& p, const Vec3& d) const
    {
        double t0, t1;
        if (d.z < 0) return true;
        if (!slab(p, d, t0, t1)) return false;
        for (double t = 1e-9; t < t1; t += step)
            if (gap(p, d, t) < 0) return true;
        return false;
    }
};

}  // namespace

int main()
{
    cmfilter::GaussianMicrosurfaceOptions so;
    so.cosines = 256;
    so.sigma_h = 0.02;
    so.min_wavelength = 0.05;
    so.max_wavelength = 0.4;
    so.tile = 1.6;
    auto surface = cmfilter::GaussianMicrosurface::create(so);
    cmfilter::HeightfieldOptions ho;
    ho.texels_per_min_wavelength = 8;
    std::optional<Heightfield> built;
    const double build_ms = cmfilter_bench::time_ms([&] { built = *Heightfield::create(*surface, ho); });
    const Heightfield& h = *built;
    std::printf("Machine: %s, one thread.\n", cmfilter_bench::cpu_name().c_str());
    std::printf("Microsurface: 256 cosines, sigma_h 0.02, wavelengths 0.05 to 0.4, tile 1.6; heightfield %d x %d "
                "(8 texels per min wavelength), slab [%.4f, %.4f], built in %.0f ms.\n\n",
                h.resolution(), h.resolution(), h.min_height(), h.max_height(), build_ms);
    std::printf("| theta | tracer pairs/s | march pairs/s | tracer / march | share lit | march agrees (lit or not) | "
                "tracer pairs/s, light at the camera | share lit |\n|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    const March march{h, h.texel_size() / 4};
    for (const double theta_degrees : {0.0, 45.0, 80.0, 89.0}) {
        const double theta = theta_degrees * kPi / 180;
        std::mt19937_64 rng(1);
        std::uniform_real_distribution<double> unit(0, 1);
        std::vector<Pair> pairs(200000);
        for (Pair& p : pairs) {
            const double azimuth = 2 * kPi * unit(rng);
            const Vec3 d{std::sin(theta) * std::cos(azimuth), std::sin(theta) * std::sin(azimuth), -std::cos(theta)};
            p.origin = {so.tile * unit(rng), so.tile * unit(rng), h.max_height() + 1};
            p.direction = d;
            p.light = {d.x, d.y, -d.z};
        }
        int lit = 0;
        const double tracer_ms = cmfilter_bench::fastest_ms(5, [&] {
            lit = 0;
            for (const Pair& p : pairs)
                if (const auto hit = h.trace(p.origin, p.direction)) lit += h.occluded(hit->point, p.light) ? 0 : 1;
        });
        // The light at the camera: every shadow ray retraces its camera ray
        // out of the slab, never blocked, the longest walk.
        int back_lit = 0;
        const double back_ms = cmfilter_bench::fastest_ms(5, [&] {
            back_lit = 0;
            for (const Pair& p : pairs)
                if (const auto hit = h.trace(p.origin, p.direction))
                    back_lit += h.occluded(hit->point, -p.direction) ? 0 : 1;
        });
        // The march on the first pairs only: it is slow.
        const std::size_t marched = theta_degrees >= 80 ? 2000 : 20000;
        std::vector<char> march_lit(marched);
        const double march_ms = cmfilter_bench::fastest_ms(5, [&] {
            for (std::size_t i = 0; i < marched; ++i) {
                const Pair& p = pairs[i];
                const double t = march.trace(p.origin, p.direction);
                march_lit[i] = t >= 0 && !march.occluded(p.origin + t * p.direction, p.light);
            }
        });
        std::size_t agree = 0;
        for (std::size_t i = 0; i < marched; ++i) {
            const auto hit = h.trace(pairs[i].origin, pairs[i].direction);
            agree += (hit && !h.occluded(hit->point, pairs[i].light)) == bool(march_lit[i]) ? 1 : 0;
        }
        const double tracer_rate = pairs.size() / (tracer_ms / 1000), march_rate = marched / (march_ms / 1000);
        const double back_rate = pairs.size() / (back_ms / 1000);
        std::printf("| %g | %.3g | %.3g | %.0f | %.3f | %zu of %zu | %.3g | %.3f |\n", theta_degrees, tracer_rate,
                    march_rate, tracer_rate / march_rate, double(lit) / pairs.size(), agree, marched, back_rate,
                    double(back_lit) / pairs.size());
    }
    return 0;
}
