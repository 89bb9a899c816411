// SPDX-License-Identifier: Apache-2.0
// -u/--update, as maketx spells it: the build record a command's outputs
// carry (io/build_record.h), and the check that skips a build they already
// record.
#include "command.h"

#include "cmfilter/io/build_record.h"
#include "cmfilter/util/sha256.h"
#include "cmfilter/util/version.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <system_error>

namespace cmfilter::cli {

void add_update_option(CLI::App& app, bool& update)
{
    app.add_flag("-u,--update", update,
                 "Do nothing when the outputs record this build: the same inputs (by content), parameters and "
                 "cmfilter version (as maketx -u)");
}

Expected<std::string> build_digest(const CLI::App& app, const std::vector<std::string>& not_parameters,
                                   const std::string& color_config)
{
    // What does not change the output: where it goes, what is printed, the
    // thread count (outputs are the same for any), and -u itself.
    std::vector<std::string> skip = {"--output",  "--update", "--quiet",      "--json",
                                     "--threads", "--help",   "--ocio-config"};
    skip.insert(skip.end(), not_parameters.begin(), not_parameters.end());
    std::vector<std::string> lines;
    for (const CLI::Option* option : app.get_options()) {
        const std::string name = option->get_name();
        if (option->count() == 0 || std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
        std::string line = "option " + name;
        for (const std::string& value : option->results()) {
            std::error_code ec;
            // A file is its content: the same input anywhere is the same build.
            if (std::filesystem::is_regular_file(value, ec)) {
                auto hash = sha256_file_hex(value);
                if (!hash) return hash.error();
                line += "\x1f"
                        "file:" +
                        *hash;
            } else {
                line += "\x1f" + value;
            }
        }
        lines.push_back(line);
    }
    std::sort(lines.begin(), lines.end());
    std::string record = "cmfilter build record 1\ncommand " + app.get_name() + "\nversion " + version() + "\n";
    if (!color_config.empty()) {
        std::string config = "built-in";
        std::error_code ec;
        if (std::filesystem::is_regular_file(color_config, ec)) {
            auto hash = sha256_file_hex(color_config);
            if (!hash) return hash.error();
            config = "file:" + *hash;
        }
        record += "colour config " + config + "\n";
    }
    for (const std::string& line : lines) record += line + "\n";
    return sha256_hex(record.data(), record.size());
}

void report_up_to_date(const std::string& command, const std::vector<std::string>& outputs, const std::string& digest,
                       bool json, bool quiet)
{
    if (json) {
        nlohmann::json j;
        j["output"] = outputs.front();
        j["up_to_date"] = true;
        j["build"] = digest;
        print_json(command, std::move(j));
    } else if (!quiet) {
        for (const std::string& path : outputs)
            std::cout << "up to date: " << path << " (it records this build: the same inputs, parameters and cmfilter "
                      << version() << ")\n";
    }
}

bool outputs_record_build(const std::vector<std::string>& outputs, const std::string& digest)
{
    for (const std::string& path : outputs)
        if (recorded_build(path) != digest) return false;
    return !outputs.empty();
}

}  // namespace cmfilter::cli
