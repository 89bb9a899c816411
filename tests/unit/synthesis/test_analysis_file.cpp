// SPDX-License-Identifier: Apache-2.0
// Analysis files (analysis_file.h): an exact round trip, and files written
// here by hand in the documented layout with one thing wrong, each refused
// with a message naming the file.
#include "cmfilter/synthesis/analysis_file.h"

#include "test_images.h"

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <filesystem>
#include <random>

using namespace cmfilter;

namespace {

const std::string kDir = cmfilter_test::temp_dir("cmfilter-analysis-file");

SampleAnalysis small_analysis()
{
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<float> f(10 * 8 * 4);
    for (float& v : f) v = unit(rng);
    auto sample = sample_from_features(10, 8, 4, f, 2, true);
    REQUIRE(sample);
    AnalysisOptions options;
    options.candidates = 3;
    options.neighbourhood = 1;
    auto analysis = analyse_sample(*sample, options);
    REQUIRE(analysis);
    analysis->sample_path = "sample.lp";
    analysis->sample_kind = SampleKind::Stack;
    analysis->sample_images = 7;
    analysis->images_used = 2;
    analysis->channels = 2;
    return *analysis;
}

// One level (2 x 2 texels, 2 textons, 1 candidate) in the documented layout,
// written without the library's writer.
struct HandFile {
    std::string kind = "synthesis-analysis";
    float texton[4] = {0, 1, 1, 0};
    float candidate[4] = {1, 0, 3, 2};
    float dot[4] = {1, 0.5f, 0.5f, 2};
};

std::string write_by_hand(const std::string& name, const HandFile& h)
{
    const std::string path = kDir + "/" + name;
    OIIO::ImageSpec texels(2, 2, 2, OIIO::TypeDesc::FLOAT);
    texels.channelnames = {"texton", "c0"};
    texels.attribute("oiio:subimagename", "level-0-texels");
    texels.attribute("cmfilter:kind", h.kind);
    texels.attribute("cmfilter:format_version", 1);
    texels.attribute("cmfilter:levels", 1);
    texels.attribute("cmfilter:sample", "s.exr");
    texels.attribute("cmfilter:sample_kind", "image");
    texels.attribute("cmfilter:sample_hash", std::string(64, 'a'));
    texels.attribute("cmfilter:sample_images", 1);
    texels.attribute("cmfilter:images_used", 1);
    texels.attribute("cmfilter:channels", 3);
    texels.attribute("cmfilter:periodic", 0);
    texels.attribute("cmfilter:neighbourhood", 0);
    double seconds = 0.5, inertia = 1.0;
    texels.attribute("cmfilter:seconds", OIIO::TypeDesc::DOUBLE, &seconds);
    texels.attribute("cmfilter:inertia", OIIO::TypeDesc::DOUBLE, &inertia);
    texels.attribute("cmfilter:textons", 2);
    texels.attribute("cmfilter:candidates", 1);
    OIIO::ImageSpec dot(2, 2, 1, OIIO::TypeDesc::FLOAT);
    dot.channelnames = {"M"};
    dot.attribute("oiio:subimagename", "level-0-dot");
    float tp[8];
    for (int t = 0; t < 4; ++t) {
        tp[2 * t] = h.texton[t];
        tp[2 * t + 1] = h.candidate[t];
    }
    OIIO::ImageSpec specs[2] = {texels, dot};
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    REQUIRE(out->open(path, 2, specs));
    REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, tp));
    REQUIRE(out->open(path, dot, OIIO::ImageOutput::AppendSubimage));
    REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, h.dot));
    REQUIRE(out->close());
    return path;
}

void check_refused(const std::string& path, const std::string& text)
{
    auto r = read_analysis_exr(path);
    REQUIRE_FALSE(r);
    CHECK(r.error().kind == ErrorKind::BadInput);
    CHECK_MESSAGE(r.error().message.find(path) != std::string::npos, r.error().message);
    CHECK_MESSAGE(r.error().message.find(text) != std::string::npos, r.error().message);
}

}  // namespace

