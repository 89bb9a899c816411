// SPDX-License-Identifier: Apache-2.0
// Shared steps of reading and writing single-image cmfilter artefacts (EXR
// with cmfilter:* metadata): the kind and format-version check a reader does
// first, and the final write of float pixels through an AtomicOutput.
#pragma once

#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/error.h"

#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

namespace cmfilter {

// BadInput unless cmfilter:kind is `kind` and cmfilter:format_version is
// `version`; messages name the file and call it a cmfilter `what`.
Status check_artefact_kind(const OIIO::ImageSpec& spec, const std::string& path, const std::string& kind,
                           const std::string& what, int version);

// Writes `spec`'s pixels (float, interleaved) to out's temporary file and
// commits it to its destination.
Status write_float_artefact(AtomicOutput& out, const OIIO::ImageSpec& spec, const float* pixels);

// A multi-part artefact: specs[i]'s float pixels from pixels[i], every part
// given specs[0]'s display window (OpenEXR multi-part files share one), to
// out's temporary file, then committed.
Status write_float_artefact_parts(AtomicOutput& out, std::vector<OIIO::ImageSpec> specs,
                                  const std::vector<std::vector<float>>& pixels);

}  // namespace cmfilter
