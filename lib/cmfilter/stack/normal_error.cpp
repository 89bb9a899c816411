// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/normal_error.h"

#include "cmfilter/io/image_reading.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cmfilter {

Expected<ErrorSummary> normal_angle_error(const FitNormals& normals, const std::vector<float>& reference, int width,
                                          int height)
{
    if (normals.width != width || normals.height != height) {
        std::ostringstream msg;
        msg << "the normals are " << normals.width << "x" << normals.height << " but the reference normals are "
            << width << "x" << height << "; expected the same size";
        return bad_input(msg.str());
    }
    std::vector<double> angles;
    angles.reserve(static_cast<std::size_t>(width) * height);
    for (std::size_t t = 0; t < static_cast<std::size_t>(width) * height; ++t) {
        const float* a = &normals.normals[3 * t];
        const float* b = &reference[3 * t];
        const double la = std::sqrt(double(a[0]) * a[0] + double(a[1]) * a[1] + double(a[2]) * a[2]);
        const double lb = std::sqrt(double(b[0]) * b[0] + double(b[1]) * b[1] + double(b[2]) * b[2]);
        if (!(la > 0) || !(lb > 0) || !std::isfinite(la) || !std::isfinite(lb)) continue;
        // atan2 of |a x b| and a.b: accurate at small angles too.
        const double cx = double(a[1]) * b[2] - double(a[2]) * b[1];
        const double cy = double(a[2]) * b[0] - double(a[0]) * b[2];
        const double cz = double(a[0]) * b[1] - double(a[1]) * b[0];
        const double d = double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2];
        angles.push_back(std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), d) * 180.0 / 3.14159265358979323846);
    }
    if (angles.empty())
        return bad_input("the reference normals are zero or non-finite at every texel; expected unit normals (X, Y, "
                         "Z) such as make-stack's normals file");
    return summarize_errors(std::move(angles));
}

Expected<std::vector<float>> read_normals_image(const std::string& path, int& width, int& height)
{
    auto image = read_image(path);
    if (!image) return image.error();
    if (image->channels < 3)
        return bad_input("normals image '" + path + "' has " + std::to_string(image->channels) +
                         " channel(s); expected three (X, Y, Z)");
    width = image->width;
    height = image->height;
    std::vector<float> out(static_cast<std::size_t>(width) * height * 3);
    for (std::size_t t = 0; t < out.size() / 3; ++t)
        for (int c = 0; c < 3; ++c) out[3 * t + c] = image->pixels[t * image->channels + c];
    return out;
}

}  // namespace cmfilter
