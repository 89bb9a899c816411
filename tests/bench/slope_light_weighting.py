#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""How far eq. 19's assumption moves a slope colour (docs/slope.md).

Eq. 19 takes the slope colour C_s and the BRDF as uncorrelated: the filtered
colour is <C_s, D_s>, the map averaged over the visible slopes. The
ray-traced reference's albedo estimator weighs each visible facet by its
light cosine <m, l>+ as well (sum C V <m, l>+ / sum <m, l>+), so where the
colour depends on the slope it converges to

    <C_s <m, l>+, D_s> / <<m, l>+, D_s>,

which is not <C_s, D_s> unless <m, l>+ is the same on every facet. This
script computes both on a grid of slopes, for isotropic Gaussian slopes of
deviation SIGMA_S (no shadowing: the light cosine alone) and the set-ups of
microsurface_angle_sweep.py (the view along +u; the light at azimuth 90
degrees, along +v, or along the view for the light from the viewer), and prints CIEDE2000 between them per angle: the error
that an exact eq. 19 would keep against the reference.

    python3 tests/bench/slope_light_weighting.py BUILD_DIR WORK_DIR [--sigma-s 0.432]

The maps are read from luts/grass-rock.png (a steepness map over 0..90
degrees) and luts/slope-wheel.png (a slope-vector map over [-1, 1]^2),
sRGB-decoded; CIEDE2000 by `cmfilter compare` of 1 x 1 images.
"""
import argparse
import math
import os
import struct
import subprocess
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ANGLES = [0, 10, 20, 30, 40, 50, 60, 70, 75, 80, 85, 87, 89]


def read_png_rgb8(path):
    """A non-interlaced 8-bit RGB PNG as rows of (r, g, b) tuples."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", chunk)
            assert depth == 8 and colour == 2 and interlace == 0
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    raw, stride, rows, previous = zlib.decompress(idat), width * 3, [], bytearray(width * 3)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b = previous[i]
            c = previous[i - 3] if i >= 3 else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[3 * x:3 * x + 3]) for x in range(width)])
        previous = line
    return rows


def srgb_to_linear(code):
    v = code / 255
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


def linear_rows(path):
    return [[tuple(srgb_to_linear(c) for c in texel) for texel in row] for row in read_png_rgb8(path)]


def lerp(a, b, t):
    return tuple(x + (y - x) * t for x, y in zip(a, b))


def steepness_map(texels):
    """A 1-D map over the slope angle in degrees, [0, 90], linear between
    texel centres, clamped."""
    n = len(texels)

    def colour(sx, sy):
        x = math.degrees(math.atan(math.hypot(sx, sy))) / 90 * n - 0.5
        i = min(max(int(math.floor(x)), 0), n - 2)
        return lerp(texels[i], texels[i + 1], min(max(x - i, 0), 1))
    return colour


def vector_map(rows, s_max):
    """An image over [-s_max, s_max]^2 (row 0 at s_y = +s_max), bilinear
    between texel centres, clamped."""
    h, w = len(rows), len(rows[0])

    def colour(sx, sy):
        x = (sx + s_max) / (2 * s_max) * w - 0.5
        y = (s_max - sy) / (2 * s_max) * h - 0.5
        x, y = min(max(x, 0), w - 1), min(max(y, 0), h - 1)
        i, j = min(int(x), w - 2), min(int(y), h - 2)
        return lerp(lerp(rows[j][i], rows[j][i + 1], x - i), lerp(rows[j + 1][i], rows[j + 1][i + 1], x - i), y - j)
    return colour


def direction(theta, azimuth):
    t, a = math.radians(theta), math.radians(azimuth)
    return (math.sin(t) * math.cos(a), math.sin(t) * math.sin(a), math.cos(t))  # (u, v, normal)


def averages(colour, sigma, view, light, n=161, extent=4.5):
    """<C, D_s> and <C <m,l>+, D_s> / <<m,l>+, D_s> by a midpoint sum over
    slopes in [-extent sigma, extent sigma]^2."""
    plain, lit, wsum, lsum = [0.0] * 3, [0.0] * 3, 0.0, 0.0
    step = 2 * extent * sigma / n
    for i in range(n):
        sx = -extent * sigma + (i + 0.5) * step
        for j in range(n):
            sy = -extent * sigma + (j + 0.5) * step
            p = math.exp(-(sx * sx + sy * sy) / (2 * sigma * sigma))
            norm = math.sqrt(1 + sx * sx + sy * sy)
            seen = max(0.0, -sx * view[0] - sy * view[1] + view[2])  # projected area seen, per unit plane area
            if seen == 0:
                continue
            cosine = max(0.0, (-sx * light[0] - sy * light[1] + light[2]) / norm)
            c = colour(sx, sy)
            w = p * seen
            wsum += w
            lsum += w * cosine
            for k in range(3):
                plain[k] += w * c[k]
                lit[k] += w * cosine * c[k]
    return [x / wsum for x in plain], ([x / lsum for x in lit] if lsum > 0 else None)


def constant_image(path, rgb):
    subprocess.run(["oiiotool", "--pattern", "constant:color=" + ",".join(f"{x:.9g}" for x in rgb), "1x1", "3",
                    "-d", "float", "-o", path], check=True, capture_output=True)


def ciede2000(cmfilter, work, a, b):
    constant_image(f"{work}/a.exr", a)
    constant_image(f"{work}/b.exr", b)
    out = subprocess.run([cmfilter, "compare", f"{work}/a.exr", f"{work}/b.exr", "--json"], check=True,
                         capture_output=True, text=True).stdout
    import json
    return json.loads(out)["ciede2000"]["mean"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("build")
    parser.add_argument("work")
    parser.add_argument("--sigma-s", type=float, default=0.432,
                        help="slope deviation per axis (0.432: sigma_h 0.01, wavelengths 0.05 to 0.4)")
    args = parser.parse_args()
    cmfilter = os.path.join(os.path.abspath(args.build), "tools", "cmfilter")
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    maps = {"steepness": steepness_map(linear_rows(os.path.join(ROOT, "luts/grass-rock.png"))[0]),
            "vector": vector_map(linear_rows(os.path.join(ROOT, "luts/slope-wheel.png")), 1.0)}
    print("| map | set-up | angle | CIEDE2000, <C_s, D_s> against the light-cosine-weighted mean |")
    print("|---|---|---:|---:|")
    for name, colour in maps.items():
        for setup in ("view", "light", "both", "retro"):
            for angle in ANGLES:
                view = direction(angle if setup in ("view", "both", "retro") else 0, 0)
                light = direction(angle if setup in ("light", "both", "retro") else 0, 0 if setup == "retro" else 90)
                plain, lit = averages(colour, args.sigma_s, view, light)
                de = ciede2000(cmfilter, work, plain, lit) if lit else float("nan")
                print(f"| {name} | {setup} | {angle} | {de:.2f} |", flush=True)


if __name__ == "__main__":
    main()
