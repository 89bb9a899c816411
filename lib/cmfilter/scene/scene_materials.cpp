// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/scene/scene_materials.h"

#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/texture/moment_source.h"
#include "cmfilter/noise/noise_sigma_bake.h"
#include "cmfilter/noise/noise_sigma_table_file.h"
#include "cmfilter/noise/noise_spec.h"
#include "cmfilter/colormap/slope_color_map_loading.h"
#include "cmfilter/tables/table_color_map.h"
#include "cmfilter/scene/tolerance_tables.h"
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/texture/segment_pyramid_file.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <sstream>
#include <system_error>

namespace cmfilter {

namespace {

std::string where(const Scene& scene, std::size_t surface, const std::string& key)
{
    return scene.path + ": /surfaces/" + std::to_string(surface) + "/material/" + key + ": ";
}

// A colour map and a driver to load: a plain material's, or a microsurface
// material's base layer (keys under /material/base/).
struct LayerSource {
    const Scene& scene;
    std::size_t i;
    const ColorMapSource& colormap;
    const DriverSource& driver;
    std::string root;  // "" or "base/"
    std::string where(const std::string& key) const { return cmfilter::where(scene, i, root + key); }
};

LayerSource material_layer(const Scene& scene, std::size_t i)
{
    const MaterialSource& material = scene.surfaces[i].material;
    return {scene, i, material.colormap, material.driver, ""};
}

Error located(const Error& e, const std::string& prefix) { return {e.kind, prefix + e.message}; }

// A gradient image laid over [vmin, vmax].
ColorMapLoadOptions gradient_load_options(const std::string& path, double vmin, double vmax, WrapMode wrap,
                                          const std::string& colorspace)
{
    ColorMapLoadOptions load;
    load.path = path;
    load.vmin = vmin;
    load.vmax = vmax;
    load.wrap = wrap;
    load.colorspace = colorspace;
    return load;
}

// The layer's colour map and, unless it is fitted later, its table.
Status load_colormap(const LayerSource& layer, const ColorConfig& config, const MaterialOptions& options, ColorLayer& m,
                     MaterialProvenance& provenance)
{
    const ColorMapSource& source = layer.colormap;
    const std::string prefix = layer.where("colormap");
    if (!source.table_path.empty()) {
        auto loaded = read_gaussian_color_table(source.table_path);
        if (!loaded) return located(loaded.error(), prefix);
        TableColorMapOptions map_options;
        map_options.table_path = source.table_path;
        auto map = load_table_color_map(*loaded, map_options, config);
        if (!map) return located(map.error(), prefix);
        m.map = map->map.map;
        provenance.map_path = map->map.provenance.path;
        provenance.map_source = map->map.provenance;
        m.table = std::move(loaded->table);
        provenance.table_path = source.table_path;
        return ok();
    }
    auto map = load_color_map(
        gradient_load_options(source.image_path, source.domain_min, source.domain_max, source.wrap, source.colorspace),
        config);
    if (!map) return located(map.error(), prefix);
    m.map = std::move(map->map);
    provenance.map_path = source.image_path;
    provenance.map_source = map->provenance;
    const std::optional<double>& tolerance = options.tables.tolerance;
    if (tolerance ? *tolerance > 0 : source.tolerance.has_value()) return ok();  // fitted later
    GaussianColorTableOptions table_options;
    table_options.threads = options.threads;
    auto table = GaussianColorTable::bake(m.map, table_options);
    if (!table) return located(table.error(), prefix);
    m.table = std::move(*table);
    return ok();
}

// A clamp map whose domain misses the driver's values [lo, hi] (`what` says
// how they were measured) shows one end colour everywhere: surely the wrong
// domain.
Status check_domain(const LayerSource& layer, const ColorMap& map, double lo, double hi, const std::string& what)
{
    if (map.wrap != WrapMode::Clamp || !(hi < map.vmin || lo > map.vmax)) return ok();
    std::ostringstream s;
    s << layer.where("colormap") << "the colour map's domain [" << map.vmin << ", " << map.vmax
      << "] does not meet the driver's values (" << what << ": [" << lo << ", " << hi << "])";
    return bad_input(s.str());
}

// A procedural noise and its sigma table: named, or baked here.
Expected<NoiseDriver> load_noise_driver(const LayerSource& layer, const ColorMap& map, const MaterialOptions& options,
                                        MaterialProvenance& provenance)
{
    const DriverSource& driver = layer.driver;
    const std::size_t i = layer.i;
    const std::string prefix = layer.where("driver");
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
        provenance.sigma_table_baked = true;
    }

