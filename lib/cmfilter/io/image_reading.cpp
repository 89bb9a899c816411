// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/image_reading.h"

#include "cmfilter/color/interop_chromaticities.h"

#include "cmfilter/util/memory_budget.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace cmfilter {

Expected<std::unique_ptr<OIIO::ImageInput>> open_image_input(const std::string& path, const OIIO::ImageSpec* config)
{
    std::error_code ec;
    if (!fs::exists(path, ec)) return io_error("cannot read '" + path + "': no such file");
    if (fs::is_directory(path, ec)) return io_error("cannot read '" + path + "': it is a directory");
    if (!std::ifstream(path, std::ios::binary).good())
        return io_error("cannot read '" + path + "': permission denied or unreadable");
    if (fs::file_size(path, ec) == 0) return bad_input("'" + path + "' is empty (0 bytes); expected an image");

    auto in = OIIO::ImageInput::open(path, config);
    if (!in) {
        std::string why = OIIO::geterror();
        return bad_input("'" + path + "' is not an image OpenImageIO can read" +
                         (why.empty() ? std::string() : " (" + why + ")"));
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
        std::ostringstream msg;
        msg << "'" << path << "' has no pixels (" << spec.width << " x " << spec.height << ", " << spec.nchannels
            << " channels); expected at least 1 x 1";
        return bad_input(msg.str());
    }
    return Expected<std::unique_ptr<OIIO::ImageInput>>(std::move(in));
}

namespace {

// Native bytes a strip of rows aims at: small enough to stay in cache,
// large enough that a read call is not per row.
constexpr double kStripBytes = double(4 << 20);

}  // namespace

int native_strip_rows(const OIIO::ImageSpec& spec)
{
    if (spec.tile_width > 0) return std::max(1, spec.tile_height);
    const double row = double(std::max(spec.width, 1)) * double(std::max<std::size_t>(spec.pixel_bytes(true), 1));
    return static_cast<int>(std::clamp(std::floor(kStripBytes / row), 1.0, double(std::max(spec.height, 1))));
}

Status check_image_allocation(const OIIO::ImageSpec& spec, const std::string& path, int channels, int copies)
{
    // The floats, and one strip of native rows (a row of tiles) twice: the
    // strip read_float_pixels converts from, and the whole-pixel strip an
    // image reader without channel subsets copies a subset out of.
    const double strip = double(spec.width) * double(native_strip_rows(spec)) * double(spec.pixel_bytes(true));
    const double bytes = double(spec.width) * double(spec.height) * double(channels) * sizeof(float) * copies +
                         2 * strip;
    return check_allocation(bytes, "'" + path + "' (" + std::to_string(spec.width) + " x " +
                                       std::to_string(spec.height) + " pixels, " + std::to_string(channels) +
                                       (channels == 1 ? " channel)" : " channels)"));
}

namespace {

// Rows [y_begin, y_end) of a scanline image's subimage `subimage`, MIP level
// `miplevel`, channels [chbegin, chend) as float into `out` (the rows' full
// width), in native strips of native_strip_rows rows converted here: asked
// for float, OpenImageIO 2.4's read_scanlines converts through a buffer of
// about 64 MB (more for a large "tiff:RowsPerStrip"), whatever the image's
// size, allocated on every call.
bool read_float_scanlines(OIIO::ImageInput& in, const OIIO::ImageSpec& spec, int subimage, int miplevel, int chbegin,
                          int chend, int y_begin, int y_end, float* out)
{
    const int nch = chend - chbegin;
    const std::size_t width = static_cast<std::size_t>(spec.width);
    const std::size_t out_row = width * static_cast<std::size_t>(nch);
    const int rows = native_strip_rows(spec);
    const bool uniform = spec.channelformats.empty();
    std::vector<char> strip;
    for (int y = y_begin; y < y_end; y += rows) {
        const int end = std::min(y_end, y + rows);
        const int h = end - y;
        float* dst = out + static_cast<std::size_t>(y - y_begin) * out_row;
        if (uniform && spec.format == OIIO::TypeDesc::FLOAT) {
            if (!in.read_scanlines(subimage, miplevel, spec.y + y, spec.y + end, 0, chbegin, chend,
                                   OIIO::TypeDesc::UNKNOWN, dst))
                return false;
            continue;
        }
        // Mixed channel types are read and converted a channel at a time.
        const int groups = uniform ? 1 : nch;
        for (int g = 0; g < groups; ++g) {
            const int c0 = uniform ? chbegin : chbegin + g, c1 = uniform ? chend : c0 + 1;
            const OIIO::TypeDesc type = uniform ? spec.format : spec.channelformat(c0);
            const std::size_t pixel = spec.pixel_bytes(c0, c1, true);
            strip.resize(width * static_cast<std::size_t>(h) * pixel);
            if (!in.read_scanlines(subimage, miplevel, spec.y + y, spec.y + end, 0, c0, c1, OIIO::TypeDesc::UNKNOWN,
                                   strip.data()))
                return false;
            const OIIO::stride_t fx = sizeof(float) * static_cast<OIIO::stride_t>(nch);
            if (!OIIO::convert_image(c1 - c0, spec.width, h, 1, strip.data(), type, OIIO::AutoStride, OIIO::AutoStride,
                                     OIIO::AutoStride, dst + (c0 - chbegin), OIIO::TypeDesc::FLOAT, fx, fx * spec.width,
                                     OIIO::AutoStride))
                return false;
        }
    }
    return true;
}

// Rows [window.y, window.y + window.height) of subimage 0, level 0 of `in`,
// all channels, as float, a strip of native rows (a row of tiles) at a time,
// keeping columns [window.x, window.x + window.width) in `out`.
bool read_float_window(OIIO::ImageInput& in, const ImageWindow& window, float* out)
{
    const OIIO::ImageSpec spec = in.spec(0, 0);
    const int nch = spec.nchannels;
    const std::size_t width = static_cast<std::size_t>(spec.width);
    const int end = window.y + window.height;
    // The whole width of a scanline image: straight into `out`.
    if (spec.tile_width <= 0 && window.x == 0 && window.width == spec.width)
        return read_float_scanlines(in, spec, 0, 0, 0, nch, window.y, end, out);
    const int rows = native_strip_rows(spec);
    const int first = spec.tile_width > 0 ? window.y - window.y % rows : window.y;
    std::vector<float> strip;
    for (int y = first; y < end; y += rows) {
        const int y1 = std::min(spec.height, y + rows);
        strip.resize(width * static_cast<std::size_t>(y1 - y) * static_cast<std::size_t>(nch));
        // Tiled images: a row of tiles, read and converted by the library
        // itself (its read_scanlines would divide by a strip height of 0).
        const bool read = spec.tile_width > 0 ? in.read_tiles(0, 0, spec.x, spec.x + spec.width, spec.y + y,
                                                              spec.y + y1, spec.z, spec.z + std::max(spec.depth, 1), 0,
                                                              nch, OIIO::TypeDesc::FLOAT, strip.data())
                                              : read_float_scanlines(in, spec, 0, 0, 0, nch, y, y1, strip.data());
        if (!read) return false;
        for (int row = std::max(y, window.y); row < std::min(y1, end); ++row) {
            const float* src = strip.data() + (static_cast<std::size_t>(row - y) * width + window.x) * nch;
            std::copy_n(src, static_cast<std::size_t>(window.width) * nch,
                        out + static_cast<std::size_t>(row - window.y) * window.width * nch);
        }
    }
    return true;
}

}  // namespace

