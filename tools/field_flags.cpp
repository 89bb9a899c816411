// SPDX-License-Identifier: Apache-2.0
// Library messages name options by field; the command line names them by flag.
#include "command.h"

#include <algorithm>
#include <cctype>

namespace cmfilter::cli {

namespace {

bool continues_name(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

std::string name_flags(const std::string& text, const FieldFlags& flags)
{
    std::vector<const std::pair<std::string, std::string>*> longest_first;
    for (const auto& entry : flags)
        if (!entry.first.empty()) longest_first.push_back(&entry);
    std::stable_sort(longest_first.begin(), longest_first.end(),
                     [](const auto* a, const auto* b) { return a->first.size() > b->first.size(); });
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        bool replaced = false;
        if (i == 0 || !continues_name(text[i - 1]))
            for (const auto* entry : longest_first) {
                const std::string& field = entry->first;
                const std::size_t end = i + field.size();
                if (text.compare(i, field.size(), field) == 0 && (end == text.size() || !continues_name(text[end]))) {
                    out += entry->second;
                    i = end;
                    replaced = true;
                    break;
                }
            }
        if (!replaced) out += text[i++];
    }
    return out;
}

FieldFlags color_map_flags()
{
    return {{"ColorMapLoadOptions::vmin:vmax", "--domain"},
            {"ColorMapLoadOptions::row", "--row"},
            {"ColorMapLoadOptions::column", "--column"},
            {"TableColorMapOptions::map_override", "--map"}};
}

}  // namespace cmfilter::cli
