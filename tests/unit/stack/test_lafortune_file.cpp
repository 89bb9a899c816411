// SPDX-License-Identifier: Apache-2.0
// Lafortune fit files: written and read back bit for bit (parameters, lobe
// counts, view, metadata), and damaged files refused with the reason named.
#include "cmfilter/stack/lafortune_file.h"

#include "test_images.h"

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

using namespace cmfilter;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

LafortuneFit random_fit(LafortuneVariant variant, int channels, int lobes, std::mt19937_64& rng)
{
    std::uniform_real_distribution<float> value(-2, 2), exponent(1, 500);
    LafortuneFit fit;
    fit.variant = variant;
    fit.width = 5;
    fit.height = 3;
    fit.channels = channels;
    fit.lobes = lobes;
    fit.auto_lobes = true;
    fit.view = normalize(Vec3{0.1, -0.2, 0.9});
    fit.colorspace = "lin_rec709";
    fit.fallbacks = 7;
    fit.parameters.resize(fit.texels() * fit.stride());
    for (std::size_t i = 0; i < fit.parameters.size(); ++i) {
        const int j = static_cast<int>(i % fit.stride()) % fit.scalar_stride();
        const bool is_exponent = (variant == LafortuneVariant::Rgb || int(i % fit.stride()) < fit.scalar_stride()) &&
                                 j > 0 && (j - 1) % 4 == 3;
        fit.parameters[i] = is_exponent ? exponent(rng) : value(rng);
    }
    const int scalars = variant == LafortuneVariant::Rgb ? channels : 1;
    for (std::size_t i = 0; i < fit.texels() * scalars; ++i)
        fit.lobe_counts.push_back(static_cast<unsigned char>(i % (lobes + 1)));
    return fit;
}

// Rewrites `path` with one attribute changed (or a pixel set).
void rewrite(const std::string& path, const std::string& name, const std::string& value, int pixel = -1,
             float pixel_value = 0)
{
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    OIIO::ImageSpec spec = in->spec();
    std::vector<float> pixels(spec.image_pixels() * spec.nchannels);
    REQUIRE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    in->close();
    if (!name.empty()) spec.attribute(name, value);
    if (pixel >= 0) pixels[static_cast<std::size_t>(pixel)] = pixel_value;
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    REQUIRE(out->open(path, spec));
    REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
}

}  // namespace

TEST_CASE("lafortune file: every variant written and read back exactly")
{
    const std::string dir = cmfilter_test::temp_dir("cmfilter-lafortune-file");
    std::mt19937_64 rng(4);
    struct Case {
        LafortuneVariant variant;
        int channels, lobes;
    };
    for (const Case& c : {Case{LafortuneVariant::Luminance, 3, 7}, Case{LafortuneVariant::Luminance, 1, 2},
                          Case{LafortuneVariant::Rgb, 3, 2}, Case{LafortuneVariant::Rgb, 3, 1}}) {
        const LafortuneFit fit = random_fit(c.variant, c.channels, c.lobes, rng);
        const std::string path = dir + "/fit.exr";
        REQUIRE(write_lafortune_exr(path, fit, "stack.lp"));
        std::string source;
        const auto back = read_lafortune_exr(path, &source);
        REQUIRE(back);
        CHECK(cmfilter_test::same_file_path(source, "stack.lp"));
        CHECK(back->variant == fit.variant);
        CHECK(back->width == fit.width);
        CHECK(back->height == fit.height);
        CHECK(back->channels == fit.channels);
        CHECK(back->lobes == fit.lobes);
        CHECK(back->auto_lobes == fit.auto_lobes);
        CHECK(back->view == fit.view);
        CHECK(back->fallbacks == 7);
        CHECK(back->colorspace == fit.colorspace);
        CHECK(back->encoding == fit.encoding);
        REQUIRE(back->parameters.size() == fit.parameters.size());
        CHECK(std::memcmp(back->parameters.data(), fit.parameters.data(), fit.parameters.size() * sizeof(float)) == 0);
        CHECK(back->lobe_counts == fit.lobe_counts);
        // The histogram in the metadata, counted here.
        auto in = OIIO::ImageInput::open(path);
        REQUIRE(in);
        std::vector<long long> counts(c.lobes + 1, 0);
        for (unsigned char n : fit.lobe_counts) ++counts[n];
        std::string expected;
        for (std::size_t i = 0; i < counts.size(); ++i) expected += (i ? "," : "") + std::to_string(counts[i]);
        CHECK(in->spec().get_string_attribute("cmfilter:lobe_histogram") == expected);
        CHECK(in->spec().get_string_attribute("cmfilter:kind") == "lafortune-fit");
    }
}

TEST_CASE("lafortune file: bad fits not written, damaged files refused with the reason")
{
    const std::string dir = cmfilter_test::temp_dir("cmfilter-lafortune-file-bad");
    std::mt19937_64 rng(8);
    const std::string path = dir + "/fit.exr";
    std::filesystem::remove(path);  // a file from an earlier run
    LafortuneFit fit = random_fit(LafortuneVariant::Luminance, 3, 2, rng);
    LafortuneFit nan = fit;
    nan.parameters[3] = std::numeric_limits<float>::quiet_NaN();
    auto st = write_lafortune_exr(path, nan);
    REQUIRE_FALSE(st);
    CHECK(contains(st.error().message, "non-finite"));
    CHECK_FALSE(std::filesystem::exists(path));
    LafortuneFit below = fit;
    below.view = {0, 0, -1};
    REQUIRE_FALSE(write_lafortune_exr(path, below));
    LafortuneFit short_fit = fit;
    short_fit.parameters.pop_back();
    REQUIRE_FALSE(write_lafortune_exr(path, short_fit));

    auto refused = [&](const std::string& name, const std::string& value, const std::string& words, int pixel = -1,
                       float pixel_value = 0) {
        REQUIRE(write_lafortune_exr(path, fit));
        rewrite(path, name, value, pixel, pixel_value);
        const auto back = read_lafortune_exr(path);
        REQUIRE_FALSE(back);
        CHECK(back.error().kind == ErrorKind::BadInput);
        CHECK(contains(back.error().message, path));
        CHECK(contains(back.error().message, words));
    };
    refused("cmfilter:kind", "linear-fit", "not a cmfilter Lafortune fit");
    refused("cmfilter:format_version", "2", "format version");
    refused("cmfilter:variant", "phong", "unknown Lafortune variant 'phong'");
    refused("cmfilter:channels", "4", "cmfilter:channels 4");
    refused("cmfilter:lobes", "3", "channels, expected");
    refused("cmfilter:lobes", "9", "cmfilter:lobes 9");
    refused("cmfilter:encoding", "raw", "unknown cmfilter:encoding");
    refused("cmfilter:fallbacks", "many", "cmfilter:fallbacks");
    // Pixels: a NaN, a lobe count out of range, an exponent below 1. The
    // file's channels are sorted by name: find them.
    REQUIRE(write_lafortune_exr(path, fit));
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    const std::vector<std::string> names = in->spec().channelnames;
    const int total = in->spec().nchannels;
    in->close();
    auto index = [&](const std::string& name) {
        return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
    };
    refused("", "", "non-finite parameter (channel L.rho", index("L.rho"), std::numeric_limits<float>::infinity());
    refused("", "", "lobe count 3", total + index("L.lobes"), 3);
    refused("", "", "lobe exponent 0.5", 2 * total + index("L.1.n"), 0.5f);
}
