// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/method_tolerance_record.h"

#include "cmfilter/io/metadata.h"

#include <cmath>

namespace cmfilter {

void set_method_tolerance_metadata(OIIO::ImageSpec& spec, const MethodToleranceRecord& record)
{
    spec.attribute("cmfilter:method", record.method);
    set_double_attribute(spec, "cmfilter:method_tolerance", record.tolerance);
    set_double_attribute(spec, "cmfilter:method_error", record.error);
    spec.attribute("cmfilter:method_lods", record.lods);
    spec.attribute("cmfilter:method_table", record.table);
}

std::optional<MethodToleranceRecord> get_method_tolerance_metadata(const OIIO::ImageSpec& spec)
{
    const double tolerance = double_attribute(spec, "cmfilter:method_tolerance");
    if (!std::isfinite(tolerance)) return std::nullopt;
    MethodToleranceRecord r;
    r.method = spec.get_string_attribute("cmfilter:method");
    r.tolerance = tolerance;
    r.error = double_attribute(spec, "cmfilter:method_error");
    r.lods = spec.get_string_attribute("cmfilter:method_lods");
    r.table = spec.get_string_attribute("cmfilter:method_table");
    return r;
}

}  // namespace cmfilter
