// SPDX-License-Identifier: Apache-2.0
// libFuzzer's start-up hook, the same for every harness (compiled into each,
// CMakeLists.txt): the in-memory image format registered and the memory
// cap set before the first input.
#include "fuzz_checks.h"
#include "fuzz_image.h"

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    cmfilter::fuzz::register_fuzz_image_format();
    cmfilter::fuzz::limit_memory_for_fuzzing();
    return 0;
}
