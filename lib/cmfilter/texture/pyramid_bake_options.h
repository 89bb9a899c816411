// SPDX-License-Identifier: Apache-2.0
// What every pyramid baked from a driver texture takes (moment pyramids,
// histogram pyramids): the driver and how to read it, the output file, and
// the tiled MIP-map's wrap, tiles and compression.
#pragma once

#include "cmfilter/io/driver_image.h"
#include "cmfilter/math/texture_wrap.h"

#include <string>

namespace cmfilter {

struct PyramidBakeOptions {
    std::string driver_path;
    std::string output_path;  // .exr, written atomically
    std::string channel;      // name or index; empty: single-channel driver
    NonFinitePolicy nonfinite = NonFinitePolicy::Error;
    TextureWrap wrap = TextureWrap::Clamp;
    int tile_size = 64;               // square tiles, as maketx's default
    std::string compression = "zip";  // OpenEXR compression, as maketx's default
    int threads = 0;                  // 0: all cores

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
