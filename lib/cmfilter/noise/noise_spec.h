// SPDX-License-Identifier: Apache-2.0
// A procedural noise as a value: basis, fractal sum, parameters and seed, with
// a text form for the command line and for artefact metadata:
//     BASIS[:key=value,...]                 one octave of gradient | value | gabor
//     fbm[:base=BASIS,key=value,...]        fractal sums (fractal_noise.h)
//     turbulence[:base=BASIS,key=value,...]
// keys: seed (all); octaves, lacunarity, gain (fbm, turbulence); amplitude,
// bandwidth, frequency, orientation (radians; absent: isotropic), density
// (impulses per unit area) (gabor basis). Unset keys keep their defaults.
// to_string prints every key of the spec's kind, numbers in shortest
// round-trip form, so parse(to_string(s)) == s.
#pragma once

#include "cmfilter/util/error.h"
#include "cmfilter/noise/fractal_noise.h"
#include "cmfilter/noise/gabor_noise.h"

#include <cstdint>
#include <optional>
#include <string>

namespace cmfilter {

enum class NoiseBasis { Gradient, Value, Gabor };
const char* to_string(NoiseBasis basis);

struct NoiseSpec {
    NoiseBasis basis = NoiseBasis::Gradient;
    std::optional<FractalSum> fractal;  // none: a single octave of the basis
    FractalOptions fractal_options;     // used when fractal is set
    GaborNoiseOptions gabor;            // used when basis is Gabor
    std::uint64_t seed = 0;
};

bool operator==(const NoiseSpec& a, const NoiseSpec& b);

// Parses the text form; errors (BadInput) quote the offending key or value.
Expected<NoiseSpec> parse_noise_spec(const std::string& text);
std::string to_string(const NoiseSpec& spec);

// The noise a spec describes, as a FractalNoise (one octave for a plain basis),
// with every parameter validated. Turbulence measures the basis' mean |n|
// (measure_mean_abs).
Expected<FractalNoise> make_noise(const NoiseSpec& spec);

}  // namespace cmfilter