    if (map.wrap == WrapMode::Clamp) {
        const NoiseGlobalStats stats = measure_global_stats(*noise, 1 << 16, 7, options.threads);
        if (auto st =
                check_domain(layer, map, stats.mean - 3 * stats.sigma, stats.mean + 3 * stats.sigma, "mean +- 3 sigma");
            !st)
            return st.error();
    }
    return NoiseDriver{FilteredNoise(std::move(*noise), std::move(*table))};
}

// A moment pyramid (bake-moments output) and the driver it was baked from,
// read back from its cmfilter:source and checked as apply checks it.
Expected<TextureDriver> load_moments_driver(const LayerSource& layer, const ColorMap& map,
                                            const MaterialOptions& options, MaterialProvenance& provenance)
{
    const std::string& path = layer.driver.moments_path;
    const std::string prefix = layer.where("driver/moments");
    auto moments = MomentTexture::open(path);
    if (!moments) return located(moments.error(), prefix);
    const MomentPyramidInfo& info = moments->info();
    if (auto st = check_domain(layer, map, info.driver_min, info.driver_max, "min and max"); !st) return st.error();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(info.source, ec)) {
        // The pyramid alone serves naive and gaussian; what needs level 0
        // refuses the material with this (render, load_histograms).
        provenance.driver_path = info.source;
        provenance.missing_driver = prefix + "cannot read driver '" + info.source + "' recorded in '" + path +
                                    "' (cmfilter:source): no such file";
        auto texture = FilteredTexture::create(std::move(*moments), std::nullopt);
        if (!texture) return located(texture.error(), prefix);
        return TextureDriver{std::move(*texture), std::nullopt, std::nullopt};
    }
    auto source = read_moment_source(info.source, path, info, options.threads);
    if (!source) return located(source.error(), prefix);
    if (!is_moment_source(*source, info))
        return bad_input(prefix + moment_source_changed(info.source, *source, path, info) + "; re-bake the moments");
    provenance.driver_path = info.source;  // before the moments (and info with them) move
    auto texture = FilteredTexture::create(std::move(*moments), std::move(source->image.values));
    if (!texture) return located(texture.error(), prefix);
    return TextureDriver{std::move(*texture), std::nullopt, std::nullopt};
}

// A driver image: read once, its moment pyramid baked in process into a
// temporary file (TextureSystem reads files) that the texture keeps.
Expected<TextureDriver> load_image_driver(const LayerSource& layer, const ColorMap& map, const MaterialOptions& options,
                                          MaterialProvenance& provenance)
{
    const std::string& path = layer.driver.image_path;
    const std::size_t i = layer.i;
    const std::string prefix = layer.where("driver/image");
    MomentBakeOptions bake;
    bake.driver_path = path;
    bake.wrap = TextureWrap::Periodic;  // texture coordinates repeat (scene.h)
    bake.order = options.moment_order;
    bake.threads = options.threads;
    auto driver = read_driver_and_hash(bake.driver_read());
    if (!driver) return located(driver.error(), prefix);
    if (auto st = check_domain(layer, map, driver->image.min, driver->image.max, "min and max"); !st) return st.error();
    if (options.note)
        options.note("baking the moment pyramid of " + path + " (surface " + std::to_string(i) +
                     "; bake it once with bake-moments --wrap periodic and name it with driver/moments to skip "
                     "this)");
    auto file = TemporaryFile::create("cmfilter-moments", ".exr");
    if (!file) return located(file.error(), prefix);
    bake.output_path = file->path();
    auto baked = bake_moment_pyramid(bake, *driver);
    if (!baked) return located(baked.error(), prefix);
    auto moments = MomentTexture::open(file->path());
    if (!moments) return located(moments.error(), prefix);
    auto texture = FilteredTexture::create(std::move(*moments), std::move(driver->image.values),
                                           std::make_shared<const TemporaryFile>(std::move(*file)));
    if (!texture) return located(texture.error(), prefix);
    provenance.driver_path = path;
    provenance.moments_baked = true;
    return TextureDriver{std::move(*texture), std::nullopt, std::nullopt};
}

