// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/microsurface_surface.h"

#include "cmfilter/render/layered_surface.h"

#include <string>

namespace cmfilter {

namespace {

class MicrosurfaceRenderer : public LayeredSurfaceRenderer {
public:
    MicrosurfaceRenderer(const MicrosurfaceDriver& driver, std::size_t surface, std::unique_ptr<DriverRenderer> base,
                         RenderMethod method)
        : LayeredSurfaceRenderer(surface, driver.colors, std::move(base), nullptr, method),
          surface_model_(driver.surface)
    {
    }

    Status prepare_tracing(const RenderContext& context) override
    {
        HeightfieldOptions ho;
        ho.threads = context.options.threads;
        ho.slopes = colors_.slope.has_value();  // the slope map reads them at each hit
        auto field = Heightfield::create(surface_model_, ho);
        if (!field)
            return Error{field.error().kind,
                         context.scene.path + ": /surfaces/" + std::to_string(surface_) +
                             "/material/microsurface: " + std::string(to_string(context.options.method)) +
                             " traces one tile tabulated at 8 texels per shortest wavelength, at most 4096 per "
                             "side (a shorter tile or a longer min_wavelength fits): " +
                             field.error().message};
        heightfield_.emplace(std::move(*field));
        return ok();
    }

protected:
    void filter_piece(const FootprintPiece& p, MicrosurfaceFootprint& footprint, ResolvedSlope& slope) const override
    {
        footprint = filter_microsurface(surface_model_, p.u, p.v, p.e1u, p.e1v, p.e2u, p.e2v);
        if (colors_.slope) slope = resolved_slope(surface_model_, p.u, p.v, p.e1u, p.e1v, p.e2u, p.e2v);
    }

private:
    const GaussianMicrosurface& surface_model_;
};

}  // namespace

Expected<std::unique_ptr<SurfaceRenderer>> make_microsurface_renderer(const MicrosurfaceDriver& driver,
                                                                      std::size_t surface, const RenderOptions& options)
{
    const RenderMethod method = layered_method(options, surface);
    auto base = make_base_renderer(driver.base, surface, options, method);
    if (!base) return base.error();
    return std::unique_ptr<SurfaceRenderer>(
        std::make_unique<MicrosurfaceRenderer>(driver, surface, std::move(*base), method));
}

}  // namespace cmfilter
