// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/scene/tolerance_tables.h"

#include "cmfilter/scene/driver_sigma_range.h"
#include "cmfilter/tables/plain_lookup.h"
#include "cmfilter/tables/table_size_search.h"

#include <cmath>
#include <sstream>

namespace cmfilter {

namespace {

Error located(const Scene& scene, std::size_t surface, const Error& e)
{
    return prefixed(scene.path + ": /surfaces/" + std::to_string(surface) + "/material/colormap: ", e);
}

Status check_optional(const std::optional<double>& value, const char* field, const char* expected)
{
    if (value && !(std::isfinite(*value) && *value >= 0)) {
        std::ostringstream msg;
        msg << field << " " << *value << " is invalid (expected " << expected << ")";
        return bad_input(msg.str(), field);
    }
    return ok();
}

}  // namespace

Status check_plain_bound(const std::optional<double>& plain_bound)
{
    return check_optional(plain_bound, "TableChoiceOptions::plain_bound",
                          "a CIEDE2000 difference >= 0; 0 turns it off");
}

Status choose_surface_table(const Scene& scene, std::size_t surface, ColorLayer& layer,
                            const TableChoiceOptions& options)
{
    if (auto st = check_optional(options.tolerance, "TableChoiceOptions::tolerance", "a CIEDE2000 difference > 0"); !st)
        return st;
    if (auto st = check_plain_bound(options.plain_bound); !st) return st;
    if (surface >= scene.surfaces.size())
        return bad_input(scene.path + ": surface " + std::to_string(surface) + " does not exist");
    const std::optional<double> tolerance = options.tolerance
                                                ? (*options.tolerance > 0 ? options.tolerance : std::nullopt)
                                                : scene.surfaces[surface].material.colormap.tolerance;

    TableFit fit;
    if (tolerance) {
        auto range = largest_surface_sigma(scene, surface, options.threads);
        if (!range) return range.error();
        TableSizeSearchOptions search;
        search.tolerance = *tolerance;
        search.quantile = options.quantile;
        search.sigma_max = range->sigma_max;
        search.seed = options.seed;
        search.threads = options.threads;
        auto found = find_smallest_table(layer.map, search);
        if (!found) return located(scene, surface, found.error());
        layer.table = std::move(found->table);
        fit.tolerance = *tolerance;
        fit.statistic = quantile_name(options.quantile);
        fit.error = found->error;
        fit.sigma_max = range->sigma_max;
        fit.sigma_max_how = range->how;
        fit.candidates = static_cast<int>(found->trials.size());
    }
    fit.plain_bound = options.plain_bound ? *options.plain_bound : tolerance ? kPlainLookupFraction * *tolerance : 0.0;
    layer.plain = PlainLookupSigma();
    if (fit.plain_bound > 0) {
        PlainLookupOptions plain;
        plain.bound = fit.plain_bound;
        plain.sigma_cap = layer.table.axes().sigma_max;
        plain.threads = options.threads;
        auto sigma = plain_lookup_sigma(layer.map, plain);
        if (!sigma) return located(scene, surface, sigma.error());
        layer.plain = std::move(*sigma);
    }
    layer.fit = std::move(fit);
    return ok();
}

Status choose_surface_tables(const Scene& scene, std::vector<Material>& materials, const TableChoiceOptions& options)
{
    for (std::size_t i = 0; i < materials.size(); ++i)
        if (auto st = choose_surface_table(scene, i, table_layer(materials[i]), options); !st) return st;
    return ok();
}

}  // namespace cmfilter
