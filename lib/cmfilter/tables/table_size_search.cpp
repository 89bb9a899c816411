// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/tables/table_size_search.h"

#include "cmfilter/tables/table_lookup_error.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

namespace cmfilter {

namespace {

using Key = std::tuple<int, int, int>;  // spacing, values, sigmas

Key key_of(const TableSize& size) { return {static_cast<int>(size.spacing), size.values, size.sigmas}; }

std::string describe(const TableSize& size)
{
    return std::to_string(size.values) + " x " + std::to_string(size.sigmas) + " " + to_string(size.spacing);
}

Status check_counts(const std::vector<int>& counts, const char* name)
{
    if (counts.empty()) return bad_input(std::string(name) + " is empty (expected at least one count)");
    for (std::size_t i = 0; i < counts.size(); ++i) {
        if (counts[i] < 2)
            return bad_input(std::string(name) + " holds " + std::to_string(counts[i]) + " (expected counts >= 2)");
        if (i > 0 && counts[i] <= counts[i - 1])
            return bad_input(std::string(name) + " is not strictly ascending at " + std::to_string(counts[i]));
    }
    return ok();
}

Status check_options(const TableSizeSearchOptions& o)
{
    if (!std::isfinite(o.tolerance) || o.tolerance <= 0) {
        std::ostringstream msg;
        msg << "TableSizeSearchOptions::tolerance " << o.tolerance
            << " is invalid (expected a CIEDE2000 difference > 0)";
        return bad_input(msg.str(), "TableSizeSearchOptions::tolerance");
    }
    if (!(o.quantile > 0 && o.quantile <= 1)) {
        std::ostringstream msg;
        msg << "tolerance quantile " << o.quantile << " is invalid (expected 0 < q <= 1; 1 is the maximum)";
        return bad_input(msg.str(), "TableSizeSearchOptions::quantile");
    }
    if (auto st = check_counts(o.value_counts, "the list of value counts"); !st) return st;
    if (auto st = check_counts(o.sigma_counts, "the list of sigma counts"); !st) return st;
    if (o.spacings.empty()) return bad_input("the list of sigma spacings is empty");
    if (o.search_samples < 1 || o.verify_samples < 1)
        return bad_input("the search and verification sample counts must be >= 1 (got " +
                         std::to_string(o.search_samples) + " and " + std::to_string(o.verify_samples) + ")");
    return ok();
}

// Everything one search holds: the map, the points, and what it measured.
class Search {
public:
    Search(const ColorMap& map, const TableSizeSearchOptions& options, double sigma_max)
        : map_(map), options_(options), sigma_max_(sigma_max)
    {
        LookupErrorOptions draw;
        draw.samples = options.search_samples;
        draw.seed = options.seed;
        draw.threads = options.threads;
        points_ = draw_lookup_error_points(map, sigma_max, draw);
    }

    Expected<GaussianColorTable> bake(const TableSize& size) const
    {
        GaussianColorTableOptions table;
        table.values = size.values;
        table.sigmas = size.sigmas;
        table.sigma_max = sigma_max_;
        table.margin = options_.margin;
        table.spacing = size.spacing;
        table.threads = options_.threads;
        return GaussianColorTable::bake(map_, table);
    }

    double statistic(const GaussianColorTable& table, const LookupErrorPoints& points) const
    {
        return nearest_rank_quantile(lookup_errors(table, points, options_.threads), options_.quantile);
    }

    // Whether the candidate meets the tolerance at the search points and was
    // not excluded by verification; measures it the first time.
    Expected<bool> passes(const TableSize& size)
    {
        if (rejected_.count(key_of(size))) return false;
        auto found = measured_.find(key_of(size));
        if (found == measured_.end()) {
            auto table = bake(size);
            if (!table) return table.error();
            const double error = statistic(*table, points_);
            found = measured_.emplace(key_of(size), trials_.size()).first;
            trials_.push_back({size, error, false, 0.0});
        }
        return trials_[found->second].error <= options_.tolerance;
    }

    // The staircase of one spacing: the smallest passing size it finds that
    // is no larger than `best` (ties: the lower search error).
    Status walk(SigmaSpacing spacing, std::optional<TableSize>& best)
    {
        const std::vector<int>& values = options_.value_counts;
        int idx = static_cast<int>(values.size()) - 1;
        for (int sigmas : options_.sigma_counts) {
            const auto size_at = [&](int i) { return TableSize{values[i], sigmas, spacing}; };
            while (idx >= 0 && best && size_at(idx).bytes() > best->bytes()) --idx;
            if (idx < 0) break;
            auto pass = passes(size_at(idx));
            if (!pass) return pass.error();
            if (!*pass) continue;
            while (idx > 0) {
                auto smaller = passes(size_at(idx - 1));
                if (!smaller) return smaller.error();
                if (!*smaller) break;
                --idx;
            }
            consider(size_at(idx), best);
        }
        return ok();
    }

