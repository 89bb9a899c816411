// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthesis/kcoherence_synthesis.h"

#include "cmfilter/synthesis/synthesis_random.h"
#include "cmfilter/util/stopwatch.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace cmfilter {

namespace {

std::string size_text(int width, int height) { return std::to_string(width) + " x " + std::to_string(height); }

int ceil_half_power(int size, int level)
{
    return static_cast<int>((static_cast<long long>(size) + (1LL << level) - 1) >> level);
}

struct Offset {
    int dx, dy;
    bool causal;  // before the centre in scan-line order: a row above, or the same row to the left
};

// The (2n + 1)^2 window without its centre, nearest offsets first (the
// distance sums exit early, and near texels weigh most on which is best).
std::vector<Offset> window_offsets(int n)
{
    std::vector<Offset> offsets;
    for (int dy = -n; dy <= n; ++dy)
        for (int dx = -n; dx <= n; ++dx)
            if (dx || dy) offsets.push_back({dx, dy, dy < 0 || (dy == 0 && dx < 0)});
    std::stable_sort(offsets.begin(), offsets.end(), [](const Offset& a, const Offset& b) {
        return a.dx * a.dx + a.dy * a.dy < b.dx * b.dx + b.dy * b.dy;
    });
    return offsets;
}

// One level of the output being synthesised against one level of the analysis.
class LevelSynthesis {
public:
    LevelSynthesis(const LevelAnalysis& analysis, int width, int height, const SynthesisOptions& options, bool periodic,
                   int level)
        : a_(analysis), width_(width), height_(height), k_(options.k), toroidal_(options.toroidal), periodic_(periodic),
          level_(level), seed_(options.seed), offsets_(window_offsets(options.neighbourhood)),
          out_(static_cast<std::size_t>(width) * height, -1), seeded_(out_.size(), 0), stamp_(a_.texels(), 0)
    {
        // ||v_i - v_j||^2 for every pair of textons: one lookup per window texel.
        const int t = a_.textons;
        distance_.resize(static_cast<std::size_t>(t) * t);
        for (int i = 0; i < t; ++i)
            for (int j = 0; j < t; ++j)
                distance_[static_cast<std::size_t>(i) * t + j] = std::max(0.0f, a_.distance(i, j));
    }

    // The coarsest level of a toroidal output starts from random texels, so
    // that the first rows' wrapped causal windows read something.
    void fill_random()
    {
        for (std::size_t p = 0; p < out_.size(); ++p) out_[p] = random_texel(p, 0);
    }

    // Texel (2x, 2y) takes twice the coarser level's coordinate (fig. 4b).
    void seed_from(const std::vector<std::int32_t>& coarse, int coarse_width, int coarse_height,
                   int coarse_sample_width)
    {
        for (int y = 0; y < coarse_height; ++y)
            for (int x = 0; x < coarse_width; ++x) {
                const int fx = 2 * x, fy = 2 * y;
                if (fx >= width_ || fy >= height_) continue;
                const std::int32_t s = coarse[static_cast<std::size_t>(y) * coarse_width + x];
                const int sx = sample_x(2 * (s % coarse_sample_width)), sy = sample_y(2 * (s / coarse_sample_width));
                const std::size_t p = static_cast<std::size_t>(fy) * width_ + fx;
                out_[p] = sy * a_.width + sx;
                seeded_[p] = 1;
            }
    }

    // The first pass in scan-line order: every texel not seeded, matched on
    // the causal window and any seeded texel in the whole window.
    void scan()
    {
        for (int y = 0; y < height_; ++y)
            for (int x = 0; x < width_; ++x) {
                const std::size_t p = static_cast<std::size_t>(y) * width_ + x;
                if (seeded_[p]) continue;
                out_[p] = best_match(x, y, false);
            }
    }

    // Seeded texels again, each with its whole window (sec. 4.2: "the
    // synthesis is again performed on the previously omitted pixels").
    void correct_seeded()
    {
        for (int y = 0; y < height_; ++y)
            for (int x = 0; x < width_; ++x) {
                const std::size_t p = static_cast<std::size_t>(y) * width_ + x;
                if (seeded_[p]) out_[p] = best_match(x, y, true);
            }
    }

    // A toroidal output's first n rows and columns, whose first pass read
    // wrapped texels not yet synthesised, again with whole windows.
    void correct_wrap(int n)
    {
        for (int y = 0; y < height_; ++y)
            for (int x = 0; x < width_; ++x)
                if (y < n || x < n) out_[static_cast<std::size_t>(y) * width_ + x] = best_match(x, y, true);
    }

