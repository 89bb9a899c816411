// SPDX-License-Identifier: Apache-2.0
// Reading any image OpenImageIO can read into float pixels, with errors that
// tell a missing or unreadable file (Io) from a file that is not an image or
// has no pixels (BadInput). Shared by colour maps and, later, drivers.
#pragma once

#include "cmfilter/util/error.h"

#include <OpenImageIO/imageio.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cmfilter {

// A rectangle of an image's pixels, from the top-left of its data window.
struct ImageWindow {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
};

struct ImageData {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<std::string> channel_names;
    // The pixels read (ImageData::window: all of them unless a reader asked
    // for less): window.width * window.height * channels, row-major, top row
    // first.
    ImageWindow window;
    std::vector<float> pixels;
    std::string format;      // OpenImageIO format name ("png", "openexr", ...)
    std::string pixel_type;  // stored type ("uint8", "half", "float", ...)
    bool is_float = false;   // stored as half/float/double
    // The colour space the file declares: "colorInteropID", else the
    // "cmfilter:linear_space" cmfilter's own files record, else the interop
    // ID of OpenEXR's "chromaticities" when they are a known space's
    // (color/interop_chromaticities.h), else empty.
    std::string colorspace_attr;
    std::string oiio_colorspace;  // "oiio:ColorSpace": what OpenImageIO reports, often only its guess for the format
    float gamma_attr = 0;         // "oiio:Gamma" when declared, else 0
};

// Refuses (BadInput, before reading pixels) an image whose float pixels do
// not fit in what this process may allocate (check_image_allocation).
Expected<ImageData> read_image(const std::string& path);

// What a reader keeps of an image, chosen from its header (an ImageData
// without pixels): a window of it, or an error that refuses the image
// before any pixel is read.
using ImageWindowChoice = std::function<Expected<ImageWindow>(const ImageData& header)>;

// read_image keeping only the window `choose` returns: it holds the window
// and a strip of rows (native_strip_rows) at a time. The image is refused by
// the same size check as a whole read (check_image_allocation), before the
// window is chosen: every column of the window's rows is decoded, and
// sequential formats (PNG, JPEG) decode the rows above it too.
Expected<ImageData> read_image(const std::string& path, const ImageWindowChoice& choose);

// Reads channels [chbegin, chend) of subimage `subimage`, MIP level
// `miplevel` of `in` as float into `out` (width x height x channels, top row
// first), in strips of native_strip_rows rows that it converts itself (a
// tiled image: a row of tiles at a time, by OpenImageIO), so that no more
// than a strip is held beside `out`. False (with in's error set) when a read
// fails.
bool read_float_pixels(OIIO::ImageInput& in, int subimage, int miplevel, int chbegin, int chend, float* out);

// Rows of `spec` that read_float_pixels reads at a time: about 4 MB of
// native pixels, at least one row and at most the image; a tiled image's
// tile height.
int native_strip_rows(const OIIO::ImageSpec& spec);

// BadInput naming `path` and its size when `channels` float values for each
// of `spec`'s width x height pixels (times `copies`), with two strips of
// native rows (native_strip_rows) that reading converts them from, exceed
// the memory budget (util/memory_budget.h); what a reader calls before it
// allocates them.
Status check_image_allocation(const OIIO::ImageSpec& spec, const std::string& path, int channels, int copies = 1);

// Opens `path` for reading after the same checks: Io when it is missing, a
// directory or unreadable; BadInput when it is empty, not an image, or has no
// pixels. `config` (may be null) is passed to OpenImageIO's ImageInput::open.
Expected<std::unique_ptr<OIIO::ImageInput>> open_image_input(const std::string& path,
                                                             const OIIO::ImageSpec* config = nullptr);

}  // namespace cmfilter
