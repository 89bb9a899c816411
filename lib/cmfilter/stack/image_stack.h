// SPDX-License-Identifier: Apache-2.0
// An image stack: one view slot of a BTF, images of the same size and
// channel count of one surface, each lit from one direction (its light
// file, light_file.h). Any format OpenImageIO reads. Integer images are
// display-encoded colour and are decoded to scene-linear with OpenColorIO,
// as colour maps are (image_colorspace.h: an explicit colour space, else the
// file's metadata, else sRGB); float images (EXR) are taken as linear.
// Every image is read into memory as float (streamed_fit.h fits a stack
// without holding it).
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/io/image_colorspace.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/math/vec3.h"
#include "cmfilter/stack/light_file.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <string>
#include <vector>

namespace cmfilter {

// The fewest lights a stack may have: a PTM has 6 coefficients per channel.
constexpr int kMinStackLights = 6;

// What the values of a stack (or a fit of one) are.
enum class StackEncoding {
    SceneLinear,     // the config's scene_linear role (or data, for non-colour channels)
    DisplayEncoded,  // sRGB display codes / 255 (or / 65535), as .ptm and .rti hold them
};
const char* to_string(StackEncoding encoding);

struct ImageStack {
    int width = 0, height = 0, channels = 0;
    std::vector<Vec3> lights;         // unit, z >= 0, one per image, in the light file's order
    std::vector<std::string> images;  // each image's path as read (resolved against the .lp)
    std::string light_file;           // the .lp read (empty: made in memory)
    StackEncoding encoding = StackEncoding::SceneLinear;
    std::string colorspace;  // SceneLinear: the linear space; DisplayEncoded: the sRGB encoding; data: its space
    // lights.size() images, each width * height * channels floats,
    // row-major, top row first, interleaved: image k's texel t channel c is
    // pixels[(k * texels() + t) * channels + c].
    std::vector<float> pixels;

    std::size_t texels() const { return static_cast<std::size_t>(width) * height; }
    int count() const { return static_cast<int>(lights.size()); }
    const float* image(int k) const { return pixels.data() + static_cast<std::size_t>(k) * texels() * channels; }
    float* image(int k) { return pixels.data() + static_cast<std::size_t>(k) * texels() * channels; }
};

struct StackLoadOptions {
    std::string light_file;  // the .lp
    // The images' colour space (integer images; empty: each file's metadata,
    // else sRGB). Float images are linear whatever it says, unless named.
    std::string colorspace;
    // Keep the values display-encoded (sRGB codes / 255 for integer files;
    // float files are encoded from scene-linear with the config's sRGB) for
    // the fits that .ptm and .rti files hold.
    StackEncoding encoding = StackEncoding::SceneLinear;
    int threads = 0;  // images read in parallel; 0: all cores
};

// BadInput naming the file: the light file's own errors (read_light_file),
// fewer than kMinStackLights lights, images of different sizes or channel
// counts (naming both files and both values), an image with non-finite
// pixels. Io naming the image: a missing or unreadable image.
Expected<ImageStack> load_image_stack(const StackLoadOptions& options, const ColorConfig& config);

// One image of a stack, read and decoded as load_image_stack reads each:
// checked finite, its colour channels decoded to scene-linear (the colour
// space from StackLoadOptions::colorspace, else the file's metadata, else
// sRGB; float images linear) and re-encoded to sRGB display values when
// StackLoadOptions::encoding asks for them. Shared with the streamed fits
// and errors that hold one image at a time (streamed_fit.h,
// relight_error.h), so that all of them read, decode and check alike.
struct StackImage {
    ImageData data;         // width * height * channels floats, decoded
    ImageColorSpace space;  // the colour space the file was decoded from
};

// Io naming the image: missing or unreadable. BadInput naming the image: a
// non-finite value (with its texel and channel), or an unknown colour space.
Expected<StackImage> load_stack_image(const std::string& path, const StackLoadOptions& options,
                                      const ColorConfig& config);

// BadInput naming the light file when it has fewer than kMinStackLights.
Status check_stack_light_count(const LightFile& lights);

// BadInput when `image` (at `path`) differs in size or channels from the
// stack's first image (`first_path`, width x height, channels), naming both
// files and both values.
Status check_stack_image_shape(const std::string& path, const ImageData& image, const std::string& first_path,
                               int width, int height, int channels);

// The colour space a stack's values are in (ImageStack::colorspace), given
// its first image's.
std::string stack_colorspace(const ImageColorSpace& first, const StackLoadOptions& options, const ColorConfig& config);

}  // namespace cmfilter
