// SPDX-License-Identifier: Apache-2.0
// A BTF: several view slots of one surface, each an image stack (its `.lp`
// light file, light_file.h) seen from one view direction, named by a small
// JSON manifest (docs/stacks.md#btf-manifest):
//     {"format": "cmfilter-btf", "version": 1,
//      "views": [{"lights": "view-00/stack.lp", "view": [0, 0, 1]},
//                {"lights": "view-01/stack.lp", "view": [0.5, 0, 0.866]}]}
// Paths are relative to the manifest's folder; view directions point from
// the surface towards the camera in the stack's frame (x right, y up, z out
// of the surface) and are normalised on read.
#pragma once

#include "cmfilter/math/vec3.h"
#include "cmfilter/util/error.h"

#include <string>
#include <vector>

namespace cmfilter {

struct BtfView {
    std::string lights;  // the view slot's .lp, as written
    Vec3 view;           // unit, z > 0
};

struct BtfManifest {
    std::string path;  // the manifest read
    std::vector<BtfView> views;
    std::string light_file_path(std::size_t k) const;  // resolved against the manifest's folder
};

// BadInput naming the file and the JSON pointer of the bad value: not a
// cmfilter-btf manifest of a known version, no views, a view whose
// direction is zero, non-finite or not above the horizon (z <= 0).
Expected<BtfManifest> read_btf_manifest(const std::string& path);
Status write_btf_manifest(const std::string& path, const std::vector<BtfView>& views);

}  // namespace cmfilter
