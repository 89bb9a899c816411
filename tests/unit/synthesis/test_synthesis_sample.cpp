// SPDX-License-Identifier: Apache-2.0
// Synthesis samples (synthesis_sample.h): a stack written here (EXR images
// and a .lp) loads into features in the documented order; the hash follows
// the files' bytes; a farthest-point selection worked out by hand; a
// pyramid level against hand-computed 2 x 2 means; bad inputs.
#include "cmfilter/synthesis/synthesis_sample.h"

#include "cmfilter/stack/btf_manifest.h"
#include "cmfilter/util/sha256.h"

#include "test_images.h"
#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <fstream>

using namespace cmfilter;

namespace {

const std::string kDir = cmfilter_test::temp_dir("cmfilter-synthesis-sample");

// Image k of a w x h RGB stack: texel t channel c holds value(k, t, c).
float value(int k, int t, int c) { return 0.5f * k + 0.125f * t + 0.03125f * c; }

std::string write_stack(const std::string& name, int n, int w, int h)
{
    std::string lp = std::to_string(n) + "\n";
    for (int k = 0; k < n; ++k) {
        std::vector<float> px(static_cast<std::size_t>(w * h * 3));
        for (int t = 0; t < w * h; ++t)
            for (int c = 0; c < 3; ++c) px[static_cast<std::size_t>(3 * t + c)] = value(k, t, c);
        const std::string file = name + "-" + std::to_string(k) + ".exr";
        cmfilter_test::write_image(kDir + "/" + file, w, h, 3, OIIO::TypeDesc::FLOAT, px.data());
        lp += file + " 0 0.1 1\n";
    }
    const std::string path = kDir + "/" + name + ".lp";
    std::ofstream(path) << lp;
    return path;
}

}  // namespace

TEST_CASE("synthesis sample: a stack's features are each texel's values image by image, channel by channel")
{
    const auto config = cmfilter_test::builtin_color_config();
    SampleOptions options;
    options.path = write_stack("order", 3, 4, 3);
    auto sample = load_synthesis_sample(options, config);
    REQUIRE(sample);
    CHECK(sample->kind == SampleKind::Stack);
    CHECK(sample->images == 3);
    CHECK(sample->channels == 3);
    CHECK(sample->dims == 9);
    CHECK(sample->used == std::vector<int>{0, 1, 2});
    REQUIRE(sample->width() == 4);
    REQUIRE(sample->height() == 3);
    for (int t = 0; t < 12; ++t)
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) CHECK(sample->levels[0].feature(t, 9)[3 * k + c] == value(k, t, c));
    // The hash: SHA-256 over the images' SHA-256 digests (hex), in order.
    std::string digests;
    for (int k = 0; k < 3; ++k) digests += *sha256_file_hex(kDir + "/order-" + std::to_string(k) + ".exr");
    CHECK(sample->hash == sha256_hex(digests.data(), digests.size()));
}

TEST_CASE("synthesis sample: a BTF's features are view by view, and one image is a sample of its own")
{
    const auto config = cmfilter_test::builtin_color_config();
    const std::string a = write_stack("view-a", 2, 2, 2), b = write_stack("view-b", 3, 2, 2);
    const std::string manifest = kDir + "/btf.json";
    REQUIRE(write_btf_manifest(manifest, {{"view-b.lp", {0, 0, 1}}, {"view-a.lp", {0.5, 0, 0.8}}}));
    SampleOptions options;
    options.path = manifest;
    auto btf = load_synthesis_sample(options, config);
    REQUIRE(btf);
    CHECK(btf->kind == SampleKind::Btf);
    CHECK(btf->images == 5);
    REQUIRE(btf->dims == 15);
    const int image_of_slot[5] = {0, 1, 2, 0, 1};  // view b's three, then view a's two
    for (int t = 0; t < 4; ++t)
        for (int s = 0; s < 5; ++s)
            for (int c = 0; c < 3; ++c)
                CHECK(btf->levels[0].feature(t, 15)[3 * s + c] == value(image_of_slot[s], t, c));
    options.path = kDir + "/view-a-1.exr";
    auto image = load_synthesis_sample(options, config);
    REQUIRE(image);
    CHECK(image->kind == SampleKind::Image);
    CHECK(image->images == 1);
    CHECK(image->levels[0].feature(3, 3)[2] == value(1, 3, 2));
}

