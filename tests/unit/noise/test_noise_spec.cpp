// SPDX-License-Identifier: Apache-2.0
// NoiseSpec: text form round trips, defaults, errors that name the bad value,
// and the noise it makes.
#include "cmfilter/noise/noise_spec.h"

#include "cmfilter/noise/gradient_noise.h"

#include <doctest/doctest.h>

#include <cmath>
#include <utility>

using namespace cmfilter;

namespace {

std::string error_of(const std::string& text)
{
    auto spec = parse_noise_spec(text);
    if (spec) return "(parsed)";
    CHECK(spec.error().kind == ErrorKind::BadInput);
    return spec.error().message;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("noise specs parse with defaults and print in full")
{
    auto plain = parse_noise_spec("gradient");
    REQUIRE(plain);
    CHECK(plain->basis == NoiseBasis::Gradient);
    CHECK_FALSE(plain->fractal);
    CHECK(to_string(*plain) == "gradient:seed=0");

    auto fbm = parse_noise_spec("fbm:base=value,octaves=4,gain=0.6,seed=12");
    REQUIRE(fbm);
    CHECK(fbm->basis == NoiseBasis::Value);
    CHECK(fbm->fractal == FractalSum::Fbm);
    CHECK(fbm->fractal_options.octaves == 4);
    CHECK(fbm->fractal_options.lacunarity == 2.0);
    CHECK(to_string(*fbm) == "fbm:base=value,octaves=4,lacunarity=2,gain=0.6,seed=12");

    auto gabor = parse_noise_spec("turbulence:base=gabor,frequency=0.25,orientation=1.2,density=3");
    REQUIRE(gabor);
    CHECK(to_string(*gabor) == "turbulence:base=gabor,octaves=6,lacunarity=2,gain=0.5,amplitude=1,"
                               "bandwidth=0.8,frequency=0.25,density=3,orientation=1.2,seed=0");
}

TEST_CASE("noise specs round trip through their text form")
{
    NoiseSpec s;
    s.basis = NoiseBasis::Gabor;
    s.fractal = FractalSum::Turbulence;
    s.fractal_options = {5, 2.0 / 3.0 + 1.0, 0.1, FractalSum::Turbulence};  // 5/3: needs 17 digits
    s.gabor.bandwidth = 0.1 * 3;
    s.gabor.orientation = -0.7;
    s.seed = 18446744073709551615ull;
    auto back = parse_noise_spec(to_string(s));
    REQUIRE(back);
    CHECK(*back == s);
    for (const char* text : {"value:seed=3", "gabor:amplitude=2,bandwidth=1,frequency=0,density=5,seed=1",
                             "fbm:base=gradient,octaves=1,lacunarity=3.5,gain=1,seed=9"}) {
        auto p = parse_noise_spec(text);
        REQUIRE(p);
        CHECK(to_string(*p) == text);
    }
}

TEST_CASE("the names other tools use for the same noises parse to it")
{
    // OSL's noise("perlin") and noise("snoise") are signed gradient noise;
    // RenderMan spells fBm "fBm". Each alias gives the canonical spec, and
    // the canonical text is what is printed and recorded.
    const std::pair<const char*, const char*> same[] = {
        {"perlin", "gradient"},
        {"snoise:seed=4", "gradient:seed=4"},
        {"Perlin", "gradient"},
        {"fBm:base=perlin,octaves=3", "fbm:base=gradient,octaves=3"},
        {"Turbulence:base=snoise", "turbulence:base=gradient"},
        {"FBM:base=Value", "fbm:base=value"},
    };
    for (const auto& pair : same) {
        const char* alias = pair.first;
        const char* canonical = pair.second;
        CAPTURE(alias);
        auto a = parse_noise_spec(alias);
        auto c = parse_noise_spec(canonical);
        REQUIRE(a);
        REQUIRE(c);
        CHECK(*a == *c);
        CHECK(to_string(*a) == to_string(*c));
        CHECK(to_string(*a).rfind(std::string(canonical).substr(0, std::string(canonical).find(':')), 0) == 0);
    }
}

TEST_CASE("noise spec errors name the bad key or value")
{
    CHECK(contains(error_of("simplex"), "'simplex'"));
    CHECK(contains(error_of("fbm:base=simplex"), "'simplex'"));
    CHECK(contains(error_of("fbm:octaves=three"), "octaves: 'three'"));
    CHECK(contains(error_of("fbm:octaves=2.5"), "octaves: '2.5'"));
    CHECK(contains(error_of("gradient:octaves=3"), "octaves does not apply"));
    CHECK(contains(error_of("fbm:frequency=3"), "frequency does not apply"));
    CHECK(contains(error_of("value:seed=-1"), "seed: '-1'"));
    CHECK(contains(error_of("value:seed=1,seed=2"), "seed is given twice"));
    CHECK(contains(error_of("gabor:bandwidth"), "'bandwidth' is not key=value"));
    CHECK(contains(error_of("gabor:bandwidth=inf"), "bandwidth: 'inf'"));
    // Values that parse but make no valid noise fail in make_noise, named too.
    auto spec = parse_noise_spec("fbm:lacunarity=0.5");
    REQUIRE(spec);
    auto noise = make_noise(*spec);
    REQUIRE_FALSE(noise);
    CHECK(contains(noise.error().message, "lacunarity must be > 1"));
    spec = parse_noise_spec("gabor:bandwidth=-2");
    REQUIRE(spec);
    noise = make_noise(*spec);
    REQUIRE_FALSE(noise);
    CHECK(contains(noise.error().message, "bandwidth"));
}

TEST_CASE("a noise spec makes the noise it names")
{
    // One octave of gradient noise: the basis itself at a seed-shifted point,
    // so its range is the basis' bound.
    auto spec = parse_noise_spec("gradient:seed=5");
    REQUIRE(spec);
    auto noise = make_noise(*spec);
    REQUIRE(noise);
    CHECK(noise->options().octaves == 1);
    for (double x = 0.1; x < 50; x += 0.7) CHECK(std::fabs((*noise)(x, 0.5 * x)) <= GradientNoise::bound_2d);
    // Same spec, same noise; another seed, another.
    auto again = make_noise(*spec);
    auto other = make_noise(*parse_noise_spec("gradient:seed=6"));
    REQUIRE(again);
    REQUIRE(other);
    CHECK((*again)(3.3, 4.4) == (*noise)(3.3, 4.4));
    CHECK((*other)(3.3, 4.4) != (*noise)(3.3, 4.4));
    // Gabor's base period is its wavelength.
    auto gabor = make_noise(*parse_noise_spec("fbm:base=gabor,frequency=0.25"));
    REQUIRE(gabor);
    CHECK(gabor->base_period() == 4.0);
    // Turbulence measures its basis' mean |n|: for gradient noise, between 0 and the bound.
    auto turbulence = make_noise(*parse_noise_spec("turbulence:octaves=3"));
    REQUIRE(turbulence);
    CHECK(turbulence->octave_mean() > 0.05);
    CHECK(turbulence->octave_mean() < GradientNoise::bound_2d);
}
