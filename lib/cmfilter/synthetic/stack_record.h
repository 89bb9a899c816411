// SPDX-License-Identifier: Apache-2.0
// The record of a synthetic stack (make_stack.h), a JSON file beside its
// light file (stack.lp -> stack.json) holding every parameter it was made
// with, so that the same surface can be rendered again under other lights
// (ground truth at held-out lights):
//   {"format": "cmfilter-synthetic-stack", "version": 1,
//    "cmfilter_version": "...",
//    "scene": "/abs/scene.json", "scene_sha256": "<64 hex>",
//    "surface": 0, "surface_kind": "microsurface" | "displacement",
//    "tile": 0.8,                       texture units
//    "view": [x, y, z],                 unit, stack frame
//    "view_slot": 0, "view_slots": 1,
//    "size": 64, "samples": 16, "seed": 0,
//    "specular": "ggx:ks=0.04,alpha=0.2" (specular_lobe.h),
//    "dome": {"spec": "fibonacci:64", "min_elevation_degrees": 10, "count": 64},
//    "lights": "stack.lp", "images": ".exr",
//    "normals": "stack.normals.exr", "albedo": "stack.albedo.exr" | null,
//    "frame": "...", "shading": "...",     words, for a reader
//    "rays": N, "hits": N}
// Paths are relative to the record's folder (the scene's too, since
// io/recorded_path.h; an absolute scene path, as older records hold, is read
// as it is).
// make_stack writes it; this file reads it back.
#pragma once

#include "cmfilter/synthetic/make_stack.h"
#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

// The options the record's stack was made with: scene, surface, its one
// view, size, samples, seed, specular lobe, image extension, albedo (the
// dome and output are the caller's). BadInput naming the file and the JSON
// pointer of a missing or bad value, a record of another format or
// version, or a scene whose SHA-256 is no longer the recorded one (the
// ground truth would be another surface's). Io when the record or the
// scene cannot be read.
Expected<MakeStackOptions> read_stack_record(const std::string& path);

}  // namespace cmfilter