// The histogram pyramid of a texture driver (render --method exact): baked
// from the level-0 driver the texture was made from, with its wrap and
// channel, into a temporary file that the material keeps.
Status load_histograms(const Scene& scene, std::size_t i, const MaterialOptions& options, TextureDriver& texture,
                       MaterialProvenance& provenance)
{
    const DriverSource& driver = scene.surfaces[i].material.driver;
    const std::string prefix = where(scene, i, driver.kind == DriverKind::Moments ? "driver/moments" : "driver/image");
    if (!provenance.missing_driver.empty())
        return io_error(provenance.missing_driver +
                        "; exact bakes its histograms from the driver's texels: re-bake the "
                        "moments from the driver where it is now, or name the driver itself with driver/image");
    const MomentPyramidInfo& moments = texture.texture.moments().info();
    HistogramBakeOptions bake;
    bake.driver_path = provenance.driver_path;
    if (driver.kind == DriverKind::Moments) bake.channel = moments.channel;
    bake.wrap = moments.wrap;
    bake.threads = options.threads;
    if (options.note)
        options.note("baking the histogram pyramid of " + provenance.driver_path + " (surface " + std::to_string(i) +
                     "; --method exact)");
    auto file = TemporaryFile::create("cmfilter-histograms", ".exr");
    if (!file) return located(file.error(), prefix);
    bake.output_path = file->path();
    auto baked = bake_histogram_pyramid(bake);
    if (!baked) return located(baked.error(), prefix);
    auto histograms = HistogramTexture::open(file->path());
    if (!histograms) return located(histograms.error(), prefix);
    provenance.histograms_file = std::make_shared<const TemporaryFile>(std::move(*file));
    texture.histograms.emplace(std::move(*histograms));
    return ok();
}

// Where surface i's segment pyramid is named or baked for: driver/segments,
// else its driver's key.
std::string segments_where(const Scene& scene, std::size_t i)
{
    const DriverSource& driver = scene.surfaces[i].material.driver;
    return where(scene, i,
                 !driver.segments_path.empty()        ? "driver/segments"
                 : driver.kind == DriverKind::Moments ? "driver/moments"
                                                      : "driver/image");
}

