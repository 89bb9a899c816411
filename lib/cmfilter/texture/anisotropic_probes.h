// SPDX-License-Identifier: Apache-2.0
// Anisotropic footprints as several square-ish ones, the way texture units
// filter anisotropically: the pixel's parallelogram (edges e1, e2 in texture
// space, points c + s e1 + t e2 with s, t in [-1/2, 1/2]) is cut along its
// longer edge into n = min(max_probes, ceil(|major| / |minor|)) equal pieces;
// probe j sits at c + ((j + 1/2) / n - 1/2) major, and each piece (edges
// major / n and minor) is reduced to one width by the chosen FootprintWidth.
// The filtered colour is the mean of the probes' colours: a thin footprint
// near the horizon keeps what varies across it, which one wide square
// averages away. n = 1 (max_probes = 1, or a footprint no longer than wide)
// is the single footprint of footprint_width.h.
#pragma once

#include "cmfilter/texture/footprint_width.h"

namespace cmfilter {

struct FootprintProbes {
    int count = 1;
    double step_u = 0, step_v = 0;    // the major edge: probe j at c + ((j + 0.5) / count - 0.5) (step_u, step_v)
    double minor_u = 0, minor_v = 0;  // the other edge, each piece's whole
    double width = 0;                 // of each piece
};

FootprintProbes footprint_probes(double e1u, double e1v, double e2u, double e2v, int max_probes, FootprintWidth choice);

}  // namespace cmfilter
