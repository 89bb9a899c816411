#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# The linear fits measured on the bundled synthetic stacks (docs/stacks.md#measured):
# for each stack and model, the fit to cmfilter's float EXR and to the
# interchange file (.ptm or .rti): fit time, file bytes, the relighting error
# (RMSE in scene-linear, CIEDE2000 mean / p95 / max) at the training lights
# and at held-out lights that make-stack renders from the stack's record, and
# the angle of the fit's normals to the surface's true mean normals.
#   python3 tests/bench/stack_fit_accuracy.py build/tools/cmfilter OUT_DIR
import json
import os
import subprocess
import sys


def run(*args):
    return subprocess.run([str(a) for a in args], check=True, capture_output=True, text=True).stdout


def main():
    cmfilter, out = sys.argv[1], sys.argv[2]
    here = os.path.dirname(os.path.abspath(__file__))
    examples = os.path.join(here, "..", "..", "examples")
    os.makedirs(out, exist_ok=True)
    run("bash", os.path.join(examples, "make_stacks.sh"), cmfilter, out)
    # Held-out lights for the near-diffuse stack too (shiny-held comes with the bundle).
    os.makedirs(os.path.join(out, "near-diffuse-held"), exist_ok=True)
    run(cmfilter, "make-stack", "--from", os.path.join(out, "near-diffuse", "stack.json"), "-o",
        os.path.join(out, "near-diffuse-held", "stack.lp"), "--dome", "regular:16", "--min-elevation", "20", "-q")
    stacks = [("near-diffuse", "near-diffuse-held"), ("shiny", "shiny-held"), ("stage", None)]
    print("| stack | model | file | fit s | bytes | train RMSE | train dE mean | p95 | max | "
          "held RMSE | held dE mean | p95 | max | normal mean deg | p95 | max |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, held in stacks:
        lp = os.path.join(out, name, "stack.lp")
        truth = os.path.join(out, name, "stack.normals.exr")
        held_lp = os.path.join(out, held, "stack.lp") if held else None
        for model in ["ptm-rgb", "ptm-lrgb", "hsh2", "hsh3"]:
            interchange = "ptm" if model.startswith("ptm") else "rti"
            for ext in ["exr", interchange]:
                fit = os.path.join(out, f"{name}-{model}.{ext}")
                args = [cmfilter, "fit", lp, "--model", model, "-o", fit, "--json"]
                if held_lp:
                    args += ["--held-out", held_lp]
                j = json.loads(run(*args))
                n = json.loads(run(cmfilter, "normals", fit, "--reference", truth, "--json"))
                t, h, a = j["training_error"], j.get("held_out_error"), n["angle_degrees"]
                held_cells = (f"{h['rmse']:.4f} | {h['delta_e_mean']:.2f} | {h['delta_e_p95']:.2f} | "
                              f"{h['delta_e_max']:.1f}") if h else "- | - | - | -"
                print(f"| {name} | {model} | {ext} | {j['seconds']['fit']:.3f} | {j['bytes']} | "
                      f"{t['rmse']:.4f} | {t['delta_e_mean']:.2f} | {t['delta_e_p95']:.2f} | {t['delta_e_max']:.1f} | "
                      f"{held_cells} | {a['mean']:.1f} | {a['p95']:.1f} | {a['max']:.1f} |")


if __name__ == "__main__":
    main()
