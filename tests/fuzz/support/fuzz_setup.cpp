// SPDX-License-Identifier: Apache-2.0
#include "fuzz_checks.h"

#include <OpenImageIO/imageio.h>

#include <cstdlib>

namespace cmfilter::fuzz {

void limit_memory_for_fuzzing()
{
    // 16 MB unless CMFILTER_FUZZ_MEMORY_LIMIT says otherwise: the long run
    // (long_run.sh) lowers it, so that images, which cost time in proportion
    // to their size, stay small enough to reach its number of inputs.
    const char* limit = std::getenv("CMFILTER_FUZZ_MEMORY_LIMIT");
    setenv("CMFILTER_MEMORY_LIMIT", limit != nullptr && *limit != '\0' ? limit : "16M", 1);
    // One thread: libFuzzer runs one input at a time, and OpenImageIO's pool
    // would only add threads to every input.
    OIIO::attribute("threads", 1);
    OIIO::attribute("exr_threads", 1);
}

}  // namespace cmfilter::fuzz
