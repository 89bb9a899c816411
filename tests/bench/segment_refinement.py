#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Fewer channels for a map that changes after the bake: the segment pyramid
(docs/apply.md, "The map changes after the bake: the segment pyramid")
against a Gaussian within each piece of the map, measured in NumPy.

The filtered colour of a footprint is the box mean of C0(f), C0 the map
(scene-linear RGB, decoded from the sRGB PNGs in luts/) applied to an 8-bit
driver f. Map entry i sits at driver value i / 255 (the knot convention
"entry i at i / (N - 1)"; cmfilter's own maps put texel centres at
(i + 0.5) / N), C0 is linear between entries and clamped beyond, so for an
8-bit driver C0(f) is a lookup and the reference, the box mean of C0(f) over
each aligned 2^L x 2^L square, is exact (computed from each square's
histogram). Methods, each as channels stored per texel (float32, 4 bytes a
channel; nothing is stored in half):

  A-greedy  the segment pyramid's design: box means of the hat functions at
            K + 1 breakpoints (K channels: the hats sum to one), weighed by
            the map's least-squares colours at the breakpoints (the map
            projected onto the hats over the driver's level-0 histogram).
            Breakpoints: every map entry at first, then the one whose removal
            raises the histogram-weighted CIEDE2000 of the interpolant least
            is removed, one at a time; then one sweep moves each breakpoint
            to the best of up to 12 entries between its neighbours (least-
            squares fit, weighted mean CIEDE2000 over the driver's values).
  A-arclen  the same hats and least-squares colours, breakpoints at equal
            arc length (summed CIEDE2000 between neighbouring entries) plus
            both entries of every hard edge.
  G         the paper's method (Heitz et al. 2013, eq. 10): the map convolved
            with a Gaussian of the footprint's mean and standard deviation of
            f, 2 channels (first and second moment).
  B, Bm     the refinement: the driver range split only at the map's hard
            edges (a jump: CIEDE2000 between neighbouring entries above
            JUMP_DE; a kink: a second difference in CIELAB above KINK_DE away
            from a jump) into S pieces (Bm: every piece that is not flat cut
            into m pieces of equal arc length); per piece the share P_s, the
            first and second moments of f within it; the colour is
            sum_s P_s T_s(mu_s, sigma_s), T_s the piece's map (restricted to
            the piece, clamped at its ends) convolved with the Gaussian of
            the piece's conditional mean and standard deviation, evaluated
            exactly (closed form for a piecewise-linear map: no table).
            3S - 1 channels (the shares sum to one).
  Bflat     B's colours, counting only the share of a flat piece (its moments
            do not change its colour): S - 1 + 2 x (pieces that are not flat).
            Written only where some piece is flat.

Error: CIEDE2000 between the method's and the reference's box mean,
linear RGB (sRGB / Rec. 709 primaries, D65) to XYZ by the sRGB matrix, then
skimage.color.xyz2lab (D65, 2 degrees); no sRGB encoding on the way, no
clipping. Mean over the texels of each LOD 1-6. Drivers: skimage.data camera,
moon, astronaut (rgb2gray, rounded to 8 bits), 512 x 512, and coins (a
256 x 256 crop). Maps: every 256 x 1 PNG in luts/ (slope-wheel, a 2-D map,
is skipped).

Writes docs/data/segment-refinement.csv (driver,map,method,channels,
bytes_per_texel,lod,mean_de2000) and a markdown table; about 3 minutes on
one core:

    python3 tests/bench/segment_refinement.py [--csv docs/data/segment-refinement.csv] [--summary /tmp/segment-refinement.md]
