// SPDX-License-Identifier: Apache-2.0
// Conventions for cmfilter:* metadata on OpenImageIO specs: floating-point
// parameters are stored as double attributes and read back as doubles
// (float attributes, as older files or other tools write them, widened).
#pragma once

#include <OpenImageIO/imageio.h>

#include <cmath>

namespace cmfilter {

inline void set_double_attribute(OIIO::ImageSpec& spec, const char* name, double value)
{
    spec.attribute(name, OIIO::TypeDesc::DOUBLE, &value);
}

// NaN when the attribute is missing.
inline double double_attribute(const OIIO::ImageSpec& spec, const char* name)
{
    const OIIO::ParamValue* p = spec.find_attribute(name);
    if (!p) return std::nan("");
    return p->type() == OIIO::TypeDesc::DOUBLE ? p->get<double>() : static_cast<double>(p->get_float());
}

}  // namespace cmfilter
