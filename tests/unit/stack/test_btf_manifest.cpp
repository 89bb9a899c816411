// SPDX-License-Identifier: Apache-2.0
// BTF manifests (btf_manifest.h): a written manifest reads back, paths
// resolve against its folder, and bad ones are refused at their pointer.
#include "cmfilter/stack/btf_manifest.h"

#include "test_images.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>

using namespace cmfilter;

namespace {
const std::string kDir = cmfilter_test::temp_dir("cmfilter-btf-manifest");

std::string error_of(const std::string& json)
{
    std::ofstream(kDir + "/bad.json") << json;
    auto m = read_btf_manifest(kDir + "/bad.json");
    REQUIRE_FALSE(m);
    CHECK(m.error().kind == ErrorKind::BadInput);
    return m.error().message;
}
}  // namespace

TEST_CASE("BTF manifest: written, read back, directions normalised, paths resolved")
{
    const std::string path = kDir + "/btf.json";
    REQUIRE(write_btf_manifest(path, {{"view-00/stack.lp", {0, 0, 1}}, {"view-01/stack.lp", {0.6, 0, 0.8}}}));
    std::ofstream(kDir + "/raw.json")
        << R"({"format": "cmfilter-btf", "version": 1, "views": [{"lights": "a.lp", "view": [3, 0, 4]}]})";
    auto raw = read_btf_manifest(kDir + "/raw.json");
    REQUIRE(raw);
    CHECK(raw->views[0].view.x == doctest::Approx(0.6));
    CHECK(raw->light_file_path(0) == kDir + "/a.lp");
    auto m = read_btf_manifest(path);
    REQUIRE(m);
    REQUIRE(m->views.size() == 2);
    CHECK(m->views[1].view.z == doctest::Approx(0.8));
    CHECK(m->light_file_path(1) == kDir + "/view-01/stack.lp");
}

TEST_CASE("BTF manifest: bad manifests name the value")
{
    CHECK(error_of(R"({"format": "other", "version": 1, "views": []})").find("/format") != std::string::npos);
    CHECK(error_of(R"({"format": "cmfilter-btf", "version": 2, "views": []})").find("/version") != std::string::npos);
    CHECK(error_of(R"({"format": "cmfilter-btf", "version": 1, "views": []})").find("non-empty array") !=
          std::string::npos);
    CHECK(error_of(R"({"format": "cmfilter-btf", "version": 1, "views": [{"lights": "a.lp", "view": [1, 0, 0]}]})")
              .find("/views/0/view: expected a view direction above the surface") != std::string::npos);
    CHECK(error_of(R"({"format": "cmfilter-btf", "version": 1, "views": [{"lights": "a.lp", "view": [0, 0, 0]}]})")
              .find("nonzero") != std::string::npos);
    // A view slot without its view direction.
    CHECK(error_of(R"({"format": "cmfilter-btf", "version": 1, "views": [{"lights": "a.lp"}]})")
              .find("/views/0/view: required key is missing") != std::string::npos);
    CHECK(error_of(R"({"format": "cmfilter-btf", "version": 1, "views": [{"view": [0, 0, 1]}]})")
              .find("/views/0/lights: required key is missing") != std::string::npos);
}
