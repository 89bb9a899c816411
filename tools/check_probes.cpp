// SPDX-License-Identifier: Apache-2.0
// --probes, for the commands that render.
#include "command.h"

namespace cmfilter::cli {

Status check_probes(int probes)
{
    if (probes < 1 || probes > 64)
        return bad_input("--probes " + std::to_string(probes) + " is out of range (expected 1 to 64)");
    return ok();
}

}  // namespace cmfilter::cli
