// SPDX-License-Identifier: Apache-2.0
// cmfilter relight (to be written).
#include "command.h"

namespace cmfilter::cli {

Command setup_relight(CLI::App& parent)
{
    Command c;
    c.app = parent.add_subcommand("relight", "(not yet available)");
    c.run = [] { return Status(runtime_error("relight is not yet available")); };
    return c;
}

}  // namespace cmfilter::cli
