// SPDX-License-Identifier: Apache-2.0
// The stack records make-stack writes beside a synthetic stack and reads
// back (synthetic/stack_record.h): any bytes as the record's JSON.
#include "support/fuzz_checks.h"
#include "support/scratch_file.h"

#include "cmfilter/synthetic/stack_record.h"

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string path = fuzz::write_scratch_file("stack.json", data, size);
    (void)read_stack_record(path);
    return 0;
}
