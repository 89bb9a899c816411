// SPDX-License-Identifier: Apache-2.0
// RTI files (stack/rti_file.h): any bytes as an .rti file.
#include "support/fuzz_checks.h"

#include "cmfilter/stack/rti_file.h"

#include <string>

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    if (auto fit = decode_rti(bytes, "fuzz.rti")) {
        fuzz::require(fit->coefficients.size() == fit->texels() * std::size_t(fit->stride()),
                      "an RTI file holds stride() coefficients per texel");
        fuzz::require_finite(fit->coefficients, "RTI coefficients are finite");
    }
    return 0;
}
