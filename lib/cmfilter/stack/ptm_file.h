// SPDX-License-Identifier: Apache-2.0
// Polynomial Texture Map files, version 1.2 (Malzbender et al.'s "PTM
// format" document, as HP's PTMviewer, RTIViewer and PTMfitter read and
// write them): PTM_FORMAT_RGB and PTM_FORMAT_LRGB. A header of text lines
// (the version string, the format, width and height on lines of their own,
// six scales and six biases), then the coefficient bytes, rows bottom to
// top. A coefficient byte b stands for (b - bias) * scale. The values are
// display-encoded 8-bit colour, as every viewer expects, so the fits they
// hold are fitted to encoded values (StackEncoding::DisplayEncoded).
// Layout and the choice of scale and bias: docs/stacks.md#ptm-files.
#pragma once

#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

struct PtmQuantisation {
    // Per term k: the largest |error| quantisation makes in a coefficient.
    double max_coefficient_error[6] = {};
    // The largest |error| it makes in a relit value at the fit's lights... or
    // at a dense set of directions over the hemisphere (display codes / 255).
    double max_value_error = 0;
};

// A PtmRgb or PtmLrgb fit of 3 channels, DisplayEncoded. Scale and bias per
// term chosen from the data (docs). BadInput naming the fit's problem
// otherwise.
Status write_ptm(const std::string& path, const LinearFit& fit, PtmQuantisation* quantisation = nullptr);

// RGB and LRGB (and their JPEG-compressed variants where supported, see the
// docs). BadInput naming the file and what is wrong: an unknown version or
// format, a truncated file (bytes expected and found), bad header numbers.
Expected<LinearFit> read_ptm(const std::string& path);

}  // namespace cmfilter