// The segment pyramid of surface i's texture driver, baked from its level-0
// driver (with its wrap and channel) for the breakpoints of its map into a
// temporary file the material keeps.
Status bake_segments(const Scene& scene, std::size_t i, const MaterialOptions& options, Material& m)
{
    const std::string prefix = segments_where(scene, i);
    if (!m.provenance.missing_driver.empty())
        return io_error(m.provenance.missing_driver +
                        "; segments bakes its ramp means from the driver's texels: re-bake the moments from the "
                        "driver where it is now, name the driver itself with driver/image, or name a segment "
                        "pyramid with driver/segments");
    const MomentPyramidInfo& moments = std::get<TextureDriver>(m.driver).texture.moments().info();
    SegmentPyramidBakeOptions bake;
    bake.driver_path = m.provenance.driver_path;
    if (scene.surfaces[i].material.driver.kind == DriverKind::Moments) bake.channel = moments.channel;
    bake.wrap = moments.wrap;
    bake.threads = options.threads;
    bake.maps = {&m.color.map};
    bake.map_sources = {m.provenance.map_path};
    bake.tolerance_de = options.segments_tolerance;
    if (options.note)
        options.note("baking the segment pyramid of " + m.provenance.driver_path + " (surface " + std::to_string(i) +
                     "; --method segments; bake it once with bake-moments --segments and name it with "
                     "driver/segments to skip this)");
    auto file = TemporaryFile::create("cmfilter-segments", ".exr");
    if (!file) return located(file.error(), prefix);
    bake.output_path = file->path();
    if (auto baked = bake_segment_pyramid(bake); !baked) return located(baked.error(), prefix);
    const std::string path = file->path();
    return open_segments(scene, i, m, path, std::make_shared<const TemporaryFile>(std::move(*file)));
}

// A noise or texture driver over the layer's colour map.
Expected<MaterialDriver> load_driver(const LayerSource& layer, const ColorMap& map, const MaterialOptions& options,
                                     MaterialProvenance& provenance)
{
    const auto as_driver = [](auto loaded) -> Expected<MaterialDriver> {
        if (!loaded) return loaded.error();
        return MaterialDriver{std::move(*loaded)};
    };
    switch (layer.driver.kind) {
    case DriverKind::Noise: return as_driver(load_noise_driver(layer, map, options, provenance));
    case DriverKind::Moments: return as_driver(load_moments_driver(layer, map, options, provenance));
    case DriverKind::Image: return as_driver(load_image_driver(layer, map, options, provenance));
    }
    return runtime_error(layer.where("driver") + "unknown driver kind");
}

// A plain material: C0 (loaded already) over a noise or texture driver.
Expected<Material> load_driven_material(const LayerSource& layer, const MaterialOptions& options,
                                        MaterialProvenance provenance, ColorLayer color)
{
    auto driver = load_driver(layer, color.map, options, provenance);
    if (!driver) return driver.error();
    return Material{std::move(provenance), std::move(color), std::move(*driver)};
}

// A slope colour map (sec. 5.2): a steepness gradient over degrees, or a
// slope-vector image.
Status load_slope_map(const Scene& scene, std::size_t i, const ColorConfig& config, std::optional<SlopeMap>& slope,
                      MaterialProvenance& provenance)
{
    const SlopeColorMapSource& source = *scene.surfaces[i].material.slope_colormap;
    const std::string prefix = where(scene, i, "slope_colormap");
    if (source.kind == SlopeMapKind::Steepness) {
        auto map = load_color_map(gradient_load_options(source.image_path, source.domain_min, source.domain_max,
                                                        source.wrap, source.colorspace),
                                  config);
        if (!map) return located(map.error(), prefix);
        slope = SteepnessColorMap{std::move(map->map)};
    } else {
        SlopeVectorColorMapLoadOptions load;
        load.path = source.image_path;
        load.colorspace = source.colorspace;
        load.s_max = source.max_slope;
        auto map = load_slope_vector_color_map(load, config);
        if (!map) return located(map.error(), prefix);
        slope = std::move(map->map);
    }
    provenance.slope_map_path = source.image_path;
    return ok();
}

// A base layer: C0 and its driver, loaded as a plain material's (its table
// the default one).
Expected<std::shared_ptr<const Material>> load_base_layer(const Scene& scene, std::size_t i, const ColorConfig& config,
                                                          const MaterialOptions& options)
{
    const BaseLayerSource& source = *scene.surfaces[i].material.base;
    const LayerSource layer{scene, i, source.colormap, source.driver, "base/"};
    MaterialOptions base_options = options;
    base_options.tables.tolerance = 0;  // the default table
    MaterialProvenance provenance;
    ColorLayer color;
    if (auto st = load_colormap(layer, config, base_options, color, provenance); !st) return st.error();
    auto base = load_driven_material(layer, base_options, std::move(provenance), std::move(color));
    if (!base) return base.error();
    return std::make_shared<const Material>(std::move(*base));
}

