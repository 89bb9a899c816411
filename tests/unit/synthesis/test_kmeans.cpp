// SPDX-License-Identifier: Apache-2.0
// k-means (kmeans.h): separated clusters recovered exactly against their
// known membership, the inertia against a brute-force sum, the same result
// for any thread count, and a k-means++ start that stops at the distinct
// points.
#include "cmfilter/synthesis/kmeans.h"

#include <doctest/doctest.h>

#include <map>
#include <random>
#include <set>
#include <vector>

using namespace cmfilter;

namespace {

std::vector<float> random_points(std::size_t count, int dims, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<float> p(count * static_cast<std::size_t>(dims));
    for (float& v : p) v = unit(rng);
    return p;
}

}  // namespace

TEST_CASE("kmeans: well-separated clusters are recovered exactly, each centre the mean of its points")
{
    const int dims = 5, clusters = 6, per = 40;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<float> jitter(-0.5f, 0.5f);
    std::vector<float> points;
    std::vector<int> truth;
    for (int c = 0; c < clusters; ++c)
        for (int i = 0; i < per; ++i) {
            for (int d = 0; d < dims; ++d) points.push_back(100.0f * ((c + d) % clusters) + 50.0f * c + jitter(rng));
            truth.push_back(c);
        }
    KMeansOptions options;
    options.clusters = clusters;
    options.seed = 3;
    auto result = kmeans(points.data(), truth.size(), dims, options);
    REQUIRE(result);
    REQUIRE(result->clusters == clusters);
    // The labels are the true partition (up to renaming).
    std::map<int, int> name;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        const auto it = name.emplace(truth[i], result->labels[i]).first;
        CHECK(it->second == result->labels[i]);
    }
    std::set<int> distinct;
    for (const auto& kv : name) distinct.insert(kv.second);
    CHECK(distinct.size() == static_cast<std::size_t>(clusters));
    for (int c = 0; c < clusters; ++c)
        for (int d = 0; d < dims; ++d) {
            double mean = 0;
            for (int i = 0; i < per; ++i) mean += points[static_cast<std::size_t>(c * per + i) * dims + d];
            mean /= per;
            CHECK(result->centres[static_cast<std::size_t>(name[c]) * dims + d] == doctest::Approx(mean).epsilon(1e-6));
        }
}

TEST_CASE("kmeans: the inertia is the brute-force sum of squared distances, and each point has its nearest centre")
{
    const std::size_t count = 700;
    const int dims = 9;
    const std::vector<float> points = random_points(count, dims, 11);
    KMeansOptions options;
    options.clusters = 13;
    options.max_iterations = 100;
    auto result = kmeans(points.data(), count, dims, options);
    REQUIRE(result);
    REQUIRE(result->clusters == 13);
    double inertia = 0;
    for (std::size_t i = 0; i < count; ++i) {
        double best = 1e300, own = 0;
        for (int c = 0; c < result->clusters; ++c) {
            double d2 = 0;
            for (int d = 0; d < dims; ++d) {
                const double e = double(points[i * dims + d]) - result->centres[static_cast<std::size_t>(c) * dims + d];
                d2 += e * e;
            }
            best = std::min(best, d2);
            if (c == result->labels[i]) own = d2;
        }
        inertia += own;
        // Converged (fewer than 100 iterations): the label is the nearest centre.
        if (result->iterations < 100) CHECK(own <= best + 1e-5);
    }
    CHECK(result->iterations < 100);
    CHECK(result->inertia == doctest::Approx(inertia).epsilon(1e-9));
}

TEST_CASE("kmeans: the same labels, centres and inertia for 1 and 2 threads")
{
    const std::size_t count = 1500;  // several blocks of points
    const int dims = 12;
    const std::vector<float> points = random_points(count, dims, 5);
    KMeansOptions options;
    options.clusters = 40;
    options.seed = 9;
    options.threads = 1;
    auto one = kmeans(points.data(), count, dims, options);
    options.threads = 2;
    auto two = kmeans(points.data(), count, dims, options);
    REQUIRE(one);
    REQUIRE(two);
    CHECK(one->labels == two->labels);
    CHECK(one->centres == two->centres);
    CHECK(one->inertia == two->inertia);
    CHECK(one->iterations == two->iterations);
}

TEST_CASE("kmeans: k-means++ with k = the distinct points gives zero inertia, and more clusters than those stop early")
{
    // 5 distinct points, each repeated 3 times, interleaved.
    const float distinct[5][2] = {{0, 0}, {3, 1}, {-2, 7}, {10, -4}, {5, 5}};
    std::vector<float> points;
    for (int r = 0; r < 3; ++r)
        for (const auto& p : distinct) points.insert(points.end(), {p[0], p[1]});
    KMeansOptions options;
    options.clusters = 5;
    auto exact = kmeans(points.data(), 15, 2, options);
    REQUIRE(exact);
    CHECK(exact->clusters == 5);
    CHECK(exact->inertia == 0.0);
    for (int i = 0; i < 15; ++i)
        CHECK(exact->labels[static_cast<std::size_t>(i)] == exact->labels[static_cast<std::size_t>(i % 5)]);
    options.clusters = 9;
    auto fewer = kmeans(points.data(), 15, 2, options);
    REQUIRE(fewer);
    CHECK(fewer->clusters == 5);
    CHECK(fewer->centres.size() == 10);
    CHECK(fewer->inertia == 0.0);
}

TEST_CASE("kmeans: bad options and points are refused, naming the field")
{
    std::vector<float> points = random_points(10, 2, 1);
    KMeansOptions options;
    options.clusters = 0;
    auto r = kmeans(points.data(), 10, 2, options);
    REQUIRE_FALSE(r);
    CHECK(r.error().field == "KMeansOptions::clusters");
    options.clusters = 11;
    r = kmeans(points.data(), 10, 2, options);
    REQUIRE_FALSE(r);
    CHECK(r.error().field == "KMeansOptions::clusters");
    CHECK(r.error().message.find("(10)") != std::string::npos);
    options.clusters = 2;
    options.max_iterations = -1;
    r = kmeans(points.data(), 10, 2, options);
    REQUIRE_FALSE(r);
    CHECK(r.error().field == "KMeansOptions::max_iterations");
    options.max_iterations = 5;
    points[7] = std::nanf("");
    r = kmeans(points.data(), 10, 2, options);
    REQUIRE_FALSE(r);
    CHECK(r.error().kind == ErrorKind::BadInput);
    CHECK(r.error().message.find("point 3") != std::string::npos);
}
