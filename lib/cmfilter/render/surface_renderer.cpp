// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/surface_renderer.h"

namespace cmfilter {

void DriverRenderer::sample(const CameraRay&, const SurfaceHit& h, const RenderContext& context,
                            PixelSamples& pixel) const
{
    const Rgb c = shade(point_albedo(h.u, h.v), h.normal, context.scene.light);
    pixel.sum += c;
    pixel.shaded_sum += c;
    ++pixel.hits;
    pixel.distance += h.t;
}

}  // namespace cmfilter
