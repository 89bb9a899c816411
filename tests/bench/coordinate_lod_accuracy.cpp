// SPDX-License-Identifier: Apache-2.0
// Rendering through a coordinate map at a level of detail (coordinate_lookup.h)
// against the box-filtered full-size output (the reference), for L = 1 .. 6
// and every method: the naive mip of the coordinates, the centre texel's
// coordinate into the sample's level L, hierarchical synthesis's own level
// maps (where the map has them) and the per-footprint patch offsets read
// exactly from a summed-area table (Bosserhoff & Nicoll sec. 4.2: a
// coordinate map is a driver, and a mip of it averages across seams).
// CSV on stdout:
//   lod,method,rmse,mean_abs,ms
// (ms: the fastest of three renders of the whole level, reference included).
//
//   cmfilter-coordinate-lod-accuracy MAP.exr --source SAMPLE|FIT [--image I]
//       [--light x,y,z] [--view x,y,z] [--periodic] [--patches P] [--threads T]
//   cmfilter-coordinate-lod-accuracy --synthetic-seams [--size N] [--sample N]
//       [--min-side S] [--max-side S] [--periodic] [--seed S] [--patches P] [--threads T]
// The second needs no synthesis: random rectangular patches (one offset
// each) of a procedural sample (tests/support/patch_map_support.h).
#include "cmfilter/color/color_config.h"
#include "cmfilter/synthesis/coordinate_lookup.h"
#include "cmfilter/synthesis/synthesis_source.h"
#include "cmfilter/synthesis/coordinate_map_file.h"

#include "bench_timing.h"
#include "patch_map_support.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

using namespace cmfilter;

namespace {

int fail(const std::string& message)
{
    std::cerr << "cmfilter-coordinate-lod-accuracy: " << message << "\n";
    return 2;
}

std::optional<Vec3> parse_direction(const std::string& text)
{
    Vec3 d;
    char c1 = 0, c2 = 0;
    std::istringstream in(text);
    if (!(in >> d.x >> c1 >> d.y >> c2 >> d.z) || c1 != ',' || c2 != ',') return std::nullopt;
    return d;
}

}  // namespace

int main(int argc, char** argv)
{
    std::string map_path;
    SourceOptions source;
    bool synthetic = false, periodic = false;
    int size = 512, sample_size = 128, min_side = 8, max_side = 48, patches = 4, threads = 0;
    std::uint64_t seed = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const auto next = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::cerr << "cmfilter-coordinate-lod-accuracy: " << a << " needs a value\n";
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--synthetic-seams") synthetic = true;
        else if (a == "--periodic") periodic = true;
        else if (a == "--source") source.path = next();
        else if (a == "--image") source.image = std::stoi(next());
        else if (a == "--light" || a == "--view") {
            const std::string v = next();
            auto d = parse_direction(v);
            if (!d) return fail(a + " '" + v + "' is not x,y,z");
            (a == "--light" ? source.light : source.view) = *d;
        } else if (a == "--size") size = std::stoi(next());
        else if (a == "--sample") sample_size = std::stoi(next());
        else if (a == "--min-side") min_side = std::stoi(next());
        else if (a == "--max-side") max_side = std::stoi(next());
        else if (a == "--seed") seed = std::stoull(next());
        else if (a == "--patches") patches = std::stoi(next());
        else if (a == "--threads") threads = std::stoi(next());
        else if (!a.empty() && a[0] != '-' && map_path.empty()) map_path = a;
        else return fail("unknown argument '" + a + "'");
    }

    CoordinateMap map;
    SampleImage sample;
    if (synthetic) {
        if (size < 1 || sample_size < 2 || min_side < 1 || max_side < min_side || max_side > sample_size)
            return fail("expected --size >= 1, --sample >= 2 and 1 <= --min-side <= --max-side <= --sample");
        sample = cmfilter_test::procedural_sample(sample_size, sample_size, 3, periodic, seed + 1);
        map = cmfilter_test::random_patch_map(size, size, sample_size, sample_size, min_side, max_side, periodic, seed);
    } else {
        if (map_path.empty() || source.path.empty())
            return fail("expected MAP.exr --source SAMPLE, or --synthetic-seams");
        auto read = read_coordinate_map_exr(map_path);
        if (!read) return fail(read.error().message);
        map = std::move(*read);
        auto config = ColorConfig::load("");
        if (!config) return fail(config.error().message);
        source.periodic = periodic;
        source.threads = threads;
        auto loaded = load_source_image(source, *config);
        if (!loaded) return fail(loaded.error().message);
        sample = std::move(loaded->image);
        std::cerr << "source: " << loaded->description << "\n";
    }

    std::printf("lod,method,rmse,mean_abs,ms\n");
    for (int lod = 1; lod <= 6; ++lod) {
        LodOptions options;
        options.lod = lod;
        options.patches = patches;
        options.threads = threads;
        options.method = LodMethod::Reference;
        auto reference = render_at_lod(map, sample, options);
        if (!reference) return fail(reference.error().message);
        for (LodMethod method :
             {LodMethod::Reference, LodMethod::NaiveMip, LodMethod::Point, LodMethod::Levels, LodMethod::Patches}) {
            if (method == LodMethod::Levels && lod >= static_cast<int>(map.levels.size())) continue;
            options.method = method;
            Expected<OutputImage> out = runtime_error("not rendered");
            double best = 1e300;
            for (int run = 0; run < 3; ++run)
                best = std::min(best, cmfilter_bench::time_ms([&] { out = render_at_lod(map, sample, options); }));
            if (!out) return fail(out.error().message);
            const cmfilter_test::ImageDifference d = cmfilter_test::image_difference(*out, *reference);
            std::printf("%d,%s,%.6g,%.6g,%.4g\n", lod, to_string(method), d.rmse, d.mean_abs, best);
        }
    }
    return 0;
}
