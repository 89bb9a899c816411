#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A microsurface material's colour against view and light angle.

For each angle and set-up (the view swept with the light overhead, the
light swept with the view overhead, both at the same angle with azimuths 90
degrees apart, and the light from the viewer), this renders a far patch of
a bundled microsurface scene's material (its first surface's) seen through
a narrow camera, so that every pixel looks at the angle and its footprint
spans several of the longest wavelengths, by the chosen methods and by the
ray-traced reference (twice, with other seeds: their difference is the
reference's own noise). `cmfilter compare` gives each method's mean
CIEDE2000 against the reference. Writes WORK_DIR/NAME-angles.csv,
WORK_DIR/NAME-angles.png (gnuplot) and prints the table of the docs.

    python3 tests/bench/microsurface_angle_sweep.py BUILD_DIR WORK_DIR
        --scene [LABEL=]SCENE.json [--scene [LABEL=]SCENE.json ...] --name NAME
        [--methods naive,gaussian,exact] [--setups view,light] [--angles 0,20,40]
        [--title TEXT] [--key 'top right'] [--threads N] [--spp N] [--size N] [--image-means]

With several scenes, each is a row of panels and the CSV gains a `scene`
column (its LABEL, by default the file's name). A case already rendered in
WORK_DIR (its NAME-...row.json) is not rendered again, so an interrupted
sweep goes on where it stopped; remove the folder to start afresh.
tests/bench/height_angle_sweep.py is this script with the height-coloured
scene and all five methods.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

# absolute_paths: a material with its file paths made absolute, so it can be written elsewhere.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
from write_small_scene import absolute_paths  # noqa: E402

# Each series: its name and its render options. The plain method names are
# the paper's model (eqs. 13 and 19); render's defaults are "all-correlated".
SERIES = {
    "naive": ["--method", "naive"],
    "gaussian": ["--method", "gaussian", "--masking", "uncorrelated", "--slope-shading", "uncorrelated"],
    "gaussian-exact": ["--method", "gaussian-exact", "--masking", "uncorrelated", "--slope-shading", "uncorrelated"],
    "exact": ["--method", "exact", "--masking", "uncorrelated", "--slope-shading", "uncorrelated"],
    "gaussian-exact correlated": ["--method", "gaussian-exact", "--masking", "correlated", "--slope-shading", "uncorrelated"],
    "gaussian shading-correlated": ["--method", "gaussian", "--slope-shading", "correlated", "--masking", "uncorrelated"],
    "exact shading-correlated": ["--method", "exact", "--slope-shading", "correlated", "--masking", "uncorrelated"],
    "gaussian all-correlated": ["--method", "gaussian", "--slope-shading", "correlated", "--masking", "correlated"],
    "exact all-correlated": ["--method", "exact", "--slope-shading", "correlated", "--masking", "correlated"],
}
ANGLES = [0, 10, 20, 30, 40, 50, 60, 70, 75, 80, 85, 87, 89]
SETUPS = {
    "view": "view swept, light overhead",
    "light": "light swept, view overhead",
    "both": "view and light at the angle, azimuths 90 degrees apart",
    "retro": "light from the viewer (same angle and azimuth)",
}
SHORT_SETUPS = {"view": "view swept", "light": "light swept", "both": "both, 90 degrees apart",
                "retro": "light from the viewer"}
FOV_DEGREES = 0.5       # every pixel within 0.25 degrees of the angle
FOOTPRINT = 1.0         # texture units across a pixel (2.5 longest wavelengths)
STYLES = {"naive": 'pt 9 lc rgb "red"', "gaussian": 'pt 7 lc rgb "blue"',
          "gaussian-exact": 'pt 5 lc rgb "dark-violet"', "exact": 'pt 13 lc rgb "dark-green"',
          "gaussian-exact correlated": 'pt 4 dt 2 lc rgb "orange"',
          "gaussian shading-correlated": 'pt 6 dt 2 lc rgb "blue"',
          "exact shading-correlated": 'pt 12 dt 2 lc rgb "dark-green"',
          "gaussian all-correlated": 'pt 8 dt 4 lc rgb "orange"',
          "exact all-correlated": 'pt 10 dt 4 lc rgb "dark-green"',
          "reference_repeat": 'pt 1 dt 3 lc rgb "gray40"'}
TITLES = {"reference_repeat": "reference vs itself (other seed)"}


def direction(theta_degrees, azimuth_degrees):
    t, a = math.radians(theta_degrees), math.radians(azimuth_degrees)
    return [math.sin(t) * math.cos(a), math.cos(t), math.sin(t) * math.sin(a)]


def bundled_material(scene_path):
    scene = json.load(open(scene_path))
    return absolute_paths(scene["surfaces"][0]["material"], os.path.dirname(os.path.abspath(scene_path)))


def patch_scene(material, view, light, footprint, size, fov_degrees=FOV_DEGREES):
    """A plane (texture units = scene units) seen along `view` (a unit vector
    from the surface towards the camera) through a narrow camera whose pixels
    are `footprint` texture units across (at normal incidence; 1 / cos theta
    longer along the view's azimuth)."""
    distance = footprint * size / math.radians(fov_degrees)
    up = [0, 0, 1] if abs(view[2]) < 0.9 else [1, 0, 0]
    return {
        "camera": {"position": [distance * c for c in view], "look_at": [0, 0, 0], "up": up,
                   "fov_degrees": fov_degrees, "resolution": [size, size]},
        "light": {"direction": light, "radiance": [1, 1, 1]},
        "background": [0, 0, 0],
        "surfaces": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                      "mapping": {"type": "planar", "origin": [0, 0, 0], "u_axis": [1, 0, 0], "v_axis": [0, 0, 1]},
                      "material": material}],
    }


