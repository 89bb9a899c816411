// SPDX-License-Identifier: Apache-2.0
// PTM / HSH fits in EXR (stack/fit_file.h) from arbitrary headers.
#include "support/fuzz_checks.h"
#include "support/scratch_file.h"

#include "cmfilter/ops/artefact_info.h"
#include "cmfilter/stack/fit_file.h"

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string path = fuzz::write_scratch_file("fit.cmfuzz", data, size);
    if (auto fit = read_fit_exr(path)) {
        fuzz::require(fit->coefficients.size() == fit->texels() * std::size_t(fit->stride()),
                      "a fit holds stride() coefficients per texel");
        fuzz::require_finite(fit->coefficients, "fit coefficients are finite");
    }
    (void)read_artefact_info(path);
    return 0;
}
