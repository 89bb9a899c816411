// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/ops/error_heatmap.h"

#include "cmfilter/io/output_date.h"
#include "cmfilter/util/atomic_output.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

namespace cmfilter {

Rgb8 heatmap_color(double e, double max)
{
    double t = e / max;
    if (!(t > 0.0)) t = 0.0;  // also NaN
    if (t > 1.0) t = 1.0;
    Rgb8 code{};
    for (int k = 0; k < 3; ++k) {
        const double ramp = std::clamp(3.0 * t - k, 0.0, 1.0);
        code[k] = static_cast<unsigned char>(std::lround(255.0 * ramp));
    }
    return code;
}

Status write_heatmap_png(const std::string& path, const HeatmapImage& image)
{
    if (auto st = check_output_path(path, ".png"); !st) return st;
    const std::size_t n = static_cast<std::size_t>(image.width) * image.height;
    if (!image.errors || image.errors->size() != n)
        return runtime_error("heat map of " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                             " pixels was given the wrong number of errors");
    std::vector<unsigned char> codes(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const Rgb8 c = heatmap_color((*image.errors)[i], image.max);
        std::copy(c.begin(), c.end(), codes.begin() + 3 * i);
    }

    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    if (!image.description.empty()) spec.attribute("ImageDescription", image.description);
    auto writer = OIIO::ImageOutput::create(out->temp_path());
    if (!writer) return runtime_error("OpenImageIO cannot write PNG: " + OIIO::geterror());
    if (auto st = set_output_date(spec, *writer); !st) return st;
    if (!writer->open(out->temp_path(), spec) || !writer->write_image(OIIO::TypeDesc::UINT8, codes.data()) ||
        !writer->close())
        return out->write_error(writer->geterror());
    return out->commit();
}

}  // namespace cmfilter
