// SPDX-License-Identifier: Apache-2.0
// Polynomial texture maps (stack/ptm_file.h): any bytes as a .ptm file.
#include "support/fuzz_checks.h"

#include "cmfilter/stack/ptm_file.h"

#include <string>

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    if (auto fit = decode_ptm(bytes, "fuzz.ptm")) {
        fuzz::require(fit->coefficients.size() == fit->texels() * std::size_t(fit->stride()),
                      "a PTM holds stride() coefficients per texel");
        fuzz::require_finite(fit->coefficients, "PTM coefficients are finite");
    }
    return 0;
}
