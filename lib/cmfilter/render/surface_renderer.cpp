#include "cmfilter/render/surface_renderer.h"

#include "cmfilter/render/displacement_surface.h"
#include "cmfilter/render/microsurface_surface.h"
#include "cmfilter/render/noise_surface.h"
#include "cmfilter/render/texture_surface.h"

#include <type_traits>
#include <variant>

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

namespace {

template <typename Made, typename Renderer>
Expected<std::unique_ptr<Renderer>> as_renderer(Expected<std::unique_ptr<Made>> made)
{
    if (!made) return made.error();
    return std::unique_ptr<Renderer>(std::move(*made));
}

}  // namespace

Expected<std::unique_ptr<SurfaceRenderer>> make_surface_renderer(const Material& material, std::size_t surface,
                                                                 const RenderOptions& options)
{
    using Made = Expected<std::unique_ptr<SurfaceRenderer>>;
    return std::visit(
        [&](const auto& driver) -> Made {
            using Driver = std::decay_t<decltype(driver)>;
            if constexpr (std::is_same_v<Driver, NoiseDriver>)
                return as_renderer<DriverRenderer, SurfaceRenderer>(
                    make_noise_renderer(material.color, driver, surface, options.method));
            else if constexpr (std::is_same_v<Driver, TextureDriver>)
                return as_renderer<DriverRenderer, SurfaceRenderer>(
                    make_texture_renderer(material, driver, surface, options.method, options));
            else if constexpr (std::is_same_v<Driver, MicrosurfaceDriver>)
                return make_microsurface_renderer(driver, surface, options);
            else {
                static_assert(std::is_same_v<Driver, DisplacementDriver>, "a driver kind without its renderer");
                return make_displacement_renderer(driver, surface, options);
            }
        },
        material.driver);
}

Expected<std::unique_ptr<DriverRenderer>> make_driver_renderer(const Material& material, std::size_t surface,
                                                               RenderMethod colour_method,
                                                               const RenderOptions& options)
{
    if (const auto* noise = std::get_if<NoiseDriver>(&material.driver))
        return make_noise_renderer(material.color, *noise, surface, colour_method);
    if (const auto* texture = std::get_if<TextureDriver>(&material.driver))
        return make_texture_renderer(material, *texture, surface, colour_method, options);
    return bad_input("render: surface " + std::to_string(surface) +
                     ": a base layer needs a noise or texture driver, not a microsurface");
}

}  // namespace cmfilter
