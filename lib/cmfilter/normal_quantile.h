// Phi^-1, the standard normal quantile: Acklam's rational approximation
// refined by one Halley step on erfc, accurate to about 1e-15 relative over
// (0, 1); -inf at 0, +inf at 1, NaN outside [0, 1].
#pragma once

namespace cmfilter {

double normal_quantile(double p);

}  // namespace cmfilter
