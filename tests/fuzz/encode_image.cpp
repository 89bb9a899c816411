// SPDX-License-Identifier: Apache-2.0
// Turns a real image into the fuzz harnesses' in-memory encoding
// (support/fuzz_image.h), for seed corpora:
//   cmfilter_fuzz_encode_image IN.exr OUT.cmfuzz [MAX_VALUES]
// Every subimage with its MIP level count, size, channels, pixel type,
// tiling and int, float and string attributes; the first MAX_VALUES (default
// 4096) pixel values of each subimage's full-size level. Prints the first
// subimage's cmfilter:kind (an empty line for an image that has none), so a
// script can sort images by the harness that reads them.
#include "support/fuzz_image.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

using namespace cmfilter::fuzz;

namespace {

int type_code(OIIO::TypeDesc t)
{
    if (t == OIIO::TypeDesc::HALF) return 1;
    if (t == OIIO::TypeDesc::UINT8) return 2;
    if (t == OIIO::TypeDesc::UINT16) return 3;
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s IN OUT.cmfuzz [MAX_VALUES]\n", argv[0]);
        return 1;
    }
    const std::size_t max_values = argc > 3 ? std::strtoul(argv[3], nullptr, 10) : 4096;
    auto in = OIIO::ImageInput::open(argv[1]);
    if (!in) {
        std::fprintf(stderr, "cannot read %s: %s\n", argv[1], OIIO::geterror().c_str());
        return 1;
    }
    FuzzImage image;
    const std::string kind = in->spec().get_string_attribute("cmfilter:kind");
    for (int s = 0; in->seek_subimage(s, 0); ++s) {
        const OIIO::ImageSpec spec = in->spec();
        FuzzSubimage sub;
        sub.width = spec.width;
        sub.height = spec.height;
        sub.channel_names = spec.channelnames;
        sub.type = type_code(spec.format);
        sub.tiled = spec.tile_width > 0;
        int levels = 1;
        while (in->seek_subimage(s, levels)) ++levels;
        in->seek_subimage(s, 0);
        sub.levels = std::min(levels, 8);
        for (const OIIO::ParamValue& p : spec.extra_attribs) {
            FuzzAttribute attr;
            attr.name = p.name().string();
            if (p.type() == OIIO::TypeDesc::INT) {
                attr.kind = 0;
                attr.int_value = p.get_int();
            } else if (p.type() == OIIO::TypeDesc::FLOAT || p.type() == OIIO::TypeDesc::DOUBLE) {
                attr.kind = 1;
                attr.float_value = p.get_float();
            } else if (p.type() == OIIO::TypeDesc::STRING) {
                attr.kind = 2;
                attr.string_value = p.get_string();
            } else {
                continue;
            }
            sub.attributes.push_back(attr);
        }
        std::vector<float> pixels(spec.image_pixels() * std::size_t(spec.nchannels));
        if (!in->read_image(s, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) {
            std::fprintf(stderr, "cannot read the pixels of %s: %s\n", argv[1], in->geterror().c_str());
            return 1;
        }
        pixels.resize(std::min(pixels.size(), max_values));
        sub.values = pixels;
        image.subimages.push_back(std::move(sub));
        if (image.subimages.size() == 4) break;
    }
    std::ofstream out(argv[2], std::ios::binary);
    const std::string bytes = encode_fuzz_image(image);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) return 1;
    std::printf("%s\n", kind.c_str());
    return 0;
}
