// SPDX-License-Identifier: Apache-2.0
// Colour management through OpenColorIO: the config cmfilter filters with
// (built in, or a studio config from a file), name resolution with helpful
// errors, the defaults the config itself gives (roles and file rules), and
// conversions to and from its scene_linear role.
// Colour maps are converted to scene-linear on load; drivers are data and
// never pass through here.
#pragma once

#include "cmfilter/util/error.h"

#include <memory>
#include <string>
#include <vector>

namespace cmfilter {

class ColorConfig {
public:
    // path empty: the config compiled into libcmfilter (lib/ocio/config.ocio).
    static Expected<ColorConfig> load(const std::string& path);

    // Canonical colour-space name for a name, alias or role of this config;
    // else, for a name cmfilter's built-in config knows (as cmfilter's own
    // files and OpenImageIO record them: "Linear Rec.709", "sRGB",
    // "lin_ap1_scene"), the first of that space's names and aliases this
    // config knows ("sRGB" -> "sRGB - Texture" in an ACES config); else an
    // error that lists every known name.
    Expected<std::string> resolve(const std::string& name) const;

    // The canonical colour space of a role ("scene_linear", "color_picking",
    // "data", "default", ...), or empty when the config has no such role.
    std::string role_space(const std::string& role) const;

    // The colour space the config's file rules give `path`, when a rule
    // other than the Default rule matches it; empty otherwise.
    std::string file_rule_space(const std::string& path) const;

    // The config's sRGB-encoded texture space: the space cmfilter's built-in
    // "sRGB" resolves to (resolve), else the color_picking role. Integer
    // images are decoded with it by default, and display formats (PNG,
    // JPEG) are encoded with it. An error naming the config when it has
    // neither.
    Expected<std::string> srgb_texture_name() const;

    // An identifier other tools read for a canonical colour space of this
    // config: the colour interop ID ("lin_rec709_scene", "lin_ap1_scene",
    // ...) of the built-in space it is the same as by name or alias; empty
    // when there is none.
    std::string interop_id(const std::string& canonical_name) const;
    bool is_data(const std::string& canonical_name) const;
    std::vector<std::string> names() const;
    std::string scene_linear_name() const;
    std::string source() const { return source_; }  // "built-in" or the file path

    // In-place conversion of interleaved RGB floats; the name as resolve
    // takes it.
    Status to_scene_linear(std::vector<float>& rgb, const std::string& from) const;
    Status from_scene_linear(std::vector<float>& rgb, const std::string& to) const;

private:
    struct Impl;
    std::shared_ptr<const Impl> impl_;
    std::string source_;
};

}  // namespace cmfilter
