// SPDX-License-Identifier: Apache-2.0
// A Gaussian microsurface for height-correlated colour filtering (Heitz et
// al. 2013, sec. 5.1): heights h(x, y) = sum_k a_k cos(2 pi <f_k, (x, y)> +
// phi_k), a sum of many random-phase cosines, Gaussian by the central limit
// theorem, whose statistics are known exactly from its spectrum:
//   sigma_h^2          = sum_k a_k^2 / 2,
//   sigma_s(d)^2       = sum_k a_k^2 (2 pi <f_k, d>)^2 / 2,
// the standard deviation of the slope dh/dd along a unit direction d (Smith's
// Lambda, eq. 3, takes it along the view's or the light's azimuth). The
// frequencies' directions are uniform, their lengths log-uniform between
// 1 / max_wavelength and 1 / min_wavelength, and the amplitudes equal,
// scaled so that sigma_h is exactly the one asked for; everything is drawn
// from `seed` (SplitMix64). With a `tile` > 0 the surface repeats with that
// period along x and y: each frequency is snapped to the nearest nonzero
// multiple of 1 / tile in each coordinate (the statistics above stay exact
// for the snapped frequencies), so a heightfield tabulated over one tile
// (heightfield_tracer.h) is the same surface everywhere. Immutable;
// thread-safe.
#pragma once

#include "cmfilter/util/error.h"

#include <cstdint>
#include <vector>

namespace cmfilter {

struct GaussianMicrosurfaceOptions {
    int cosines = 256;             // >= 1 (Gaussian heights need dozens)
    double sigma_h = 0.05;         // height standard deviation, >= 0
    double min_wavelength = 0.01;  // > 0
    double max_wavelength = 0.1;   // >= min_wavelength
    std::uint64_t seed = 1;
    // > 0: the period along x and y, >= max_wavelength; 0: not periodic.
    double tile = 0;
};

class GaussianMicrosurface {
public:
    // One term a cos(2 pi (fx x + fy y) + phase), fx and fy in cycles per
    // unit length.
    struct Cosine {
        double amplitude, fx, fy, phase;
    };

    // BadInput naming the option for a count < 1, a negative or non-finite
    // sigma_h, or wavelengths out of order or not finite and positive.
    static Expected<GaussianMicrosurface> create(const GaussianMicrosurfaceOptions& options);

    double height(double x, double y) const;
    // (dh/dx, dh/dy).
    void gradient(double x, double y, double& dx, double& dy) const;

    double sigma_h() const { return sigma_h_; }
    // The slope standard deviation along the unit direction (cos a, sin a).
    double sigma_s(double azimuth) const;
    const std::vector<Cosine>& cosines() const { return cosines_; }
    double tile() const { return tile_; }  // 0: not periodic

private:
    GaussianMicrosurface() = default;
    std::vector<Cosine> cosines_;
    double sigma_h_ = 0, tile_ = 0;
};

}  // namespace cmfilter