"""
import os

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import argparse  # noqa: E402
import csv  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402
from scipy.special import ndtr  # noqa: E402
from skimage import color, data, io  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
LODS = [1, 2, 3, 4, 5, 6]
N = 256  # map entries and driver codes
JUMP_DE = 10.0  # CIEDE2000 between neighbouring entries: a jump
KINK_DE = 10.0  # |second difference| in CIELAB at an entry: a kink
A_CHANNELS = list(range(1, 21)) + [24, 28, 32, 40, 48, 64]
B_SPLITS = [1, 2, 3, 4, 5, 6, 8]
TOLERANCE = 0.5
REFINE_PLACES = 12

_XYZ = np.array([[0.4124564, 0.3575761, 0.1804375],
                 [0.2126729, 0.7151522, 0.0721750],
                 [0.0193339, 0.1191920, 0.9503041]])


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def srgb_decode(codes):
    c = np.asarray(codes, dtype=np.float64) / 255.0
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def lab(lin):
    """CIELAB of linear RGB (..., 3), through XYZ, D65 2 degrees."""
    return color.xyz2lab(np.asarray(lin, dtype=np.float64) @ _XYZ.T)


def de2000(lab1, lab2):
    return color.deltaE_ciede2000(lab1, lab2)


# --------------------------------------------------------------------------- inputs

def load_maps(lut_dir):
    maps = {}
    for path in sorted(Path(lut_dir).glob("*.png")):
        img = io.imread(path)
        if img.ndim != 3 or img.shape[0] != 1 or img.shape[1] != N:
            log(f"skipping {path.name}: {img.shape}, not a {N} x 1 map")
            continue
        maps[path.stem] = srgb_decode(img[0, :, :3])
    return maps


def load_drivers():
    astro = np.round(color.rgb2gray(data.astronaut()) * 255.0).astype(np.uint8)
    coins = data.coins()
    return {
        "camera": data.camera()[:512, :512],
        "coins": coins[23:279, 64:320],
        "moon": data.moon()[:512, :512],
        "astronaut": astro[:512, :512],
    }


def level_histograms(f8):
    """Rows: every aligned 2^L x 2^L square of every LOD in LODS, in order;
    columns: the driver's 256 codes; entries: each code's share of the square.
    Returns (sparse matrix, row offsets of each LOD)."""
    h, w = f8.shape
    yy, xx = np.mgrid[0:h, 0:w]
    mats, offsets, start = [], [], 0
    for level in LODS:
        bw, bh = w >> level, h >> level
        block = ((yy >> level) * bw + (xx >> level)).ravel()
        m = sp.coo_matrix((np.full(block.size, 1.0 / (1 << (2 * level))), (block, f8.ravel().astype(np.int64))),
                          shape=(bw * bh, N)).tocsr()
        mats.append(m)
        offsets.append(start)
        start += bw * bh
    return sp.vstack(mats).tocsr(), np.array(offsets)


# --------------------------------------------------------------------------- hard edges and pieces

def hard_edges(lab_map):
    """Jumps (interval i between entries i and i + 1) and kinks (at entry i)."""
    step = de2000(lab_map[:-1], lab_map[1:])
    jumps = [int(i) for i in np.nonzero(step > JUMP_DE)[0]]
    second = np.linalg.norm(np.diff(lab_map, 2, axis=0), axis=1)  # at entry i + 1
    js = set(jumps)
    kinks = [int(i) + 1 for i in np.nonzero(second > KINK_DE)[0] if int(i) not in js and int(i) + 1 not in js]
    return jumps, kinks, step


def edge_pieces(jumps, kinks):
    """Pieces as (first map entry, last map entry, first code, last code):
    a jump's ramp (entries i, i + 1) is left out of both neighbours' maps
    (no 8-bit code falls inside it); a kink's entry belongs to both maps."""
    cuts = sorted([(i, "jump") for i in jumps] + [(i, "kink") for i in kinks])
    pieces, ka, va = [], 0, 0
    for i, kind in cuts:
        if kind == "jump":
            pieces.append((ka, i, va, i))
            ka, va = i + 1, i + 1
        else:
            pieces.append((ka, i, va, i - 1))
            ka, va = i, i
    pieces.append((ka, N - 1, va, N - 1))
    return pieces


