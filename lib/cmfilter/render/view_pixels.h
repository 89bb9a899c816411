// SPDX-License-Identifier: Apache-2.0
// The pixels of a view that render --method auto measures its per-surface
// choices on (microsurface_method_choice.h, surface_probe_choice.h): the
// whole frame's centre rays traced as render traces them, up to a number of
// each surface's pixels spread evenly over them in scan order, coloured one
// surface at a time by a surface renderer as the render colours them
// (shaded, without edge coverage), and the mean CIEDE2000 between two
// colourings per band of the pixels' LOD (its integer part).
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/microsurface/height_moment_table.h"
#include "cmfilter/render/render_options.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/scene/scene_materials.h"
#include "cmfilter/scene/surface_hit.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <string>
#include <vector>

namespace cmfilter {

struct SurfacePixels {
    std::size_t surface_pixels = 0;  // the frame's pixels whose centre ray hits the surface
    std::vector<SurfaceHit> hits;    // up to max_pixels of their centre rays' hits
};

// One entry per scene surface (its hits empty where no pixel sees it), the
// whole frame of the scene's camera whatever region a render asks for.
// max_pixels >= 1.
Expected<std::vector<SurfacePixels>> sample_surface_pixels(const Scene& scene, std::size_t max_pixels, int threads);

struct ColouredPixels {
    std::vector<Rgb> colours;  // shaded, scene-linear
    std::vector<double> lods;  // FilteredHit::lod (the render's LOD AOV)
    double seconds = 0;        // wall time to colour them
};

// Each hit of `surface` coloured by the renderer render makes for it under
// `options` (its method, per-surface choices and probes) and shaded.
// `table` serves gaussian-exact on microsurfaces (may be null otherwise).
Expected<ColouredPixels> colour_surface_pixels(const Scene& scene, const Material& material, std::size_t surface,
                                               const RenderOptions& options, const HeightMomentTable* table,
                                               const std::vector<SurfaceHit>& hits);

// The pixels' LOD bands [L, L + 1), L integer, in increasing order.
struct LodBands {
    std::vector<double> lods;         // each band's L
    std::vector<std::size_t> pixels;  // pixels per band
    std::vector<std::size_t> band;    // each pixel's band
};
LodBands lod_bands(const std::vector<double>& lods);

// Mean CIEDE2000 between `colours` and `reference` (pixel by pixel) per
// band, over all pixels, and the worst band (the first of equals).
struct BandedError {
    std::vector<double> errors;
    double mean = 0, worst = 0, worst_lod = 0;
};
BandedError banded_error(const LodBands& bands, const std::vector<Rgb>& colours, const std::vector<Rgb>& reference);

// One candidate of a choice measured on the view: its colours against the
// reference's, per band, and whether its worst band meets the tolerance.
struct ViewTrial {
    std::vector<double> errors;  // mean CIEDE2000 per LOD band (ViewMeasurement::lods)
    double mean = 0;             // over every measured pixel
    double worst = 0;            // the largest of `errors`
    double worst_lod = 0;        // its band
    double seconds = 0;          // wall time to colour the measured pixels
    bool meets = false;
};
ViewTrial measure_trial(const LodBands& bands, const ColouredPixels& coloured, const ColouredPixels& reference,
                        double tolerance);

// What a choice measured on the view measured: its tolerance, the surface's
// pixels and its LOD bands.
struct ViewMeasurement {
    double tolerance = 0;
    std::size_t surface_pixels = 0;  // the frame's pixels whose centre ray hits the surface
    std::size_t pixels = 0;          // of those, measured
    std::vector<double> lods;        // each band's least LOD: band [L, L + 1)
    std::vector<std::size_t> band_pixels;
};
ViewMeasurement view_measurement(double tolerance, const SurfacePixels& pixels, const LodBands& bands);

// BadInput naming `<options>::tolerance` or `<options>::max_pixels` (e.g.
// "ProbeChoiceOptions") for a tolerance not finite and > 0 or a pixel count
// below 1.
Status check_view_choice(const std::string& options, double tolerance, int max_pixels);

}  // namespace cmfilter