def scene_for(material, setup, angle, size, footprint=FOOTPRINT):
    view = direction(angle if setup in ("view", "both", "retro") else 0, 0)
    light = direction(angle if setup in ("light", "both", "retro") else 0, 0 if setup == "retro" else 90)
    return patch_scene(material, view, light, footprint, size)


def render(cmfilter, scene, options, output, threads, spp=None, seed=0):
    command = [cmfilter, "render", scene, *options, "-o", output, "--threads", str(threads), "--json",
               "--seed", str(seed)]
    if spp:
        command += ["--spp", str(spp)]
    return json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)


def mean_de(cmfilter, a, b):
    out = subprocess.run([cmfilter, "compare", a, b, "--json"], check=True, capture_output=True, text=True).stdout
    return json.loads(out)["ciede2000"]["mean"]


def image_mean(path):
    """An image's mean colour as a 1 x 1 float image beside it (oiiotool's
    statistics, 6 digits)."""
    out = subprocess.run(["oiiotool", "-v", "--stats", path], check=True, capture_output=True, text=True).stdout
    average = next(line for line in out.splitlines() if "Stats Avg:" in line).split(":")[1].split()[:3]
    mean = path[:-len(".exr")] + ".mean.exr"
    subprocess.run(["oiiotool", "--pattern", "constant:color=" + ",".join(average), "1x1", "3", "-d", "float",
                    "-o", mean], check=True, capture_output=True)
    return mean


def compare_case(cmfilter, scene, name, methods, threads, spp, image_means=False):
    """Renders `scene` (a file) by the reference (seeds 1 and 2) and every
    method; returns the reference's time and spp, its repeat difference, and
    each method's mean CIEDE2000 and time; with `image_means`, also the
    CIEDE2000 between the images' mean colours (keys "... (means)"): the
    part of the difference that is not per pixel."""
    reference = render(cmfilter, scene, ["--method", "reference"], name + ".reference.exr", threads, spp, 1)
    render(cmfilter, scene, ["--method", "reference"], name + ".reference-b.exr", threads, spp, 2)
    row = {"reference_spp": reference["samples"], "reference_seconds": round(reference["seconds"], 3),
           "reference_repeat": mean_de(cmfilter, name + ".reference.exr", name + ".reference-b.exr")}
    if image_means:
        row["reference_repeat (means)"] = mean_de(cmfilter, image_mean(name + ".reference.exr"),
                                                  image_mean(name + ".reference-b.exr"))
    seconds = {}
    for method in methods:
        image = f"{name}.{method.replace(' ', '-')}.exr"
        seconds[method] = round(render(cmfilter, scene, SERIES[method], image, threads)["seconds"], 3)
        row[method] = mean_de(cmfilter, image, name + ".reference.exr")
        if image_means:
            row[method + " (means)"] = mean_de(cmfilter, image_mean(image), name + ".reference.mean.exr")
    return row, seconds


