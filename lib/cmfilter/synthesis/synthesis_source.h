// SPDX-License-Identifier: Apache-2.0
// What synth-apply renders through a coordinate map: one image of the
// sample (an image, a stack's image, a BTF view's image) or a fit of it
// (PTM, HSH, Lafortune: stack_fit.h) relit at a light and view, as a
// SampleImage of the sample's size.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/math/vec3.h"
#include "cmfilter/synthesis/coordinate_lookup.h"
#include "cmfilter/util/error.h"

#include <optional>
#include <string>

namespace cmfilter {

struct SourceOptions {
    std::string path;  // an image, a `.lp`, a BTF manifest, or a fit (.ptm, .rti, a fit EXR)
    // The sample's image by its index across the sample (a BTF: over every
    // view, in order); -1: by `light` (and `view`), else image 0.
    int image = -1;
    std::optional<Vec3> light;  // a stack: the image lit from it (within 1e-3); a fit: relit there
    std::optional<Vec3> view;   // a BTF: the view slot (within 1e-3); a Lafortune fit: rendered from it
    std::string colorspace;     // the images' colour space, as SampleOptions::colorspace
    bool periodic = false;
    int threads = 0;
};

struct SourceImage {
    SampleImage image;
    std::string description;  // "image 3 of stack.lp (light 0.5, 0, 0.87)", "ptm-rgb fit.ptm relit at .."
    bool is_fit = false;
    std::string colorspace;  // the values' space: scene-linear (a .ptm/.rti decoded), or a data space
};

// Io / BadInput as the readers; BadInput naming the field and value:
// SourceOptions::image outside the sample, a light or view none of the
// stack's images has, a light below the horizon, a view for a linear fit.
Expected<SourceImage> load_source_image(const SourceOptions& options, const ColorConfig& config);

// Whether `path` is a fit rather than a sample, as load_source_image decides:
// a .ptm, an .rti, or an EXR whose cmfilter:kind is a fit's. Io when an EXR
// cannot be opened.
Expected<bool> is_fit_source(const std::string& path);

}  // namespace cmfilter
