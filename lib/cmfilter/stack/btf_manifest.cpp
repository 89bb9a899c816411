// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/btf_manifest.h"

#include "cmfilter/io/json_document.h"
#include "cmfilter/io/json_reading.h"
#include "cmfilter/util/atomic_output.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace cmfilter {

namespace {

constexpr int kManifestVersion = 1;

std::string folder_of(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

Expected<BtfView> read_view(const JsonValue& value)
{
    auto object = JsonObject::read(value, {"lights", "view"});
    if (!object) return object.error();
    BtfView view;
    if (auto st = object->read_required("lights", view.lights, read_string); !st) return st.error();
    auto direction = object->require("view");
    if (!direction) return direction.error();
    auto numbers = read_numbers(*direction, 3);
    if (!numbers) return numbers.error();
    const Vec3 d{(*numbers)[0], (*numbers)[1], (*numbers)[2]};
    const double len = length(d);
    if (!(len > 0) || !std::isfinite(len)) return direction->expected("a nonzero view direction [x, y, z]");
    view.view = d / len;
    if (!(view.view.z > 0)) return direction->expected("a view direction above the surface (z > 0)");
    return view;
}

}  // namespace

std::string BtfManifest::light_file_path(std::size_t k) const
{
    const std::string& name = views.at(k).lights;
    if (!name.empty() && name[0] == '/') return name;
    return folder_of(path) + name;
}

Expected<BtfManifest> read_btf_manifest(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) return io_error("cannot read BTF manifest '" + path + "': no such file or not readable");
    std::ostringstream text;
    text << in.rdbuf();
    auto document = parse_json_document(text.str(), path);
    if (!document) return document.error();
    const JsonValue root(*document, path);
    auto object = JsonObject::read(root, {"format", "version", "views"});
    if (!object) return object.error();
    auto format = object->require("format");
    if (!format) return format.error();
    if (!format->json().is_string() || format->json().get<std::string>() != "cmfilter-btf")
        return format->expected("\"cmfilter-btf\"");
    auto version = object->require("version");
    if (!version) return version.error();
    if (!version->json().is_number_integer() || version->json().get<long long>() != kManifestVersion)
        return version->expected("version " + std::to_string(kManifestVersion));
    auto views = object->require("views");
    if (!views) return views.error();
    if (!views->json().is_array() || views->json().empty()) return views->expected("a non-empty array of views");
    BtfManifest manifest;
    manifest.path = path;
    for (std::size_t i = 0; i < views->json().size(); ++i) {
        auto view = read_view(views->element(i));
        if (!view) return view.error();
        manifest.views.push_back(std::move(*view));
    }
    return manifest;
}

Status write_btf_manifest(const std::string& path, const std::vector<BtfView>& views)
{
    nlohmann::json doc;
    doc["format"] = "cmfilter-btf";
    doc["version"] = kManifestVersion;
    doc["views"] = nlohmann::json::array();
    for (const BtfView& v : views)
        doc["views"].push_back({{"lights", v.lights}, {"view", {v.view.x, v.view.y, v.view.z}}});
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();
    {
        std::ofstream f(out->temp_path(), std::ios::binary);
        f << doc.dump(2) << "\n";
        f.close();
        if (!f) return out->write_error("the BTF manifest could not be written");
    }
    return out->commit();
}

}  // namespace cmfilter
