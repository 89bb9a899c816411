// SPDX-License-Identifier: Apache-2.0
// The renderer of a noise or texture material (surface_renderer.h), as a
// microsurface's base layer needs it: filtered over a footprint and read at
// a point.
#pragma once

#include "cmfilter/render/surface_renderer.h"

namespace cmfilter {

// A noise's or a texture's renderer coloured by `colour_method` (a
// microsurface's base layer: naive or gaussian), refused as
// make_surface_renderer refuses it for options.method; BadInput for a
// microsurface material.
Expected<std::unique_ptr<DriverRenderer>> make_driver_renderer(const Material& material, std::size_t surface,
                                                               RenderMethod colour_method,
                                                               const RenderOptions& options);

}  // namespace cmfilter
