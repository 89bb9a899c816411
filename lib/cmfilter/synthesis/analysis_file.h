// SPDX-License-Identifier: Apache-2.0
// A sample analysis (sample_analysis.h) as an OpenEXR file, so that many
// syntheses reuse it (docs/synthesis.md#analysis-files): cmfilter:kind
// "synthesis-analysis", cmfilter:format_version 1, the sample's path, kind,
// hash (cmfilter:sample_hash), image counts, channels, periodicity and the
// neighbourhood; per level two subimages: "level-L-texels" (width x height,
// channels "texton", "c0" .. "c{m-1}" holding texel indices as exact
// floats) and "level-L-dot" (textons x textons, channel "M"). The file's
// metadata (also cmfilter:levels and cmfilter:seconds) is on subimage 0;
// each texels subimage holds cmfilter:textons, cmfilter:candidates and
// cmfilter:inertia. Every part shares level 0's display window (OpenEXR
// multi-part files require one).
#pragma once

#include "cmfilter/synthesis/sample_analysis.h"
#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

inline constexpr const char* kSynthesisAnalysisKind = "synthesis-analysis";

// Io when the file cannot be written; nothing left behind on failure.
Status write_analysis_exr(const std::string& path, const SampleAnalysis& analysis);

// Io: missing or unreadable. BadInput naming the file: not an analysis, an
// unknown version, a texton or texel index out of range, non-integral
// indices, non-finite or non-symmetric dot products, inconsistent sizes.
Expected<SampleAnalysis> read_analysis_exr(const std::string& path);

// BadInput naming both files and both hashes when the analysis was made
// from another sample; naming both sizes when it describes another size,
// count of images used or channels.
Status check_analysis_matches(const SampleAnalysis& analysis, const std::string& analysis_path,
                              const SynthesisSample& sample);

}  // namespace cmfilter
