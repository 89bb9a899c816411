// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/noise_surface.h"

#include "cmfilter/texture/anisotropic_probes.h"
#include "cmfilter/texture/footprint_width.h"
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/noise/noise_sub_footprints.h"

#include <string>

namespace cmfilter {

namespace {

class NoiseRenderer : public DriverRenderer {
public:
    NoiseRenderer(const ColorLayer& color, const FilteredNoise& noise, RenderMethod method,
                  const SubFootprintOptions& squares, int max_probes)
        : color_(color), noise_(noise), method_(method), squares_(squares), max_probes_(max_probes)
    {
    }

    FilteredHit filter(const SurfaceHit& h, const RenderContext& context, HitScratch& scratch) const override
    {
        const RenderOptions& options = context.options;
        const bool colour = !context.supersampled;
        FilteredHit out;
        if (max_probes_ > 1) {
            // Over an anisotropic footprint: probes along its major edge
            // (anisotropic_probes.h), colours averaged.
            const FootprintProbes probes =
                footprint_probes(h.du_dx, h.dv_dx, h.du_dy, h.dv_dy, max_probes_, options.footprint);
            // Each probe's piece of the parallelogram, for mixture's squares.
            const FootprintEdges piece{probes.step_u / probes.count, probes.step_v / probes.count, probes.minor_u,
                                       probes.minor_v};
            for (int j = 0; j < probes.count; ++j) {
                const double o = (j + 0.5) / probes.count - 0.5;
                const FilteredNoise::Parameters f =
                    noise_.filter(h.u + o * probes.step_u, h.v + o * probes.step_v, probes.width);
                if (colour)
                    out.albedo += albedo(h.u + o * probes.step_u, h.v + o * probes.step_v, probes.width, piece, f,
                                         scratch.counts);
                out.mean += f.mean;
                out.sigma += f.sigma;
            }
            out.albedo = (1.0 / probes.count) * out.albedo;
            out.mean /= probes.count;
            out.sigma /= probes.count;
            out.lod = noise_.lod(probes.width);
            return out;
        }
        // One footprint, as one width (footprint_width.h): the noise's mean
        // and sigma (sec. 4.2) and the footprint's LOD.
        const double w = footprint_width(options.footprint, h.du_dx, h.dv_dx, h.du_dy, h.dv_dy);
        const FilteredNoise::Parameters f = noise_.filter(h.u, h.v, w);
        out.mean = f.mean;
        out.sigma = f.sigma;
        out.lod = noise_.lod(w);
        if (colour) out.albedo = albedo(h.u, h.v, w, {h.du_dx, h.dv_dx, h.du_dy, h.dv_dy}, f, scratch.counts);
        return out;
    }

    Rgb point_albedo(double u, double v) const override { return color_.map.evaluate(noise_.noise()(u, v)); }

private:
    // The colour of the footprint of width w and edges e at (u, v), filtered
    // to f: naive C0(mean), gaussian T(mean, sigma), mixture over its
    // sub-footprints, cut along its edges (noise_sub_footprints.h; f's own
    // where it takes one).
    // Mixture takes gaussian's colour where the whole footprint is below the
    // small-sigma shortcut (gaussian_albedo.h): there C0 is linear within the
    // shortcut's bound over the footprint's values, so the squares' colours
    // average to the colour of their mean.
    Rgb albedo(double u, double v, double w, const FootprintEdges& e, const FilteredNoise::Parameters& f,
               AlbedoCounts& counts) const
    {
        if (method_ == RenderMethod::Naive) return color_.map.evaluate(f.mean);
        if (method_ != RenderMethod::Mixture || f.sigma < color_.plain.below(f.mean))
            return gaussian_albedo(color_, f.mean, f.sigma, counts);
        // The footprint counts once (as a footprint coloured by a table),
        // not once per square.
        ++counts.footprints;
        AlbedoCounts squares;
        return sub_footprint_color<Rgb>(noise_, u, v, w, e, f, squares_, [&](const FilteredNoise::Parameters& p) {
            return gaussian_albedo(color_, p.mean, p.sigma, squares);
        });
    }

    const ColorLayer& color_;
    const FilteredNoise& noise_;
    RenderMethod method_;
    SubFootprintOptions squares_;
    int max_probes_;  // the surface's (max_probes_of)
};

}  // namespace

Expected<std::unique_ptr<DriverRenderer>> make_noise_renderer(const ColorLayer& color, const NoiseDriver& driver,
                                                              std::size_t surface, RenderMethod colour_method,
                                                              const SubFootprintOptions& squares, int max_probes)
{
    if (colour_method == RenderMethod::Exact)
        return bad_input("render: surface " + std::to_string(surface) + ": exact needs a texture driver with at most " +
                         std::to_string(kHistogramMaxValues) +
                         " distinct values; noise drivers have no exact filtering distribution");
    if (colour_method == RenderMethod::ColorPyramid || colour_method == RenderMethod::Segments)
        return bad_input(
            "render: surface " + std::to_string(surface) + ": " + to_string(colour_method) +
            " needs a texture driver, whose texels it " +
            (colour_method == RenderMethod::Segments ? "ramps between the map's breakpoints" : "maps through C0") +
            " and box-mips; a noise has no level 0 to bake (render it by gaussian or mixture)");
    return std::unique_ptr<DriverRenderer>(
        std::make_unique<NoiseRenderer>(color, driver.noise, colour_method, squares, max_probes));
}

}  // namespace cmfilter
