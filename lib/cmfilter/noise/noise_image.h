// SPDX-License-Identifier: Apache-2.0
// A procedural noise rendered as a driver image (docs/noise.md): a
// single-channel float32 OpenEXR, channel "Y", holding data (no colour space),
// pixel (i, j) (row j = 0 at the top) = noise(scale (i + 1/2), scale (j + 1/2)):
// the noise at the pixel centre, `scale` noise units per pixel. The spec's text
// form, the scale and the base period are stored as cmfilter:* metadata
// (cmfilter:kind = noise-image), so the image says which noise it samples.
#pragma once

#include "cmfilter/util/error.h"
#include "cmfilter/noise/noise_spec.h"

#include <string>
#include <vector>

namespace cmfilter {

inline constexpr const char* kNoiseImageKind = "noise-image";

struct NoiseImageOptions {
    NoiseSpec spec;
    int width = 256, height = 256;  // 1..65536 each
    double scale = 1.0 / 16.0;      // noise units per pixel, finite and > 0
    int threads = 0;                // 0: all cores
};

// width * height samples, row-major, top row first. Checks the options
// (BadInput naming the bad value) and the spec (make_noise).
Expected<std::vector<float>> render_noise_image(const NoiseImageOptions& options);

// Renders and writes `path` atomically (.exr).
Status write_noise_image(const std::string& path, const NoiseImageOptions& options);

}  // namespace cmfilter
