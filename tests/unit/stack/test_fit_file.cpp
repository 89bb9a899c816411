// SPDX-License-Identifier: Apache-2.0
// Linear fit EXR files: an exact round trip of every model, the channels
// as OpenImageIO sees them, and the reader's errors on files written here
// with OpenImageIO directly.
#include "cmfilter/stack/fit_file.h"

#include "test_images.h"

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

LinearFit random_fit(std::mt19937_64& rng, LinearModel model, int channels)
{
    std::uniform_real_distribution<float> coefficient(-3, 3);
    LinearFit fit;
    fit.model = model;
    fit.width = 5;
    fit.height = 4;
    fit.channels = channels;
    fit.encoding = StackEncoding::DisplayEncoded;
    fit.colorspace = "sRGB - Texture";
    fit.conditioning.lights = 40;
    fit.conditioning.terms = basis_terms(model);
    fit.conditioning.largest_singular = 4.25;
    fit.conditioning.smallest_singular = 0.125;
    fit.conditioning.condition_number = 34;
    fit.coefficients.resize(fit.texels() * static_cast<std::size_t>(fit.stride()));
    for (float& v : fit.coefficients) v = coefficient(rng);
    return fit;
}

// A float EXR with the given channels and cmfilter:* attributes, written
// with OpenImageIO alone.
void write_exr(const std::string& path, const std::vector<std::string>& names, const std::vector<float>& pixels,
               const std::vector<std::pair<std::string, std::string>>& text, int channels_attribute)
{
    const int w = 2, h = 1;
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    OIIO::ImageSpec spec(w, h, static_cast<int>(names.size()), OIIO::TypeDesc::FLOAT);
    spec.channelnames = names;
    for (const auto& [k, v] : text) spec.attribute(k, v);
    spec.attribute("cmfilter:format_version", 1);
    spec.attribute("cmfilter:channels", channels_attribute);
    REQUIRE(pixels.size() == names.size() * w * h);
    REQUIRE(out->open(path, spec));
    REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    REQUIRE(out->close());
}

std::vector<std::string> ptm_rgb_names()
{
    std::vector<std::string> names;
    for (const char* c : {"R", "G", "B"})
        for (int k = 0; k < 6; ++k) names.push_back(std::string(c) + ".a" + std::to_string(k));
    return names;
}

std::string read_error(const std::string& path, ErrorKind kind = ErrorKind::BadInput)
{
    auto fit = read_fit_exr(path);
    if (fit) return "(read)";
    CHECK(fit.error().kind == kind);
    return fit.error().message;
}

}  // namespace

TEST_CASE("fit file: every model round trips exactly with its metadata")
{
    const std::string dir = cmfilter_test::temp_dir("cmfilter_fit_file");
    std::mt19937_64 rng(7);
    struct Case {
        LinearModel model;
        int channels;
    };
    for (Case c : {Case{LinearModel::PtmRgb, 3}, Case{LinearModel::PtmLrgb, 3}, Case{LinearModel::PtmLrgb, 1},
                   Case{LinearModel::Hsh2, 4}, Case{LinearModel::Hsh3, 1}}) {
        const std::string model_name = to_string(c.model);
        CAPTURE(model_name);
        CAPTURE(c.channels);
        const LinearFit fit = random_fit(rng, c.model, c.channels);
        const std::string path = dir + "/fit.exr";
        FitFileInfo info;
        info.source = "stacks/dome.lp";
        info.extra = {{"cmfilter:fit_seconds", "0.25"}, {"note", "hello"}};
        REQUIRE(write_fit_exr(path, fit, info));
        FitFileInfo back_info;
        auto back = read_fit_exr(path, &back_info);
        REQUIRE(back);
        CHECK(back->model == fit.model);
        CHECK(back->width == fit.width);
        CHECK(back->height == fit.height);
        CHECK(back->channels == fit.channels);
        CHECK(back->encoding == StackEncoding::DisplayEncoded);
        CHECK(back->colorspace == "sRGB - Texture");
        CHECK(back->coefficients == fit.coefficients);
        CHECK(back->conditioning.lights == 40);
        CHECK(back->conditioning.terms == basis_terms(c.model));
        CHECK(back->conditioning.largest_singular == 4.25);
        CHECK(back->conditioning.smallest_singular == 0.125);
        CHECK(back->conditioning.condition_number == 34);
        CHECK(back->conditioning.clamped == 0);
        CHECK(cmfilter_test::same_file_path(back_info.source, "stacks/dome.lp"));
        REQUIRE(back_info.extra.size() == 2);
        CHECK(back_info.extra[0] == std::pair<std::string, std::string>{"cmfilter:fit_seconds", "0.25"});
        CHECK(back_info.extra[1] == std::pair<std::string, std::string>{"cmfilter:note", "hello"});

        // As OpenImageIO sees it: float channels named by colour and term.
        auto in = OIIO::ImageInput::open(path);
        REQUIRE(in);
        const OIIO::ImageSpec& spec = in->spec();
        CHECK(spec.format == OIIO::TypeDesc::FLOAT);
        CHECK(spec.get_string_attribute("cmfilter:kind") == "linear-fit");
        CHECK(spec.get_string_attribute("cmfilter:model") == to_string(c.model));
        CHECK(spec.get_string_attribute("cmfilter:encoding") == "display-encoded");
        std::vector<float> pixels(fit.texels() * static_cast<std::size_t>(spec.nchannels));
        REQUIRE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
        const auto column = [&](const std::string& name) {
            for (int i = 0; i < spec.nchannels; ++i)
                if (spec.channelnames[static_cast<std::size_t>(i)] == name) return i;
            FAIL("no channel " << name);
            return -1;
        };
        const std::size_t t = 7;
        const int stride = fit.stride();
        if (c.model == LinearModel::PtmRgb) {
            CHECK(pixels[t * stride + column("G.a3")] == fit.texel(t)[6 + 3]);
            CHECK(pixels[t * stride + column("B.a5")] == fit.texel(t)[12 + 5]);
        } else if (c.model == LinearModel::PtmLrgb) {
            CHECK(pixels[t * stride + column("L.a2")] == fit.texel(t)[2]);
            CHECK(pixels[t * stride + column(c.channels == 3 ? "G" : "Y")] == fit.texel(t)[c.channels == 3 ? 7 : 6]);
        } else if (c.model == LinearModel::Hsh2) {
            CHECK(pixels[t * stride + column("A.h3")] == fit.texel(t)[3 * 4 + 3]);
        } else {
            CHECK(pixels[t * stride + column("Y.h8")] == fit.texel(t)[8]);
        }
    }
}

