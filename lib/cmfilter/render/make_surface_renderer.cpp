// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/make_surface_renderer.h"

#include "cmfilter/render/displacement_surface.h"
#include "cmfilter/render/layered_surface.h"
#include "cmfilter/render/microsurface_surface.h"
#include "cmfilter/render/noise_surface.h"
#include "cmfilter/render/texture_surface.h"

#include <type_traits>
#include <variant>

namespace cmfilter {

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
            if constexpr (std::is_same_v<Driver, NoiseDriver>) {
                const int chosen = surface < options.noise_sub_footprints.size() ? options.noise_sub_footprints[surface]
                                                                                 : 0;
                SubFootprintOptions squares = options.sub_footprints;
                if (chosen > 0) squares.max_cells = chosen;
                return as_renderer<DriverRenderer, SurfaceRenderer>(make_noise_renderer(
                    material.color, driver, surface, chosen > 0 ? RenderMethod::Mixture : options.method, squares,
                    max_probes_of(options, surface)));
            } else if constexpr (std::is_same_v<Driver, TextureDriver>)
                return as_renderer<DriverRenderer, SurfaceRenderer>(make_texture_renderer(
                    material, driver, surface,
                    surface < options.texture_methods.size() ? options.texture_methods[surface] : options.method,
                    options));
            else if (const RenderMethod layered = layered_method(options, surface);
                     layered == RenderMethod::ColorPyramid || layered == RenderMethod::Segments)
                return bad_input("render: surface " + std::to_string(surface) + ": " + to_string(layered) +
                                 " needs a texture driver; a microsurface's colours come from its "
                                 "heights and slopes (render it by gaussian, gaussian-exact or exact)");
            else if constexpr (std::is_same_v<Driver, MicrosurfaceDriver>)
                return make_microsurface_renderer(driver, surface, options);
            else {
                static_assert(std::is_same_v<Driver, DisplacementDriver>, "a driver kind without its renderer");
                return make_displacement_renderer(driver, surface, options);
            }
        },
        material.driver);
}

}  // namespace cmfilter
