// The shape every cmfilter subcommand takes: a setup function registers the
// subcommand's options on the CLI11 app and returns the action to run once
// parsing succeeded. Actions call the library and report; they return a
// Status whose error main() prints once, as "cmfilter <cmd>: error: ...",
// and maps to the exit code of its kind (docs/exit-codes.md).
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/util/error.h"

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace cmfilter::cli {

struct Command {
    CLI::App* app = nullptr;
    std::function<Status()> run;
};

Command setup_apply(CLI::App& parent);
Command setup_bake_colormap(CLI::App& parent);
Command setup_bake_moments(CLI::App& parent);
Command setup_compare(CLI::App& parent);
Command setup_info(CLI::App& parent);
Command setup_noise_image(CLI::App& parent);
Command setup_bake_noise(CLI::App& parent);
Command setup_render(CLI::App& parent);
Command setup_bench(CLI::App& parent);

// Splits "a:b" into two numbers; names the option and the text on failure.
Expected<std::pair<double, double>> parse_range(const std::string& option, const std::string& text);

// Splits "WxH" into two integers in 1..65536; names the option and the text on failure.
Expected<std::pair<int, int>> parse_size(const std::string& option, const std::string& text);

// A progress callback printing "\r<command>: N%" on stderr when the percent
// changes (a newline at 100%); callers use it only when stderr is a terminal.
std::function<void(double)> terminal_progress(const std::string& command);

// The OpenColorIO config named by --ocio-config (empty: $OCIO if set, else
// the built-in config).
Expected<ColorConfig> load_color_config(const std::string& ocio_config_option);

}  // namespace cmfilter::cli
