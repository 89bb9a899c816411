#!/usr/bin/env python3
"""Height-correlated colour against view and light angle (docs/microsurface.md).

For each angle from 0 to 89 degrees and four set-ups (the view swept with
the light overhead, the light swept with the view overhead, both at the
same angle with azimuths 90 degrees apart, and the light from the viewer:
where Smith's model, which takes masking and shadowing as independent, is
furthest from the truth), this renders a far patch of the
bundled microsurface (examples/scenes/plane-microsurface-sand-snow.json's
material) seen through a narrow camera, so that every pixel looks at the
angle and its footprint spans several of the longest wavelengths, by every
method: naive, gaussian, gaussian-exact, exact, gaussian-exact with
masking and shadowing correlated by azimuth (render --masking correlated),
and the ray-traced reference (twice, with other seeds: their difference is
the reference's own noise).
`cmfilter compare` gives each method's mean CIEDE2000 against the
reference. Writes WORK_DIR/height-angles.csv, WORK_DIR/height-angles.png
(gnuplot) and prints the table of the docs.

    python3 tests/bench/height_angle_sweep.py BUILD_DIR WORK_DIR [--threads N] [--spp N] [--size N]
"""
import argparse
import csv
import json
import math
import os
import subprocess

# Each series: its name and its render options.
SERIES = {
    "naive": ["--method", "naive"],
    "gaussian": ["--method", "gaussian"],
    "gaussian-exact": ["--method", "gaussian-exact"],
    "exact": ["--method", "exact"],
    "gaussian-exact correlated": ["--method", "gaussian-exact", "--masking", "correlated"],
}
METHODS = list(SERIES)
ANGLES = [0, 10, 20, 30, 40, 50, 60, 70, 75, 80, 85, 87, 89]
SETUPS = {
    "view": "view swept, light overhead",
    "light": "light swept, view overhead",
    "both": "view and light at the angle, azimuths 90 degrees apart",
    "retro": "light from the viewer (same angle and azimuth)",
}
FOV_DEGREES = 0.5       # every pixel within 0.25 degrees of the angle
FOOTPRINT = 1.0         # texture units across a pixel (2.5 longest wavelengths)


def direction(theta_degrees, azimuth_degrees):
    t, a = math.radians(theta_degrees), math.radians(azimuth_degrees)
    return [math.sin(t) * math.cos(a), math.cos(t), math.sin(t) * math.sin(a)]


def scene_for(setup, angle, size, root):
    bundled = json.load(open(os.path.join(root, "examples/scenes/plane-microsurface-sand-snow.json")))
    material = bundled["surfaces"][0]["material"]
    material["colormap"]["image"] = os.path.join(root, "luts", "sand-snow.png")
    view = direction(angle if setup in ("view", "both", "retro") else 0, 0)
    light = direction(angle if setup in ("light", "both", "retro") else 0, 0 if setup == "retro" else 90)
    distance = FOOTPRINT * size / math.radians(FOV_DEGREES)
    return {
        "camera": {"position": [distance * c for c in view], "look_at": [0, 0, 0], "up": [0, 0, 1],
                   "fov_degrees": FOV_DEGREES, "resolution": [size, size]},
        "light": {"direction": light, "radiance": [1, 1, 1]},
        "background": [0, 0, 0],
        "surfaces": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                      "mapping": {"type": "planar", "origin": [0, 0, 0], "u_axis": [1, 0, 0], "v_axis": [0, 0, 1]},
                      "material": material}],
    }


def render(cmfilter, scene, options, output, threads, spp=None, seed=0):
    command = [cmfilter, "render", scene, *options, "-o", output, "--threads", str(threads), "--json",
               "--seed", str(seed)]
    if spp:
        command += ["--spp", str(spp)]
    return json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)


