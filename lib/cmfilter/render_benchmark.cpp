#include "cmfilter/render_benchmark.h"

#include "cmfilter/ciede2000.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <tuple>
#include <sstream>

namespace cmfilter {

std::string BenchConfiguration::label() const
{
    switch (method) {
    case RenderMethod::Gaussian:
        return "gaussian " + std::to_string(table_values) + "x" + std::to_string(table_sigmas) + " " +
               to_string(spacing) + (footprint == FootprintWidth::Rms ? "" : std::string(" ") + to_string(footprint));
    case RenderMethod::Supersample: return "supersample " + std::to_string(samples);
    default: return to_string(method);
    }
}

std::vector<BenchConfiguration> default_bench_configurations()
{
    std::vector<BenchConfiguration> c;
    c.push_back({RenderMethod::Naive, 1, 256, 256, SigmaSpacing::Sqrt, FootprintWidth::Rms});
    for (int n : {16, 64, 256})
        for (SigmaSpacing s : {SigmaSpacing::Sqrt, SigmaSpacing::Linear})
            c.push_back({RenderMethod::Gaussian, 1, n, n, s, FootprintWidth::Rms});
    for (FootprintWidth f : {FootprintWidth::Area, FootprintWidth::Major, FootprintWidth::Minor})
        c.push_back({RenderMethod::Gaussian, 1, 256, 256, SigmaSpacing::Sqrt, f});
    for (int spp : {1, 4, 16, 64, 256})
        c.push_back({RenderMethod::Supersample, spp, 256, 256, SigmaSpacing::Sqrt, FootprintWidth::Rms});
    return c;
}

namespace {

struct Bands {
    double near = 0, horizon = 0;  // distance < near: near band; >= horizon: horizon band
};

Bands distance_bands(const RenderedImage& reference)
{
    std::vector<float> d;
    for (std::size_t p = 0; p < reference.hit.size(); ++p)
        if (reference.hit[p]) d.push_back(reference.distance[p]);
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
        if (!reference.hit[p]) continue;
        const Rgb a{reference.rgb[3 * p], reference.rgb[3 * p + 1], reference.rgb[3 * p + 2]};
        const Rgb b{image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]};
        const double e = ciede2000_linear_rgb(a, b);
        all.push_back(e);
        const double t = reference.distance[p];
        (t < bands.near ? near : t < bands.horizon ? middle : horizon).push_back(e);
    }
    return {summarize_errors(all), summarize_errors(near), summarize_errors(middle), summarize_errors(horizon)};
}

}  // namespace

Expected<SceneBench> bench_scene(const Scene& scene, std::vector<SurfaceMaterial>& materials,
                                 const BenchOptions& options)
{
    if (options.repeats < 1) return bad_input("bench: repeats must be >= 1, got " + std::to_string(options.repeats));
    SceneBench bench;
    bench.scene = scene.path;

    RenderOptions ro;
    ro.method = RenderMethod::Reference;
    ro.samples = options.reference_samples;
    ro.seed = options.seed;
    ro.threads = options.threads;
    auto reference = render(scene, materials, ro);
    if (!reference) return reference.error();
    ro.seed = options.seed + 1;
    auto second = render(scene, materials, ro);
    if (!second) return second.error();
    const Bands bands = distance_bands(*reference);
    bench.width = reference->width;
    bench.height = reference->height;
    for (unsigned char h : reference->hit) bench.pixels_hit += h;
    bench.near_distance = bands.near;
    bench.horizon_distance = bands.horizon;
    bench.reference_seconds = std::min(reference->seconds, second->seconds);
    bench.reference_samples = reference->samples;
    bench.reference_repeatability = compare(*reference, *second, bands);
    if (options.note)
        options.note(scene.path + ": reference (" + std::to_string(reference->samples) + " rays per pixel) in " +
                     std::to_string(bench.reference_seconds) + " s");

    // The tables every surface holds now; re-baked when a configuration asks for others.
    using TableKey = std::tuple<int, int, SigmaSpacing>;
    std::optional<TableKey> baked;
    for (const BenchConfiguration& c : options.configurations) {
        BenchRow row;
        row.configuration = c;
        const TableKey key{c.table_values, c.table_sigmas, c.spacing};
        if (c.method == RenderMethod::Gaussian && !(baked == key)) {
            GaussianColorTableOptions to;
            to.values = c.table_values;
            to.sigmas = c.table_sigmas;
            to.spacing = c.spacing;
            to.threads = options.threads;
            for (SurfaceMaterial& m : materials) {
                auto table = GaussianColorTable::bake(m.map, to);
                if (!table) return table.error();
                m.table = std::move(*table);
            }
            baked = key;
        }
        if (c.method == RenderMethod::Gaussian)
            for (const SurfaceMaterial& m : materials) row.table_bytes += m.table.data().size() * sizeof(float);
        RenderOptions r;
        r.method = c.method;
        r.samples = c.samples;
        r.seed = options.seed + 2;
        r.threads = options.threads;
        r.footprint = c.footprint;
        r.max_probes = options.max_probes;
        r.edge_coverage = options.edge_coverage;
        row.seconds = std::numeric_limits<double>::infinity();
        Expected<RenderedImage> image = bad_input("bench: no render");
        for (int k = 0; k < options.repeats; ++k) {
            image = render(scene, materials, r);
            if (!image) return image.error();
            row.seconds = std::min(row.seconds, image->seconds);
        }
        row.error = compare(*reference, *image, bands);
        if (options.note)
            options.note(scene.path + ": " + c.label() + ": " + std::to_string(row.seconds) + " s, mean dE00 " +
                         std::to_string(row.error.all.mean));
        bench.rows.push_back(row);
    }
    return bench;
}

std::string bench_csv(const std::vector<SceneBench>& benches)
{
    std::ostringstream s;
    s.precision(6);
    s << "scene,configuration,method,spp,table_values,table_sigmas,spacing,footprint,table_bytes,seconds,"
         "mean,p95,max,near_mean,near_p95,middle_mean,middle_p95,horizon_mean,horizon_p95\n";
    auto errors = [&](const BandedError& e) {
        s << e.all.mean << "," << e.all.p95 << "," << e.all.max << "," << e.near.mean << "," << e.near.p95 << ","
          << e.middle.mean << "," << e.middle.p95 << "," << e.horizon.mean << "," << e.horizon.p95 << "\n";
    };
    for (const SceneBench& b : benches) {
        s << b.scene << ",reference," << "reference," << b.reference_samples << ",,,,,0," << b.reference_seconds << ",";
        errors(BandedError{});
        s << b.scene << ",reference-repeat," << "reference," << b.reference_samples << ",,,,,0," << b.reference_seconds
          << ",";
        errors(b.reference_repeatability);
        for (const BenchRow& r : b.rows) {
            const BenchConfiguration& c = r.configuration;
            s << b.scene << "," << c.label() << "," << to_string(c.method) << "," << c.samples << ",";
            if (c.method == RenderMethod::Gaussian)
                s << c.table_values << "," << c.table_sigmas << "," << to_string(c.spacing);
            else
                s << ",,";
            s << "," << (c.method == RenderMethod::Supersample ? "" : to_string(c.footprint));
            s << "," << r.table_bytes << "," << r.seconds << ",";
            errors(r.error);
        }
    }
    return s.str();
}

}  // namespace cmfilter
