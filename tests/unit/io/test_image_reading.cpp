// SPDX-License-Identifier: Apache-2.0
// read_float_pixels (io/image_reading.h), which reads scanline images in
// native strips and converts them itself, against OpenImageIO's own float
// conversion (ImageBuf::get_pixels): 8-bit, 16-bit, half and float images
// spanning several strips, channel subsets, and an EXR whose channels have
// different types; windows of scanline and tiled images (read_image with a
// window) against ImageBuf::get_pixels of the same rectangle. Bit-identical
// results are expected: both convert with OpenImageIO's convert_pixel_values.
#include "cmfilter/io/image_reading.h"

#include "test_images.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

const std::string kDir = temp_dir("cmfilter-test-image-reading");

// Channels [chbegin, chend) as float, converted by OpenImageIO itself.
std::vector<float> oiio_float_pixels(const std::string& path, int chbegin, int chend)
{
    OIIO::ImageBuf buf(path);
    REQUIRE(buf.read(0, 0, true, OIIO::TypeDesc::FLOAT));
    OIIO::ROI roi = buf.roi();
    roi.chbegin = chbegin;
    roi.chend = chend;
    std::vector<float> out(roi.npixels() * std::size_t(chend - chbegin));
    REQUIRE(buf.get_pixels(roi, OIIO::TypeDesc::FLOAT, out.data()));
    return out;
}

std::vector<float> cmfilter_float_pixels(const std::string& path, int chbegin, int chend)
{
    auto in = open_image_input(path);
    REQUIRE(in);
    const OIIO::ImageSpec& spec = (*in)->spec();
    std::vector<float> out(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(chend - chbegin));
    REQUIRE(read_float_pixels(**in, 0, 0, chbegin, chend, out.data()));
    return out;
}

// Native pixel bytes, a pattern that exercises every bit of the type.
std::vector<unsigned char> pattern(std::size_t bytes)
{
    std::vector<unsigned char> data(bytes);
    std::uint32_t x = 12345;
    for (auto& b : data) {
        x = x * 1103515245u + 12345u;
        b = static_cast<unsigned char>(x >> 16);
    }
    return data;
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("strips hold about 4 MB of native rows, at least one row, at most the image")
{
    OIIO::ImageSpec wide(40000, 300, 1, OIIO::TypeDesc::UINT8);
    CHECK(native_strip_rows(wide) == (4 << 20) / 40000);
    OIIO::ImageSpec small(64, 32, 4, OIIO::TypeDesc::FLOAT);
    CHECK(native_strip_rows(small) == 32);
    OIIO::ImageSpec huge_row(2000000, 10, 4, OIIO::TypeDesc::FLOAT);
    CHECK(native_strip_rows(huge_row) == 1);
    OIIO::ImageSpec tiled(1024, 1024, 1, OIIO::TypeDesc::HALF);
    tiled.tile_width = tiled.tile_height = 64;
    CHECK(native_strip_rows(tiled) == 64);
}

TEST_CASE("8-bit, 16-bit, half and float images over several strips read as OpenImageIO converts them")
{
    struct Case {
        const char* name;
        OIIO::TypeDesc type;
        int width, height, channels;
    };
    // Each spans at least three strips of native_strip_rows rows.
    const Case cases[] = {{"u8.tif", OIIO::TypeDesc::UINT8, 20000, 700, 1},
                          {"u16.tif", OIIO::TypeDesc::UINT16, 9000, 800, 2},
                          {"half.exr", OIIO::TypeDesc::HALF, 4000, 900, 3},
                          {"float.exr", OIIO::TypeDesc::FLOAT, 3000, 400, 4}};
    for (const Case& c : cases) {
        CAPTURE(c.name);
        OIIO::ImageSpec spec(c.width, c.height, c.channels, c.type);
        REQUIRE(c.height >= 3 * native_strip_rows(spec));
        auto data = pattern(spec.image_bytes());
        if (c.type == OIIO::TypeDesc::HALF || c.type == OIIO::TypeDesc::FLOAT) {
            // Finite values only: scale a uniform pattern.
            std::vector<float> f(spec.image_pixels() * std::size_t(c.channels));
            for (std::size_t i = 0; i < f.size(); ++i) f[i] = float(data[i]) / 7.0f - 10.0f;
            OIIO::convert_pixel_values(OIIO::TypeDesc::FLOAT, f.data(), c.type, data.data(), int(f.size()));
        }
        const std::string path = kDir + "/" + c.name;
        write_image(path, c.width, c.height, c.channels, c.type, data.data());
        CHECK(same_bits(cmfilter_float_pixels(path, 0, c.channels), oiio_float_pixels(path, 0, c.channels)));
        if (c.channels > 1)
            CHECK(same_bits(cmfilter_float_pixels(path, 1, c.channels), oiio_float_pixels(path, 1, c.channels)));
    }
}

TEST_CASE("an EXR whose channels have different types reads each channel as OpenImageIO converts it")
{
    const int W = 257, H = 65;
    OIIO::ImageSpec spec(W, H, 3, OIIO::TypeDesc::FLOAT);
    spec.channelformats = {OIIO::TypeDesc::HALF, OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::HALF};
    std::vector<float> f(std::size_t(W) * H * 3);
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = 0.001f * float(i % 9973) - 3.0f;
    const std::string path = kDir + "/mixed.exr";
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    REQUIRE(out->open(path, spec));
    REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, f.data()));
    REQUIRE(out->close());
    auto in = open_image_input(path);
    REQUIRE(in);
    REQUIRE((*in)->spec().channelformats.size() == 3);
    CHECK(same_bits(cmfilter_float_pixels(path, 0, 3), oiio_float_pixels(path, 0, 3)));
    CHECK(same_bits(cmfilter_float_pixels(path, 1, 3), oiio_float_pixels(path, 1, 3)));
    CHECK(same_bits(cmfilter_float_pixels(path, 2, 3), oiio_float_pixels(path, 2, 3)));
}