TEST_CASE("analysis file: a written analysis reads back exactly")
{
    const SampleAnalysis a = small_analysis();
    const std::string path = kDir + "/round-trip.exr";
    const Status written = write_analysis_exr(path, a);
    REQUIRE_MESSAGE(written, (written ? std::string() : written.error().message));
    auto b = read_analysis_exr(path);
    REQUIRE(b);
    CHECK(cmfilter_test::same_file_path(b->sample_path, a.sample_path));
    CHECK(b->sample_hash == a.sample_hash);
    CHECK(b->sample_kind == SampleKind::Stack);
    CHECK(b->sample_images == 7);
    CHECK(b->images_used == 2);
    CHECK(b->channels == 2);
    CHECK(b->periodic);
    CHECK(b->neighbourhood == 1);
    CHECK(b->seconds == 0.0);  // not recorded: the same inputs give the same bytes
    REQUIRE(b->levels.size() == 2);
    for (std::size_t l = 0; l < 2; ++l) {
        const LevelAnalysis &x = a.levels[l], &y = b->levels[l];
        CHECK(y.width == x.width);
        CHECK(y.height == x.height);
        CHECK(y.textons == x.textons);
        CHECK(y.candidates == x.candidates);
        CHECK(y.texton == x.texton);
        CHECK(y.similar == x.similar);
        CHECK(y.dot == x.dot);
        CHECK(y.inertia == x.inertia);
    }
}

TEST_CASE(
    "analysis file: files written by hand in the documented layout with one value wrong are refused, naming the file")
{
    HandFile good;
    // A valid layout, except for neighbourhood 0, which is refused last.
    check_refused(write_by_hand("neighbourhood.exr", good), "cmfilter:neighbourhood 0");

    HandFile texton = good;
    texton.texton[2] = 2;  // only textons 0 and 1 exist
    check_refused(write_by_hand("texton.exr", texton), "texton index 2");

    HandFile candidate = good;
    candidate.candidate[1] = 4;  // 4 texels: 0 .. 3
    check_refused(write_by_hand("candidate.exr", candidate), "candidate texel index 4");

    HandFile itself = good;
    itself.candidate[3] = 3;
    check_refused(write_by_hand("itself.exr", itself), "not the texel itself");

    HandFile fraction = good;
    fraction.candidate[0] = 1.5f;
    check_refused(write_by_hand("fraction.exr", fraction), "non-integral");

    HandFile asymmetric = good;
    asymmetric.dot[1] = 0.25f;
    check_refused(write_by_hand("asymmetric.exr", asymmetric), "non-symmetric");

    HandFile kind = good;
    kind.kind = "linear-fit";
    check_refused(write_by_hand("kind.exr", kind), "is not a cmfilter synthesis analysis");
}

TEST_CASE("analysis file: a missing file is an Io error, and an unwritable path leaves nothing")
{
    auto r = read_analysis_exr(kDir + "/missing.exr");
    REQUIRE_FALSE(r);
    CHECK(r.error().kind == ErrorKind::Io);
    CHECK(r.error().message.find("missing.exr") != std::string::npos);
    const std::string bad = kDir + "/no-such-dir/a.exr";
    auto st = write_analysis_exr(bad, small_analysis());
    REQUIRE_FALSE(st);
    CHECK(st.error().kind == ErrorKind::Io);
    CHECK_FALSE(std::filesystem::exists(bad));
}

TEST_CASE("analysis file: an analysis of another sample is refused, naming both files and both hashes")
{
    SampleAnalysis a = small_analysis();
    auto other = sample_from_features(10, 8, 2, std::vector<float>(160, 0.5f));
    REQUIRE(other);
    other->path = "other.exr";
    other->used = {0, 1};
    other->channels = 2;
    auto st = check_analysis_matches(a, "a.exr", *other);
    REQUIRE_FALSE(st);
    CHECK(st.error().kind == ErrorKind::BadInput);
    for (const std::string& s :
         {std::string("a.exr"), std::string("sample.lp"), std::string("other.exr"), a.sample_hash, other->hash})
        CHECK_MESSAGE(st.error().message.find(s) != std::string::npos, st.error().message);
    other->hash = a.sample_hash;
    CHECK(check_analysis_matches(a, "a.exr", *other));
}
