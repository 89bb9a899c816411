# SPDX-License-Identifier: Apache-2.0
# Synthetic stacks and the microsurface functions against NumPy and SciPy:
# the Fibonacci dome from its formula; a displacement's traced normals and
# images from the piecewise-linear profile through its texel heights (a
# pixel's 4 x 4 strata each lie on one linear piece, so the mean of
# <n, l> over them is exact); a flat tile's PNG stack as colour x cos,
# encoded to sRGB here; Smith's Lambda and the heights seen lit by SciPy's
# quadrature of their definitions (eqs. 3, 15-16), eqs. 13, 17-18 evaluated
# here.
import json

import numpy as np
import pytest
import scipy.integrate
import scipy.stats
import tifffile

import cmfilter
from conftest import read_png, srgb_to_linear, write_png8
from test_ops import srgb_encode

TEXELS = 16  # displacement texels per side
CODES = np.array([204, 128, 64])  # the map's one colour, 8-bit sRGB


def displacement_scene(folder, heights):
    """A plane displaced by heights[j, i] (texture units), coloured by one
    colour; returns the scene's path and the colour, scene-linear."""
    tifffile.imwrite(folder / "heights.tif", heights.astype(np.float32))
    write_png8(folder / "map.png", np.tile(CODES / 255, (1, 2, 1)))
    scene = {
        "camera": {"position": [0, 1, 0], "look_at": [0, 0, 4], "resolution": [8, 8]},
        "light": {"direction": [0, 1, 0]},
        "surfaces": [{
            "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
            "mapping": {"type": "planar", "u_axis": [1, 0, 0], "v_axis": [0, 0, 1]},
            "material": {"displacement": {"image": "heights.tif", "height_scale": 1},
                         "colormap": {"image": "map.png", "domain": [-1, 1]}}}],
    }
    (folder / "scene.json").write_text(json.dumps(scene))
    return str(folder / "scene.json"), srgb_to_linear(CODES / 255)


# The profile along u: linear between texel centres (k + 1/2) / N, periodic.
PROFILE = (0.02 * np.sin(2 * np.pi * (np.arange(TEXELS) + 0.5) / TEXELS)).astype(np.float32).astype(np.float64)


def slope(u):
    k = np.floor(u * TEXELS - 0.5).astype(int)
    return (PROFILE[(k + 1) % TEXELS] - PROFILE[k % TEXELS]) * TEXELS


def height(u):
    k = np.floor(u * TEXELS - 0.5).astype(int)
    return PROFILE[k % TEXELS] + (u - (k + 0.5) / TEXELS) * slope(u)


def pieces(a, b):
    """The linear pieces' slopes over [a, b] and the share of it each covers."""
    nodes = (np.arange(-1, TEXELS + 1) + 0.5) / TEXELS
    edges = np.concatenate([[a], nodes[(nodes > a) & (nodes < b)], [b]])
    return slope(0.5 * (edges[1:] + edges[:-1])), np.diff(edges) / (b - a)


@pytest.fixture
def relief(tmp_path):
    return displacement_scene(tmp_path, np.tile(PROFILE, (TEXELS, 1)))


def test_fibonacci_dome_is_the_golden_angle_spiral():
    n, e = 20, np.radians(15)
    lights = cmfilter.light_dome(f"fibonacci:{n}", min_elevation_degrees=15)
    k = np.arange(n)
    z = np.sin(e) + (1 - np.sin(e)) * (k + 0.5) / n
    phi = k * np.pi * (3 - np.sqrt(5))
    r = np.sqrt(1 - z * z)
    np.testing.assert_allclose(lights, np.stack([r * np.cos(phi), r * np.sin(phi), z], axis=1), atol=1e-12)
    regular = cmfilter.light_dome("regular:30")
    assert regular.shape == (30, 3)
    np.testing.assert_allclose(np.linalg.norm(regular, axis=1), 1, atol=1e-12)
    assert regular[:, 2].min() >= np.sin(np.radians(10)) - 1e-12 and regular[:, 2].max() == pytest.approx(1)
    with pytest.raises(cmfilter.Error, match="sphere:4") as e:
        cmfilter.light_dome("sphere:4")
    assert e.value.kind == "bad_input"


