// SPDX-License-Identifier: Apache-2.0
// A plugin linking libcmfilter: one exported C function that loads a baked
// table and looks up the filtered colour at (mean, sigma).
#include "cmfilter/tables/gaussian_color_table_file.h"

extern "C" __attribute__((visibility("default"))) int cmfilter_plugin_lookup(const char* table_path, double mean,
                                                                             double sigma, float rgb[3])
{
    auto loaded = cmfilter::read_gaussian_color_table(table_path);
    if (!loaded) return 1;
    const cmfilter::Rgb c = loaded->table.lookup(mean, sigma, nullptr);
    rgb[0] = c.r;
    rgb[1] = c.g;
    rgb[2] = c.b;
    return 0;
}
