// SPDX-License-Identifier: Apache-2.0
// How a table or a pyramid is stored in its OpenEXR file, as maketx spells
// it: the pixel type (-d half|float), the tiles (--tile W H) and the
// compression (--compression NAME, with an optional ":level" for zip, zips
// and dwaa/dwab). Every cmfilter artefact reads back from any of these.
#pragma once

#include "cmfilter/util/error.h"

#include <OpenImageIO/imageio.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace cmfilter {

enum class ExrPixelType { Float, Half };

struct ExrOutputOptions {
    ExrPixelType pixel_type = ExrPixelType::Float;
    int tile_width = 0;  // 0 with tile_height 0: the artefact's own default (scanlines, or 64 for pyramids)
    int tile_height = 0;
    std::string compression = "zip";  // OpenEXR's names: none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab
    // Further text attributes the file records (name, value): the command's
    // build record (cmfilter:build, io/build_record.h), a pipeline's own.
    std::vector<std::pair<std::string, std::string>> attributes;
};

const char* to_string(ExrPixelType type);
Expected<ExrPixelType> parse_exr_pixel_type(const std::string& text);

// BadInput naming `owner`'s field (owner: "BakeOptions::output", say) for an
// unknown compression or level, or tiles of a side outside 1..4096 (or one
// side 0 and not the other).
Status check_exr_output_options(const ExrOutputOptions& options, const std::string& owner);

// Sets the pixel type, tiles (when given), compression and attributes on `spec`.
void apply_exr_output_options(OIIO::ImageSpec& spec, const ExrOutputOptions& options);

// Whether these options lose precision (half pixels; pxr24 on floats, which
// it rounds to 24 bits; b44 and b44a on halves; dwaa and dwab on colour
// channels): words for a report, empty when lossless.
std::string exr_output_loss(const ExrOutputOptions& options);

// "float, zip, scanlines", "half, dwaa:45, 32 x 16 tiles" (`default_tiles`
// when the options name none).
std::string exr_output_text(const ExrOutputOptions& options, const std::string& default_tiles);

// BadInput naming `path` when a value of `values` does not fit a half
// (|v| > 65504 or not finite) and the options ask for half pixels: a half
// file would hold infinities.
Status check_half_range(const float* values, std::size_t count, const ExrOutputOptions& options,
                        const std::string& path);

}  // namespace cmfilter