// What colours a microsurface besides C_h: its slope map, its base layer and
// their combination.
Status load_microsurface_colors(const Scene& scene, std::size_t i, const ColorConfig& config,
                                const MaterialOptions& options, MicrosurfaceColors& colors,
                                std::shared_ptr<const Material>& base, MaterialProvenance& provenance)
{
    const MaterialSource& material = scene.surfaces[i].material;
    if (material.slope_colormap)
        if (auto st = load_slope_map(scene, i, config, colors.slope, provenance); !st) return st;
    if (material.base) {
        auto loaded = load_base_layer(scene, i, config, options);
        if (!loaded) return loaded.error();
        base = std::move(*loaded);
    }
    colors.combine = material.combine;
    return ok();
}

// A microsurface material (Driver: MicrosurfaceDriver or DisplacementDriver)
// over `surface`: C_h (`heights`), its slope map, base layer and combination,
// and height_scale from the mapping (scene units per texture unit).
template <class Driver, class Shape>
Expected<Material> layered_material(const Scene& scene, std::size_t i, const ColorConfig& config,
                                    const MaterialOptions& options, MaterialProvenance provenance,
                                    std::optional<ColorLayer> heights, Shape surface)
{
    MicrosurfaceColors colors;
    colors.height = std::move(heights);
    std::shared_ptr<const Material> base;
    if (auto st = load_microsurface_colors(scene, i, config, options, colors, base, provenance); !st) return st.error();
    return Material{
        std::move(provenance), ColorLayer{},
        Driver{std::move(surface), 1.0 / length(scene.surfaces[i].mapping.u_axis), std::move(colors), std::move(base)}};
}

// A Gaussian microsurface (sec. 5), a clamp height map's domain checked
// against its heights' +- 3 sigma_h, and its colours.
Expected<Material> load_microsurface_material(const Scene& scene, std::size_t i, const ColorConfig& config,
                                              const MaterialOptions& options, MaterialProvenance provenance,
                                              std::optional<ColorLayer> heights)
{
    const Surface& surface = scene.surfaces[i];
    auto micro = GaussianMicrosurface::create(*surface.material.microsurface);
    if (!micro) return located(micro.error(), where(scene, i, "microsurface"));
    const double sigma = micro->sigma_h();
    if (heights)
        if (auto st = check_domain(material_layer(scene, i), heights->map, -3 * sigma, 3 * sigma,
                                   "the microsurface's heights, +- 3 sigma_h");
            !st)
            return st.error();
    return layered_material<MicrosurfaceDriver>(scene, i, config, options, std::move(provenance), std::move(heights),
                                                std::move(*micro));
}

// A textured displacement, a clamp height map's domain checked against its
// heights, and its colours.
Expected<Material> load_displacement_material(const Scene& scene, std::size_t i, const ColorConfig& config,
                                              const MaterialOptions& options, MaterialProvenance provenance,
                                              std::optional<ColorLayer> heights)
{
    const Surface& surface = scene.surfaces[i];
    const DisplacementSource& source = *surface.material.displacement;
    DisplacementOptions o;
    o.path = source.image_path;
    o.channel = source.channel;
    o.height_scale = source.height_scale;
    o.threads = options.threads;
    auto texture = DisplacementTexture::load(o);
    if (!texture) return located(texture.error(), where(scene, i, "displacement"));
    if (heights) {
        const int n = texture->size();
        double lo = texture->texel_height(0, 0), hi = lo;
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                lo = std::min(lo, texture->texel_height(k, j));
                hi = std::max(hi, texture->texel_height(k, j));
            }
        if (auto st =
                check_domain(material_layer(scene, i), heights->map, lo, hi, "the displacement's heights, min and max");
            !st)
            return st.error();
    }
    return layered_material<DisplacementDriver>(scene, i, config, options, std::move(provenance), std::move(heights),
                                                std::move(*texture));
}

