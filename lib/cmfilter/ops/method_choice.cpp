// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/ops/method_choice.h"

#include "cmfilter/ops/image_comparison.h"
#include "cmfilter/texture/color_pyramid_texture.h"
#include "cmfilter/texture/segment_pyramid_texture.h"
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/texture/moment_texture.h"
#include "cmfilter/util/stopwatch.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace cmfilter {

namespace {

// The fixed order that breaks ties of bytes per texel: the fewer lookups
// and the simpler arithmetic first.
int method_rank(FilterMethod m)
{
    switch (m) {
    case FilterMethod::Naive: return 0;
    case FilterMethod::Gaussian: return 1;
    case FilterMethod::ColorPyramid: return 2;
    case FilterMethod::Segments: return 3;
    case FilterMethod::Mixture: return 4;
    case FilterMethod::Exact: return 5;
    case FilterMethod::Reference: return 6;
    }
    return 7;
}

std::string short_number(double v)
{
    std::ostringstream s;
    s.precision(4);
    s << v;
    return s.str();
}

double mean_of(const std::vector<double>& v)
{
    return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

}  // namespace

const MethodTrial* MethodChoice::best() const
{
    const MethodTrial* b = nullptr;
    for (const MethodTrial& t : trials)
        if (!b || t.worst < b->worst) b = &t;
    return b;
}

std::string lod_list_text(const std::vector<double>& lods)
{
    std::ostringstream s;
    for (std::size_t i = 0; i < lods.size(); ++i) s << (i ? ", " : "") << lods[i];
    return s.str();
}

Expected<MethodChoice> choose_filter_method(const ApplyOptions& base, const ColorConfig& config,
                                            const MethodChoiceOptions& options)
{
    if (!(std::isfinite(options.tolerance) && options.tolerance > 0))
        return bad_input("MethodChoiceOptions::tolerance " + short_number(options.tolerance) +
                             " is invalid (expected a CIEDE2000 difference > 0)",
                         "MethodChoiceOptions::tolerance");
    for (double lod : options.lods)
        if (!(std::isfinite(lod) && lod >= 0))
            return bad_input("MethodChoiceOptions::lods holds " + short_number(lod) +
                                 " (expected finite levels of detail >= 0)",
                             "MethodChoiceOptions::lods");
    for (FilterMethod m : options.candidates)
        if (m == FilterMethod::Reference)
            return bad_input("MethodChoiceOptions::candidates holds reference, the measure of the others "
                             "(expected naive, gaussian, color-pyramid, mixture or exact)",
                             "MethodChoiceOptions::candidates");

    auto moments = MomentTexture::open(base.moments_path);
    if (!moments) return moments.error();
    const int top = moments->reachable_levels() - 1;
    const int order = moments->info().order;

    MethodChoice out;
    out.tolerance = options.tolerance;
    if (options.lods.empty()) {
        for (int l = 1; l <= std::min(8, top); ++l) out.lods.push_back(l);
        if (out.lods.empty()) out.lods.push_back(0);
    } else {
        for (double l : options.lods)
            if (l <= top) out.lods.push_back(l);
        if (out.lods.empty())
            return bad_input("MethodChoiceOptions::lods " + lod_list_text(options.lods) + " all lie above level " +
                                 std::to_string(top) + ", the top '" + base.moments_path + "' reaches",
                             "MethodChoiceOptions::lods");
    }

    // The candidates, each with what a renderer stores per texel for it.
    std::vector<FilterMethod> wanted = options.candidates;
    if (wanted.empty())
        wanted = {FilterMethod::Naive,    FilterMethod::Gaussian, FilterMethod::ColorPyramid,
                  FilterMethod::Segments, FilterMethod::Mixture,  FilterMethod::Exact};
    const bool asked = !options.candidates.empty();
    std::size_t bins = 0;
    if (!base.histograms_path.empty()) {
        auto h = HistogramTexture::open(base.histograms_path);
        if (!h) return h.error();
        bins = h->info().values.size();
    }
    std::optional<ColorPyramidInfo> color_pyramid;
    if (!options.color_pyramid_path.empty()) {
        auto p = ColorPyramidTexture::open(options.color_pyramid_path);
        if (!p) return p.error();
        if (p->info().width != moments->info().width || p->info().height != moments->info().height)
            return bad_input("colour pyramid '" + options.color_pyramid_path + "' is " +
                                 std::to_string(p->info().width) + " x " + std::to_string(p->info().height) + " but '" +
                                 base.moments_path + "' is " + std::to_string(moments->info().width) + " x " +
                                 std::to_string(moments->info().height) + " (expected the same driver)",
                             "MethodChoiceOptions::color_pyramid_path");
        color_pyramid = p->info();
    }
    std::optional<SegmentPyramidInfo> segment_pyramid;
    if (!options.segment_pyramid_path.empty()) {
        auto p = SegmentPyramidTexture::open(options.segment_pyramid_path);
        if (!p) return p.error();
        if (p->info().width != moments->info().width || p->info().height != moments->info().height)
            return bad_input("segment pyramid '" + options.segment_pyramid_path + "' is " +
                                 std::to_string(p->info().width) + " x " + std::to_string(p->info().height) + " but '" +
                                 base.moments_path + "' is " + std::to_string(moments->info().width) + " x " +
                                 std::to_string(moments->info().height) + " (expected the same driver)",
                             "MethodChoiceOptions::segment_pyramid_path");
        segment_pyramid = p->info();
    }
    for (FilterMethod m : wanted) {
        if (std::any_of(out.trials.begin(), out.trials.end(), [m](const MethodTrial& t) { return t.method == m; }))
            continue;
        MethodTrial t;
        t.method = m;
        switch (m) {
        case FilterMethod::Naive: t.bytes_per_texel = 4; break;
        case FilterMethod::Gaussian:
            t.bytes_per_texel = 8;
            t.table_lookups = 1;
            break;
        case FilterMethod::Mixture:
            if (order != 4) {
                const std::string why = "mixture: '" + base.moments_path + "' holds " + std::to_string(order) +
                                        " moments (mixture needs MomentBakeOptions::order 4)";
                if (asked) return bad_input(why, "MethodChoiceOptions::candidates");
                out.skipped.push_back(why);
                continue;
            }
            t.bytes_per_texel = 16;
            t.table_lookups = 2;
            break;
        case FilterMethod::ColorPyramid:
            if (!color_pyramid) {
                const std::string why = "color-pyramid: no colour pyramid of the driver through this map "
                                        "(MethodChoiceOptions::color_pyramid_path)";
                if (asked) return bad_input(why, "MethodChoiceOptions::color_pyramid_path");
                out.skipped.push_back(why);
                continue;
            }
            t.bytes_per_texel = color_pyramid->bytes_per_texel();
            break;
        case FilterMethod::Segments:
            if (!segment_pyramid) {
                const std::string why = "segments: no segment pyramid of the driver "
                                        "(MethodChoiceOptions::segment_pyramid_path)";
                if (asked) return bad_input(why, "MethodChoiceOptions::segment_pyramid_path");
                out.skipped.push_back(why);
                continue;
            }
            t.bytes_per_texel = segment_pyramid->bytes_per_texel();
            break;
        case FilterMethod::Exact:
            if (bins == 0) {
                const std::string why = "exact: no histogram pyramid (ApplyOptions::histograms_path)";
                if (asked) return bad_input(why, "ApplyOptions::histograms_path");
                out.skipped.push_back(why);
                continue;
            }
            t.bytes_per_texel = 4 * bins;
            break;
        case FilterMethod::Reference: break;
        }
        out.trials.push_back(std::move(t));
    }
    std::stable_sort(out.trials.begin(), out.trials.end(), [](const MethodTrial& a, const MethodTrial& b) {
        if (a.bytes_per_texel != b.bytes_per_texel) return a.bytes_per_texel < b.bytes_per_texel;
        return method_rank(a.method) < method_rank(b.method);
    });

    for (std::size_t i = 0; i < out.lods.size(); ++i) {
        ApplyOptions run = base;
        run.lod = out.lods[i];
        run.width = run.height = 0;  // one pixel per texel of level floor(lod)
        run.progress = nullptr;
        run.method = FilterMethod::Reference;
        const Stopwatch reference_time;
        auto reference = apply_filter(run, config);
        if (!reference) return reference.error();
        out.reference_ms += reference_time.elapsed_ms();
        for (MethodTrial& t : out.trials) {
            run.method = t.method;
            run.moments_path = t.method == FilterMethod::ColorPyramid ? options.color_pyramid_path
                               : t.method == FilterMethod::Segments   ? options.segment_pyramid_path
                                                                      : base.moments_path;
            const Stopwatch time;
            auto image = apply_filter(run, config);
            if (!image) return image.error();
            t.time_ms += time.elapsed_ms();
            const RgbDifference d = measure_rgb_difference(reference->rgb.data(), image->rgb.data(), image->width,
                                                           image->height, base.threads);
            const double e = mean_of(d.de2000);
            t.errors.push_back(e);
            if (i == 0 || e > t.worst) {
                t.worst = e;
                t.worst_lod = out.lods[i];
            }
        }
        if (options.progress) options.progress(static_cast<double>(i + 1) / static_cast<double>(out.lods.size()));
    }
    for (std::size_t i = 0; i < out.trials.size(); ++i) {
        MethodTrial& t = out.trials[i];
        t.meets = t.worst <= options.tolerance;
        if (t.meets && !out.chosen) out.chosen = i;
    }
    return out;
}

Error no_method_meets(const MethodChoice& choice, const std::string& subject)
{
    std::ostringstream s;
    s << subject << ": no method meets MethodChoiceOptions::tolerance " << short_number(choice.tolerance)
      << " (mean CIEDE2000 at LOD " << lod_list_text(choice.lods) << ")";
    if (const MethodTrial* b = choice.best())
        s << "; the closest is " << to_string(b->method) << " at " << short_number(b->worst) << " (LOD " << b->worst_lod
          << ")";
    for (const std::string& why : choice.skipped) s << "; not tried: " << why;
    return bad_input(s.str(), "MethodChoiceOptions::tolerance");
}

}  // namespace cmfilter
