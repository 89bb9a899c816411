// SPDX-License-Identifier: Apache-2.0
// Tables that model no more than a scene needs (docs/render.md, "Table sizes
// and the small-sigma shortcut"). For each surface:
//   - with a tolerance (the caller's, else the scene's colormap/tolerance),
//     its table is the smallest that meets it
//     (table_size_search.h: CIEDE2000 of bilinear lookups against the exact
//     eq. 10, p99.9 at random (v, sigma)) over sigma in [0, sigma_max], with
//     sigma_max the largest sigma that surface's driver produces
//     (largest_surface_sigma, driver_sigma_range.h), the same search and
//     sigma range as `bake-colormap --tolerance DE --for SCENE`;
//   - the small-sigma shortcut: layer.plain, the sigma per mean below which
//     the gaussian method takes C0(mean) directly, where the exact T stays
//     within `plain_bound` CIEDE2000 of C0 (plain_lookup.h). By
//     default the bound is kPlainLookupFraction of the tolerance for a fitted
//     table, and the shortcut is off for a table that was not fitted.
#pragma once

#include "cmfilter/scene/material.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/tables/color_layer.h"
#include "cmfilter/tables/table_fit.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace cmfilter {

// BadInput (field TableChoiceOptions::plain_bound, named --shortcut) unless
// the small-sigma shortcut's bound is unset or finite and >= 0: the one check
// of it.
Status check_plain_bound(const std::optional<double>& plain_bound);

// Fits surface `surface`'s table (layer.table, layer.fit) over its map
// (layer.map) and sets its shortcut (layer.plain). BadInput for an
// out-of-range tolerance or bound (named as
// --tolerance / --shortcut), or when no table of the search grid meets the
// tolerance; the errors of largest_surface_sigma. Messages name the surface.
Status choose_surface_table(const Scene& scene, std::size_t surface, ColorLayer& layer,
                            const TableChoiceOptions& options);

// choose_surface_table for every surface's table layer (material.h), in order.
Status choose_surface_tables(const Scene& scene, std::vector<Material>& materials, const TableChoiceOptions& options);

}  // namespace cmfilter
