// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthetic/specular_lobe.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;

Error bad_lobe(const std::string& text, const std::string& why)
{
    return bad_input("specular lobe '" + text + "' " + why +
                         " (expected none, blinn-phong:ks=K,n=N or ggx:ks=K,alpha=A)",
                     "MakeStackOptions::specular");
}

std::string number_text(double v)
{
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

// Smith's G1 for GGX (Walter et al. 2007, eq. 34), c = <m, w> > 0.
double ggx_g1(double c, double alpha2) { return 2 * c / (c + std::sqrt(alpha2 + (1 - alpha2) * c * c)); }

}  // namespace

Expected<SpecularLobe> parse_specular_lobe(const std::string& text)
{
    SpecularLobe lobe;
    if (text == "none") return lobe;
    const std::size_t colon = text.find(':');
    const std::string kind = text.substr(0, colon);
    if (kind == "blinn-phong") lobe.kind = SpecularKind::BlinnPhong;
    else if (kind == "ggx") lobe.kind = SpecularKind::Ggx;
    else return bad_lobe(text, "is of an unknown kind '" + kind + "'");
    if (colon == std::string::npos) return bad_lobe(text, "has no parameters");
    const std::string second = lobe.kind == SpecularKind::BlinnPhong ? "n" : "alpha";
    bool seen_ks = false, seen_second = false;
    std::stringstream rest(text.substr(colon + 1));
    std::string item;
    while (std::getline(rest, item, ',')) {
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos) return bad_lobe(text, "has a parameter '" + item + "' without '='");
        const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
        char* end = nullptr;
        errno = 0;
        const double v = std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0' || errno != 0 || !std::isfinite(v))
            return bad_lobe(text, "has " + key + " '" + value + "', not a number");
        bool& seen = key == "ks" ? seen_ks : seen_second;
        if (key != "ks" && key != second) return bad_lobe(text, "has an unknown parameter '" + key + "'");
        if (seen) return bad_lobe(text, "gives " + key + " twice");
        seen = true;
        (key == "ks" ? lobe.ks : (lobe.kind == SpecularKind::BlinnPhong ? lobe.exponent : lobe.alpha)) = v;
    }
    if (!seen_ks || !seen_second) return bad_lobe(text, "lacks " + std::string(!seen_ks ? "ks" : second));
    if (auto st = check_specular_lobe(lobe); !st) return bad_lobe(text, "is out of range: " + st.error().message);
    return lobe;
}

std::string specular_text(const SpecularLobe& lobe)
{
    switch (lobe.kind) {
    case SpecularKind::None: return "none";
    case SpecularKind::BlinnPhong: return "blinn-phong:ks=" + number_text(lobe.ks) + ",n=" + number_text(lobe.exponent);
    case SpecularKind::Ggx: return "ggx:ks=" + number_text(lobe.ks) + ",alpha=" + number_text(lobe.alpha);
    }
    return "?";
}

Status check_specular_lobe(const SpecularLobe& lobe)
{
    if (lobe.kind == SpecularKind::None) return ok();
    if (!(lobe.ks >= 0 && lobe.ks <= 1))
        return bad_input("SpecularLobe::ks " + number_text(lobe.ks) + " is invalid: expected 0 to 1",
                         "SpecularLobe::ks");
    if (lobe.kind == SpecularKind::BlinnPhong && !(lobe.exponent >= 0 && lobe.exponent <= 100000))
        return bad_input("SpecularLobe::exponent " + number_text(lobe.exponent) + " is invalid: expected 0 to 100000",
                         "SpecularLobe::exponent");
    if (lobe.kind == SpecularKind::Ggx && !(lobe.alpha >= 0.001 && lobe.alpha <= 1))
        return bad_input("SpecularLobe::alpha " + number_text(lobe.alpha) + " is invalid: expected 0.001 to 1",
                         "SpecularLobe::alpha");
    return ok();
}

double blinn_phong_normalisation(double n)
{
    return 8 * kPi *
           (n / ((n + 2) * (n + 4)) - std::pow(2.0, -(n + 4) / 2) * 2 / (n + 4) +
            std::pow(2.0, -(n + 2) / 2) / (n + 2));
}

double specular_factor(const SpecularLobe& lobe, const Vec3& m, const Vec3& l, const Vec3& v)
{
    if (lobe.kind == SpecularKind::None || lobe.ks == 0) return 0;
    const double ml = dot(m, l), mv = dot(m, v);
    if (!(ml > 0 && mv > 0)) return 0;
    const Vec3 sum = l + v;
    const double sum_length = length(sum);
    if (!(sum_length > 0)) return 0;
    const Vec3 h = sum / sum_length;
    const double mh = std::max(0.0, dot(m, h));
    if (lobe.kind == SpecularKind::BlinnPhong)
        return lobe.ks * std::pow(mh, lobe.exponent) * kPi / blinn_phong_normalisation(lobe.exponent);
    const double a2 = lobe.alpha * lobe.alpha;
    const double q = mh * mh * (a2 - 1) + 1;
    const double d = a2 / (kPi * q * q);
    const double g = ggx_g1(ml, a2) * ggx_g1(mv, a2);
    const double f = lobe.ks + (1 - lobe.ks) * std::pow(1 - std::max(0.0, dot(h, l)), 5);
    return kPi * d * g * f / (4 * ml * mv);
}

}  // namespace cmfilter
