// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/anisotropic_probes.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

FootprintProbes footprint_probes(double e1u, double e1v, double e2u, double e2v, int max_probes, FootprintWidth choice)
{
    FootprintProbes p;
    const double l1 = std::hypot(e1u, e1v), l2 = std::hypot(e2u, e2v);
    const bool first_major = l1 >= l2;
    const double major_u = first_major ? e1u : e2u, major_v = first_major ? e1v : e2v;
    const double minor_u = first_major ? e2u : e1u, minor_v = first_major ? e2v : e1v;
    const double major = std::max(l1, l2), minor = std::min(l1, l2);
    if (max_probes > 1 && major > minor) {
        const double ratio = minor > 0 ? major / minor : static_cast<double>(max_probes);
        p.count = static_cast<int>(std::min<double>(max_probes, std::ceil(ratio)));
    }
    p.step_u = major_u;
    p.step_v = major_v;
    p.minor_u = minor_u;
    p.minor_v = minor_v;
    p.width = footprint_width(choice, major_u / p.count, major_v / p.count, minor_u, minor_v);
    return p;
}

}  // namespace cmfilter
