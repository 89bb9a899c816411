// SPDX-License-Identifier: Apache-2.0
// Height-correlated colour on a Gaussian microsurface (Heitz et al. 2013,
// sec. 5.1) at the edges of its domain: every function from Smith's Lambda to
// the height-filtered albedo swept over view and light angles from 0 to just
// beyond 90 degrees, height deviations from 0 to large, slope deviations from
// 0 to 1e3 and Lambda sums up to 1e100 and infinity. Nothing may be NaN or
// infinite (except Lambda itself at and beyond 90 degrees, where eq. 3 is
// +infinity), and every value must stay in its range, the bounds derived
// here rather than read from the code: visibility in [0, 1]; D_h's mean in
// [0, sigma_h sqrt(2 ln(L + 1))] (the mean of the largest of L + 1 normals,
// E max <= sqrt(2 ln n) sigma_h, holds for real L + 1 >= 1 as well) and its
// deviation in [0, sigma_h]; a colour, a mean of the map's colours, within
// the map's per-channel range; an albedo V times such a colour.
#include "cmfilter/microsurface/height_color.h"
#include "cmfilter/microsurface/height_filtered_albedo.h"
#include "cmfilter/microsurface/height_filtering.h"
#include "cmfilter/microsurface/height_moment_table.h"
#include "cmfilter/microsurface/microsurface_footprint.h"
#include "cmfilter/microsurface/smith_lambda.h"

#include "microsurface_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

// View and light angles: 0, small, moderate, grazing, exactly 90 degrees and
// slightly beyond (below the surface: read as 90).
std::vector<double> sweep_thetas()
{
    return {0.0,
            degrees(1e-6),
            degrees(30),
            degrees(60),
            degrees(85),
            degrees(89),
            degrees(89.9),
            degrees(89.999),
            kPi / 2,
            std::nextafter(kPi / 2, 4.0),
            degrees(90.001),
            degrees(91)};
}

const std::vector<double> kSigmaH = {0.0, 1e-12, 1e-6, 0.008, 0.05};
const std::vector<double> kSigmaS = {0.0, 1e-12, 0.35, 10.0, 1e3};
const std::vector<double> kLambdaSums = {0.0, 1e-12, 0.5, 1.0, 10.0, 1e3, 1e6, 1e12, 1e18, 1e100, kInf};

// The resolved part of a footprint: its mean height and the resolved
// surface's height and slope deviations (none, smooth, a needle-thin spike).
struct Resolved {
    double mean_height, sigma_h, sigma_s;
};
const Resolved kResolved[] = {{0.0, 0, 0}, {0.021, 0, 0}, {-0.01, 0.006, 0.3}, {0.004, 1e-12, 1e3}};

// The bound on D_h's mean: sigma_h sqrt(2 ln(L + 1)), L clamped to 1e100 as
// the header documents for infinite sums.
double mean_bound(double lambda_sum, double sigma_h)
{
    return sigma_h * std::sqrt(2 * std::log1p(std::min(lambda_sum, 1e100)));
}

}  // namespace

TEST_CASE("Smith Lambda and the mean visibility stay finite and in range from 0 to beyond 90 degrees")
{
    const std::vector<double> thetas = sweep_thetas();
    std::vector<double> lambdas;
    for (double theta : thetas)
        for (double s : {0.0, 1e-12, 1e-6, 0.35, 10.0, 1e3}) {
            CAPTURE(theta);
            CAPTURE(s);
            const double lambda = smith_lambda_gaussian(theta, s);
            CHECK_FALSE(std::isnan(lambda));
            CHECK(lambda >= 0);
            if (theta < kPi / 2) CHECK(std::isfinite(lambda));  // eq. 3: finite below 90 degrees
            else CHECK(lambda == kInf);                         // +infinity at and beyond 90
            if (theta == 0) CHECK(lambda == 0);
            if (s == 0 && theta < kPi / 2) CHECK(lambda == 0);  // a flat surface masks nothing
            lambdas.push_back(lambda);
            // The same from cot theta.
            if (theta > 0 && theta < kPi / 2) {
                const double from_cot = smith_lambda_gaussian_cot(1 / std::tan(theta), s);
                CHECK(from_cot == doctest::Approx(lambda).epsilon(1e-12));
            }
        }
    CHECK(smith_lambda_gaussian_cot(kInf, 0.3) == 0);
    CHECK(smith_lambda_gaussian_cot(0, 0.3) == kInf);
    // Every pair of those Lambdas: V in [0, 1], never NaN; (1 + Lo) / (1 + Lo + Li) where both are finite.
    for (double lo : lambdas)
        for (double li : lambdas) {
            const double v = mean_visibility(lo, li);
            CAPTURE(lo);
            CAPTURE(li);
            REQUIRE(v >= 0);
            REQUIRE(v <= 1);
            if (std::isfinite(lo) && std::isfinite(li)) CHECK(v == doctest::Approx((1 + lo) / (1 + lo + li)));
        }
    CHECK(mean_visibility(kInf, kInf) == 0.5);
    CHECK(mean_visibility(0, kInf) == 0);
    CHECK(mean_visibility(kInf, 0) == 1);
}

