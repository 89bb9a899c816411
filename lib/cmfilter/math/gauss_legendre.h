// SPDX-License-Identifier: Apache-2.0
// 8-point Gauss-Legendre quadrature: exact for polynomials of degree <= 15 on
// [a, b]; the library's building block for smooth and piecewise-polynomial
// integrals (split at the kinks before calling it).
#pragma once

namespace cmfilter {

// F returns a double or any value with +=, + and scaling by a double (Rgb).
template <typename F>
auto gauss_legendre_8(F&& f, double a, double b)
{
    static constexpr double node[4] = {0.18343464249564980, 0.52553240991632899, 0.79666647741362674,
                                       0.96028985649753623};
    static constexpr double weight[4] = {0.36268378337836198, 0.31370664587788729, 0.22238103445337447,
                                         0.10122853629037626};
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    decltype(f(a)) sum{};
    for (int i = 0; i < 4; ++i) sum += weight[i] * (f(mid - half * node[i]) + f(mid + half * node[i]));
    return half * sum;
}

// 2-point Gauss-Legendre: exact for cubics, for intervals much narrower than
// the scale on which the integrand bends (its error is (b - a)^5 f''''/4320).
template <typename F>
auto gauss_legendre_2(F&& f, double a, double b)
{
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b), node = 0.57735026918962576;
    return half * (f(mid - half * node) + f(mid + half * node));
}

// The same over n equal panels of [a, b].
template <typename F>
auto gauss_legendre_8(F&& f, double a, double b, int panels)
{
    decltype(f(a)) sum{};
    const double h = (b - a) / panels;
    for (int p = 0; p < panels; ++p) sum += gauss_legendre_8(f, a + p * h, a + (p + 1) * h);
    return sum;
}

}  // namespace cmfilter
