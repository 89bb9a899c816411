// SPDX-License-Identifier: Apache-2.0
// A surface coloured by a Gaussian microsurface's layers (sec. 5;
// gaussian_microsurface.h), for `render` (layered_surface.h): each probe's
// footprint filtered exactly over the microsurface's cosines
// (microsurface_footprint.h); the ray-traced methods trace one tile
// tabulated as a heightfield (heightfield_tracer.h).
#pragma once

#include "cmfilter/render/surface_renderer.h"

namespace cmfilter {

Expected<std::unique_ptr<SurfaceRenderer>>
make_microsurface_renderer(const MicrosurfaceDriver& driver, std::size_t surface, const RenderOptions& options);

}  // namespace cmfilter
