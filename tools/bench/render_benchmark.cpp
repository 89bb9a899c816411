// SPDX-License-Identifier: Apache-2.0
#include "bench/render_benchmark.h"

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/scene/tolerance_tables.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>
#include <sstream>

namespace cmfilter::bench {

namespace {

// BenchRow::driver_bytes of one material.
std::size_t driver_bytes(const Material& m, RenderMethod method)
{
    const bool sampled = method == RenderMethod::Supersample || method == RenderMethod::Reference;
    if (const auto* noise = std::get_if<NoiseDriver>(&m.driver))
        return sampled ? 0 : noise->noise.table().sigmas().size() * sizeof(float);
    const auto* texture = std::get_if<TextureDriver>(&m.driver);
    if (!texture) return 0;
    const double texels = static_cast<double>(texture->texture.width()) * texture->texture.height();
    if (sampled) return static_cast<std::size_t>(texels * sizeof(float));
    double channels = 2;
    if (method == RenderMethod::Naive) channels = 1;
    if (method == RenderMethod::Mixture) channels = 4;
    if (method == RenderMethod::Exact) channels = static_cast<double>(texture->texture.distinct_values());
    return static_cast<std::size_t>(channels * sizeof(float) * texels * 4 / 3);
}

}  // namespace

std::string BenchConfiguration::label() const
{
    switch (method) {
    case RenderMethod::Gaussian: {
        std::ostringstream s;
        s << "gaussian ";
        if (tolerance > 0) s << "tol " << tolerance;
        else s << table_values << "x" << table_sigmas << " " << to_string(spacing);
        if (footprint != FootprintWidth::Rms) s << " " << to_string(footprint);
        const double default_shortcut = tolerance > 0 ? kPlainLookupFraction * tolerance : 0.0;
        if (shortcut != default_shortcut) {
            if (shortcut > 0) s << " shortcut " << shortcut;
            else s << " no-shortcut";
        }
        return s.str();
    }
    case RenderMethod::Supersample: return "supersample " + std::to_string(samples);
    default: return to_string(method);
    }
}

std::vector<BenchConfiguration> default_bench_configurations()
{
    std::vector<BenchConfiguration> c;
    c.push_back({RenderMethod::Naive, 1, 256, 256, SigmaSpacing::Sqrt, FootprintWidth::Rms});
    c.push_back({RenderMethod::Exact, 1, 256, 256, SigmaSpacing::Sqrt, FootprintWidth::Rms});
    c.push_back({RenderMethod::GaussianExact, 1, 256, 256, SigmaSpacing::Sqrt, FootprintWidth::Rms});
    for (int n : {16, 64, 256})
        for (SigmaSpacing s : {SigmaSpacing::Sqrt, SigmaSpacing::Linear})
            c.push_back({RenderMethod::Gaussian, 1, n, n, s, FootprintWidth::Rms});
    for (FootprintWidth f : {FootprintWidth::Area, FootprintWidth::Major, FootprintWidth::Minor})
        c.push_back({RenderMethod::Gaussian, 1, 256, 256, SigmaSpacing::Sqrt, f});
    for (double tolerance : {1.0, 0.5}) {
        BenchConfiguration fitted{RenderMethod::Gaussian, 1, 256, 256, SigmaSpacing::Sqrt, FootprintWidth::Rms};
        fitted.tolerance = tolerance;
        fitted.shortcut = kPlainLookupFraction * tolerance;
        c.push_back(fitted);
        if (tolerance == 1.0) {
            fitted.shortcut = 0;
            c.push_back(fitted);
        }
    }
    BenchConfiguration shortcut{RenderMethod::Gaussian, 1, 256, 256, SigmaSpacing::Sqrt, FootprintWidth::Rms};
    shortcut.shortcut = 0.1;
    c.push_back(shortcut);
    for (int spp : {1, 4, 16, 64, 256})
        c.push_back({RenderMethod::Supersample, spp, 256, 256, SigmaSpacing::Sqrt, FootprintWidth::Rms});
    // Last: its texture pyramids of four moments stay for what follows.
    c.push_back({RenderMethod::Mixture, 1, 256, 256, SigmaSpacing::Sqrt, FootprintWidth::Rms});
    return c;
}

Expected<std::vector<BenchConfiguration>> select_bench_configurations(const std::vector<BenchConfiguration>& all,
                                                                      const std::vector<std::string>& labels)
{
    std::string known;
    for (const BenchConfiguration& c : all) known += (known.empty() ? "'" : ", '") + c.label() + "'";
    for (const std::string& label : labels)
        if (std::none_of(all.begin(), all.end(), [&](const BenchConfiguration& c) { return c.label() == label; }))
            return bad_input("configuration '" + label + "' is unknown (expected one of " + known + ")");
    std::vector<BenchConfiguration> chosen;
    for (const BenchConfiguration& c : all)
        if (std::find(labels.begin(), labels.end(), c.label()) != labels.end()) chosen.push_back(c);
    return chosen;
}

namespace {

struct Bands {
    double near = 0, horizon = 0;  // distance < near: near band; >= horizon: horizon band
};

// The distance at which pixel p of the reference sees a surface: the mean
// over its rays that hit one (the pixels a surface covers in part count,
// even where the centre ray misses), else the centre ray's; none where
// nothing is seen.
std::optional<double> surface_distance(const RenderedImage& reference, std::size_t p)
{
    if (!reference.covered.empty() && reference.covered[p] > 0) return reference.covered_distance[p];
    if (reference.hit[p]) return reference.distance[p];
    return std::nullopt;
}

Bands distance_bands(const RenderedImage& reference)
{
    std::vector<double> d;
    for (std::size_t p = 0; p < reference.hit.size(); ++p)
        if (const auto t = surface_distance(reference, p)) d.push_back(*t);
    Bands b;
    if (d.empty()) return b;
    std::sort(d.begin(), d.end());
    b.near = d[d.size() / 3];
    b.horizon = d[(2 * d.size()) / 3];
    return b;
}

BandedError compare(const RenderedImage& reference, const RenderedImage& image, const Bands& bands)
{
    std::vector<double> all, near, middle, horizon;
    for (std::size_t p = 0; p < reference.hit.size(); ++p) {
        const auto t = surface_distance(reference, p);
        if (!t) continue;
        const Rgb a{reference.rgb[3 * p], reference.rgb[3 * p + 1], reference.rgb[3 * p + 2]};
        const Rgb b{image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]};
        const double e = ciede2000_linear_rgb(a, b);
        all.push_back(e);
        (*t < bands.near ? near : *t < bands.horizon ? middle : horizon).push_back(e);
    }
    return {summarize_errors(all), summarize_errors(near), summarize_errors(middle), summarize_errors(horizon)};
}

// Adds `round` into `sum`, which already holds `rounds` renders: the running
// mean of the renders' colours, their rays and their time.
void average_in(RenderedImage& sum, const RenderedImage& round, int rounds)
{
    const float w = 1.0f / static_cast<float>(rounds + 1);
    for (std::size_t i = 0; i < sum.rgb.size(); ++i) sum.rgb[i] += w * (round.rgb[i] - sum.rgb[i]);
    for (std::size_t p = 0; p < sum.covered.size(); ++p) {
        // The mean distance over every round's hitting rays.
        const float before = sum.covered[p] * static_cast<float>(rounds), added = round.covered[p];
        if (before + added > 0)
            sum.covered_distance[p] = (before * sum.covered_distance[p] + added * round.covered_distance[p]) /
                                      (before + added);
        sum.covered[p] += w * (round.covered[p] - sum.covered[p]);
    }
    sum.samples += round.samples;
    sum.seconds += round.seconds;
}

// The reference and a second, independent one, grown round by round until
// they differ by at most options.reference_repeat (BenchOptions). Round 0
// renders the two with seeds s and s + 1, round k >= 1 with s + 2k + 1 and
// s + 2k + 2: never s + 2, the configurations' seed.
Expected<std::pair<RenderedImage, RenderedImage>>
repeatable_references(const Scene& scene, const std::vector<Material>& materials, const BenchOptions& options)
{
    RenderOptions ro;
    ro.method = RenderMethod::Reference;
    ro.samples = options.reference_samples;
    ro.threads = options.threads;
    ro.region = options.region;
    std::optional<RenderedImage> first, second;
    for (int round = 0;; ++round) {
        ro.seed = options.seed + (round == 0 ? 0 : 2 * round + 1);
        auto a = render(scene, materials, ro);
        if (!a) return a.error();
        ro.seed = options.seed + (round == 0 ? 1 : 2 * round + 2);
        auto b = render(scene, materials, ro);
        if (!b) return b.error();
        const int round_samples = a->samples;
        if (round == 0) {
            first = std::move(*a);
            second = std::move(*b);
        } else {
            average_in(*first, *a, round);
            average_in(*second, *b, round);
        }
        if (first->samples + round_samples > options.max_reference_samples) break;
        if (compare(*first, *second, distance_bands(*first)).all.mean <= options.reference_repeat) break;
        if (options.note)
            options.note(scene.path + ": the references differ by more than " +
                         std::to_string(options.reference_repeat) + " mean dE00 at " + std::to_string(first->samples) +
                         " rays per pixel; adding " + std::to_string(round_samples));
    }
    return std::make_pair(std::move(*first), std::move(*second));
}

}  // namespace

