// SPDX-License-Identifier: Apache-2.0
// cmfilter fit (to be written).
#include "command.h"

namespace cmfilter::cli {

Command setup_fit(CLI::App& parent)
{
    Command c;
    c.app = parent.add_subcommand("fit", "(not yet available)");
    c.run = [] { return Status(runtime_error("fit is not yet available")); };
    return c;
}

}  // namespace cmfilter::cli
