#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Inputs that declare more than any process should allocate, for the
# resource-limit tests (limits.cmake):
#   huge.png          a PNG whose header claims 100000 x 100000 RGB pixels
#                     (and holds no pixel data: nothing is read before the
#                     size is refused)
#   huge-scene.json   the largest resolution a scene may ask for, 16384 x 4096
#   many.lp + t.png   a stack of 10000 images, each the same 256 x 128 RGB PNG
#   many-small.lp     the same 10000 lights on a 16 x 16 PNG (s.png)
#   usage: make_limit_fixtures.py OUT_DIR
import json
import math
import os
import struct
import sys
import zlib


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def png(width, height, rows=None):
    head = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    body = chunk(b"IDAT", zlib.compress(rows)) if rows is not None else b""
    return head + body + chunk(b"IEND", b"")


out = sys.argv[1]
os.makedirs(out, exist_ok=True)
with open(os.path.join(out, "huge.png"), "wb") as f:
    f.write(png(100000, 100000, b"\x00" * 1024))
row = b"\x00" + bytes((x * 2) % 256 for x in range(256 * 3))
with open(os.path.join(out, "t.png"), "wb") as f:
    f.write(png(256, 128, row * 128))
small = b"\x00" + bytes((x * 8) % 256 for x in range(16 * 3))
with open(os.path.join(out, "s.png"), "wb") as f:
    f.write(png(16, 16, small * 16))
for name, image in (("many.lp", "t.png"), ("many-small.lp", "s.png")):
    with open(os.path.join(out, name), "w") as f:
        f.write("10000\n")
        for i in range(10000):
            # A spiral over the dome, elevations 17 to 80 degrees: a PTM needs them varied.
            z = 0.3 + 0.68 * i / 10000
            r = math.sqrt(1 - z * z)
            a = 2.399963 * i
            f.write("%s %.6f %.6f %.6f\n" % (image, r * math.cos(a), r * math.sin(a), z))
# The test scene good.json at the largest resolution, its files made absolute.
scenes = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes")
with open(os.path.join(scenes, "good.json")) as f:
    scene = json.load(f)
scene["camera"]["resolution"] = [16384, 4096]
material = scene["surfaces"][0]["material"]
material["colormap"]["image"] = os.path.normpath(os.path.join(scenes, material["colormap"]["image"]))
material["driver"]["sigma_table"] = os.path.normpath(os.path.join(scenes, material["driver"]["sigma_table"]))
with open(os.path.join(out, "huge-scene.json"), "w") as f:
    json.dump(scene, f, indent=1)
