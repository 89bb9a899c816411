// SPDX-License-Identifier: Apache-2.0
// A surface coloured by C0 over a texture driver (filtered_texture.h), for
// `render` (surface_renderer.h): the one-ray methods filter its pyramids
// over the centre ray's footprint (texture_footprint.h: naive, gaussian, and
// exact from the histogram pyramid); the ray-traced methods read f bilinear
// in its level 0 at each hit, and so refuse a texture without it.
#pragma once

#include "cmfilter/render/surface_renderer.h"

namespace cmfilter {

// `material` holds `driver` (its C0 and the provenance naming a missing
// level 0).
Expected<std::unique_ptr<DriverRenderer>> make_texture_renderer(const Material& material, const TextureDriver& driver,
                                                                std::size_t surface, RenderMethod colour_method,
                                                                const RenderOptions& options);

}  // namespace cmfilter
