#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
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

It is tests/bench/microsurface_angle_sweep.py with that scene, every method
and every set-up (its other options pass through).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import microsurface_angle_sweep  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

if __name__ == "__main__":
    microsurface_angle_sweep.main(defaults={
        "scene": [os.path.join(ROOT, "examples/scenes/plane-microsurface-sand-snow.json")],
        "name": "height",
        "methods": "naive,gaussian,gaussian-exact,exact,gaussian-exact correlated",
        "title": "Height-correlated colour (sand-snow microsurface): mean CIEDE2000 against the ray-traced heightfield",
    })
