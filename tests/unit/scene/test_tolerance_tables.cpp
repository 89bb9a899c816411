// SPDX-License-Identifier: Apache-2.0
// Tables fitted to a scene (tolerance_tables.h): a surface's table covers
// exactly its driver's sigma range (the largest box sigma of its noise sigma
// table, read here from the file), meets the tolerance against the
// brute-force quadrature of eq. 10 at fresh random points, and is smaller than
// the fixed 256 x 256 default for a smooth map; the scene's colormap/tolerance
// does the same as the option, which overrides it; the small-sigma shortcut is
// on by default only for fitted tables.
#include "cmfilter/scene/tolerance_tables.h"

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/noise/noise_sigma_table_file.h"
#include "cmfilter/scene/scene_loading.h"
#include "cmfilter/scene/scene_materials.h"

#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace cmfilter;
namespace fs = std::filesystem;

namespace {

const std::string kScene = std::string(CMFILTER_SOURCE_DIR) + "/examples/scenes/plane-fbm-terrain.json";

// Each surface's table layer (material.h), as prepare_materials leaves it.
std::vector<ColorLayer> table_layers_for(const Scene& scene, const TableChoiceOptions& tables)
{
    auto config = ColorConfig::load("");
    REQUIRE(config);
    MaterialOptions options;
    options.tables = tables;
    options.threads = 2;
    auto materials = prepare_materials(scene, *config, options);
    REQUIRE(materials);
    std::vector<ColorLayer> layers;
    for (Material& m : *materials) layers.push_back(std::move(table_layer(m)));
    return layers;
}

// The q-quantile (nearest rank) of CIEDE2000 between the table's lookups and
// the reference quadrature at n fresh points, v uniform over the domain and
// sigma = sigma_max u^2, u uniform.
double independent_error(const ColorLayer& m, double q, int n)
{
    cmfilter_test::ReferenceMap ref;
    ref.vmin = m.map.vmin;
    ref.vmax = m.map.vmax;
    for (const Rgb& c : m.map.texels) ref.texels.push_back({c.r, c.g, c.b});
    std::minstd_rand rng(97);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> errors;
    for (int i = 0; i < n; ++i) {
        const double v = ref.vmin + (ref.vmax - ref.vmin) * unit(rng);
        const double u = unit(rng);
        const double sigma = m.table.axes().sigma_max * u * u;
        const cmfilter_test::Rgb3 exact = cmfilter_test::reference_convolution(ref, v, sigma);
        errors.push_back(ciede2000_linear_rgb({exact[0], exact[1], exact[2]}, m.table.lookup(v, sigma)));
    }
    std::sort(errors.begin(), errors.end());
    return errors[static_cast<std::size_t>(std::ceil(q * n - 1e-9)) - 1];
}

}  // namespace

TEST_CASE("a surface's fitted table covers its driver's sigma range and meets the tolerance independently")
{
    auto scene = load_scene(kScene);
    REQUIRE(scene);
    TableChoiceOptions tables;
    tables.tolerance = 1.0;
    const std::vector<ColorLayer> materials = table_layers_for(*scene, tables);
    REQUIRE(materials.size() == 1);
    const ColorLayer& m = materials[0];

    auto sigma_table = read_noise_sigma_table(scene->surfaces[0].material.driver.sigma_table_path, FootprintShape::Box);
    REQUIRE(sigma_table);
    const std::vector<double>& sigmas = sigma_table->table.sigmas();
    CHECK(m.table.axes().sigma_max == doctest::Approx(*std::max_element(sigmas.begin(), sigmas.end())));
    CHECK(m.fit.tolerance == 1.0);
    CHECK(m.fit.statistic == "p99.9");
    CHECK(m.fit.error <= 1.0);
    const double p99 = independent_error(m, 0.99, 3000);
    CAPTURE(p99);
    CHECK(p99 <= 1.0);
    // A smooth map needs far less than the fixed default.
    const GaussianColorTableOptions defaults;
    CHECK(m.table.data().size() < static_cast<std::size_t>(defaults.values) * defaults.sigmas * 3 / 10);
    // The shortcut is on, at a tenth of the tolerance.
    CHECK(m.fit.plain_bound == doctest::Approx(0.1));
    CHECK_FALSE(m.plain.empty());
    CHECK(m.plain.largest() > 0);
}

TEST_CASE("the scene's colormap tolerance fits as the option does, the option 0 keeps the fixed table")
{
    auto scene = load_scene(kScene);
    REQUIRE(scene);
    // Without a tolerance: the fixed default, no shortcut.
    const std::vector<ColorLayer> fixed = table_layers_for(*scene, {});
    const GaussianColorTableOptions defaults;
    CHECK(fixed[0].table.axes().values == defaults.values);
    CHECK(fixed[0].table.axes().sigmas == defaults.sigmas);
    CHECK(fixed[0].fit.tolerance == 0.0);
    CHECK(fixed[0].plain.empty());

    scene->surfaces[0].material.colormap.tolerance = 1.0;
    const std::vector<ColorLayer> from_scene = table_layers_for(*scene, {});
    TableChoiceOptions option;
    option.tolerance = 1.0;
    scene->surfaces[0].material.colormap.tolerance.reset();
    const std::vector<ColorLayer> from_option = table_layers_for(*scene, option);
    CHECK(from_scene[0].fit.tolerance == 1.0);
    CHECK(from_scene[0].table.data() == from_option[0].table.data());
    CHECK(from_scene[0].plain.cells() == from_option[0].plain.cells());

    scene->surfaces[0].material.colormap.tolerance = 1.0;
    option.tolerance = 0.0;    // overrides the scene's: the fixed table
    option.plain_bound = 0.2;  // with the shortcut asked for explicitly
    const std::vector<ColorLayer> overridden = table_layers_for(*scene, option);
    CHECK(overridden[0].table.axes().values == defaults.values);
    CHECK(overridden[0].fit.tolerance == 0.0);
    CHECK(overridden[0].fit.plain_bound == 0.2);
    CHECK_FALSE(overridden[0].plain.empty());
}

TEST_CASE("bad tolerance and shortcut values are refused, naming the option")
{
    auto scene = load_scene(kScene);
    REQUIRE(scene);
    std::vector<ColorLayer> materials = table_layers_for(*scene, {});
    TableChoiceOptions options;
    options.tolerance = -1.0;
    auto st = choose_surface_table(*scene, 0, materials[0], options);
    REQUIRE_FALSE(st);
    CHECK(st.error().message.find("TableChoiceOptions::tolerance -1 is invalid") != std::string::npos);
    options.tolerance.reset();
    options.plain_bound = std::nan("");
    st = choose_surface_table(*scene, 0, materials[0], options);
    REQUIRE_FALSE(st);
    CHECK(st.error().message.find("TableChoiceOptions::plain_bound nan is invalid") != std::string::npos);
    options.plain_bound.reset();
    st = choose_surface_table(*scene, 3, materials[0], options);
    REQUIRE_FALSE(st);
    CHECK(st.error().message.find("surface 3 does not exist") != std::string::npos);
}
