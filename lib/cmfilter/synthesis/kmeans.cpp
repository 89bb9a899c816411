// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthesis/kmeans.h"

#include "cmfilter/synthesis/synthesis_random.h"

#include "cmfilter/util/parallel_for.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace cmfilter {

namespace {

// Points are assigned in blocks of this many, whatever the thread count, so
// every block's GEMM (and so every distance) is the same for any count.
constexpr int kBlock = 256;

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstRowMap = Eigen::Map<const RowMatrix>;

int block_count(std::size_t count) { return static_cast<int>((count + kBlock - 1) / kBlock); }

// k-means++ seeding (Arthur & Vassilvitskii 2007): the first centre uniformly
// at random, each next one a point drawn with probability proportional to
// D(x)^2, its squared distance to the nearest centre chosen. Stops early
// when every D(x)^2 is 0 (no further distinct point). Returns the indices
// of the points chosen as centres.
std::vector<std::size_t> kmeans_plus_plus(const ConstRowMap& points, int clusters, std::uint64_t seed, int threads)
{
    const std::size_t count = static_cast<std::size_t>(points.rows());
    SplitMix64 rng(seed);
    std::vector<std::size_t> chosen;
    chosen.reserve(static_cast<std::size_t>(clusters));
    chosen.push_back(std::min(count - 1, static_cast<std::size_t>(rng.uniform() * static_cast<double>(count))));
    std::vector<double> d2(count, std::numeric_limits<double>::infinity());
    const int blocks = block_count(count);
    while (true) {
        const auto centre = points.row(static_cast<Eigen::Index>(chosen.back()));
        parallel_for(blocks, threads, [&](int b) {
            const std::size_t end = std::min(count, static_cast<std::size_t>(b + 1) * kBlock);
            for (std::size_t i = static_cast<std::size_t>(b) * kBlock; i < end; ++i) {
                // Exact differences: a point equal to a centre is at 0.
                const double d = (points.row(static_cast<Eigen::Index>(i)) - centre).squaredNorm();
                d2[i] = std::min(d2[i], d);
            }
        });
        if (static_cast<int>(chosen.size()) == clusters) break;
        double total = 0;
        for (double d : d2) total += d;
        if (!(total > 0)) break;
        const double target = rng.uniform() * total;
        double cumulative = 0;
        std::size_t pick = count;
        std::size_t last_positive = count;
        for (std::size_t i = 0; i < count; ++i) {
            if (d2[i] <= 0) continue;
            last_positive = i;
            cumulative += d2[i];
            if (cumulative > target) {
                pick = i;
                break;
            }
        }
        chosen.push_back(pick < count ? pick : last_positive);
    }
    return chosen;
}

// Lloyd's assignment step: each point's nearest centre (ties: the lower
// index), with ||x - c||^2 = ||x||^2 - 2 x.c + ||c||^2 and the x.c of a block
// of points against every centre in one GEMM. `distance` receives each
// point's squared distance to its centre as that expansion gives it.
void assign_points(const ConstRowMap& points, const Eigen::VectorXf& point_norms, const RowMatrix& centres, int threads,
                   std::vector<int>& labels, std::vector<float>& distance)
{
    const std::size_t count = static_cast<std::size_t>(points.rows());
    const Eigen::Index k = centres.rows();
    const Eigen::VectorXf centre_norms = centres.rowwise().squaredNorm();
    parallel_for(block_count(count), threads, [&](int b) {
        const Eigen::Index begin = static_cast<Eigen::Index>(b) * kBlock;
        const Eigen::Index rows = std::min<Eigen::Index>(kBlock, static_cast<Eigen::Index>(count) - begin);
        RowMatrix dots(rows, k);
        dots.noalias() = points.middleRows(begin, rows) * centres.transpose();
        for (Eigen::Index r = 0; r < rows; ++r) {
            const float xx = point_norms[begin + r];
            int best = 0;
            float best_d = std::numeric_limits<float>::infinity();
            for (Eigen::Index j = 0; j < k; ++j) {
                const float d = xx - 2 * dots(r, j) + centre_norms[j];
                if (d < best_d) {
                    best_d = d;
                    best = static_cast<int>(j);
                }
            }
            labels[static_cast<std::size_t>(begin + r)] = best;
            distance[static_cast<std::size_t>(begin + r)] = best_d;
        }
    });
}

// Lloyd's update step: every cluster's mean, summed in double over its
// points in index order (the same sums for any thread count). An empty
// cluster first takes the point farthest from its centre among clusters
// that keep at least one other point (ties: the lower index).
void update_centres(const ConstRowMap& points, int threads, std::vector<int>& labels, std::vector<float>& distance,
                    RowMatrix& centres)
{
    const std::size_t count = static_cast<std::size_t>(points.rows());
    const int k = static_cast<int>(centres.rows());
    std::vector<std::size_t> members(static_cast<std::size_t>(k), 0);
    for (int l : labels) ++members[static_cast<std::size_t>(l)];
    for (int j = 0; j < k; ++j) {
        if (members[static_cast<std::size_t>(j)] > 0) continue;
        std::size_t far = count;
        for (std::size_t i = 0; i < count; ++i)
            if (members[static_cast<std::size_t>(labels[i])] > 1 && (far == count || distance[i] > distance[far]))
                far = i;
        if (far == count) continue;  // cannot happen while clusters <= distinct points
        --members[static_cast<std::size_t>(labels[far])];
        labels[far] = j;
        distance[far] = 0;
        members[static_cast<std::size_t>(j)] = 1;
    }
    // Points grouped by cluster, in index order (a stable counting sort).
    std::vector<std::size_t> start(static_cast<std::size_t>(k) + 1, 0);
    for (int j = 0; j < k; ++j)
        start[static_cast<std::size_t>(j) + 1] = start[static_cast<std::size_t>(j)] +
                                                 members[static_cast<std::size_t>(j)];
    std::vector<std::size_t> order(count), fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < count; ++i) order[fill[static_cast<std::size_t>(labels[i])]++] = i;
    const Eigen::Index dims = points.cols();
    parallel_for(k, threads, [&](int j) {
        const std::size_t first = start[static_cast<std::size_t>(j)], last = start[static_cast<std::size_t>(j) + 1];
        if (first == last) return;
        Eigen::VectorXd sum = Eigen::VectorXd::Zero(dims);
        for (std::size_t m = first; m < last; ++m)
            sum += points.row(static_cast<Eigen::Index>(order[m])).transpose().cast<double>();
        centres.row(j) = (sum / static_cast<double>(last - first)).cast<float>().transpose();
    });
}

}  // namespace

