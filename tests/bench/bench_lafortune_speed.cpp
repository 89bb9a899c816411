// SPDX-License-Identifier: Apache-2.0
// The Lafortune fit's speed (the second paper: 112 s for a 256 x 256,
// 2-lobe luminance fit at 1.3 GHz): a SIZE x SIZE, LIGHTS-light RGB stack
// made in memory (smooth random relief under a Fibonacci dome, Lambertian
// colour plus a Phong highlight of exponent 40 about the mirror direction of
// the view (0, 0, 1)), fitted with 2 luminance lobes on THREADS threads; the
// fastest of ROUNDS fits, with the lobe-count histogram, the fallbacks and
// the RMS of the fit at the stack's lights.
//   cmfilter-bench-lafortune-speed [SIZE] [LIGHTS] [THREADS] [ROUNDS] [LOBES]
#include "bench_timing.h"

#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/lafortune_fit.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

using namespace cmfilter;

namespace {

ImageStack make_stack(int size, int lights)
{
    ImageStack stack;
    stack.width = stack.height = size;
    stack.channels = 3;
    const double golden = 3.14159265358979323846 * (3 - std::sqrt(5.0));
    for (int k = 0; k < lights; ++k) {
        const double z = 1 - (k + 0.5) / lights * 0.9;  // elevations above about 6 degrees
        const double r = std::sqrt(1 - z * z);
        stack.lights.push_back({r * std::cos(golden * k), r * std::sin(golden * k), z});
    }
    stack.pixels.resize(stack.texels() * 3 * lights);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const double u = 6.2831853 * i / size, v = 6.2831853 * j / size;
            const Vec3 n = normalize(Vec3{0.4 * std::cos(3 * u) * std::sin(v), -0.3 * std::sin(2 * v + u), 1});
            const Vec3 mirror = 2 * n.z * n - Vec3{0, 0, 1};
            const double c[3] = {0.6 + 0.3 * std::sin(u), 0.5, 0.4 + 0.3 * std::cos(v)};
            const std::size_t t = static_cast<std::size_t>(j) * size + i;
            for (int k = 0; k < lights; ++k) {
                const Vec3 l = stack.lights[k];
                const double shade = std::max(0.0, dot(n, l));
                const double highlight = shade > 0 ? 0.3 * std::pow(std::max(0.0, dot(mirror, l)), 40) : 0;
                for (int ch = 0; ch < 3; ++ch)
                    stack.pixels[(k * stack.texels() + t) * 3 + ch] = static_cast<float>(c[ch] * shade + highlight);
            }
        }
    return stack;
}

}  // namespace

int main(int argc, char** argv)
{
    const int size = argc > 1 ? std::atoi(argv[1]) : 256;
    const int lights = argc > 2 ? std::atoi(argv[2]) : 64;
    const int threads = argc > 3 ? std::atoi(argv[3]) : 2;
    const int rounds = argc > 4 ? std::atoi(argv[4]) : 3;
    const int lobes = argc > 5 ? std::atoi(argv[5]) : 2;
    const ImageStack stack = make_stack(size, lights);
    LafortuneFitOptions options;
    options.lobes = lobes;
    options.threads = threads;
    Expected<LafortuneFit> fit = runtime_error("not fitted");
    const double ms = cmfilter_bench::fastest_ms(rounds, [&] {
        fit = fit_lafortune(stack, options);
        if (!fit) {
            std::fprintf(stderr, "%s\n", fit.error().message.c_str());
            std::exit(4);
        }
    });
    double sum = 0;
    for (int k = 0; k < lights; ++k) {
        const std::vector<float> relit = relight_lafortune(*fit, stack.lights[k], threads);
        for (std::size_t i = 0; i < relit.size(); ++i) {
            const double d = relit[i] - stack.image(k)[i];
            sum += d * d;
        }
    }
    std::printf("machine: %s, %u hardware threads; fastest of %d fits\n", cmfilter_bench::cpu_name().c_str(),
                std::thread::hardware_concurrency(), rounds);
    std::printf("stack: %d x %d, %d lights, RGB in memory; luminance, %d lobes, %d threads\n", size, size, lights,
                lobes, threads);
    std::printf("fit: %.1f ms (%.2f us per texel per thread)\n", ms, ms * 1e3 * threads / stack.texels());
    std::printf("rms at the stack's lights: %.5f; fallbacks: %lld; lobe histogram:",
                std::sqrt(sum / (stack.texels() * 3.0 * lights)), fit->fallbacks);
    for (long long n : fit->lobe_histogram()) std::printf(" %lld", n);
    std::printf("\n");
    return 0;
}
