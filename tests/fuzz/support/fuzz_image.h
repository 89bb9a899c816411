// SPDX-License-Identifier: Apache-2.0
// An in-memory image for the fuzz harnesses: a few bytes describe every
// subimage's size, channels, pixel type, tiling, MIP levels, attributes and
// pixel values, and an OpenImageIO image format of the harnesses' own
// ("cmfuzz", files ending in .cmfuzz) serves that description to whatever
// opens the file, with ImageInput, ImageBuf or a TextureSystem. cmfilter's
// readers then run exactly as on an EXR, on attribute sets and sizes the
// fuzzer chooses, without the fuzzer having to get through OpenEXR's
// decoder first, and without the pixels ever being held in memory: pixel i
// of a level is values[i % values.size()].
//
// The encoding (all integers little-endian, strings a u8 length and bytes):
//   u8 subimages (1 + b % 4), then for each subimage:
//     u8 levels (1 + b % 8)   i32 width   i32 height   u8 channels (b % 16)
//     u8 type (b % 4: float, half, uint8, uint16)   u8 tiled (b % 2: 64 x 64 tiles)
//     channels x string (channel names)
//     u8 attributes, then each: string name, u8 kind (b % 3: int, float,
//       string), then an i32, an f32 or a string
//     u16 values, then that many f32
// Bytes run out: everything not read is empty or zero.
#pragma once

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <string>
#include <vector>

namespace cmfilter::fuzz {

struct FuzzAttribute {
    std::string name;
    int kind = 0;  // 0 int, 1 float, 2 string
    std::int32_t int_value = 0;
    float float_value = 0;
    std::string string_value;
};

struct FuzzSubimage {
    int levels = 1;
    std::int32_t width = 0;
    std::int32_t height = 0;
    std::vector<std::string> channel_names;
    int type = 0;  // 0 float, 1 half, 2 uint8, 3 uint16
    bool tiled = false;
    std::vector<FuzzAttribute> attributes;
    std::vector<float> values;
};

struct FuzzImage {
    std::vector<FuzzSubimage> subimages;
};

FuzzImage decode_fuzz_image(const std::uint8_t* data, std::size_t size);
std::string encode_fuzz_image(const FuzzImage& image);

// The ImageSpec of `sub` at MIP level `level` (level 0: full size).
OIIO::ImageSpec fuzz_image_spec(const FuzzSubimage& sub, int level);

// Registers the "cmfuzz" format with OpenImageIO; call once, before the
// first read.
void register_fuzz_image_format();

}  // namespace cmfilter::fuzz
