// SPDX-License-Identifier: Apache-2.0
// The exact mean and central standard deviation of the height filtering
// distribution D_h (eqs. 15-16; height_filtering.h) tabulated over the
// Lambda sum L = Lambda_o + Lambda_i, for the renderer's `gaussian-exact`
// representation: a Gaussian with D_h's own moments in place of the paper's
// fit (eqs. 17-18). Nodes are uniform in s = ln(1 + L) over [0, ln(1 +
// max_lambda_sum)] (L beyond it reads the last node), in units of sigma_h
// (the moments scale with it), looked up linearly in s: within 1e-4 of the
// exact moments (relative; absolute near L = 0, where the mean is 0) with
// the default 512 nodes up to L = 1e6 (unit test: 2.6e-5 at worst).
#pragma once

#include "cmfilter/util/error.h"
#include "cmfilter/microsurface/height_filtering.h"

#include <vector>

namespace cmfilter {

struct HeightMomentTableOptions {
    int nodes = 512;              // >= 2
    double max_lambda_sum = 1e6;  // > 0, finite
};

class HeightMomentTable {
public:
    // BadInput naming the option for fewer than 2 nodes or a max_lambda_sum
    // that is not finite and positive.
    static Expected<HeightMomentTable> create(const HeightMomentTableOptions& options = {});

    // The moments for a Lambda sum (NaN and negative read as 0) and sigma_h.
    HeightMoments lookup(double lambda_sum, double sigma_h) const;

    // The nodes (sigma_h = 1) and the end of the s axis, ln(1 + max_lambda_sum):
    // what a renderer uploads to look it up (shaders/cmfilter_height.glsl).
    const std::vector<double>& node_means() const { return mean_; }
    const std::vector<double>& node_sigmas() const { return sigma_; }
    double s_max() const { return s_max_; }

private:
    HeightMomentTable() = default;
    std::vector<double> mean_, sigma_;  // per node, sigma_h = 1
    double s_max_ = 0;
};

}  // namespace cmfilter