def is_flat(lin_map, ka, kb):
    seg = lin_map[ka:kb + 1]
    return bool(np.all(np.abs(seg - seg[0]) < 1e-12))


def split_piece(piece, m, step, lin_map):
    """Cut a piece that is not flat into m pieces of equal arc length (summed
    CIEDE2000 of neighbouring entries), at map entries."""
    ka, kb, va, vb = piece
    if m == 1 or kb - ka < 2 or is_flat(lin_map, ka, kb):
        return [piece]
    arc = np.concatenate([[0.0], np.cumsum(step[ka:kb])])  # arc[j - ka] at entry j
    cuts = []
    for q in range(1, m):
        j = ka + int(np.argmin(np.abs(arc - arc[-1] * q / m)))
        j = min(max(j, va + 1, ka + 1), kb - 1)
        if (not cuts or j > cuts[-1]) and j <= vb:
            cuts.append(j)
    out, a, v = [], ka, va
    for j in cuts:
        out.append((a, j, v, j - 1))
        a, v = j, j
    out.append((a, kb, v, vb))
    return out


# --------------------------------------------------------------------------- G and B

def gaussian_of_piece(lin_map, ka, kb, mu, sigma):
    """(C_piece * N(0, sigma^2))(mu), C_piece the map through entries ka..kb,
    clamped beyond: C(ka) + sum_j dslope_j E[(X - x_j)^+]."""
    x = np.arange(ka, kb + 1) / (N - 1.0)
    c = lin_map[ka:kb + 1]
    out = np.repeat(c[:1], mu.size, axis=0)
    if kb == ka:
        return out
    slope = np.diff(c, axis=0) / np.diff(x)[:, None]
    dslope = np.diff(np.vstack([np.zeros((1, 3)), slope, np.zeros((1, 3))]), axis=0)
    keep = np.any(np.abs(dslope) > 0, axis=1)
    x, dslope = x[keep], dslope[keep]
    if x.size == 0:
        return out
    sig = np.maximum(sigma, 1e-12)
    rows = max(1, 4_000_000 // x.size)
    for r0 in range(0, mu.size, rows):
        d = mu[r0:r0 + rows, None] - x[None, :]
        z = d / sig[r0:r0 + rows, None]
        g = d * ndtr(z) + sig[r0:r0 + rows, None] * np.exp(-0.5 * z * z) * (1.0 / np.sqrt(2.0 * np.pi))
        out[r0:r0 + rows] += g @ dslope
    return out


def piecewise_gaussian(hist, lin_map, pieces):
    """sum_s P_s T_s(mu_s, sigma_s) for every row of hist; the 3 box means of
    each piece rounded to float32 as a float pyramid would store them."""
    f = np.arange(N) / (N - 1.0)
    out = np.zeros((hist.shape[0], 3))
    for ka, kb, va, vb in pieces:
        ind = np.zeros(N)
        ind[va:vb + 1] = 1.0
        mom = (hist @ np.stack([ind, ind * f, ind * f * f], axis=1)).astype(np.float32).astype(np.float64)
        p = mom[:, 0]
        sel = p > 0
        if not np.any(sel):
            continue
        mu = mom[sel, 1] / p[sel]
        var = np.maximum(mom[sel, 2] / p[sel] - mu * mu, 0.0)
        out[sel] += p[sel, None] * gaussian_of_piece(lin_map, ka, kb, mu, np.sqrt(var))
    return out


# --------------------------------------------------------------------------- A

def hats(breakpoints):
    """The hat functions at the breakpoints (map entries), sampled at every
    entry: (N, len(breakpoints)); clamped beyond the ends."""
    b = np.asarray(breakpoints)
    basis = np.zeros((N, b.size))
    eye = np.eye(b.size)
    idx = np.arange(N)
    for k in range(b.size):
        basis[:, k] = np.interp(idx, b, eye[k])
    return basis


def least_squares_colors(breakpoints, lin_map, weights):
    basis = hats(breakpoints)
    ridge = 1e-9
    a = basis.T @ (basis * weights[:, None]) + ridge * np.eye(basis.shape[1])
    rhs = basis.T @ (lin_map * weights[:, None]) + ridge * lin_map[np.asarray(breakpoints)]
    return basis @ np.linalg.solve(a, rhs)  # the approximated map at every entry


def weighted_fit_error(breakpoints, lin_map, lab_map, weights, used):
    approx = least_squares_colors(breakpoints, lin_map, weights)
    return float(np.sum(weights[used] * de2000(lab_map[used], lab(approx[used]))))


def greedy_breakpoints(lin_map, lab_map, weights, wanted):
    """Remove breakpoints (map entries) one at a time, the one whose removal
    raises the weighted CIEDE2000 of the interpolant least (beyond the first
    and the last breakpoint the interpolant is constant, so a flat end needs
    none); the sets with len - 1 in wanted, at least two breakpoints."""
    # Positions 1..N are the entries 0..N-1; 0 and N + 1 are sentinels.
    def seg_err(pa, pb):
        if pa == 0:
            v, col = np.arange(0, pb - 1), None
            const = lin_map[pb - 1]
        elif pb == N + 1:
            v, col = np.arange(pa, N), None
            const = lin_map[pa - 1]
        else:
            a, b = pa - 1, pb - 1
            v = np.arange(a + 1, b)
        v = v[weights[v] > 0]
        if v.size == 0:
            return 0.0
        if pa == 0 or pb == N + 1:
            col = np.repeat(const[None, :], v.size, axis=0)
        else:
            t = ((v - a) / (b - a))[:, None]
            col = lin_map[a] * (1 - t) + lin_map[b] * t
        return float(np.sum(weights[v] * de2000(lab_map[v], lab(col))))

    size = N + 2
    prev = np.arange(-1, size - 1)
    nxt = np.arange(1, size + 1)
    alive = np.zeros(size, bool)
    alive[1:N + 1] = True
    err_right = np.zeros(size)  # error of the interval from a live position to the next
    merged = np.full(size, np.inf)
    cost = np.full(size, np.inf)

    def update(k):
        if k <= 0 or k >= N + 1:
            return
        merged[k] = seg_err(prev[k], nxt[k])
        cost[k] = merged[k] - err_right[prev[k]] - err_right[k]

    for k in range(1, N + 1):
        update(k)
    sets = {}
    count = N
    while count > 2:
        if count - 1 in wanted:
            sets[count - 1] = [int(i) - 1 for i in np.nonzero(alive)[0]]
        k = int(np.argmin(cost))
        p, n = prev[k], nxt[k]
        err_right[p] = merged[k]
        alive[k] = False
        cost[k] = np.inf
        nxt[p], prev[n] = n, p
        count -= 1
        update(p)
        update(n)
    sets[1] = [int(i) - 1 for i in np.nonzero(alive)[0]]
    return sets


def refine_breakpoints(bps, lin_map, lab_map, weights, used):
    """One sweep: each interior breakpoint to the best of up to 12 entries
    between its neighbours (least-squares fit, weighted mean CIEDE2000)."""
    bps = list(bps)
    best = weighted_fit_error(bps, lin_map, lab_map, weights, used)
    for i in range(1, len(bps) - 1):
        lo, hi = bps[i - 1] + 1, bps[i + 1] - 1
        if hi <= lo:
            continue
        places = np.unique(np.round(np.linspace(lo, hi, min(REFINE_PLACES, hi - lo + 1))).astype(int))
        for j in places:
            if j == bps[i]:
                continue
            trial = bps[:i] + [int(j)] + bps[i + 1:]
            e = weighted_fit_error(trial, lin_map, lab_map, weights, used)
            if e < best:
                best, bps = e, trial
    return bps


def arclen_breakpoints(lin_map, step, jumps, channels):
    moving = np.nonzero(np.any(np.abs(np.diff(lin_map, axis=0)) > 0, axis=1))[0]
    if moving.size == 0:
        return None
    forced = {int(moving[0]), int(moving[-1]) + 1}  # a flat end needs no breakpoint
    for i in jumps:
        forced |= {i, i + 1}
    free = channels + 1 - len(forced)
    if free < 0:
        return None
    s = step.copy()
    s[jumps] = 0.0
    arc = np.concatenate([[0.0], np.cumsum(s)])
    targets = np.linspace(0.0, arc[-1], free + 2)[1:-1]
    picked = set(forced)
    for t in targets:
        picked.add(int(np.argmin(np.abs(arc - t))))
    return sorted(picked)


# --------------------------------------------------------------------------- measuring

def per_lod_means(ref_lab, colours, offsets):
    d = de2000(ref_lab, lab(colours))
    return np.add.reduceat(d, offsets) / np.diff(np.append(offsets, d.size))


def worst_over_lods(rows):
    """(driver, map, method, channels) -> worst mean over the LODs."""
    worst = {}
    for r in rows:
        key = (r["driver"], r["map"], r["method"], r["channels"])
        worst[key] = max(worst.get(key, 0.0), r["mean_de2000"])
    return worst


def fewest_cell(worst, driver, mapname, methods):
    """Fewest channels whose worst mean is within TOLERANCE over the methods,
    as text: '13', or '>23' where none is (23: the most measured)."""
    cand = [(ch, w) for (d, m, me, ch), w in worst.items() if d == driver and m == mapname and me in methods]
    if not cand:
        return "-"
    ok = [ch for ch, w in cand if w <= TOLERANCE]
    return str(min(ok)) if ok else f">{max(ch for ch, _ in cand)}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--luts", default=str(ROOT / "luts"))
    ap.add_argument("--csv", default=str(ROOT / "docs" / "data" / "segment-refinement.csv"))
    ap.add_argument("--summary", default="/tmp/segment-refinement.md")
    ap.add_argument("--drivers", default="camera,coins,moon,astronaut")
    ap.add_argument("--maps", default="")
    args = ap.parse_args()

    t0 = time.time()
    maps = load_maps(args.luts)
    if args.maps:
        maps = {k: v for k, v in maps.items() if k in args.maps.split(",")}
    all_drivers = load_drivers()
    drivers = {k: all_drivers[k] for k in args.drivers.split(",")}
    rows = []
    edges_info = {}

    def add(driver, mapname, method, channels, means):
        for level, m in zip(LODS, means):
            rows.append({"driver": driver, "map": mapname, "method": method, "channels": int(channels),
                         "bytes_per_texel": 4 * int(channels), "lod": level, "mean_de2000": float(m)})

    for dname, f8 in drivers.items():
        hist, offsets = level_histograms(f8)
        counts = np.bincount(f8.ravel(), minlength=N).astype(np.float64)
        weights = counts / counts.sum()
        used = weights > 0
        for mname, lin_map in maps.items():
            t1 = time.time()
            lab_map = lab(lin_map)
            ref_lab = lab(hist @ lin_map)
            jumps, kinks, step = hard_edges(lab_map)
            edges_info[mname] = (jumps, kinks)

            # G: one Gaussian over the whole map.
            add(dname, mname, "G", 2, per_lod_means(ref_lab, piecewise_gaussian(hist, lin_map, [(0, N - 1, 0, N - 1)]),
                                                     offsets))

            # B and Bm: pieces at the hard edges, optionally cut further.
            base = edge_pieces(jumps, kinks)
            seen = set()
            for m in B_SPLITS:
                pieces = [q for p in base for q in split_piece(p, m, step, lin_map)]
                key = tuple(pieces)
                if key in seen:
                    continue
                seen.add(key)
                means = per_lod_means(ref_lab, piecewise_gaussian(hist, lin_map, pieces), offsets)
                s = len(pieces)
                add(dname, mname, "B" if m == 1 else f"B{m}", 3 * s - 1, means)
                if m == 1:
                    flat = sum(is_flat(lin_map, p[0], p[1]) for p in pieces)
                    if flat:
                        add(dname, mname, "Bflat", s - 1 + 2 * (s - flat), means)

            # A: hats at breakpoints, least-squares colours.
            sets = greedy_breakpoints(lin_map, lab_map, weights, set(A_CHANNELS))
            done = set()
            for k in A_CHANNELS:
                bps = sets.get(k)
                if bps is None:
                    continue
                bps = refine_breakpoints(bps, lin_map, lab_map, weights, used)
                approx = least_squares_colors(bps, lin_map, weights)
                add(dname, mname, "A-greedy", len(bps) - 1, per_lod_means(ref_lab, hist @ approx, offsets))
            for k in A_CHANNELS:
                bps = arclen_breakpoints(lin_map, step, jumps, k)
                if bps is None or tuple(bps) in done:
                    continue
                done.add(tuple(bps))
                approx = least_squares_colors(bps, lin_map, weights)
                add(dname, mname, "A-arclen", len(bps) - 1, per_lod_means(ref_lab, hist @ approx, offsets))
            log(f"{dname} {mname}: {len(jumps)} jumps, {len(kinks)} kinks, {len(base)} pieces, "
                f"{time.time() - t1:.1f} s (total {time.time() - t0:.0f} s)")

    Path(args.csv).parent.mkdir(parents=True, exist_ok=True)
    fields = ["driver", "map", "method", "channels", "bytes_per_texel", "lod", "mean_de2000"]
    with open(args.csv, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=fields)
        w.writeheader()
        for r in rows:
            w.writerow({**r, "mean_de2000": f"{r['mean_de2000']:.6g}"})
    log(f"wrote {args.csv} ({len(rows)} rows) in {time.time() - t0:.0f} s")
    write_summary(args.summary, rows, list(drivers), list(maps), edges_info, time.time() - t0)


