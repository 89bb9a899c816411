// SPDX-License-Identifier: Apache-2.0
// How a method was chosen for a colour-difference tolerance
// (ops/method_choice.h): what `apply --tolerance` records in its image and
// `bake-moments --tolerance` in its pyramid, as cmfilter:* metadata
// (docs/moments-format.md):
//   cmfilter:method            the method chosen (naive, gaussian, mixture, exact)
//   cmfilter:method_tolerance  the tolerance, mean CIEDE2000 at every LOD measured
//   cmfilter:method_error      the worst mean CIEDE2000 the method reached there
//   cmfilter:method_lods       the LODs measured ("1, 2, 3")
//   cmfilter:method_table      the colour table measured against (relative to the file)
#pragma once

#include <OpenImageIO/imageio.h>

#include <optional>
#include <string>

namespace cmfilter {

struct MethodToleranceRecord {
    std::string method;
    double tolerance = 0;
    double error = 0;
    std::string lods;
    std::string table;
};

// `table` as it should be recorded (already relative to the file written).
void set_method_tolerance_metadata(OIIO::ImageSpec& spec, const MethodToleranceRecord& record);

// None when the file records no tolerance choice (cmfilter:method_tolerance
// missing).
std::optional<MethodToleranceRecord> get_method_tolerance_metadata(const OIIO::ImageSpec& spec);

}  // namespace cmfilter
