// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/linear_model.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

const char* to_string(LinearModel model)
{
    switch (model) {
    case LinearModel::PtmRgb: return "ptm-rgb";
    case LinearModel::PtmLrgb: return "ptm-lrgb";
    case LinearModel::Hsh2: return "hsh2";
    case LinearModel::Hsh3: return "hsh3";
    }
    return "?";
}

std::optional<LinearModel> parse_linear_model(const std::string& name)
{
    for (LinearModel m : {LinearModel::PtmRgb, LinearModel::PtmLrgb, LinearModel::Hsh2, LinearModel::Hsh3})
        if (name == to_string(m)) return m;
    return std::nullopt;
}

int basis_terms(LinearModel model)
{
    switch (model) {
    case LinearModel::PtmRgb:
    case LinearModel::PtmLrgb: return 6;
    case LinearModel::Hsh2: return 4;
    case LinearModel::Hsh3: return 9;
    }
    return 0;
}

std::array<double, kMaxLinearTerms> evaluate_basis(LinearModel model, const Vec3& l)
{
    std::array<double, kMaxLinearTerms> b{};
    if (model == LinearModel::PtmRgb || model == LinearModel::PtmLrgb) {
        // Malzbender et al. 2001, eq. 2: a0 lu^2 + a1 lv^2 + a2 lu lv + a3 lu + a4 lv + a5.
        b[0] = l.x * l.x;
        b[1] = l.y * l.y;
        b[2] = l.x * l.y;
        b[3] = l.x;
        b[4] = l.y;
        b[5] = 1;
        return b;
    }
    // Hemispherical harmonics (Gautron et al. 2004) in the closed form and
    // order RTIViewer evaluates them: theta the light's angle from the
    // normal, phi its azimuth from +x towards +y, c = cos(theta),
    // s = sqrt(c - c^2). Viewers clamp theta a little below 90 degrees at
    // render time; the basis here is unclamped.
    const double pi = 3.14159265358979323846;
    const double c = std::clamp(l.z, 0.0, 1.0);
    const double phi = std::atan2(l.y, l.x);
    const double s = std::sqrt(std::max(0.0, c - c * c));
    b[0] = 1 / std::sqrt(2 * pi);
    b[1] = std::sqrt(6 / pi) * std::cos(phi) * s;
    b[2] = std::sqrt(3 / (2 * pi)) * (-1 + 2 * c);
    b[3] = std::sqrt(6 / pi) * s * std::sin(phi);
    if (model == LinearModel::Hsh2) return b;
    b[4] = std::sqrt(30 / pi) * std::cos(2 * phi) * (-c + c * c);
    b[5] = std::sqrt(30 / pi) * std::cos(phi) * (-1 + 2 * c) * s;
    b[6] = std::sqrt(5 / (2 * pi)) * (1 - 6 * c + 6 * c * c);
    b[7] = std::sqrt(30 / pi) * (-1 + 2 * c) * s * std::sin(phi);
    b[8] = std::sqrt(30 / pi) * (-c + c * c) * std::sin(2 * phi);
    return b;
}

}  // namespace cmfilter
