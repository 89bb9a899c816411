// SPDX-License-Identifier: Apache-2.0
// A linear fit (linear_fit.h) as a float OpenEXR file: one channel per
// coefficient, unquantised, with cmfilter:* metadata (cmfilter:kind
// "linear-fit", format version, model, channel count, encoding, colour
// space, the light set's conditioning and the source light file); the
// layout is docs/stacks.md#fit-files. Channels are named by colour channel
// and term: PtmRgb "R.a0" .. "R.a5", "G.a0", ..; Hsh2/Hsh3 "R.h0" ..;
// PtmLrgb the luminance polynomial "L.a0" .. "L.a5" and the base colour
// "R", "G", "B" (one channel: "Y"). Colour channels are R, G, B (and A for
// a fourth); one channel is Y; otherwise C0, C1, ...
#pragma once

#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/util/error.h"

#include <string>
#include <utility>
#include <vector>

namespace cmfilter {

inline constexpr const char* kLinearFitKind = "linear-fit";

struct FitFileInfo {
    std::string source;  // the light file it was fitted to (may be empty)
    // Further text attributes, by full name ("cmfilter:fit_seconds"; a name
    // without the "cmfilter:" prefix is given it on write). Read back: every
    // cmfilter:* text attribute the format does not define itself.
    std::vector<std::pair<std::string, std::string>> extra;
};

// The EXR channel names of a fit's coefficients, in LinearFit's per-texel
// order.
std::vector<std::string> fit_channel_names(LinearModel model, int channels);

// BadInput when the fit is inconsistent (coefficient count) or holds
// non-finite values; Io when the file cannot be written. Nothing is left
// behind on failure.
Status write_fit_exr(const std::string& path, const LinearFit& fit, const FitFileInfo& info);

// Io: missing or unreadable. BadInput naming the file: not a cmfilter
// linear fit, an unknown model or version, channels that do not match the
// model, non-finite coefficients.
Expected<LinearFit> read_fit_exr(const std::string& path, FitFileInfo* info = nullptr);

}  // namespace cmfilter
