// SPDX-License-Identifier: Apache-2.0
// The option values the cmfilter command parses from text: the first byte
// picks the parser, the rest is the text. Sizes "WxH", ranges "a:b", light
// directions "x,y,z", light domes, specular lobes and the named choices.
#include "support/fuzz_checks.h"

#include "../../tools/command.h"

#include "cmfilter/math/texture_wrap.h"
#include "cmfilter/math/wrap_mode.h"
#include "cmfilter/ops/filtered_image.h"
#include "cmfilter/synthesis/coordinate_lookup.h"
#include "cmfilter/synthetic/light_dome.h"
#include "cmfilter/synthetic/specular_lobe.h"
#include "cmfilter/tables/gaussian_color_table.h"

#include <cmath>
#include <string>

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size == 0) return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    switch (data[0] % 10) {
    case 0:
        if (auto s = cli::parse_size("--size", text))
            fuzz::require(s->first >= 1 && s->second >= 1 && s->first <= 65536 && s->second <= 65536,
                          "a size is 1..65536 each way");
        break;
    case 1:
        if (auto r = cli::parse_range("--range", text))
            fuzz::require(std::isfinite(r->first) && std::isfinite(r->second), "a range is finite");
        break;
    case 2:
        if (auto d = cli::parse_direction("--light", text)) {
            const double n = std::sqrt(d->x * d->x + d->y * d->y + d->z * d->z);
            fuzz::require(std::abs(n - 1) < 1e-9 && d->z >= 0, "a direction is unit, at or above the horizon");
        }
        break;
    case 3:
        if (auto dome = parse_dome(text)) (void)dome_text(*dome);
        break;
    case 4:
        if (auto lobe = parse_specular_lobe(text)) (void)specular_text(*lobe);
        break;
    case 5: (void)parse_filter_method(text); break;
    case 6: (void)parse_sigma_spacing(text); break;
    case 7: (void)parse_texture_wrap(text); break;
    case 8: (void)parse_wrap_mode(text); break;
    default: (void)parse_lod_method(text); break;
    }
    return 0;
}
