#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Every reflectance model measured on the bundled synthetic stacks
# (docs/stacks.md#every-model-compared): PTM RGB and LRGB, HSH 2 and 3,
# Lafortune RGB (2 lobes per channel), Lafortune luminance with 1 to 7
# lobes and auto, each fitted to cmfilter's float EXR (scene-linear), on the
# near-diffuse, the shiny and the uneven-dome (stage) stacks: fit seconds,
# bytes, and the relighting error (RMSE in scene-linear, CIEDE2000 mean / p95
# / max) at the training lights and at 16 held-out lights make-stack renders
# from each record. Writes the table (stdout), a CSV, two charts (held-out
# CIEDE2000 against bytes and against fit time, one point per model, gnuplot)
# and, for the shiny stack, the best linear and the Lafortune fits relit
# beside the ground truth with CIEDE2000 heat maps at a grazing (15 degrees)
# and a raking (35 degrees) light.
#   python3 tests/bench/stack_model_comparison.py build/tools/cmfilter OUT_DIR [DOCS_DIR]
import csv
import json
import os
import subprocess
import sys

MODELS = ([("ptm-rgb", []), ("ptm-lrgb", []), ("hsh2", []), ("hsh3", []), ("lafortune-rgb", ["--lobes", "2"])] +
          [(f"lafortune-{n}", ["--lobes", str(n)]) for n in range(1, 8)] + [("lafortune-auto", ["--lobes", "auto"])])


def run(*args):
    return subprocess.run([str(a) for a in args], check=True, capture_output=True, text=True).stdout


def model_args(name, extra):
    if name.startswith("lafortune-rgb"):
        return ["--model", "lafortune-rgb"] + extra
    if name.startswith("lafortune"):
        return ["--model", "lafortune"] + extra
    return ["--model", name]


