// SPDX-License-Identifier: Apache-2.0
// The shape every cmfilter subcommand takes: a setup function registers the
// subcommand's options on the CLI11 app and returns the action to run once
// parsing succeeded. Actions call the library and report; they return a
// Status whose error main() prints once, as "cmfilter <cmd>: error: ...",
// and maps to the exit code of its kind (docs/exit-codes.md). The library
// names an option by its options struct's field ("ApplyOptions::lod"); each
// command lists the flags it gives those fields, and main() writes the flag
// where the message names the field.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/io/exr_output_options.h"
#include "cmfilter/io/rgb_image_file.h"
#include "cmfilter/math/vec3.h"
#include "cmfilter/ops/method_choice.h"
#include "cmfilter/ops/sub_footprint_choice.h"
#include "cmfilter/render/pixel_region.h"
#include "cmfilter/render/microsurface_method_choice.h"
#include "cmfilter/render/render_options.h"
#include "cmfilter/render/surface_probe_choice.h"
#include "cmfilter/render/surface_lods.h"
#include "cmfilter/scene/material.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/synthesis/sample_analysis.h"
#include "cmfilter/util/error.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cmfilter::cli {

// Qualified options fields ("ApplyOptions::lod") and how the command line
// names each: its flag ("--driver"; a message that asks for a value names its
// placeholder after the field: "pass ApplyOptions::driver_path PATH").
using FieldFlags = std::vector<std::pair<std::string, std::string>>;

// `text` (a library error or warning) with every field of `flags` it names
// written as its flag. A field is replaced only as a whole name (not followed
// by a letter, a digit or '_'), the longest first.
std::string name_flags(const std::string& text, const FieldFlags& flags);

// The fields of colour-map loading (ColorMapLoadOptions, TableColorMapOptions)
// as bake-colormap and apply name them; every command that loads a colour map
// (from an image, a table or a scene) names them so.
FieldFlags color_map_flags();