def test_trace_hits_the_profile_with_its_facet_normal(relief):
    scene, colour = relief
    surface = cmfilter.SyntheticSurface.load(scene)
    assert (surface.kind, surface.tile) == ("displacement", 1.0)
    u = np.array([0.05, 0.21, 0.4, 0.66, 0.93])
    hits = surface.trace(u, 0.37)
    assert hits["hit"].all() and hits["normal"].shape == (5, 3)
    s = slope(u)
    np.testing.assert_allclose(hits["normal"], np.stack([-s, 0 * s, np.ones(5)], axis=1) / np.hypot(1, s)[:, None],
                               atol=1e-9)
    np.testing.assert_allclose(hits["point"][:, 2], height(u), atol=1e-7)
    np.testing.assert_allclose(hits["color"], np.tile(colour, (5, 1)), atol=2e-4)


def test_stack_images_are_colour_times_the_pixels_mean_cosine(relief):
    scene, colour = relief
    surface = cmfilter.SyntheticSurface.load(scene)
    lights = np.array([[0, 0, 1], [0.5, 0, 0.866], [-0.4, 0.3, 0.866]])
    lights /= np.linalg.norm(lights, axis=1)[:, None]
    size = 8
    stack = surface.render_stack(lights, size=size, samples=16, seed=3, albedo=True, threads=2)
    assert stack["images"].shape == (3, size, size, 3) and stack["images"].dtype == np.float32
    for i in range(size):
        s, w = pieces(i / size, (i + 1) / size)
        n = np.stack([-s, 0 * s, np.ones_like(s)], axis=1) / np.hypot(1, s)[:, None]
        # Heights vary along u alone: the stack's y = -v does not meet the normals.
        cosines = np.maximum(0, n @ (lights * [1, -1, 1]).T)
        expected = (w @ cosines)[:, None] * colour
        np.testing.assert_allclose(stack["images"][:, :, i, :], np.repeat(expected[:, None, :], size, axis=1),
                                   rtol=1e-5, atol=1e-6)
        mean_normal = w @ n
        np.testing.assert_allclose(stack["normals"][:, i, :], np.tile(mean_normal / np.linalg.norm(mean_normal),
                                                                      (size, 1)), atol=1e-6)
    np.testing.assert_allclose(stack["albedo"], np.broadcast_to(colour, (size, size, 3)), atol=2e-4)
    with pytest.raises(cmfilter.Error, match="view") as e:
        surface.render_stack(lights, view=(0, 1, -0.5), size=2)
    assert e.value.kind == "bad_input"


def test_make_stack_of_a_flat_tile_writes_colour_times_cos(tmp_path):
    scene, colour = displacement_scene(tmp_path, np.full((TEXELS, TEXELS), 0.1))
    made = cmfilter.make_stack(scene, str(tmp_path / "stack.lp"), size=4, samples=1, dome="fibonacci:6",
                               min_elevation_degrees=20, image_extension=".png")
    assert (made["lights"], made["size"], made["surface_kind"]) == (6, 4, "displacement")
    lines = (tmp_path / "stack.lp").read_text().split("\n")
    assert int(lines[0]) == 6
    names = [line.split()[0] for line in lines[1:7]]
    lights = np.array([[float(x) for x in line.split()[1:]] for line in lines[1:7]])
    k = np.arange(6)
    z = np.sin(np.radians(20)) + (1 - np.sin(np.radians(20))) * (k + 0.5) / 6
    np.testing.assert_allclose(lights[:, 2], z, atol=1e-6)
    for name, light in zip(names, lights):
        image = read_png(tmp_path / name)
        expected = np.round(srgb_encode(colour * light[2]) * 255) / 255
        np.testing.assert_allclose(image[:, :, :3], np.broadcast_to(expected, (4, 4, 3)), atol=1.01 / 255)
    record = json.loads((tmp_path / "stack.json").read_text())
    assert (record["size"], record["samples"], record["images"]) == (4, 1, ".png")
    with pytest.raises(cmfilter.Error, match="6") as e:
        cmfilter.make_stack(scene, str(tmp_path / "few.lp"), size=2, samples=1, dome="fibonacci:3")
    assert e.value.kind == "bad_input"
    assert not (tmp_path / "few.lp").exists()


