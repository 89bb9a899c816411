// SPDX-License-Identifier: Apache-2.0
// Helpers for the renderer's unit tests: printing a Vec3 in doctest messages,
// finiteness, angles, central differences, a scene camera, a terrain fBm
// material, and the CIEDE2000 difference of two renders.
#pragma once

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/color/color_config.h"
#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/color/error_summary.h"
#include "cmfilter/noise/noise_spec.h"
#include "cmfilter/render/render.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/scene/scene_materials.h"
#include "cmfilter/math/vec3.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace doctest {
template <>
struct StringMaker<cmfilter::Vec3> {
    static String convert(const cmfilter::Vec3& v)
    {
        std::ostringstream s;
        s << std::setprecision(17) << "(" << v.x << ", " << v.y << ", " << v.z << ")";
        return s.str().c_str();
    }
};
}  // namespace doctest

namespace cmfilter_test {

inline bool is_finite(const cmfilter::Vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The angle between two non-zero vectors, accurate for small and large angles.
inline double angle_between(const cmfilter::Vec3& a, const cmfilter::Vec3& b)
{
    return std::atan2(cmfilter::length(cmfilter::cross(a, b)), cmfilter::dot(a, b));
}

// (f(h) - f(-h)) / 2h for f(s), a Vec3 or a double at an offset s.
template <typename F>
auto central_difference(const F& f, double h)
{
    return (f(h) - f(-h)) / (2 * h);
}

inline cmfilter::SceneCamera make_scene_camera(const cmfilter::Vec3& position, const cmfilter::Vec3& look_at,
                                               const cmfilter::Vec3& up, double fov_degrees, int width, int height)
{
    cmfilter::SceneCamera c;
    c.position = position;
    c.look_at = look_at;
    c.up = up;
    c.fov_degrees = fov_degrees;
    c.width = width;
    c.height = height;
    return c;
}

// The bundled scenes' material: the terrain map over [-0.68, 0.68] driven by
// a 6-octave gradient fBm, with a 16 x 16 table and a placeholder sigma table
// (0.1 at every LOD: for tests that do not judge gaussian's colours).
inline cmfilter::Material terrain_fbm_material()
{
    auto config = cmfilter::ColorConfig::load("");
    REQUIRE(config);
    cmfilter::ColorMapLoadOptions load;
    load.path = std::string(CMFILTER_SOURCE_DIR) + "/luts/terrain.png";
    load.vmin = -0.68;
    load.vmax = 0.68;
    auto map = cmfilter::load_color_map(load, *config);
    REQUIRE(map);
    auto spec = cmfilter::parse_noise_spec("fbm:base=gradient,octaves=6");
    REQUIRE(spec);
    auto noise = cmfilter::make_noise(*spec);
    REQUIRE(noise);
    auto sigmas = cmfilter::NoiseSigmaTable::create(-9, 0.25, std::vector<double>(45, 0.1));
    REQUIRE(sigmas);
    cmfilter::ColorLayer color;
    color.map = map->map;
    cmfilter::GaussianColorTableOptions table_options;
    table_options.values = 16;
    table_options.sigmas = 16;
    auto table = cmfilter::GaussianColorTable::bake(color.map, table_options);
    REQUIRE(table);
    color.table = std::move(*table);
    return {
        {}, std::move(color), cmfilter::NoiseDriver{cmfilter::FilteredNoise(std::move(*noise), std::move(*sigmas))}};
}

// CIEDE2000 between two renders of the same scene, over the pixels the first
// one hit.
inline cmfilter::ErrorSummary render_difference(const cmfilter::RenderedImage& a, const cmfilter::RenderedImage& b)
{
    std::vector<double> errors;
    for (std::size_t p = 0; p < a.hit.size(); ++p) {
        if (!a.hit[p]) continue;
        const cmfilter::Rgb x{a.rgb[3 * p], a.rgb[3 * p + 1], a.rgb[3 * p + 2]};
        const cmfilter::Rgb y{b.rgb[3 * p], b.rgb[3 * p + 1], b.rgb[3 * p + 2]};
        errors.push_back(cmfilter::ciede2000_linear_rgb(x, y));
    }
    return cmfilter::summarize_errors(errors);
}

// The stability check of mixture against gaussian on one scene: each
// rendered, with a reference of the given seed, mixture's pixels all finite,
// and mixture's mean CIEDE2000 from the reference no more than gaussian's
// plus 0.05 (a shared reference).
inline void check_mixture_within_gaussian(const cmfilter::Scene& scene,
                                          const std::vector<cmfilter::Material>& materials, std::uint64_t seed,
                                          double elevation)
{
    using namespace cmfilter;
    RenderOptions options;
    options.method = RenderMethod::Mixture;
    auto mixture = render(scene, materials, options);
    options.method = RenderMethod::Gaussian;
    auto gaussian = render(scene, materials, options);
    options.method = RenderMethod::Reference;
    options.seed = seed;
    auto reference = render(scene, materials, options);
    REQUIRE(mixture);
    REQUIRE(gaussian);
    REQUIRE(reference);
    for (float v : mixture->rgb) REQUIRE(std::isfinite(v));
    const ErrorSummary m = render_difference(*mixture, *reference);
    const ErrorSummary g = render_difference(*gaussian, *reference);
    MESSAGE("elevation " << elevation << ": " << m.count << " pixels on the plane; mean CIEDE2000 mixture " << m.mean
                         << ", gaussian " << g.mean);
    CHECK(m.count > 0);
    CHECK(m.mean <= g.mean + 0.05);
}

}  // namespace cmfilter_test
