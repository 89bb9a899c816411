// SPDX-License-Identifier: Apache-2.0
// What the .ptm and .rti interchange tests share: a blank display-encoded
// fit, a fit's relit value computed here from the basis, random light
// directions, the bound a per-term coefficient error sets on relit values,
// fits altered to be unwritable, and the checks that a writer refuses fits
// and a reader refuses files with the messages expected.
#pragma once

#include "cmfilter/math/vec3.h"
#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/stack/linear_model.h"
#include "cmfilter/util/error.h"

#include "ptm_test_files.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace cmfilter_test {

// A 3-channel DisplayEncoded fit of `model`, width x height, its
// coefficients all 0.
inline cmfilter::LinearFit display_encoded_fit(cmfilter::LinearModel model, int width, int height)
{
    cmfilter::LinearFit fit;
    fit.model = model;
    fit.width = width;
    fit.height = height;
    fit.channels = 3;
    fit.encoding = cmfilter::StackEncoding::DisplayEncoded;
    fit.coefficients.resize(fit.texels() * fit.stride());
    return fit;
}

// Texel t's channel c relit from direction l, computed here from the basis:
// sum_k a_ck B_k(l); PtmLrgb the luminance polynomial times the base colour.
inline double relit_value(const cmfilter::LinearFit& fit, std::size_t t, int c, const cmfilter::Vec3& l)
{
    const auto b = cmfilter::evaluate_basis(fit.model, l);
    const float* v = fit.coefficients.data() + t * fit.stride();
    double s = 0;
    if (fit.model == cmfilter::LinearModel::PtmLrgb) {
        for (int k = 0; k < 6; ++k) s += v[k] * b[k];
        return s * v[6 + c];
    }
    for (int k = 0; k < fit.terms(); ++k) s += v[c * fit.terms() + k] * b[k];
    return s;
}

// n directions uniform on the upper unit hemisphere.
inline std::vector<cmfilter::Vec3> random_hemisphere_directions(std::mt19937_64& rng, int n)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<cmfilter::Vec3> d;
    for (int i = 0; i < n; ++i) {
        const double z = u(rng), phi = 2 * 3.14159265358979323846 * u(rng), r = std::sqrt(1 - z * z);
        d.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    return d;
}

// Two fits of one model and size whose coefficients of term k differ by at
// most term_error[k] relight, at each of `directions`, within
// sum_k term_error[k] |B_k(l)| of each other (every texel and channel).
inline void check_relit_within_term_errors(const cmfilter::LinearFit& a, const cmfilter::LinearFit& b,
                                           const std::vector<double>& term_error,
                                           const std::vector<cmfilter::Vec3>& directions)
{
    for (const cmfilter::Vec3& l : directions) {
        const auto basis = cmfilter::evaluate_basis(a.model, l);
        double bound = 0;
        for (int k = 0; k < a.terms(); ++k) bound += term_error[k] * std::abs(basis[k]);
        for (std::size_t t = 0; t < a.texels(); ++t)
            for (int c = 0; c < 3; ++c)
                CHECK(std::abs(relit_value(a, t, c, l) - relit_value(b, t, c, l)) <= bound + 1e-6);
    }
}

// The largest |difference| of two fits' relit values at the pole (0, 0, 1).
inline double max_relit_difference_at_pole(const cmfilter::LinearFit& a, const cmfilter::LinearFit& b)
{
    double d = 0;
    for (std::size_t t = 0; t < a.texels(); ++t)
        for (int c = 0; c < 3; ++c)
            d = std::max(d, std::abs(relit_value(a, t, c, {0, 0, 1}) - relit_value(b, t, c, {0, 0, 1})));
    return d;
}

// `fit` with `channels` channels (its coefficients resized to match).
inline cmfilter::LinearFit with_channels(cmfilter::LinearFit fit, int channels)
{
    fit.channels = channels;
    fit.coefficients.resize(fit.texels() * fit.stride());
    return fit;
}

// `fit` marked as fitted to scene-linear values.
inline cmfilter::LinearFit as_scene_linear(cmfilter::LinearFit fit)
{
    fit.encoding = cmfilter::StackEncoding::SceneLinear;
    return fit;
}

// `fit` with coefficient `index` (of all its coefficients) set to `value`.
inline cmfilter::LinearFit with_coefficient(cmfilter::LinearFit fit, std::size_t index, float value)
{
    fit.coefficients.at(index) = value;
    return fit;
}

// A fit a writer must refuse, and what its message must say after
// "cannot write '<path>' as <format>: ".
struct RefusedFit {
    cmfilter::LinearFit fit;
    std::string message;
};

// Each fit refused by `write` with BadInput and that message, leaving no
// file at `path`.
inline void
check_fits_refused(const std::function<cmfilter::Status(const std::string&, const cmfilter::LinearFit&)>& write,
                   const std::string& path, const std::string& format, const std::vector<RefusedFit>& cases)
{
    std::filesystem::remove(path);
    for (const RefusedFit& c : cases) {
        CAPTURE(c.message);
        auto written = write(path, c.fit);
        REQUIRE_FALSE(written);
        CHECK(written.error().kind == cmfilter::ErrorKind::BadInput);
        CHECK(written.error().message.find("cannot write '" + path + "' as " + format + ": " + c.message) !=
              std::string::npos);
        CHECK_FALSE(std::filesystem::exists(path));
    }
}

// A file's bytes a reader must refuse, and a part of its message.
struct RefusedFile {
    std::string bytes, message;
};

// Each file, written to `path`, refused by `read` with BadInput naming the
// file and saying the case's message; a file that does not exist
// (`missing`) refused with Io.
inline void check_files_refused(const std::function<cmfilter::Expected<cmfilter::LinearFit>(const std::string&)>& read,
                                const std::string& path, const std::vector<RefusedFile>& cases,
                                const std::string& missing)
{
    for (const RefusedFile& c : cases) {
        CAPTURE(c.message);
        write_bytes(path, c.bytes);
        auto fit = read(path);
        REQUIRE_FALSE(fit);
        CHECK(fit.error().kind == cmfilter::ErrorKind::BadInput);
        CHECK(fit.error().message.find("'" + path + "'") != std::string::npos);
        CHECK(fit.error().message.find(c.message) != std::string::npos);
    }
    auto absent = read(missing);
    REQUIRE_FALSE(absent);
    CHECK(absent.error().kind == cmfilter::ErrorKind::Io);
}

}  // namespace cmfilter_test
