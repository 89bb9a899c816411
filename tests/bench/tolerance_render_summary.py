# SPDX-License-Identifier: Apache-2.0
"""Table sizes and the small-sigma shortcut in a `cmfilter bench` CSV
(docs/render.md, "Table sizes and the small-sigma shortcut"): per scene, the
bytes of the tables fitted to tolerances 1 and 0.5 against the fixed 256 x 256
default and the render error each reaches against the reference; then the
shortcut's share of footprints and its effect on error and time.
    python3 tolerance_render_summary.py bench.csv"""
import os
import sys

from bench_csv import f, read
from bench_csv import pick as pick_row

rows, scenes = read(sys.argv[1])


def pick(scene, configuration):
    return pick_row(rows, scene, configuration)


def table(r):
    if r["table_values"]:
        return "%s x %s %s" % (r["table_values"], r["table_sigmas"], r["spacing"])
    return "(per surface)"


def error(r):
    return "%.2f (%.2f / %.2f / %.2f)" % (f(r, "mean"), f(r, "near_mean"), f(r, "middle_mean"), f(r, "horizon_mean"))


def share(r):
    return 100.0 * f(r, "plain_footprints") / f(r, "footprints")


print("| scene | 256 x 256 sqrt (786432 bytes): mean (near / middle / horizon) | tol 1: table | bytes | of 256 x 256 "
      "| lookup p99.9 | mean (near / middle / horizon) | tol 0.5: table | bytes | of 256 x 256 | lookup p99.9 "
      "| mean (near / middle / horizon) |")
print("|---|---|---|---:|---:|---:|---|---|---:|---:|---:|---|")
for s in scenes:
    fixed = pick(s, "gaussian 256x256 sqrt")
    cells = [os.path.basename(s), error(fixed)]
    for tol in ("1", "0.5"):
        r = pick(s, "gaussian tol " + tol)
        cells += [table(r), r["table_bytes"], "%.2f%%" % (100.0 * f(r, "table_bytes") / f(fixed, "table_bytes")),
                  "%.3f" % f(r, "table_error"), error(r)]
    print("| " + " | ".join(cells) + " |")

print()
print("| scene | tol 1: footprints on C0 | mean with / without shortcut | time with / without (s) "
      "| 256 x 256: footprints on C0 (bound 0.1) | mean with / without shortcut | time with / without (s) |")
print("|---|---:|---|---|---:|---|---|")
for s in scenes:
    a, b = pick(s, "gaussian tol 1"), pick(s, "gaussian tol 1 no-shortcut")
    c, d = pick(s, "gaussian 256x256 sqrt shortcut 0.1"), pick(s, "gaussian 256x256 sqrt")
    print("| %s | %.1f%% | %.3f / %.3f | %.4f / %.4f | %.1f%% | %.3f / %.3f | %.4f / %.4f |" % (
        os.path.basename(s), share(a), f(a, "mean"), f(b, "mean"), f(a, "seconds"), f(b, "seconds"),
        share(c), f(c, "mean"), f(d, "mean"), f(c, "seconds"), f(d, "seconds")))
