// SPDX-License-Identifier: Apache-2.0
// The PTM and HSH bases: PTM against its monomials; HSH against the
// hemispherical harmonics of Gautron et al. 2004 computed here from their
// definition (shifted associated Legendre polynomials, factorials), and
// their orthonormality over the hemisphere by quadrature.
#include "cmfilter/stack/linear_model.h"

#include "cmfilter/math/gauss_legendre.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace cmfilter;

namespace {

constexpr double kPi = 3.14159265358979323846;

double factorial(int n)
{
    double f = 1;
    for (int i = 2; i <= n; ++i) f *= i;
    return f;
}

// The associated Legendre function P_l^m(x), m >= 0, WITHOUT the
// Condon-Shortley phase (-1)^m, by the standard recurrences:
// P_m^m = (2m - 1)!! (1 - x^2)^(m/2), P_{m+1}^m = x (2m + 1) P_m^m,
// (l - m) P_l^m = x (2l - 1) P_{l-1}^m - (l + m - 1) P_{l-2}^m.
double legendre(int l, int m, double x)
{
    double pmm = 1;
    const double root = std::sqrt(std::max(0.0, 1 - x * x));
    for (int i = 1; i <= m; ++i) pmm *= (2 * i - 1) * root;
    if (l == m) return pmm;
    double pm1 = x * (2 * m + 1) * pmm;
    if (l == m + 1) return pm1;
    double pll = 0;
    for (int ll = m + 2; ll <= l; ++ll) {
        pll = (x * (2 * ll - 1) * pm1 - (ll + m - 1) * pmm) / (ll - m);
        pmm = pm1;
        pm1 = pll;
    }
    return pll;
}

// Gautron et al. 2004, eq. 6-7: H_l^m(theta, phi) with the shifted argument
// 2 cos(theta) - 1 and K_l^m = sqrt((2l + 1)(l - |m|)! / (2 pi (l + |m|)!)).
double gautron_hsh(int l, int m, double theta, double phi)
{
    const int am = std::abs(m);
    const double k = std::sqrt((2 * l + 1) * factorial(l - am) / (2 * kPi * factorial(l + am)));
    const double p = legendre(l, am, 2 * std::cos(theta) - 1);
    if (m > 0) return std::sqrt(2.0) * k * std::cos(m * phi) * p;
    if (m < 0) return std::sqrt(2.0) * k * std::sin(am * phi) * p;
    return k * p;
}

// RTIViewer's order of the terms: (l, m) and the sign of its closed form
// relative to Gautron's definition without the Condon-Shortley phase. The
// m = +-2 terms (4 and 8) carry RTIViewer's (-cos(theta) + cos^2(theta)),
// the negative of 3 (1 - x^2) / 4 = cos(theta) - cos^2(theta) in
// P_2^2(2 cos(theta) - 1); the other terms agree in sign.
struct TermIndex {
    int l, m;
    double sign;
};
constexpr TermIndex kRtiViewerTerms[9] = {{0, 0, 1}, {1, 1, 1}, {1, 0, 1},  {1, -1, 1}, {2, 2, -1},
                                          {2, 1, 1}, {2, 0, 1}, {2, -1, 1}, {2, -2, -1}};

Vec3 direction(double theta, double phi)
{
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

}  // namespace

TEST_CASE("linear model: names round trip and term counts")
{
    for (LinearModel m : {LinearModel::PtmRgb, LinearModel::PtmLrgb, LinearModel::Hsh2, LinearModel::Hsh3}) {
        auto parsed = parse_linear_model(to_string(m));
        REQUIRE(parsed);
        CHECK(*parsed == m);
    }
    CHECK_FALSE(parse_linear_model("ptm"));
    CHECK(basis_terms(LinearModel::PtmRgb) == 6);
    CHECK(basis_terms(LinearModel::PtmLrgb) == 6);
    CHECK(basis_terms(LinearModel::Hsh2) == 4);
    CHECK(basis_terms(LinearModel::Hsh3) == 9);
}

TEST_CASE("linear model: the PTM basis is Malzbender's six monomials")
{
    for (double theta : {0.0, 0.3, 0.9, 1.4})
        for (double phi : {0.0, 1.0, 2.5, -2.0}) {
            const Vec3 l = direction(theta, phi);
            const auto b = evaluate_basis(LinearModel::PtmRgb, l);
            const double expected[6] = {l.x * l.x, l.y * l.y, l.x * l.y, l.x, l.y, 1};
            for (int k = 0; k < 6; ++k) CHECK(b[static_cast<std::size_t>(k)] == doctest::Approx(expected[k]));
            CHECK(evaluate_basis(LinearModel::PtmLrgb, l) == b);
        }
}

TEST_CASE("linear model: HSH terms match Gautron's definition (RTIViewer's signs)")
{
    for (double theta : {0.0, 0.2, 0.7, 1.1, 1.5})
        for (double phi : {0.0, 0.4, 1.9, 3.0, -1.2, -2.8}) {
            const Vec3 l = direction(theta, phi);
            const auto h3 = evaluate_basis(LinearModel::Hsh3, l);
            const auto h2 = evaluate_basis(LinearModel::Hsh2, l);
            for (int k = 0; k < 9; ++k) {
                const TermIndex& t = kRtiViewerTerms[k];
                const double expected = t.sign * gautron_hsh(t.l, t.m, theta, phi);
                CHECK(h3[static_cast<std::size_t>(k)] == doctest::Approx(expected).epsilon(1e-12));
                if (k < 4) CHECK(h2[static_cast<std::size_t>(k)] == doctest::Approx(expected).epsilon(1e-12));
            }
        }
}

TEST_CASE("linear model: HSH 3 is orthonormal over the hemisphere")
{
    // dOmega = d(cos theta) d(phi); cos theta by Gauss-Legendre (the
    // products are polynomials in cos theta once the phi integral has
    // removed the odd ones), phi by a uniform rule (exact for the
    // trigonometric polynomials of degree < 64 that occur).
    const int phis = 64;
    double gram[9][9] = {};
    for (int p = 0; p < phis; ++p) {
        const double phi = 2 * kPi * (p + 0.5) / phis;
        for (int i = 0; i < 9; ++i)
            for (int j = 0; j < 9; ++j)
                gram[i][j] += (2 * kPi / phis) * gauss_legendre_8(
                                                     [&](double c) {
                    const Vec3 l = direction(std::acos(c), phi);
                    const auto b = evaluate_basis(LinearModel::Hsh3, l);
                    return b[static_cast<std::size_t>(i)] * b[static_cast<std::size_t>(j)];
                                                     },
                                                     0.0, 1.0, 4);
    }
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) CHECK(gram[i][j] == doctest::Approx(i == j ? 1.0 : 0.0).epsilon(1e-9));
}
