// SPDX-License-Identifier: Apache-2.0
// Scenes for the synthetic stack tests: a textured displacement whose
// heights the test chooses, coloured by one constant colour (a C_h map of
// one colour), written as files in a scratch folder, and the surface loaded
// from them.
#pragma once

#include "cmfilter/synthetic/synthetic_surface.h"

#include "test_images.h"
#include "unit_test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace cmfilter_test {

// The constant colour of the test scenes' map.
inline cmfilter::Rgb synthetic_test_color() { return {0.8, 0.5, 0.25}; }

// Writes `dir`/`name`.json: one plane whose displacement is the n x n image
// of texel heights height(i, j) (column i, row j from the top), coloured
// synthetic_test_color(); returns the scene's path.
inline std::string write_displacement_scene(const std::string& dir, const std::string& name, int n,
                                            const std::function<double(int, int)>& height)
{
    std::vector<float> texels(static_cast<std::size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) texels[static_cast<std::size_t>(j) * n + i] = static_cast<float>(height(i, j));
    write_image(dir + "/" + name + "-height.exr", n, n, 1, OIIO::TypeDesc::FLOAT, texels.data());
    const cmfilter::Rgb c = synthetic_test_color();
    const float map[6] = {float(c.r), float(c.g), float(c.b), float(c.r), float(c.g), float(c.b)};
    write_image(dir + "/" + name + "-map.exr", 2, 1, 3, OIIO::TypeDesc::FLOAT, map);
    nlohmann::json scene = nlohmann::json::parse(R"({
      "camera": {"position": [0, 1, 0], "look_at": [0, 0, 4], "resolution": [8, 8]},
      "light": {"direction": [0, 1, 0]},
      "surfaces": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
         "mapping": {"type": "planar", "u_axis": [1, 0, 0], "v_axis": [0, 0, 1]},
         "material": {}}]})");
    scene["surfaces"][0]["material"] = {{"displacement", {{"image", name + "-height.exr"}, {"height_scale", 1}}},
                                        {"colormap", {{"image", name + "-map.exr"}, {"domain", {-1, 1}}}}};
    const std::string path = dir + "/" + name + ".json";
    std::ofstream(path) << scene.dump(2);
    return path;
}

inline cmfilter::SyntheticSurface load_synthetic_surface(const std::string& scene, std::size_t surface = 0)
{
    cmfilter::SyntheticSurfaceOptions o;
    o.scene = scene;
    o.surface = surface;
    o.threads = 2;
    auto s = cmfilter::SyntheticSurface::load(o, builtin_color_config());
    REQUIRE_MESSAGE(s, (s ? "" : s.error().message));
    return std::move(*s);
}

}  // namespace cmfilter_test
