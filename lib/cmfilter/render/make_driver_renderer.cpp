// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/make_driver_renderer.h"

#include "cmfilter/render/noise_surface.h"
#include "cmfilter/render/texture_surface.h"

#include <string>
#include <variant>

namespace cmfilter {

Expected<std::unique_ptr<DriverRenderer>> make_driver_renderer(const Material& material, std::size_t surface,
                                                               RenderMethod colour_method, const RenderOptions& options)
{
    if (const auto* noise = std::get_if<NoiseDriver>(&material.driver))
        return make_noise_renderer(material.color, *noise, surface, colour_method, options.sub_footprints,
                                   max_probes_of(options, surface));
    if (const auto* texture = std::get_if<TextureDriver>(&material.driver))
        return make_texture_renderer(material, *texture, surface, colour_method, options);
    return bad_input("render: surface " + std::to_string(surface) +
                     ": a base layer needs a noise or texture driver, not a microsurface");
}

}  // namespace cmfilter
