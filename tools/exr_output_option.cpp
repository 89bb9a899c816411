// SPDX-License-Identifier: Apache-2.0
// -d, --tile and --compression: how a table or pyramid is stored, spelled as
// maketx spells them.
#include "command.h"

#include <nlohmann/json.hpp>

namespace cmfilter::cli {

void add_exr_output_options(CLI::App& app, ExrOutputArgs& args, const std::string& default_tiles)
{
    app.add_option("-d,--data-format", args.pixel_type, "Pixel type of the file: half or float (as maketx -d)")
        ->capture_default_str();
    app.add_option("--tile", args.tile, "Tiles W H (default: " + default_tiles + ")")->expected(2);
    app.add_option("--compression", args.compression,
                   "OpenEXR compression: none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab (zip:1..9, "
                   "dwaa:1..1000 for a level)")
        ->capture_default_str();
}

Expected<ExrOutputOptions> exr_output_options_from_args(const ExrOutputArgs& args)
{
    ExrOutputOptions options;
    auto type = parse_exr_pixel_type(args.pixel_type);
    if (!type) return bad_input("-d '" + args.pixel_type + "' is unknown (expected half or float)");
    options.pixel_type = *type;
    if (args.tile.size() == 2) {
        options.tile_width = args.tile[0];
        options.tile_height = args.tile[1];
        if (options.tile_width == 0 || options.tile_height == 0)
            return bad_input("--tile " + std::to_string(args.tile[0]) + " " + std::to_string(args.tile[1]) +
                             " is invalid (expected both sides in 1..4096)");
    }
    options.compression = args.compression;
    if (auto st = check_exr_output_options(options, "ExrOutputOptions"); !st) return st.error();
    return options;
}

nlohmann::json storage_json(const ExrOutputOptions& options)
{
    nlohmann::json j;
    j["pixel_type"] = to_string(options.pixel_type);
    j["compression"] = options.compression;
    j["tile"] = options.tile_width > 0 ? nlohmann::json{options.tile_width, options.tile_height} : nlohmann::json();
    j["lossy"] = exr_output_loss(options);
    return j;
}

FieldFlags exr_output_flags()
{
    return {{"ExrOutputOptions.compression", "--compression"},
            {"ExrOutputOptions.tile", "--tile"},
            {"MomentBakeOptions::storage.compression", "--compression"},
            {"MomentBakeOptions::storage.tile", "--tile"},
            {"HistogramBakeOptions::storage.compression", "--compression"},
            {"HistogramBakeOptions::storage.tile", "--tile"}};
}

}  // namespace cmfilter::cli
