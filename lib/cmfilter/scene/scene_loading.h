// SPDX-License-Identifier: Apache-2.0
// Reading a scene file (docs/scene-format.md) into a Scene: JSON parsed with
// nlohmann-json, then checked key by key. Every error is BadInput and names
// the file and the JSON path of the offending value (e.g.
// "scene.json: /surfaces/1/radius: expected a number > 0, got -2"): malformed
// JSON (with line and column), unknown keys, wrong types, missing required
// keys, zero or parallel camera vectors, resolution 0 or above the limits in
// scene.h, a referenced file that does not exist. Relative paths in the file
// are resolved against the scene file's folder.
#pragma once

#include "cmfilter/util/error.h"
#include "cmfilter/scene/scene.h"

#include <string>

namespace cmfilter {

Expected<Scene> load_scene(const std::string& path);

// The same from text already read; `path` names it in messages and is the
// base for relative paths.
Expected<Scene> parse_scene(const std::string& json_text, const std::string& path);

}  // namespace cmfilter