Status refuse_noise_for_exact(const Scene& scene, std::size_t i)
{
    if (scene.surfaces[i].material.has_microsurface() || scene.surfaces[i].material.driver.kind != DriverKind::Noise)
        return ok();
    return bad_input(where(scene, i, "driver") + "exact needs a texture driver with at most " +
                     std::to_string(kHistogramMaxValues) +
                     " distinct values; noise drivers have no exact filtering distribution");
}

}  // namespace

Expected<std::vector<Material>> prepare_materials(const Scene& scene, const ColorConfig& config,
                                                  const MaterialOptions& options)
{
    std::vector<Material> materials;
    materials.reserve(scene.surfaces.size());
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        const MaterialSource& source = scene.surfaces[i].material;
        MaterialProvenance provenance;
        ColorLayer color;  // C0, or a microsurface's C_h
        if (source.has_colormap())
            if (auto st = load_colormap(material_layer(scene, i), config, options, color, provenance); !st)
                return st.error();
        if (options.histograms)
            if (auto st = refuse_noise_for_exact(scene, i); !st) return st.error();
        std::optional<ColorLayer> heights;
        if (source.has_microsurface() && source.has_colormap()) heights = std::move(color);
        auto material =
            !source.has_microsurface()
                ? load_driven_material(material_layer(scene, i), options, std::move(provenance), std::move(color))
            : source.microsurface
                ? load_microsurface_material(scene, i, config, options, std::move(provenance), std::move(heights))
                : load_displacement_material(scene, i, config, options, std::move(provenance), std::move(heights));
        if (!material) return material.error();
        Material& m = materials.emplace_back(std::move(*material));
        if (auto* texture = std::get_if<TextureDriver>(&m.driver); texture && options.histograms)
            if (auto st = load_histograms(scene, i, options, *texture, m.provenance); !st) return st.error();
        if (has_texture_driver(m) && !source.driver.segments_path.empty()) {
            if (auto st = open_segments(scene, i, m, source.driver.segments_path, nullptr); !st) return st.error();
        } else if (has_texture_driver(m) && options.segments) {
            if (auto st = bake_segments(scene, i, options, m); !st) return st.error();
        }
        if (source.has_microsurface() && !source.has_colormap()) continue;  // no table of its own
        TableChoiceOptions tables = options.tables;
        tables.threads = options.threads;
        if (auto st = choose_surface_table(scene, i, table_layer(m), tables); !st) return st.error();
    }
    return materials;
}

bool exact_filterable(const std::vector<Material>& materials)
{
    for (const Material& m : materials) {
        if (is_microsurface(m)) continue;  // a microsurface's <C_h, D_h> is exact without histograms (height_color.h)
        const auto* texture = std::get_if<TextureDriver>(&m.driver);
        if (!texture || !texture->texture.has_level0() ||
            texture->texture.distinct_values() > static_cast<std::size_t>(kHistogramMaxValues))
            return false;
    }
    return true;
}

Status prepare_surface_histograms(const Scene& scene, std::vector<Material>& materials, std::size_t i,
                                  const MaterialOptions& options)
{
    if (materials.size() != scene.surfaces.size() || i >= materials.size())
        return bad_input("histograms: " + std::to_string(materials.size()) + " materials for " +
                         std::to_string(scene.surfaces.size()) + " surfaces (surface " + std::to_string(i) + ")");
    auto* texture = std::get_if<TextureDriver>(&materials[i].driver);
    if ((texture && texture->histograms) || is_microsurface(materials[i])) return ok();
    if (auto st = refuse_noise_for_exact(scene, i); !st) return st;
    if (!texture) return ok();  // a noise driver on a surface the scene says is a texture's: nothing to bake from
    return load_histograms(scene, i, options, *texture, materials[i].provenance);
}

