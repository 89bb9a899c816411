// SPDX-License-Identifier: Apache-2.0
// Coordinate-map files (coordinate_map_file.h): an exact round trip of every
// level and field, a file written here by hand as oiiotool writes one (int
// attributes), and files with one value wrong, each refused naming the file.
#include "cmfilter/synthesis/coordinate_map_file.h"

#include "test_images.h"

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

using namespace cmfilter;

namespace {

const std::string kDir = cmfilter_test::temp_dir("cmfilter-coordinate-map-file");

CoordinateLevel random_level(std::mt19937_64& rng, int w, int h, int sw, int sh)
{
    CoordinateLevel level;
    level.width = w;
    level.height = h;
    level.sample_width = sw;
    level.sample_height = sh;
    std::uniform_int_distribution<int> ux(0, sw - 1), uy(0, sh - 1);
    for (int t = 0; t < w * h; ++t) {
        level.coords.push_back(ux(rng));
        level.coords.push_back(uy(rng));
    }
    // The sample's corners, where rounding would show first.
    level.coords[0] = sw - 1;
    level.coords[1] = sh - 1;
    level.coords[2] = 0;
    level.coords[3] = 0;
    return level;
}

// A one-level file as oiiotool writes one: every number an int attribute
// (seconds a float or absent), u, v the texel centres (x + 0.5) / W, (y + 0.5) / H.
struct HandFile {
    std::string kind = "coordinate-map";
    int version = 1;
    int sample_width = 5, sample_height = 3;
    bool with_v = true;
    float seconds = 1.5f;  // NaN: no cmfilter:seconds attribute
    float u[4] = {0.1f, 0.3f, 0.5f, 0.9f};
    float v[4] = {0.5f, 0.1f, 0.9f, 0.5f};
};

std::string write_by_hand(const std::string& name, const HandFile& h)
{
    const std::string path = kDir + "/" + name;
    OIIO::ImageSpec spec(2, 2, h.with_v ? 2 : 1, OIIO::TypeDesc::FLOAT);
    spec.channelnames = h.with_v ? std::vector<std::string>{"u", "v"} : std::vector<std::string>{"u"};
    spec.attribute("cmfilter:kind", h.kind);
    spec.attribute("cmfilter:format_version", h.version);
    spec.attribute("cmfilter:sample", "grass.png");
    spec.attribute("cmfilter:sample_hash", 0);  // oiiotool's `--attrib cmfilter:sample_hash 0` is an int
    spec.attribute("cmfilter:sample_kind", "image");
    if (h.sample_width != 0) spec.attribute("cmfilter:sample_width", h.sample_width);
    spec.attribute("cmfilter:sample_height", h.sample_height);
    spec.attribute("cmfilter:sample_periodic", 1);
    spec.attribute("cmfilter:k", 3);
    spec.attribute("cmfilter:neighbourhood", 2);
    spec.attribute("cmfilter:levels", 1);
    spec.attribute("cmfilter:toroidal", 0);
    spec.attribute("cmfilter:seed", 42);
    if (!std::isnan(h.seconds)) spec.attribute("cmfilter:seconds", h.seconds);
    std::vector<float> px;
    for (int t = 0; t < 4; ++t) {
        px.push_back(h.u[t]);
        if (h.with_v) px.push_back(h.v[t]);
    }
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    REQUIRE(out->open(path, spec));
    REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    REQUIRE(out->close());
    return path;
}

void check_refused(const std::string& path, const std::vector<std::string>& texts)
{
    auto r = read_coordinate_map_exr(path);
    REQUIRE_FALSE(r);
    CHECK(r.error().kind == ErrorKind::BadInput);
    CHECK_MESSAGE(r.error().message.find(path) != std::string::npos, r.error().message);
    for (const std::string& text : texts)
        CHECK_MESSAGE(r.error().message.find(text) != std::string::npos, r.error().message);
}

// A one-level 4 x 4 map into a 6 x 6 image sample with the smallest valid
// record (k, neighbourhood and levels 1).
CoordinateMap one_level_map(std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    CoordinateMap map;
    map.info.sample_kind = "image";
    map.info.k = map.info.neighbourhood = map.info.levels = 1;
    map.levels.push_back(random_level(rng, 4, 4, 6, 6));
    return map;
}

}  // namespace

