// SPDX-License-Identifier: Apache-2.0
// The on-disk form of a baked noise sigma table (docs/bake-noise.md): a
// one-row float32 OpenEXR, width = number of LODs (column k at
// LOD lod_first + k lod_step), channels box_sigma, gaussian_sigma,
// box_ci, gaussian_ci (the 95% confidence half-widths), with the noise spec,
// the LOD grid, the Monte-Carlo counts and the global statistics as
// cmfilter:* metadata (cmfilter:kind = noise-sigma-table). Written atomically.
// Also a CSV export of the same rows.
#pragma once

#include "cmfilter/io/exr_output_options.h"
#include "cmfilter/util/error.h"
#include "cmfilter/noise/noise_sigma_bake.h"
#include "cmfilter/noise/noise_sigma_table.h"

#include <string>

namespace cmfilter {

inline constexpr const char* kNoiseSigmaTableKind = "noise-sigma-table";

// `noise_spec` is the spec's text form (noise_spec.h); `base_period` the
// noise's p_0, recorded so a reader can turn widths into LODs.
// `storage`: pixel type, tiles and compression (default float, scanlines, zip).
Status write_noise_sigma_table(const std::string& path, const NoiseSigmaBake& bake, const std::string& noise_spec,
                               double base_period, const ExrOutputOptions& storage = {});

// Header "lod,width,box_sigma,box_ci,box_footprints,box_samples,gaussian_sigma,
// gaussian_ci,gaussian_footprints,gaussian_samples", one row per LOD,
// numbers in shortest round-trip form. Written atomically.
Status write_noise_sigma_csv(const std::string& path, const NoiseSigmaBake& bake, double base_period);

struct LoadedNoiseSigmaTable {
    NoiseSigmaTable table;
    std::string noise_spec;
    double base_period = 1;
};

// The column of `shape`; BadInput when the file is not a noise sigma table or
// its metadata disagrees with its pixels.
Expected<LoadedNoiseSigmaTable> read_noise_sigma_table(const std::string& path, FootprintShape shape);

}  // namespace cmfilter
