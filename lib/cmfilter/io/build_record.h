// SPDX-License-Identifier: Apache-2.0
// The build record of an output: cmfilter:build, a SHA-256 (hex) of what
// made the file (the command, its parameters, the hashes of its inputs and
// cmfilter's version), as the command computes it. A command asked to update
// (-u) does nothing when its outputs already record the build it would do.
#pragma once

#include <string>

namespace cmfilter {

// The attribute name.
inline constexpr const char* kBuildRecordAttribute = "cmfilter:build";

// The build `path` records; empty when the file is missing, unreadable, not
// an image or records none.
std::string recorded_build(const std::string& path);

}  // namespace cmfilter
