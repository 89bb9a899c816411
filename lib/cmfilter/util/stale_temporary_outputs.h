// SPDX-License-Identifier: Apache-2.0
// Removing the temporaries (temporary_output_name.h) that writers killed
// before they finished left beside a destination. One is stale when
//   - its host is this host and its process is gone (kill(pid, 0) fails
//     with ESRCH), or
//   - its host is another (a disk shared between hosts, where the process
//     cannot be asked) and it was last modified more than max_age ago.
// A temporary of a process that is alive on this host is never removed, nor
// is any file whose name does not follow the pattern for this destination.
#pragma once

#include "cmfilter/util/error.h"

#include <chrono>
#include <string>
#include <vector>

namespace cmfilter {

struct StaleTemporaryOptions {
    std::string destination;         // the output path whose temporaries are looked for
    std::chrono::hours max_age{24};  // for other hosts' temporaries
};

// Whether process `pid` exists on this host (kill(pid, 0) does not fail with
// ESRCH; a process of another user counts as alive).
bool process_is_alive(long pid);

// Removes the destination's stale temporaries from its directory (a folder
// of that name too, with what it holds) and returns the paths removed. Fails
// (Io) only when the directory cannot be listed; a temporary that cannot be
// removed is left and not returned.
Expected<std::vector<std::string>> remove_stale_temporary_outputs(const StaleTemporaryOptions& options);

}  // namespace cmfilter
