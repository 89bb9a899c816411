# SPDX-License-Identifier: Apache-2.0
"""A scene file with absolute paths and its texture mapping scaled (the noise
or texture made SCALE times finer), for the benches that sweep a scene's
scale (render_scale_sweep.sh, render_sub_footprints.sh).

    python3 tests/bench/scaled_scene.py SOURCE.json TARGET.json SCALE
"""
import json
import os
import sys

source, target, scale = sys.argv[1], sys.argv[2], float(sys.argv[3])
folder = os.path.dirname(os.path.abspath(source))
scene = json.load(open(source))
for surface in scene["surfaces"]:
    mapping = surface["mapping"]
    if mapping["type"] == "planar":
        mapping["u_axis"] = [scale * x for x in mapping["u_axis"]]
        mapping["v_axis"] = [scale * x for x in mapping["v_axis"]]
    else:
        mapping["u_scale"] *= scale
        mapping["v_scale"] *= scale
    material = surface["material"]
    for part, key in (("colormap", "image"), ("colormap", "table"), ("driver", "sigma_table"),
                      ("driver", "image"), ("driver", "moments")):
        if key in material[part]:
            material[part][key] = os.path.normpath(os.path.join(folder, material[part][key]))
json.dump(scene, open(target, "w"), indent=1)
