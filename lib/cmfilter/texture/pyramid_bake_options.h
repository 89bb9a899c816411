// SPDX-License-Identifier: Apache-2.0
// What every pyramid baked from a driver texture takes (moment pyramids,
// histogram pyramids): the driver and how to read it, the output file, and
// the tiled MIP-map's wrap, tiles and compression.
#pragma once

#include "cmfilter/io/driver_image.h"
#include "cmfilter/io/exr_output_options.h"
#include "cmfilter/math/texture_wrap.h"

#include <string>

namespace cmfilter {

struct PyramidBakeOptions {
    std::string driver_path;
    std::string output_path;  // .exr, written atomically
    std::string channel;      // name or index; empty: single-channel driver
    NonFinitePolicy nonfinite = NonFinitePolicy::Error;
    TextureWrap wrap = TextureWrap::Clamp;
    // Pixel type, tiles and compression (io/exr_output_options.h); tiles
    // 0 x 0 mean 64 x 64, maketx's default, as zip is.
    ExrOutputOptions storage;
    int threads = 0;  // 0: all cores

    DriverReadOptions driver_read() const
    {
        DriverReadOptions read;
        read.path = driver_path;
        read.channel = channel;
        read.nonfinite = nonfinite;
        read.threads = threads;
        return read;
    }
};

}  // namespace cmfilter
