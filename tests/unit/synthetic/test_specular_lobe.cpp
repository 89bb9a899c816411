// SPDX-License-Identifier: Apache-2.0
// Specular lobes (specular_lobe.h): Blinn-Phong's albedo at normal
// incidence is ks, by quadrature of the lobe over the hemisphere, for
// several exponents; its closed-form normalisation against the same
// quadrature; GGX's albedo about ks for a smooth lobe, less for a rough
// one; parsing and its errors.
#include "cmfilter/synthetic/specular_lobe.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace cmfilter;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The integral over the hemisphere of pi f <m, l> / pi for v = m = z.
double albedo(const SpecularLobe& lobe, int steps = 1500)
{
    const Vec3 m{0, 0, 1};
    double sum = 0;
    for (int a = 0; a < steps; ++a) {
        const double theta = 0.5 * kPi * (a + 0.5) / steps;
        for (int b = 0; b < 8; ++b) {  // the lobe is isotropic about m = v
            const double phi = 2 * kPi * (b + 0.5) / 8;
            const Vec3 l{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
            sum += specular_factor(lobe, m, l, m) / kPi * std::cos(theta) * std::sin(theta) * (0.5 * kPi / steps) *
                   (2 * kPi / 8);
        }
    }
    return sum;
}

}  // namespace

TEST_CASE("specular lobe: Blinn-Phong's albedo at normal incidence is ks")
{
    for (double n : {0.0, 1.0, 8.0, 64.0, 500.0}) {
        const SpecularLobe lobe{SpecularKind::BlinnPhong, 0.4, n, 0.2};
        CHECK(albedo(lobe, n > 100 ? 6000 : 1500) == doctest::Approx(0.4).epsilon(2e-3));
    }
    CHECK(blinn_phong_normalisation(0) == doctest::Approx(kPi));
}

TEST_CASE("specular lobe: GGX's albedo at normal incidence is about F0 when smooth, less when rough")
{
    const double smooth = albedo({SpecularKind::Ggx, 0.5, 32, 0.05}, 20000);
    CHECK(smooth == doctest::Approx(0.5).epsilon(0.03));
    const double rough = albedo({SpecularKind::Ggx, 0.5, 32, 0.8});
    CHECK(rough < 0.5);
    CHECK(rough > 0.1);
}

TEST_CASE("specular lobe: option strings and their errors")
{
    auto b = parse_specular_lobe("blinn-phong:ks=0.3,n=50");
    REQUIRE(b);
    CHECK(b->kind == SpecularKind::BlinnPhong);
    CHECK(b->ks == 0.3);
    CHECK(b->exponent == 50);
    auto g = parse_specular_lobe("ggx:alpha=0.25,ks=0.04");
    REQUIRE(g);
    CHECK(g->kind == SpecularKind::Ggx);
    CHECK(g->alpha == 0.25);
    auto round = parse_specular_lobe(specular_text(*g));
    REQUIRE(round);
    CHECK(round->alpha == 0.25);
    CHECK(round->ks == 0.04);
    CHECK(parse_specular_lobe("none")->kind == SpecularKind::None);
    for (const char* bad : {"phong:ks=1,n=2", "ggx", "ggx:ks=0.04", "ggx:ks=0.04,alpha=0", "ggx:ks=2,alpha=0.1",
                            "blinn-phong:ks=0.1,n=x", "blinn-phong:ks=0.1,ks=0.2,n=3", "blinn-phong:ks=0.1,alpha=3"}) {
        auto e = parse_specular_lobe(bad);
        REQUIRE_FALSE(e);
        CHECK(e.error().message.find(std::string("'") + bad + "'") != std::string::npos);
        CHECK(e.error().field == "MakeStackOptions::specular");
    }
}
