// SPDX-License-Identifier: Apache-2.0
// Colour tables (tables/gaussian_color_table_file.h) from arbitrary headers:
// read_gaussian_color_table and `cmfilter info`'s reader.
#include "support/fuzz_checks.h"
#include "support/scratch_file.h"

#include "cmfilter/ops/artefact_info.h"
#include "cmfilter/tables/gaussian_color_table_file.h"

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string path = fuzz::write_scratch_file("table.cmfuzz", data, size);
    if (auto table = read_gaussian_color_table(path)) {
        fuzz::require_finite(table->table.data(), "a colour table read back holds only finite values");
        fuzz::require(table->table.axes().values >= 2 && table->table.axes().sigmas >= 2, "table axes of 2 or more");
    }
    (void)read_artefact_info(path);
    return 0;
}