TEST_CASE("fit file: the writer refuses inconsistent or non-finite fits and leaves no file")
{
    const std::string dir = cmfilter_test::temp_dir("cmfilter_fit_file");
    std::mt19937_64 rng(8);
    LinearFit fit = random_fit(rng, LinearModel::PtmRgb, 3);
    const std::string path = dir + "/bad_write.exr";
    std::filesystem::remove(path);
    fit.coefficients[11] = std::nanf("");
    auto st = write_fit_exr(path, fit, {});
    REQUIRE_FALSE(st);
    CHECK(contains(st.error().message, "non-finite"));
    CHECK_FALSE(std::filesystem::exists(path));
    fit.coefficients[11] = 0;
    fit.coefficients.pop_back();
    CHECK_FALSE(write_fit_exr(path, fit, {}));
    CHECK_FALSE(std::filesystem::exists(path));
}

TEST_CASE("fit file: the reader names what is wrong with a file")
{
    const std::string dir = cmfilter_test::temp_dir("cmfilter_fit_file");
    const auto names = ptm_rgb_names();
    std::vector<float> pixels(names.size() * 2, 0.5f);
    const std::vector<std::pair<std::string, std::string>> good = {
        {"cmfilter:kind", "linear-fit"}, {"cmfilter:model", "ptm-rgb"}, {"cmfilter:encoding", "scene-linear"}};

    // The well-formed file reads, so each error below is its one change.
    write_exr(dir + "/good.exr", names, pixels, good, 3);
    auto fit = read_fit_exr(dir + "/good.exr");
    REQUIRE(fit);
    CHECK(fit->coefficients == pixels);

    write_exr(dir + "/table.exr", names, pixels,
              {{"cmfilter:kind", "gaussian-color-table"},
               {"cmfilter:model", "ptm-rgb"},
               {"cmfilter:encoding", "scene-linear"}},
              3);
    CHECK(contains(read_error(dir + "/table.exr"), "is not a cmfilter linear fit"));

    write_exr(dir + "/model.exr", names, pixels,
              {{"cmfilter:kind", "linear-fit"}, {"cmfilter:model", "ptm-xyz"}, {"cmfilter:encoding", "scene-linear"}},
              3);
    CHECK(contains(read_error(dir + "/model.exr"), "unknown linear model 'ptm-xyz'"));

    {
        auto out = OIIO::ImageOutput::create(dir + "/version.exr");
        OIIO::ImageSpec spec(2, 1, static_cast<int>(names.size()), OIIO::TypeDesc::FLOAT);
        spec.channelnames = names;
        for (const auto& [k, v] : good) spec.attribute(k, v);
        spec.attribute("cmfilter:format_version", 2);
        spec.attribute("cmfilter:channels", 3);
        REQUIRE(out->open(dir + "/version.exr", spec));
        REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
        REQUIRE(out->close());
    }
    CHECK(contains(read_error(dir + "/version.exr"), "format version 2"));

    // 18 channels but cmfilter:channels says 1 (6 expected).
    write_exr(dir + "/count.exr", names, pixels, good, 1);
    CHECK(contains(read_error(dir + "/count.exr"), "has 18 channels, expected 6"));

    // The right count with one channel misnamed.
    auto renamed = names;
    renamed[4] = "R.b4";
    write_exr(dir + "/renamed.exr", renamed, pixels, good, 3);
    CHECK(contains(read_error(dir + "/renamed.exr"), "no channel R.a4"));

    auto infinite = pixels;
    infinite[25] = INFINITY;
    write_exr(dir + "/inf.exr", names, infinite, good, 3);
    CHECK(contains(read_error(dir + "/inf.exr"), "non-finite coefficient"));

    write_exr(dir + "/encoding.exr", names, pixels,
              {{"cmfilter:kind", "linear-fit"}, {"cmfilter:model", "ptm-rgb"}, {"cmfilter:encoding", "gamma"}}, 3);
    CHECK(contains(read_error(dir + "/encoding.exr"), "unknown cmfilter:encoding 'gamma'"));

    CHECK(contains(read_error(dir + "/missing.exr", ErrorKind::Io), "missing.exr"));
}
