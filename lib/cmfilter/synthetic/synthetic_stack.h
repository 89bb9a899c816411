// SPDX-License-Identifier: Apache-2.0
// The images of a synthetic surface's tile (synthetic_surface.h) under a
// set of lights, in memory: one view slot of a synthetic BTF with its exact
// ground truth (make_stack.h writes them).
//
// The camera is orthographic along -view, one texel per pixel: pixel (i,
// j), column i and row j from the top, covers the texture square u in [i,
// i + 1] t / S, v in [j, j + 1] t / S of the mean plane h = 0 (t the tile,
// S the size), so the images of any view are registered texel for texel
// (a rectified BTF). Its rays pass through `samples` points of the square,
// stratified: a gx x gy grid (gx the largest divisor of samples not above
// its square root), one point jittered uniformly in each cell by a
// SplitMix64 generator seeded from the seed and the pixel's index alone, so
// the result is the same for any thread count, and the same points serve
// every light (and every view of a BTF, and a later ground-truth render
// with the same seed).
//
// Shading of a ray's first hit, facet normal m, for each light l (unit,
// both in the stack's frame, converted to the heightfield's):
//   value = V <m, l>+ (colour + pi f_spec(m, l, v))
// with colour the material's at the hit (Lambertian facet), V = 1 unless
// the shadow ray is blocked or the facet faces away (hard shadows), f_spec
// the optional lobe (specular_lobe.h). Values are scene-linear, without
// 1 / pi: a white Lambertian facet facing the light gives 1 under unit
// irradiance. A ray that meets nothing (not possible on a periodic surface
// seen from above) adds 0. A pixel is the mean over its rays.
// Per pixel also the true mean normal: the visible hits' micro-normals
// averaged and normalised, in the stack's frame ((0, 0, 1) with no hit),
// and optionally the mean colour of the visible hits (the albedo).
#pragma once

#include "cmfilter/math/vec3.h"
#include "cmfilter/synthetic/specular_lobe.h"
#include "cmfilter/synthetic/synthetic_surface.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cmfilter {

inline constexpr int kMaxSyntheticSize = 4096;
inline constexpr int kMaxSyntheticSamples = 1 << 16;

struct SyntheticStackOptions {
    Vec3 view{0, 0, 1};  // towards the camera, stack frame; normalised here; z > 0
    int size = 64;       // S, pixels per side: 1 .. kMaxSyntheticSize
    int samples = 16;    // rays per pixel: 1 .. kMaxSyntheticSamples
    SpecularLobe specular;
    std::uint64_t seed = 0;
    int threads = 0;      // 0: all cores
    bool albedo = false;  // also the mean colour per pixel
    // The fraction of rows done, called from the calling thread; may be empty.
    std::function<void(double)> progress;
};

struct SyntheticStack {
    int size = 0;
    Vec3 view;                 // unit, stack frame
    std::vector<Vec3> lights;  // unit, stack frame
    // lights.size() RGB images, each size * size * 3 floats, row-major, top
    // row first (ImageStack's layout).
    std::vector<float> pixels;
    std::vector<float> normals;  // size * size * 3: the true mean normals, stack frame
    std::vector<float> albedo;   // size * size * 3 when asked, else empty
    std::size_t rays = 0, hits = 0;
    double seconds = 0;

    std::size_t texels() const { return static_cast<std::size_t>(size) * size; }
    const float* image(std::size_t k) const { return pixels.data() + k * texels() * 3; }
};

// BadInput unless 1 <= size <= kMaxSyntheticSize and 1 <= samples <=
// kMaxSyntheticSamples, naming the fields `owner`::size and ::samples (the
// options struct they came from: "SyntheticStackOptions", "MakeStackOptions").
Status check_synthetic_size(int size, int samples, const std::string& owner);

// BadInput naming the field (SyntheticStackOptions::view, ::size, ::samples,
// SpecularLobe's) or the light (its index and value): a zero or non-finite
// direction, a view not above the horizon (z <= 0), a light below it (z <
// 0), no lights, a size or sample count out of range.
Expected<SyntheticStack> render_synthetic_stack(const SyntheticSurface& surface, const std::vector<Vec3>& lights,
                                                const SyntheticStackOptions& options);

}  // namespace cmfilter
