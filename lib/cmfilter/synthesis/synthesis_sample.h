// SPDX-License-Identifier: Apache-2.0
// A synthesis sample (Bosserhoff & Nicoll sec. 4.1): a small surface whose
// texels are compared by their values across every image it holds. One
// image (any channels), an image stack (its `.lp`) or a multi-view BTF (its
// manifest, btf_manifest.h). Each texel's feature vector is its values in
// every image, in order (a BTF: view by view, each view's images in its
// light file's order), optionally over a selection of representative images.
// Colour images are decoded to scene-linear as stacks are (image_stack.h);
// data images (one channel, or a data colour space) are taken as they are.
// For hierarchical synthesis (sec. 4.2, figure 4) the sample is a pyramid:
// level l + 1 halves level l with a 2 x 2 box (an odd edge repeats its last
// texel), each level analysed on its own.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cmfilter {

enum class SampleKind { Image, Stack, Btf };
const char* to_string(SampleKind kind);  // "image", "stack", "btf"

struct SampleLevel {
    int width = 0, height = 0;
    std::vector<float> features;  // width * height * SynthesisSample::dims, row-major, top row first
    std::size_t texels() const { return static_cast<std::size_t>(width) * height; }
    const float* feature(std::size_t texel, int dims) const { return features.data() + texel * dims; }
};

struct SynthesisSample {
    std::string path;  // the image, .lp or manifest read ("" for one made in memory)
    SampleKind kind = SampleKind::Image;
    // SHA-256 (64 hex digits) naming the sample's content: sample_content_hash
    // over its image files in order. Coordinate maps and analyses record it.
    std::string hash;
    int channels = 0;                 // per image
    int images = 0;                   // images in the sample (a BTF: over every view)
    std::vector<int> used;            // the images the features hold (indices into the sample's images), ascending
    int dims = 0;                     // used.size() * channels
    bool periodic = false;            // the sample tiles (a synthetic tile): neighbourhoods wrap, else they clamp
    std::vector<SampleLevel> levels;  // levels[0] full resolution
    int width() const { return levels.empty() ? 0 : levels[0].width; }
    int height() const { return levels.empty() ? 0 : levels[0].height; }
};

struct SampleOptions {
    std::string path;        // an image, a `.lp` light file, or a BTF manifest (`.json`)
    std::string colorspace;  // the images' colour space (empty: metadata, else sRGB; float images linear)
    // Representative images to keep (0: all). More than the sample holds
    // keeps all. Chosen by farthest-point selection over whole images
    // (Tong et al. 2002 cluster images; sec. 4.1: "about 150").
    int select_images = 0;
    int levels = 1;         // pyramid levels, >= 1; the coarsest must still be at least 2 x 2
    bool periodic = false;  // see SynthesisSample::periodic
    int threads = 0;
};

// Io naming the file: missing or unreadable. BadInput naming the file and
// value: an empty image or stack, images of different sizes or channels
// (both files, both values), non-finite values, SampleOptions::levels < 1
// or more than the sample's size allows (naming the coarsest size),
// SampleOptions::select_images < 0.
Expected<SynthesisSample> load_synthesis_sample(const SampleOptions& options, const ColorConfig& config);

// A sample made in memory: one level-0 feature image (width * height * dims
// floats), its pyramid built as load_synthesis_sample builds it. The hash is
// SHA-256 of the float bytes. BadInput as load_synthesis_sample.
Expected<SynthesisSample> sample_from_features(int width, int height, int dims, std::vector<float> features,
                                               int levels = 1, bool periodic = false);

// The image files a sample's path names, in feature order (the image
// itself; a stack's images; a BTF's views' images).
Expected<std::vector<std::string>> sample_image_files(const std::string& path);

// SHA-256 over the SHA-256 digests of `files`' bytes, in order (each read
// in chunks): of the digests' 64-hex-digit texts, concatenated. What
// SynthesisSample::hash holds for a sample read from files.
Expected<std::string> sample_content_hash(const std::vector<std::string>& files);

}  // namespace cmfilter
