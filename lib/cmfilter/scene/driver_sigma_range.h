// SPDX-License-Identifier: Apache-2.0
// The largest footprint sigma a colour table will be looked up with for a
// driver (bake-colormap --for): the sigma_max a table needs so that none of
// that driver's lookups clamps (GaussianColorTable::lookup holds sigma above
// sigma_max at sigma_max). From
//   a noise sigma table (bake-noise): its largest box sigma, the column the
//       renderer reads. sigma_at interpolates between nodes and holds the end
//       nodes beyond them, so no lookup exceeds it;
//   a moment pyramid (bake-moments): the largest sqrt(max(0, m2 - m1^2)) over
//       every texel of every level TextureSystem can reach (level 0 included),
//       i.e. the largest box-footprint sigma the file stores. A lookup between
//       texels blends the moments of neighbouring footprints and can exceed
//       it slightly (by the spread of their means);
//   a driver image (in a scene): the same over the aligned 2^k x 2^k block
//       moments of the image (the last odd row or column of a level dropped),
//       and the whole image;
//   a scene (.json): the largest over the surfaces whose colour map is
//       `map_path` (the same file), or over every surface when none is: a
//       noise driver's sigma table as above, or, without one, the noise's
//       global sigma (its standard deviation over the plane: what the
//       largest footprints approach), taken at the upper end of its 95%
//       confidence interval (measure_global_stats with bake-noise's defaults);
//       a microsurface's sigma_h (its height filtering distribution, eqs.
//       15-18, is never wider).
#pragma once

#include "cmfilter/util/error.h"
#include "cmfilter/scene/scene.h"

#include <cstddef>
#include <string>

namespace cmfilter {

struct DriverSigmaRange {
    double sigma_max = 0;  // the largest sigma
    std::string kind;      // "noise-sigma-table", "moment-pyramid", "scene"
    std::string how;       // one line: where sigma_max came from
};

struct DriverSigmaOptions {
    std::string map_path;  // the colour map image being baked (selects a scene's surfaces)
    int threads = 0;       // 0: all cores
};

// By the file: a name ending in .json is a scene, anything else must be a
// noise sigma table or a moment pyramid. Io when the file cannot be read;
// BadInput when it is another kind of file (the message names the kind
// found and the kinds expected) or holds no positive sigma.
Expected<DriverSigmaRange> largest_driver_sigma(const std::string& path, const DriverSigmaOptions& options);

// The parts, for callers that know what they hold.
Expected<DriverSigmaRange> largest_noise_table_sigma(const std::string& path);
Expected<DriverSigmaRange> largest_moment_pyramid_sigma(const std::string& path);
Expected<DriverSigmaRange> largest_driver_image_sigma(const std::string& path, int threads);
Expected<DriverSigmaRange> largest_scene_sigma(const Scene& scene, const DriverSigmaOptions& options);
// One surface's driver, as for a scene (messages name /surfaces/i/material/driver);
// BadInput for a surface index out of range.
Expected<DriverSigmaRange> largest_surface_sigma(const Scene& scene, std::size_t surface, int threads);

}  // namespace cmfilter