TEST_CASE("synthesis sample: the hash changes when one byte of one image changes")
{
    const auto config = cmfilter_test::builtin_color_config();
    SampleOptions options;
    options.path = write_stack("hash", 2, 2, 2);
    auto before = load_synthesis_sample(options, config);
    REQUIRE(before);
    const std::string image = kDir + "/hash-1.exr";
    std::vector<float> px(12);
    for (int t = 0; t < 4; ++t)
        for (int c = 0; c < 3; ++c) px[static_cast<std::size_t>(3 * t + c)] = value(1, t, c);
    px[5] = std::nextafter(px[5], 10.0f);  // one low bit of one value
    cmfilter_test::write_image(image, 2, 2, 3, OIIO::TypeDesc::FLOAT, px.data());
    auto after = load_synthesis_sample(options, config);
    REQUIRE(after);
    CHECK(after->hash != before->hash);
    CHECK(after->hash.size() == 64);
}

TEST_CASE("synthesis sample: farthest-point selection picks the images worked out by hand")
{
    // Image k: 2 x 2 grey RGB, texel 0 holding a_k in every channel, the rest 0.
    // Its variance is 3 a_k^2 / 16 and the squared distance of images j and k
    // 3 (a_j - a_k)^2: the first pick is a = 9 (image 4), then the farthest
    // from it, a = 0 (image 0); then a = 5 (image 2) and a = 4 (image 5) are
    // both 16 from the nearest chosen: the lower index, image 2.
    const auto config = cmfilter_test::builtin_color_config();
    const float a[6] = {0, 1, 5, 2, 9, 4};
    std::string lp = "6\n";
    for (int k = 0; k < 6; ++k) {
        std::vector<float> px(12, 0.0f);
        px[0] = px[1] = px[2] = a[k];
        const std::string file = "select-" + std::to_string(k) + ".exr";
        cmfilter_test::write_image(kDir + "/" + file, 2, 2, 3, OIIO::TypeDesc::FLOAT, px.data());
        lp += file + " 0 0 1\n";
    }
    std::ofstream(kDir + "/select.lp") << lp;
    SampleOptions options;
    options.path = kDir + "/select.lp";
    options.select_images = 3;
    auto sample = load_synthesis_sample(options, config);
    REQUIRE(sample);
    CHECK(sample->images == 6);
    CHECK(sample->used == std::vector<int>{0, 2, 4});
    CHECK(sample->dims == 9);
    CHECK(sample->levels[0].feature(0, 9)[3] == 5.0f);
    CHECK(sample->levels[0].feature(0, 9)[6] == 9.0f);
    options.select_images = 10;  // more than the sample holds: all
    auto all = load_synthesis_sample(options, config);
    REQUIRE(all);
    CHECK(all->used.size() == 6);
}

