// What `render` needs of each surface's material, loaded once: the colour map
// C0 (naive and supersampled methods evaluate it exactly), its Gaussian table
// T(mean, sigma) (eq. 10), and the driver. A map image is laid over its
// domain and its table baked in process (default options); a baked table
// brings C0 back from its own metadata (table_color_map.h). A noise driver
// uses its sigma table when the scene names one (the table must have been
// baked for the same noise) and bakes one otherwise (bake-noise's defaults;
// seconds per noise). A texture driver (filtered_texture.h) is a moment
// pyramid and its level-0 driver: a `moments` file brings the driver back
// from its cmfilter:source, which must still be the file it was baked from
// (SHA-256, as apply checks it); when that file is gone the pyramid alone
// serves naive and gaussian, and SurfaceMaterial::missing_driver says so to
// the methods that need level 0 (render refuses supersample and reference,
// and the histograms of exact are refused here). An `image` is read once and
// its moment pyramid baked in process (bake-moments' defaults but periodic
// wrap: scene textures repeat) into a temporary file that lives as long as
// the material.
// A microsurface material (scene.h) gets its Gaussian microsurface or
// textured displacement, C_h in map and table when it has a height map, its
// slope map (a steepness gradient laid over degrees, or a slope-vector
// image), and its base layer: a SurfaceMaterial of its own (C0 and its
// driver, loaded as above with the default table).
// For `render --method exact` (MaterialOptions::histograms) a texture driver
// also gets its histogram pyramid (histogram_pyramid.h), baked in process
// from the same level-0 driver with the same wrap into a temporary file of
// its own; a noise driver is refused (it has no exact filtering
// distribution), and so is a driver with more than kHistogramMaxValues
// distinct values (the histogram bake's own error).
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/colormap/color_map.h"
#include "cmfilter/microsurface/displacement_texture.h"
#include "cmfilter/util/error.h"
#include "cmfilter/noise/filtered_noise.h"
#include "cmfilter/texture/filtered_texture.h"
#include "cmfilter/tables/gaussian_color_table.h"
#include "cmfilter/microsurface/gaussian_microsurface.h"
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/tables/plain_lookup.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/colormap/slope_color_map.h"
#include "cmfilter/tables/table_fit.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace cmfilter {

// A microsurface material's slope colour map C_s (sec. 5.2).
using SlopeMap = std::variant<SteepnessColorMap, SlopeVectorColorMap>;

struct SurfaceMaterial {
    // C0 over the driver, scene-linear; with a microsurface C_h over its
    // heights (height_map), or unused (no height map).
    ColorMap map;
    GaussianColorTable table;           // T(mean, sigma)
    // The small-sigma shortcut (plain_lookup.h): the gaussian method takes
    // C0(mean) itself where sigma < plain.below(mean); empty: never.
    PlainLookupSigma plain;
    TableFit fit;                       // how the table was chosen (tolerance_tables.h)
    std::optional<FilteredNoise> noise;     // a procedural driver, or
    std::optional<FilteredTexture> texture; // a texture driver, or
    // a microsurface whose heights drive the map (sec. 5.1): exactly one is
    // set. Heights and wavelengths in texture units; height_scale scene units
    // per texture unit (1 / the mapping's axis length).
    std::optional<GaussianMicrosurface> microsurface;
    // or a textured displacement in its place (scene.h), with the same units.
    std::optional<DisplacementTexture> displacement;
    double height_scale = 1;
    // A microsurface material's layers (scene.h): whether map is C_h, the
    // slope map C_s, the base layer (C0 and its driver: a plain material of
    // its own, default table), and how they combine (sec. 6).
    bool height_map = false;
    std::optional<SlopeMap> slope_map;
    std::shared_ptr<const SurfaceMaterial> base;
    ColorCombination combine;
    std::string slope_map_path;

    // A microsurface material (Gaussian or displaced): coloured by its layers.
    bool layered() const { return microsurface || displacement; }
    std::string map_path, table_path;   // provenance (empty table_path: baked here)
    std::string driver_path;            // texture: the level-0 driver image read (or recorded, when gone)
    // A moments driver whose recorded driver is gone (no level 0): the error
    // naming the surface, the driver and the moments file; empty otherwise.
    std::string missing_driver;
    bool sigma_table_baked = false;     // the noise's sigma table was baked here
    bool moments_baked = false;         // the texture's moment pyramid was baked here
    // Texture drivers with MaterialOptions::histograms: the histogram pyramid
    // of the level-0 driver and its temporary file (declared first: removed
    // after the TextureSystem closes it).
    std::shared_ptr<const TemporaryFile> histograms_file;
    std::optional<HistogramTexture> histograms;
};

struct MaterialOptions {
    int threads = 0;
    // Called with a line of text before slow steps (a sigma-table or moment
    // pyramid bake).
    std::function<void(const std::string&)> note;
    // Bake each texture driver's histogram pyramid (render --method exact);
    // BadInput for a noise driver or a driver with too many distinct values.
    bool histograms = false;
    // Each surface's table: the fixed default, or fitted to a tolerance, and
    // the small-sigma shortcut (tolerance_tables.h). Its threads are these.
    TableChoiceOptions tables;
};

// One SurfaceMaterial per scene surface, in order, its table chosen by
// choose_surface_table (a surface fitted to a tolerance skips the default bake). Errors name the surface's
// key (/surfaces/i/material/...) and the file: unreadable tables, maps,
// moment pyramids or driver images, a sigma table baked for another noise, a
// moments file whose recorded driver changed (BadInput), or is gone when
// histograms are asked for (Io), or
// a clamp colour map whose domain misses the driver's values entirely (noise:
// mean +- 3 sigma; texture: its min and max).
Expected<std::vector<SurfaceMaterial>> prepare_materials(const Scene& scene, const ColorConfig& config,
                                                         const MaterialOptions& options);

// Whether `render --method exact` can filter these materials: every one has
// a texture driver with its level 0 and at most kHistogramMaxValues distinct
// values.
bool exact_filterable(const std::vector<SurfaceMaterial>& materials);

// Bakes the histogram pyramid of every material that lacks one, as
// prepare_materials does with MaterialOptions::histograms (and with its
// errors), for materials prepared without.
Status prepare_histograms(const Scene& scene, std::vector<SurfaceMaterial>& materials,
                          const MaterialOptions& options);

}  // namespace cmfilter
