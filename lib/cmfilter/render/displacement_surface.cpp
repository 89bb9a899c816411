// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/displacement_surface.h"

#include "cmfilter/render/layered_surface.h"

#include <string>

namespace cmfilter {

namespace {

class DisplacementRenderer : public LayeredSurfaceRenderer {
public:
    DisplacementRenderer(const DisplacementDriver& driver, std::size_t surface, std::unique_ptr<DriverRenderer> base,
                         RenderMethod method)
        : LayeredSurfaceRenderer(surface, driver.colors, std::move(base), &driver.texture, method),
          texture_(driver.texture)
    {
    }

    Status prepare_tracing(const RenderContext& context) override
    {
        auto field = texture_.heightfield(context.options.threads);
        heightfield_shift_ = 0.5 / texture_.size();
        if (!field)
            return Error{
                field.error().kind,
                context.scene.path + ": /surfaces/" + std::to_string(surface_) +
                    "/material/displacement: " + std::string(to_string(context.options.method)) +
                    " traces the texels as a heightfield, which needs a power-of-two size: " + field.error().message};
        heightfield_.emplace(std::move(*field));
        return ok();
    }

protected:
    void filter_piece(const FootprintPiece& p, MicrosurfaceFootprint& f, ResolvedSlope& slope) const override
    {
        // The texture's moments over the piece: nothing it resolves is taken
        // as shadowing geometry (V_r = 1).
        const DisplacementFootprint d = texture_.footprint(p.u, p.v, p.e1u, p.e1v, p.e2u, p.e2v);
        f.mean_height = d.mean_height;
        f.sigma_h = d.sigma_h;
        f.slope_xx = d.slope_xx;
        f.slope_xy = d.slope_xy;
        f.slope_yy = d.slope_yy;
        slope = {d.slope_x, d.slope_y};
    }

private:
    const DisplacementTexture& texture_;
};

}  // namespace

Expected<std::unique_ptr<SurfaceRenderer>> make_displacement_renderer(const DisplacementDriver& driver,
                                                                      std::size_t surface, const RenderOptions& options)
{
    const RenderMethod method = layered_method(options, surface);
    auto base = make_base_renderer(driver.base, surface, options, method);
    if (!base) return base.error();
    return std::unique_ptr<SurfaceRenderer>(
        std::make_unique<DisplacementRenderer>(driver, surface, std::move(*base), method));
}

}  // namespace cmfilter