    const std::vector<std::int32_t>& result() const { return out_; }

private:
    const LevelAnalysis& a_;
    int width_, height_, k_;
    bool toroidal_, periodic_;
    int level_;
    std::uint64_t seed_;
    std::vector<Offset> offsets_;
    std::vector<std::int32_t> out_;  // sample texel per output texel, -1 not yet synthesised
    std::vector<std::uint8_t> seeded_;
    std::vector<float> distance_;
    std::vector<std::uint32_t> stamp_;  // candidates already tried for this texel
    std::uint32_t stamp_value_ = 0;
    std::vector<std::int32_t> candidates_;
    std::vector<int> known_dx_, known_dy_, known_texton_;

    int sample_x(int x) const
    {
        if (periodic_) return ((x % a_.width) + a_.width) % a_.width;
        return std::clamp(x, 0, a_.width - 1);
    }
    int sample_y(int y) const
    {
        if (periodic_) return ((y % a_.height) + a_.height) % a_.height;
        return std::clamp(y, 0, a_.height - 1);
    }

    std::int32_t random_texel(std::size_t p, int pass) const
    {
        const std::uint64_t h = synthesis_hash(seed_, static_cast<std::uint64_t>(level_) * 4 + pass, p);
        return static_cast<std::int32_t>(h % a_.texels());
    }

    // The sample texel whose neighbourhood is nearest the output's around
    // (x, y), among the k-coherence candidates (fig. 3).
    std::int32_t best_match(int x, int y, bool whole_window)
    {
        known_dx_.clear();
        known_dy_.clear();
        known_texton_.clear();
        candidates_.clear();
        if (++stamp_value_ == 0) {
            std::fill(stamp_.begin(), stamp_.end(), 0);
            stamp_value_ = 1;
        }
        const std::size_t centre = static_cast<std::size_t>(y) * width_ + x;
        auto add_candidate = [&](std::int32_t s) {
            if (stamp_[s] == stamp_value_) return;
            stamp_[s] = stamp_value_;
            candidates_.push_back(s);
        };
        // A texel being corrected competes with its own coordinate.
        if (whole_window && out_[centre] >= 0) add_candidate(out_[centre]);
        for (const Offset& o : offsets_) {
            int nx = x + o.dx, ny = y + o.dy;
            if (toroidal_) {
                nx = ((nx % width_) + width_) % width_;
                ny = ((ny % height_) + height_) % height_;
            } else if (nx < 0 || ny < 0 || nx >= width_ || ny >= height_) {
                continue;
            }
            const std::size_t q = static_cast<std::size_t>(ny) * width_ + nx;
            const std::int32_t s = out_[q];
            if (s < 0) continue;
            if (!whole_window && !o.causal && !seeded_[q]) continue;
            known_dx_.push_back(o.dx);
            known_dy_.push_back(o.dy);
            known_texton_.push_back(a_.texton[s]);
            // Its sample texel shifted back by the offset (Ashikhmin's
            // coherence, k = 1), and that texel's k - 1 most similar. Off a
            // sample that does not tile there is no such texel: clamping it
            // would repeat the edge texel into streaks.
            int cx = s % a_.width - o.dx, cy = s / a_.width - o.dy;
            if (periodic_) {
                cx = sample_x(cx);
                cy = sample_y(cy);
            } else if (cx < 0 || cy < 0 || cx >= a_.width || cy >= a_.height) {
                continue;
            }
            const std::int32_t c = cy * a_.width + cx;
            add_candidate(c);
        }
        // Then each continuing copy's k - 1 most similar texels: on a tie
        // the earlier candidate wins, so a copy continues where it can (a
        // flat region, where every candidate ties, is walked through as the
        // sample has it rather than left for its lowest-numbered texel).
        const std::size_t continuing = candidates_.size();
        const int extra = std::min(k_ - 1, a_.candidates);
        for (std::size_t b = 0; b < continuing; ++b) {
            const std::int32_t* similar = a_.similar.data() + static_cast<std::size_t>(candidates_[b]) * a_.candidates;
            for (int j = 0; j < extra; ++j) add_candidate(similar[j]);
        }
        // No neighbour yet, or none whose copy continues inside the sample:
        // a fresh copy starts at a random texel, or the best of it and its
        // k - 1 most similar when there are neighbours to match.
        if (candidates_.empty()) {
            const std::int32_t start = random_texel(centre, whole_window ? 2 : 1);
            if (known_texton_.empty()) return start;
            add_candidate(start);
            const std::int32_t* similar = a_.similar.data() + static_cast<std::size_t>(start) * a_.candidates;
            for (int j = 0; j < std::min(k_ - 1, a_.candidates); ++j) add_candidate(similar[j]);
        }

        std::int32_t best = candidates_.front();
        float best_cost = std::numeric_limits<float>::infinity();
        const int t = a_.textons;
        const std::size_t known = known_texton_.size();
        for (const std::int32_t c : candidates_) {
            const int cx = c % a_.width, cy = c / a_.width;
            // Summed until it exceeds the best so far; only a complete sum
            // below it wins.
            float cost = 0;
            std::size_t i = 0;
            for (; i < known; ++i) {
                const std::int32_t s = sample_y(cy + known_dy_[i]) * a_.width + sample_x(cx + known_dx_[i]);
                cost += distance_[static_cast<std::size_t>(known_texton_[i]) * t + a_.texton[s]];
                if (cost > best_cost) break;
            }
            if (i == known && cost < best_cost) {
                best_cost = cost;
                best = c;
            }
        }
        return best;
    }
};

}  // namespace

