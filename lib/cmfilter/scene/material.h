// SPDX-License-Identifier: Apache-2.0
// What `render` needs of each surface's material, loaded once
// (scene_materials.h): its colour layer C0 with its Gaussian table
// (color_layer.h), the driver that colours it, and where all of it came from.
// The driver is one of a closed set:
//   NoiseDriver         a procedural noise and its sigma table
//                       (filtered_noise.h);
//   TextureDriver       a moment pyramid and its level-0 driver
//                       (filtered_texture.h), with its histogram pyramid
//                       for `render --method exact` and its segment
//                       pyramid for `render --method segments`;
//   MicrosurfaceDriver  a Gaussian microsurface whose heights and slopes
//                       colour it (sec. 5);
//   DisplacementDriver  a textured displacement in its place (scene.h).
// A microsurface material's colours are its driver's (microsurface_colors.h:
// C_h over its heights, C_s over its slopes, and how they combine), with a
// base layer: a material of its own (C0 over a noise or texture driver).
#pragma once

#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/microsurface/displacement_texture.h"
#include "cmfilter/microsurface/gaussian_microsurface.h"
#include "cmfilter/microsurface/microsurface_colors.h"
#include "cmfilter/noise/filtered_noise.h"
#include "cmfilter/tables/color_layer.h"
#include "cmfilter/texture/filtered_texture.h"
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/texture/segment_pyramid_texture.h"
#include "cmfilter/util/temporary_file.h"

#include <memory>
#include <optional>
#include <string>
#include <variant>

namespace cmfilter {

struct Material;

struct NoiseDriver {
    FilteredNoise noise;
};

struct TextureDriver {
    FilteredTexture texture;
    // With MaterialOptions::histograms: the histogram pyramid of the level-0
    // driver (its file: MaterialProvenance::histograms_file).
    std::optional<HistogramTexture> histograms;
    // The segment pyramid of the level-0 driver (render --method segments):
    // the scene's driver/segments, or baked here with
    // MaterialOptions::segments (its file: MaterialProvenance::segments_file).
    std::optional<SegmentPyramidTexture> segments;
};

// Heights and wavelengths in texture units (scene.h); height_scale scene
// units per texture unit (1 / the mapping's axis length).
struct MicrosurfaceDriver {
    GaussianMicrosurface surface;
    double height_scale = 1;
    MicrosurfaceColors colors;
    std::shared_ptr<const Material> base;  // C0 over a driver of its own (default table); null: none
};

// With the same units as MicrosurfaceDriver's.
struct DisplacementDriver {
    DisplacementTexture texture;
    double height_scale = 1;
    MicrosurfaceColors colors;
    std::shared_ptr<const Material> base;  // as MicrosurfaceDriver's
};

using MaterialDriver = std::variant<NoiseDriver, TextureDriver, MicrosurfaceDriver, DisplacementDriver>;

// Where a material's parts came from and what was made for it here.
struct MaterialProvenance {
    std::string map_path, table_path;  // its colour map (C0, or C_h); empty table_path: baked here
    // Where C0 came from, as a table file records it (a driver's colour map;
    // empty for a microsurface's).
    std::optional<ColorMapProvenance> map_source;
    std::string driver_path;     // texture: the level-0 driver image read (or recorded, when gone)
    std::string slope_map_path;  // microsurface: C_s's image
    // A moments driver whose recorded driver is gone (no level 0): the error
    // naming the surface, the driver and the moments file; empty otherwise.
    std::string missing_driver;
    bool sigma_table_baked = false;  // the noise's sigma table was baked here
    bool moments_baked = false;      // the texture's moment pyramid was baked here
    // The histogram pyramid's temporary file (TextureDriver::histograms).
    std::shared_ptr<const TemporaryFile> histograms_file;
    // The segment pyramid's temporary file when baked here (TextureDriver::segments).
    std::shared_ptr<const TemporaryFile> segments_file;
};

struct Material {
    // Declared first: its temporary files are removed after the textures
    // that read them close.
    MaterialProvenance provenance;
    // C0 over a noise's or a texture's values; a microsurface's colours are
    // its driver's (this stays empty).
    ColorLayer color;
    MaterialDriver driver;
};

// A microsurface material (Gaussian or displaced): coloured by its layers.
inline bool is_microsurface(const Material& m)
{
    return std::holds_alternative<MicrosurfaceDriver>(m.driver) || std::holds_alternative<DisplacementDriver>(m.driver);
}

// A material coloured through a texture driver (a moment pyramid).
inline bool has_texture_driver(const Material& m) { return std::holds_alternative<TextureDriver>(m.driver); }

// A material coloured through a procedural noise driver.
inline bool has_noise_driver(const Material& m) { return std::holds_alternative<NoiseDriver>(m.driver); }

// The microsurface's colours, or null for a noise or texture driver.
inline const MicrosurfaceColors* microsurface_colors(const Material& m)
{
    if (const auto* d = std::get_if<MicrosurfaceDriver>(&m.driver)) return &d->colors;
    if (const auto* d = std::get_if<DisplacementDriver>(&m.driver)) return &d->colors;
    return nullptr;
}

inline MicrosurfaceColors* microsurface_colors(Material& m)
{
    if (auto* d = std::get_if<MicrosurfaceDriver>(&m.driver)) return &d->colors;
    if (auto* d = std::get_if<DisplacementDriver>(&m.driver)) return &d->colors;
    return nullptr;
}

// The layer a surface's table belongs to (tolerance_tables.h): C0 over a
// driver, or C_h over a microsurface's heights; a microsurface without a
// height map has none and gives the material's own, empty, layer.
inline const ColorLayer& table_layer(const Material& m)
{
    const MicrosurfaceColors* colors = microsurface_colors(m);
    return colors && colors->height ? *colors->height : m.color;
}

inline ColorLayer& table_layer(Material& m)
{
    MicrosurfaceColors* colors = microsurface_colors(m);
    return colors && colors->height ? *colors->height : m.color;
}

}  // namespace cmfilter
