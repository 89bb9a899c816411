// SPDX-License-Identifier: Apache-2.0
// How far the paper's Gaussian fit of the height filtering distribution
// (eqs. 17-18) is from D_h's exact mean and central standard deviation
// (height_filtering.h), over the Lambda sum L, in units of sigma_h
// (docs/microsurface.md). Prints a markdown table at chosen L and the worst
// differences over a log grid of L up to 10, 100 and 1e6.
//   build/tests/bench/cmfilter-height-fit-accuracy
#include "cmfilter/microsurface/height_filtering.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

int main()
{
    using cmfilter::HeightMoments;
    std::printf(
        "| L | exact mean | fit mean (eq. 17) | exact sigma | fit sigma (eq. 18) |\n|---:|---:|---:|---:|---:|\n");
    for (double L : {0.0, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 1e3, 1e4, 1e5, 1e6}) {
        const HeightMoments e = cmfilter::exact_height_moments(L, 1), f = cmfilter::paper_height_fit(L, 1);
        std::printf("| %g | %.4f | %.4f | %.4f | %.4f |\n", L, e.mean, f.mean, e.sigma, f.sigma);
    }
    std::printf("\n| L up to | worst mean difference (at L) | worst sigma difference (at L) |\n|---:|---|---|\n");
    for (double top : {10.0, 100.0, 1e6}) {
        double dm = 0, ds = 0, lm = 0, ls = 0;
        for (double e = -4; e <= std::log10(top) + 1e-9; e += 0.01) {
            const double L = std::pow(10.0, e);
            const HeightMoments a = cmfilter::exact_height_moments(L, 1), b = cmfilter::paper_height_fit(L, 1);
            if (std::abs(a.mean - b.mean) > dm) dm = std::abs(a.mean - b.mean), lm = L;
            if (std::abs(a.sigma - b.sigma) > ds) ds = std::abs(a.sigma - b.sigma), ls = L;
        }
        std::printf("| %g | %.4f sigma_h (%.3g) | %.4f sigma_h (%.3g) |\n", top, dm, lm, ds, ls);
    }
    return 0;
}
