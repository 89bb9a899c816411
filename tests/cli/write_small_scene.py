#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes a copy of a scene file at another resolution, its relative file
paths made absolute (against the scene's own folder) so that the copy can
stand anywhere: python3 write_small_scene.py SCENE OUT WIDTH HEIGHT."""
import json
import os
import sys

PATH_KEYS = ("image", "table", "moments", "sigma_table")


def absolute_paths(value, folder):
    if isinstance(value, dict):
        return {k: (os.path.normpath(os.path.join(folder, v)) if k in PATH_KEYS and isinstance(v, str)
                    else absolute_paths(v, folder)) for k, v in value.items()}
    if isinstance(value, list):
        return [absolute_paths(v, folder) for v in value]
    return value


def main():
    source, out, width, height = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    with open(source) as f:
        scene = json.load(f)
    scene = absolute_paths(scene, os.path.dirname(os.path.abspath(source)))
    scene["camera"]["resolution"] = [width, height]
    with open(out, "w") as f:
        json.dump(scene, f, indent=2)
    print(f"wrote {out}: {source} at {width} x {height}")


if __name__ == "__main__":
    main()
