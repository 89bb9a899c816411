// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/math/scaled_erfc.h"

#include <cmath>

namespace cmfilter {

double scaled_erfc(double a)
{
    constexpr double kPi = 3.14159265358979323846;
    if (a < 4) return std::erfc(a) * std::exp(a * a);
    double f = a;
    for (int k = 60; k >= 1; --k) f = a + (0.5 * k) / f;
    return 1.0 / (f * std::sqrt(kPi));
}

}  // namespace cmfilter
