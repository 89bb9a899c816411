// SPDX-License-Identifier: Apache-2.0
// A stack named on the command line: a light file (.lp), or a BTF manifest
// (.json) and one of its view slots.
#include "command.h"

#include "cmfilter/stack/btf_manifest.h"
#include "cmfilter/util/atomic_output.h"

namespace cmfilter::cli {

Expected<StackSlot> resolve_stack_slot(const std::string& path, const std::optional<int>& slot)
{
    StackSlot out;
    if (lowercase_extension(path) != ".json") {
        if (slot)
            return bad_input("--slot " + std::to_string(*slot) + " picks a view slot of a BTF manifest, but '" + path +
                             "' is a light file (expected a .json manifest, or no --slot)");
        out.light_file = path;
        return out;
    }
    auto manifest = read_btf_manifest(path);
    if (!manifest) return manifest.error();
    const int k = slot.value_or(0);
    const int count = static_cast<int>(manifest->views.size());
    if (k < 0 || k >= count)
        return bad_input("--slot " + std::to_string(k) + " is out of range: '" + path + "' has " +
                         std::to_string(count) + " view slot" + (count == 1 ? "" : "s") + " (expected 0 to " +
                         std::to_string(count - 1) + ")");
    out.light_file = manifest->light_file_path(static_cast<std::size_t>(k));
    out.view = manifest->views[static_cast<std::size_t>(k)].view;
    out.slot = k;
    return out;
}

}  // namespace cmfilter::cli
