// What `render` needs of each surface's material, loaded once: the colour map
// C0 (naive and supersampled methods evaluate it exactly), its Gaussian table
// T(mean, sigma) (eq. 10), and the driver. A map image is laid over its
// domain and its table baked in process (default options); a baked table
// brings C0 back from its own metadata (table_color_map.h). A noise driver
// uses its sigma table when the scene names one (the table must have been
// baked for the same noise) and bakes one otherwise (bake-noise's defaults;
// seconds per noise).
#pragma once

#include "cmfilter/color_config.h"
#include "cmfilter/color_map.h"
#include "cmfilter/error.h"
#include "cmfilter/filtered_noise.h"
#include "cmfilter/gaussian_color_table.h"
#include "cmfilter/scene.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cmfilter {

struct SurfaceMaterial {
    ColorMap map;                       // C0, scene-linear
    GaussianColorTable table;           // T(mean, sigma)
    std::optional<FilteredNoise> noise; // the procedural driver
    std::string map_path, table_path;   // provenance (empty table_path: baked here)
    bool sigma_table_baked = false;     // the noise's sigma table was baked here
};

struct MaterialOptions {
    int threads = 0;
    // Called with a line of text before slow steps (a sigma-table bake).
    std::function<void(const std::string&)> note;
};

// One SurfaceMaterial per scene surface, in order. BadInput names the surface
// (/surfaces/i) and the file: unreadable tables or maps, a sigma table baked
// for another noise, a texture driver (not supported yet), or a colour map
// whose domain misses the driver's values entirely.
Expected<std::vector<SurfaceMaterial>> prepare_materials(const Scene& scene, const ColorConfig& config,
                                                         const MaterialOptions& options);

}  // namespace cmfilter
