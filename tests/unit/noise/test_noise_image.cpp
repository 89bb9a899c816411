// SPDX-License-Identifier: Apache-2.0
// noise-image: the noise sampled at pixel centres, written as a float EXR driver.
#include "cmfilter/io/image_reading.h"
#include "cmfilter/noise/noise_image.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>

using namespace cmfilter;

TEST_CASE("noise image holds the noise at pixel centres")
{
    NoiseImageOptions o;
    auto spec = parse_noise_spec("fbm:base=value,octaves=3,seed=9");
    REQUIRE(spec);
    o.spec = *spec;
    o.width = 7;
    o.height = 5;
    o.scale = 0.3;
    auto noise = make_noise(o.spec);
    REQUIRE(noise);
    const std::string path = (std::filesystem::temp_directory_path() / "cmfilter-test-noise.exr").string();
    REQUIRE(write_noise_image(path, o));
    auto image = read_image(path);
    REQUIRE(image);
    CHECK(image->channels == 1);
    CHECK(image->channel_names.at(0) == "Y");
    CHECK(image->pixel_type == "float");
    for (int j = 0; j < o.height; ++j)
        for (int i = 0; i < o.width; ++i) {
            // Stored as float32: the value rounded to float exactly.
            const float want = static_cast<float>((*noise)(0.3 * (i + 0.5), 0.3 * (j + 0.5)));
            CHECK(image->pixels[static_cast<std::size_t>(j * o.width + i)] == want);
        }
    std::remove(path.c_str());
}

TEST_CASE("noise image rejects a bad size and scale")
{
    NoiseImageOptions o;
    o.width = 0;
    CHECK(render_noise_image(o).error().kind == ErrorKind::BadInput);
    o.width = 4;
    o.scale = -1;
    CHECK(render_noise_image(o).error().message.find("scale") != std::string::npos);
}
