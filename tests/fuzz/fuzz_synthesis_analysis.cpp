// SPDX-License-Identifier: Apache-2.0
// Synthesis analyses (synthesis/analysis_file.h) from arbitrary multi-part
// headers.
#include "support/fuzz_checks.h"
#include "support/scratch_file.h"

#include "cmfilter/ops/artefact_info.h"
#include "cmfilter/synthesis/analysis_file.h"

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string path = fuzz::write_scratch_file("analysis.cmfuzz", data, size);
    if (auto analysis = read_analysis_exr(path)) {
        fuzz::require(!analysis->levels.empty(), "an analysis has a level");
        for (const LevelAnalysis& level : analysis->levels) fuzz::require_finite(level.dot, "dot products are finite");
    }
    (void)read_artefact_info(path);
    return 0;
}
