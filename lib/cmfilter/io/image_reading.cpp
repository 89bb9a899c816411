// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/image_reading.h"

#include <OpenImageIO/imageio.h>

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
    img.pixels.resize(static_cast<std::size_t>(img.width) * img.height * img.channels);
    if (!in->read_image(0, 0, 0, img.channels, OIIO::TypeDesc::FLOAT, img.pixels.data())) {
        std::string why = in->geterror();
        return io_error("cannot read the pixels of '" + path + "': " + why);
    }
    return img;
}

}  // namespace cmfilter
