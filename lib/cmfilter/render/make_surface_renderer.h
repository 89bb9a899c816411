// SPDX-License-Identifier: Apache-2.0
// The renderer of a surface for its material's driver kind
// (surface_renderer.h): the one dispatch over the kinds of material.h.
#pragma once

#include "cmfilter/render/surface_renderer.h"

namespace cmfilter {

// The renderer of surface `surface`'s material for options.method. The
// errors render() documents for a material: exact on a noise driver or a
// texture without its histogram pyramid (BadInput), supersample or reference
// on a texture without its level 0 (Io, naming it).
Expected<std::unique_ptr<SurfaceRenderer>> make_surface_renderer(const Material& material, std::size_t surface,
                                                                 const RenderOptions& options);

}  // namespace cmfilter
