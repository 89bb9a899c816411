# SPDX-License-Identifier: Apache-2.0
# Colour maps and Gaussian colour tables against SciPy: the map decoded from
# the PNG here, T(v, sigma) of eq. 10 by SciPy's Simpson rule on a fine grid.
import numpy as np
import pytest
import scipy.integrate
import scipy.stats

import cmfilter
from conftest import c0, linear_colormap


def quadrature_T(texels, vmin, vmax, v, sigma, nodes=40001):
    """(C0 * N(0, sigma^2))(v) by SciPy's composite Simpson rule on a fine
    grid over +-8 sigma (C0 piecewise linear: error far below the tests')."""
    x = np.linspace(v - 8 * sigma, v + 8 * sigma, nodes)
    weights = scipy.stats.norm.pdf(x, v, sigma)
    return scipy.integrate.simpson(c0(texels, vmin, vmax, x) * weights[:, None], x=x, axis=0)


def test_colormap_texels_are_the_png_decoded_from_srgb(luts):
    m = cmfilter.ColorMap.load(str(luts / "terrain.png"), vmin=-1, vmax=1)
    expected = linear_colormap(luts / "terrain.png")
    assert m.texels.shape == expected.shape
    np.testing.assert_allclose(m.texels, expected, atol=2e-4)
    v = np.linspace(-1.2, 1.2, 97)
    np.testing.assert_allclose(m.evaluate(v), c0(expected, -1, 1, v), atol=2e-4)
    assert not m.texels.flags.writeable


def test_table_lookup_matches_quadrature_of_eq10(luts):
    m = cmfilter.ColorMap.load(str(luts / "terrain.png"))
    table = cmfilter.ColorTable.bake(m, values=256, sigmas=64, sigma_max=0.25, threads=1)
    texels = linear_colormap(luts / "terrain.png")
    rng = np.random.default_rng(3)
    v = rng.uniform(-0.2, 1.2, 12)
    sigma = rng.uniform(0.01, 0.25, 12)
    expected = np.array([quadrature_T(texels, 0, 1, a, s) for a, s in zip(v, sigma)])
    # The exact convolution, no table: quadrature's accuracy.
    np.testing.assert_allclose(m.convolve(v, sigma), expected, atol=5e-4)
    # The table: bilinear between nodes.
    np.testing.assert_allclose(table.lookup(v, sigma), expected, atol=4e-3)
    # Row 0 is the map itself; the nodes are where eq. 10 was evaluated.
    assert table.data.shape == (64, 256, 3)
    np.testing.assert_allclose(table.data[0], c0(texels, 0, 1, table.value_nodes), atol=3e-4)
    j, i = 40, 100
    np.testing.assert_allclose(table.data[j, i],
                               quadrature_T(texels, 0, 1, table.value_nodes[i], table.sigma_nodes[j]), atol=5e-4)


def test_methods_on_arrays_of_mean_and_sigma(luts, tmp_path):
    texels = linear_colormap(luts / "terrain.png")
    table = cmfilter.ColorTable.bake(cmfilter.ColorMap.load(str(luts / "terrain.png")), values=256, sigmas=32)
    table.write(str(tmp_path / "t.exr"))
    table = cmfilter.ColorTable.read(str(tmp_path / "t.exr"))  # C0 comes back from the file's metadata
    mean = np.array([[0.1, 0.35], [0.42, 0.9]])
    sigma = np.array([0.0, 0.05])
    naive = table.color(mean, sigma, method="naive")
    assert naive.shape == (2, 2, 3)
    np.testing.assert_allclose(naive, c0(texels, 0, 1, mean), atol=2e-4)
    exact = table.color(mean, sigma, method="gaussian-exact")
    expected = [[quadrature_T(texels, 0, 1, m, s) if s > 0 else c0(texels, 0, 1, m) for m, s in zip(row, sigma)]
                for row in mean]
    np.testing.assert_allclose(exact, expected, atol=5e-4)
    np.testing.assert_array_equal(table.color(mean, sigma), table.lookup(mean, sigma))
    np.testing.assert_allclose(table.colormap().texels, texels, atol=2e-4)
    with pytest.raises(cmfilter.Error, match="method 'box'"):
        table.color(mean, sigma, method="box")


def test_lookup_broadcasts_and_keeps_shape(luts):
    table = cmfilter.ColorTable.bake(cmfilter.ColorMap.load(str(luts / "step.png")), values=64, sigmas=16)
    mean = np.linspace(0, 1, 10).reshape(2, 5)
    out = table.lookup(mean, 0.05)
    assert out.shape == (2, 5, 3)
    np.testing.assert_array_equal(out.reshape(10, 3), table.lookup(mean.ravel(), np.full(10, 0.05)))


def test_table_file_round_trip(luts, tmp_path):
    table = cmfilter.ColorTable.bake(cmfilter.ColorMap.load(str(luts / "terrain.png")), values=32, sigmas=8)
    path = tmp_path / "terrain.exr"
    table.write(str(path))
    back = cmfilter.ColorTable.read(str(path))
    np.testing.assert_array_equal(back.data, table.data)
    assert back.sigma_max == pytest.approx(table.sigma_max)
    assert back.source["sha256"] == table.source["sha256"] != ""


def test_errors_carry_the_library_message(luts, tmp_path):
    missing = tmp_path / "missing.png"
    with pytest.raises(cmfilter.Error, match="missing.png") as e:
        cmfilter.ColorMap.load(str(missing))
    assert e.value.kind == "io"
    assert isinstance(e.value, RuntimeError)
    # A colour map is not a table.
    with pytest.raises(cmfilter.Error, match="terrain.png") as e:
        cmfilter.ColorTable.read(str(luts / "terrain.png"))
    assert e.value.kind in ("bad_input", "io")
    with pytest.raises(cmfilter.Error, match="values"):
        cmfilter.ColorTable.bake(cmfilter.ColorMap.load(str(luts / "terrain.png")), values=1)
    with pytest.raises(cmfilter.Error, match="wrap"):
        cmfilter.ColorMap.load(str(luts / "terrain.png"), wrap="sideways")
