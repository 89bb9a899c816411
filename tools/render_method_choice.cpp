// SPDX-License-Identifier: Apache-2.0
// render --method auto: each texture surface's method chosen for the
// tolerance as `apply --tolerance` chooses it (ops/method_choice.h), on its
// own driver and table: four moments of its driver (with the texture's
// wrap and channel), its colour pyramid through its map, a segment pyramid
// of its map's breakpoints for the tolerance (or the scene's), its table (the
// fitted one, when fitted) and, for a driver of at most kHistogramMaxValues
// values, its histogram pyramid are written to temporary files and measured
// against the box reference.
#include "command.h"

#include "cmfilter/ops/sub_footprint_choice.h"
#include "cmfilter/tables/gaussian_albedo.h"
#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/texture/color_pyramid_file.h"
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/texture/segment_pyramid_file.h"
#include "cmfilter/util/memory_budget.h"
#include "cmfilter/util/temporary_file.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace cmfilter::cli {

namespace {

// The largest histogram pyramid --method auto bakes to measure exact.
constexpr double kAutoHistogramBytes = 512.0 * 1024 * 1024;
// The most channels of the segment pyramid --method auto bakes to measure
// segments (as bake-moments --tolerance).
constexpr int kAutoSegmentChannels = 64;

}  // namespace

Expected<std::vector<SurfaceMethodChoice>>
choose_texture_methods(const Scene& scene, const std::vector<Material>& materials, const ColorConfig& config,
                       const MethodChoiceOptions& options, const std::vector<SurfaceLodRange>* view, int threads)
{
    std::vector<SurfaceMethodChoice> out;
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const Material& m = materials[i];
        const auto* texture = std::get_if<TextureDriver>(&m.driver);
        if (!texture || is_microsurface(m)) continue;
        // The levels its pixels reach: floor of the least to ceil of the
        // greatest LOD, within the pyramid (render's LODs are log2 of the
        // footprint's width in level-0 texels, as apply's levels).
        std::vector<double> seen_lods;
        if (options.lods.empty() && view && i < view->size()) {
            const SurfaceLodRange& seen = (*view)[i];
            if (seen.pixels == 0) continue;  // no pixel needs it
            const double top = texture->texture.moments().reachable_levels() - 1;
            const double a = std::clamp(std::floor(seen.first), 0.0, top);
            const double b = std::clamp(std::ceil(seen.last), 0.0, top);
            for (double l = a; l <= b; l += 1) seen_lods.push_back(l);
        }
        const std::string surface = "surface " + std::to_string(i) + " (" + scene.path + ")";
        if (!m.provenance.missing_driver.empty())
            return io_error(m.provenance.missing_driver + "; --method auto measures each method against the box "
                                                          "mean of C0 over the driver's texels");
        if (!m.provenance.map_source)
            return bad_input(surface + ": its colour map's source is unknown (cannot measure its methods)");
        const MomentPyramidInfo& info = texture->texture.moments().info();

        auto moments = TemporaryFile::create("cmfilter-auto-moments", ".exr");
        if (!moments) return moments.error();
        MomentBakeOptions bake;
        bake.driver_path = m.provenance.driver_path;
        bake.channel = std::to_string(info.channel_index);
        bake.wrap = info.wrap;
        bake.order = 4;
        bake.output_path = moments->path();
        bake.threads = threads;
        if (auto baked = bake_moment_pyramid(bake); !baked) return prefixed(surface + ": ", baked.error());

        // The colour pyramid through the material's own map (a scene's maps
        // are fixed), as render --method color-pyramid colours it.
        auto colors = TemporaryFile::create("cmfilter-auto-color-pyramid", ".exr");
        if (!colors) return colors.error();
        ColorPyramidBakeOptions cp;
        static_cast<PyramidBakeOptions&>(cp) = bake;
        cp.output_path = colors->path();
        cp.map = &m.color.map;
        cp.map_source = m.provenance.map_path;
        cp.linear_space = config.scene_linear_name();
        cp.linear_interop_id = config.interop_id(cp.linear_space);
        if (auto baked = bake_color_pyramid(cp); !baked) return prefixed(surface + ": ", baked.error());

        // The segment pyramid of the material's map: the scene's, or the
        // fewest breakpoints within the tolerance (up to
        // kAutoSegmentChannels, else no candidate).
        std::string segments_path;
        std::shared_ptr<const TemporaryFile> segments_file;
        if (texture->segments) {
            segments_path = texture->segments->path();
        } else {
            auto file = TemporaryFile::create("cmfilter-auto-segments", ".exr");
            if (!file) return file.error();
            SegmentPyramidBakeOptions sp;
            static_cast<PyramidBakeOptions&>(sp) = bake;
            sp.output_path = file->path();
            sp.maps = {&m.color.map};
            sp.map_sources = {m.provenance.map_path};
            sp.tolerance_de = options.tolerance;
            sp.max_channels = kAutoSegmentChannels;
            // BadInput: more channels than kAutoSegmentChannels (no
            // candidate); anything else (writing the file) is an error.
            if (auto baked = bake_segment_pyramid(sp)) {
                segments_path = file->path();
                segments_file = std::make_shared<const TemporaryFile>(std::move(*file));
            } else if (baked.error().kind != ErrorKind::BadInput) {
                return prefixed(surface + ": ", baked.error());
            }
        }

        auto table = TemporaryFile::create("cmfilter-auto-table", ".exr");
        if (!table) return table.error();
        GaussianColorTableInfo table_info;
        table_info.source = *m.provenance.map_source;
        if (auto st = write_gaussian_color_table(table->path(), m.color.table, table_info); !st)
            return prefixed(surface + ": ", st.error());

        // The histogram pyramid when the driver has few enough values and it
        // stays within kAutoHistogramBytes (4 bytes a value a texel, 4/3
        // over the levels).
        std::optional<TemporaryFile> histograms;
        const std::size_t values = texture->texture.distinct_values();
        const double histogram_bytes = 4.0 * static_cast<double>(values) * texture->texture.width() *
                                       texture->texture.height() * 4 / 3;
        std::string too_large;
        if (values <= static_cast<std::size_t>(kHistogramMaxValues) && histogram_bytes > kAutoHistogramBytes)
            too_large = "exact: the histogram pyramid of " + std::to_string(values) + " values would take " +
                        byte_size_text(histogram_bytes) + " (more than " + byte_size_text(kAutoHistogramBytes) + ")";
        if (values <= static_cast<std::size_t>(kHistogramMaxValues) && too_large.empty()) {
            auto file = TemporaryFile::create("cmfilter-auto-histograms", ".exr");
            if (!file) return file.error();
            HistogramBakeOptions h;
            static_cast<PyramidBakeOptions&>(h) = bake;
            h.output_path = file->path();
            if (auto baked = bake_histogram_pyramid(h); !baked) return prefixed(surface + ": ", baked.error());
            histograms = std::move(*file);
        }

        ApplyOptions inputs;
        inputs.moments_path = moments->path();
        inputs.table_path = table->path();
        inputs.driver_path = m.provenance.driver_path;
        if (histograms) inputs.histograms_path = histograms->path();
        inputs.threads = threads;
        MethodChoiceOptions o = options;
        if (!seen_lods.empty()) o.lods = seen_lods;
        o.color_pyramid_path = colors->path();
        o.segment_pyramid_path = segments_path;
        // A `moments` file of two moments renders as it is: no mixture.
        if (!m.provenance.moments_baked && info.order != 4 && o.candidates.empty()) {
            o.candidates = {FilterMethod::Naive, FilterMethod::Gaussian, FilterMethod::ColorPyramid};
            if (!segments_path.empty()) o.candidates.push_back(FilterMethod::Segments);
            if (histograms) o.candidates.push_back(FilterMethod::Exact);
        }
        auto choice = choose_filter_method(inputs, config, o);
        if (!choice) return prefixed(surface + ": ", choice.error());
        for (std::string& why : choice->skipped) {
            if (!too_large.empty() && why.rfind("exact:", 0) == 0) why = too_large;
            if (segments_path.empty() && why.rfind("segments:", 0) == 0)
                why = "segments: the material's map needs more than " + std::to_string(kAutoSegmentChannels) +
                      " channels at this tolerance";
        }
        if (!choice->choice()) return no_method_meets(*choice, surface);
        out.push_back({i, std::move(*choice), segments_path, std::move(segments_file)});
    }
    return out;
}