def write_summary(path, rows, drivers, mapnames, edges_info, seconds):
    worst = worst_over_lods(rows)
    b_methods = ["B"] + [f"B{m}" for m in B_SPLITS if m > 1]
    order = " / ".join(drivers)
    lines = [f"| map | hard edges | G, 2 ch: worst mean ({order}) | A: fewest ch | B, Bm (3S - 1): fewest ch | "
             f"with Bflat: fewest ch |", "|---|---|---|---|---|---|"]
    for mname in mapnames:
        jumps, kinks = edges_info[mname]
        edge = f"{len(jumps)} jumps" + (f", {len(kinks)} kinks" if kinks else "") if jumps or kinks else "none"
        g = " / ".join(f"{worst[(d, mname, 'G', 2)]:.2f}" for d in drivers)
        cells = [g]
        for methods in (["A-greedy", "A-arclen"], b_methods, b_methods + ["Bflat"]):
            cells.append(" / ".join(fewest_cell(worst, d, mname, methods) for d in drivers))
        lines.append(f"| {mname} | {edge} | " + " | ".join(cells) + " |")
    text = ["# Segment pyramid (A) against a Gaussian within each piece (B)", "",
            "    /usr/bin/python3 tests/bench/segment_refinement.py", "",
            f"Fewest channels (float32, 4 bytes each) whose worst mean CIEDE2000 over LOD 1-6 is within "
            f"{TOLERANCE}, per driver ({order}); A: best of A-greedy and A-arclen, channels 1-20, 24, 28, 32, 40, "
            f"48, 64; B: pieces at the hard edges cut into m = {', '.join(map(str, B_SPLITS))}; "
            f">N: not met within N, the most measured. Run time {seconds:.0f} s.", ""] + lines + [""]
    Path(path).write_text("\n".join(text))
    log(f"wrote {path}")


if __name__ == "__main__":
    main()
