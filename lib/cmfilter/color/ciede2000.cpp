// SPDX-License-Identifier: Apache-2.0
// CIEDE2000 colour difference: scene-linear Rec.709 -> XYZ -> CIE L*a*b*, then
// the CIEDE2000 formula. Each step cites its equation in Sharma, Wu & Dalal
// (2005), "The CIEDE2000 color-difference formula: implementation notes,
// supplementary test data, and mathematical observations", section 2, whose
// numbering (eqs. 2-22) is used below; hue angles are in degrees throughout.
#include "cmfilter/color/ciede2000.h"

#include <cmath>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

struct Xyz {
    double x, y, z;
};

// Clip to [0, 1]; NaN (which fails every comparison) becomes 0.
double clip01(double v)
{
    if (!(v > 0.0)) return 0.0;
    return v > 1.0 ? 1.0 : v;
}

// Linear Rec.709/sRGB (D65) to CIE XYZ: the matrix of IEC 61966-2-1:1999
// (sRGB), built from the ITU-R BT.709 primaries and the D65 white point.
Xyz rec709_to_xyz(double r, double g, double b)
{
    return {0.4124 * r + 0.3576 * g + 0.1805 * b, 0.2126 * r + 0.7152 * g + 0.0722 * b,
            0.0193 * r + 0.1192 * g + 0.9505 * b};
}

// The reference white: XYZ of RGB (1,1,1) through the same matrix (the row
// sums), computed by the same code so that white gives exactly X/Xn = Y/Yn =
// Z/Zn = 1 and hence a* = b* = 0.
const Xyz& reference_white()
{
    static const Xyz white = rec709_to_xyz(1.0, 1.0, 1.0);
    return white;
}

// CIE 15:2004, section 8.2.1: f(t) = t^(1/3) for t > (24/116)^3, else
// (841/108) t + 16/116 (the linear segment near black).
double lab_f(double t)
{
    constexpr double delta = 6.0 / 29.0;  // 24/116
    if (t > delta * delta * delta) return std::cbrt(t);
    return t / (3.0 * delta * delta) + 4.0 / 29.0;
}

// Hue angle in [0, 360) degrees; 0 where a = b = 0 (Sharma et al. 2005, eq. 7).
double hue_degrees(double b, double a)
{
    if (a == 0.0 && b == 0.0) return 0.0;
    double h = std::atan2(b, a) / kDeg;
    if (h < 0.0) h += 360.0;
    return h;
}

double pow7(double v)
{
    const double v2 = v * v;
    return v2 * v2 * v2 * v;
}

}  // namespace

Lab linear_rec709_to_lab(const Rgb& c)
{
    const Xyz xyz = rec709_to_xyz(clip01(c.r), clip01(c.g), clip01(c.b));
    const Xyz& n = reference_white();
    // CIE 15:2004, section 8.2.1: L* = 116 f(Y/Yn) - 16,
    // a* = 500 (f(X/Xn) - f(Y/Yn)), b* = 200 (f(Y/Yn) - f(Z/Zn)).
    const double fx = lab_f(xyz.x / n.x);
    const double fy = lab_f(xyz.y / n.y);
    const double fz = lab_f(xyz.z / n.z);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double ciede2000(const Lab& x, const Lab& y)
{
    constexpr double k25_7 = 6103515625.0;  // 25^7

    // Step 1: C'_i and h'_i.
    const double c1 = std::hypot(x.a, x.b);  // eq. 2
    const double c2 = std::hypot(y.a, y.b);  // eq. 2
    const double c_mean = 0.5 * (c1 + c2);   // eq. 3
    const double c_mean7 = pow7(c_mean);
    const double g = 0.5 * (1.0 - std::sqrt(c_mean7 / (c_mean7 + k25_7)));  // eq. 4
    const double a1p = (1.0 + g) * x.a;                                     // eq. 5
    const double a2p = (1.0 + g) * y.a;                                     // eq. 5
    const double c1p = std::hypot(a1p, x.b);                                // eq. 6
    const double c2p = std::hypot(a2p, y.b);                                // eq. 6
    const double h1p = hue_degrees(x.b, a1p);                               // eq. 7
    const double h2p = hue_degrees(y.b, a2p);                               // eq. 7

    // Step 2: Delta L', Delta C', Delta H'.
    const double dLp = y.L - x.L;  // eq. 8
    const double dCp = c2p - c1p;  // eq. 9
    const double c_product = c1p * c2p;
    double dhp = 0.0;  // eq. 10: 0 when a chroma is 0
    if (c_product != 0.0) {
        dhp = h2p - h1p;
        if (dhp > 180.0) dhp -= 360.0;
        else if (dhp < -180.0) dhp += 360.0;
    }
    const double dHp = 2.0 * std::sqrt(c_product) * std::sin(0.5 * dhp * kDeg);  // eq. 11

    // Step 3: the weighting functions and Delta E00.
    const double Lp_mean = 0.5 * (x.L + y.L);  // eq. 12
    const double Cp_mean = 0.5 * (c1p + c2p);  // eq. 13
    double hp_mean = h1p + h2p;                // eq. 14: the sum when a chroma is 0
    if (c_product != 0.0) {
        if (std::fabs(h1p - h2p) <= 180.0) hp_mean = 0.5 * (h1p + h2p);
        else if (h1p + h2p < 360.0) hp_mean = 0.5 * (h1p + h2p + 360.0);
        else hp_mean = 0.5 * (h1p + h2p - 360.0);
    }
    const double t = 1.0 - 0.17 * std::cos((hp_mean - 30.0) * kDeg)  // eq. 15
                     + 0.24 * std::cos(2.0 * hp_mean * kDeg) + 0.32 * std::cos((3.0 * hp_mean + 6.0) * kDeg) -
                     0.20 * std::cos((4.0 * hp_mean - 63.0) * kDeg);
    const double hue_offset = (hp_mean - 275.0) / 25.0;
    const double d_theta = 30.0 * std::exp(-hue_offset * hue_offset);  // eq. 16
    const double Cp_mean7 = pow7(Cp_mean);
    const double r_c = 2.0 * std::sqrt(Cp_mean7 / (Cp_mean7 + k25_7));  // eq. 17
    const double l50 = (Lp_mean - 50.0) * (Lp_mean - 50.0);
    const double s_l = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50);  // eq. 18
    const double s_c = 1.0 + 0.045 * Cp_mean;                      // eq. 19
    const double s_h = 1.0 + 0.015 * Cp_mean * t;                  // eq. 20
    const double r_t = -std::sin(2.0 * d_theta * kDeg) * r_c;      // eq. 21

    const double tl = dLp / s_l;                                    // kL = 1
    const double tc = dCp / s_c;                                    // kC = 1
    const double th = dHp / s_h;                                    // kH = 1
    return std::sqrt(tl * tl + tc * tc + th * th + r_t * tc * th);  // eq. 22
}

double ciede2000_linear_rgb(const Rgb& x, const Rgb& y)
{
    return ciede2000(linear_rec709_to_lab(x), linear_rec709_to_lab(y));
}

}  // namespace cmfilter
