// SPDX-License-Identifier: Apache-2.0
// Noise sigma tables (noise/noise_sigma_table_file.h) from arbitrary headers,
// both footprint columns.
#include "support/fuzz_checks.h"
#include "support/scratch_file.h"

#include "cmfilter/noise/noise_sigma_table_file.h"
#include "cmfilter/ops/artefact_info.h"

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string path = fuzz::write_scratch_file("noise-table.cmfuzz", data, size);
    for (FootprintShape shape : {FootprintShape::Box, FootprintShape::Gaussian}) {
        if (auto t = read_noise_sigma_table(path, shape)) {
            fuzz::require_finite(t->table.sigmas(), "noise sigmas are finite");
            for (double lod : {-3.0, 0.0, 2.5, 40.0})
                fuzz::require(std::isfinite(t->table.sigma_at(lod)), "sigma_at is finite at any LOD");
        }
    }
    (void)read_artefact_info(path);
    return 0;
}
