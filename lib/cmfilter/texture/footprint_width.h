// SPDX-License-Identifier: Apache-2.0
// One width for an anisotropic pixel footprint, to pick the LOD of a
// procedural noise's sigma table (which is tabulated for square footprints).
// A box pixel maps to the parallelogram spanned by e1 = d(u, v)/dx and
// e2 = d(u, v)/dy in texture space; its points are c + s e1 + t e2 with s, t
// uniform in [-1/2, 1/2]. Choices (docs/render.md charts their effect):
//   rms    sqrt((|e1|^2 + |e2|^2) / 2). Exact in the linear regime: a linear
//          function g . x varies over the parallelogram with variance
//          ((g . e1)^2 + (g . e2)^2) / 12, whose mean over gradient
//          directions, |g|^2 (|e1|^2 + |e2|^2) / 24, is that of a square of
//          this width, |g|^2 w^2 / 12. The default.
//   area   sqrt(|e1 x e2|): the square of the same area; too small for long,
//          thin footprints (a ground plane near the horizon).
//   major  max(|e1|, |e2|): conservative, over-blurs thin footprints.
//   minor  min(|e1|, |e2|): sharp, under-filters thin footprints.
#pragma once

#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

enum class FootprintWidth { Rms, Area, Major, Minor };
const char* to_string(FootprintWidth width);
Expected<FootprintWidth> parse_footprint_width(const std::string& text);

double footprint_width(FootprintWidth choice, double e1u, double e1v, double e2u, double e2v);

}  // namespace cmfilter
