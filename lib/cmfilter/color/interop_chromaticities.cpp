// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/color/interop_chromaticities.h"

#include <cmath>

namespace cmfilter {

namespace {

struct Known {
    const char* id;
    Chromaticities xy;
};

// ITU-R BT.709 (sRGB) and P3 with D65 white; ACES AP1 and AP0 with the ACES
// white (SMPTE ST 2065-1).
constexpr Known kKnown[] = {
    {"lin_rec709_scene", {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f}},
    {"lin_p3d65_scene", {0.680f, 0.320f, 0.265f, 0.690f, 0.150f, 0.060f, 0.3127f, 0.3290f}},
    {"lin_ap1_scene", {0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f}},
    {"lin_ap0_scene", {0.7347f, 0.2653f, 0.0f, 1.0f, 0.0001f, -0.0770f, 0.32168f, 0.33767f}},
};

}  // namespace

std::optional<Chromaticities> interop_chromaticities(const std::string& interop_id)
{
    for (const Known& k : kKnown)
        if (interop_id == k.id) return k.xy;
    return std::nullopt;
}

std::string interop_id_of_chromaticities(const Chromaticities& c)
{
    for (const Known& k : kKnown) {
        bool same = true;
        for (std::size_t i = 0; i < c.size(); ++i) same = same && std::fabs(c[i] - k.xy[i]) <= 1e-3f;
        if (same) return k.id;
    }
    return {};
}

}  // namespace cmfilter
