// SPDX-License-Identifier: Apache-2.0
// The exact filtering distribution of a driver with few distinct values
// (Heitz et al. 2013, sec. 4.1, "exact solutions"): per MIP level and texel,
// the histogram of f over the texel's box footprint, one channel per distinct
// value v_b (at most 256): channel b holds the box mean of the indicator
// [f == v_b], i.e. the fraction of the footprint where f = v_b. The filtered
// colour of any colour map is then the inner product
//     <C, D> = sum_b h_b C(v_b),
// exact for a box footprint, and a lookup between levels blends histograms
// linearly, as it blends colours.
//
// The file is a tiled, mip-mapped float32 OpenEXR with the same level
// geometry as a moment pyramid (docs/moments-format.md: level k is
// max(1, W >> k) x max(1, H >> k), exact box means for any size), channels
// "h000", "h001", ... (zero-padded: OpenEXR sorts channels by name) and the
// distinct values in the cmfilter:* metadata. Its cost
// is B float32 channels per texel for B distinct values: 4 B x 4/3 bytes per
// driver texel over all levels (for a 2048 x 2048 driver with 16 values,
// 358 MB on disk before compression; with 256 values, 5.7 GB), which is why
// the method is limited to drivers with few distinct values.
#pragma once

#include "cmfilter/io/driver_image.h"
#include "cmfilter/util/error.h"
#include "cmfilter/texture/pyramid_bake_options.h"
#include "cmfilter/math/texture_wrap.h"

#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>
#include <vector>

namespace OIIO_NAMESPACE {
class TextureSystem;
}

namespace cmfilter {

inline constexpr const char* kHistogramPyramidKind = "histogram-pyramid";
inline constexpr int kHistogramPyramidFormatVersion = 1;
inline constexpr int kHistogramMaxValues = 256;

struct HistogramPyramidInfo {
    int width = 0, height = 0;
    int levels = 0;
    std::vector<double> values;  // the distinct driver values v_b, ascending (as float32 values)
    std::string channel;         // driver channel used
    TextureWrap wrap = TextureWrap::Clamp;
    std::string source;
    std::string source_sha256;
    std::size_t nonfinite_replaced = 0;
    std::string baked_by;  // cmfilter version (filled in on read)
};

// The cmfilter:* attributes of a histogram pyramid (and the "wrapmodes"
// TextureSystem reads), set on the level-0 spec being written / read back.
// Reading gives BadInput naming `path` when the file is not a histogram
// pyramid or its metadata is inconsistent with its channels.
// The source is recorded relative to `path`, the file being written or read
// (io/recorded_path.h).
void set_histogram_pyramid_metadata(OIIO::ImageSpec& spec, const HistogramPyramidInfo& info, const std::string& path);
Expected<HistogramPyramidInfo> get_histogram_pyramid_metadata(const OIIO::ImageSpec& spec, const std::string& path);

struct HistogramBakeOptions : PyramidBakeOptions {};

// BadInput (listing how many there are) when the driver has more than
// kHistogramMaxValues distinct values.
Expected<HistogramPyramidInfo> bake_histogram_pyramid(const HistogramBakeOptions& options);

// A histogram pyramid opened for lookups, through OpenImageIO's TextureSystem
// with bilinear interpolation and trilinear blending, as MomentTexture.
class HistogramTexture {
public:
    // Io when unreadable, BadInput when not a histogram pyramid.
    static Expected<HistogramTexture> open(const std::string& path);

    const HistogramPyramidInfo& info() const { return info_; }
    int bins() const { return static_cast<int>(info_.values.size()); }

    // The fraction of the footprint at each distinct value (bins() weights,
    // summing to 1 up to rounding, none negative) at (s, t) and lod, with the
    // conventions of MomentTexture::lookup. Thread-safe.
    bool lookup(float s, float t, float lod, float* weights) const;

private:
    HistogramTexture() = default;
    std::string path_;
    HistogramPyramidInfo info_;
    std::shared_ptr<OIIO::TextureSystem> ts_;
};

}  // namespace cmfilter
