// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/fit_loading.h"

#include "cmfilter/stack/fit_file.h"
#include "cmfilter/stack/ptm_file.h"
#include "cmfilter/stack/rti_file.h"
#include "cmfilter/util/atomic_output.h"

namespace cmfilter {

FitFileFormat fit_file_format(const std::string& path)
{
    const std::string ext = lowercase_extension(path);
    if (ext == ".ptm") return FitFileFormat::Ptm;
    if (ext == ".rti") return FitFileFormat::Rti;
    return FitFileFormat::Exr;
}

const char* to_string(FitFileFormat format)
{
    switch (format) {
    case FitFileFormat::Exr: return "exr";
    case FitFileFormat::Ptm: return "ptm";
    case FitFileFormat::Rti: return "rti";
    }
    return "?";
}

Expected<LinearFit> load_fit(const std::string& path)
{
    switch (fit_file_format(path)) {
    case FitFileFormat::Ptm: return read_ptm(path);
    case FitFileFormat::Rti: return read_rti(path);
    case FitFileFormat::Exr: break;
    }
    return read_fit_exr(path);
}

}  // namespace cmfilter
