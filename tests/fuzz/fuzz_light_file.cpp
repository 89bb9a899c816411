// SPDX-License-Identifier: Apache-2.0
// RTI light files (stack/light_file.h): any bytes as a .lp file; a file that
// reads must give unit directions at or above the horizon and write back to
// a file that reads the same.
#include "support/fuzz_checks.h"
#include "support/scratch_file.h"

#include "cmfilter/stack/light_file.h"

#include <cmath>

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string path = fuzz::write_scratch_file("lights.lp", data, size);
    auto lights = read_light_file(path);
    if (!lights) return 0;
    fuzz::require(!lights->lights.empty(), "a light file has a light");
    for (const LightEntry& e : lights->lights) {
        const Vec3& d = e.direction;
        fuzz::require(std::abs(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z) - 1) < 1e-6 && d.z >= 0,
                      "light directions are unit, at or above the horizon");
    }
    const std::string text = format_light_file(lights->lights);
    const std::string again =
        fuzz::write_scratch_file("again.lp", reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
    auto back = read_light_file(again);
    fuzz::require(back.has_value() && back->lights.size() == lights->lights.size(),
                  "a light file written back reads with as many lights");
    return 0;
}
