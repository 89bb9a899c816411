// SPDX-License-Identifier: Apache-2.0
// --tolerance's method choice (ops/method_choice.h) on the command line: the
// LODs it measures, and how it is reported (--json, and a table in the text
// report).
#include "command.h"

#include <nlohmann/json.hpp>

#include <iomanip>
#include <ostream>

namespace cmfilter::cli {

nlohmann::json method_choice_json(const MethodChoice& choice)
{
    nlohmann::json trials = nlohmann::json::array();
    for (const MethodTrial& t : choice.trials)
        trials.push_back({{"method", to_string(t.method)},
                          {"bytes_per_texel", t.bytes_per_texel},
                          {"table_lookups", t.table_lookups},
                          {"errors", t.errors},
                          {"worst", t.worst},
                          {"worst_lod", t.worst_lod},
                          {"meets", t.meets},
                          {"time_ms", t.time_ms}});
    const MethodTrial* c = choice.choice();
    return {{"tolerance", choice.tolerance},
            {"lods", choice.lods},
            {"method", c ? nlohmann::json(to_string(c->method)) : nlohmann::json(nullptr)},
            {"error", c ? nlohmann::json(c->worst) : nlohmann::json(nullptr)},
            {"reference_ms", choice.reference_ms},
            {"trials", std::move(trials)},
            {"skipped", choice.skipped}};
}

void add_measure_lods_option(CLI::App& app, std::vector<double>& lods, bool noise)
{
    app.add_option("--measure-lods", lods,
                   noise
                       ? "LODs --tolerance measures each method at, comma-separated: pyramid levels for textures, "
                         "log2(width / base period) for noises (default: on each surface, the integer LODs that cover "
                         "the footprints the view's pixels reach, within its pyramid or sigma table)"
                       : "LODs --tolerance measures each method at, comma-separated (default: every integer LOD "
                         "from 1 to 8 the pyramid reaches)")
        ->delimiter(',');
}

nlohmann::json sub_footprint_choice_json(const SubFootprintChoice& choice)
{
    nlohmann::json trials = nlohmann::json::array();
    for (const SubFootprintTrial& t : choice.trials)
        trials.push_back({{"max_cells", t.max_cells},
                          {"errors", t.errors},
                          {"worst", t.worst},
                          {"worst_lod", t.worst_lod},
                          {"meets", t.meets}});
    nlohmann::json j = {{"tolerance", choice.tolerance}, {"lods", choice.lods}, {"trials", trials}};
    j["chosen"] = choice.choice() ? nlohmann::json(choice.choice()->max_cells) : nlohmann::json(nullptr);
    return j;
}

void print_sub_footprint_choice(std::ostream& out, const SubFootprintChoice& choice)
{
    const auto flags = out.flags();
    const auto precision = out.precision();
    out << std::setprecision(3) << "  tolerance  mean CIEDE2000 <= " << choice.tolerance << " at LOD "
        << lod_list_text(choice.lods) << ":\n";
    for (std::size_t i = 0; i < choice.trials.size(); ++i) {
        const SubFootprintTrial& t = choice.trials[i];
        out << "    up to " << std::setw(2) << t.max_cells << " x " << std::left << std::setw(2) << t.max_cells
            << std::right << " squares, worst " << std::setw(7) << t.worst << " (LOD " << t.worst_lod << ")"
            << (choice.chosen == i ? "  <- chosen"
                : t.meets          ? "  meets"
                                   : "")
            << "\n";
    }
    out.flags(flags);
    out.precision(precision);
}

nlohmann::json microsurface_choice_json(const MicrosurfaceMethodChoice& choice)
{
    nlohmann::json trials = nlohmann::json::array();
    for (const MicrosurfaceTrial& t : choice.trials)
        trials.push_back({{"method", to_string(t.method)},
                          {"errors", t.errors},
                          {"mean", t.mean},
                          {"worst", t.worst},
                          {"worst_lod", t.worst_lod},
                          {"meets", t.meets},
                          {"seconds", t.seconds}});
    const MicrosurfaceTrial* c = choice.choice();
    return {{"tolerance", choice.tolerance},
            {"pixels", choice.pixels},
            {"surface_pixels", choice.surface_pixels},
            {"lods", choice.lods},
            {"band_pixels", choice.band_pixels},
            {"method", c ? nlohmann::json(to_string(c->method)) : nlohmann::json(nullptr)},
            {"trials", std::move(trials)}};
}

void print_microsurface_choice(std::ostream& out, const MicrosurfaceMethodChoice& choice)
{
    const auto flags = out.flags();
    const auto precision = out.precision();
    out << std::setprecision(3) << "  tolerance  mean CIEDE2000 from exact <= " << choice.tolerance
        << " in every LOD band " << lod_list_text(choice.lods) << " (" << choice.pixels << " of its "
        << choice.surface_pixels << " pixels):\n";
    for (std::size_t i = 0; i < choice.trials.size(); ++i) {
        const MicrosurfaceTrial& t = choice.trials[i];
        out << "    " << std::left << std::setw(14) << to_string(t.method) << std::right << " worst " << std::setw(7)
            << t.worst << " (LOD " << t.worst_lod << "), mean " << std::setw(7) << t.mean << ", " << std::setw(7)
            << t.seconds << " s"
            << (choice.chosen == i ? "  <- chosen"
                : t.meets          ? "  meets"
                                   : "")
            << "\n";
    }
    out.flags(flags);
    out.precision(precision);
}

void print_method_choice(std::ostream& out, const MethodChoice& choice)
{
    const auto flags = out.flags();
    const auto precision = out.precision();
    out << std::setprecision(3) << "  tolerance  mean CIEDE2000 <= " << choice.tolerance << " at LOD "
        << lod_list_text(choice.lods) << ":\n";
    for (std::size_t i = 0; i < choice.trials.size(); ++i) {
        const MethodTrial& t = choice.trials[i];
        out << "    " << std::left << std::setw(9) << to_string(t.method) << std::right << std::setw(4)
            << t.bytes_per_texel << " B/texel, worst " << std::setw(7) << t.worst << " (LOD " << t.worst_lod << "), "
            << std::setw(7) << t.time_ms << " ms"
            << (choice.chosen == i ? "  <- chosen"
                : t.meets          ? "  meets"
                                   : "")
            << "\n";
    }
    for (const std::string& why : choice.skipped) out << "    not tried: " << why << "\n";
    out.flags(flags);
    out.precision(precision);
}

}  // namespace cmfilter::cli
