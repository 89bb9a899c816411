// SPDX-License-Identifier: Apache-2.0
// Lafortune fits in EXR (stack/lafortune_file.h) from arbitrary headers.
#include "support/fuzz_checks.h"
#include "support/scratch_file.h"

#include "cmfilter/ops/artefact_info.h"
#include "cmfilter/stack/lafortune_file.h"

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string path = fuzz::write_scratch_file("lafortune.cmfuzz", data, size);
    if (auto fit = read_lafortune_exr(path)) {
        fuzz::require(fit->parameters.size() ==
                          std::size_t(fit->width) * std::size_t(fit->height) * std::size_t(fit->stride()),
                      "a Lafortune fit holds stride() values per texel");
        fuzz::require_finite(fit->parameters, "Lafortune parameters are finite");
    }
    (void)read_artefact_info(path);
    return 0;
}
