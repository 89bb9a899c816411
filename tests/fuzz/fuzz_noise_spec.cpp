// SPDX-License-Identifier: Apache-2.0
// Noise specs (noise/noise_spec.h): any text, and the noise a valid spec
// makes, evaluated.
#include "support/fuzz_checks.h"

#include "cmfilter/noise/noise_spec.h"

#include <string>

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto spec = parse_noise_spec(text);
    if (!spec) return 0;
    auto noise = make_noise(*spec);
    if (!noise) return 0;
    for (double x : {0.0, 0.37, -12.5, 1e6})
        fuzz::require(std::isfinite((*noise)(x, 0.25 * x + 0.1)), "noise values are finite");
    return 0;
}
