// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/math/gauss_hermite.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

GaussHermiteRule gauss_hermite_rule(int n)
{
    n = std::clamp(n, 1, 100);
    constexpr double kPi = 3.14159265358979323846;
    const double pi_m4 = std::pow(kPi, -0.25);
    std::vector<double> x(n), w(n);
    double z = 0;
    for (int i = 0; i < (n + 1) / 2; ++i) {
        // Initial guesses for the largest roots first.
        if (i == 0) z = std::sqrt(2.0 * n + 1) - 1.85575 * std::pow(2.0 * n + 1, -1.0 / 6);
        else if (i == 1) z -= 1.14 * std::pow(static_cast<double>(n), 0.426) / z;
        else if (i == 2) z = 1.86 * z - 0.86 * x[0];
        else if (i == 3) z = 1.91 * z - 0.91 * x[1];
        else z = 2 * z - x[i - 2];
        double derivative = 1;
        for (int iteration = 0; iteration < 100; ++iteration) {
            // Orthonormal Hermite functions' polynomial part: p_j(z), p_{j-1}(z).
            double p1 = pi_m4, p2 = 0;
            for (int j = 0; j < n; ++j) {
                const double p3 = p2;
                p2 = p1;
                p1 = z * std::sqrt(2.0 / (j + 1)) * p2 - std::sqrt(static_cast<double>(j) / (j + 1)) * p3;
            }
            derivative = std::sqrt(2.0 * n) * p2;
            const double step = p1 / derivative;
            z -= step;
            if (std::abs(step) <= 1e-15 * (1 + std::abs(z))) break;
        }
        x[i] = z, x[n - 1 - i] = -z;
        w[i] = w[n - 1 - i] = 2 / (derivative * derivative);
    }
    if (n % 2 == 1) x[n / 2] = 0;  // the middle root, exactly
    GaussHermiteRule rule;
    rule.nodes.resize(n);
    rule.weights.resize(n);
    for (int i = 0; i < n; ++i) {
        rule.nodes[i] = -std::sqrt(2.0) * x[i];  // x descending
        rule.weights[i] = w[i] / std::sqrt(kPi);
    }
    return rule;
}

}  // namespace cmfilter
