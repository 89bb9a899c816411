#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Which per-texel representation of a driver's footprint distribution, at
most 4 channels and independent of the colour map, comes closest to the box
reference through hard-edged maps (docs/apply.md, "Beyond two moments").

An independent NumPy study, not the library: footprints are the 2^k x 2^k
blocks of level k (k = 1..8) of scikit-image's photographs, read as data in
[0, 1]; each map is the bundled PNG, linearised, evaluated piecewise linearly
through texel centres and clamped, as ColorMap::evaluate does. Candidates:

  gaussian  the paper's N(mean, sigma^2) of 2 moments (sec. 4.2)
  mixture   p N(a, s^2) + (1 - p) N(b, s^2) matching 4 moments (the library's
            math/moment_mixture.h, re-derived here from the cumulants)
  atoms     2 atoms (Gauss quadrature) matching 3 moments, no width
  bins      4 bins at the driver's global quartiles, 3 weights a texel, each
            bin's colour the mean of C0 over the driver's values in it
  naive     C0(mean)

Gaussian expectations are exact for the piecewise-linear map sampled on 2048
cells (normal CDF differences); CIEDE2000 by scikit-image on the sRGB
encoding of linear RGB. Prints CSV: driver,map,lod,candidate,mean_de2000.

    /usr/bin/python3 tests/bench/texture_representations.py [DRIVERS] > study.csv
DRIVERS: comma-separated skimage.data names (default camera,moon,coins,gravel).
"""
import sys

import numpy as np
import skimage.io
from scipy.special import ndtr
from skimage import color, data

LUTS = __file__.rsplit('/tests/', 1)[0] + '/luts/'
CELLS = 2048


def srgb_to_linear(c):
    c = c / 255.0
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def linear_to_srgb(c):
    c = np.clip(c, 0, 1)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1 / 2.4) - 0.055)


def load_map(name):
    return srgb_to_linear(skimage.io.imread(LUTS + name + '.png')[0, :, :3].astype(float))


def evaluate(cmap, v):
    """C0(v): piecewise linear through texel centres, clamped."""
    n = len(cmap)
    x = np.clip(v * n - 0.5, 0, n - 1)
    i = np.minimum(np.floor(x).astype(int), n - 2)
    t = (x - i)[..., None]
    return cmap[i] * (1 - t) + cmap[i + 1] * t


def gaussian_expectation(cmap, mean, sigma):
    edges = np.linspace(0, 1, CELLS + 1)
    cell_colors = evaluate(cmap, (edges[:-1] + edges[1:]) / 2)
    out = np.zeros(mean.shape + (3,))
    flat_mean, flat_sigma, flat_out = mean.ravel(), np.maximum(sigma.ravel(), 1e-9), out.reshape(-1, 3)
    for s in range(0, flat_mean.size, 4096):
        cdf = ndtr((edges[None, :] - flat_mean[s:s + 4096, None]) / flat_sigma[s:s + 4096, None])
        w = np.diff(cdf, axis=1)
        w[:, 0] += cdf[:, 0]
        w[:, -1] += 1 - cdf[:, -1]
        flat_out[s:s + 4096] = w @ cell_colors
    return out


def block_means(a, k):
    b = 2 ** k
    h, w = a.shape[0] // b, a.shape[1] // b
    return a[:h * b, :w * b].reshape(h, b, w, b, *a.shape[2:]).mean(axis=(1, 3))


def mixture(mean, var, mu3, mu4, two_point=False):
    """Two Gaussians of one width: the two-point part's variance fraction t
    is the positive root of 2 t^3 + kappa t - gamma^2 (cumulants of a
    two-point law), found by bisection on [0, 1]; two_point forces t = 1."""
    ok = var > 1e-12
    safe = np.where(ok, var, 1.0)
    kappa = np.where(ok, mu4 / safe ** 2 - 3, 0)
    gamma2 = np.where(ok, mu3 ** 2 / safe ** 3, 0)
    if two_point:
        t = np.where(ok, 1.0, 0.0)
    else:
        lo, hi = np.zeros_like(mean), np.ones_like(mean)
        for _ in range(60):
            mid = (lo + hi) / 2
            below = 2 * mid ** 3 + kappa * mid - gamma2 < 0
            lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
        t = np.where(ok, (lo + hi) / 2, 0.0)
    v = t * var
    skew = np.where(v > 1e-14, mu3 / np.maximum(v, 1e-300) ** 1.5, 0)
    p = 0.5 * (1 + skew / np.sqrt(skew * skew + 4))
    d = np.sqrt(v / np.maximum(p * (1 - p), 1e-300))
    return p, mean - (1 - p) * d, mean + p * d, np.sqrt(np.maximum(var - v, 0))


def delta_e(a, b):
    return color.deltaE_ciede2000(color.rgb2lab(linear_to_srgb(a)), color.rgb2lab(linear_to_srgb(b))).mean()


def study(name, f, maps):
    quartile_bin = np.digitize(f, np.quantile(f, [0.25, 0.5, 0.75]))
    for k in range(1, 9):
        raw = [block_means(f ** j, k) for j in (1, 2, 3, 4)]
        mean = raw[0]
        var = np.maximum(raw[1] - mean ** 2, 0)
        mu3 = raw[2] - 3 * mean * raw[1] + 2 * mean ** 3
        mu4 = raw[3] - 4 * mean * raw[2] + 6 * mean ** 2 * raw[1] - 3 * mean ** 4
        p, a, b, s = mixture(mean, var, mu3, mu4)
        atom_p, atom_a, atom_b, _ = mixture(mean, var, mu3, mu4, two_point=True)
        weights = [block_means((quartile_bin == j).astype(float), k) for j in range(4)]
        for map_name in maps:
            cmap = load_map(map_name)
            reference = block_means(evaluate(cmap, f), k)
            candidates = {
                'gaussian': gaussian_expectation(cmap, mean, np.sqrt(var)),
                'mixture': p[..., None] * gaussian_expectation(cmap, a, s)
                + (1 - p)[..., None] * gaussian_expectation(cmap, b, s),
                'atoms': atom_p[..., None] * evaluate(cmap, atom_a) + (1 - atom_p)[..., None] * evaluate(cmap, atom_b),
                'bins': sum(weights[j][..., None] * evaluate(cmap, f[quartile_bin == j]).mean(axis=0)
                            for j in range(4)),
                'naive': evaluate(cmap, mean),
            }
            for candidate, image in candidates.items():
                print(f'{name},{map_name},{k},{candidate},{delta_e(image, reference):.4f}', flush=True)


def main():
    names = sys.argv[1].split(',') if len(sys.argv) > 1 else ['camera', 'moon', 'coins', 'gravel']
    print('driver,map,lod,candidate,mean_de2000')
    np.seterr(all='ignore')
    for name in names:
        study(name, getattr(data, name)().astype(float) / 255.0, ['stripes', 'step', 'narrow-band'])


if __name__ == '__main__':
    main()
