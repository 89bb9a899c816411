// SPDX-License-Identifier: Apache-2.0
// Shared steps of reading and writing single-image cmfilter artefacts (EXR
// with cmfilter:* metadata): the kind and format-version check a reader does
// first, and the final write of float pixels through an AtomicOutput.
#pragma once

#include "cmfilter/io/exr_output_options.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/error.h"

#include <OpenImageIO/imageio.h>

#include <functional>
#include <string>
#include <vector>

namespace cmfilter {

// BadInput unless cmfilter:kind is `kind` and cmfilter:format_version is
// `version`; messages name the file and call it a cmfilter `what`.
Status check_artefact_kind(const OIIO::ImageSpec& spec, const std::string& path, const std::string& kind,
                           const std::string& what, int version);

// A single-image artefact read back: its pixels and its header.
struct ArtefactImage {
    ImageData image;
    OIIO::ImageSpec spec;  // subimage 0, level 0, with every attribute
};

// Opens `path`, checks its kind and version as check_artefact_kind does,
// then `check_header` when given (the reader's own checks of the header
// against its size and channels), and only then reads its pixels
// (read_image): a file that is not the artefact asked for costs a header
// read, whatever size it declares.
Expected<ArtefactImage> read_artefact_image(const std::string& path, const std::string& kind, const std::string& what,
                                            int version,
                                            const std::function<Status(const OIIO::ImageSpec&)>& check_header = {});

// Writes `spec`'s pixels (float, interleaved) to out's temporary file,
// stored as `storage` asks (pixel type, tiles, compression; BadInput for
// values past a half's range in a half file), and commits it to its
// destination.
Status write_float_artefact(AtomicOutput& out, OIIO::ImageSpec spec, const float* pixels,
                            const ExrOutputOptions& storage = {});

// A multi-part artefact: specs[i]'s float pixels from pixels[i], every part
// given specs[0]'s display window (OpenEXR multi-part files share one), to
// out's temporary file, then committed.
Status write_float_artefact_parts(AtomicOutput& out, std::vector<OIIO::ImageSpec> specs,
                                  const std::vector<std::vector<float>>& pixels);

}  // namespace cmfilter
