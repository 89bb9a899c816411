// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/build_record.h"

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <system_error>

namespace cmfilter {

std::string recorded_build(const std::string& path)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return {};
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        (void)OIIO::geterror();  // the error is this function's answer, not a message for later
        return {};
    }
    return in->spec().get_string_attribute(kBuildRecordAttribute);
}

}  // namespace cmfilter
