// SPDX-License-Identifier: Apache-2.0
// --json: every command's summary names the command and the version of its
// schema (docs/json-schema.md, docs/cmfilter.schema.json).
#include "command.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace cmfilter::cli {

void print_json(const std::string& command, nlohmann::json summary)
{
    summary["command"] = command;
    summary["schema_version"] = kJsonSchemaVersion;
    std::cout << summary.dump(2) << "\n";
}

}  // namespace cmfilter::cli
