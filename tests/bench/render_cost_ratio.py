#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""gaussian's cost against naive's, per scene (docs/render.md, "Cost").

The bench's own times (every configuration once after the other, threads
on shared cores) scatter by tens of percent between configurations that do
the same work, too much for a 1.15 target. This runs `cmfilter render
SCENE --method M --threads 1 --json` for naive and gaussian alternately,
ROUNDS times each, and takes the fastest pixel-loop time (`seconds`) of
each: the baseline runs in the same script, interleaved, so a slow spell of
the machine hits both alike.

    python3 tests/bench/render_cost_ratio.py BUILD_DIR [ROUNDS] SCENE.json...
"""
import json
import os
import subprocess
import sys
import tempfile


def seconds(cmfilter, scene, method, output):
    out = subprocess.run([cmfilter, "render", scene, "--method", method, "--threads", "1", "--json", "-o", output],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)["seconds"]


def main():
    build, args = sys.argv[1], sys.argv[2:]
    rounds = 7
    if args and args[0].isdigit():
        rounds, args = int(args[0]), args[1:]
    cmfilter = os.path.join(build, "tools", "cmfilter")
    print(f"| scene | naive (ms) | gaussian (ms) | gaussian / naive |")
    print("|---|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as work:
        output = os.path.join(work, "render.exr")
        for scene in args:
            best = {"naive": float("inf"), "gaussian": float("inf")}
            for _ in range(rounds):
                for method in best:
                    best[method] = min(best[method], seconds(cmfilter, scene, method, output))
            name = os.path.basename(scene)
            print(f"| {name} | {1000 * best['naive']:.1f} | {1000 * best['gaussian']:.1f} | "
                  f"{best['gaussian'] / best['naive']:.2f} |")


if __name__ == "__main__":
    main()
