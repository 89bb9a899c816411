// SPDX-License-Identifier: Apache-2.0
// A linear fit (linear_fit.h) as a float OpenEXR file: one channel per
// coefficient, unquantised, with cmfilter:* metadata (cmfilter:kind
// "linear-fit", format version, model, channel count, encoding, colour
// space, the light set's conditioning and the source light file); the
// layout is docs/stacks.md#fit-files.
#pragma once

#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/util/error.h"

#include <string>
#include <utility>
#include <vector>

namespace cmfilter {

struct FitFileInfo {
    std::string source;                                      // the light file it was fitted to (may be empty)
    std::vector<std::pair<std::string, std::string>> extra;  // further cmfilter:* text attributes
};

Status write_fit_exr(const std::string& path, const LinearFit& fit, const FitFileInfo& info);

// Io: missing or unreadable. BadInput naming the file: not a cmfilter
// linear fit, an unknown model or version, channels that do not match the
// model, non-finite coefficients.
Expected<LinearFit> read_fit_exr(const std::string& path, FitFileInfo* info = nullptr);

}  // namespace cmfilter