TEST_CASE("coordinate map file: every level and field reads back exactly")
{
    std::mt19937_64 rng(5);
    CoordinateMap a;
    a.info.sample_path = "samples/brick.png";
    a.info.sample_hash = std::string(64, 'c');
    a.info.sample_kind = "stack";
    a.info.sample_periodic = true;
    a.info.k = 6;
    a.info.neighbourhood = 3;
    a.info.levels = 3;
    a.info.toroidal = true;
    a.info.seed = 0xfedcba9876543210ull;  // beyond any int attribute
    a.info.seconds = 2.718281828459045;
    // Sample sides up to 4096, where (x + 0.5) / W as float is coarsest.
    a.levels.push_back(random_level(rng, 37, 23, 4093, 4096));
    a.levels.push_back(random_level(rng, 19, 12, 2047, 2048));
    a.levels.push_back(random_level(rng, 10, 6, 3, 7));
    const std::string path = kDir + "/round-trip.exr";
    const Status written = write_coordinate_map_exr(path, a);
    REQUIRE_MESSAGE(written, (written ? std::string() : written.error().message));
    auto b = read_coordinate_map_exr(path);
    REQUIRE_MESSAGE(b, (b ? std::string() : b.error().message));
    CHECK(cmfilter_test::same_file_path(b->info.sample_path, a.info.sample_path));
    CHECK(b->info.sample_hash == a.info.sample_hash);
    CHECK(b->info.sample_kind == "stack");
    CHECK(b->info.sample_periodic);
    CHECK(b->info.k == 6);
    CHECK(b->info.neighbourhood == 3);
    CHECK(b->info.levels == 3);
    CHECK(b->info.toroidal);
    CHECK(b->info.seed == 0xfedcba9876543210ull);
    CHECK(b->info.seconds == 0.0);  // not recorded: the same inputs give the same bytes
    REQUIRE(b->levels.size() == 3);
    for (std::size_t l = 0; l < 3; ++l) {
        const CoordinateLevel &x = a.levels[l], &y = b->levels[l];
        CHECK(y.width == x.width);
        CHECK(y.height == x.height);
        CHECK(y.sample_width == x.sample_width);
        CHECK(y.sample_height == x.sample_height);
        CHECK(y.coords == x.coords);
    }

    // The stored u, v are the texel centres (read back with OIIO directly).
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    std::vector<float> uv(2 * 37 * 23);
    REQUIRE(in->read_image(0, 0, 0, 2, OIIO::TypeDesc::FLOAT, uv.data()));
    CHECK(uv[0] == doctest::Approx((4092 + 0.5) / 4093).epsilon(1e-7));
    CHECK(uv[1] == doctest::Approx((4095 + 0.5) / 4096).epsilon(1e-7));
    CHECK(uv[2] == doctest::Approx(0.5 / 4093).epsilon(1e-6));
    CHECK(in->spec().get_string_attribute("cmfilter:kind") == "coordinate-map");
}

TEST_CASE("coordinate map file: a file with int attributes, as oiiotool writes, reads")
{
    auto r = read_coordinate_map_exr(write_by_hand("oiiotool.exr", HandFile{}));
    REQUIRE_MESSAGE(r, (r ? std::string() : r.error().message));
    CHECK(cmfilter_test::same_file_path(r->info.sample_path, kDir + "/grass.png"));  // relative to the map
    CHECK(r->info.sample_hash == "0");
    CHECK(r->info.sample_periodic);
    CHECK_FALSE(r->info.toroidal);
    CHECK(r->info.k == 3);
    CHECK(r->info.seed == 42);
    CHECK(r->info.seconds == 1.5);
    REQUIRE(r->levels.size() == 1);
    const CoordinateLevel& level = r->full();
    CHECK(level.sample_width == 5);
    CHECK(level.sample_height == 3);
    // floor(u * 5), floor(v * 3) by hand: u 0.1 0.3 0.5 0.9 -> 0 1 2 4; v 0.5 0.1 0.9 0.5 -> 1 0 2 1.
    CHECK(level.coords == std::vector<std::int32_t>{0, 1, 1, 0, 2, 2, 4, 1});

    // Without a synthesis time (oiiotool writes none): 0.
    HandFile untimed;
    untimed.seconds = std::numeric_limits<float>::quiet_NaN();
    auto u = read_coordinate_map_exr(write_by_hand("untimed.exr", untimed));
    REQUIRE_MESSAGE(u, (u ? std::string() : u.error().message));
    CHECK(u->info.seconds == 0.0);
    HandFile negative;
    negative.seconds = -2.0f;
    check_refused(write_by_hand("negative-time.exr", negative), {"cmfilter:seconds -2"});
}

