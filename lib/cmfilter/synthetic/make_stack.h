// SPDX-License-Identifier: Apache-2.0
// `cmfilter make-stack`: a synthetic image stack with exact ground truth
// (docs/make-stack.md). A scene surface's tile
// (synthetic_surface.h) rendered under each light of a dome (light_dome.h)
// from one view, or from several (a BTF), by render_synthetic_stack
// (synthetic_stack.h), and written as a stack that load_image_stack reads.
//
// Files, one view (output: the light file, e.g. out/stack.lp):
//   out/stack-000.exr ...   one image per light, in the dome's order
//                           (scene-linear float EXR, or 8-bit sRGB PNG
//                           through write_rgb_image: clipped to [0, 1]);
//   out/stack.normals.exr   the true mean normal per pixel (stack frame);
//   out/stack.albedo.exr    with `albedo`: the mean colour per pixel;
//   out/stack.json          the record (stack_record.h): every parameter,
//                           the scene's SHA-256, the dome, view and lobe;
//   out/stack.lp            the light file (write_light_file), written
//                           last: a stack is complete when its .lp exists.
// Several views (output: the BTF manifest, e.g. out/btf.json): view slot k
// is a full stack as above in out/view-KK/stack.lp (folders made as needed),
// and the manifest (write_btf_manifest) is written last. Every file is
// written atomically (atomic_output.h); nothing non-finite is written.
//
// Ground truth at further lights: read_stack_record gives back the options
// a stack was made with; set another dome and output and make it again:
// the same surface, view, samples and seed, so the same rays, lit by the
// new lights.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/math/vec3.h"
#include "cmfilter/synthetic/light_dome.h"
#include "cmfilter/synthetic/specular_lobe.h"
#include "cmfilter/synthetic/synthetic_surface.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cmfilter {

// The record's format version (stack_record.h).
inline constexpr int kStackRecordVersion = 1;

struct MakeStackOptions {
    std::string scene;        // the scene file
    std::size_t surface = 0;  // its surface to trace
    // Towards the camera, stack frame (normalised; z > 0); one per view slot.
    std::vector<Vec3> views{{0, 0, 1}};
    int size = 64;     // pixels per side (synthetic_stack.h)
    int samples = 16;  // rays per pixel
    SpecularLobe specular;
    DomeOptions dome;  // at least kMinStackLights lights
    std::uint64_t seed = 0;
    int threads = 0;  // 0: all cores
    // One view: the .lp to write; several: the BTF manifest (.json).
    std::string output;
    std::string image_extension = ".exr";  // ".exr" or ".png"
    bool albedo = false;                   // also write the mean colour per pixel
    // The fraction done; may be empty.
    std::function<void(double)> progress;
};

struct MadeStack {
    std::vector<std::string> light_files;  // one per view slot
    std::vector<std::string> records;
    std::string manifest;  // several views only
    SyntheticSurfaceKind kind = SyntheticSurfaceKind::Microsurface;
    double tile = 0;  // texture units
    int lights = 0, size = 0, samples = 0;
    std::size_t files = 0;  // written
    std::size_t rays = 0;
    double render_seconds = 0, seconds = 0;
};

// BadInput naming the field (MakeStackOptions::output, ::image_extension,
// ::views, ::dome; synthetic_stack.h's and light_dome.h's) and the value:
// an output of the wrong extension for the view count or in a folder that
// does not exist, an image extension other than .exr or .png, no views, a
// view that is zero, non-finite or not above the horizon, fewer than
// kMinStackLights lights; the surface's, the dome's and the renderer's own
// errors. Io when a file cannot be written.
Expected<MadeStack> make_stack(const MakeStackOptions& options, const ColorConfig& config);

// The record's path beside a stack's light file: stack.lp -> stack.json.
std::string stack_record_path(const std::string& light_file);

}  // namespace cmfilter
