// SPDX-License-Identifier: Apache-2.0
// Scene files (scene/scene_loading.h): any text as a scene's JSON, and the
// sigma ranges a tolerance render derives from a parsed scene.
#include "support/fuzz_checks.h"

#include "cmfilter/scene/scene_loading.h"

#include <string>

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (auto scene = parse_scene(text, "/nonexistent/fuzz/scene.json")) {
        fuzz::require(scene->camera.width > 0 && scene->camera.height > 0, "a parsed scene has a positive resolution");
    }
    return 0;
}