Status check_reference_options(const BenchOptions& options)
{
    if (options.reference_samples < kReferenceSamples || options.reference_samples > kMaxSamples)
        return bad_input("BenchOptions::reference_samples " + std::to_string(options.reference_samples) +
                             " is out of range (expected " + std::to_string(kReferenceSamples) + " to " +
                             std::to_string(kMaxSamples) + ")",
                         "BenchOptions::reference_samples");
    if (!(options.reference_repeat >= 0) || !std::isfinite(options.reference_repeat))
        return bad_input("BenchOptions::reference_repeat " + std::to_string(options.reference_repeat) +
                             " is out of range (expected a finite mean CIEDE2000 >= 0)",
                         "BenchOptions::reference_repeat");
    if (options.max_reference_samples < options.reference_samples || options.max_reference_samples > kMaxSamples)
        return bad_input("BenchOptions::max_reference_samples " + std::to_string(options.max_reference_samples) +
                             " is out of range (expected BenchOptions::reference_samples " +
                             std::to_string(options.reference_samples) + " to " + std::to_string(kMaxSamples) + ")",
                         "BenchOptions::max_reference_samples");
    return ok();
}

Expected<SceneBench> bench_scene(const Scene& scene, std::vector<Material>& materials, const BenchOptions& options)
{
    if (options.repeats < 1) return bad_input("bench: repeats must be >= 1, got " + std::to_string(options.repeats));
    if (auto st = check_reference_options(options); !st) return st.error();
    if (options.region)
        if (auto st =
                check_pixel_region(*options.region, scene.camera.width, scene.camera.height, "BenchOptions::region");
            !st)
            return prefixed(scene.path + ": ", st.error());
    SceneBench bench;
    bench.scene = scene.path;

    auto references = repeatable_references(scene, materials, options);
    if (!references) return references.error();
    const RenderedImage& reference = references->first;
    const RenderedImage& second = references->second;
    const Bands bands = distance_bands(reference);
    bench.width = reference.frame_width;
    bench.height = reference.frame_height;
    bench.region = {reference.x0, reference.y0, reference.x0 + reference.width, reference.y0 + reference.height};
    for (std::size_t p = 0; p < reference.hit.size(); ++p) bench.pixels_hit += surface_distance(reference, p) ? 1 : 0;
    bench.near_distance = bands.near;
    bench.horizon_distance = bands.horizon;
    bench.reference_seconds = reference.seconds;
    bench.reference_samples = reference.samples;
    bench.reference_repeatability = compare(reference, second, bands);
    if (options.note)
        options.note(scene.path + ": reference (" + std::to_string(reference.samples) + " rays per pixel) in " +
                     std::to_string(bench.reference_seconds) + " s, repeatable to " +
                     std::to_string(bench.reference_repeatability.all.mean) + " mean dE00");

    // The tables every surface holds now; re-baked (or fitted) when a configuration asks for others.
    using TableKey = std::tuple<int, int, SigmaSpacing, double, double>;
    std::optional<TableKey> baked;
    const bool exact = exact_filterable(materials);
    for (const BenchConfiguration& c : options.configurations) {
        if (c.method == RenderMethod::Exact) {
            if (!exact) {
                if (options.note)
                    options.note(scene.path + ": exact: left out (not every driver is a texture with at most " +
                                 std::to_string(kHistogramMaxValues) + " values)");
                continue;
            }
            MaterialOptions mo;
            mo.threads = options.threads;
            mo.note = options.note;
            if (auto st = prepare_histograms(scene, materials, mo); !st) return st.error();
        }
        if (c.method == RenderMethod::Mixture) {
            // Four moments for the texture drivers baked in process; noise
            // drivers take sub-footprints; a scene with neither would render
            // gaussian.
            if (std::none_of(materials.begin(), materials.end(), has_texture_driver) &&
                std::none_of(materials.begin(), materials.end(), has_noise_driver)) {
                if (options.note)
                    options.note(scene.path + ": mixture: left out (no texture or noise driver: it would be gaussian)");
                continue;
            }
            MaterialOptions mo;
            mo.threads = options.threads;
            mo.note = options.note;
            mo.moment_order = 4;
            if (auto st = prepare_moment_order(scene, materials, mo); !st) return st.error();
        }
        if (c.method == RenderMethod::GaussianExact &&
            std::none_of(materials.begin(), materials.end(), is_microsurface)) {
            if (options.note)
                options.note(scene.path + ": gaussian-exact: left out (no microsurface: it would be gaussian)");
            continue;
        }
        BenchRow row;
        row.configuration = c;
        const TableKey key{c.table_values, c.table_sigmas, c.spacing, c.tolerance, c.shortcut};
        const bool tabled = c.method == RenderMethod::Gaussian || c.method == RenderMethod::Mixture;
        if (tabled && !(baked == key)) {
            if (c.tolerance <= 0) {
                GaussianColorTableOptions to;
                to.values = c.table_values;
                to.sigmas = c.table_sigmas;
                to.spacing = c.spacing;
                to.threads = options.threads;
                for (Material& m : materials) {
                    ColorLayer& layer = table_layer(m);
                    auto table = GaussianColorTable::bake(layer.map, to);
                    if (!table) return table.error();
                    layer.table = std::move(*table);
                }
            }
            TableChoiceOptions choice;
            choice.tolerance = std::max(0.0, c.tolerance);  // 0: keep the tables just baked
            choice.plain_bound = c.shortcut;
            choice.threads = options.threads;
            if (auto st = choose_surface_tables(scene, materials, choice); !st) return st.error();
            baked = key;
        }
        for (const Material& m : materials) row.driver_bytes += driver_bytes(m, c.method);
        if (tabled)
            for (std::size_t i = 0; i < materials.size(); ++i) {
                const ColorLayer& m = table_layer(materials[i]);
                const TableAxes& ax = m.table.axes();
                row.table_bytes += m.table.data().size() * sizeof(float);
                row.table_error = std::max(row.table_error, m.fit.error);
                if (i == 0) {
                    row.table_values = ax.values;
                    row.table_sigmas = ax.sigmas;
                    row.spacing = ax.spacing;
                } else if (ax.values != row.table_values || ax.sigmas != row.table_sigmas ||
                           ax.spacing != row.spacing) {
                    row.table_values = row.table_sigmas = 0;
                }
            }
        RenderOptions r;
        r.method = c.method;
        r.samples = c.samples;
        r.seed = options.seed + 2;
        r.threads = options.threads;
        r.footprint = c.footprint;
        r.max_probes = options.max_probes;
        r.sub_footprints = options.sub_footprints;
        r.edge_coverage = options.edge_coverage;
        r.region = options.region;
        row.seconds = std::numeric_limits<double>::infinity();
        Expected<RenderedImage> image = bad_input("bench: no render");
        for (int k = 0; k < options.repeats; ++k) {
            image = render(scene, materials, r);
            if (!image) return image.error();
            row.seconds = std::min(row.seconds, image->seconds);
        }
        row.footprints = image->footprints;
        row.plain_footprints = image->plain_footprints;
        row.error = compare(reference, *image, bands);
        if (options.note)
            options.note(scene.path + ": " + c.label() + ": " + std::to_string(row.seconds) + " s, mean dE00 " +
                         std::to_string(row.error.all.mean));
        bench.rows.push_back(row);
    }
    if (options.keep_reference) bench.reference_image = std::move(references->first);
    return bench;
}

