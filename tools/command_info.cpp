// SPDX-License-Identifier: Apache-2.0
// cmfilter info: what a cmfilter artefact is and every parameter it was baked with.
#include "command.h"

#include "cmfilter/ops/artefact_info.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace cmfilter::cli {

namespace {

struct InfoArgs {
    std::string path;
    bool json = false;
};

Status run(const InfoArgs& args)
{
    auto info = read_artefact_info(args.path);
    if (!info) return info.error();
    if (args.json) {
        nlohmann::json j;
        j["path"] = info->path;
        j["kind"] = info->kind;
        j["description"] = info->description;
        j["format"] = info->format;
        j["size"] = {info->width, info->height};
        j["channels"] = info->channels;
        // Numbers as numbers, as the file types them; text as text.
        j["parameters"] = nlohmann::json::object();
        for (const auto& [key, value] : info->parameters) {
            const bool number = std::find(info->numeric.begin(), info->numeric.end(), key) != info->numeric.end();
            nlohmann::json typed = value;
            if (number) typed = nlohmann::json::parse(value, nullptr, false);
            j["parameters"][key] = typed.is_discarded() ? nlohmann::json(value) : typed;
        }
        print_json("info", std::move(j));
        return ok();
    }
    std::cout << info->path << ": " << info->kind << "\n  " << info->description << "\n  " << info->format << ", "
              << info->width << " x " << info->height << ", " << info->channels << " channels\n";
    std::size_t width = 0;
    for (const auto& kv : info->parameters) width = std::max(width, kv.first.size());
    for (const auto& [key, value] : info->parameters)
        std::cout << "  " << key << std::string(width - key.size() + 2, ' ') << value << "\n";
    return ok();
}

}  // namespace

Command setup_info(CLI::App& parent)
{
    auto args = std::make_shared<InfoArgs>();
    CLI::App* app =
        parent.add_subcommand("info", "Print what a cmfilter artefact is and every parameter it was baked with");
    app->add_option("FILE", args->path, "A file written by cmfilter")->required();
    app->add_flag("--json", args->json, "Print the same as JSON");
    return {app, [args] { return run(*args); }, {}};
}

}  // namespace cmfilter::cli