TEST_CASE("the exact moments, the paper fit and the moment table stay finite and in range for any Lambda sum")
{
    auto table = HeightMomentTable::create();
    REQUIRE(table);
    std::vector<double> sums = kLambdaSums;
    sums.push_back(std::nan(""));
    sums.push_back(-1.0);  // below 0 reads as 0
    for (double sigma_h : {0.0, 1e-12, 1e-6, 0.008, 10.0}) {
        double previous_mean = -1;
        for (double L : sums) {
            CAPTURE(sigma_h);
            CAPTURE(L);
            const double as_read = std::isnan(L) || L < 0 ? 0.0 : L;
            const HeightMoments e = exact_height_moments(L, sigma_h);
            const HeightMoments f = paper_height_fit(L, sigma_h);
            const HeightMoments t = table->lookup(L, sigma_h);
            for (const HeightMoments& m : {e, f, t}) {
                CHECK(std::isfinite(m.mean));
                CHECK(std::isfinite(m.sigma));
                CHECK(m.sigma >= 0);
                CHECK(m.sigma <= sigma_h * (1 + 1e-9));
                CHECK(m.mean >= -1e-9 * sigma_h);
            }
            // The exact mean within the bound on the largest of L + 1 normals.
            CHECK(e.mean <= mean_bound(as_read, sigma_h) + 1e-9 * sigma_h);
            // The table reads its last node (L = 1e6) beyond it, within 1e-4 sigma_h of the exact moments.
            const double tabled = std::min(as_read, 1e6);
            CHECK(t.mean <= mean_bound(tabled, sigma_h) + 1e-4 * sigma_h);
            if (as_read <= 1e6) {
                CHECK(std::fabs(t.mean - e.mean) <= 1e-4 * std::max(e.mean, sigma_h));
                CHECK(std::fabs(t.sigma - e.sigma) <= 1e-4 * sigma_h);
            }
            // A flat surface: 0 and 0.
            if (sigma_h == 0) CHECK((e.mean == 0 && e.sigma == 0 && f.mean == 0 && f.sigma == 0 && t.mean == 0));
            // The mean never falls as L grows (the sweep is increasing up to inf).
            if (!std::isnan(L) && L >= 0) {
                CHECK(e.mean >= previous_mean - 1e-12 * sigma_h);
                previous_mean = e.mean;
            }
        }
    }
    // NaN reads as 0.
    CHECK(exact_height_moments(std::nan(""), 1).sigma == doctest::Approx(1).epsilon(1e-9));
    CHECK(table->lookup(std::nan(""), 1).sigma == doctest::Approx(1).epsilon(1e-9));
}

TEST_CASE("the exact height colour stays within the map's colours for any sigma_h, Lambda sum and offset")
{
    const ColorMap map = microsurface_test_map();
    const ColorRange range = color_range(map);
    for (double sigma_h : {0.0, 1e-12, 1e-6, 0.008, 0.05, 10.0})
        for (double L : kLambdaSums)
            for (double offset : {0.0, -0.02, 0.027, 1e3}) {
                CAPTURE(sigma_h);
                CAPTURE(L);
                CAPTURE(offset);
                const Rgb c = exact_height_color(map, sigma_h, L, offset);
                REQUIRE(is_finite(c));
                CHECK(within_scaled_range(c, range, 1.0, 1e-7));
            }
    CHECK(is_finite(exact_height_color(map, 0.01, std::nan(""))));
}

