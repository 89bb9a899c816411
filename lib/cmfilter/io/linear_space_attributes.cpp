// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/linear_space_attributes.h"

#include "cmfilter/color/interop_chromaticities.h"

namespace cmfilter {

void set_linear_space_attributes(OIIO::ImageSpec& spec, const std::string& linear_space, const std::string& interop_id)
{
    if (linear_space.empty()) return;
    spec.attribute("oiio:ColorSpace", linear_space);
    spec.attribute("cmfilter:linear_space", linear_space);
    const std::string& id = interop_id;
    if (id.empty()) return;
    spec.attribute("colorInteropID", id);
    if (auto xy = interop_chromaticities(id))
        spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), xy->data());
}

}  // namespace cmfilter
