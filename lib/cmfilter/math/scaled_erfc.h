// SPDX-License-Identifier: Apache-2.0
// The scaled complementary error function erfcx(a) = erfc(a) e^{a^2}, for
// a >= 0: the factor that keeps Gaussian tail integrals finite and free of
// cancellation where erfc itself underflows or loses its digits (Smith's
// Lambda, smith_lambda.h; the slope filtering distribution,
// slope_filtering.h). erfc times e^{a^2} below a = 4, Lentz's continued
// fraction sqrt(pi) erfcx(a) = 1 / (a + (1/2) / (a + 1 / (a + (3/2) / (a + ...))))
// (60 levels) from there on.
#pragma once

namespace cmfilter {

// a >= 0.
double scaled_erfc(double a);

}  // namespace cmfilter
