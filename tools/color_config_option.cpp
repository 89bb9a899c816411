// SPDX-License-Identifier: Apache-2.0
// The OpenColorIO config a command uses: --ocio-config FILE, else $OCIO, else
// the config built into libcmfilter.
#include "command.h"

#include <cstdlib>

namespace cmfilter::cli {

std::string color_config_for_record(const std::string& ocio_config_option)
{
    if (!ocio_config_option.empty()) return ocio_config_option;
    if (const char* env = std::getenv("OCIO"); env && *env) return env;
    return "built-in";
}

Expected<ColorConfig> load_color_config(const std::string& ocio_config_option)
{
    std::string path = ocio_config_option;
    if (path.empty())
        if (const char* env = std::getenv("OCIO"); env && *env) path = env;
    return ColorConfig::load(path);
}

}  // namespace cmfilter::cli
