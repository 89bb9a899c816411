// SPDX-License-Identifier: Apache-2.0
// The maximum mipmap (max_mipmap.h) against the brute-force maximum of the
// nodes of each block, wrapping.
#include "cmfilter/microsurface/max_mipmap.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace cmfilter;

TEST_CASE("max mipmap blocks hold the largest node of each block, rounded up to a float")
{
    const int n = 16;
    std::mt19937_64 rng(5);
    std::normal_distribution<double> normal(0, 1);
    std::vector<double> periodic(n * n);
    for (double& h : periodic) h = normal(rng);
    std::vector<double> closed((n + 1) * (n + 1));
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) closed[j * (n + 1) + i] = periodic[(j % n) * n + (i % n)];
    const MaxMipmap mip(closed.data(), n);
    REQUIRE(mip.top_level() == 4);
    for (int k = 1; k <= 4; ++k) {
        const int size = 1 << k, blocks = n / size;
        for (int by = 0; by < blocks; ++by)
            for (int bx = 0; bx < blocks; ++bx) {
                double m = -1e300;
                for (int j = by * size; j <= (by + 1) * size; ++j)
                    for (int i = bx * size; i <= (bx + 1) * size; ++i) m = std::max(m, periodic[(j % n) * n + (i % n)]);
                CAPTURE(k);
                CAPTURE(bx);
                CAPTURE(by);
                const double b = mip.block_max(k, bx, by);
                CHECK(b >= m);
                CHECK(b - m <= std::abs(m) * 1.2e-7);  // one float ulp
                // Wrapping in both directions.
                CHECK(mip.block_max(k, bx - blocks, by + 3 * blocks) == b);
            }
    }
    CHECK(MaxMipmap(closed.data(), 1).top_level() == 0);
}
