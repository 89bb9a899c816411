// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/recorded_path.h"

#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace cmfilter {

namespace {

fs::path absolute_normal(const fs::path& p)
{
    std::error_code ec;
    const fs::path a = fs::absolute(p, ec);
    return (ec ? p : a).lexically_normal();
}

}  // namespace

std::string path_for_record(const std::string& input, const std::string& artefact)
{
    if (input.empty()) return input;
    const fs::path in = absolute_normal(input);
    const fs::path folder = absolute_normal(artefact).parent_path();
    const fs::path relative = in.lexically_relative(folder);
    return (relative.empty() ? in : relative).generic_string();
}

std::string path_from_record(const std::string& recorded, const std::string& artefact)
{
    if (recorded.empty()) return recorded;
    const fs::path r(recorded);
    if (r.is_absolute()) return recorded;
    const fs::path folder = fs::path(artefact).parent_path();
    return (folder / r).lexically_normal().generic_string();
}

}  // namespace cmfilter
