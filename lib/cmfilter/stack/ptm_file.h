// SPDX-License-Identifier: Apache-2.0
// Polynomial Texture Map files, version 1.2 (Malzbender, Gelb and Wolters,
// "Polynomial Texture Map (.ptm) File Format", HP Labs), PTM_FORMAT_RGB and
// PTM_FORMAT_LRGB, as HP's PTMfitter writes them and RTIViewer, relight
// (cnr-isti-vclab, legacy_rti.cpp), rti-builder (cceh/rti) and the Java
// RTIViewer (JedMills) read them. The layout:
//
//   PTM_1.2\n
//   PTM_FORMAT_RGB\n            (or PTM_FORMAT_LRGB)
//   <width>\n
//   <height>\n
//   <s0> <s1> <s2> <s3> <s4> <s5>\n     six scales, decimal floats
//   <b0> <b1> <b2> <b3> <b4> <b5>\n     six biases, decimal integers
//   coefficient bytes
//
// Term k is the PTM basis term of Malzbender et al. 2001, eq. 2, in the
// order a0..a5 = lu^2, lv^2, lu lv, lu, lv, 1 (linear_model.h). A byte b of
// term k stands for the coefficient (b - bias_k) * scale_k, in display
// codes (0..255). Rows run bottom to top (the first row stored is the
// image's bottom row), pixels left to right.
//   RGB: three planes, red, green, blue; each holds every pixel's six bytes
//        a0..a5: 18 * width * height bytes. A viewer shows channel c as
//        clamp(sum_k a_ck B_k(l), 0, 255).
//   LRGB: every pixel's six luminance bytes a0..a5, then every pixel's
//        three colour bytes R G B (each block rows bottom to top): 9 *
//        width * height bytes. A viewer shows channel c as
//        L(l) / 255 * C_c with L = sum_k a_k B_k(l) clamped to [0, 255]
//        and C_c the colour byte.
// The reader splits the header into whitespace-separated tokens, so width
// and height may share a line and the scales and biases may run over lines
// (as the format document allows); the bytes begin after the end of the
// line that holds the sixth bias. Bytes after the coefficients are ignored,
// as the viewers ignore them.
//
// The values are display-encoded 8-bit colour, as every viewer expects, so
// the fits they hold are fitted to encoded values
// (StackEncoding::DisplayEncoded). In a LinearFit they are on the scale of
// codes / 255, so relighting gives display codes / 255 (unclamped): RGB
// coefficient (b - bias) * scale / 255; LRGB polynomial coefficient
// (b - bias) * scale / 255 and base colour C / 255.
//
// Writing: per term k, over every texel (and channel), the range
// [min_k, max_k] of the coefficients in codes, widened to hold 0 (so the
// bias is a byte, 0..255, which every reader accepts); of the 256 biases
// the one that needs the smallest scale to cover the range, the scale the
// smallest that covers it (decimal text read back as the viewers read it);
// each byte round(v / scale + bias). A coefficient is then within scale / 2
// of the fit's. A range of 0 (every coefficient 0) writes scale 1, bias 0.
// LRGB base colour: the file holds 8-bit colour bytes and the luminance
// polynomial, so each texel's base colour c is divided by its largest
// channel m (when m > 0) and the polynomial multiplied by m: relit values
// P(l) c are unchanged, the largest channel's byte is 255 and the others
// lose the least to rounding; a negative channel is written as 0.
#pragma once

#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

// What quantisation did to a fit written as .ptm, on the LinearFit's scale
// (display codes / 255).
struct PtmQuantisation {
    // Per term k: the largest |error| in a coefficient (RGB: over texels and
    // channels; LRGB: the luminance polynomial, after the base colour's
    // factor moved into it).
    double max_coefficient_error[6] = {};
    // LRGB: the largest |error| in a base colour channel.
    double max_color_error = 0;
    // The largest |error| in a relit value over texels, channels and the
    // dense set of hemisphere_directions() (relit_difference.h): the fit
    // against what the file decodes to.
    double max_value_error = 0;
    double scales[6] = {};  // as written
    int biases[6] = {};
};

// A PtmRgb or PtmLrgb fit of 3 channels, DisplayEncoded, written
// atomically (no file on failure). BadInput naming the fit's model,
// encoding or channels and what is needed; a non-finite coefficient
// (naming the texel).
Status write_ptm(const std::string& path, const LinearFit& fit, PtmQuantisation* quantisation = nullptr);

// PTM_FORMAT_RGB and PTM_FORMAT_LRGB. BadInput naming the file and what is
// wrong: an unknown version or format line (the JPEG, JPEG-LS, LUM and LUT
// formats named as not supported), a bad width or height (not a positive
// integer, or above 65536), a scale that is not a finite number, a bias
// that is not an integer, a truncated file ("expected N bytes of
// coefficients, found M"). Io when it cannot be read. The fit: encoding
// DisplayEncoded, colorspace "sRGB", channels 3, conditioning unknown (all
// zero: the file holds no lights).
Expected<LinearFit> read_ptm(const std::string& path);

// The same from the file's bytes in memory; `name` names it in messages.
Expected<LinearFit> decode_ptm(const std::string& bytes, const std::string& name);

}  // namespace cmfilter