Expected<std::vector<SurfaceSubFootprintChoice>>
choose_noise_sub_footprints(const Scene& scene, const std::vector<Material>& materials, double tolerance,
                            const std::vector<double>& lods, const std::vector<SurfaceLodRange>* view, int threads)
{
    std::vector<SurfaceSubFootprintChoice> out;
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const Material& m = materials[i];
        const auto* noise = std::get_if<NoiseDriver>(&m.driver);
        if (!noise || is_microsurface(m)) continue;
        const std::string surface = "surface " + std::to_string(i) + " (" + scene.path + ")";
        SubFootprintChoiceOptions o;
        o.tolerance = tolerance;
        o.lods = lods;
        if (lods.empty() && view && i < view->size()) {
            const SurfaceLodRange& seen = (*view)[i];
            if (seen.pixels == 0) continue;  // no pixel needs it
            o.lods = sub_footprint_lods_between(noise->noise.table(), seen.first, seen.last);
        }
        o.threads = threads;
        const ColorLayer& layer = m.color;
        auto choice = choose_sub_footprints(
            noise->noise, layer.map,
            [&layer](double mean, double sigma) {
            AlbedoCounts counts;
            return gaussian_albedo(layer, mean, sigma, counts);
            },
            o);
        if (!choice) return prefixed(surface + ": ", choice.error());
        if (!choice->choice()) {
            const SubFootprintTrial* best = choice->best();
            std::ostringstream msg;
            msg << surface << ": no number of sub-footprints meets --tolerance " << tolerance
                << " (mean CIEDE2000 at every LOD " << lod_list_text(choice->lods) << " of its noise"
                << (lods.empty() && view ? ", those its pixels reach" : "") << "): the closest, up to "
                << best->max_cells << " x " << best->max_cells << " squares, is " << best->worst << " at LOD "
                << best->worst_lod;
            return bad_input(msg.str());
        }
        out.push_back({i, std::move(*choice)});
    }
    return out;
}

RenderMethod render_method_of(FilterMethod method)
{
    switch (method) {
    case FilterMethod::Naive: return RenderMethod::Naive;
    case FilterMethod::Mixture: return RenderMethod::Mixture;
    case FilterMethod::Exact: return RenderMethod::Exact;
    case FilterMethod::ColorPyramid: return RenderMethod::ColorPyramid;
    case FilterMethod::Segments: return RenderMethod::Segments;
    default: return RenderMethod::Gaussian;
    }
}

}  // namespace cmfilter::cli
