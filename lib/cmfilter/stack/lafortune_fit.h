// SPDX-License-Identifier: Apache-2.0
// Per-texel Lafortune lobes (lafortune_model.h) fitted to an image stack:
// every texel (Luminance: its luminance; Rgb: each colour channel) by
// Levenberg-Marquardt with the lobe scales solved linearly, lobes added one
// at a time (lafortune_scalar_fit.h), threaded over rows of texels. No
// random numbers: the result is the same for any thread count.
//
// Auto lobes: per texel (Rgb: per channel) lobes are added while the RMS
// over the lights is above LafortuneFitOptions::tolerance, and a lobe is
// kept only if it cuts that RMS by more than LafortuneFitOptions::min_gain
// of the RMS without it: no more lobes than the texel needs, at most
// LafortuneFitOptions::lobes.
//
// Uneven domes (the second paper, sec. 5: Levenberg-Marquardt "produce[s]
// visual artifacts" where "the sampling over the hemisphere is often not
// evenly spread"): sharp lobes placed between lights fit the images and fail
// at every other light. Four remedies, each off at 0 (measured in
// docs/lafortune-artefacts.md):
//   density_radius     weights each light by 1 / (lights within this angle)
//                      (light_density.h): a dense cluster counts as one
//                      light of an even dome would, the light set resampled;
//   spacing_cap        caps every exponent so the lobe's full width at half
//                      maximum is at least this multiple of the lights' mean
//                      nearest-neighbour spacing (light_density.h): a lobe
//                      narrower than the gaps is not determined by them;
//   exponent_penalty   a prior towards broad lobes (lafortune_scalar_fit.h);
//   relative_epsilon   weights texel value k by 1 / (value_k + epsilon)^2
//                      (with the density weights, scaled to mean 1): dark
//                      values fitted relatively, as CIEDE2000 sees them.
#pragma once

#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/lafortune_model.h"
#include "cmfilter/util/error.h"

#include <vector>

namespace cmfilter {

struct LafortuneFitOptions {
    LafortuneVariant variant = LafortuneVariant::Luminance;
    // The lobes per texel (Rgb: per channel): 1..7 for Luminance, 1..2 for
    // Rgb; with auto_lobes the most.
    int lobes = 2;
    bool auto_lobes = false;
    // Auto: the RMS (the stack's values: luminance, or each channel) at or
    // below which no lobe is added; > 0.
    double tolerance = 0.005;
    // Auto: the least relative cut of the RMS a lobe must make; in [0, 1).
    double min_gain = 0.1;
    Vec3 view{0, 0, 1};       // the images' view direction, z > 0 (normalised)
    int max_iterations = 20;  // Levenberg-Marquardt iterations per refinement, >= 1
    // Levenberg-Marquardt stops when a step changes the texel's squared
    // error by less than this fraction of it; in (0, 1).
    double function_tolerance = 1e-4;
    // The light-density weights' radius in degrees, in [0, 90]; 0: every
    // light weighs 1.
    double density_radius = 0;
    // The exponent cap's multiple of the mean light spacing, >= 0; 0: no cap
    // (exponents up to kLafortuneMaxExponent). The cap is at least 2. The
    // default 2 (lobes at least twice as wide as the gaps between lights)
    // removed the artefacts on every measured dome
    // (docs/lafortune-artefacts.md); lobes sharper than that, exactly
    // recoverable from noise-free images, need 0.
    double spacing_cap = 2;
    // The exponent penalty's fraction of the texel's energy, >= 0
    // (ScalarLobeSettings::exponent_penalty); 0: none.
    double exponent_penalty = 0;
    // The relative weighting's epsilon (the stack's values), >= 0; 0: none.
    double relative_epsilon = 0;
    int threads = 0;  // 0: all cores
};

// The parameters one texel's scalar takes with `lobes` lobes: rho_d and per
// lobe a scale, two axis angles and an exponent.
constexpr int lafortune_scalar_parameters(int lobes) { return 1 + 4 * lobes; }

// BadInput naming the field: lobes outside the variant's range
// (LafortuneFitOptions::lobes); tolerance <= 0 or not finite with
// auto_lobes (::tolerance); min_gain outside [0, 1) (::min_gain); a view
// not finite, of zero length, or at or below the horizon (::view);
// max_iterations < 1 (::max_iterations); function_tolerance outside (0, 1)
// (::function_tolerance); density_radius outside [0, 90], spacing_cap,
// exponent_penalty or relative_epsilon negative or not finite (each by its
// name); fewer lights than
// lafortune_scalar_parameters(lobes) (::lobes: fewer lobes may fit, the
// rule a scalar's parameters to be determined by as many values); an Rgb
// fit of a stack with other than 3 channels, a Luminance fit of other than
// 1 or 3 (::variant); a stack whose sizes and pixel count disagree.
Expected<LafortuneFit> fit_lafortune(const ImageStack& stack, const LafortuneFitOptions& options);

// The most exponent the options allow for these lights: kLafortuneMaxExponent
// without a spacing cap, else exponent_for_lobe_width(spacing_cap x the
// mean light spacing) within [2, kLafortuneMaxExponent].
double lafortune_max_exponent(const std::vector<Vec3>& lights, const LafortuneFitOptions& options);

// The per-light weights the fit gives the lights before any relative
// weighting: light_density_weights(lights, density_radius in radians).
std::vector<double> lafortune_light_weights(const std::vector<Vec3>& lights, const LafortuneFitOptions& options);

// The model at light `light` (unit, z >= 0) and view `view` (unit, z > 0;
// the fitted view unless told) for every texel: width * height * channels
// floats, row-major, top row first. Finite for any light and view.
std::vector<float> relight_lafortune(const LafortuneFit& fit, const Vec3& light, const Vec3& view, int threads = 0);
std::vector<float> relight_lafortune(const LafortuneFit& fit, const Vec3& light, int threads = 0);

}  // namespace cmfilter
