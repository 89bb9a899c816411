// SPDX-License-Identifier: Apache-2.0
// One periodic tile of a scene surface's microsurface, ray traced for a
// synthetic image stack (make_stack.h): a Gaussian microsurface
// (MicrosurfaceDriver: one tile of GaussianMicrosurface::tile() texture
// units) or a textured displacement (DisplacementDriver: one texture unit),
// tabulated as the Heightfield that `render --method reference` traces
// (render/microsurface_surface.cpp and displacement_surface.cpp), coloured
// at each hit by the material's layers exactly as render's ray-traced
// methods colour it (render/layered_surface.cpp): C_h(height), C_s(slope),
// the base layer's point colour, combined by combine_point_color.
//
// Frames. The heightfield's frame is the texture's: (u, v, h), u along the
// image's columns, v growing downwards with the rows (texture convention,
// displacement_texture.h), h the height in texture units. A stack's frame
// (light_file.h) is x right, y up towards the image's top row, z towards
// the camera; so a stack direction (x, y, z) is (x, -y, z) in the
// heightfield's frame, and back (to_heightfield_frame, to_stack_frame: the
// same flip). A light from +y lights the slopes that face the top row:
// those whose height rises towards the rows below (dh/dv > 0).
//
// A displacement's heightfield lies half a texel off the texture
// (DisplacementTexture::heightfield_xy): trace() takes and returns texture
// coordinates and shifts them as render does.
//
// Immutable once made; const queries are thread-safe.
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/color/color_config.h"
#include "cmfilter/math/vec3.h"
#include "cmfilter/microsurface/heightfield_tracer.h"
#include "cmfilter/scene/material.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cmfilter {

// (x, y, z) -> (x, -y, z): the stack's frame to the heightfield's and back.
inline Vec3 to_heightfield_frame(const Vec3& stack) { return {stack.x, -stack.y, stack.z}; }
inline Vec3 to_stack_frame(const Vec3& heightfield) { return {heightfield.x, -heightfield.y, heightfield.z}; }

class DriverRenderer;  // render/surface_renderer.h: the base layer's colour at a point

enum class SyntheticSurfaceKind { Microsurface, Displacement };
const char* to_string(SyntheticSurfaceKind kind);

// A primary ray's first hit on the tile.
struct SyntheticHit {
    Vec3 point;   // heightfield frame (the heightfield's own x, y: a displacement's shifted half a texel)
    Vec3 normal;  // the bilinear patch's unit micro-normal, heightfield frame, z > 0
    Rgb color;    // the material's colour there
};

struct SyntheticSurfaceOptions {
    std::string scene;        // the scene file (docs/scene-format.md)
    std::size_t surface = 0;  // the surface whose material is traced
    int threads = 0;          // loading and tabulating; 0: all cores
};

class SyntheticSurface {
public:
    // load_scene, prepare_materials and create. BadInput naming the scene
    // file and the surface (field SyntheticSurfaceOptions::surface): an
    // index past the scene's surfaces; the loaders' own errors.
    static Expected<SyntheticSurface> load(const SyntheticSurfaceOptions& options, const ColorConfig& config);
    // A prepared scene's surface. BadInput naming the file and the surface
    // (/surfaces/i) when its material is not a Gaussian microsurface or a
    // textured displacement (its kind named), or when its tile cannot be
    // tabulated (the heightfield's error).
    static Expected<SyntheticSurface> create(std::shared_ptr<const Scene> scene,
                                             std::shared_ptr<const std::vector<Material>> materials,
                                             std::size_t surface, int threads);

    SyntheticSurfaceKind kind() const { return kind_; }
    // The tile's side in texture units: a Gaussian microsurface's period, or
    // 1 for a displacement.
    double tile() const { return heightfield_->tile(); }
    const Heightfield& heightfield() const { return *heightfield_; }
    const Scene& scene() const { return *scene_; }
    std::size_t surface() const { return surface_; }

    // The ray along -view (heightfield frame, unit, z > 0) through the
    // texture point (u, v) of the mean plane h = 0; none when it meets no
    // surface.
    std::optional<SyntheticHit> trace(double u, double v, const Vec3& view) const;
    // Whether the light (heightfield frame, unit) reaches the hit: the
    // facet faces it and the shadow ray is not blocked (hard shadows).
    bool lit(const SyntheticHit& hit, const Vec3& light) const;

private:
    SyntheticSurface() = default;
    std::shared_ptr<const Scene> scene_;
    std::shared_ptr<const std::vector<Material>> materials_;
    std::size_t surface_ = 0;
    SyntheticSurfaceKind kind_ = SyntheticSurfaceKind::Microsurface;
    const MicrosurfaceColors* colors_ = nullptr;
    std::shared_ptr<const DriverRenderer> base_;  // null: no base layer
    std::shared_ptr<const Heightfield> heightfield_;
    double shift_ = 0;  // texture (u, v) = heightfield (x, y) + shift
};

}  // namespace cmfilter