Status open_segments(const Scene& scene, std::size_t i, Material& m, const std::string& path,
                     std::shared_ptr<const TemporaryFile> file)
{
    const std::string prefix = segments_where(scene, i);
    auto* texture = std::get_if<TextureDriver>(&m.driver);
    if (!texture || is_microsurface(m))
        return bad_input(prefix + "a segment pyramid colours a texture driver, and surface " + std::to_string(i) +
                         " has none");
    auto pyramid = SegmentPyramidTexture::open(path);
    if (!pyramid) return located(pyramid.error(), prefix);
    const SegmentPyramidInfo& info = pyramid->info();
    const MomentPyramidInfo& moments = texture->texture.moments().info();
    // The same driver texels, read alike: its hash, channel, size and wrap.
    std::string differs;
    if (info.source_sha256 != moments.source_sha256)
        differs = "was baked from '" + info.source + "' (SHA-256 " + info.source_sha256.substr(0, 12) +
                  "), and the texture's driver is '" + moments.source + "' (SHA-256 " +
                  moments.source_sha256.substr(0, 12) + ")";
    else if (info.channel_index != moments.channel_index)
        differs = "holds driver channel " + info.channel + ", and the texture's is " + moments.channel;
    else if (info.width != moments.width || info.height != moments.height)
        differs = "is " + std::to_string(info.width) + " x " + std::to_string(info.height) + ", and the texture " +
                  std::to_string(moments.width) + " x " + std::to_string(moments.height);
    else if (info.wrap != moments.wrap)
        differs = std::string("was baked with wrap ") + to_string(info.wrap) + ", and the texture's wrap is " +
                  to_string(moments.wrap) + " (scene textures repeat: bake-moments --wrap periodic)";
    if (!differs.empty())
        return bad_input(prefix + "segment pyramid '" + path + "' " + differs + " (expected the texture's own driver)");
    const std::string map_name = m.provenance.map_path.empty() ? std::string("the material's map")
                                                               : "the material's map '" + m.provenance.map_path + "'";
    if (auto fit = check_segment_pyramid_map(info, path, m.color.map, map_name); !fit)
        return located(fit.error(), prefix);
    texture->segments.emplace(std::move(*pyramid));
    m.provenance.segments_file = std::move(file);
    return ok();
}

Status prepare_histograms(const Scene& scene, std::vector<Material>& materials, const MaterialOptions& options)
{
    if (materials.size() != scene.surfaces.size())
        return bad_input("histograms: " + std::to_string(materials.size()) + " materials for " +
                         std::to_string(scene.surfaces.size()) + " surfaces");
    for (std::size_t i = 0; i < materials.size(); ++i)
        if (auto st = prepare_surface_histograms(scene, materials, i, options); !st) return st;
    return ok();
}

Status prepare_moment_order(const Scene& scene, std::vector<Material>& materials, const MaterialOptions& options)
{
    if (materials.size() != scene.surfaces.size())
        return bad_input("moments: " + std::to_string(materials.size()) + " materials for " +
                         std::to_string(scene.surfaces.size()) + " surfaces");
    for (std::size_t i = 0; i < materials.size(); ++i) {
        auto* texture = std::get_if<TextureDriver>(&materials[i].driver);
        if (!texture || is_microsurface(materials[i]) || !materials[i].provenance.moments_baked ||
            scene.surfaces[i].material.driver.kind != DriverKind::Image ||
            texture->texture.moments().info().order == options.moment_order)
            continue;
        auto baked =
            load_image_driver(material_layer(scene, i), materials[i].color.map, options, materials[i].provenance);
        if (!baked) return baked.error();
        texture->texture = std::move(baked->texture);
    }
    return ok();
}

}  // namespace cmfilter