bool read_float_pixels(OIIO::ImageInput& in, int subimage, int miplevel, int chbegin, int chend, float* out)
{
    const OIIO::ImageSpec spec = in.spec(subimage, miplevel);
    // Tiled images are read a row of tiles at a time by the library itself
    // (its read_scanlines would divide by a strip height of 0 on them).
    if (spec.tile_width > 0) return in.read_image(subimage, miplevel, chbegin, chend, OIIO::TypeDesc::FLOAT, out);
    return read_float_scanlines(in, spec, subimage, miplevel, chbegin, chend, 0, spec.height, out);
}

Expected<ImageData> read_image(const std::string& path) { return read_image(path, nullptr); }

Expected<ImageData> read_image(const std::string& path, const ImageWindowChoice& choose)
{
    auto opened = open_image_input(path);
    if (!opened) return opened.error();
    auto& in = *opened;
    const OIIO::ImageSpec& spec = in->spec();
    ImageData img;
    img.width = spec.width;
    img.height = spec.height;
    img.channels = spec.nchannels;
    img.channel_names = spec.channelnames;
    img.format = in->format_name();
    img.pixel_type = spec.format.c_str();
    img.is_float = spec.format.basetype == OIIO::TypeDesc::HALF || spec.format.basetype == OIIO::TypeDesc::FLOAT ||
                   spec.format.basetype == OIIO::TypeDesc::DOUBLE;
    // colorInteropID (the OpenEXR / OpenImageIO 3 convention) and cmfilter's
    // own record win over oiio:ColorSpace, which OpenImageIO 2.4 reports as
    // "Linear" for any EXR (its writer drops it) and "sRGB" for most PNGs.
    img.colorspace_attr = spec.get_string_attribute("colorInteropID");
    if (img.colorspace_attr.empty()) img.colorspace_attr = spec.get_string_attribute("cmfilter:linear_space");
    if (img.colorspace_attr.empty())  // OpenEXR's chromaticities of a space the built-in config knows
        if (const OIIO::ParamValue* c =
                spec.find_attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8))) {
            Chromaticities xy;
            std::copy_n(static_cast<const float*>(c->data()), xy.size(), xy.begin());
            img.colorspace_attr = interop_id_of_chromaticities(xy);
        }
    img.oiio_colorspace = spec.get_string_attribute("oiio:ColorSpace");
    img.gamma_attr = spec.get_float_attribute("oiio:Gamma", 0.0f);
    if (auto fits = check_image_allocation(spec, path, img.channels); !fits) return fits.error();
    img.window = {0, 0, img.width, img.height};
    if (choose) {
        auto window = choose(img);
        if (!window) return window.error();
        const ImageWindow& w = *window;
        if (w.x < 0 || w.y < 0 || w.width <= 0 || w.height <= 0 || w.width > img.width - w.x ||
            w.height > img.height - w.y) {
            std::ostringstream msg;
            msg << "window " << w.width << " x " << w.height << " at (" << w.x << ", " << w.y << ") is outside '"
                << path << "' (" << img.width << " x " << img.height << ")";
            return bad_input(msg.str(), "ImageWindow");
        }
        img.window = w;
    }
    const ImageWindow& w = img.window;
    img.pixels.resize(static_cast<std::size_t>(w.width) * w.height * img.channels);
    const bool whole = w.width == img.width && w.height == img.height;
    if (!(whole ? read_float_pixels(*in, 0, 0, 0, img.channels, img.pixels.data())
                : read_float_window(*in, w, img.pixels.data()))) {
        std::string why = in->geterror();
        return io_error("cannot read the pixels of '" + path + "': " + why);
    }
    return img;
}

}  // namespace cmfilter