TEST_CASE("synthesis sample: a pyramid level is the 2 x 2 mean, an odd edge repeating its last texel")
{
    // 5 x 3, two dimensions: f(x, y) = (x + 10 y, x * y).
    std::vector<float> f;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) f.insert(f.end(), {float(x + 10 * y), float(x * y)});
    auto sample = sample_from_features(5, 3, 2, f, 2);
    REQUIRE(sample);
    REQUIRE(sample->levels.size() == 2);
    const SampleLevel& l1 = sample->levels[1];
    CHECK(l1.width == 3);
    CHECK(l1.height == 2);
    // (0, 0): texels (0,0) (1,0) (0,1) (1,1): (0 + 1 + 10 + 11) / 4, (0 + 0 + 0 + 1) / 4.
    CHECK(l1.feature(0, 2)[0] == doctest::Approx(5.5));
    CHECK(l1.feature(0, 2)[1] == doctest::Approx(0.25));
    // (2, 0): x = 4 repeated: (4 + 4 + 14 + 14) / 4, (0 + 0 + 4 + 4) / 4.
    CHECK(l1.feature(2, 2)[0] == doctest::Approx(9.0));
    CHECK(l1.feature(2, 2)[1] == doctest::Approx(2.0));
    // (1, 1): y = 2 repeated: (22 + 23 + 22 + 23) / 4, (4 + 6 + 4 + 6) / 4.
    CHECK(l1.feature(4, 2)[0] == doctest::Approx(22.5));
    CHECK(l1.feature(4, 2)[1] == doctest::Approx(5.0));
    // (2, 1): texel (4, 2) four times.
    CHECK(l1.feature(5, 2)[0] == doctest::Approx(24.0));
    CHECK(l1.feature(5, 2)[1] == doctest::Approx(8.0));
}

TEST_CASE("synthesis sample: bad inputs are refused, naming the file, field and value")
{
    const auto config = cmfilter_test::builtin_color_config();
    SampleOptions options;
    options.path = write_stack("bad", 2, 4, 4);
    options.levels = 0;
    auto r = load_synthesis_sample(options, config);
    REQUIRE_FALSE(r);
    CHECK(r.error().field == "SampleOptions::levels");
    options.levels = 3;  // 4 x 4, 2 x 2, 1 x 1
    r = load_synthesis_sample(options, config);
    REQUIRE_FALSE(r);
    CHECK(r.error().field == "SampleOptions::levels");
    CHECK(r.error().message.find("1 x 1") != std::string::npos);
    options.levels = 2;
    CHECK(load_synthesis_sample(options, config));
    options.select_images = -1;
    r = load_synthesis_sample(options, config);
    REQUIRE_FALSE(r);
    CHECK(r.error().field == "SampleOptions::select_images");
    options.select_images = 0;

    // Images of different sizes: both files named.
    std::vector<float> px(3 * 3 * 3, 0.25f);
    cmfilter_test::write_image(kDir + "/bad-1.exr", 3, 3, 3, OIIO::TypeDesc::FLOAT, px.data());
    r = load_synthesis_sample(options, config);
    REQUIRE_FALSE(r);
    CHECK(r.error().kind == ErrorKind::BadInput);
    CHECK(r.error().message.find("bad-0.exr") != std::string::npos);
    CHECK(r.error().message.find("bad-1.exr") != std::string::npos);

    // A missing image: Io naming it.
    std::ofstream(kDir + "/missing.lp") << "1\nnot-there.exr 0 0 1\n";
    options.path = kDir + "/missing.lp";
    r = load_synthesis_sample(options, config);
    REQUIRE_FALSE(r);
    CHECK(r.error().kind == ErrorKind::Io);
    CHECK(r.error().message.find("not-there.exr") != std::string::npos);

    // A 1 x 1 image is too small to synthesise from.
    cmfilter_test::write_image(kDir + "/tiny.exr", 1, 1, 3, OIIO::TypeDesc::FLOAT, px.data());
    options.path = kDir + "/tiny.exr";
    options.levels = 1;
    r = load_synthesis_sample(options, config);
    REQUIRE_FALSE(r);
    CHECK(r.error().message.find("tiny.exr") != std::string::npos);
    CHECK(r.error().message.find("1 x 1") != std::string::npos);

    // In memory: the wrong number of values.
    auto m = sample_from_features(4, 4, 2, std::vector<float>(31, 0.0f));
    REQUIRE_FALSE(m);
    CHECK(m.error().message.find("31") != std::string::npos);
    std::vector<float> nan(32, 0.0f);
    nan[9] = std::nanf("");
    m = sample_from_features(4, 4, 2, nan);
    REQUIRE_FALSE(m);
    CHECK(m.error().message.find("non-finite") != std::string::npos);
}
