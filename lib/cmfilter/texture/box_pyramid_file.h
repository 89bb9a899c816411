// SPDX-License-Identifier: Apache-2.0
// Writing a box pyramid (box_pyramid.h) as a tiled, mip-mapped float32 (or
// half: ExrOutputOptions) OpenEXR that OpenImageIO's TextureSystem reads: level 0 streamed tile row
// by tile row as the caller fills its rows, every upper level accumulated
// from the same rows and appended at the end. Shared by the pyramids whose
// channels are box means of per-texel functions of the driver: moment
// pyramids ((f - c), (f - c)^2) and histogram pyramids (indicators).
//
// Each level-0 tile row is handed to a writer thread (OpenEXR compresses a
// call's tiles on its own thread pool) while the next row is computed; two
// row buffers alternate. Compression dominates the time
// (docs/benchmarks.md), so this overlap is what there is to win.
#pragma once

#include "cmfilter/io/exr_output_options.h"
#include "cmfilter/util/error.h"

#include <OpenImageIO/imageio.h>

#include <functional>
#include <string>
#include <vector>

namespace cmfilter {

struct BoxPyramidFileOptions {
    std::string path;  // where to write (a temporary file)
    std::string name;  // the destination, for messages
    int width = 0, height = 0;
    std::vector<std::string> channel_names;  // one per channel
    ExrOutputOptions storage;                // tiles 0 x 0: 64 x 64
    int threads = 0;
    std::function<void(OIIO::ImageSpec&)> set_metadata;  // on level 0's spec
    std::function<void(double fraction)> progress;       // optional
};

// Fills level-0 row y as channel planes: planes[c * width + x] (double; level
// 0 is stored as their float32 rounding). Called concurrently for different
// rows; thread is 0 .. threads-1.
using BoxPyramidRowFill = std::function<void(int y, int thread, double* planes)>;

struct BoxPyramidFileTimes {
    double build_ms = 0;  // filling rows and accumulating the upper levels
    double write_ms = 0;  // waiting for the writer: encoding and writing
};

Expected<BoxPyramidFileTimes> write_box_pyramid_file(const BoxPyramidFileOptions& options,
                                                     const BoxPyramidRowFill& fill);

}  // namespace cmfilter
