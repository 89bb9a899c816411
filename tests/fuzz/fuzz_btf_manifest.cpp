// SPDX-License-Identifier: Apache-2.0
// BTF manifests (stack/btf_manifest.h): any bytes as the manifest's JSON.
#include "support/fuzz_checks.h"
#include "support/scratch_file.h"

#include "cmfilter/stack/btf_manifest.h"

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string path = fuzz::write_scratch_file("btf.json", data, size);
    (void)read_btf_manifest(path);
    return 0;
}