    double error_of(const TableSize& size) const { return trials_[measured_.at(key_of(size))].error; }

    // Makes `candidate` (measured, passing) the best if it has fewer bytes,
    // or as many and a lower error.
    void consider(const TableSize& candidate, std::optional<TableSize>& best) const
    {
        if (!best || candidate.bytes() < best->bytes() ||
            (candidate.bytes() == best->bytes() && error_of(candidate) < error_of(*best)))
            best = candidate;
    }

    Expected<TableSizeSearchResult> run()
    {
        for (;;) {
            std::optional<TableSize> best;
            for (SigmaSpacing spacing : options_.spacings)
                if (auto st = walk(spacing, best); !st) return st.error();
            // Where the error is not monotone in the value count, a walk can
            // pass over a smaller candidate measured on an earlier walk
            // (before a rejection): every passing one counts.
            for (const TableSizeTrial& t : trials_)
                if (t.error <= options_.tolerance && !rejected_.count(key_of(t.size))) consider(t.size, best);
            if (!best) return no_table_meets();

            auto table = bake(*best);
            if (!table) return table.error();
            if (verify_points_.v.empty()) {
                LookupErrorOptions draw;
                draw.samples = options_.verify_samples;
                draw.seed = options_.seed + 1;
                draw.threads = options_.threads;
                verify_points_ = draw_lookup_error_points(map_, sigma_max_, draw);
            }
            std::vector<double> errors = lookup_errors(*table, verify_points_, options_.threads);
            const double verify_error = nearest_rank_quantile(errors, options_.quantile);
            TableSizeTrial& trial = trials_[measured_.at(key_of(*best))];
            trial.verified = true;
            trial.verify_error = verify_error;
            if (verify_error > options_.tolerance) {
                rejected_.insert(key_of(*best));
                continue;
            }
            TableSizeSearchResult result;
            result.table = std::move(*table);
            result.size = *best;
            result.sigma_max = sigma_max_;
            result.search_error = trial.error;
            result.error = verify_error;
            result.verify_summary = summarize_errors(std::move(errors));
            result.trials = trials_;
            result.rejected = static_cast<int>(rejected_.size());
            return result;
        }
    }

private:
    Error no_table_meets() const
    {
        // A candidate's error: its search error, or the larger of both when verified.
        const auto error = [](const TableSizeTrial& t) {
            return t.verified ? std::max(t.error, t.verify_error) : t.error;
        };
        const TableSizeTrial* lowest = nullptr;
        for (const TableSizeTrial& t : trials_)
            if (!lowest || error(t) < error(*lowest)) lowest = &t;
        const std::string stat = quantile_name(options_.quantile);
        std::ostringstream msg;
        msg << "no table up to " << options_.value_counts.back() << " values x " << options_.sigma_counts.back()
            << " sigmas meets the tolerance " << options_.tolerance << " (CIEDE2000 " << stat << " at "
            << options_.search_samples << " random (v, sigma), sigma_max " << sigma_max_ << ")";
        if (lowest) {
            msg << ": the lowest " << stat << " reached is " << lowest->error << ", by " << describe(lowest->size);
            if (lowest->verified) msg << " (" << lowest->verify_error << " at the verification points)";
        }
        if (!rejected_.empty())
            msg << "; " << rejected_.size() << " that passed at the search points failed at the "
                << options_.verify_samples << " verification points";
        return bad_input(msg.str());
    }

    const ColorMap& map_;
    const TableSizeSearchOptions& options_;
    double sigma_max_;
    LookupErrorPoints points_, verify_points_;
    std::vector<TableSizeTrial> trials_;
    std::map<Key, std::size_t> measured_;  // index into trials_
    std::set<Key> rejected_;
};

}  // namespace

std::vector<int> power_of_two_counts(int lo, int hi)
{
    std::vector<int> counts;
    for (int n = lo; n <= hi && n > 0; n *= 2) {
        counts.push_back(n);
        if (n + n / 2 <= hi) counts.push_back(n + n / 2);
    }
    return counts;
}

std::string quantile_name(double q)
{
    if (q >= 1) return "max";
    std::ostringstream s;
    s << "p" << q * 100;
    return s.str();
}

Expected<TableSizeSearchResult> find_smallest_table(const ColorMap& map, const TableSizeSearchOptions& options)
{
    if (auto st = check_options(options); !st) return st.error();
    if (auto st = validate(map, "colour map"); !st) return st.error();
    // Resolve sigma_max (and check it and the margin) once, as the bake would.
    GaussianColorTableOptions axes_options;
    axes_options.values = options.value_counts.front();
    axes_options.sigmas = options.sigma_counts.front();
    axes_options.sigma_max = options.sigma_max;
    axes_options.margin = options.margin;
    auto axes = make_table_axes(map, axes_options);
    if (!axes) return axes.error();
    Search search(map, options, axes->sigma_max);
    return search.run();
}

}  // namespace cmfilter
