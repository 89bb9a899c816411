// SPDX-License-Identifier: Apache-2.0
// Hemispherical-harmonics RTI files (`.rti`, "#HSH1.2") as RTIViewer reads
// them and Cultural Heritage Imaging's HSH fitter and relight
// (cnr-isti-vclab, rtibuilder.cpp) write them; checked also against
// relight's reader (legacy_rti.cpp) and the Android RTIViewer (RTI.java).
// The layout:
//
//   #HSH1.2\n
//   #<comment>\n ...            any further lines that begin with '#'
//   3\n                         the RTI type: 3 = HSH
//   <width> <height> <bands>\n  bands = 3 (R, G, B)
//   <terms> <basis type> <element size>\n   terms 4 (order 2) or 9 (order 3);
//                               basis type 2; element size 1 (one byte)
//   terms little-endian float32 scales, then terms float32 biases
//   coefficient bytes: rows top to bottom (the first row stored is the
//   image's top row), pixels left to right, per pixel the bands R, G, B,
//   per band the terms in RTIViewer's order (linear_model.h):
//   width * height * 3 * terms bytes.
//
// A byte b of term k stands for the coefficient b / 255 * scale_k + bias_k,
// and a viewer shows a band as clamp(sum_k coefficient_k H_k(l), 0, 1) *
// 255: the values are display-encoded 8-bit colour (as .ptm, ptm_file.h),
// so the fits they hold are fitted to encoded values
// (StackEncoding::DisplayEncoded), and in a LinearFit they are on the scale
// of codes / 255 as they stand. The basis type is not read (the viewers
// ignore it); bytes after the coefficients are ignored.
//
// Writing: per term k, over every texel and band, the range [min_k, max_k];
// scale_k = max_k - min_k and bias_k = min_k (as float32; a range of 0
// writes scale 1), each byte round((v - bias_k) / scale_k * 255): a
// coefficient is then within scale_k / 510 of the fit's. No comment lines
// are written (some readers count the header's lines).
#pragma once

#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

// What quantisation did to a fit written as .rti, on the LinearFit's scale.
struct RtiQuantisation {
    int terms = 0;
    // Per term k < terms: the largest |error| in a coefficient over texels
    // and bands.
    double max_coefficient_error[kMaxLinearTerms] = {};
    // The largest |error| in a relit value over texels, bands and the dense
    // set of hemisphere_directions() (relit_difference.h).
    double max_value_error = 0;
    float scales[kMaxLinearTerms] = {};  // as written
    float biases[kMaxLinearTerms] = {};
};

// A Hsh2 or Hsh3 fit of 3 channels, DisplayEncoded, written atomically (no
// file on failure). BadInput naming the fit's model, encoding or channels
// and what is needed; a non-finite coefficient (naming the texel).
Status write_rti(const std::string& path, const LinearFit& fit, RtiQuantisation* quantisation = nullptr);

// HSH .rti of 4 or 9 terms, 3 bands, 1-byte elements. BadInput naming the
// file and what is wrong: a first line other than #HSH1.2, an RTI type other
// than 3 (PTM, SH and adaptive-basis .rti named as not supported), a bad
// size line, bands other than 3, terms other than 4 or 9, an element size
// other than 1, a scale or bias that is not finite, a truncated file
// ("expected N bytes of coefficients, found M"). Io when it cannot be read.
// The fit: encoding DisplayEncoded, colorspace "sRGB", conditioning unknown.
Expected<LinearFit> read_rti(const std::string& path);

// The same from the file's bytes in memory; `name` names it in messages.
Expected<LinearFit> decode_rti(const std::string& bytes, const std::string& name);

}  // namespace cmfilter
