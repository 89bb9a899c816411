#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The snake's slope colour against view angle (docs/microsurface.md#the-snake).

A far patch of examples/scenes/snake-scales.exr (a textured displacement,
one repeat per texture unit) seen through a narrow camera at each view angle
(the light overhead, or at --light THETA,AZIMUTH degrees: from the normal,
and from the view's azimuth), coloured by luts/snake-rims.png over the slope angle,
every pixel's footprint 2 repeats wide: naive, gaussian (a Gaussian D_s of
the footprint's slope moments), exact (D_s from the texture's own slopes),
both also with --slope-shading correlated and with that and --masking
correlated, against the ray-traced reference, at the bundled relief
(height_scale 1: slopes to about 60 degrees) and at half of it (to about 40
degrees). `cmfilter compare` gives the mean CIEDE2000. Writes
WORK_DIR/snake-angles.csv and prints a Markdown table.

    python3 tests/bench/snake_angle_sweep.py BUILD_DIR WORK_DIR [--threads N] [--spp N] [--light THETA,AZIMUTH]
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import microsurface_angle_sweep as sweep  # noqa: E402

ANGLES = [0, 20, 40, 60, 70, 80, 85]
SCALES = [1.0, 0.5]
# The series of microsurface_angle_sweep.py (the plain method names are the
# paper's model, eqs. 13 and 19; render's defaults are "all-correlated").
SERIES = {name: sweep.SERIES[name] for name in [
    "naive", "gaussian", "exact", "gaussian shading-correlated", "exact shading-correlated",
    "gaussian all-correlated", "exact all-correlated"]}
METHODS = list(SERIES)
SIZE = 16
FOV_DEGREES = 0.5
FOOTPRINT = 2.0  # texture units (repeats) across a pixel


def scene(root, angle, height_scale, light=(0.0, 0.0)):
    t = math.radians(angle)
    lt, la = math.radians(light[0]), math.radians(light[1])
    view = [math.sin(t), math.cos(t), 0]
    distance = FOOTPRINT * SIZE / math.radians(FOV_DEGREES)
    material = {
        "displacement": {"image": os.path.join(root, "examples/scenes/snake-scales.exr"), "height_scale": height_scale},
        "slope_colormap": {"image": os.path.join(root, "luts/snake-rims.png"), "by": "steepness"},
    }
    return {
        "camera": {"position": [distance * c for c in view], "look_at": [0, 0, 0], "up": [0, 0, 1],
                   "fov_degrees": FOV_DEGREES, "resolution": [SIZE, SIZE]},
        "light": {"direction": [math.sin(lt) * math.cos(la), math.cos(lt), math.sin(lt) * math.sin(la)],
                  "radiance": [1, 1, 1]},
        "background": [0, 0, 0],
        "surfaces": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                      "mapping": {"type": "planar", "origin": [0, 0, 0], "u_axis": [1, 0, 0], "v_axis": [0, 0, 1]},
                      "material": material}],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("work")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--spp", type=int, default=4096)
    parser.add_argument("--light", default="0,0", help="THETA,AZIMUTH in degrees (azimuth 0: the viewer's side)")
    args = parser.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    cmfilter = os.path.join(args.build, "tools", "cmfilter")
    os.makedirs(args.work, exist_ok=True)
    scene_path = os.path.join(args.work, "snake-patch.json")
    light = tuple(float(x) for x in args.light.split(","))

    def render(options, output):
        subprocess.run([cmfilter, "render", scene_path, *options, "-o", output, "--threads", str(args.threads), "-q"],
                       check=True)

    def mean_de(a, b):
        out = subprocess.run([cmfilter, "compare", a, b, "--json"], check=True, capture_output=True, text=True)
        return json.loads(out.stdout)["ciede2000"]["mean"]

    rows = []
    for scale in SCALES:
        for angle in ANGLES:
            with open(scene_path, "w") as f:
                json.dump(scene(root, angle, scale, light), f)
            reference = os.path.join(args.work, "reference.exr")
            render(["--method", "reference", "--spp", str(args.spp)], reference)
            row = {"height_scale": scale, "angle": angle}
            for method in METHODS:
                image = os.path.join(args.work, method.replace(" ", "-") + ".exr")
                render(SERIES[method], image)
                row[method] = round(mean_de(image, reference), 3)
            rows.append(row)
            print(row, flush=True)
    with open(os.path.join(args.work, "snake-angles.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["height_scale", "angle", *METHODS])
        writer.writeheader()
        writer.writerows(rows)
    print("| height_scale | view angle | " + " | ".join(METHODS) + " |")
    print("|---:|---:|" + "---:|" * len(METHODS))
    for row in rows:
        print(f"| {row['height_scale']} | {row['angle']} | " + " | ".join(f"{row[m]:.2f}" for m in METHODS) + " |")


if __name__ == "__main__":
    main()