Expected<KMeansResult> kmeans(const float* points, std::size_t count, int dims, const KMeansOptions& options)
{
    if (dims < 1) return bad_input("k-means of points with " + std::to_string(dims) + " dimensions; expected >= 1");
    if (count == 0) return bad_input("k-means of no points; expected at least one");
    if (options.clusters < 1 || static_cast<std::size_t>(options.clusters) > count)
        return bad_input("KMeansOptions::clusters " + std::to_string(options.clusters) +
                             " is invalid: expected between 1 and the number of points (" + std::to_string(count) + ")",
                         "KMeansOptions::clusters");
    if (options.max_iterations < 0)
        return bad_input("KMeansOptions::max_iterations " + std::to_string(options.max_iterations) +
                             " is invalid: expected >= 0",
                         "KMeansOptions::max_iterations");
    const std::size_t values = count * static_cast<std::size_t>(dims);
    for (std::size_t i = 0; i < values; ++i)
        if (!std::isfinite(points[i]))
            return bad_input("k-means point " + std::to_string(i / dims) + " has a non-finite value in dimension " +
                             std::to_string(i % dims) + "; expected finite values");

    const ConstRowMap x(points, static_cast<Eigen::Index>(count), dims);
    const std::vector<std::size_t> seeds = kmeans_plus_plus(x, options.clusters, options.seed, options.threads);
    const int k = static_cast<int>(seeds.size());
    RowMatrix centres(k, dims);
    for (int j = 0; j < k; ++j) centres.row(j) = x.row(static_cast<Eigen::Index>(seeds[static_cast<std::size_t>(j)]));

    const Eigen::VectorXf point_norms = x.rowwise().squaredNorm();
    std::vector<int> labels(count), next(count);
    std::vector<float> distance(count);
    assign_points(x, point_norms, centres, options.threads, labels, distance);
    int iterations = 0;
    while (true) {
        update_centres(x, options.threads, labels, distance, centres);
        if (iterations == options.max_iterations) break;
        assign_points(x, point_norms, centres, options.threads, next, distance);
        ++iterations;
        if (next == labels) break;
        labels.swap(next);
    }

    KMeansResult result;
    result.clusters = k;
    result.dims = dims;
    result.centres.assign(centres.data(), centres.data() + centres.size());
    result.labels = std::move(labels);
    result.iterations = iterations;
    // The inertia from exact differences (not the expansion), summed in
    // point order in double.
    std::vector<double> point_inertia(count);
    parallel_for(block_count(count), options.threads, [&](int b) {
        const std::size_t end = std::min(count, static_cast<std::size_t>(b + 1) * kBlock);
        for (std::size_t i = static_cast<std::size_t>(b) * kBlock; i < end; ++i)
            point_inertia[i] =
                (x.row(static_cast<Eigen::Index>(i)).cast<double>() - centres.row(result.labels[i]).cast<double>())
                    .squaredNorm();
    });
    for (double v : point_inertia) result.inertia += v;
    return result;
}

}  // namespace cmfilter