def main():
    cmfilter, out = sys.argv[1], sys.argv[2]
    docs = sys.argv[3] if len(sys.argv) > 3 else None
    here = os.path.dirname(os.path.abspath(__file__))
    examples = os.path.join(here, "..", "..", "examples")
    os.makedirs(out, exist_ok=True)
    run("bash", os.path.join(examples, "make_stacks.sh"), cmfilter, out)
    for name in ["near-diffuse", "stage"]:
        os.makedirs(os.path.join(out, f"{name}-held"), exist_ok=True)
        run(cmfilter, "make-stack", "--from", os.path.join(out, name, "stack.json"), "-o",
            os.path.join(out, f"{name}-held", "stack.lp"), "--dome", "regular:16", "--min-elevation", "20", "-q")
    rows = []
    for stack in ["near-diffuse", "shiny", "stage"]:
        lp = os.path.join(out, stack, "stack.lp")
        held = os.path.join(out, f"{stack}-held", "stack.lp")
        for name, extra in MODELS:
            fit = os.path.join(out, f"{stack}-{name}.exr")
            j = json.loads(run(cmfilter, "fit", lp, *model_args(name, extra), "-o", fit, "--held-out", held, "--json"))
            t, h = j["training_error"], j["held_out_error"]
            rows.append({"stack": stack, "model": name, "fit_s": j["seconds"]["fit"], "bytes": j["bytes"],
                         "train_rmse": t["rmse"], "train_de_mean": t["delta_e_mean"], "train_de_p95": t["delta_e_p95"],
                         "train_de_max": t["delta_e_max"], "held_rmse": h["rmse"], "held_de_mean": h["delta_e_mean"],
                         "held_de_p95": h["delta_e_p95"], "held_de_max": h["delta_e_max"],
                         "lobe_histogram": " ".join(str(c) for c in j.get("lobe_histogram", []))})
    print("| stack | model | fit s | bytes | train RMSE | train dE mean | p95 | max | held RMSE | held dE mean | p95 | max |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r['stack']} | {r['model']} | {r['fit_s']:.2f} | {r['bytes']} | {r['train_rmse']:.4f} | "
              f"{r['train_de_mean']:.2f} | {r['train_de_p95']:.2f} | {r['train_de_max']:.1f} | {r['held_rmse']:.4f} | "
              f"{r['held_de_mean']:.2f} | {r['held_de_p95']:.2f} | {r['held_de_max']:.1f} |")
    for r in rows:
        if r["lobe_histogram"]:
            print(f"lobe counts 0..7, {r['stack']} {r['model']}: {r['lobe_histogram']}")
    if not docs:
        return
    data = os.path.join(docs, "data", "stack-models.csv")
    with open(data, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    # One .dat per stack for gnuplot: bytes, fit seconds, held dE mean, label.
    for stack in ["near-diffuse", "shiny", "stage"]:
        with open(os.path.join(out, f"{stack}.dat"), "w") as f:
            for r in rows:
                if r["stack"] == stack:
                    f.write(f"{r['bytes']} {r['fit_s']} {r['held_de_mean']} {r['model']}\n")
    for x, col, xlabel, name in [("bytes", 1, "model bytes (float EXR)", "bytes"),
                                 ("time", 2, "fit seconds (64 x 64, 64 lights, 2 cores)", "time")]:
        png = os.path.join(docs, "images", f"stack-models-error-{name}.png")
        plot = ", ".join(f"'{out}/{s}.dat' using {col}:3 with points pt 7 title '{s}', "
                         f"'{out}/{s}.dat' using {col}:3:4 with labels offset 0.5,0.5 font ',7' left notitle"
                         for s in ["near-diffuse", "shiny", "stage"])
        script = (f"set terminal pngcairo size 900,560; set output '{png}'; set logscale x; set grid;"
                  f"set xlabel '{xlabel}'; set ylabel 'mean CIEDE2000 at 16 held-out lights';"
                  f"set key top right; plot {plot}")
        subprocess.run(["gnuplot", "-e", script], check=True)
    # Relit beside the truth at a grazing (15 degrees, from -x) and a raking
    # (35 degrees, from +x -y) light on the shiny stack; make-stack renders
    # at least 6 lights, so four more fill the file.
    lights = os.path.join(out, "shown-lights.lp")
    with open(lights, "w") as f:
        f.write("6\na 0 0 1\nb 0.5 0 0.866\nc 0 0.5 0.866\nd -0.5 0 0.866\n"
                "grazing -0.9659 0 0.2588\nraking 0.5792 -0.5792 0.5736\n")
    shown = os.path.join(out, "shiny-shown")
    os.makedirs(shown, exist_ok=True)
    run(cmfilter, "make-stack", "--from", os.path.join(out, "shiny", "stack.json"), "--dome", f"file:{lights}",
        "-o", os.path.join(shown, "stack.lp"), "-q")
    tiles = []
    for index, light in [(4, "-0.9659,0,0.2588"), (5, "0.5792,-0.5792,0.5736")]:
        truth = os.path.join(shown, f"stack-{index:03d}.exr")
        truth_png = os.path.join(out, f"shown-{index}-truth.png")
        run("oiiotool", truth, "--colorconvert", "linear", "sRGB", "--resize:filter=box", "192x192", "-d", "uint8",
            "-o", truth_png)
        tiles.append(truth_png)
        for name in ["hsh3", "lafortune-rgb", "lafortune-auto"]:
            relit = os.path.join(out, f"shown-{index}-{name}.exr")
            run(cmfilter, "relight", os.path.join(out, f"shiny-{name}.exr"), "--light", light, "-o", relit, "-q")
            heat = os.path.join(out, f"shown-{index}-{name}-heat.png")
            run(cmfilter, "compare", truth, relit, "--heatmap", heat, "--heatmap-max", "10")
            for src, dst in [(relit, f"{relit}.png"), (heat, f"{heat}.big.png")]:
                conv = ["--colorconvert", "linear", "sRGB"] if src.endswith(".exr") else []
                run("oiiotool", src, *conv, "--resize:filter=box", "192x192", "-d", "uint8", "-o", dst)
            tiles += [f"{relit}.png", f"{heat}.big.png"]
    run("oiiotool", *tiles, "--mosaic:pad=4", "7x2", "-o", os.path.join(docs, "images", "stack-models-shiny-relit.png"))

if __name__ == "__main__":
    main()
