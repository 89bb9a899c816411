#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A combined microsurface material across scales (docs/slope.md): the
paper's figure 11 as a number.

The material of examples/scenes/plane-microsurface-combined.json (a base
layer over a noise, height-correlated and slope-correlated colour, summed
with weights) and the same layers multiplied (combine {"mode": "product"}),
on a patch seen at a fixed oblique angle (the view 60 degrees from the
normal, the light from the side at 45 degrees) through a narrow camera whose
pixels are F texture units across, for a series of footprints F from well
under the shortest wavelength to many longest wavelengths (along the view's
azimuth a pixel is 1 / cos 60 = 2 times longer). Each method against the
ray-traced reference (and a second reference, another seed: its own noise),
mean CIEDE2000 per footprint and method. Writes WORK_DIR/combined-scales.csv,
WORK_DIR/combined-scales.png (gnuplot) and prints the table of the docs.

    python3 tests/bench/combined_scale_sweep.py BUILD_DIR WORK_DIR
        [--footprints 0.003,0.01,0.03,0.1,0.3,1,3,10] [--methods naive,gaussian,exact]
        [--view 60] [--scene SCENE.json] [--threads N] [--spp N] [--size N]

--scene takes another material with a sum of layers and a base layer (e.g.
examples/scenes/plane-snake.json); the outputs keep their names.