Expected<CoordinateMap> synthesise(const SampleAnalysis& analysis, const SynthesisOptions& options)
{
    const Stopwatch clock;
    if (analysis.levels.empty() || analysis.levels[0].texels() == 0)
        return bad_input("the analysis of '" + analysis.sample_path + "' holds no levels; expected an analysed sample");
    auto size_error = [](const char* field, int value) {
        return bad_input(std::string("SynthesisOptions::") + field + " " + std::to_string(value) +
                             " is invalid: expected 1 to " + std::to_string(kMaxSynthesisSize) + " texels",
                         std::string("SynthesisOptions::") + field);
    };
    if (options.width < 1 || options.width > kMaxSynthesisSize) return size_error("width", options.width);
    if (options.height < 1 || options.height > kMaxSynthesisSize) return size_error("height", options.height);
    const int available = static_cast<int>(analysis.levels.size());
    if (options.levels < 1 || options.levels > available)
        return bad_input("SynthesisOptions::levels " + std::to_string(options.levels) + " is invalid: expected 1 to " +
                             std::to_string(available) + " (the levels the analysis of '" + analysis.sample_path +
                             "' holds)",
                         "SynthesisOptions::levels");
    const LevelAnalysis& coarsest = analysis.levels[options.levels - 1];
    if (options.neighbourhood < 1 || 2 * options.neighbourhood + 1 > std::min(coarsest.width, coarsest.height))
        return bad_input("SynthesisOptions::neighbourhood " + std::to_string(options.neighbourhood) +
                             " is invalid: expected >= 1 with a (2n + 1)^2 window no larger than the coarsest "
                             "sample level used (" +
                             size_text(coarsest.width, coarsest.height) + ")",
                         "SynthesisOptions::neighbourhood");
    int most_k = std::numeric_limits<int>::max();
    for (int l = 0; l < options.levels; ++l) most_k = std::min(most_k, analysis.levels[l].candidates + 1);
    if (options.k < 1 || options.k > most_k)
        return bad_input("SynthesisOptions::k " + std::to_string(options.k) + " is invalid: expected 1 to " +
                             std::to_string(most_k) + " (the analysis keeps " + std::to_string(most_k - 1) +
                             " similar texels per texel, plus the texel itself)",
                         "SynthesisOptions::k");

    CoordinateMap map;
    map.levels.resize(options.levels);
    std::vector<std::int32_t> coarser;
    int coarser_width = 0, coarser_height = 0, coarser_sample_width = 0;
    for (int l = options.levels - 1; l >= 0; --l) {
        const LevelAnalysis& level = analysis.levels[l];
        const int width = ceil_half_power(options.width, l), height = ceil_half_power(options.height, l);
        LevelSynthesis synthesis(level, width, height, options, analysis.periodic, l);
        const bool coarsest_level = l == options.levels - 1;
        if (coarsest_level) {
            if (options.toroidal) synthesis.fill_random();
        } else {
            synthesis.seed_from(coarser, coarser_width, coarser_height, coarser_sample_width);
        }
        synthesis.scan();
        if (!coarsest_level) synthesis.correct_seeded();
        if (options.toroidal) synthesis.correct_wrap(options.neighbourhood);

        CoordinateLevel& out = map.levels[l];
        out.width = width;
        out.height = height;
        out.sample_width = level.width;
        out.sample_height = level.height;
        out.coords.resize(out.texels() * 2);
        const std::vector<std::int32_t>& result = synthesis.result();
        for (std::size_t p = 0; p < out.texels(); ++p) {
            out.coords[2 * p] = result[p] % level.width;
            out.coords[2 * p + 1] = result[p] / level.width;
        }
        coarser = result;
        coarser_width = width;
        coarser_height = height;
        coarser_sample_width = level.width;
    }
    CoordinateMapInfo& info = map.info;
    info.sample_path = analysis.sample_path;
    info.sample_hash = analysis.sample_hash;
    info.sample_kind = to_string(analysis.sample_kind);
    info.sample_periodic = analysis.periodic;
    info.k = options.k;
    info.neighbourhood = options.neighbourhood;
    info.levels = options.levels;
    info.toroidal = options.toroidal;
    info.seed = options.seed;
    info.seconds = clock.elapsed_ms() / 1000;
    return map;
}

}  // namespace cmfilter
