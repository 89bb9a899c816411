// SPDX-License-Identifier: Apache-2.0
// Each surface's material (material.h), loaded once for `render`, one
// loader per driver kind: the colour map C0 (naive and supersampled methods
// evaluate it exactly), its Gaussian table T(mean, sigma) (eq. 10), and the
// driver. A map image is laid over its
// domain and its table baked in process (default options); a baked table
// brings C0 back from its own metadata (table_color_map.h). A noise driver
// uses its sigma table when the scene names one (the table must have been
// baked for the same noise) and bakes one otherwise (bake-noise's defaults;
// seconds per noise). A texture driver (filtered_texture.h) is a moment
// pyramid and its level-0 driver: a `moments` file brings the driver back
// from its cmfilter:source, which must still be the file it was baked from
// (SHA-256, as apply checks it); when that file is gone the pyramid alone
// serves naive and gaussian, and MaterialProvenance::missing_driver says so to
// the methods that need level 0 (render refuses supersample and reference,
// and the histograms of exact are refused here). An `image` is read once and
// its moment pyramid baked in process (bake-moments' defaults but periodic
// wrap: scene textures repeat) into a temporary file that lives as long as
// the material.
// A microsurface material (scene.h) gets its Gaussian microsurface or
// textured displacement, C_h in map and table when it has a height map, its
// slope map (a steepness gradient laid over degrees, or a slope-vector
// image), and its base layer: a Material of its own (C0 and its driver,
// loaded as above with the default table).
// For `render --method exact` (MaterialOptions::histograms) a texture driver
// also gets its histogram pyramid (histogram_pyramid.h), baked in process
// from the same level-0 driver with the same wrap into a temporary file of
// its own; a noise driver is refused (it has no exact filtering
// distribution), and so is a driver with more than kHistogramMaxValues
// distinct values (the histogram bake's own error).
// For `render --method segments` (MaterialOptions::segments) a texture
// driver gets its segment pyramid (segment_pyramid_file.h) for its map's
// breakpoints, baked in process from the same level-0 driver with the same
// wrap into a temporary file of its own, unless the scene names one
// (driver/segments), which is opened and checked against the driver and the
// map instead.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/scene/material.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/tables/table_fit.h"
#include "cmfilter/util/error.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cmfilter {

struct MaterialOptions {
    int threads = 0;
    // Called with a line of text before slow steps (a sigma-table or moment
    // pyramid bake).
    std::function<void(const std::string&)> note;
    // Bake each texture driver's histogram pyramid (render --method exact);
    // BadInput for a noise driver or a driver with too many distinct values.
    bool histograms = false;
    // Bake each texture driver's segment pyramid (render --method segments)
    // for the breakpoints of its map, unless the scene names one
    // (driver/segments, opened whatever this says): every breakpoint of the
    // map over the driver's range (segments_tolerance 0), or the fewest that
    // keep it within segments_tolerance (SegmentPyramidBakeOptions::tolerance_de).
    bool segments = false;
    double segments_tolerance = 0;
    // Moments per texel of the pyramids baked in process from driver
    // images: 2, or 4 for render --method mixture (MomentBakeOptions::order).
    int moment_order = 2;
    // Each surface's table: the fixed default, or fitted to a tolerance, and
    // the small-sigma shortcut (tolerance_tables.h). Its threads are these.
    TableChoiceOptions tables;
};

// One Material per scene surface, in order, its table chosen by
// choose_surface_table (a surface fitted to a tolerance skips the default bake). Errors name the surface's
// key (/surfaces/i/material/...) and the file: unreadable tables, maps,
// moment pyramids or driver images, a sigma table baked for another noise, a
// moments file whose recorded driver changed (BadInput), or is gone when
// histograms are asked for (Io), or
// a clamp colour map whose domain misses the driver's values entirely (noise:
// mean +- 3 sigma; texture: its min and max).
Expected<std::vector<Material>> prepare_materials(const Scene& scene, const ColorConfig& config,
                                                  const MaterialOptions& options);

// Whether `render --method exact` can filter these materials: every one has
// a texture driver with its level 0 and at most kHistogramMaxValues distinct
// values.
bool exact_filterable(const std::vector<Material>& materials);

// Bakes the histogram pyramid of every material that lacks one, as
// prepare_materials does with MaterialOptions::histograms (and with its
// errors), for materials prepared without.
Status prepare_histograms(const Scene& scene, std::vector<Material>& materials, const MaterialOptions& options);
// The same for surface `surface` alone.
Status prepare_surface_histograms(const Scene& scene, std::vector<Material>& materials, std::size_t surface,
                                  const MaterialOptions& options);

// Opens the segment pyramid at `path` as surface `surface`'s
// (TextureDriver::segments), as prepare_materials opens the scene's
// driver/segments: BadInput, naming the key and both files, when it was
// baked from another driver (SHA-256, channel, size or wrap) or the
// material's map does not fit its breakpoints (check_segment_pyramid_map),
// or the surface has no texture driver. `file`: the temporary file it lies
// in, kept with the material (null for a file of the user's).
Status open_segments(const Scene& scene, std::size_t surface, Material& material, const std::string& path,
                     std::shared_ptr<const TemporaryFile> file);

// Re-bakes, with MaterialOptions::moment_order moments, the pyramid of every
// surface's texture driver baked in process from a driver image with
// another order (materials prepared for one method, then rendered with
// mixture); a `moments` file is left as it is (the renderer names it when it
// holds too few) and so is a microsurface's base layer.
Status prepare_moment_order(const Scene& scene, std::vector<Material>& materials, const MaterialOptions& options);

}  // namespace cmfilter
