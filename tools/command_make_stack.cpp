// SPDX-License-Identifier: Apache-2.0
// cmfilter make-stack (to be written).
#include "command.h"

namespace cmfilter::cli {

Command setup_make_stack(CLI::App& parent)
{
    Command c;
    c.app = parent.add_subcommand("make-stack", "(not yet available)");
    c.run = [] { return Status(runtime_error("make-stack is not yet available")); };
    return c;
}

}  // namespace cmfilter::cli
