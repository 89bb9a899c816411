// SPDX-License-Identifier: Apache-2.0
// .lp light files (light_file.h): parsing, normalisation, and every kind of
// bad file named with its line.
#include "cmfilter/stack/light_file.h"

#include "test_images.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

using namespace cmfilter;

namespace {

std::string write_text(const std::string& name, const std::string& text)
{
    const std::string path = cmfilter_test::temp_dir("cmfilter-light-file") + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

std::string error_of(const std::string& text)
{
    auto f = read_light_file(write_text("bad.lp", text));
    REQUIRE_FALSE(f);
    CHECK(f.error().kind == ErrorKind::BadInput);
    return f.error().message;
}

}  // namespace

TEST_CASE("light file: names, normalised directions and paths relative to the file")
{
    const std::string path =
        write_text("good.lp", "3\nimg_0.png 0 0 2\n\n  img_1.png\t3 4 0  \r\n/abs/img_2.png -1 -1 1\n");
    auto f = read_light_file(path);
    REQUIRE(f);
    REQUIRE(f->lights.size() == 3);
    CHECK(f->lights[0].image == "img_0.png");
    CHECK(f->lights[0].direction.z == doctest::Approx(1.0));
    CHECK(f->lights[1].direction.x == doctest::Approx(0.6));
    CHECK(f->lights[1].direction.y == doctest::Approx(0.8));
    CHECK(f->lights[1].line == 4);
    const double s = 1 / std::sqrt(3.0);
    CHECK(f->lights[2].direction.x == doctest::Approx(-s));
    CHECK(f->lights[2].direction.z == doctest::Approx(s));
    CHECK(f->image_path(0) == cmfilter_test::temp_dir("cmfilter-light-file") + "/img_0.png");
    CHECK(f->image_path(2) == "/abs/img_2.png");
}

TEST_CASE("light file: names may hold spaces, a line with a number too many is malformed")
{
    auto f = read_light_file(write_text("spaces.lp", "2\nmy img 0.5.png 0.5 0.5 0.7\nb c.png\t0 0 1\n"));
    REQUIRE(f);
    CHECK(f->lights[0].image == "my img 0.5.png");
    CHECK(f->lights[0].direction.x == doctest::Approx(0.5 / std::sqrt(0.99)));
    CHECK(f->lights[1].image == "b c.png");
    CHECK(error_of("1\na.png 0.1 0.2 0.3 0.4\n").find("line 2: expected 'image x y z'") != std::string::npos);
}

TEST_CASE("light file: what format_light_file writes reads back")
{
    std::vector<LightEntry> lights = {{"a.exr", {0.1, 0.2, std::sqrt(1 - 0.05)}, 0}, {"b.exr", {0, 0, 1}, 0}};
    const std::string text = format_light_file(lights);
    CHECK(text.rfind("2\n", 0) == 0);
    auto f = read_light_file(write_text("round.lp", text));
    REQUIRE(f);
    REQUIRE(f->lights.size() == 2);
    CHECK(f->lights[0].direction.x == doctest::Approx(0.1).epsilon(1e-8));
    CHECK(f->lights[1].image == "b.exr");
}

TEST_CASE("light file: bad files are refused naming the line and the problem")
{
    CHECK(error_of("2\na.png 0 0 1\n").find("says 2 lights but 1 follows") != std::string::npos);
    CHECK(error_of("1\na.png 0 0 1\nb.png 0 0 1\n").find("says 1 light but 2 follow") != std::string::npos);
    CHECK(error_of("x\n").find("line 1: expected the number of lights") != std::string::npos);
    CHECK(error_of("").find("is empty") != std::string::npos);
    CHECK(error_of("2\na.png 0 0 1\nb.png 0 1\n").find("line 3: expected 'image x y z'") != std::string::npos);
    CHECK(error_of("1\na.png 0,5 0 0,8\n").find("line 2: '0,5' has a decimal comma") != std::string::npos);
    CHECK(error_of("1\na.png 0 0 0\n").find("line 2: the light direction of 'a.png' is zero") != std::string::npos);
    CHECK(error_of("1\na.png 0 nan 1\n").find("line 2: the light direction of 'a.png' is not finite") !=
          std::string::npos);
    CHECK(error_of("1\na.png 0 1e999 1\n").find("line 2: '1e999' is not a number") != std::string::npos);
    CHECK(error_of("1\na.png 0.5 0 -0.1\n").find("is below the horizon") != std::string::npos);
    CHECK(error_of("1\na.png 0 0 one\n").find("'one' is not a number") != std::string::npos);
}

TEST_CASE("light file: a missing file is an I/O error")
{
    auto f = read_light_file("/nonexistent/dir/x.lp");
    REQUIRE_FALSE(f);
    CHECK(f.error().kind == ErrorKind::Io);
}

TEST_CASE("light file: images named by another machine's paths are found beside the .lp")
{
    const std::string dir = cmfilter_test::temp_dir("cmfilter-light-file-moved");
    std::filesystem::create_directories(dir + "/jpeg");
    for (const char* f : {"/img_01.jpg", "/img_02.jpg", "/jpeg/img_03.jpg"}) std::ofstream(dir + f) << "x";
    const std::string lp = dir + "/moved.lp";
    std::ofstream(lp) << "4\nC:\\capture\\jpeg\\img_01.jpg 0 0 1\n/mnt/rig/session/img_02.jpg 0 0 1\n"
                         "jpeg\\img_03.jpg 0 0 1\nC:\\capture\\gone.jpg 0 0 1\n";
    auto f = read_light_file(lp);
    REQUIRE(f);
    CHECK(f->image_path(0) == dir + "/img_01.jpg");
    CHECK(f->image_path(1) == dir + "/img_02.jpg");
    CHECK(f->image_path(2) == dir + "/jpeg/img_03.jpg");
    // Not found anywhere: the name as written, resolved, so the error names it.
    CHECK(f->image_path(3) == dir + "/C:\\capture\\gone.jpg");
}

TEST_CASE("light file: a missing relative name is not replaced by a file of the same name")
{
    const std::string dir = cmfilter_test::temp_dir("cmfilter-light-file-relative");
    std::ofstream(dir + "/img.png") << "x";
    std::ofstream(dir + "/rel.lp") << "1\nsub/img.png 0 0 1\n";
    auto f = read_light_file(dir + "/rel.lp");
    REQUIRE(f);
    CHECK(f->image_path(0) == dir + "/sub/img.png");
}
