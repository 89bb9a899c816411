// SPDX-License-Identifier: Apache-2.0
// Independent check of a table written by `cmfilter bake-colormap`: decodes
// the map image with the stated transfer formula (not OpenColorIO; "srgb" is
// the C1 sRGB curve of cmfilter's built-in config, see
// reference_convolution.h), reads the
// table and its metadata with plain OpenImageIO, places the nodes by the
// geometry documented in docs/table-format.md, and compares nodes with
// brute-force quadrature (tests/support/reference_convolution.h).
//   verify_table TABLE.exr MAP_IMAGE srgb|gamma2.2|linear [TOLERANCE]
#include "reference_convolution.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using cmfilter_test::ReferenceMap;

namespace {

double decode(const std::string& how, double e)
{
    if (how == "srgb") return cmfilter_test::srgb_moncurve_to_linear(e);
    if (how == "gamma2.2") return e <= 0 ? 0.0 : std::pow(e, 2.2);
    return e;
}

double attr(const OIIO::ImageSpec& spec, const char* name)
{
    const OIIO::ParamValue* p = spec.find_attribute(name);
    if (!p) {
        std::cerr << "verify_table: metadata " << name << " missing\n";
        std::exit(1);
    }
    return p->type() == OIIO::TypeDesc::DOUBLE ? p->get<double>() : p->get_float();
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 4) {
        std::cerr << "usage: verify_table TABLE.exr MAP_IMAGE srgb|gamma2.2|linear [TOLERANCE]\n";
        return 2;
    }
    const double tolerance = argc > 4 ? std::atof(argv[4]) : 1e-6;
    auto map_in = OIIO::ImageInput::open(argv[2]);
    auto table_in = OIIO::ImageInput::open(argv[1]);
    if (!map_in || !table_in) {
        std::cerr << "verify_table: cannot open inputs\n";
        return 1;
    }
    const OIIO::ImageSpec ms = map_in->spec();
    std::vector<float> raw(static_cast<std::size_t>(ms.width) * ms.height * ms.nchannels);
    map_in->read_image(0, 0, 0, ms.nchannels, OIIO::TypeDesc::FLOAT, raw.data());

    const OIIO::ImageSpec ts = table_in->spec();
    std::vector<float> table(static_cast<std::size_t>(ts.width) * ts.height * 3);
    table_in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, table.data());

    ReferenceMap ref;
    ref.vmin = attr(ts, "cmfilter:domain_min");
    ref.vmax = attr(ts, "cmfilter:domain_max");
    ref.wrap = ts.get_string_attribute("cmfilter:wrap");
    for (int i = 0; i < ms.width; ++i) {  // row 0 of the map image
        cmfilter_test::Rgb3 c;
        for (int ch = 0; ch < 3; ++ch)
            c[ch] = decode(argv[3], raw[static_cast<std::size_t>(i) * ms.nchannels + (ms.nchannels >= 3 ? ch : 0)]);
        ref.texels.push_back(c);
    }
    const int values = ts.width, sigmas = ts.height;
    const double margin = attr(ts, "cmfilter:margin"), sigma_max = attr(ts, "cmfilter:sigma_max");
    const bool sqrt_spacing = ts.get_string_attribute("cmfilter:sigma_spacing") == "sqrt";
    auto value_at = [&](int i) {
        if (ref.wrap == "repeat") return ref.vmin + (ref.vmax - ref.vmin) * i / values;
        const double a = ref.wrap == "clamp" ? ref.vmin - margin : ref.vmin;
        const double b = ref.wrap == "clamp" ? ref.vmax + margin : ref.vmax;
        return a + (b - a) * i / (values - 1);
    };
    auto sigma_at = [&](int j) {
        const double t = static_cast<double>(j) / (sigmas - 1);
        return sigma_max * (sqrt_spacing ? t * t : t);
    };

    double worst = 0;
    int worst_i = 0, worst_j = 0, checked = 0;
    auto check = [&](int i, int j) {
        const cmfilter_test::Rgb3 r = cmfilter_test::reference_convolution(ref, value_at(i), sigma_at(j));
        for (int ch = 0; ch < 3; ++ch) {
            const double d = std::fabs(table[(static_cast<std::size_t>(j) * values + i) * 3 + ch] - r[ch]);
            if (d > worst) worst = d, worst_i = i, worst_j = j;
        }
        ++checked;
    };
    for (int i = 0; i < values; ++i) check(i, 0), check(i, sigmas - 1);
    std::mt19937 rng(1);
    for (int k = 0; k < 3000; ++k) check(static_cast<int>(rng() % values), static_cast<int>(rng() % sigmas));
    std::cout << "verify_table: " << checked << " nodes, max |table - quadrature| = " << worst << " at value node "
              << worst_i << ", sigma node " << worst_j << " (tolerance " << tolerance << ")\n";
    return worst <= tolerance ? 0 : 1;
}
