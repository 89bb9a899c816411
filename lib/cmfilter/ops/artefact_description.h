// SPDX-License-Identifier: Apache-2.0
// What `info` says of a file: its kind, a one-line description, its size
// and every parameter it records (artefact_info.h, stack_info.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace cmfilter {

struct ArtefactInfo {
    std::string path;
    std::string kind;
    std::string description;
    std::string format;  // OpenImageIO format name
    int width = 0, height = 0, channels = 0;
    std::vector<std::pair<std::string, std::string>> parameters;  // without the "cmfilter:" prefix
    std::vector<std::string> numeric;  // the names of the parameters that are numbers (the rest are text)
};

}  // namespace cmfilter
