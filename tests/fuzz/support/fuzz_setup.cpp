// SPDX-License-Identifier: Apache-2.0
#include "fuzz_checks.h"

#include <OpenImageIO/imageio.h>

#include <cstdlib>

namespace cmfilter::fuzz {

void limit_memory_for_fuzzing()
{
    setenv("CMFILTER_MEMORY_LIMIT", "16M", 1);
    // One thread: libFuzzer runs one input at a time, and OpenImageIO's pool
    // would only add threads to every input.
    OIIO::attribute("threads", 1);
    OIIO::attribute("exr_threads", 1);
}

}  // namespace cmfilter::fuzz
