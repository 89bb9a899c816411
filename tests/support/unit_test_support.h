// Helpers shared by the unit tests: a library colour map paired with its
// independent test-side twin, and the built-in colour config.
#pragma once

#include "cmfilter/color_config.h"
#include "cmfilter/color_map.h"

#include "reference_convolution.h"

#include <doctest/doctest.h>

namespace cmfilter_test {

// The same texels as a libcmfilter ColorMap and as a ReferenceMap.
struct MapPair {
    cmfilter::ColorMap map;
    ReferenceMap ref;
};

inline cmfilter::ColorConfig builtin_color_config()
{
    auto config = cmfilter::ColorConfig::load("");
    REQUIRE(config);
    return *config;
}

}  // namespace cmfilter_test
