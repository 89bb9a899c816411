#include "cmfilter/filtered_image_file.h"

#include "cmfilter/atomic_output.h"
#include "cmfilter/metadata.h"
#include "cmfilter/version.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace cmfilter {

namespace {

std::string lower_extension(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

}  // namespace

Status check_filtered_image_output(const std::string& path)
{
    const std::string ext = lower_extension(path);
    if (ext != ".exr" && ext != ".png" && ext != ".jpg" && ext != ".jpeg")
        return bad_input("output '" + path +
                         "' has the wrong extension (expected .exr, .png, .jpg or .jpeg)");
    return check_output_path(path, "");
}

Status write_filtered_image(const std::string& path, const FilteredImage& image,
                            const ColorConfig& config)
{
    if (auto st = check_filtered_image_output(path); !st) return st;
    const bool exr = lower_extension(path) == ".exr";
    OIIO::ImageSpec spec(image.width, image.height, 3, exr ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    spec.attribute("cmfilter:kind", kFilteredImageKind);
    spec.attribute("cmfilter:version", version());
    spec.attribute("cmfilter:method", to_string(image.method));
    set_double_attribute(spec, "cmfilter:lod", image.lod);
    set_double_attribute(spec, "cmfilter:lod_requested", image.lod_requested);
    spec.attribute("cmfilter:moments", image.moments_path);
    spec.attribute("cmfilter:table", image.table_path);
    spec.attribute("cmfilter:driver_source", image.moments.source);
    if (!image.map_path.empty()) spec.attribute("cmfilter:map", image.map_path);
    if (!image.driver_path.empty()) spec.attribute("cmfilter:driver", image.driver_path);
    if (!image.histograms_path.empty()) spec.attribute("cmfilter:histograms", image.histograms_path);

    std::vector<unsigned char> codes;
    if (exr) {
        spec.attribute("compression", "zip");
        spec.attribute("oiio:ColorSpace", image.linear_space);
    } else {
        // Scene-linear -> sRGB encoding through OpenColorIO, then 8-bit codes.
        auto srgb = config.resolve("sRGB");
        if (!srgb) return srgb.error();
        std::vector<float> encoded = image.rgb;
        if (auto st = config.from_scene_linear(encoded, *srgb); !st) return st;
        codes.resize(encoded.size());
        for (std::size_t i = 0; i < encoded.size(); ++i) {
            float v = encoded[i];
            if (!(v > 0.0f)) v = 0.0f;  // also NaN
            if (v > 1.0f) v = 1.0f;
            codes[i] = static_cast<unsigned char>(std::lround(255.0f * v));
        }
        spec.attribute("oiio:ColorSpace", "sRGB");
        spec.attribute("cmfilter:encoding", *srgb);
    }

    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();
    auto writer = OIIO::ImageOutput::create(out->temp_path());
    if (!writer) return runtime_error("OpenImageIO cannot write '" + path + "': " + OIIO::geterror());
    if (!writer->open(out->temp_path(), spec) ||
        !(exr ? writer->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data())
              : writer->write_image(OIIO::TypeDesc::UINT8, codes.data())) ||
        !writer->close()) {
        std::string why = writer->geterror();
        return io_error("cannot write '" + path + "': " + why);
    }
    return out->commit();
}

}  // namespace cmfilter
