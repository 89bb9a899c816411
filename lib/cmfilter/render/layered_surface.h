// SPDX-License-Identifier: Apache-2.0
// What a Gaussian microsurface's and a textured displacement's surfaces
// share in `render` (surface_renderer.h; secs. 5-6): colours by layers
// (microsurface_colors.h) masked and shadowed.
//   The one-ray methods cut the centre ray's footprint, the parallelogram of
//   its ray differentials, along its longer edge into up to max_probes
//   pieces (anisotropic_probes.h), take each piece's unresolved footprint
//   (the kind's own: microsurface_footprint.h, or the displacement's
//   moments) and colour its layers (microsurface_albedo.h); V and the layers
//   are averaged over the pieces and combined with the base layer's colour,
//   filtered over the whole footprint as a driver's (naive, or gaussian).
//   The ray-traced methods trace the displaced plane and its shadow ray
//   (displaced_plane_sample.h) through the kind's heightfield, colour each
//   hit by the combination, and estimate the albedo per pixel
//   (docs/microsurface.md).
#pragma once

#include "cmfilter/microsurface/displacement_slope_color.h"
#include "cmfilter/microsurface/heightfield_tracer.h"
#include "cmfilter/microsurface/microsurface_footprint.h"
#include "cmfilter/render/surface_renderer.h"

#include <optional>

namespace cmfilter {

class LayeredSurfaceRenderer : public SurfaceRenderer {
public:
    FilteredHit filter(const SurfaceHit& hit, const RenderContext& context, HitScratch& scratch) const override;
    void sample(const CameraRay& ray, const SurfaceHit& hit, const RenderContext& context,
                PixelSamples& pixel) const override;

protected:
    // `displacement`: a textured displacement's own slopes and heights for
    // its slope layer (microsurface_layers); null on a Gaussian microsurface.
    // `method`: the surface's own (layered_method), which sets how its D_h
    // and D_s are represented for the one-ray methods.
    LayeredSurfaceRenderer(std::size_t surface, const MicrosurfaceColors& colors, std::unique_ptr<DriverRenderer> base,
                           const DisplacementTexture* displacement, RenderMethod method);

    // The unresolved footprint over one piece and its resolved mean slope
    // (needed with a slope map).
    virtual void filter_piece(const FootprintPiece& piece, MicrosurfaceFootprint& footprint,
                              ResolvedSlope& slope) const = 0;

    std::size_t surface_;
    const MicrosurfaceColors& colors_;
    std::unique_ptr<DriverRenderer> base_;  // null: no base layer
    const DisplacementTexture* displacement_;
    HeightRepresentation heights_;
    SlopeRepresentation slopes_;
    // The ray-traced methods' heightfield (prepare_tracing) and
    // trace_displaced_plane's shift for it.
    std::optional<Heightfield> heightfield_;
    double heightfield_shift_ = 0;
};

// The method a layered surface renders by: its entry of
// RenderOptions::microsurface_methods, else RenderOptions::method.
RenderMethod layered_method(const RenderOptions& options, std::size_t surface);

// How a one-ray method represents a microsurface's height filtering
// distribution (height_filtered_albedo.h) and its slope filtering
// distribution (microsurface_albedo.h).
HeightRepresentation height_representation(RenderMethod method);
SlopeRepresentation slope_representation(RenderMethod method);

// The base layer's renderer (none without one), coloured naive for the
// naive `method` (the surface's, layered_method) and gaussian otherwise.
Expected<std::unique_ptr<DriverRenderer>> make_base_renderer(const std::shared_ptr<const Material>& base,
                                                             std::size_t surface, const RenderOptions& options,
                                                             RenderMethod method);

}  // namespace cmfilter
