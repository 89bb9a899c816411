// SPDX-License-Identifier: Apache-2.0
// A linear fit (linear_fit.h) of an image stack read from its files one
// image at a time, for stacks larger than memory (a 50-megapixel capture of
// 100 lights is 60 GB as float). The pseudo-inverse P = A^+ (terms x
// lights) depends only on the lights, so a texel's coefficients
// P [I_1 .. I_n]^T are the sum over lights k of P[:, k] I_k: each image is
// added to per-texel accumulators (double) as it is read, in index order.
//
// PtmLrgb in the same one pass: with G_c = P I_c (channel c's accumulated
// polynomial, as PtmRgb's), the luminance polynomial is a = P Y =
// sum_c w_c G_c (w the Rec. 709 weights, or 1); with A = U S V^T and W =
// S V^T, the fitted luminance F = A a has sum_k F_k^2 = |W a|^2 and
// sum_k I_{c,k} F_k = (W a) . (W G_c) (a has no component along a clamped
// singular vector, so the clamped part of A^T I_c does not enter); the
// negligible-energy guard and its mean-colour fallback need sum_k Y_k^2 and
// sum_k I_{c,k}, accumulated too. The base colour is then
// c = sum_k I_k F_k / sum_k F_k^2 as in fit_linear.
//
// Peak memory: the accumulators, 8 bytes x texels x (channels x terms;
// PtmLrgb channels x 7 + 1), and the returned coefficients, 4 bytes x
// texels x LinearFit::stride(), plus at most StackLoadOptions::threads
// images in flight (0: the hardware threads), each as read and decoded (4
// bytes x texels x channels, with its decoder's and the colour conversion's
// temporaries); not the stack. For the 256 x 256 x 64 RGB stack of
// docs/stacks.md#memory, PTM RGB: 9.4 MB of accumulators and 4.7 MB of
// coefficients, against 50 MB for the stack as float (measured peaks 22 MB
// and 68 MB).
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/util/error.h"

#include <functional>

namespace cmfilter {

// fit_linear(load_image_stack(load, config), options) to float rounding,
// without holding the stack. In order: the light file's errors and the
// light count (as load_image_stack), then LinearFitOptions and the light set
// (as fit_linear: check_light_set, naming the light file) before any image
// is read; then per image, in index order, the errors of load_image_stack
// (a missing or unreadable image, a non-finite value, a size or channel
// count other than the first image's, naming both files), and PtmLrgb on
// other than 1 or 3 channels after the first image. Images are read
// StackLoadOptions::threads at a time in parallel; the accumulation is
// threaded over blocks of texels by LinearFitOptions::threads, each texel
// adding the images in index order, so the result is the same for any
// thread counts. `progress` (may be empty) gets the fraction of images
// added, from the calling thread.
Expected<LinearFit> fit_linear_from_files(const StackLoadOptions& load, const LinearFitOptions& options,
                                          const ColorConfig& config, const std::function<void(double)>& progress = {});

}  // namespace cmfilter
