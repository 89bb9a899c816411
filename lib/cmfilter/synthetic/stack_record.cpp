// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthetic/stack_record.h"

#include "cmfilter/io/recorded_path.h"
#include "cmfilter/io/json_document.h"
#include "cmfilter/io/json_reading.h"
#include "cmfilter/util/sha256.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace cmfilter {

namespace {

using json = nlohmann::json;

Expected<JsonValue> member(const JsonValue& object, const std::string& key)
{
    if (!object.json().contains(key)) return object.member_error(key, "required key is missing");
    return object.member(key);
}

Expected<long long> read_integer(const JsonValue& object, const std::string& key, long long lo, long long hi)
{
    auto v = member(object, key);
    if (!v) return v.error();
    const json& j = v->json();
    if (!j.is_number_integer() || j.get<long long>() < lo || j.get<long long>() > hi)
        return v->expected("an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
    return j.get<long long>();
}

Expected<std::string> read_string(const JsonValue& object, const std::string& key)
{
    auto v = member(object, key);
    if (!v) return v.error();
    if (!v->json().is_string()) return v->expected("a string");
    return v->json().get<std::string>();
}

}  // namespace

Expected<MakeStackOptions> read_stack_record(const std::string& path)
{
    std::ifstream f(path);
    if (!f) return io_error(path + ": cannot open the stack record");
    std::stringstream text;
    text << f.rdbuf();
    auto document = parse_json_document(text.str(), path);
    if (!document) return document.error();
    const JsonValue root(*document, path);
    if (!root.json().is_object()) return root.expected("a cmfilter-synthetic-stack record (a JSON object)");
    auto format = read_string(root, "format");
    if (!format) return format.error();
    if (*format != "cmfilter-synthetic-stack") return root.member("format").expected("\"cmfilter-synthetic-stack\"");
    auto version = read_integer(root, "version", 1, 1000000);
    if (!version) return version.error();
    if (*version != kStackRecordVersion)
        return root.member("version").expected("version " + std::to_string(kStackRecordVersion));

    MakeStackOptions o;
    auto scene = read_string(root, "scene");
    if (!scene) return scene.error();
    o.scene = path_from_record(*scene, path);
    auto digest = read_string(root, "scene_sha256");
    if (!digest) return digest.error();
    auto now = sha256_file_hex(o.scene);
    if (!now) return prefixed(path + ": /scene: ", now.error());
    if (*now != *digest)
        return bad_input(path + ": /scene_sha256: the scene " + o.scene +
                         " has changed since the stack was made (SHA-256 " + *now + ", recorded " + *digest +
                         "): its ground truth would be another surface's");
    auto surface = read_integer(root, "surface", 0, 1 << 20);
    if (!surface) return surface.error();
    o.surface = static_cast<std::size_t>(*surface);

    auto view = member(root, "view");
    if (!view) return view.error();
    const json& v = view->json();
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
        return view->expected("a direction [x, y, z]");
    o.views = {{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}};

    auto size = read_integer(root, "size", 1, 1 << 30);
    if (!size) return size.error();
    o.size = static_cast<int>(*size);
    auto samples = read_integer(root, "samples", 1, 1 << 30);
    if (!samples) return samples.error();
    o.samples = static_cast<int>(*samples);
    auto seed = member(root, "seed");
    if (!seed) return seed.error();
    if (!seed->json().is_number_unsigned() && !(seed->json().is_number_integer() && seed->json().get<long long>() >= 0))
        return seed->expected("an integer >= 0");
    o.seed = seed->json().get<std::uint64_t>();

    auto specular = read_string(root, "specular");
    if (!specular) return specular.error();
    auto lobe = parse_specular_lobe(*specular);
    if (!lobe) return prefixed(path + ": /specular: ", lobe.error());
    o.specular = *lobe;

    auto images = read_string(root, "images");
    if (!images) return images.error();
    o.image_extension = *images;
    auto albedo = member(root, "albedo");
    if (!albedo) return albedo.error();
    if (!albedo->json().is_null() && !albedo->json().is_string()) return albedo->expected("a file name or null");
    o.albedo = albedo->json().is_string();
    return o;
}

}  // namespace cmfilter