TEST_CASE("a footprint of any size on a microsurface of any roughness gives finite, consistent spreads")
{
    for (double sigma_h : {0.0, 1e-12, 1e-6, 0.008}) {
        const GaussianMicrosurface surface = test_microsurface(sigma_h, 32, 9);
        double amplitude_sum = 0;
        for (const GaussianMicrosurface::Cosine& k : surface.cosines()) amplitude_sum += std::fabs(k.amplitude);
        for (double w : {0.0, 1e-12, 1e-3, 0.3, 1e6, 1e12})
            for (double shear : {0.0, 0.7}) {
                CAPTURE(sigma_h);
                CAPTURE(w);
                CAPTURE(shear);
                const MicrosurfaceFootprint f =
                    filter_microsurface(surface, 1.37, -2.9, w, shear * w, -0.4 * w, 1.2 * w);
                CHECK(std::isfinite(f.mean_height));
                CHECK(std::fabs(f.mean_height) <= amplitude_sum * (1 + 1e-12));
                CHECK(std::isfinite(f.sigma_h));
                CHECK(f.sigma_h >= 0);
                CHECK(f.sigma_h <= sigma_h * (1 + 1e-12));
                CHECK(std::isfinite(f.slope_xx));
                CHECK(std::isfinite(f.slope_yy));
                CHECK(std::isfinite(f.slope_xy));
                CHECK(f.slope_xx >= 0);
                CHECK(f.slope_yy >= 0);
                CHECK(f.slope_xy * f.slope_xy <= f.slope_xx * f.slope_yy * (1 + 1e-9) + 1e-300);  // a covariance
                for (double azimuth : {0.0, 1.0, 2.5, -2.0}) {
                    const double s = f.sigma_s(azimuth);
                    CHECK(std::isfinite(s));
                    CHECK(s <= surface.sigma_s(azimuth) * (1 + 1e-9) + 1e-300);  // never more than the whole surface's
                }
            }
    }
}

TEST_CASE("the resolved visibility stays in 0 to 1 and is Phi of the height to the power Lambda")
{
    for (double height : {-1.0, -0.01, 0.0, 0.004, 1.0})
        for (double sigma_r : {0.0, 1e-12, 1e-6, 0.008, 10.0}) {
            double previous = 1;
            for (double lambda : {0.0, 1e-12, 1.0, 1e6, 1e12, 1e100, kInf}) {
                CAPTURE(height);
                CAPTURE(sigma_r);
                CAPTURE(lambda);
                const double v = resolved_visibility(height, sigma_r, lambda);
                REQUIRE(std::isfinite(v));
                CHECK(v >= 0);
                CHECK(v <= 1);
                CHECK(v <= previous);  // more shadowing as Lambda grows
                previous = v;
                if (lambda == 0 || sigma_r == 0) CHECK(v == 1);
                // Phi(h / sigma_r)^Lambda from erfc, where it neither under- nor overflows.
                const double phi = 0.5 * std::erfc(-height / (sigma_r * std::sqrt(2.0)));
                if (sigma_r > 0 && std::isfinite(lambda) && phi > 0 && std::pow(phi, lambda) > 1e-300)
                    CHECK(v == doctest::Approx(std::pow(phi, lambda)).epsilon(1e-9));
            }
        }
}

