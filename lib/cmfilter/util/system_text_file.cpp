// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/util/system_text_file.h"

#include <fstream>
#include <sstream>

namespace cmfilter {

std::string read_system_text_file(const std::string& path)
{
    std::ifstream in(path);
    if (!in) return {};
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace cmfilter
