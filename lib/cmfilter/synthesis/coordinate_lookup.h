// SPDX-License-Identifier: Apache-2.0
// Rendering through a coordinate map (sec. 4.2 and 5: one more texture
// lookup), at full size and at any level of detail. A coordinate map is a
// driver: averaging coordinates across a seam, as a mip of the map does,
// lands in an unrelated part of the sample, wrong in the way filtering a
// driver before its colour map is (Heitz et al. 2013, sec. 1). The methods:
// - Reference: the full-size output box-filtered over each 2^L x 2^L
//   footprint (what every other method is measured against);
// - NaiveMip: the map's coordinates box-averaged over the footprint, then
//   the sample's pyramid level L read there bilinearly;
// - Point: the footprint's centre texel's coordinate into the sample's
//   level L (right inside a patch, one patch only at a seam);
// - Levels: hierarchical synthesis's own level-L map into the sample's
//   level L (as far as the synthesis has levels);
// - Patches: per footprint, the distribution of its texels' patch offsets
//   (c(p) - p: constant over each piece copied whole), its `patches` most
//   common kept with their shares; each offset's footprint box read exactly
//   from a summed-area table of the sample, weighted by its share. Exact
//   where a footprint lies in one patch, a mixture of the right pieces at
//   a seam. The patch levels are built from the full-size map in one pass
//   per level and can be kept for a renderer.
#pragma once

#include "cmfilter/synthesis/coordinate_map.h"
#include "cmfilter/synthesis/sample_image.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <string>
#include <vector>

namespace cmfilter {

struct OutputImage {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;
};

enum class LodMethod { Reference, NaiveMip, Point, Levels, Patches };
const char* to_string(LodMethod method);  // "reference", "naive", "point", "levels", "patches"
Expected<LodMethod> parse_lod_method(const std::string& name);

struct LodOptions {
    int lod = 0;  // L >= 0: footprints of 2^L x 2^L full-size texels
    LodMethod method = LodMethod::Patches;
    int patches = 4;  // Patches: offsets kept per footprint, >= 1
    int threads = 0;
};

// The full-size output: each texel the sample texel its coordinate names.
// BadInput when the map's level 0 points outside the image's size (naming
// both sizes).
Expected<OutputImage> render_through_map(const CoordinateMap& map, const SampleImage& sample, int threads = 0);

// The output at level of detail L: ceil(width / 2^L) x ceil(height / 2^L)
// texels (edge footprints cover what the output has). BadInput naming the
// field: LodOptions::lod < 0, LodOptions::patches < 1, Levels at an L the
// map has no level for; the sizes as render_through_map.
Expected<OutputImage> render_at_lod(const CoordinateMap& map, const SampleImage& sample, const LodOptions& options);

// A patch level: per footprint of level L, `patches` entries of (dx, dy,
// share): the offset (sample texel - output texel, full-size texels) of a
// piece and the share of the footprint it covers, most common first; unused
// entries have share 0. A share is the fraction of the whole footprint: they sum to 1 when the footprint holds at most `patches` pieces, and render_at_lod reads what is left at the full-size output's mean. Offsets into a periodic sample
// (reads wrap) are wrapped into [0, W) x [0, H) of the map's level-0 sample,
// so that a piece copied across the sample's edge keeps one offset. Ties
// between offsets as common are kept by lower (dy, dx). BadInput naming
// LodOptions::lod (< 0) or LodOptions::patches (< 1), or a map without a
// level 0.
struct PatchLevel {
    int lod = 0, width = 0, height = 0, patches = 0;
    std::vector<float> entries;  // width * height * patches * 3
    const float* entry(std::size_t texel, int k) const { return entries.data() + (texel * patches + k) * 3; }
};
Expected<PatchLevel> build_patch_level(const CoordinateMap& map, int lod, int patches, bool periodic, int threads = 0);

}  // namespace cmfilter
