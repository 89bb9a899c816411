// SPDX-License-Identifier: Apache-2.0
// cmfilter normals (to be written).
#include "command.h"

namespace cmfilter::cli {

Command setup_normals(CLI::App& parent)
{
    Command c;
    c.app = parent.add_subcommand("normals", "(not yet available)");
    c.run = [] { return Status(runtime_error("normals is not yet available")); };
    return c;
}

}  // namespace cmfilter::cli
