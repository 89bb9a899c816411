#include "cmfilter/scene_materials.h"

#include "cmfilter/color_map_loading.h"
#include "cmfilter/gaussian_color_table_file.h"
#include "cmfilter/noise_sigma_bake.h"
#include "cmfilter/noise_sigma_table_file.h"
#include "cmfilter/noise_spec.h"
#include "cmfilter/table_color_map.h"

#include <sstream>

namespace cmfilter {

namespace {

std::string where(const Scene& scene, std::size_t surface, const std::string& key)
{
    return scene.path + ": /surfaces/" + std::to_string(surface) + "/material/" + key + ": ";
}

Error located(const Error& e, const std::string& prefix) { return {e.kind, prefix + e.message}; }

Status load_colormap(const Scene& scene, std::size_t i, const ColorConfig& config, const MaterialOptions& options,
                     SurfaceMaterial& m)
{
    const ColorMapSource& source = scene.surfaces[i].material.colormap;
    const std::string prefix = where(scene, i, "colormap");
    if (!source.table_path.empty()) {
        auto loaded = read_gaussian_color_table(source.table_path);
        if (!loaded) return located(loaded.error(), prefix);
        TableColorMapOptions map_options;
        map_options.table_path = source.table_path;
        auto map = load_table_color_map(*loaded, map_options, config);
        if (!map) return located(map.error(), prefix);
        m.map = map->map.map;
        m.map_path = map->map.provenance.path;
        m.table = std::move(loaded->table);
        m.table_path = source.table_path;
        return ok();
    }
    ColorMapLoadOptions load;
    load.path = source.image_path;
    load.vmin = source.domain_min;
    load.vmax = source.domain_max;
    load.wrap = source.wrap;
    load.colorspace = source.colorspace;
    auto map = load_color_map(load, config);
    if (!map) return located(map.error(), prefix);
    GaussianColorTableOptions table_options;
    table_options.threads = options.threads;
    auto table = GaussianColorTable::bake(map->map, table_options);
    if (!table) return located(table.error(), prefix);
    m.map = std::move(map->map);
    m.map_path = source.image_path;
    m.table = std::move(*table);
    return ok();
}

Status load_driver(const Scene& scene, std::size_t i, const MaterialOptions& options, SurfaceMaterial& m)
{
    const DriverSource& driver = scene.surfaces[i].material.driver;
    const std::string prefix = where(scene, i, "driver");
    if (driver.kind != DriverKind::Noise)
        return bad_input(prefix + "texture drivers (moments, image) are not supported by render yet; use a noise");
    auto spec = parse_noise_spec(driver.noise_spec);
    if (!spec) return located(spec.error(), prefix + "noise: ");
    auto noise = make_noise(*spec);
    if (!noise) return located(noise.error(), prefix + "noise: ");

    std::optional<NoiseSigmaTable> table;
    if (!driver.sigma_table_path.empty()) {
        auto loaded = read_noise_sigma_table(driver.sigma_table_path, FootprintShape::Box);
        if (!loaded) return located(loaded.error(), prefix + "sigma_table: ");
        auto baked_for = parse_noise_spec(loaded->noise_spec);
        if (!baked_for || !(*baked_for == *spec))
            return bad_input(prefix + "sigma_table: '" + driver.sigma_table_path + "' was baked for the noise '" +
                             loaded->noise_spec + "', not for '" + to_string(*spec) + "'");
        table = std::move(loaded->table);
    } else {
        if (options.note)
            options.note("baking the sigma table of " + to_string(*spec) + " (surface " + std::to_string(i) +
                         "; name one with driver/sigma_table to skip this)");
        NoiseSigmaBakeOptions bake_options;
        bake_options.threads = options.threads;
        auto bake = bake_noise_sigma(*noise, bake_options);
        if (!bake) return located(bake.error(), prefix);
        auto box = bake->table(FootprintShape::Box);
        if (!box) return located(box.error(), prefix);
        table = std::move(*box);
        m.sigma_table_baked = true;
    }

    // A clamp map whose domain misses mean +- 3 sigma of the noise shows one
    // end colour everywhere: surely the wrong domain.
    if (m.map.wrap == WrapMode::Clamp) {
        const NoiseGlobalStats stats = measure_global_stats(*noise, 1 << 16, 7, options.threads);
        const double lo = stats.mean - 3 * stats.sigma, hi = stats.mean + 3 * stats.sigma;
        if (hi < m.map.vmin || lo > m.map.vmax) {
            std::ostringstream s;
            s << where(scene, i, "colormap") << "the colour map's domain [" << m.map.vmin << ", " << m.map.vmax
              << "] does not meet the driver's values (mean +- 3 sigma: [" << lo << ", " << hi << "])";
            return bad_input(s.str());
        }
    }
    m.noise.emplace(std::move(*noise), std::move(*table));
    return ok();
}

}  // namespace

Expected<std::vector<SurfaceMaterial>> prepare_materials(const Scene& scene, const ColorConfig& config,
                                                         const MaterialOptions& options)
{
    std::vector<SurfaceMaterial> materials(scene.surfaces.size());
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        if (auto st = load_colormap(scene, i, config, options, materials[i]); !st) return st.error();
        if (auto st = load_driver(scene, i, options, materials[i]); !st) return st.error();
    }
    return materials;
}

}  // namespace cmfilter
