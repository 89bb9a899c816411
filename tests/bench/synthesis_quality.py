#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Synthesis quality and time on the bundled samples (docs/synthesis.md#quality):
# the photographs (scikit-image's brick, grass, gravel), the procedural
# terrain texture (examples/synth_samples.sh) and the synthetic stacks
# (examples/make_stacks.sh: the near-diffuse 64-light stack and the 7-view
# BTF), each analysed once (synth-analyse, timed) and synthesised at 256 x 256
# at the paper's settings (k = 1, 3, 6; neighbourhood 2, 3; 1 and 3 levels):
# coherence, coverage and seams against naive tiling, and the synthesis time.
# Writes the table (stdout, markdown), a CSV, a chart of coherence against
# time (gnuplot) and, per sample, the sample, naive tiling and the
# syntheses side by side.
#   python3 tests/bench/synthesis_quality.py build/tools/cmfilter OUT_DIR [DOCS_DIR]
import csv
import json
import os
import subprocess
import sys

SETTINGS = [(k, n, levels) for levels in (1, 3) for n in (2, 3) for k in (1, 3, 6)]
SIZE = "256x256"


def run(*args):
    return subprocess.run([str(a) for a in args], check=True, capture_output=True, text=True).stdout


def main():
    cmfilter, out = sys.argv[1], sys.argv[2]
    docs = sys.argv[3] if len(sys.argv) > 3 else None
    here = os.path.dirname(os.path.abspath(__file__))
    examples = os.path.join(here, "..", "..", "examples")
    os.makedirs(out, exist_ok=True)
    run("bash", os.path.join(examples, "synth_samples.sh"), cmfilter, out)
    run("bash", os.path.join(examples, "make_stacks.sh"), cmfilter, os.path.join(out, "stacks"))
    samples = [("brick", os.path.join(out, "brick.png"), []),
               ("grass", os.path.join(out, "grass.png"), []),
               ("gravel", os.path.join(out, "gravel.png"), []),
               ("terrain", os.path.join(out, "terrain.png"), []),
               ("near-diffuse", os.path.join(out, "stacks", "near-diffuse", "stack.lp"), ["--periodic"]),
               ("multiview", os.path.join(out, "stacks", "multiview", "btf.json"), ["--periodic"])]
    rows = []
    for name, path, extra in samples:
        analyses = {}
        for n in (2, 3):
            analysis = os.path.join(out, f"{name}-n{n}-analysis.exr")
            a = json.loads(run(cmfilter, "synth-analyse", path, "-o", analysis, "--levels", 3, "--neighbourhood", n,
                               *extra, "--json"))
            analyses[n] = (analysis, a["seconds"])
        for k, n, levels in SETTINGS:
            analysis, analysis_s = analyses[n]
            tag = f"{name}-k{k}-n{n}-l{levels}"
            coords = os.path.join(out, f"{tag}.exr")
            j = json.loads(run(cmfilter, "synth", path, "--analysis", analysis, "-o", coords, "--size", SIZE, "-k", k,
                               "--levels", levels, "--quality", "--preview", os.path.join(out, f"{tag}.png"),
                               "--json"))
            q, t = j["quality"], j["tiled_quality"]
            rows.append({"sample": name, "k": k, "n": n, "levels": levels, "synth_s": j["synthesis_seconds"],
                         "analysis_s": analysis_s, "coherence": q["coherence"], "coverage": q["coverage"],
                         "seam_share": q["seam_share"], "seam_contrast": q["seam_contrast"],
                         "tiled_coherence": t["coherence"], "tiled_coverage": t["coverage"],
                         "tiled_seam_share": t["seam_share"], "tiled_seam_contrast": t["seam_contrast"]})
    with open(os.path.join(out, "synthesis_quality.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("| sample | k | n | levels | synthesis s | coherence | coverage | seams (share, contrast) | tiling: coherence, coverage, seams |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['sample']} | {r['k']} | {r['n']} | {r['levels']} | {r['synth_s']:.3f} | {r['coherence']:.3f} | "
              f"{r['coverage']:.2f} | {r['seam_share']:.3f}, {r['seam_contrast']:.2f} | {r['tiled_coherence']:.3f}, "
              f"{r['tiled_coverage']:.2f}, {r['tiled_seam_share']:.3f}, {r['tiled_seam_contrast']:.2f} |")
    print()
    for name, _, _ in samples:
        a = [r["analysis_s"] for r in rows if r["sample"] == name]
        print(f"analysis of {name}: {min(a):.2f} to {max(a):.2f} s (3 levels, neighbourhood 2 and 3)")
    if docs:
        chart(rows, out, docs)
        mosaics(samples, out, docs)


def chart(rows, out, docs):
    data = os.path.join(out, "synthesis_quality.dat")
    with open(data, "w") as f:
        for name in dict.fromkeys(r["sample"] for r in rows):
            f.write(f'"{name}"\n')
            for r in rows:
                if r["sample"] == name:
                    f.write(f"{r['synth_s']} {r['coherence']} k{r['k']}n{r['n']}l{r['levels']}\n")
            f.write("\n\n")
    png = os.path.join(docs, "images", "synthesis-quality-time.png")
    script = f"""set terminal pngcairo size 900,560 font ",11"
set output "{png}"
set logscale x
set xlabel "synthesis time, 256 x 256 (s, log)"
set ylabel "coherence (0: every output neighbourhood is in the sample)"
set key outside right
set grid
plot for [i=0:{len(set(r['sample'] for r in rows)) - 1}] "{data}" index i using 1:2 with points pt 7 ps 1.2 title columnheader(1)
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def first_image(path):
    """The first image of a stack (.lp) or of a BTF manifest's first view."""
    if path.endswith(".json"):
        with open(path) as f:
            path = os.path.join(os.path.dirname(path), json.load(f)["views"][0]["lights"])
    with open(path) as f:
        f.readline()
        return os.path.join(os.path.dirname(path), f.readline().split()[0])


def mosaics(samples, out, docs):
    for name, path, _ in samples:
        first = os.path.join(out, f"{name}-k1-n2-l1.png")
        images = [os.path.join(out, f"{name}-k{k}-n{n}-l{l}.png") for k, n, l in
                  [(1, 2, 1), (3, 2, 1), (6, 2, 1), (1, 2, 3), (3, 2, 3), (6, 3, 3)]]
        if not os.path.exists(first):
            continue
        sample_png = os.path.join(out, f"{name}-sample.png")
        tiled_png = os.path.join(out, f"{name}-tiled.png")
        src = path if path.endswith(".png") else first_image(path)
        grey = int(run("oiiotool", src, "--echo", "{TOP.nchannels}").split()[0]) == 1
        run("oiiotool", src, "--ch", "0,0,0" if grey else "R,G,B", "-d", "uint8", "-o", sample_png)
        width = int(run("oiiotool", sample_png, "--echo", "{TOP.width}").split()[0])
        tiles = -(-256 // width)
        dup = ["--dup"] * (tiles - 1)
        run("oiiotool", sample_png, *dup, "--mosaic", f"{tiles}x1", *dup, "--mosaic", f"1x{tiles}", "--cut",
            "256x256+0+0", "-o", tiled_png)
        args = [tiled_png] + sum([[i, "--ch", "R,G,B"] for i in images], [])
        run("oiiotool", *args, "--mosaic:pad=4", f"{len(images) + 1}x1", "-o",
            os.path.join(docs, "images", f"synthesis-{name}.png"))


if __name__ == "__main__":
    main()
