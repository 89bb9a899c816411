// SPDX-License-Identifier: Apache-2.0
// Hemispherical-harmonics RTI files (`.rti`, "#HSH1.2") as RTIViewer reads
// and writes them: a text header (type 3, width, height, bands, terms, basis
// type, element size), per-term scales and biases, then the quantised
// coefficients. Display-encoded 8-bit, as .ptm (ptm_file.h). Layout:
// docs/stacks.md#rti-files.
#pragma once

#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/stack/ptm_file.h"
#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

// A Hsh2 or Hsh3 fit of 3 channels, DisplayEncoded.
Status write_rti(const std::string& path, const LinearFit& fit, double* max_value_error = nullptr);

Expected<LinearFit> read_rti(const std::string& path);

}  // namespace cmfilter