def cached(path, compute):
    if os.path.exists(path):
        return json.load(open(path))
    value = compute()
    with open(path + ".tmp", "w") as f:
        json.dump(value, f)
    os.replace(path + ".tmp", path)
    return value


def write_csv(path, rows):
    with open(path + ".tmp", "w", newline="") as f:
        w = csv.DictWriter(f, list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    os.replace(path + ".tmp", path)


def plot_panel(g, dat, index, series_list):
    """Writes one gnuplot panel: data sets `index`, `index + 1`, ... of `dat`,
    one per series, the key only in the first panel. Returns the next index."""
    plots = []
    for series in series_list:
        plots.append(f'"{dat}" index {index} with linespoints lw 2 ps 1.2 '
                     f'{STYLES[series]} title "{TITLES.get(series, series)}"')
        index += 1
    g.write("plot " + ", \\\n     ".join(plots) + "\n")
    g.write("unset key\n")  # one key, in the first panel
    return index


def parse_scene(text):
    label, sep, path = text.partition("=")
    if not sep:
        label, path = os.path.splitext(os.path.basename(text))[0], text
    return label, path


def main(argv=None, defaults=None):
    defaults = defaults or {}
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("build")
    parser.add_argument("work")
    parser.add_argument("--scene", action="append", help="[LABEL=]SCENE.json, repeatable")
    parser.add_argument("--name", default="microsurface", help="the outputs' prefix in WORK_DIR")
    parser.add_argument("--methods", default=",".join(SERIES),
                        help="comma-separated, from: " + ", ".join(SERIES))
    parser.add_argument("--setups", default=",".join(SETUPS), help="comma-separated, from: " + ", ".join(SETUPS))
    parser.add_argument("--angles", default=",".join(map(str, ANGLES)), help="degrees, comma-separated")
    parser.add_argument("--title", default=None, help="the chart's title")
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--spp", type=int, default=4096)
    parser.add_argument("--size", type=int, default=16)
    parser.add_argument("--key", default="bottom left", help="where the chart's key goes (gnuplot's set key)")
    parser.add_argument("--image-means", action="store_true",
                        help="also the CIEDE2000 between the images' mean colours (CSV columns '... (means)')")
    parser.set_defaults(**defaults)
    args = parser.parse_args(argv)
    if not args.scene:
        parser.error("--scene is required")
    scenes = [parse_scene(s) for s in args.scene]
    methods = [m.strip() for m in args.methods.split(",") if m.strip()]
    setups = [s.strip() for s in args.setups.split(",") if s.strip()]
    angles = [float(a) if "." in a else int(a) for a in args.angles.split(",")]
    for m in methods:
        if m not in SERIES:
            parser.error(f"unknown method '{m}' (expected one of: {', '.join(SERIES)})")
    for s in setups:
        if s not in SETUPS:
            parser.error(f"unknown set-up '{s}' (expected one of: {', '.join(SETUPS)})")
    cmfilter = os.path.join(os.path.abspath(args.build), "tools", "cmfilter")
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    several = len(scenes) > 1
    rows = []
    for label, scene_path in scenes:
        material = bundled_material(scene_path)
        for setup in setups:
            for angle in angles:
                name = f"{work}/{args.name}-{label + '-' if several else ''}{setup}-{angle}"
                scene = name + ".json"
                json.dump(scene_for(material, setup, angle, args.size), open(scene, "w"), indent=1)
                result = cached(name + ".row.json", lambda: compare_case(cmfilter, scene, name, methods,
                                                                         args.threads, args.spp,
                                                                         args.image_means)[0])
                row = ({"scene": label} if several else {}) | {"setup": setup, "angle": angle}
                row |= {k: result[k] for k in ("reference_spp", "reference_seconds", "reference_repeat")}
                row |= {m: result[m] for m in methods}
                if args.image_means:
                    row |= {k + " (means)": result[k + " (means)"] for k in methods + ["reference_repeat"]}
                rows.append(row)
                print(*([label] if several else []), setup, angle, {k: (round(v, 3) if isinstance(v, float) else v) for k, v in row.items()
                                            if k not in ("scene", "setup", "angle")}, flush=True)
    out = f"{work}/{args.name}-angles.csv"
    write_csv(out, rows)

    print(("\n| scene " if several else "\n") + "| set-up | angle | " + " | ".join(methods) + " | reference repeat |")
    print(("|---" if several else "") + "|---|---:|" + "---:|" * (len(methods) + 1))
    for r in rows:
        print((f"| {r['scene']} " if several else "") + f"| {r['setup']} | {r['angle']} | " +
              " | ".join(f"{r[m]:.2f}" for m in methods) + f" | {r['reference_repeat']:.2f} |")

    if args.image_means:
        print("\nThe images' mean colours, CIEDE2000:")
        print(("\n| scene " if several else "\n") + "| set-up | angle | " + " | ".join(methods) +
              " | reference repeat |")
        print(("|---" if several else "") + "|---|---:|" + "---:|" * (len(methods) + 1))
        for r in rows:
            print((f"| {r['scene']} " if several else "") + f"| {r['setup']} | {r['angle']} | " +
                  " | ".join(f"{r[m + ' (means)']:.2f}" for m in methods) +
                  f" | {r['reference_repeat (means)']:.2f} |")

    series_list = methods + ["reference_repeat"]
    dat = f"{work}/{args.name}-angles.dat"
    with open(dat, "w") as d:
        for label, _ in scenes:
            for setup in setups:
                for series in series_list:
                    d.write(f"# {label} {setup} {series}\n")
                    for r in rows:
                        if r["setup"] == setup and (not several or r["scene"] == label):
                            d.write(f"{r['angle']} {max(float(r[series]), 1e-3)}\n")
                    d.write("\n\n")
    title = args.title or f"{args.name}: mean CIEDE2000 against the ray-traced heightfield"
    gp = f"{work}/{args.name}-angles.gp"
    with open(gp, "w") as g:
        g.write(f'set terminal pngcairo size {450 * len(setups)},{520 * len(scenes)} font ",11"\n'
                f'set output "{work}/{args.name}-angles.png"\n'
                f'set multiplot layout {len(scenes)},{len(setups)} title "{title}"\n'
                'set grid\nset xrange [0:90]\nset xtics 10\nset logscale y\nset yrange [0.01:100]\n'
                f'set key {args.key} samplen 2\nset ylabel "mean CIEDE2000"\n'
                'set arrow 1 from 80, graph 0 to 80, graph 1 nohead dt 2 lc rgb "black"\n'
                'set arrow 2 from graph 0, first 2 to graph 1, first 2 nohead dt 2 lc rgb "black"\n')
        index = 0
        for label, _ in scenes:
            for setup in setups:
                panel = SETUPS[setup] if not several else f"{label}: {SHORT_SETUPS[setup]}"
                g.write(f'set title "{panel}"\nset xlabel "angle from the normal (degrees)"\n')
                index = plot_panel(g, dat, index, series_list)
        g.write("unset multiplot\n")
    subprocess.run(["gnuplot", gp], check=True)
    print(f"wrote {out} and {work}/{args.name}-angles.png")


if __name__ == "__main__":
    main()
