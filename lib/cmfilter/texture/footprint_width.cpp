// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/footprint_width.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

const char* to_string(FootprintWidth width)
{
    switch (width) {
    case FootprintWidth::Rms: return "rms";
    case FootprintWidth::Area: return "area";
    case FootprintWidth::Major: return "major";
    case FootprintWidth::Minor: return "minor";
    }
    return "rms";
}

Expected<FootprintWidth> parse_footprint_width(const std::string& text)
{
    for (FootprintWidth w : {FootprintWidth::Rms, FootprintWidth::Area, FootprintWidth::Major, FootprintWidth::Minor})
        if (text == to_string(w)) return w;
    return bad_input("footprint width '" + text + "' is unknown (expected rms, area, major or minor)");
}

double footprint_width(FootprintWidth choice, double e1u, double e1v, double e2u, double e2v)
{
    const double l1 = e1u * e1u + e1v * e1v, l2 = e2u * e2u + e2v * e2v;
    switch (choice) {
    case FootprintWidth::Rms: return std::sqrt(0.5 * (l1 + l2));
    case FootprintWidth::Area: return std::sqrt(std::fabs(e1u * e2v - e1v * e2u));
    case FootprintWidth::Major: return std::sqrt(std::max(l1, l2));
    case FootprintWidth::Minor: return std::sqrt(std::min(l1, l2));
    }
    return 0;
}

}  // namespace cmfilter
