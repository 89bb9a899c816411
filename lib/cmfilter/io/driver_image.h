// SPDX-License-Identifier: Apache-2.0
// Reading a driver texture f: one channel of any image OpenImageIO reads,
// taken as data. No colour conversion and no alpha premultiplication: 8- and
// 16-bit codes map to [0, 1] as OpenImageIO's float conversion does (code /
// 255, code / 65535), half and float values are used as stored. Non-finite
// texels are refused, or replaced by 0 and counted. The statistics a moment
// pyramid needs (mean, min, max) come from the same pass.
#pragma once

#include "cmfilter/util/error.h"

#include <cstddef>
#include <string>
#include <vector>

namespace cmfilter {

enum class NonFinitePolicy {
    Error,  // a NaN or Inf texel is BadInput
    Zero,   // replaced by 0 and counted
};

// "error", "zero".
const char* to_string(NonFinitePolicy policy);
Expected<NonFinitePolicy> parse_non_finite_policy(const std::string& name);

struct DriverReadOptions {
    std::string path;
    std::string channel;  // a channel name or 0-based index; empty: the image must have one channel
    NonFinitePolicy nonfinite = NonFinitePolicy::Error;
    int threads = 0;  // 0: all cores
};

struct DriverImage {
    int width = 0;
    int height = 0;
    std::string channel;  // name of the channel read ("" when the file names none)
    int channel_index = 0;
    std::string pixel_type;     // stored type ("uint8", "half", "float", ...)
    std::vector<float> values;  // width * height, row-major, top row first
    std::size_t nonfinite_replaced = 0;
    double mean = 0;  // over all texels, after replacement (double precision)
    double min = 0;
    double max = 0;
};

Expected<DriverImage> read_driver(const DriverReadOptions& options);

// read_driver, and the SHA-256 of the file's bytes (computed beside the
// decode) for the cmfilter:source_sha256 of what is baked from it.
struct HashedDriver {
    DriverImage image;
    std::string sha256;
};
Expected<HashedDriver> read_driver_and_hash(const DriverReadOptions& options);

}  // namespace cmfilter