struct Command {
    CLI::App* app = nullptr;
    std::function<Status()> run;
    FieldFlags flags;  // the fields its errors may name
    // The exit code of a run that succeeded: 0, unless a command's own gate
    // says otherwise (compare --warn / --fail: docs/exit-codes.md).
    std::function<int()> success_code{};
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
Command setup_make_stack(CLI::App& parent);
Command setup_fit(CLI::App& parent);
Command setup_relight(CLI::App& parent);
Command setup_normals(CLI::App& parent);
Command setup_synth_analyse(CLI::App& parent);
Command setup_synth(CLI::App& parent);
Command setup_synth_apply(CLI::App& parent);

// Splits "a:b" into two numbers; names the option and the text on failure.
Expected<std::pair<double, double>> parse_range(const std::string& option, const std::string& text);

// Splits "WxH" into two integers in 1..65536; names the option and the text on failure.
Expected<std::pair<int, int>> parse_size(const std::string& option, const std::string& text);

// parse_size within a scene's limits (kMaxImageSide a side, kMaxImagePixels
// in all): render --size and bench --size, which replace a scene's resolution.
Expected<std::pair<int, int>> parse_image_size(const std::string& option, const std::string& text);

// "x0,y0,x1,y1": four integers >= 0 (render --region, bench --region);
// BadInput naming the option and the text otherwise. Whether the region
// lies in a frame is check_pixel_region's to say.
Expected<PixelRegion> parse_region(const std::string& option, const std::string& text);

// "x,y,z": a direction, normalised; BadInput naming the option unless three
// finite numbers, nonzero, with z >= 0 (at or above the horizon).
Expected<Vec3> parse_direction(const std::string& option, const std::string& text);
// A stack as fit and relight --reference name it: a light file (.lp), or
// a BTF manifest (.json) and its view slot `slot` (default 0), which gives
// the light file and the view. BadInput: --slot with a light file, a slot
// out of range; the manifest's own errors.
struct StackSlot {
    std::string light_file;
    std::optional<Vec3> view;  // the manifest slot's view direction
    std::optional<int> slot;   // the manifest slot read
};
Expected<StackSlot> resolve_stack_slot(const std::string& path, const std::optional<int>& slot);

// The options of a sample's analysis (synth-analyse, and synth when it
// makes the analysis itself): SampleOptions and AnalysisOptions.
struct SampleAnalysisArgs {
    int levels = 1;
    int textons = 0;
    int candidates = 10;
    int neighbourhood = 2;
    int select_images = 0;
    bool periodic = false;
    std::uint64_t seed = 1;
    std::string colorspace;
};
// Registers --levels, --textons, --candidates, --neighbourhood, --select,
// --periodic, --seed and --colorspace; the flags are those fields' names.
void add_sample_analysis_options(CLI::App& app, SampleAnalysisArgs& args);
FieldFlags sample_analysis_flags();
// The flags among add_sample_analysis_options' given on the command line.
std::vector<std::string> given_sample_analysis_options(const CLI::App& app);
// The sample at `path` read and analysed with those options.
Expected<SampleAnalysis> analyse_sample_from_args(const std::string& path, const SampleAnalysisArgs& args,
                                                  const ColorConfig& config, int threads);

// `values` (width * height * channels, scene-linear in `linear_space`)
// written with write_rgb_image; PNG/JPEG get grey RGB from one channel and
// lose a fourth; non-finite values are written as 0.
Status write_output_image(const std::string& path, int width, int height, int channels, std::vector<float> values,
                          const std::string& linear_space, const ImageAttributes& attributes,
                          const ColorConfig& config);

// -d half|float, --tile W H, --compression NAME: the storage of a table or
// pyramid (io/exr_output_options.h), spelled as maketx spells them.
struct ExrOutputArgs {
    std::string pixel_type = "float";
    std::vector<int> tile;  // empty, or W H
    std::string compression = "zip";
};
// `default_tiles` says what no --tile means ("scanlines", "64 64").
void add_exr_output_options(CLI::App& app, ExrOutputArgs& args, const std::string& default_tiles);
Expected<ExrOutputOptions> exr_output_options_from_args(const ExrOutputArgs& args);
FieldFlags exr_output_flags();
// {"pixel_type", "compression", "tile": [W, H] or null, "lossy": words or ""}.
nlohmann::json storage_json(const ExrOutputOptions& options);

// -u/--update (update_option.cpp). A command's build digest: SHA-256 over
// its name, cmfilter's version, the colour config's content (a path, or
// empty when the command uses none; "built-in" when the path is not a file)
// and every option given on the command line, each value that names a file
// replaced by the file's SHA-256; options that do not change the output
// (--output, --json, -q, --threads, -u, and `not_parameters`) left out.
void add_update_option(CLI::App& app, bool& update);
Expected<std::string> build_digest(const CLI::App& app, const std::vector<std::string>& not_parameters,
                                   const std::string& color_config);
// Whether every one of `outputs` records `digest` (io/build_record.h).
bool outputs_record_build(const std::vector<std::string>& outputs, const std::string& digest);
// What a command skipped for -u says: a line an output on stdout, or with
// `json` the summary {"output", "up_to_date": true, "build"}.
void report_up_to_date(const std::string& command, const std::vector<std::string>& outputs, const std::string& digest,
                       bool json, bool quiet);
// The colour config a command uses, for build_digest: --colorconfig, else
// $OCIO, else "built-in".
std::string color_config_for_record(const std::string& ocio_config_option);

// --json: prints `summary` on stdout with "command" and "schema_version"
// added (docs/json-schema.md; the schema file is docs/cmfilter.schema.json).
constexpr int kJsonSchemaVersion = 1;
void print_json(const std::string& command, nlohmann::json summary);

// --tolerance's choice (ops/method_choice.h), for apply and bake-moments:
// {"tolerance", "lods", "method" (null when none met), "error",
// "reference_ms", "trials": [{"method", "bytes_per_texel", "table_lookups",
// "errors", "worst", "worst_lod", "meets", "time_ms"}], "skipped"}; and as
// a table of lines for the text report.
nlohmann::json method_choice_json(const MethodChoice& choice);
// --measure-lods L,L,...: the LODs a --tolerance choice measures
// (MethodChoiceOptions::lods).
// noise: render's, where the LODs are also a noise's.
void add_measure_lods_option(CLI::App& app, std::vector<double>& lods, bool noise = false);
void print_method_choice(std::ostream& out, const MethodChoice& choice);

// render --method auto (render_method_choice.cpp): each texture surface's
// cheapest method for the tolerance, measured on its driver and table as
// apply --tolerance measures (temporary files), at options.lods; without
// them, at the integer levels that cover the view's footprints on the
// surface (`view`, by surface: survey_surface_lods), within its pyramid, a
// surface no pixel sees not measured; with neither, levels 1 to 8. BadInput
// naming the surface when none meets it. Surfaces of other drivers are left
// out.
struct SurfaceMethodChoice {
    std::size_t surface = 0;
    MethodChoice choice;
    // The segment pyramid measured (the scene's driver/segments, or baked for
    // the tolerance into segments_file); empty when none was.
    std::string segments_path;
    std::shared_ptr<const TemporaryFile> segments_file;
};
Expected<std::vector<SurfaceMethodChoice>>
choose_texture_methods(const Scene& scene, const std::vector<Material>& materials, const ColorConfig& config,
                       const MethodChoiceOptions& options, const std::vector<SurfaceLodRange>* view, int threads);
RenderMethod render_method_of(FilterMethod method);

// render --method auto (render_method_choice.cpp): each noise surface's
// fewest sub-footprints for the tolerance (ops/sub_footprint_choice.h:
// measured on its noise, colour map and table against supersampling, at
// `lods` (log2 of the width over the base period); without `lods`, at the
// integer LODs that cover the view's footprints on the surface (`view`, by
// surface: survey_surface_lods), a surface no pixel sees not measured; with
// neither, every integer LOD of its sigma table); BadInput naming the
// surface when none meets it.
struct SurfaceSubFootprintChoice {
    std::size_t surface = 0;
    SubFootprintChoice choice;
};
Expected<std::vector<SurfaceSubFootprintChoice>>
choose_noise_sub_footprints(const Scene& scene, const std::vector<Material>& materials, double tolerance,
                            const std::vector<double>& lods, const std::vector<SurfaceLodRange>* view, int threads);
nlohmann::json sub_footprint_choice_json(const SubFootprintChoice& choice);
void print_sub_footprint_choice(std::ostream& out, const SubFootprintChoice& choice);

// render --method auto: each microsurface surface's choice
// (render/microsurface_method_choice.h): {"tolerance", "pixels",
// "surface_pixels", "lods", "band_pixels", "method" (null when none met),
// "trials": [{"method", "errors", "mean", "worst", "worst_lod", "meets",
// "seconds"}]}; and as a table of lines for the text report.
nlohmann::json microsurface_choice_json(const MicrosurfaceMethodChoice& choice);
void print_microsurface_choice(std::ostream& out, const MicrosurfaceMethodChoice& choice);
// render --method auto: each surface's probe choice
// (render/surface_probe_choice.h): {"tolerance", "ceiling", "pixels",
// "surface_pixels", "lods", "band_pixels", "probes" (null when none met),
// "trials": [{"probes", "errors", "mean", "worst", "worst_lod", "meets",
// "seconds"}]}; and as a table of lines for the text report.
nlohmann::json probe_choice_json(const ProbeChoice& choice);
void print_probe_choice(std::ostream& out, const ProbeChoice& choice);

// A progress callback printing "\r<command>: N%" on stderr when the percent
// changes (a newline at 100%); callers use it only when stderr is a terminal.
std::function<void(double)> terminal_progress(const std::string& command);

// The OpenColorIO config named by --ocio-config (empty: $OCIO if set, else
// the built-in config).
Expected<ColorConfig> load_color_config(const std::string& ocio_config_option);

}  // namespace cmfilter::cli
