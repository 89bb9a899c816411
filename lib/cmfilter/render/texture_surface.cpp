// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/texture_surface.h"

#include "cmfilter/colormap/map_breakpoints.h"
#include "cmfilter/render/texture_footprint.h"

#include <optional>
#include <string>
#include <utility>

namespace cmfilter {

namespace {

// What a texture driver's probes colour for a method (texture_footprint.h).
TextureColor texture_color(RenderMethod method)
{
    switch (method) {
    case RenderMethod::Naive: return TextureColor::Naive;
    case RenderMethod::Gaussian:
    case RenderMethod::GaussianExact: return TextureColor::Gaussian;
    case RenderMethod::Exact: return TextureColor::Exact;
    case RenderMethod::Mixture: return TextureColor::Mixture;
    case RenderMethod::ColorPyramid: return TextureColor::ColorPyramid;
    case RenderMethod::Segments: return TextureColor::Segments;
    default: return TextureColor::None;
    }
}

class TextureRenderer : public DriverRenderer {
public:
    TextureRenderer(const ColorLayer& color, const TextureDriver& driver, RenderMethod method,
                    std::vector<Rgb> bin_colors, std::optional<ColorPyramid> color_pyramid, TextureSegments segments,
                    int max_probes)
        : color_(color), driver_(driver), method_(method), bin_colors_(std::move(bin_colors)),
          color_pyramid_(std::move(color_pyramid)), segments_(std::move(segments)), max_probes_(max_probes)
    {
    }

    FilteredHit filter(const SurfaceHit& h, const RenderContext& context, HitScratch& scratch) const override
    {
        // Its pyramids looked up by probes along the footprint's major edge
        // (texture_footprint.h); supersampled pixels take only the AOVs.
        const TextureFootprint f = filter_texture_footprint(
            color_, driver_.texture, driver_.histograms ? &*driver_.histograms : nullptr, h,
            context.supersampled ? TextureColor::None : texture_color(method_), context.options.footprint, max_probes_,
            bin_colors_, scratch.weights, color_pyramid_ ? &*color_pyramid_ : nullptr, &segments_);
        scratch.counts.footprints += f.counts.footprints;
        scratch.counts.plain += f.counts.plain;
        return {f.albedo, f.mean, f.sigma, f.lod};
    }

    Rgb point_albedo(double u, double v) const override { return color_.map.evaluate(driver_.texture.value(u, v)); }

private:
    const ColorLayer& color_;
    const TextureDriver& driver_;
    RenderMethod method_;
    std::vector<Rgb> bin_colors_;                // exact: C0 at the histogram's distinct values
    std::optional<ColorPyramid> color_pyramid_;  // color-pyramid: C0(f) box-mipped
    TextureSegments segments_;                   // segments: the driver's pyramid and the map's ramp colours
    int max_probes_;
};

}  // namespace

Expected<std::unique_ptr<DriverRenderer>> make_texture_renderer(const Material& material, const TextureDriver& driver,
                                                                std::size_t surface, RenderMethod colour_method,
                                                                const RenderOptions& options)
{
    // The supersampled methods read f at each ray's hit from level 0, which
    // a moments driver whose recorded driver is gone lacks.
    if ((options.method == RenderMethod::Supersample || options.method == RenderMethod::Reference) &&
        !driver.texture.has_level0())
        return io_error(material.provenance.missing_driver + "; " + to_string(options.method) +
                        " reads the driver's texels at each ray's hit (naive and gaussian need only the "
                        "moments): re-bake the moments from the driver where it is now, or name the "
                        "driver itself with driver/image");
    if (colour_method == RenderMethod::Mixture && driver.texture.moments().info().order != 4)
        return bad_input("render: surface " + std::to_string(surface) +
                         ": mixture needs a moment pyramid of order 4, and the texture's holds " +
                         std::to_string(driver.texture.moments().info().order) +
                         " moments (name a driver image, baked in process with four, or re-bake the moments with "
                         "MomentBakeOptions::order 4)");
    std::vector<Rgb> bin_colors;
    if (colour_method == RenderMethod::Exact) {
        if (!driver.histograms)
            return bad_input("render: surface " + std::to_string(surface) +
                             ": exact needs the texture's histogram pyramid (MaterialOptions::histograms)");
        for (double v : driver.histograms->info().values) bin_colors.push_back(material.color.map.evaluate(v));
    }
    // color-pyramid: C0(f) of level 0 box-mipped through the material's map,
    // the pyramid bake-moments --method color-pyramid writes for it.
    std::optional<ColorPyramid> color_pyramid;
    if (colour_method == RenderMethod::ColorPyramid) {
        if (!driver.texture.has_level0())
            return io_error(material.provenance.missing_driver +
                            "; color-pyramid maps the driver's texels through C0 (naive and gaussian need only the "
                            "moments): re-bake the moments from the driver where it is now, or name the driver "
                            "itself with driver/image");
        const MomentPyramidInfo& info = driver.texture.moments().info();
        ColorPyramidOptions po;
        po.driver = driver.texture.level0();
        po.width = info.width;
        po.height = info.height;
        po.map = &material.color.map;
        po.wrap = info.wrap;
        po.reference = info.reference;
        po.threads = options.threads;
        color_pyramid = ColorPyramid::build(po);
    }
    // segments: the ramp means of the driver's segment pyramid (prepared
    // with the material, scene_materials.h), weighed by the map's colours
    // through its breakpoints, as apply --method segments weighs them.
    TextureSegments segments;
    if (colour_method == RenderMethod::Segments) {
        if (!driver.segments)
            return bad_input("render: surface " + std::to_string(surface) +
                             ": segments needs the texture's segment pyramid (MaterialOptions::segments, or the "
                             "scene's driver/segments)");
        const SegmentPyramidInfo& info = driver.segments->info();
        segments.pyramid = &*driver.segments;
        segments.ramp_colors = ramp_colors(material.color.map, info.breakpoints, info.weights());
    }
    return std::unique_ptr<DriverRenderer>(std::make_unique<TextureRenderer>(
        material.color, driver, colour_method, std::move(bin_colors), std::move(color_pyramid), std::move(segments),
        max_probes_of(options, surface)));
}

}  // namespace cmfilter
