// SPDX-License-Identifier: Apache-2.0
// The optional specular lobe of a synthetic stack's facets (make_stack.h):
// each visible, lit facet of micro-normal m adds V <m, l> pi f(m, l, v) to
// its Lambertian colour, in the same units (pi times radiance under unit
// irradiance: a white Lambertian facet facing the light gives 1). The lobe
// is white. Written on the command line as (parse_specular_lobe):
//   none
//   blinn-phong:ks=K,n=N   f = ks (m.h)^n / I_n, h the half vector of l and
//                          v, I_n = integral over the hemisphere of (m.h)^n
//                          <m, l> dl for v = m, in closed form
//                          (blinn_phong_normalisation): the lobe's albedo
//                          at normal incidence is ks exactly (n = 0: a
//                          Lambertian lobe of albedo ks).
//   ggx:ks=K,alpha=A       Walter et al. 2007: f = D(h) G F / (4 <m, l> <m,
//                          v>), D the GGX (Trowbridge-Reitz) distribution of
//                          roughness alpha about m, G = G1(l) G1(v) Smith's
//                          separable masking-shadowing, F Schlick's Fresnel
//                          with F0 = ks, F = ks + (1 - ks) (1 - <h, l>)^5:
//                          a dielectric coat of normal reflectance ks (0.04
//                          for glass or plastic); its albedo at normal
//                          incidence is about ks for small alpha, less for
//                          rough lobes (G).
#pragma once

#include "cmfilter/math/vec3.h"
#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

enum class SpecularKind { None, BlinnPhong, Ggx };

struct SpecularLobe {
    SpecularKind kind = SpecularKind::None;
    double ks = 0;         // blinn-phong: the albedo at normal incidence; ggx: F0; 0 .. 1
    double exponent = 32;  // blinn-phong: n, 0 .. 100000
    double alpha = 0.2;    // ggx: roughness, 0.001 .. 1
};

// BadInput naming the text and what was expected (field
// MakeStackOptions::specular): an unknown kind, a missing, unknown or
// repeated parameter, a number that does not parse, a value out of range.
Expected<SpecularLobe> parse_specular_lobe(const std::string& text);
// The text parse_specular_lobe reads back.
std::string specular_text(const SpecularLobe& lobe);
// BadInput naming the field (SpecularLobe::ks, ::exponent, ::alpha) out of range.
Status check_specular_lobe(const SpecularLobe& lobe);

// I_n = integral of (m.h)^n <m, l> over the hemisphere of l about m, for
// the view along m: 8 pi [n / ((n + 2)(n + 4)) - 2^(-(n+4)/2) 2 / (n + 4) +
// 2^(-(n+2)/2) / (n + 2)] (substituting c = <m, h> = cos(theta / 2)).
double blinn_phong_normalisation(double exponent);

// pi f(m, l, v) for unit vectors with <m, l> > 0 (0 where <m, v> <= 0 or
// for no lobe): what multiplies V <m, l> beside the facet's colour.
double specular_factor(const SpecularLobe& lobe, const Vec3& m, const Vec3& l, const Vec3& v);

}  // namespace cmfilter