std::string bench_csv(const std::vector<SceneBench>& benches)
{
    std::ostringstream s;
    s.precision(6);
    s << "scene,configuration,method,spp,table_values,table_sigmas,spacing,footprint,table_bytes,seconds,"
         "mean,p95,max,near_mean,near_p95,middle_mean,middle_p95,horizon_mean,horizon_p95,"
         "tolerance,table_error,shortcut,footprints,plain_footprints,driver_bytes\n";
    auto errors = [&](const BandedError& e) {
        s << e.all.mean << "," << e.all.p95 << "," << e.all.max << "," << e.near.mean << "," << e.near.p95 << ","
          << e.middle.mean << "," << e.middle.p95 << "," << e.horizon.mean << "," << e.horizon.p95;
    };
    for (const SceneBench& b : benches) {
        s << b.scene << ",reference,"
          << "reference," << b.reference_samples << ",,,,,0," << b.reference_seconds << ",";
        errors(BandedError{});
        s << ",,,,,,\n";
        s << b.scene << ",reference-repeat,"
          << "reference," << b.reference_samples << ",,,,,0," << b.reference_seconds << ",";
        errors(b.reference_repeatability);
        s << ",,,,,,\n";
        for (const BenchRow& r : b.rows) {
            const BenchConfiguration& c = r.configuration;
            s << b.scene << "," << c.label() << "," << to_string(c.method) << "," << c.samples << ",";
            if (c.method == RenderMethod::Gaussian && r.table_values > 0)
                s << r.table_values << "," << r.table_sigmas << "," << to_string(r.spacing);
            else s << ",,";
            s << "," << (c.method == RenderMethod::Supersample ? "" : to_string(c.footprint));
            s << "," << r.table_bytes << "," << r.seconds << ",";
            errors(r.error);
            if (c.method == RenderMethod::Gaussian) {
                s << ",";
                if (c.tolerance > 0) s << c.tolerance << "," << r.table_error;
                else s << ",";
                s << "," << c.shortcut << "," << r.footprints << "," << r.plain_footprints << ",";
            } else {
                s << ",,,,,,";
            }
            s << r.driver_bytes << "\n";
        }
    }
    return s.str();
}

}  // namespace cmfilter::bench