TEST_CASE("the height-filtered albedo of every representation stays finite and in range on all sweeps")
{
    const ColorLayer heights = microsurface_test_layer(4, 8, 0.05);
    const ColorRange range = color_range(heights.map);
    auto table = HeightMomentTable::create();
    REQUIRE(table);
    const std::vector<double> thetas = sweep_thetas();
    AlbedoCounts counts;
    std::size_t evaluated = 0;
    for (HeightRepresentation representation : {HeightRepresentation::Naive, HeightRepresentation::PaperFit,
                                                HeightRepresentation::ExactMoments, HeightRepresentation::Exact})
        for (double sigma_h : kSigmaH)
            for (double sigma_s : kSigmaS)
                for (const Resolved& r : kResolved)
                    for (double theta_o : thetas)
                        for (double theta_i : thetas) {
                            const HeightDirections d{theta_o, 0.4, theta_i, -2.2};
                            const double mean_height = r.mean_height;
                            const HeightAlbedo a = height_filtered_albedo(
                                heights, hand_footprint(mean_height, sigma_h, sigma_s, r.sigma_h, r.sigma_s), d,
                                representation, *table, counts);
                            ++evaluated;
                            const bool finite = is_finite(a.albedo) && std::isfinite(a.mean) &&
                                                std::isfinite(a.sigma) && std::isfinite(a.visibility) &&
                                                std::isfinite(a.resolved_visibility) && !std::isnan(a.lambda_sum);
                            const double v = a.visibility * a.resolved_visibility;
                            const bool in_range = a.visibility >= 0 && a.visibility <= 1 &&
                                                  a.resolved_visibility >= 0 && a.resolved_visibility <= 1 &&
                                                  a.sigma >= 0 && a.sigma <= sigma_h * (1 + 1e-9) &&
                                                  a.lambda_sum >= 0 && within_scaled_range(a.albedo, range, v, 1e-6);
                            // Lambda is finite while both directions are above the surface.
                            const bool lambda_ok = !(theta_o < kPi / 2 && theta_i < kPi / 2) ||
                                                   std::isfinite(a.lambda_sum);
                            if (!(finite && in_range && lambda_ok)) {
                                CAPTURE(static_cast<int>(representation));
                                CAPTURE(sigma_h);
                                CAPTURE(sigma_s);
                                CAPTURE(mean_height);
                                CAPTURE(theta_o);
                                CAPTURE(theta_i);
                                CAPTURE(a.albedo.r);
                                CAPTURE(a.albedo.g);
                                CAPTURE(a.albedo.b);
                                CAPTURE(a.mean);
                                CAPTURE(a.sigma);
                                CAPTURE(a.lambda_sum);
                                CAPTURE(a.visibility);
                                CAPTURE(a.resolved_visibility);
                                CHECK(finite);
                                CHECK(in_range);
                                CHECK(lambda_ok);
                            }
                        }
    CHECK(evaluated == 4 * kSigmaH.size() * kSigmaS.size() * std::size(kResolved) * thetas.size() * thetas.size());
    // Naive takes no masking: V = 1 and the resolved mean's colour.
    const HeightAlbedo naive = height_filtered_albedo(heights, hand_footprint(0.021, 0.008, 0.35),
                                                      {kPi / 2, 0, kPi / 2, 0}, HeightRepresentation::Naive, *table,
                                                      counts);
    CHECK(naive.visibility == 1);
    CHECK(naive.albedo.r == doctest::Approx(reference_map_color(heights.map, 0.021).r).epsilon(1e-12));
}

TEST_CASE("correlated masking and shadowing stays finite and in range, and meets eq. 13 where it should")
{
    const double inf = std::numeric_limits<double>::infinity();
    const double lambdas[] = {0.0, 1e-12, 0.3, 2.0, 1e6, 1e300, inf};
    const double azimuths[] = {0.0, 0.5, 1.5707963267948966, 3.141592653589793, -2.0, 7.0, 1e9};
    for (double lo : lambdas)
        for (double li : lambdas)
            for (double phi : azimuths) {
                CAPTURE(lo);
                CAPTURE(li);
                CAPTURE(phi);
                const double v = mean_visibility(lo, li, phi, MaskingShadowing::DirectionCorrelated);
                CHECK(std::isfinite(v));
                CHECK(v >= 0);
                CHECK(v <= 1);
                const double L = lambda_sum(lo, li, phi, MaskingShadowing::DirectionCorrelated);
                CHECK_FALSE(std::isnan(L));
                // Never more than the independent sum, never less than the larger Lambda.
                CHECK(L <= lo + li);
                CHECK(L >= std::max(lo, li));
                CHECK(mean_visibility(lo, li, phi, MaskingShadowing::Uncorrelated) == mean_visibility(lo, li));
            }
    // The light from the viewer's side (phi = 0) at the same angle: all seen is lit.
    CHECK(mean_visibility(0.7, 0.7, 0.0, MaskingShadowing::DirectionCorrelated) == 1.0);
    CHECK(mean_visibility(inf, inf, 0.0, MaskingShadowing::DirectionCorrelated) == 1.0);
    // lambda(pi) = 4.41 pi / (4.41 pi + 1), by hand.
    const double c = 4.41 * 3.141592653589793 / (4.41 * 3.141592653589793 + 1);
    CHECK(lambda_sum(0.5, 0.25, 3.141592653589793, MaskingShadowing::DirectionCorrelated) ==
          doctest::Approx(0.5 + c * 0.25).epsilon(1e-12));
}
