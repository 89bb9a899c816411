# SPDX-License-Identifier: Apache-2.0
"""Summary of a `cmfilter bench` CSV against the render targets (docs/render.md):
gaussian (256x256 sqrt table, rms footprint) against naive, the supersample of
about gaussian's time, and the reference; and exact against gaussian on the
scenes that have it.
    python3 render_bench_summary.py render-bench.csv"""
import math
import os
import sys

from bench_csv import f, read
from bench_csv import pick as pick_row

rows, scenes = read(sys.argv[1])


def pick(scene, configuration):
    return pick_row(rows, scene, configuration)


print("| scene | gaussian mean (near / middle / horizon) | naive mean | naive / gaussian error | gaussian / naive time "
      "| supersample at gaussian's time | reference time / gaussian | reference rays (repeat) |")
print("|---|---|---:|---:|---:|---|---:|---:|")
for s in scenes:
    g = pick(s, "gaussian 256x256 sqrt")
    n = pick(s, "naive")
    ref = pick(s, "reference")
    rep = pick(s, "reference-repeat")
    ss = [r for r in rows if r["scene"] == s and r["method"] == "supersample"]
    ss.sort(key=lambda r: f(r, "seconds"))
    # The supersample whose time is nearest gaussian's (in log time).
    near = min(ss, key=lambda r: abs(math.log(f(r, "seconds") / f(g, "seconds"))))
    print("| %s | %.2f (%.2f / %.2f / %.2f) | %.2f | %.2f | %.2f | %s spp: %.2f in %.1fx the time (%.2fx gaussian's error) | %.0f | %s (%.3f) |" % (
        os.path.basename(s), f(g, "mean"), f(g, "near_mean"), f(g, "middle_mean"), f(g, "horizon_mean"),
        f(n, "mean"), f(n, "mean") / f(g, "mean"), f(g, "seconds") / f(n, "seconds"),
        near["spp"], f(near, "mean"), f(near, "seconds") / f(g, "seconds"), f(near, "mean") / f(g, "mean"),
        f(ref, "seconds") / f(g, "seconds"), ref["spp"], f(rep, "mean")))

# Every gaussian configuration's mean error (bands for the tolerance tables).
labels = [c for c in dict.fromkeys(r["configuration"] for r in rows if r["method"] == "gaussian")]
print()
print("| scene | " + " | ".join(l[len("gaussian "):] for l in labels) + " |")
print("|---|" + "---:|" * len(labels))
for s in scenes:
    cells = []
    for l in labels:
        r = [x for x in rows if x["scene"] == s and x["configuration"] == l]
        cells.append("%.2f" % f(r[0], "mean") if r else "")
    print("| %s | %s |" % (os.path.splitext(os.path.basename(s))[0], " | ".join(cells)))

# exact, on the scenes it can filter (every driver a texture with at most 256
# values; bench leaves it out elsewhere).
exact = [s for s in scenes if any(r["scene"] == s and r["method"] == "exact" for r in rows)]
if exact:
    print()
    print("| scene | exact mean (near / middle / horizon) | gaussian mean | exact / gaussian time |")
    print("|---|---|---:|---:|")
    for s in exact:
        e = pick(s, "exact")
        g = pick(s, "gaussian 256x256 sqrt")
        print("| %s | %.2f (%.2f / %.2f / %.2f) | %.2f | %.2f |" % (
            os.path.basename(s), f(e, "mean"), f(e, "near_mean"), f(e, "middle_mean"), f(e, "horizon_mean"),
            f(g, "mean"), f(e, "seconds") / f(g, "seconds")))
