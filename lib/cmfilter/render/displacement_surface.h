// SPDX-License-Identifier: Apache-2.0
// A surface coloured by a textured displacement's layers (scene.h;
// displacement_texture.h), for `render` (layered_surface.h): each probe's
// footprint from the texture's moments (nothing it resolves is taken as
// shadowing geometry, V_r = 1), its slope layer from the texture's own
// slopes and heights (microsurface_albedo.h); the ray-traced methods trace
// its texels as a heightfield.
#pragma once

#include "cmfilter/render/surface_renderer.h"

namespace cmfilter {

Expected<std::unique_ptr<SurfaceRenderer>>
make_displacement_renderer(const DisplacementDriver& driver, std::size_t surface, const RenderOptions& options);

}  // namespace cmfilter
