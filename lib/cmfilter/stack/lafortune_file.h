// SPDX-License-Identifier: Apache-2.0
// A Lafortune fit (lafortune_model.h) as a float OpenEXR file: one channel
// per parameter, unquantised, with cmfilter:* metadata: cmfilter:kind
// "lafortune-fit", cmfilter:format_version 1, cmfilter:variant ("rgb" or
// "luminance"), cmfilter:channels, cmfilter:lobes (slots per texel or
// channel), cmfilter:auto_lobes (0 or 1), cmfilter:lobe_histogram (texels,
// or texel channels for rgb, with 0, 1, .. lobes: "n0,n1,.."),
// cmfilter:fallbacks, cmfilter:view_x/_y/_z (the fitted view),
// cmfilter:encoding, cmfilter:colorspace, cmfilter:source, cmfilter:layout.
// Channels: Luminance "L.rho", "L.0.ax", "L.0.ay", "L.0.az", "L.0.n", ..
// per slot, the base colour "R", "G", "B" (one channel: "Y") and the lobe
// count "L.lobes"; Rgb per colour channel c "c.rho", "c.0.ax", .., "c.lobes".
#pragma once

#include "cmfilter/stack/lafortune_model.h"
#include "cmfilter/util/error.h"

#include <string>
#include <vector>

namespace cmfilter {

inline constexpr const char* kLafortuneFitKind = "lafortune-fit";

// The EXR channel names of a fit's parameters in LafortuneFit's per-texel
// order, then the lobe count channels.
std::vector<std::string> lafortune_channel_names(LafortuneVariant variant, int channels, int lobes);

// BadInput when the fit is inconsistent (sizes, lobe counts, a view below
// the horizon) or holds non-finite values; Io when the file cannot be
// written. `source`: the light file fitted (may be empty). Nothing is left
// behind on failure.
Status write_lafortune_exr(const std::string& path, const LafortuneFit& fit, const std::string& source = {});

// Io: missing or unreadable. BadInput naming the file and the reason: not a
// cmfilter Lafortune fit, an unknown variant or version, a channel or lobe
// count the variant does not allow, missing or extra channels, a view that
// is missing or below the horizon, non-finite parameters, a lobe count
// outside [0, lobes], a negative exponent below 1.
Expected<LafortuneFit> read_lafortune_exr(const std::string& path, std::string* source = nullptr);

}  // namespace cmfilter
