// SPDX-License-Identifier: Apache-2.0
// Gauss-Hermite rules for the standard normal (gauss_hermite.h) against the
// normal's moments E[Z^2j] = (2j - 1)!! (exact up to degree 2n - 1) and the
// probabilists' Hermite recurrence He_{k+1} = z He_k - k He_{k-1}, whose n-th
// polynomial vanishes at the nodes.
#include "cmfilter/math/gauss_hermite.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace cmfilter;

TEST_CASE("Gauss-Hermite rules integrate the normal's moments exactly up to degree 2n - 1")
{
    for (int n : {1, 2, 3, 5, 8, 12, 16, 24, 32, 50}) {
        CAPTURE(n);
        const GaussHermiteRule rule = gauss_hermite_rule(n);
        REQUIRE(rule.nodes.size() == static_cast<std::size_t>(n));
        REQUIRE(rule.weights.size() == static_cast<std::size_t>(n));
        for (int i = 0; i + 1 < n; ++i) CHECK(rule.nodes[i] < rule.nodes[i + 1]);
        for (double w : rule.weights) CHECK(w > 0);
        double double_factorial = 1;  // (2j - 1)!!
        for (int degree = 0; degree <= std::min(2 * n - 1, 30); ++degree) {
            CAPTURE(degree);
            double sum = 0;
            for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], degree);
            if (degree % 2 == 1) {
                CHECK(std::abs(sum) <= 1e-12 * double_factorial);
            } else {
                CHECK(sum == doctest::Approx(double_factorial).epsilon(1e-11));
                double_factorial *= degree + 1;
            }
        }
    }
}

TEST_CASE("Gauss-Hermite nodes are the roots of the n-th Hermite polynomial")
{
    for (int n : {2, 7, 12, 20}) {
        CAPTURE(n);
        for (double z : gauss_hermite_rule(n).nodes) {
            // He_n(z) / (|He_n|'s scale): the recurrence in normalised form,
            // h_k = He_k / sqrt(k!), so that a root shows as a small value.
            double previous = 0, current = 1;
            for (int k = 0; k < n; ++k) {
                const double next = (z * current - std::sqrt(static_cast<double>(k)) * previous) / std::sqrt(k + 1.0);
                previous = current;
                current = next;
            }
            CHECK(std::abs(current) <= 1e-12 * (1 + std::abs(previous)) * std::exp(0.25 * z * z));
        }
    }
}
