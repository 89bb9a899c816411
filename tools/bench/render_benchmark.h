// SPDX-License-Identifier: Apache-2.0
// Speed against accuracy for `cmfilter bench` (docs/render.md): one scene
// rendered by every method and configuration, each timed (the pixel loop's
// wall time, fastest of `repeats`) and compared per pixel (CIEDE2000) with a
// reference of `reference_samples` rays per pixel, over the pixels a
// surface covers at least in part (any of the reference's rays hits one,
// or its centre ray does: silhouette and horizon pixels count even where
// the centre ray misses), and per distance band: those pixels split in three
// equal-count bands by the mean distance of the reference's rays that hit
// (near, middle, horizon). A second reference with other seeds measures how repeatable the
// reference itself is: the two must differ by at most `reference_repeat`
// mean CIEDE2000 (0.2). Where a scene's driver is too fine for that at
// `reference_samples` rays (a noise far below the pixel), both references
// grow until it holds: each round renders both once more with fresh seeds and
// averages it in, so the rays per pixel go N, 2N, 3N, ... up to
// `max_reference_samples`: the fewest rays that make the reference as
// repeatable as asked (the rows then say how many it took).
// With a region (BenchOptions::region) every render, the references and
// each configuration, computes only the region's pixels, and the errors, the
// bands and the references' growth are the region's: a region's reference
// holds the whole frame's pixels bit for bit when its rays are fixed
// (max_reference_samples == reference_samples: one round), since every
// pixel's rays are seeded by its index in the frame (docs/farm.md).
#pragma once

#include "cmfilter/util/error.h"
#include "cmfilter/color/error_summary.h"
#include "cmfilter/tables/gaussian_color_table.h"
#include "cmfilter/render/pixel_region.h"
#include "cmfilter/render/render.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/scene/scene_materials.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cmfilter::bench {

struct BenchConfiguration {
    RenderMethod method = RenderMethod::Gaussian;
    int samples = 1;         // supersample: rays per pixel
    int table_values = 256;  // gaussian: the table every surface is re-baked with
    int table_sigmas = 256;
    SigmaSpacing spacing = SigmaSpacing::Sqrt;
    FootprintWidth footprint = FootprintWidth::Rms;  // naive, gaussian
    // gaussian: > 0, every surface gets the smallest table that meets this
    // CIEDE2000 over its own sigma range instead (tolerance_tables.h; the
    // table sizes above are then unused)
    double tolerance = 0;
    // gaussian: the small-sigma shortcut's CIEDE2000 bound (plain_lookup.h); 0: off
    double shortcut = 0;
    // e.g. "gaussian 64x64 sqrt", "gaussian 256x256 sqrt major", "gaussian 256x256 sqrt shortcut 0.1",
    // "gaussian tol 1" (shortcut kPlainLookupFraction x 1), "gaussian tol 1 no-shortcut", "supersample 16"
    std::string label() const;
};

// naive; exact (rms footprint width; only run on scenes it can filter);
// gaussian-exact (only on scenes with a microsurface, with the tables the
// materials hold when the bench starts);
// gaussian with 16 x 16, 64 x 64 and 256 x 256 tables, sqrt and linear sigma
// spacing (rms footprint width), and the 256 x 256 sqrt table with the area,
// major and minor footprint widths; gaussian with tables fitted to tolerances
// 1 and 0.5, with the small-sigma shortcut at its default bound (a tenth of
// the tolerance), tolerance 1 without the shortcut, and the 256 x 256 sqrt
// table with the shortcut at bound 0.1; supersample with 1, 4, 16, 64 and 256
// rays per pixel.
std::vector<BenchConfiguration> default_bench_configurations();

// The configurations of `all` whose labels are listed, in `all`'s order;
// BadInput naming a label that is not there, and the labels that are.
Expected<std::vector<BenchConfiguration>> select_bench_configurations(const std::vector<BenchConfiguration>& all,
                                                                      const std::vector<std::string>& labels);

struct BandedError {
    ErrorSummary all, near, middle, horizon;
};

