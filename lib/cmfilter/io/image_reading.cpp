// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/image_reading.h"

#include "cmfilter/util/memory_budget.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
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

Status check_image_allocation(const OIIO::ImageSpec& spec, const std::string& path, int channels, int copies)
{
    // The floats, and the buffer of native rows the image library converts
    // them from: it allocates 256 rows (its "read_chunk"), however few the
    // image has, or a row of tiles.
    const double rows = std::max(256, spec.tile_height);
    const double bytes = double(spec.width) * double(spec.height) * double(channels) * sizeof(float) * copies +
                         double(spec.width) * rows * double(spec.pixel_bytes(true));
    return check_allocation(bytes, "'" + path + "' (" + std::to_string(spec.width) + " x " +
                                       std::to_string(spec.height) + " pixels, " + std::to_string(channels) +
                                       (channels == 1 ? " channel)" : " channels)"));
}

bool read_float_pixels(OIIO::ImageInput& in, int subimage, int miplevel, int chbegin, int chend, float* out)
{
    const OIIO::ImageSpec spec = in.spec(subimage, miplevel);
    // Tiled images are read a row of tiles at a time by the library itself
    // (its read_scanlines would divide by a strip height of 0 on them).
    if (spec.tile_width > 0) return in.read_image(subimage, miplevel, chbegin, chend, OIIO::TypeDesc::FLOAT, out);
    const std::size_t row = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(chend - chbegin);
    constexpr std::size_t kStripValues = std::size_t(4) << 20;  // 16 MB of floats
    const int rows = static_cast<int>(std::max<std::size_t>(
        1, std::min<std::size_t>(kStripValues / std::max<std::size_t>(row, 1), std::size_t(spec.height))));
    for (int y = 0; y < spec.height; y += rows) {
        const int end = std::min(spec.height, y + rows);
        if (!in.read_scanlines(subimage, miplevel, spec.y + y, spec.y + end, 0, chbegin, chend, OIIO::TypeDesc::FLOAT,
                               out + static_cast<std::size_t>(y) * row))
            return false;
    }
    return true;
}

Expected<ImageData> read_image(const std::string& path)
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
    // colorInteropID (the OpenEXR / OpenImageIO 3 convention) wins over
    // oiio:ColorSpace, which OpenImageIO 2.4 reports as "Linear" for any EXR.
    img.colorspace_attr = spec.get_string_attribute("colorInteropID");
    if (img.colorspace_attr.empty()) img.colorspace_attr = spec.get_string_attribute("oiio:ColorSpace");
    img.gamma_attr = spec.get_float_attribute("oiio:Gamma", 0.0f);
    if (auto fits = check_image_allocation(spec, path, img.channels); !fits) return fits.error();
    img.pixels.resize(static_cast<std::size_t>(img.width) * img.height * img.channels);
    if (!read_float_pixels(*in, 0, 0, 0, img.channels, img.pixels.data())) {
        std::string why = in->geterror();
        return io_error("cannot read the pixels of '" + path + "': " + why);
    }
    return img;
}

}  // namespace cmfilter