A case already rendered in WORK_DIR (its ...row.json) is not rendered again.
"""
import argparse
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import microsurface_angle_sweep as sweep  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FOOTPRINTS = [0.003, 0.01, 0.03, 0.1, 0.3, 1, 3, 10]


def variants(cmfilter, work, threads, scene):
    """The scene's material (summed) and its product, the base layer's noise
    given a sigma table baked once unless it names one (else every render
    bakes its own)."""
    summed = sweep.bundled_material(scene)
    driver = summed["base"]["driver"]
    if "noise" in driver and "sigma_table" not in driver:
        table = f"{work}/base-sigma.exr"
        if not os.path.exists(table):
            subprocess.run([cmfilter, "bake-noise", "--noise", driver["noise"], "-o", table, "--threads",
                            str(threads), "-q"], check=True)
        driver["sigma_table"] = table
    product = dict(summed)
    product["combine"] = {"mode": "product"}
    return {"sum": summed, "product": product}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("build")
    parser.add_argument("work")
    parser.add_argument("--footprints", default=",".join(map(str, FOOTPRINTS)),
                        help="texture units across a pixel, comma-separated")
    parser.add_argument("--methods", default="naive,gaussian,exact")
    parser.add_argument("--view", type=float, default=60, help="the view's angle from the normal, degrees")
    parser.add_argument("--scene", default=os.path.join(ROOT, "examples/scenes/plane-microsurface-combined.json"),
                        help="a scene whose first material sums a base layer and microsurface layers")
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--spp", type=int, default=4096)
    parser.add_argument("--size", type=int, default=16)
    args = parser.parse_args()
    methods = [m.strip() for m in args.methods.split(",") if m.strip()]
    footprints = [float(f) for f in args.footprints.split(",")]
    cmfilter = os.path.join(os.path.abspath(args.build), "tools", "cmfilter")
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    view = sweep.direction(args.view, 0)
    light = sweep.direction(45, 90)
    rows = []
    for variant, material in variants(cmfilter, work, args.threads, args.scene).items():
        for footprint in footprints:
            name = f"{work}/combined-{variant}-{footprint:g}"
            scene = name + ".json"
            sweep.json.dump(sweep.patch_scene(material, view, light, footprint, args.size), open(scene, "w"),
                            indent=1)

            def compute():
                row, seconds = sweep.compare_case(cmfilter, scene, name, methods, args.threads, args.spp, True)
                return row | {f"{m} seconds": s for m, s in seconds.items()}
            result = sweep.cached(name + ".row.json", compute)
            row = {"combine": variant, "footprint": footprint}
            row |= {k: result[k] for k in ("reference_spp", "reference_seconds", "reference_repeat")}
            row |= {m: result[m] for m in methods}
            row |= {k + " (means)": result[k + " (means)"] for k in methods + ["reference_repeat"]}
            row |= {f"{m} seconds": result[f"{m} seconds"] for m in methods}
            rows.append(row)
            print(variant, footprint, {k: (round(v, 3) if isinstance(v, float) else v) for k, v in row.items()
                                       if k not in ("combine", "footprint")}, flush=True)
    out = f"{work}/combined-scales.csv"
    sweep.write_csv(out, rows)

    print("\n| combine | texture units per pixel | " + " | ".join(methods) + " | reference repeat |")
    print("|---|---:|" + "---:|" * (len(methods) + 1))
    for r in rows:
        print(f"| {r['combine']} | {r['footprint']:g} | " + " | ".join(f"{r[m]:.2f}" for m in methods) +
              f" | {r['reference_repeat']:.2f} |")
    print("\nThe images' mean colours, CIEDE2000:\n")
    print("| combine | texture units per pixel | " + " | ".join(methods) + " | reference repeat |")
    print("|---|---:|" + "---:|" * (len(methods) + 1))
    for r in rows:
        print(f"| {r['combine']} | {r['footprint']:g} | " + " | ".join(f"{r[m + ' (means)']:.2f}" for m in methods) +
              f" | {r['reference_repeat (means)']:.2f} |")

    series_list = methods + ["reference_repeat"]
    dat = f"{work}/combined-scales.dat"
    with open(dat, "w") as d:
        for variant in ("sum", "product"):
            for series in series_list:
                d.write(f"# {variant} {series}\n")
                for r in rows:
                    if r["combine"] == variant:
                        d.write(f"{r['footprint']} {max(float(r[series]), 1e-3)}\n")
                d.write("\n\n")
    summed = variants(cmfilter, work, args.threads, args.scene)["sum"]
    names = {"base": "base", "height": "height", "slope": "slope"}
    present = [k for k, key in (("base", "base"), ("height", "colormap"), ("slope", "slope_colormap"))
               if key in summed]
    weights = summed.get("combine", {}).get("weights", {})
    sum_label = "sum: " + " + ".join(f"{weights.get(k, 1):g} {names[k]}" for k in present)
    product_label = "product: " + " x ".join(names[k] for k in present)
    gp = f"{work}/combined-scales.gp"
    with open(gp, "w") as g:
        g.write('set terminal pngcairo size 1100,520 font ",11"\n'
                f'set output "{work}/combined-scales.png"\n'
                f'set multiplot layout 1,2 title "{os.path.basename(args.scene)}, view at '
                f'{args.view:g} degrees: mean CIEDE2000 against the ray-traced heightfield"\n'
                'set grid\nset logscale x\nset logscale y\nset yrange [0.01:1000]\n'
                'set key top right samplen 2\nset ylabel "mean CIEDE2000"\n'
                'set xlabel "pixel width (texture units)"\n'
                'set arrow 4 from graph 0, first 2 to graph 1, first 2 nohead dt 2 lc rgb "black"\n')
        micro = summed.get("microsurface")
        if micro:
            # The shortest and longest wavelengths, and a heightfield texel of the reference (8 per shortest).
            shortest, longest = micro["min_wavelength"], micro["max_wavelength"]
            g.write(f'set arrow 1 from {shortest}, graph 0 to {shortest}, graph 1 nohead dt 2 lc rgb "black"\n'
                    f'set arrow 2 from {longest}, graph 0 to {longest}, graph 1 nohead dt 2 lc rgb "black"\n'
                    f'set arrow 3 from {shortest / 8}, graph 0 to {shortest / 8}, graph 1 nohead dt 4 lc rgb "gray30"\n'
                    f'set label 1 "shortest wavelength" at {shortest}, graph 0.04 right offset -0.5,0 font ",9"\n'
                    f'set label 2 "longest" at {longest}, graph 0.04 left offset 0.5,0 font ",9"\n'
                    f'set label 3 "heightfield texel" at {shortest / 8}, graph 0.10 left offset 0.5,0 font ",9"\n')
        index = 0
        for variant, label in (("sum", sum_label), ("product", product_label)):
            g.write(f'set title "{label}"\n')
            index = sweep.plot_panel(g, dat, index, series_list)
        g.write("unset multiplot\n")
    subprocess.run(["gnuplot", gp], check=True)
    print(f"wrote {out} and {work}/combined-scales.png")


if __name__ == "__main__":
    main()
