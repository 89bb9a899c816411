// SPDX-License-Identifier: Apache-2.0
// How a microsurface material's colour layers combine (Heitz et al. 2013,
// sec. 6): a weighted sum k0 C0 + k1 C_h + k2 C_s, or the product
// C0 C_h C_s, of the layers present (microsurface_albedo.h filters either).
#pragma once

namespace cmfilter {

enum class CombineMode { Sum, Product };

struct ColorCombination {
    CombineMode mode = CombineMode::Sum;
    double base = 1, height = 1, slope = 1;  // k0, k1, k2 (Sum)
};

}  // namespace cmfilter
