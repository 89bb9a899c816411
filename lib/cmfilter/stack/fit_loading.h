// SPDX-License-Identifier: Apache-2.0
// Any linear fit from a file, by its extension: `.ptm` (ptm_file.h), `.rti`
// (rti_file.h), else cmfilter's own float EXR (fit_file.h).
#pragma once

#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

enum class FitFileFormat { Exr, Ptm, Rti };
FitFileFormat fit_file_format(const std::string& path);  // by extension, case-insensitive
const char* to_string(FitFileFormat format);             // "exr", "ptm", "rti"

Expected<LinearFit> load_fit(const std::string& path);

}  // namespace cmfilter
