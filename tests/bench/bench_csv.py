# SPDX-License-Identifier: Apache-2.0
"""Reading a `cmfilter bench` CSV: its rows, its scenes in order, one row by
scene and configuration, and a number from a row."""
import csv


def read(path):
    rows = list(csv.DictReader(open(path)))
    scenes = []
    for r in rows:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    return rows, scenes


def pick(rows, scene, configuration):
    for r in rows:
        if r["scene"] == scene and r["configuration"] == configuration:
            return r
    raise KeyError(configuration)


def f(r, key):
    return float(r[key])
