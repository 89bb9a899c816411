// SPDX-License-Identifier: Apache-2.0
// The angle between a fit's normals (fit_normals.h) and reference normals,
// such as the true mean normals make-stack writes for its synthetic
// surfaces, per texel in degrees.
#pragma once

#include "cmfilter/color/error_summary.h"
#include "cmfilter/stack/fit_normals.h"
#include "cmfilter/util/error.h"

#include <string>
#include <vector>

namespace cmfilter {

// `reference`: width * height * 3 floats (any length > 0 per texel; texels
// whose reference is zero or non-finite are skipped). BadInput when the sizes
// differ, or when no texel has a usable reference.
Expected<ErrorSummary> normal_angle_error(const FitNormals& normals, const std::vector<float>& reference, int width,
                                          int height);

// A normals image (three channels, X Y Z in the stack's frame): a
// make-stack normals file, or one `normals` wrote. Io / BadInput naming it.
Expected<std::vector<float>> read_normals_image(const std::string& path, int& width, int& height);

}  // namespace cmfilter
