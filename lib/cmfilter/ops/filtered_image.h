// SPDX-License-Identifier: Apache-2.0
// The filtered colour image of a colour-mapped driver at one level of detail
// (the `apply` command): per output pixel, the colour of the driver's
// footprint at texture coordinates (s, t) = ((x + 0.5) / width, (y + 0.5) /
// height) and level of detail lod, by one of five methods (the names hold
// across cmfilter, see docs/apply.md):
//   naive      C0(mean f): filter the driver, then map (what the paper fixes)
//   gaussian   T(mean f, sigma_f), the prefiltered table of eq. 10, with mean
//              and sigma from the moment pyramid (sec. 4.2)
//   mixture    p T(a, s) + (1 - p) T(b, s), the two-Gaussian mixture of the
//              footprint's first four moments (an order-4 moment pyramid,
//              math/moment_mixture.h), two lookups of the same table
//   exact      sum_b h_b C0(v_b), the footprint's histogram of a driver with
//              few distinct values against the map (sec. 4.1, exact solutions)
//   reference  the box mean of C0(f) over the same footprint, from level 0
//              (color_pyramid.h): the ground truth for a box filter
//   color-pyramid  the same box mean baked for one map (color_pyramid_file.h):
//              ApplyOptions::moments_path names the colour pyramid, and the
//              table's map must be the one it was baked through
//   segments   the same box mean for any map on baked breakpoints
//              (segment_pyramid_file.h): ApplyOptions::moments_path names the
//              segment pyramid, and the table's map must fit its breakpoints
// Every method reads its footprint with the same (s, t, lod) conventions as
// MomentTexture::lookup, so the methods compare like with like.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/util/error.h"
#include "cmfilter/tables/gaussian_color_table.h"
#include "cmfilter/texture/moment_pyramid_info.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cmfilter {

enum class FilterMethod { Naive, Gaussian, Exact, Reference, Mixture, ColorPyramid, Segments };

// "naive", "gaussian", "exact", "reference", "mixture", "color-pyramid", "segments".
const char* to_string(FilterMethod method);
Expected<FilterMethod> parse_filter_method(const std::string& name);

struct ApplyOptions {
    std::string moments_path;  // moment pyramid (bake-moments); color-pyramid, segments: that pyramid
    std::string table_path;    // Gaussian colour table (bake-colormap)
    double lod = 0;            // clamped to [0, top reachable level], with a warning
    FilterMethod method = FilterMethod::Gaussian;
    int width = 0, height = 0;                      // output size; 0 x 0: the size of level floor(lod)
    std::string map_path;                           // naive/exact/reference: overrides the table's cmfilter:source
    std::string driver_path;                        // reference: overrides the moments' cmfilter:source
    std::string histograms_path;                    // exact: the histogram pyramid (required)
    int threads = 0;                                // 0: all cores
    std::function<void(double fraction)> progress;  // optional, from the calling thread
};

struct FilteredImage {
    int width = 0, height = 0;
    std::vector<float> rgb;  // width * height * 3, scene-linear, top row first
    FilterMethod method = FilterMethod::Gaussian;
    std::string linear_space;  // the colour space of rgb (the config's scene_linear)
    double lod_requested = 0;
    double lod = 0;  // after clamping
    bool lod_clamped = false;
    int top_level = 0;  // the highest level of detail lookups can reach

    MomentPyramidInfo moments;  // what the moment pyramid says about itself
    std::string moments_path, table_path;
    std::string map_path;         // the colour map file used (naive, exact, reference)
    std::string driver_path;      // the driver read (reference)
    std::string histograms_path;  // exact
    // segments: the largest CIEDE2000 of the table's map against its
    // interpolant through the pyramid's breakpoints (0 when it fits exactly).
    double segment_fit_de = 0;
    // segments from a tolerance bake (least-squares colours): its mean
    // CIEDE2000 over the driver's recorded values (BreakpointFit::mean_de);
    // else 0.
    double segment_mean_fit_de = 0;

    // gaussian: table lookups outside its range (LookupCounters).
    LookupCounters table_counters;
    std::size_t failed_lookups = 0;  // texture lookups that failed (read as black)
    // Level-0 driver texels outside the table's domain [vmin, vmax] (from the
    // moments, c + m1), and their fraction.
    std::size_t texels_outside_domain = 0;
    double fraction_outside_domain = 0;

    std::vector<std::string> warnings;  // for the caller to report

    // Set by a caller that chose `method` for a tolerance (method_choice.h):
    // written as the cmfilter:method_* metadata (io/method_tolerance_record.h).
    std::optional<MethodToleranceRecord> method_choice;
};

// Io when an input cannot be read (a missing colour map or driver recorded in
// a file says to set TableColorMapOptions::map_override or
// ApplyOptions::driver_path), BadInput when a file is not what it
// should be, when the table's domain and the driver's range do not overlap
// (clamp maps), or when an option is out of range.
Expected<FilteredImage> apply_filter(const ApplyOptions& options, const ColorConfig& config);

}  // namespace cmfilter
