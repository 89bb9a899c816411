// SPDX-License-Identifier: Apache-2.0
// The segment pyramid (`--method segments`): the exact filtered colour of a
// driver through any colour map with given breakpoints, recoloured after the
// bake. Channel k (k = 1..K) of level 0 holds the ramp r_k(f) of the
// breakpoints t_0 < ... < t_K (colormap/map_breakpoints.h) per driver texel,
// and level j its box mean over the footprints of a moment pyramid's level j
// (box_pyramid.h), so that mean C(f) = C(t_0) + sum_k (C(t_k) - C(t_{k-1}))
// R_k for every map C linear between the t_k: the box mean of C(f) that the
// paper's filtering aims at (sec. 3, eq. 1 with a box kernel), without the
// colours baked in.
//
// The breakpoints are those of one or several maps over the driver's range,
// all of them (exact), or the fewest that keep every map within a CIEDE2000
// tolerance of C0: then the colours weighed by the ramp means are each map's
// least-squares colours over the driver's values (breakpoint_colors.h, from
// weights the file records) and the breakpoints may lie between the maps'
// knots. The file is a tiled, mip-mapped OpenEXR of K channels
// s001 .. sK (float32 or half: 4 K or 2 K bytes per level-0 texel) whose
// cmfilter:* metadata record the breakpoints, the tolerance and the driver;
// a map is accepted by its fit through the breakpoints, not its colours.
#pragma once

#include "cmfilter/colormap/color_map.h"
#include "cmfilter/colormap/map_breakpoints.h"
#include "cmfilter/io/driver_image.h"
#include "cmfilter/io/method_tolerance_record.h"
#include "cmfilter/texture/pyramid_bake_options.h"
#include "cmfilter/util/error.h"

#include <OpenImageIO/imageio.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cmfilter {

inline constexpr const char* kSegmentPyramidKind = "segment-pyramid";
// Version 2 adds the least-squares colours' driver weights (version 1 files,
// without, read as interpolated colours).
inline constexpr int kSegmentPyramidFormatVersion = 2;
inline constexpr int kSegmentPyramidMaxChannels = 999;  // channel names s001 .. s999

struct SegmentPyramidInfo {
    int width = 0, height = 0;  // level 0 = the driver's size
    int levels = 0;             // down to 1 x 1
    ExrPixelType pixel_type = ExrPixelType::Float;
    std::string channel;  // the driver channel used (name, else its index)
    int channel_index = 0;
    TextureWrap wrap = TextureWrap::Clamp;
    double driver_min = 0, driver_max = 0;
    std::string source;  // driver path as given
    std::string source_sha256;
    std::size_t nonfinite_replaced = 0;
    std::vector<double> breakpoints;  // t_0 < ... < t_K
    double tolerance_de = 0;          // what they were chosen for (0: every exact breakpoint)
    double fit_de = 0;                // the largest CIEDE2000 anywhere of a baked map through them
    double mean_fit_de = 0;           // the largest mean CIEDE2000 over the driver's texels of a baked map
    // With a tolerance: the largest mean CIEDE2000 of a baked map's level 1..8
    // box means against C0's (what apply measures against the reference).
    double filtered_fit_de = 0;
    std::vector<std::string> map_sources;  // the maps they were chosen for, for messages
    // Non-empty with a tolerance: the colours through the breakpoints are the
    // least-squares fit of the map over these driver weights
    // (breakpoint_colors.h), for every map applied; empty: the map's own C(t_k).
    DriverWeights color_weights;
    const DriverWeights* weights() const { return color_weights.empty() ? nullptr : &color_weights; }
    std::string baked_by;  // cmfilter version (filled in on read)
    // Set when bake-moments --tolerance chose this representation.
    std::optional<MethodToleranceRecord> method_choice;

    int channels() const { return static_cast<int>(breakpoints.size()) - 1; }
    std::size_t bytes_per_texel() const
    {
        return static_cast<std::size_t>(channels()) * (pixel_type == ExrPixelType::Half ? 2 : 4);
    }
};

// The cmfilter:* attributes (and "wrapmodes"), paths recorded relative to
// `path`. Reading gives BadInput naming `path` when the file is not a segment
// pyramid or its metadata is inconsistent.
void set_segment_pyramid_metadata(OIIO::ImageSpec& spec, const SegmentPyramidInfo& info, const std::string& path);
Expected<SegmentPyramidInfo> get_segment_pyramid_metadata(const OIIO::ImageSpec& spec, const std::string& path);

struct SegmentPyramidBakeOptions : PyramidBakeOptions {
    std::vector<const ColorMap*> maps;     // whose breakpoints to hold (at least one)
    std::vector<std::string> map_sources;  // where each came from, recorded for messages
    // BreakpointSelectionOptions::tolerance_de, then checked at levels 1..8
    // (box means against C0's) and chosen again smaller until each is within.
    double tolerance_de = 0;
    int max_channels = 0;                                // 0: no limit (up to kSegmentPyramidMaxChannels)
    std::optional<MethodToleranceRecord> method_choice;  // recorded as the cmfilter:method_* metadata
    std::function<void(double fraction)> progress;       // optional, from the calling thread
};

struct SegmentPyramidBakeResult {
    SegmentPyramidInfo info;
    BreakpointSelection selection;
    double filtered_fit_de = 0;  // SegmentPyramidInfo::filtered_fit_de
    double read_ms = 0, select_ms = 0, build_ms = 0, write_ms = 0;
};

// BadInput for missing or invalid maps (naming SegmentPyramidBakeOptions::maps),
// for breakpoints past max_channels + 1 (naming the tolerance that meets it,
// the closest), and the errors of reading the driver and writing the file.
// All or nothing.
Expected<SegmentPyramidBakeResult> bake_segment_pyramid(const SegmentPyramidBakeOptions& options);
Expected<SegmentPyramidBakeResult> bake_segment_pyramid(const SegmentPyramidBakeOptions& options,
                                                        const HashedDriver& driver);

// How `map` fits `info`'s breakpoints over the driver's range: accepted when
// its largest CIEDE2000 from its curve through them (info.weights()) is within that of the maps the
// pyramid was baked for (fit_de, plus 1e-3 for rounding: 0 for a map on the
// same breakpoints with any colours); else BadInput
// naming the pyramid, `map_name`, the error and where, and the breakpoints the
// map has that the pyramid lacks.
Expected<BreakpointFit> check_segment_pyramid_map(const SegmentPyramidInfo& info, const std::string& pyramid_path,
                                                  const ColorMap& map, const std::string& map_name);

// For a pyramid of least-squares colours (a tolerance bake), a map that
// check_segment_pyramid_map took but that fits the breakpoints worse on
// average over the driver's recorded values (fit.mean_de) than the maps it
// was baked for (info.mean_fit_de, plus 1e-3): a warning naming `map_name`,
// both means and what the tolerance kept, since the filtered error can then
// exceed it; else nothing.
std::optional<std::string> segment_recolour_warning(const SegmentPyramidInfo& info, const std::string& pyramid_path,
                                                    const BreakpointFit& fit, const std::string& map_name);

}  // namespace cmfilter
