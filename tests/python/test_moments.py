# SPDX-License-Identifier: Apache-2.0
# Drivers and moment pyramids against NumPy: the driver's codes / 255 read
# here, each level's mean and sigma as box means of f and f^2 (sec. 4.2).
import numpy as np
import pytest
import tifffile

import cmfilter
from conftest import c0, linear_colormap, write_png8
from test_tables import quadrature_T


def box_levels(f, level):
    """Box means of f and f^2 over 2^level x 2^level blocks (a power-of-two driver)."""
    b = 2**level
    h, w = f.shape
    blocks = lambda x: x.reshape(h // b, b, w // b, b).mean(axis=(1, 3))
    return blocks(f), blocks(f * f)


@pytest.fixture
def driver(tmp_path):
    rng = np.random.default_rng(11)
    y, x = np.mgrid[0:32, 0:32]
    values = 0.5 + 0.3 * np.sin(x / 3.0) * np.cos(y / 5.0) + 0.1 * rng.standard_normal((32, 32))
    path = tmp_path / "driver.png"
    return path, write_png8(path, np.clip(values, 0, 1))


def test_read_driver_is_codes_over_255(driver):
    path, f = driver
    read = cmfilter.read_driver(str(path))
    assert read.dtype == np.float32 and read.shape == (32, 32)
    np.testing.assert_allclose(read, f, atol=1e-7)


@pytest.mark.parametrize("level", [0, 1, 2, 3])
def test_level_mean_and_sigma_are_box_moments(driver, tmp_path, level):
    path, f = driver
    pyramid = cmfilter.MomentPyramid.bake(str(path), str(tmp_path / "moments.exr"), threads=1)
    assert (pyramid.width, pyramid.height, pyramid.levels) == (32, 32, 6)
    m1, m2 = box_levels(f, level)
    mean, sigma = pyramid.level(level)
    np.testing.assert_allclose(mean, m1, atol=2e-6)
    np.testing.assert_allclose(sigma, np.sqrt(np.maximum(m2 - m1 * m1, 0)), atol=5e-4)


def test_lookup_at_texel_centres_and_between_levels(driver, tmp_path):
    path, f = driver
    pyramid = cmfilter.MomentPyramid.bake(str(path), str(tmp_path / "moments.exr"))
    m1, _ = box_levels(f, 2)
    y, x = np.mgrid[0:8, 0:8]
    mean, sigma = pyramid.lookup((x + 0.5) / 8, (y + 0.5) / 8, 2.0)
    np.testing.assert_allclose(mean, m1, atol=2e-6)
    # A fractional LOD blends levels 1 and 2 linearly; at level 1's texel
    # centres level 2 is read bilinearly (edge texels clamped).
    a, _ = box_levels(f, 1)
    b, _ = box_levels(f, 2)
    y, x = np.mgrid[0:16, 0:16]
    mean, _ = pyramid.lookup((x + 0.5) / 16, (y + 0.5) / 16, 1.25)
    np.testing.assert_allclose(mean, 0.75 * a + 0.25 * bilinear(b, x / 2 - 0.25, y / 2 - 0.25), atol=2e-6)


def bilinear(img, cx, cy):
    """img at continuous texel coordinates (centre of texel i at i), edges clamped."""
    x0, y0 = np.floor(cx).astype(int), np.floor(cy).astype(int)
    fx, fy = cx - x0, cy - y0
    h, w = img.shape
    at = lambda yy, xx: img[np.clip(yy, 0, h - 1), np.clip(xx, 0, w - 1)]
    top = (1 - fx) * at(y0, x0) + fx * at(y0, x0 + 1)
    bottom = (1 - fx) * at(y0 + 1, x0) + fx * at(y0 + 1, x0 + 1)
    return (1 - fy) * top + fy * bottom


def test_not_a_moment_pyramid(luts):
    with pytest.raises(cmfilter.Error, match="terrain.png") as e:
        cmfilter.MomentPyramid.open(str(luts / "terrain.png"))
    assert e.value.kind == "bad_input"
    with pytest.raises(cmfilter.Error, match="nothing-here.png") as e:
        cmfilter.read_driver("nothing-here.png")
    assert e.value.kind == "io"


def block_moments(f, by, bx):
    """Per by x bx block of f: box means of f and the standard deviations within."""
    h, w = f.shape
    blocks = f.reshape(h // by, by, w // bx, bx)
    mean = blocks.mean(axis=(1, 3))
    return mean, np.sqrt(np.maximum((blocks * blocks).mean(axis=(1, 3)) - mean * mean, 0))


def test_footprint_probes_on_aligned_blocks_are_box_moments(driver, tmp_path):
    # An 8 x 2 texel footprint is cut into 4 probes of 2 x 2 texels (rms width
    # 2, LOD 1): centred on level-1 texels, each reads one, so the footprint's
    # mean is the box mean of its 16 texels and its sigma the mean of the 2 x 2
    # blocks' standard deviations (brute force over the texels here).
    path, f = driver
    pyramid = cmfilter.MomentPyramid.bake(str(path), str(tmp_path / "moments.exr"))
    x0, y0 = np.array([0, 8, 16, 24, 6]), np.array([0, 6, 12, 30, 20])
    along_u = pyramid.lookup_footprint((x0 + 4) / 32, (y0 + 1) / 32, 8 / 32, 0, 0, 2 / 32)
    along_v = pyramid.lookup_footprint((y0 + 1) / 32, (x0 + 4) / 32, 0, 8 / 32, 2 / 32, 0)
    for result, g in ((along_u, f), (along_v, f.T)):
        np.testing.assert_array_equal(result["probes"], 4)
        np.testing.assert_allclose(result["lod"], 1.0, atol=1e-12)
        mean, sigma = block_moments(np.stack([g[y:y + 2, x:x + 8] for x, y in zip(x0, y0)]).reshape(-1, 8), 2, 2)
        np.testing.assert_allclose(result["mean"], mean.reshape(5, 4).mean(axis=1), atol=2e-6)
        np.testing.assert_allclose(result["sigma"], sigma.reshape(5, 4).mean(axis=1), atol=5e-4)
    # One probe: the whole footprint as one square of its rms width.
    one = pyramid.lookup_footprint(0.5, 0.5, 8 / 32, 0, 0, 2 / 32, probes=1)
    assert one["probes"] == 1 and one["lod"] == pytest.approx(np.log2(np.sqrt((64 + 4) / 2)))


@pytest.mark.parametrize("level", [1, 3])
def test_anisotropic_lookup_at_equal_axes_is_the_levels_box_moments(driver, tmp_path, level):
    path, f = driver
    pyramid = cmfilter.MomentPyramid.bake(str(path), str(tmp_path / "moments.exr"))
    n = 32 >> level
    y, x = np.mgrid[0:n, 0:n]
    mean, sigma = pyramid.lookup_anisotropic((x + 0.5) / n, (y + 0.5) / n, 1 / n, 0, 0, 1 / n)
    m1, m2 = box_levels(f, level)
    np.testing.assert_allclose(mean, m1, atol=2e-6)
    np.testing.assert_allclose(sigma, np.sqrt(np.maximum(m2 - m1 * m1, 0)), atol=5e-4)


def test_anisotropic_means_of_a_linear_driver_are_its_value_at_the_centre(tmp_path):
    # f = (3 x + 4 y) / 255 exactly (8-bit codes): any footprint symmetric
    # about its centre, filtered by box means and bilinear weights, has the
    # mean f(centre), however long, thin and rotated it is.
    y, x = np.mgrid[0:32, 0:32]
    write_png8(tmp_path / "ramp.png", (3 * x + 4 * y) / 255)
    pyramid = cmfilter.MomentPyramid.bake(str(tmp_path / "ramp.png"), str(tmp_path / "moments.exr"))
    angle = np.array([0.0, 0.5, 1.1, 2.0])[:, None]
    length, width = np.array([12.0, 6.0, 3.0])[None, :] / 32, 1.5 / 32
    e1 = length * np.cos(angle), length * np.sin(angle)
    e2 = -width * np.sin(angle), width * np.cos(angle)
    u, v = 15.3 / 32, 16.6 / 32
    expected = (3 * (u * 32 - 0.5) + 4 * (v * 32 - 0.5)) / 255
    probes = pyramid.lookup_footprint(u, v, e1[0], e1[1], e2[0], e2[1])
    assert probes["mean"].shape == (4, 3) and (probes["probes"] > 1).all()
    np.testing.assert_allclose(probes["mean"], expected, atol=2e-5)
    mean, sigma = pyramid.lookup_anisotropic(u, v, e1[0], e1[1], e2[0], e2[1])
    np.testing.assert_allclose(mean, expected, atol=2e-5)
    # Across the footprint f changes by (3, 4) . e2 texels at most: sigma is below that.
    assert (sigma > 0).all() and (sigma < np.hypot(3, 4) * 32 * length / 255).all()


@pytest.fixture
def quantised(tmp_path):
    """A driver of five distinct values, for histogram pyramids."""
    rng = np.random.default_rng(5)
    path = tmp_path / "quantised.png"
    return path, write_png8(path, rng.choice([0, 51, 102, 204, 255], size=(32, 32)) / 255)


def test_histogram_levels_are_box_filtered_indicators(quantised, tmp_path):
    path, f = quantised
    h = cmfilter.HistogramPyramid.bake(str(path), str(tmp_path / "histograms.exr"))
    values = np.unique(f)
    assert (h.width, h.height, h.levels, h.bins) == (32, 32, 6, 5)
    np.testing.assert_allclose(h.values, values, rtol=1e-7)
    indicators = (f[:, :, None] == values).astype(np.float64)
    box = lambda k: indicators.reshape(32 >> k, 1 << k, 32 >> k, 1 << k, 5).mean(axis=(1, 3))
    for level in range(4):
        np.testing.assert_allclose(h.level(level), box(level), atol=1e-6)
    # A fractional LOD blends two levels as a moment pyramid's lookup does.
    y, x = np.mgrid[0:16, 0:16]
    weights = cmfilter.HistogramPyramid.open(str(tmp_path / "histograms.exr")).lookup((x + 0.5) / 16, (y + 0.5) / 16,
                                                                                   1.25)
    assert weights.shape == (16, 16, 5) and weights.dtype == np.float32
    for b in range(5):
        expected = 0.75 * box(1)[..., b] + 0.25 * bilinear(box(2)[..., b], x / 2 - 0.25, y / 2 - 0.25)
        np.testing.assert_allclose(weights[..., b], expected, atol=1e-6)


def test_exact_colour_is_the_box_mean_of_c0(quantised, tmp_path, luts):
    path, f = quantised
    moments = cmfilter.MomentPyramid.bake(str(path), str(tmp_path / "moments.exr"))
    histograms = cmfilter.HistogramPyramid.bake(str(path), str(tmp_path / "histograms.exr"))
    colormap = cmfilter.ColorMap.load(str(luts / "terrain.png"))
    texels = linear_colormap(luts / "terrain.png")
    colors = c0(texels, 0, 1, f)
    # apply's exact method at LOD 2: 4 x 4 boxes.
    table = cmfilter.ColorTable.bake(colormap, values=256, sigmas=32, sigma_max=0.6)
    table.write(str(tmp_path / "table.exr"))
    exact = cmfilter.apply(str(tmp_path / "moments.exr"), str(tmp_path / "table.exr"), lod=2, method="exact",
                           histograms=str(tmp_path / "histograms.exr"))
    np.testing.assert_allclose(exact, colors.reshape(8, 4, 8, 4, 3).mean(axis=(1, 3)), atol=5e-4)
    # A footprint of 8 x 2 texels in 2 x 2 probes: exact is the box mean of C0
    # over its texels, naive the probes' C0 of their means, gaussian their
    # T(mean, sigma) (eq. 10 by quadrature).
    result = moments.lookup_footprint(12 / 32, 7 / 32, 8 / 32, 0, 0, 2 / 32, method="exact", colormap=colormap,
                                      histograms=histograms)
    np.testing.assert_allclose(result["albedo"], colors[6:8, 8:16].mean(axis=(0, 1)), atol=5e-4)
    naive = moments.lookup_footprint(12 / 32, 7 / 32, 8 / 32, 0, 0, 2 / 32, method="naive", colormap=colormap)
    means = f[6:8, 8:16].reshape(2, 4, 2).mean(axis=(0, 2))
    np.testing.assert_allclose(naive["albedo"], c0(texels, 0, 1, means).mean(axis=0), atol=5e-4)
    gaussian = moments.lookup_footprint(12 / 32, 7 / 32, 8 / 32, 0, 0, 2 / 32, method="gaussian", table=table)
    means, sigmas = block_moments(f[6:8, 8:16], 2, 2)
    expected = np.mean([quadrature_T(texels, 0, 1, m, s) for m, s in zip(means.ravel(), sigmas.ravel())], axis=0)
    np.testing.assert_allclose(gaussian["albedo"], expected, atol=4e-3)
    with pytest.raises(cmfilter.Error, match="histograms"):
        moments.lookup_footprint(0.5, 0.5, 0.1, 0, 0, 0.1, method="exact", colormap=colormap)
    tifffile.imwrite(tmp_path / "smooth.tif", np.random.default_rng(1).random((32, 32), dtype=np.float32))
    with pytest.raises(cmfilter.Error, match="1024 distinct values") as e:
        cmfilter.HistogramPyramid.bake(str(tmp_path / "smooth.tif"), str(tmp_path / "h.exr"))
    assert e.value.kind == "bad_input"


def test_mixture_colour_of_a_two_valued_driver_is_the_box_mean_of_c0(tmp_path, luts):
    # Two values: each probe's four moments give its two values and their
    # shares exactly, so mixture's colour is the box mean of C0 over the
    # footprint's texels (up to the table's own sigma-0 error), where one
    # Gaussian is not.
    rng = np.random.default_rng(11)
    path = tmp_path / "two.png"
    f = write_png8(path, rng.choice([51, 204], size=(32, 32)) / 255)
    moments = cmfilter.MomentPyramid.bake(str(path), str(tmp_path / "moments4.exr"), order=4)
    colormap = cmfilter.ColorMap.load(str(luts / "terrain.png"))
    table = cmfilter.ColorTable.bake(colormap, values=1024, sigmas=32, sigma_max=0.6)
    colors = c0(linear_colormap(luts / "terrain.png"), 0, 1, f)
    mixture = moments.lookup_footprint(12 / 32, 7 / 32, 8 / 32, 0, 0, 2 / 32, method="mixture", table=table)
    expected = colors[6:8, 8:16].mean(axis=(0, 1))
    np.testing.assert_allclose(mixture["albedo"], expected, atol=3e-3)
    gaussian = moments.lookup_footprint(12 / 32, 7 / 32, 8 / 32, 0, 0, 2 / 32, method="gaussian", table=table)
    assert np.abs(gaussian["albedo"] - expected).max() > 10 * np.abs(mixture["albedo"] - expected).max()
    two = cmfilter.MomentPyramid.bake(str(path), str(tmp_path / "moments2.exr"))
    with pytest.raises(cmfilter.Error, match="order 4"):
        two.lookup_footprint(0.5, 0.5, 0.1, 0, 0, 0.1, method="mixture", table=table)