TEST_CASE("a window of a scanline or tiled image reads as OpenImageIO converts that rectangle")
{
    struct Case {
        const char* name;
        OIIO::TypeDesc type;
        int width, height, channels, tile;
    };
    // The TIFF spans several strips; the EXR's 32 x 32 tiles do not divide it.
    const Case cases[] = {{"window.tif", OIIO::TypeDesc::UINT16, 9000, 800, 2, 0},
                          {"window.exr", OIIO::TypeDesc::HALF, 150, 100, 3, 32}};
    // Rectangles: a row, a column, one inside tiles and strips, the whole image.
    for (const Case& c : cases) {
        CAPTURE(c.name);
        OIIO::ImageSpec spec(c.width, c.height, c.channels, c.type);
        spec.tile_width = spec.tile_height = c.tile;
        auto data = pattern(spec.image_bytes());
        if (c.type == OIIO::TypeDesc::HALF) {
            std::vector<float> f(spec.image_pixels() * std::size_t(c.channels));
            for (std::size_t i = 0; i < f.size(); ++i) f[i] = float(data[i]) / 7.0f - 10.0f;
            OIIO::convert_pixel_values(OIIO::TypeDesc::FLOAT, f.data(), c.type, data.data(), int(f.size()));
        }
        const std::string path = kDir + "/" + c.name;
        auto out = OIIO::ImageOutput::create(path);
        REQUIRE(out);
        REQUIRE(out->open(path, spec));
        REQUIRE(out->write_image(c.type, data.data()));
        REQUIRE(out->close());
        OIIO::ImageBuf buf(path);
        REQUIRE(buf.read(0, 0, true, OIIO::TypeDesc::FLOAT));
        const ImageWindow windows[] = {{0, c.height - 1, c.width, 1},
                                       {c.width / 3, 0, 1, c.height},
                                       {37, c.height / 2 - 5, c.width / 2, 41},
                                       {0, 0, c.width, c.height}};
        for (const ImageWindow& w : windows) {
            CAPTURE(w.x);
            CAPTURE(w.y);
            CAPTURE(w.width);
            CAPTURE(w.height);
            auto img = read_image(path, [&](const ImageData& header) -> Expected<ImageWindow> {
                CHECK(header.pixels.empty());
                return w;
            });
            REQUIRE(img);
            CHECK(img->width == c.width);
            CHECK(img->window.width == w.width);
            const OIIO::ROI roi(w.x, w.x + w.width, w.y, w.y + w.height, 0, 1, 0, c.channels);
            std::vector<float> expected(roi.npixels() * std::size_t(c.channels));
            REQUIRE(buf.get_pixels(roi, OIIO::TypeDesc::FLOAT, expected.data()));
            CHECK(same_bits(img->pixels, expected));
        }
        // A window beyond the image, or a refusal, reads nothing.
        auto outside = read_image(path, [&](const ImageData&) -> Expected<ImageWindow> {
            return ImageWindow{c.width - 1, 0, 2, 1};
        });
        REQUIRE_FALSE(outside);
        CHECK(outside.error().message.find("is outside") != std::string::npos);
        auto refused = read_image(path, [](const ImageData&) -> Expected<ImageWindow> { return bad_input("no"); });
        REQUIRE_FALSE(refused);
        CHECK(refused.error().message == "no");
    }
}
