// SPDX-License-Identifier: Apache-2.0
// Using libcmfilter from a renderer: load a baked table, then turn a driver's
// mean and standard deviation over a footprint into a filtered colour with one
// bilinear lookup (Heitz et al. 2013, eq. 10).
//   lookup_table TABLE.exr MEAN SIGMA
#include "cmfilter/tables/gaussian_color_table_file.h"

#include <cstdlib>
#include <iostream>

int main(int argc, char** argv)
{
    if (argc != 4) {
        std::cerr << "usage: lookup_table TABLE.exr MEAN SIGMA\n";
        return 1;
    }
    auto loaded = cmfilter::read_gaussian_color_table(argv[1]);
    if (!loaded) {
        std::cerr << "lookup_table: error: " << loaded.error().message << "\n";
        return static_cast<int>(loaded.error().kind);
    }
    cmfilter::LookupCounters counters;
    const cmfilter::Rgb c = loaded->table.lookup(std::atof(argv[2]), std::atof(argv[3]), &counters);
    std::cout << c.r << " " << c.g << " " << c.b << "\n";
    if (counters.sigma_clamped) std::cerr << "note: sigma above the table's sigma_max was clamped\n";
    return 0;
}
