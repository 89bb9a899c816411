// SPDX-License-Identifier: Apache-2.0
// Colour management through OpenColorIO: the config cmfilter filters with
// (built in, or a studio config from a file), name resolution with helpful
// errors, and conversions to and from its scene_linear role.
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

    // Canonical colour-space name for a name or alias, or an error that lists
    // every known name.
    Expected<std::string> resolve(const std::string& name) const;
    bool is_data(const std::string& canonical_name) const;
    std::vector<std::string> names() const;
    std::string scene_linear_name() const;
    std::string source() const { return source_; }  // "built-in" or the file path

    // In-place conversion of interleaved RGB floats.
    Status to_scene_linear(std::vector<float>& rgb, const std::string& from) const;
    Status from_scene_linear(std::vector<float>& rgb, const std::string& to) const;

private:
    struct Impl;
    std::shared_ptr<const Impl> impl_;
    std::string source_;
};

}  // namespace cmfilter
