// SPDX-License-Identifier: Apache-2.0
// A scene for `cmfilter render` (docs/scene-format.md): a pinhole camera, one
// directional light, and surfaces (infinite planes, spheres), each with a
// texture mapping and a material: a colour map driven by a procedural noise
// or a texture. Plain data: load_scene (scene_loading.h) fills and checks it;
// every path in it is absolute or relative to the working directory (the
// loader resolves the file's own relative paths against the scene's folder).
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/microsurface/color_combination.h"
#include "cmfilter/microsurface/gaussian_microsurface.h"
#include "cmfilter/math/vec3.h"
#include "cmfilter/math/wrap_mode.h"

#include <optional>
#include <string>
#include <vector>

namespace cmfilter {

struct SceneCamera {
    Vec3 position;
    Vec3 look_at;
    Vec3 up{0, 1, 0};
    double fov_degrees = 60;  // vertical field of view, in (0, 180)
    int width = 640;          // pixels, 1 .. kMaxImageSide
    int height = 360;
};

inline constexpr int kMaxImageSide = 16384;
inline constexpr long long kMaxImagePixels = 1LL << 26;  // 64 Mi pixels

struct SceneLight {
    Vec3 direction{0, 1, 0};  // towards the light; unit length after loading
    Rgb radiance{1, 1, 1};    // irradiance on a surface facing the light
    Rgb ambient{0, 0, 0};     // added to every lit surface point, times albedo
};

// Texture coordinates (u, v) of a surface point p, in the units the driver
// reads (noise units for a procedural driver, texture repeats for a texture,
// which wraps at 1).
//   planar:    u = <p - origin, u_axis>, v = <p - origin, v_axis>
//              (the axes' lengths are texture units per scene unit);
//   spherical: u = u_scale * phi / (2 pi), v = v_scale * theta / pi, with phi
//              the longitude about the sphere's y axis from +x, in [0, 2 pi),
//              and theta the polar angle from +y, in [0, pi].
enum class MappingKind { Planar, Spherical };
struct TextureMapping {
    MappingKind kind = MappingKind::Planar;
    Vec3 origin;
    Vec3 u_axis{1, 0, 0};
    Vec3 v_axis{0, 0, 1};
    double u_scale = 1, v_scale = 1;
};

// A colour map: a baked table (bake-colormap output), or a map image laid
// over [domain_min, domain_max] whose table the renderer bakes itself.
struct ColorMapSource {
    std::string table_path;  // set: a baked table; else the image fields
    std::string image_path;
    double domain_min = 0, domain_max = 1;
    WrapMode wrap = WrapMode::Clamp;
    std::string colorspace;  // empty: decided from the file
    // With an image: bake the smallest table whose lookup error stays within
    // this CIEDE2000 over the surface's sigma range (tolerance_tables.h)
    // instead of the default 256 x 256 one.
    std::optional<double> tolerance;
};

// The driver f: a procedural noise (spec text, noise_spec.h) with an
// optional baked sigma table (bake-noise output; absent: baked when
// rendering), or a texture: a moment pyramid (bake-moments output) or a
// driver image (its moments baked when rendering).
enum class DriverKind { Noise, Moments, Image };
struct DriverSource {
    DriverKind kind = DriverKind::Noise;
    std::string noise_spec;
    std::string sigma_table_path;
    std::string moments_path;
    std::string image_path;
    // Moments or image: a segment pyramid of the same driver
    // (bake-moments --segments) that render --method segments reads; empty:
    // baked when rendering.
    std::string segments_path;
};

// A material colours its surface by a driver (colormap = C0 of the driver's
// values) or by a Gaussian microsurface (sec. 5): its heights (colormap =
// C_h over heights, sec. 5.1), its slopes (slope_colormap = C_s, sec. 5.2),
// a base layer (base = C0 of a driver, uncorrelated with the microsurface),
// or a combination of these (sec. 6), all masked towards the viewer and
// shadowed towards the light. A microsurface lives on a plane whose planar
// mapping is a scaled isometry (u_axis and v_axis perpendicular, of equal
// length k, in the plane): its wavelengths and heights are in texture units,
// and it displaces the plane along its normal by h / k scene units. The
// driver of a base layer reads the same texture coordinates.
inline constexpr int kMaxMicrosurfaceCosines = 4096;
// A scene microsurface's default period, in longest wavelengths.
inline constexpr double kMicrosurfaceTileWavelengths = 8;

// A slope colour map (slope_color_map.h): a gradient image over the slope
// angle in degrees (steepness), or an image over the slope plane
// [-max_slope, max_slope]^2 (vector).
enum class SlopeMapKind { Steepness, Vector };
struct SlopeColorMapSource {
    SlopeMapKind kind = SlopeMapKind::Steepness;
    std::string image_path;
    double domain_min = 0, domain_max = 90;  // steepness: degrees
    WrapMode wrap = WrapMode::Clamp;         // steepness
    double max_slope = 1;                    // vector: > 0
    std::string colorspace;                  // empty: decided from the file
};

// A base layer: C0 over a driver, as a plain material has.
struct BaseLayerSource {
    ColorMapSource colormap;
    DriverSource driver;
};

// A textured displacement (displacement_texture.h): a square one-channel
// image, one repeat a texture unit, heights texel * height_scale in texture
// units, in place of a Gaussian microsurface (the paper's snake, fig. 10).
struct DisplacementSource {
    std::string image_path;
    std::string channel;  // a name or 0-based index; empty: the image's only channel
    double height_scale = 1;
};

struct MaterialSource {
    // C0 over the driver, or with a microsurface C_h over its heights; absent
    // (no table_path, no image_path) on a microsurface without a height map.
    ColorMapSource colormap;
    DriverSource driver;  // unused with a microsurface
    // The microsurface: a Gaussian one or a textured displacement (at most
    // one); the keys below are a microsurface material's.
    std::optional<GaussianMicrosurfaceOptions> microsurface;
    std::optional<DisplacementSource> displacement;
    std::optional<SlopeColorMapSource> slope_colormap;  // microsurface only
    std::optional<BaseLayerSource> base;                // microsurface only
    ColorCombination combine;                           // microsurface only (color_combination.h)

    bool has_colormap() const { return !colormap.table_path.empty() || !colormap.image_path.empty(); }
    bool has_microsurface() const { return microsurface || displacement; }
};

enum class SurfaceKind { Plane, Sphere };
struct Surface {
    SurfaceKind kind = SurfaceKind::Plane;
    Vec3 point;            // plane: a point on it
    Vec3 normal{0, 1, 0};  // plane: unit length after loading
    Vec3 center;           // sphere
    double radius = 1;     // sphere: > 0
    TextureMapping mapping;
    MaterialSource material;
};

struct Scene {
    std::string path;  // the file it was loaded from (messages, metadata)
    SceneCamera camera;
    SceneLight light;
    std::vector<Surface> surfaces;
    Rgb background{0, 0, 0};
};

}  // namespace cmfilter