struct BenchRow {
    BenchConfiguration configuration;
    double seconds = 0;           // pixel loop, fastest of the repeats
    std::size_t table_bytes = 0;  // gaussian: float32 RGB tables of every surface
    // What the method reads of every surface's driver, as stored (float32):
    // a noise's sigma table (supersampling: nothing, it is procedural); a
    // texture's pyramid of 1 (naive), 2 (gaussian) or 4 (mixture) channels,
    // or of one weight per distinct value (exact), over its levels (4/3 of
    // level 0), or level 0 alone (supersampling); microsurfaces: 0 (not
    // counted).
    std::size_t driver_bytes = 0;
    double table_error = 0;  // gaussian with a tolerance: the largest fitted table's lookup error (p99.9)
    // gaussian: the tables' axes when every surface's agree (else values 0)
    int table_values = 0, table_sigmas = 0;
    SigmaSpacing spacing = SigmaSpacing::Sqrt;
    std::size_t footprints = 0;        // gaussian: footprints (pixels or probes) coloured
    std::size_t plain_footprints = 0;  // of which took C0(mean) directly (the shortcut)
    BandedError error;                 // against the reference
};

struct SceneBench {
    std::string scene;
    int width = 0, height = 0;   // the frame
    PixelRegion region;          // the pixels rendered and compared (the whole frame without a region)
    std::size_t pixels_hit = 0;  // the pixels compared: a surface covers them at least in part
    double near_distance = 0, horizon_distance = 0;  // band limits: the hit distances' terciles
    double reference_seconds = 0;                    // the reference's rounds together
    int reference_samples = 0;                       // rays per pixel of the reference, all rounds together
    BandedError reference_repeatability;             // the reference against the second one (other seeds)
    std::vector<BenchRow> rows;
    // The reference the rows were measured against (all its rounds), when
    // BenchOptions::keep_reference.
    std::optional<RenderedImage> reference_image;
};

struct BenchOptions {
    std::vector<BenchConfiguration> configurations = default_bench_configurations();
    int reference_samples = kReferenceSamples;           // rays per pixel of each reference round
    double reference_repeat = 0.2;                       // mean CIEDE2000 the two references may differ by
    int max_reference_samples = 16 * kReferenceSamples;  // stop growing here (then the repeat may exceed it)
    int repeats = 3;
    std::uint64_t seed = 0;
    int threads = 0;
    int max_probes = 16;                           // RenderOptions::max_probes for naive and gaussian
    SubFootprintOptions sub_footprints;            // RenderOptions::sub_footprints for mixture
    bool edge_coverage = true;                     // RenderOptions::edge_coverage for naive and gaussian
    std::optional<PixelRegion> region;             // RenderOptions::region of every render; empty: the frame
    bool keep_reference = false;                   // keep the reference image in SceneBench::reference_image
    std::function<void(const std::string&)> note;  // one line per finished render, may be empty
};

// BadInput naming the field unless kReferenceSamples <= reference_samples
// <= max_reference_samples <= kMaxSamples and reference_repeat is finite and
// >= 0; bench_scene checks it first, and then that the region, if any, lies
// in the scene's frame (BadInput naming BenchOptions::region).
Status check_reference_options(const BenchOptions& options);

// `materials` are re-baked in place for each gaussian configuration (their
// colour maps stay), or fitted to its tolerance (choose_surface_tables). An
// exact configuration runs only when every surface has a texture driver with
// at most kHistogramMaxValues distinct values (exact_filterable,
// scene_materials.h), and is left out of the rows otherwise; the histogram
// pyramids it needs are baked into the materials then, unless they hold them
// already (a microsurface needs none). gaussian-exact runs only on a scene
// with a microsurface (elsewhere it is gaussian).
Expected<SceneBench> bench_scene(const Scene& scene, std::vector<Material>& materials, const BenchOptions& options);

// CSV: header and one row per configuration (and the reference's
// repeatability as method "reference-repeat"), for every scene.
std::string bench_csv(const std::vector<SceneBench>& benches);

}  // namespace cmfilter::bench