TEST_CASE("coordinate map file: u = 1 is refused naming the file, the texel and the value")
{
    HandFile h;
    h.u[3] = 1.0f;
    check_refused(write_by_hand("u-one.exr", h), {"texel (1, 1)", "u 1.0", "[0, 1)"});
    HandFile neg;
    neg.v[1] = -0.25f;
    check_refused(write_by_hand("v-negative.exr", neg), {"texel (1, 0)", "v -0.25"});
}

TEST_CASE("coordinate map file: NaN, a missing channel, a wrong kind or version, a missing sample size are refused")
{
    HandFile nan;
    nan.v[2] = std::numeric_limits<float>::quiet_NaN();
    check_refused(write_by_hand("nan.exr", nan), {"non-finite v", "texel (0, 1)"});
    HandFile no_v;
    no_v.with_v = false;
    check_refused(write_by_hand("no-v.exr", no_v), {"no channels u and v"});
    HandFile kind;
    kind.kind = "synthesis-analysis";
    check_refused(write_by_hand("kind.exr", kind), {"not a cmfilter coordinate map", "synthesis-analysis"});
    HandFile version;
    version.version = 2;
    check_refused(write_by_hand("version.exr", version), {"version 2"});
    HandFile no_width;
    no_width.sample_width = 0;
    check_refused(write_by_hand("no-width.exr", no_width), {"cmfilter:sample_width 0"});
    HandFile small;
    small.sample_height = -1;
    check_refused(write_by_hand("small.exr", small), {"cmfilter:sample_height -1"});
}

TEST_CASE("coordinate map file: a coordinate outside the sample is not written, and nothing is left behind")
{
    CoordinateMap map = one_level_map(9);
    map.levels[0].coords[2 * 5] = 6;
    const std::string path = kDir + "/outside.exr";
    std::filesystem::remove(path);
    const Status written = write_coordinate_map_exr(path, map);
    REQUIRE_FALSE(written);
    CHECK(written.error().kind == ErrorKind::BadInput);
    CHECK_MESSAGE(written.error().message.find("(6, ") != std::string::npos, written.error().message);
    CHECK_MESSAGE(written.error().message.find("texel (1, 1)") != std::string::npos, written.error().message);
    CHECK_FALSE(std::filesystem::exists(path));
    auto missing = read_coordinate_map_exr(kDir + "/missing.exr");
    REQUIRE_FALSE(missing);
    CHECK(missing.error().kind == ErrorKind::Io);
}

TEST_CASE("coordinate map file: a record the reader would refuse is not written (a sample kind, k, neighbourhood)")
{
    const CoordinateMap map = one_level_map(10);
    const std::string path = kDir + "/bad-record.exr";
    const auto refused = [&](const CoordinateMap& m, const std::string& text) {
        std::filesystem::remove(path);
        const Status written = write_coordinate_map_exr(path, m);
        REQUIRE_FALSE(written);
        CHECK(written.error().kind == ErrorKind::BadInput);
        CHECK_MESSAGE(written.error().message.find(text) != std::string::npos, written.error().message);
        CHECK_FALSE(std::filesystem::exists(path));
    };
    CoordinateMap no_kind = map;
    no_kind.info.sample_kind.clear();
    refused(no_kind, "CoordinateMapInfo::sample_kind ''");
    CoordinateMap no_k = map;
    no_k.info.k = 0;
    refused(no_k, "CoordinateMapInfo::k 0");
    CoordinateMap no_neighbourhood = map;
    no_neighbourhood.info.neighbourhood = 0;
    refused(no_neighbourhood, "CoordinateMapInfo::neighbourhood 0");
    // The same map with a valid record is written and read back by the reader.
    REQUIRE(write_coordinate_map_exr(path, map));
    auto back = read_coordinate_map_exr(path);
    REQUIRE_MESSAGE(back.has_value(), (back ? std::string() : back.error().message));
    CHECK(back->info.k == 1);
    CHECK(back->info.sample_kind == "image");
}
