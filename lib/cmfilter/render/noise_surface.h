// SPDX-License-Identifier: Apache-2.0
// A surface coloured by C0 over a procedural noise (filtered_noise.h), for
// `render` (surface_renderer.h). The one-ray methods filter the noise over
// the centre ray's footprint (surface_hit.h), cut along its major edge into
// up to max_probes pieces (anisotropic_probes.h), each one width
// (footprint_width.h): naive C0(mean), gaussian T(mean, sigma) (eq. 10;
// C0(mean) below the small-sigma shortcut, gaussian_albedo.h), mixture the
// same over each piece's sub-footprints in the transition
// (noise_sub_footprints.h), averaged over the pieces. The ray-traced methods point-evaluate C0(f(x)) at each hit.
// exact is refused: a noise has no exact filtering distribution.
#pragma once

#include "cmfilter/render/surface_renderer.h"

namespace cmfilter {

// `squares`: mixture's sub-footprints (checked by the caller).
Expected<std::unique_ptr<DriverRenderer>> make_noise_renderer(const ColorLayer& color, const NoiseDriver& driver,
                                                              std::size_t surface, RenderMethod colour_method,
                                                              const SubFootprintOptions& squares, int max_probes);

}  // namespace cmfilter