def mean_de(cmfilter, a, b):
    out = subprocess.run([cmfilter, "compare", a, b, "--json"], check=True, capture_output=True, text=True).stdout
    return json.loads(out)["ciede2000"]["mean"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("work")
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--spp", type=int, default=4096)
    parser.add_argument("--size", type=int, default=16)
    args = parser.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    cmfilter = os.path.join(os.path.abspath(args.build), "tools", "cmfilter")
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    rows = []
    for setup in SETUPS:
        for angle in ANGLES:
            name = f"{work}/{setup}-{angle}"
            scene = name + ".json"
            json.dump(scene_for(setup, angle, args.size, root), open(scene, "w"), indent=1)
            reference = render(cmfilter, scene, ["--method", "reference"], name + ".reference.exr", args.threads,
                               args.spp, 1)
            render(cmfilter, scene, ["--method", "reference"], name + ".reference-b.exr", args.threads, args.spp, 2)
            row = {"setup": setup, "angle": angle, "reference_spp": reference["samples"],
                   "reference_seconds": round(reference["seconds"], 3),
                   "reference_repeat": mean_de(cmfilter, name + ".reference.exr", name + ".reference-b.exr")}
            for method, options in SERIES.items():
                image = f"{name}.{method.replace(' ', '-')}.exr"
                render(cmfilter, scene, options, image, args.threads)
                row[method] = mean_de(cmfilter, image, name + ".reference.exr")
            rows.append(row)
            print(setup, angle, {k: (round(v, 3) if isinstance(v, float) else v) for k, v in row.items()}, flush=True)
    out = f"{work}/height-angles.csv"
    with open(out + ".tmp", "w", newline="") as f:
        w = csv.DictWriter(f, list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    os.replace(out + ".tmp", out)

    print("\n| set-up | angle | " + " | ".join(METHODS) + " | reference repeat |")
    print("|---|---:|" + "---:|" * (len(METHODS) + 1))
    for r in rows:
        print(f"| {r['setup']} | {r['angle']} | " + " | ".join(f"{r[m]:.2f}" for m in METHODS) +
              f" | {r['reference_repeat']:.2f} |")

    with open(f"{work}/height-angles.dat", "w") as d:
        for setup in SETUPS:
            for series in METHODS + ["reference_repeat"]:
                d.write(f"# {setup} {series}\n")
                for r in rows:
                    if r["setup"] == setup:
                        d.write(f"{r['angle']} {max(float(r[series]), 1e-3)}\n")
                d.write("\n\n")
    styles = {"naive": 'pt 9 lc rgb "red"', "gaussian": 'pt 7 lc rgb "blue"',
              "gaussian-exact": 'pt 5 lc rgb "dark-violet"', "exact": 'pt 13 lc rgb "dark-green"',
              "gaussian-exact correlated": 'pt 4 dt 2 lc rgb "orange"',
              "reference_repeat": 'pt 1 dt 3 lc rgb "gray40"'}
    titles = {"reference_repeat": "reference vs itself (other seed)"}
    with open(f"{work}/height-angles.gp", "w") as g:
        g.write(f'set terminal pngcairo size 1800,520 font ",11"\nset output "{work}/height-angles.png"\n'
                'set multiplot layout 1,4 title "Height-correlated colour (sand-snow microsurface): mean CIEDE2000 '
                'against the ray-traced heightfield"\n'
                'set grid\nset xrange [0:90]\nset xtics 10\nset logscale y\nset yrange [0.01:100]\n'
                'set key bottom left samplen 2\nset ylabel "mean CIEDE2000"\n'
                'set arrow 1 from 80, graph 0 to 80, graph 1 nohead dt 2 lc rgb "black"\n'
                'set arrow 2 from graph 0, first 2 to graph 1, first 2 nohead dt 2 lc rgb "black"\n')
        index = 0
        for setup, label in SETUPS.items():
            g.write(f'set title "{label}"\nset xlabel "angle from the normal (degrees)"\n')
            plots = []
            for series in METHODS + ["reference_repeat"]:
                plots.append(f'"{work}/height-angles.dat" index {index} with linespoints lw 2 ps 1.2 '
                             f'{styles[series]} title "{titles.get(series, series)}"')
                index += 1
            g.write("plot " + ", \\\n     ".join(plots) + "\n")
            g.write("unset key\n")  # one key, in the first panel
        g.write("unset multiplot\n")
    subprocess.run(["gnuplot", f"{work}/height-angles.gp"], check=True)
    print(f"wrote {out} and {work}/height-angles.png")


if __name__ == "__main__":
    main()
