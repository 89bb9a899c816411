// SPDX-License-Identifier: Apache-2.0
// What a cmfilter artefact is: its kind, a one-line description and every
// cmfilter:* parameter it was baked with, read from any file OpenImageIO opens.
#pragma once

#include "cmfilter/ops/artefact_description.h"
#include "cmfilter/util/error.h"

#include <string>
#include <utility>
#include <vector>

namespace cmfilter {

// BadInput when the file is an image but carries no cmfilter:kind.
Expected<ArtefactInfo> read_artefact_info(const std::string& path);

}  // namespace cmfilter
