// SPDX-License-Identifier: Apache-2.0
// Where a float image cmfilter writes says which scene-linear colour space
// its RGB is in, in the attributes other tools read: colorInteropID (the
// colour interop ID, OpenImageIO 3 and OpenEXR 3.3's convention), OpenEXR's
// standard chromaticities, oiio:ColorSpace (OpenImageIO 2.4, kept by formats
// other than OpenEXR), and cmfilter:linear_space (the config's own name).
// read_image reads them back in that order (io/image_colorspace.h).
#pragma once

#include <OpenImageIO/imageio.h>

#include <string>

namespace cmfilter {

// Sets them on `spec` for `linear_space`, a config's canonical name, whose
// interop ID is `interop_id` (ColorConfig::interop_id; empty: none, and then
// no colorInteropID and no chromaticities; chromaticities only for known
// primaries).
void set_linear_space_attributes(OIIO::ImageSpec& spec, const std::string& linear_space, const std::string& interop_id);

}  // namespace cmfilter
