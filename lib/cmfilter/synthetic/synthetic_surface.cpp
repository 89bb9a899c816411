// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthetic/synthetic_surface.h"

#include "cmfilter/render/surface_renderer.h"

#include "cmfilter/microsurface/microsurface_albedo.h"
#include "cmfilter/render/layered_surface.h"
#include "cmfilter/scene/scene_loading.h"
#include "cmfilter/scene/scene_materials.h"

#include <algorithm>
#include <variant>

namespace cmfilter {

namespace {

const char* driver_kind(const Material& m)
{
    if (std::holds_alternative<NoiseDriver>(m.driver)) return "a colour map over a noise driver";
    if (std::holds_alternative<TextureDriver>(m.driver)) return "a colour map over a texture driver";
    if (std::holds_alternative<MicrosurfaceDriver>(m.driver)) return "a Gaussian microsurface";
    return "a textured displacement";
}

}  // namespace

const char* to_string(SyntheticSurfaceKind kind)
{
    return kind == SyntheticSurfaceKind::Microsurface ? "microsurface" : "displacement";
}

Expected<SyntheticSurface> SyntheticSurface::load(const SyntheticSurfaceOptions& options, const ColorConfig& config)
{
    auto scene = load_scene(options.scene);
    if (!scene) return scene.error();
    if (options.surface >= scene->surfaces.size())
        return bad_input(scene->path + ": SyntheticSurfaceOptions::surface " + std::to_string(options.surface) +
                             " is invalid: the scene has " + std::to_string(scene->surfaces.size()) +
                             " surface(s), numbered from 0",
                         "SyntheticSurfaceOptions::surface");
    // Only the traced surface's material is loaded: the others may be of
    // any kind, and their tables would be baked for nothing.
    Scene one = *scene;
    one.surfaces = {scene->surfaces[options.surface]};
    const Surface& s = one.surfaces[0];
    if (!s.material.has_microsurface())
        return bad_input(scene->path + ": /surfaces/" + std::to_string(options.surface) +
                             ": make-stack traces a Gaussian microsurface or a textured displacement, but its "
                             "material is a colour map over a " +
                             (s.material.driver.kind == DriverKind::Noise ? "noise" : "texture") + " driver",
                         "SyntheticSurfaceOptions::surface");
    // Messages name the surface by its index in the scene file.
    const auto renamed = [&](Error e) {
        const std::string from = "/surfaces/0", to = "/surfaces/" + std::to_string(options.surface);
        for (std::size_t at = e.message.find(from); at != std::string::npos; at = e.message.find(from, at + to.size()))
            e.message.replace(at, from.size(), to);
        return e;
    };
    MaterialOptions mo;
    mo.threads = options.threads;
    auto materials = prepare_materials(one, config, mo);
    if (!materials) return renamed(materials.error());
    auto made = create(std::make_shared<const Scene>(std::move(one)),
                       std::make_shared<const std::vector<Material>>(std::move(*materials)), 0, options.threads);
    if (!made) return renamed(made.error());
    made->surface_ = options.surface;
    made->scene_ = std::make_shared<const Scene>(std::move(*scene));
    return made;
}

Expected<SyntheticSurface> SyntheticSurface::create(std::shared_ptr<const Scene> scene,
                                                    std::shared_ptr<const std::vector<Material>> materials,
                                                    std::size_t surface, int threads)
{
    const std::string where = scene->path + ": /surfaces/" + std::to_string(surface);
    if (surface >= materials->size() || surface >= scene->surfaces.size())
        return bad_input(where + ": no such surface (the scene has " + std::to_string(scene->surfaces.size()) + ")",
                         "SyntheticSurfaceOptions::surface");
    const Material& material = (*materials)[surface];
    SyntheticSurface s;
    std::shared_ptr<const Material> base;
    if (const auto* d = std::get_if<MicrosurfaceDriver>(&material.driver)) {
        s.kind_ = SyntheticSurfaceKind::Microsurface;
        s.colors_ = &d->colors;
        base = d->base;
        // As render's reference tabulates it (microsurface_surface.cpp).
        HeightfieldOptions ho;
        ho.threads = threads;
        ho.slopes = d->colors.slope.has_value();
        auto field = Heightfield::create(d->surface, ho);
        if (!field)
            return Error{field.error().kind, where +
                                                 "/material/microsurface: one tile tabulated at 8 texels per "
                                                 "shortest wavelength, at most 4096 per side: " +
                                                 field.error().message};
        s.heightfield_ = std::make_shared<const Heightfield>(std::move(*field));
        s.shift_ = 0;
    } else if (const auto* d = std::get_if<DisplacementDriver>(&material.driver)) {
        s.kind_ = SyntheticSurfaceKind::Displacement;
        s.colors_ = &d->colors;
        base = d->base;
        auto field = d->texture.heightfield(threads);
        if (!field)
            return Error{field.error().kind,
                         where +
                             "/material/displacement: its texels are traced as a heightfield, which needs a "
                             "power-of-two size: " +
                             field.error().message};
        s.heightfield_ = std::make_shared<const Heightfield>(std::move(*field));
        s.shift_ = 0.5 / d->texture.size();  // displacement_surface.cpp
    } else {
        return bad_input(where +
                             ": make-stack traces a Gaussian microsurface or a textured displacement, but its "
                             "material is " +
                             driver_kind(material),
                         "SyntheticSurfaceOptions::surface");
    }
    if (base) {
        RenderOptions ro;
        ro.method = RenderMethod::Reference;  // the base layer read at points, as the reference reads it
        ro.threads = threads;
        auto renderer = make_base_renderer(base, surface, ro, ro.method);
        if (!renderer) return prefixed(where + "/material/base: ", renderer.error());
        s.base_ = std::shared_ptr<const DriverRenderer>(std::move(*renderer));
    }
    s.scene_ = std::move(scene);
    s.materials_ = std::move(materials);
    s.surface_ = surface;
    return s;
}

std::optional<SyntheticHit> SyntheticSurface::trace(double u, double v, const Vec3& view) const
{
    const Heightfield& field = *heightfield_;
    // Start above the whole slab, on the ray through (u, v, 0).
    const double top = std::max(field.max_height(), 0.0) + 0.01 * field.tile();
    const Vec3 through{u - shift_, v - shift_, 0};
    const Vec3 origin = through + (top / view.z) * view;
    const auto hit = field.trace(origin, -1.0 * view);
    if (!hit) return std::nullopt;
    // The material's colour at the hit (layered_surface.cpp sample()).
    double sx = 0, sy = 0;
    if (!field.slope(hit->point.x, hit->point.y, sx, sy)) {
        sx = -hit->normal.x / hit->normal.z;
        sy = -hit->normal.y / hit->normal.z;
    }
    std::optional<Rgb> base, height, slope;
    if (base_) base = base_->point_albedo(hit->point.x + shift_, hit->point.y + shift_);
    if (colors_->height) height = colors_->height->map.evaluate(hit->height);
    if (colors_->slope) slope = std::visit([&](const auto& map) { return map.evaluate(sx, sy); }, *colors_->slope);
    return SyntheticHit{hit->point, hit->normal, combine_point_color(colors_->combine, base, height, slope)};
}

bool SyntheticSurface::lit(const SyntheticHit& hit, const Vec3& light) const
{
    return dot(hit.normal, light) > 0 && !heightfield_->occluded(hit.point, light);
}

}  // namespace cmfilter
