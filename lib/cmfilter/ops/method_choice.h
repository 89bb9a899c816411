// SPDX-License-Identifier: Apache-2.0
// The cheapest filtering method that meets a colour-difference tolerance for
// one colour-mapped texture (a material: a driver's pyramids and a colour
// table), by measurement (docs/apply.md, "Choosing a method for a
// tolerance"). Every candidate the inputs allow is run as `apply` runs it
// (filtered_image.h) at each measured level of detail, with output pixels one
// to one with that level's texels, and compared with the box reference of the
// same footprints (FilterMethod::Reference, the box mean of C0(f) from level
// 0): the error of a method at a LOD is the mean CIEDE2000 over those pixels,
// and its error overall the worst of them. The candidates, cheapest first:
//   naive     mean f alone (one float32 channel: 4 bytes per texel)
//   gaussian  mean f, mean f^2 (8 bytes) and one table lookup
//   color-pyramid  the box means of C0(f) baked for this map (12 bytes in
//             float32, 6 in half, color_pyramid_file.h), one RGB lookup and
//             no table; exact up to its storage, but tied to the map
//   segments  the ramp means of the map's breakpoints (4 K bytes in float32,
//             2 K in half, for K + 1 breakpoints, segment_pyramid_file.h), K
//             channels and no table; any map on those breakpoints
//   mixture   four moments (16 bytes, bake-moments --order 4), two lookups
//   exact     the histogram pyramid, one float32 weight per distinct value
//             (4 B bytes for B values) and no table
// ordered by bytes per texel, then in that order. The choice is the first
// that meets the tolerance; none when nothing does (the caller says so).
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/ops/filtered_image.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cmfilter {

struct MethodChoiceOptions {
    double tolerance = 1.0;  // mean CIEDE2000 at every measured LOD; finite and > 0
    // The levels of detail measured; empty: every integer LOD from 1 to
    // min(8, the top reachable level) (0 alone for a one-level pyramid).
    // Each finite and >= 0; LODs above the top level are dropped.
    std::vector<double> lods;
    // The methods tried; empty: every one the inputs allow (naive,
    // gaussian, color-pyramid with color_pyramid_path, segments with
    // segment_pyramid_path, mixture when the
    // moments are of order 4, exact when ApplyOptions::histograms_path is
    // set). Reference is not a candidate.
    std::vector<FilterMethod> candidates;
    // A colour pyramid of the same driver through the table's map
    // (color_pyramid_file.h): the candidate color-pyramid, measured as
    // apply reads it; empty: not a candidate (said in MethodChoice::skipped).
    std::string color_pyramid_path;
    // A segment pyramid of the same driver whose breakpoints the table's map
    // fits (segment_pyramid_file.h): the candidate segments; empty: not one.
    std::string segment_pyramid_path;
    // Optional: the fraction of the LODs measured, from the calling thread.
    std::function<void(double fraction)> progress;
};

// One candidate, measured.
struct MethodTrial {
    FilterMethod method = FilterMethod::Gaussian;
    std::size_t bytes_per_texel = 0;  // level 0 of what the method reads (the pyramid adds a third)
    int table_lookups = 0;            // per pixel (gaussian 1, mixture 2)
    std::vector<double> errors;       // mean CIEDE2000 per measured LOD
    double worst = 0;                 // the largest of them
    double worst_lod = 0;             // where
    double time_ms = 0;               // apply_filter at every measured LOD
    bool meets = false;               // worst <= tolerance
};

struct MethodChoice {
    double tolerance = 0;
    std::vector<double> lods;           // as measured
    std::vector<MethodTrial> trials;    // cheapest first
    std::vector<std::string> skipped;   // candidates the inputs do not allow, and why
    std::optional<std::size_t> chosen;  // index into trials: the cheapest that meets; none when none does
    double reference_ms = 0;            // the box reference at every measured LOD

    const MethodTrial* choice() const { return chosen ? &trials[*chosen] : nullptr; }
    // The trial with the lowest worst error (the closest a method came).
    const MethodTrial* best() const;
};

// "1, 2, 3" style text of a LOD list, for messages and metadata.
std::string lod_list_text(const std::vector<double>& lods);

// `base` names the inputs (moments, table, histograms, map and driver
// overrides, threads); its method, lod and size are ignored. BadInput for a
// tolerance, LOD or candidate out of range (naming the field), and the
// errors of apply_filter (a reference needs the driver the moments were
// baked from).
Expected<MethodChoice> choose_filter_method(const ApplyOptions& base, const ColorConfig& config,
                                            const MethodChoiceOptions& options);

// BadInput saying that nothing met the tolerance: the tolerance, the closest
// method and its worst error and LOD, and what a better candidate would need
// (order-4 moments, a histogram pyramid) when it was not tried. `subject`
// names the material (a file, a surface).
Error no_method_meets(const MethodChoice& choice, const std::string& subject);

}  // namespace cmfilter
