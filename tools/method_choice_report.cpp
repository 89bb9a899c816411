// SPDX-License-Identifier: Apache-2.0
// --tolerance's method choice (ops/method_choice.h) on the command line: the
// LODs it measures, and how it is reported (--json, and a table in the text
// report).
#include "command.h"

#include <nlohmann/json.hpp>

#include <iomanip>
#include <ostream>
#include <string>

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

namespace {

// What both choices measured on the view report (render/view_pixels.h).
nlohmann::json view_trial_json(const ViewTrial& t)
{
    return {{"errors", t.errors},       {"mean", t.mean},   {"worst", t.worst},
            {"worst_lod", t.worst_lod}, {"meets", t.meets}, {"seconds", t.seconds}};
}

nlohmann::json view_measurement_json(const ViewMeasurement& m)
{
    return {{"tolerance", m.tolerance},
            {"pixels", m.pixels},
            {"surface_pixels", m.surface_pixels},
            {"lods", m.lods},
            {"band_pixels", m.band_pixels}};
}

// "  tolerance  mean CIEDE2000 from <reference> <= DE in every LOD band
// ... (N of its M pixels):", and per trial its worst band, mean and time.
void print_view_measurement(std::ostream& out, const ViewMeasurement& m, const std::string& reference)
{
    out << "  tolerance  mean CIEDE2000 from " << reference << " <= " << m.tolerance << " in every LOD band "
        << lod_list_text(m.lods) << " (" << m.pixels << " of its " << m.surface_pixels << " pixels):\n";
}

void print_view_trial(std::ostream& out, const ViewTrial& t, bool chosen)
{
    out << " worst " << std::setw(7) << t.worst << " (LOD " << t.worst_lod << "), mean " << std::setw(7) << t.mean
        << ", " << std::setw(7) << t.seconds << " s"
        << (chosen    ? "  <- chosen"
            : t.meets ? "  meets"
                      : "")
        << "\n";
}

}  // namespace

nlohmann::json microsurface_choice_json(const MicrosurfaceMethodChoice& choice)
{
    nlohmann::json trials = nlohmann::json::array();
    for (const MicrosurfaceTrial& t : choice.trials) {
        nlohmann::json j = view_trial_json(t);
        j["method"] = to_string(t.method);
        trials.push_back(std::move(j));
    }
    nlohmann::json j = view_measurement_json(choice);
    j["method"] = choice.choice() ? nlohmann::json(to_string(choice.choice()->method)) : nlohmann::json(nullptr);
    j["trials"] = std::move(trials);
    return j;
}

void print_microsurface_choice(std::ostream& out, const MicrosurfaceMethodChoice& choice)
{
    const auto flags = out.flags();
    const auto precision = out.precision();
    out << std::setprecision(3);
    print_view_measurement(out, choice, "exact");
    for (std::size_t i = 0; i < choice.trials.size(); ++i) {
        out << "    " << std::left << std::setw(14) << to_string(choice.trials[i].method) << std::right;
        print_view_trial(out, choice.trials[i], choice.chosen == i);
    }
    out.flags(flags);
    out.precision(precision);
}

nlohmann::json probe_choice_json(const ProbeChoice& choice)
{
    nlohmann::json trials = nlohmann::json::array();
    for (const ProbeTrial& t : choice.trials) {
        nlohmann::json j = view_trial_json(t);
        j["probes"] = t.probes;
        trials.push_back(std::move(j));
    }
    nlohmann::json j = view_measurement_json(choice);
    j["ceiling"] = choice.ceiling;
    j["probes"] = choice.choice() ? nlohmann::json(choice.choice()->probes) : nlohmann::json(nullptr);
    j["trials"] = std::move(trials);
    return j;
}

void print_probe_choice(std::ostream& out, const ProbeChoice& choice)
{
    const auto flags = out.flags();
    const auto precision = out.precision();
    out << std::setprecision(3);
    print_view_measurement(out, choice, std::to_string(choice.ceiling) + " probes");
    for (std::size_t i = 0; i < choice.trials.size(); ++i) {
        const ProbeTrial& t = choice.trials[i];
        out << "    up to " << std::setw(2) << t.probes << (t.probes == 1 ? " probe, " : " probes,");
        print_view_trial(out, t, choice.chosen == i);
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
        out << "    " << std::left << std::setw(13) << to_string(t.method) << std::right << std::setw(4)
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
