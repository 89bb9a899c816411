// SPDX-License-Identifier: Apache-2.0
// `info` for the second paper's files, which are not single cmfilter EXRs:
// an image stack (its .lp light file), a BTF manifest (.json), and fits in
// the interchange formats (.ptm, .rti). Described as artefact_info.h
// describes an artefact: a kind, a line of description, the size, and
// parameters.
#pragma once

#include "cmfilter/ops/artefact_description.h"
#include "cmfilter/util/error.h"

#include <optional>
#include <string>

namespace cmfilter {

// None when `path` is none of these (by extension: .lp, .ptm, .rti, or a
// .json whose "format" is "cmfilter-btf"); otherwise its description or
// the reader's error.
std::optional<Expected<ArtefactInfo>> read_stack_file_info(const std::string& path);

// The description of a cmfilter linear-fit EXR (fit_file.h) of size w x h.
std::string describe_linear_fit(int width, int height);

// The description of a cmfilter lafortune-fit EXR (lafortune_file.h) from
// the info read of it (its size and the parameters cmfilter:variant,
// lobes, auto_lobes, view_x, view_y, view_z).
std::string describe_lafortune_fit(const ArtefactInfo& info);

}  // namespace cmfilter