def test_smith_lambda_is_its_integral():
    # Eq. 3 as its definition: Lambda(mu) = int_mu^inf (s - mu) p(s) ds / mu,
    # mu = cot theta, slopes N(0, sigma_s^2).
    theta = np.array([0.3, 0.7, 1.2, 1.5])[:, None]
    sigma_s = np.array([0.2, 0.5, 1.0])[None, :]
    lam = cmfilter.smith_lambda(theta, sigma_s)
    assert lam.shape == (4, 3)
    for (i, j), value in np.ndenumerate(lam):
        mu, s = 1 / np.tan(theta[i, 0]), sigma_s[0, j]
        integral = scipy.integrate.quad(lambda x: (x - mu) * scipy.stats.norm.pdf(x, 0, s), mu, np.inf,
                                        epsabs=1e-14)[0]
        assert value == pytest.approx(integral / mu, rel=1e-6, abs=1e-13)
    assert cmfilter.smith_lambda(0.0, 0.5) == 0 and cmfilter.smith_lambda(np.pi / 2, 0.5) == np.inf
    with pytest.raises(cmfilter.Error, match="sigma_s") as e:
        cmfilter.smith_lambda(0.5, -1)
    assert e.value.kind == "bad_input"


def test_visibility_and_lambda_sums_are_eq13_and_the_correlated_form():
    lo, li = np.array([0.0, 0.3, 2.0]), np.array([[0.1], [1.5]])
    np.testing.assert_allclose(cmfilter.mean_visibility(lo, li), (1 + lo) / (1 + lo + li), rtol=1e-12)
    phi = 1.2
    weight = 4.41 * phi / (4.41 * phi + 1)
    total = np.maximum(lo, li) + weight * np.minimum(lo, li)
    np.testing.assert_allclose(cmfilter.lambda_sum(lo, li, phi, masking="correlated"), total, rtol=1e-12)
    np.testing.assert_allclose(cmfilter.mean_visibility(lo, li, phi, masking="correlated"), (1 + lo) / (1 + total),
                               rtol=1e-12)
    with pytest.raises(cmfilter.Error, match="masking 'both'"):
        cmfilter.lambda_sum(0, 0, masking="both")


def test_height_moments_are_those_of_the_heights_seen_lit():
    # D_h(h) = (L + 1) P_h(h)^L p_h(h) (eqs. 15-16), by quadrature.
    sigma_h = 0.2
    for lam in (0.0, 2.5, 40.0):
        density = lambda h: (lam + 1) * scipy.stats.norm.cdf(h, 0, sigma_h) ** lam * scipy.stats.norm.pdf(h, 0, sigma_h)
        mean = scipy.integrate.quad(lambda h: h * density(h), -2, 2, epsabs=1e-13)[0]
        var = scipy.integrate.quad(lambda h: (h - mean) ** 2 * density(h), -2, 2, epsabs=1e-13)[0]
        m, s = cmfilter.height_moments(lam, sigma_h)
        assert m == pytest.approx(mean, abs=1e-9) and s == pytest.approx(np.sqrt(var), rel=1e-7)
    lam = np.array([0.0, 1.0, 10.0])
    m, s = cmfilter.height_moments(lam, sigma_h, fit="paper")
    np.testing.assert_allclose(m, 0.39 * sigma_h * np.log(4.75 * lam + 1), rtol=1e-12)
    np.testing.assert_allclose(s, sigma_h / (1 + 0.26 * np.log(1.13 * lam + 1)), rtol=1e-12)
